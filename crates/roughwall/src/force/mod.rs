//! Peak elastic force of a sphere or prolate spheroid hitting a rigid plane wall
//! (Hu et al. 2021, Eqs. 1–8; docs/physics.md §7).
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
pub(crate) mod hertz_rigid;
pub mod hertz_sphere;
pub mod hu2021;
pub mod material;
pub(crate) mod report;
pub(crate) mod spheroid;
pub(crate) mod sweep;

pub use report::{
    accuracy, convergence, Accuracy, Convergence, CONVERGENCE_STEPS, REFERENCE_STEPS,
};
pub use sweep::{Row, Sweep};

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
        let within = |v: f64, (lo, hi): (f64, f64)| v.is_finite() && (lo..=hi).contains(&v);
        within(self.density, DENSITY_RANGE_KG_M3)
            && within(self.youngs, YOUNGS_RANGE_PA)
            && within(self.diameter, DIAMETER_RANGE_M)
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
        let within = |key: &str, v: f64, (lo, hi): (f64, f64), scale: f64, why: &str| {
            if v.is_finite() && (lo..=hi).contains(&v) {
                Ok(())
            } else {
                Err(Error::invalid(
                    key,
                    v * scale,
                    &format!("{} to {} ({why})", lo * scale, hi * scale),
                ))
            }
        };
        within(
            "density_kg_m3",
            self.density,
            DENSITY_RANGE_KG_M3,
            1.0,
            "solid particles",
        )?;
        within(
            "youngs_pa",
            self.youngs,
            YOUNGS_RANGE_PA,
            1.0,
            "from soft gels to diamond",
        )?;
        within(
            "diameter_um",
            self.diameter,
            DIAMETER_RANGE_M,
            1e6,
            "a nanometre to a metre",
        )?;
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
        if !(u_n == 0.0 || (u_n.is_finite() && (MIN_U_N_M_S..=MAX_U_N_M_S).contains(&u_n))) {
            return Err(Error::invalid(
                "u_n_m_s",
                u_n,
                "0, or 1e-6 to 10000 m/s (elastic impacts: slower ones are adhesion's, faster ones hypervelocity)",
            ));
        }
        Ok(imp)
    }

    /// True if λ ≥ 1, β ∈ [0, π/2] and U_N ≥ 0, all finite (the cheap check of the hot path).
    #[inline]
    pub fn is_valid(&self) -> bool {
        self.lambda.is_finite()
            && (1.0..=MAX_LAMBDA).contains(&self.lambda)
            && self.beta.is_finite()
            && (0.0..=std::f64::consts::FRAC_PI_2).contains(&self.beta)
            && (self.u_n == 0.0
                || (self.u_n.is_finite() && (MIN_U_N_M_S..=MAX_U_N_M_S).contains(&self.u_n)))
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
    if lambda.is_finite() && (1.0..=MAX_LAMBDA).contains(&lambda) {
        Ok(())
    } else {
        Err(Error::invalid(
            "lambda",
            lambda,
            "1 ≤ λ ≤ 1000 (prolate spheroids and the sphere, up to fibres of 1000:1; oblate spheroids, λ < 1, are not modelled)",
        ))
    }
}

/// Particle densities (kg/m³): solids from aerogels to osmium, with room to spare.
pub const DENSITY_RANGE_KG_M3: (f64, f64) = (1.0, 1e5);
/// Young's moduli (Pa): soft gels (1 kPa) to diamond (≈ 1 TPa).
pub const YOUNGS_RANGE_PA: (f64, f64) = (1e3, 1e13);
/// Volume-equivalent diameters (m): a nanometre to a metre.
pub const DIAMETER_RANGE_M: (f64, f64) = (1e-9, 1.0);
/// Aspect ratios λ: spheres to fibres of 1000:1.
pub const MAX_LAMBDA: f64 = 1000.0;
/// Normal impact speeds (m/s): 0, or impacts from a micrometre per second (slower, adhesion
/// decides) up to [`MAX_U_N_M_S`]. This is the smallest positive `U_N` accepted (m/s);
/// `U_N = 0` is accepted too.
pub const MIN_U_N_M_S: f64 = 1e-6;
/// The largest normal impact speed `U_N` accepted (m/s), 10 km/s, where impacts become
/// hypervelocity: a guard that keeps the arithmetic finite, not a validity limit. The
/// elastic models hold only while the deformation stays small (Hertz, Hu et al. 2021, Eq. 3
/// and Sec. 3, Fig. 4: plastic yield sets in far below this speed for most materials).
pub const MAX_U_N_M_S: f64 = 1e4;

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
    /// Rigid spheroid, elliptical Hertz contact, effective mass, energy balance (docs/physics.md §7).
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
