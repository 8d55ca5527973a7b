//! Peak elastic force of a sphere or prolate spheroid hitting a rigid plane wall
//! (Hu et al. 2021, Eqs. 1–8; physics notes §7).
//!
//! Four models share one interface, [`Model::evaluate`]:
//! - [`Model::HertzSphere`]: Hu et al. 2021, Eq. (3) (λ = 1 only);
//! - [`Model::Hu2021`]: Hu et al. 2021, Eqs. (7)–(8) (λ ∈ {1, 1.5, 2, 3});
//! - [`Model::HertzRigid`]: rigid spheroid, elliptical Hertz contact, energy balance (closed form);
//! - [`Model::HertzDynamic`]: the same contact integrated in time, spheroid free to rotate.
//!
//! Conventions: SI units, β in radians inside (degrees only at the CSV/case boundary),
//! `D` is the volume-equivalent diameter (Hu et al. 2021, Sec. 2 and Table 1), λ = b/a ≥ 1
//! (b semi-major, a semi-minor axis), β the angle between the major axis and the wall.
pub mod hertz_dynamic;
pub mod hertz_rigid;
pub mod hertz_sphere;
pub mod hu2021;
pub mod material;
pub mod report;
pub mod spheroid;
pub mod sweep;

use crate::error::{Error, Result};

/// Elastic particle (SI units). The wall is rigid (Hu et al. 2021, Sec. 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Particle {
    /// Density ρ_p (kg/m³).
    pub density: f64,
    /// Young's modulus E_p (Pa).
    pub youngs: f64,
    /// Poisson's ratio σ_p.
    pub poisson: f64,
    /// Volume-equivalent diameter D_p (m).
    pub diameter: f64,
}

impl Particle {
    /// True if every property is finite and physical (the cheap check of the hot path).
    #[inline]
    pub fn is_valid(&self) -> bool {
        let pos = |v: f64| v.is_finite() && v > 0.0;
        pos(self.density)
            && pos(self.youngs)
            && pos(self.diameter)
            && self.poisson.is_finite()
            && self.poisson > -1.0
            && self.poisson <= 0.5
    }

    /// Checks every property is finite and physical; one-line `Error::Input` otherwise.
    #[inline]
    pub fn validate(&self) -> Result<()> {
        if self.is_valid() {
            Ok(())
        } else {
            self.explain()
        }
    }

    #[cold]
    fn explain(&self) -> Result<()> {
        let pos = |key: &str, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(Error::invalid(key, v, "a finite number > 0"))
            }
        };
        pos("density_kg_m3", self.density)?;
        pos("youngs_pa", self.youngs)?;
        pos("diameter_um", self.diameter * 1e6)?;
        if !(self.poisson.is_finite() && self.poisson > -1.0 && self.poisson <= 0.5) {
            return Err(Error::invalid("poisson", self.poisson, "-1 < σ ≤ 0.5"));
        }
        Ok(())
    }

    /// Plane-strain modulus of the particle against a rigid wall, E/(1 − σ²) (Hu et al. 2021, Eq. 1).
    pub fn e_star(&self) -> f64 {
        self.youngs / (1.0 - self.poisson * self.poisson)
    }

    /// Mass of the particle, ρ π D³ / 6 (D volume-equivalent).
    pub fn mass(&self) -> f64 {
        self.density * std::f64::consts::PI * self.diameter.powi(3) / 6.0
    }

    /// The force scale of Eq. (7), ρ^0.6 U_N^1.2 D² [E/(1−σ²)]^0.4, so that F_max = ξ × scale
    /// (Hu et al. 2021, Eq. 7).
    #[inline]
    pub fn force_scale(&self, u_n: f64) -> f64 {
        // exp(0.6 ln(ρU²) + 0.4 ln E*): one exp instead of two powf; U_N = 0 gives exp(−∞) = 0.
        (0.6 * (self.density * u_n * u_n).ln() + 0.4 * self.e_star().ln()).exp()
            * self.diameter
            * self.diameter
    }
}

/// One impact: aspect ratio, orientation and normal speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// Aspect ratio λ = b/a ≥ 1 (Hu et al. 2021, Sec. 1).
    pub lambda: f64,
    /// Orientation β (rad) between major axis and wall, in [0, π/2].
    pub beta: f64,
    /// Normal impact speed U_N ≥ 0 (m/s).
    pub u_n: f64,
}

impl Impact {
    /// Builds an impact from β in degrees, validating every field.
    pub fn from_deg(lambda: f64, beta_deg: f64, u_n: f64) -> Result<Self> {
        let imp = Impact {
            lambda,
            beta: beta_deg.to_radians().min(std::f64::consts::FRAC_PI_2),
            u_n,
        };
        validate_lambda(lambda)?;
        if !(beta_deg.is_finite() && (0.0..=90.0).contains(&beta_deg)) {
            return Err(Error::invalid("beta_deg", beta_deg, "0 ≤ β ≤ 90"));
        }
        if !(u_n.is_finite() && u_n >= 0.0) {
            return Err(Error::invalid("u_n_m_s", u_n, "a finite number ≥ 0"));
        }
        Ok(imp)
    }

    /// True if λ ≥ 1, β ∈ [0, π/2] and U_N ≥ 0, all finite (the cheap check of the hot path).
    #[inline]
    pub fn is_valid(&self) -> bool {
        self.lambda.is_finite()
            && self.lambda >= 1.0
            && self.beta.is_finite()
            && (0.0..=std::f64::consts::FRAC_PI_2).contains(&self.beta)
            && self.u_n.is_finite()
            && self.u_n >= 0.0
    }

    /// Re-validates an impact built by hand (β in radians, [0, π/2]).
    #[inline]
    pub fn validate(&self) -> Result<()> {
        if self.is_valid() {
            Ok(())
        } else {
            self.explain()
        }
    }

    #[cold]
    fn explain(&self) -> Result<()> {
        validate_lambda(self.lambda)?;
        if !(self.beta.is_finite() && (0.0..=std::f64::consts::FRAC_PI_2).contains(&self.beta)) {
            return Err(Error::invalid(
                "beta_deg",
                self.beta.to_degrees(),
                "0 ≤ β ≤ 90",
            ));
        }
        if !(self.u_n.is_finite() && self.u_n >= 0.0) {
            return Err(Error::invalid("u_n_m_s", self.u_n, "a finite number ≥ 0"));
        }
        Ok(())
    }
}

/// λ must be finite and ≥ 1: prolate spheroids and the sphere. Oblate spheroids are not modelled.
pub fn validate_lambda(lambda: f64) -> Result<()> {
    if lambda.is_finite() && lambda >= 1.0 {
        Ok(())
    } else {
        Err(Error::invalid(
            "lambda",
            lambda,
            "λ ≥ 1 (prolate spheroids and the sphere; oblate spheroids, λ < 1, are not modelled)",
        ))
    }
}

/// What a model returns for one impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForceResult {
    /// Peak elastic force F_max (N); exactly 0 for U_N = 0.
    pub f_max: f64,
    /// ξ = F_max / (ρ^0.6 U_N^1.2 D² E*^0.4) (Hu et al. 2021, Eq. 7); for U_N = 0 the U_N → 0 limit.
    pub xi: f64,
    /// Contact duration (s) where the model yields one; `None` for Hu et al.'s fit and for U_N = 0.
    pub contact_time: Option<f64>,
}

/// The force models of `rebound force-sweep`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Model {
    /// Hu et al. 2021, Eq. (3): Hertz sphere (λ = 1 only).
    HertzSphere,
    /// Hu et al. 2021, Eqs. (7)–(8).
    Hu2021,
    /// Rigid spheroid, elliptical Hertz contact, effective mass, energy balance (notes §7).
    HertzRigid,
    /// The same contact integrated in time, spheroid free to translate and rotate.
    HertzDynamic,
}

impl Model {
    /// All models, in the order of the default sweep.
    pub const ALL: [Model; 4] = [
        Model::HertzSphere,
        Model::Hu2021,
        Model::HertzRigid,
        Model::HertzDynamic,
    ];

    /// Name used in case files and CSV.
    pub fn name(self) -> &'static str {
        match self {
            Model::HertzSphere => "hertz-sphere",
            Model::Hu2021 => "hu2021",
            Model::HertzRigid => "hertz-rigid",
            Model::HertzDynamic => "hertz-dynamic",
        }
    }

    /// Parses a model name; unknown names are one-line `Error::Input`.
    pub fn from_name(name: &str) -> Result<Model> {
        Model::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| {
                Error::invalid(
                    "models",
                    name,
                    "hertz-sphere, hu2021, hertz-rigid, hertz-dynamic",
                )
            })
    }

    /// Checks that the model covers λ (called once per sweep before any work).
    pub fn check_lambda(self, lambda: f64) -> Result<()> {
        validate_lambda(lambda)?;
        match self {
            Model::HertzSphere => hertz_sphere::check_lambda(lambda),
            Model::Hu2021 => hu2021::check_lambda(lambda),
            Model::HertzRigid | Model::HertzDynamic => Ok(()),
        }
    }

    /// Peak elastic force of one impact.
    #[inline]
    pub fn evaluate(self, p: &Particle, imp: &Impact) -> Result<ForceResult> {
        p.validate()?;
        imp.validate()?;
        if matches!(self, Model::HertzSphere | Model::Hu2021) {
            self.check_lambda(imp.lambda)?;
        }
        Ok(match self {
            Model::HertzSphere => hertz_sphere::evaluate(p, imp.u_n),
            Model::Hu2021 => hu2021::evaluate(p, imp)?,
            Model::HertzRigid => hertz_rigid::evaluate(p, imp),
            Model::HertzDynamic => {
                hertz_dynamic::evaluate(p, imp, &hertz_dynamic::Options::default())
            }
        })
    }
}

/// Contact duration of a Hertzian impact, `t_c = TAU_HERTZ · δ_max / U_N`, with
/// `TAU_HERTZ = 2 ∫₀¹ dx / √(1 − x^{5/2}) = (4/5) B(2/5, 1/2)` (Johnson 1985, §11.4).
pub const TAU_HERTZ: f64 = 2.943_275_184_324_705;

/// Closed-form F_max and contact time of a Hertzian impact `F = k δ^{3/2}` of effective mass
/// `m_eff` at normal speed `u_n`: `½ m_eff U² = (2/5) k δ^{5/2}` (Hu et al. 2021, Eqs. 1–2).
pub fn hertz_impact(k: f64, m_eff: f64, u_n: f64) -> (f64, Option<f64>) {
    if u_n <= 0.0 {
        return (0.0, None);
    }
    let delta = (1.25 * m_eff * u_n * u_n / k).powf(0.4);
    (k * delta * delta.sqrt(), Some(TAU_HERTZ * delta / u_n))
}
