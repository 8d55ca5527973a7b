//! Erosion of the wall by the impacts a rebound model produces: the volume of wall material
//! one impact removes, from the particle's mass, its speed and its impact angle to the *local*
//! wall element (the facet hit, or the virtual wall sampled), by one of three laws:
//!
//! * `finnie`: Finnie (1960), ductile micro-cutting, in OpenFOAM's form;
//! * `dnv`: DNV RP-O501, as implemented in Equinor's `pysand`;
//! * `oka`: Oka, Okamura & Yoshida (2005).
//!
//! "Model only what a scene needs": a case without `[erosion]` computes none of it.

pub(crate) mod dnv;
pub(crate) mod finnie;
pub(crate) mod oka;

pub use dnv::{AngleDependency, Dnv};
pub use finnie::Finnie;
pub use oka::{Oka, OkaInput};

/// An erosion law with its parameters (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ErosionModel {
    /// Finnie (1960), ductile micro-cutting, in OpenFOAM's form (`finnie`).
    Finnie(finnie::Finnie),
    /// DNV RP-O501 (2015), Sec. 3, as implemented in Equinor's `pysand` (`dnv`).
    Dnv(dnv::Dnv),
    /// Oka, Okamura & Yoshida (2005), with the particle-size effect of Part 2 (`oka`).
    Oka(oka::Oka),
}

impl ErosionModel {
    /// Wall volume (m³) removed per kilogram of particles striking at `speed` (m/s) and
    /// impact angle `alpha` (rad, between the velocity and the local wall plane, in
    /// `[0, π/2]`), for particles of diameter `diameter_m`. Zero for a zero speed; never NaN.
    #[inline]
    pub fn volume_per_mass(&self, speed: f64, alpha: f64, diameter_m: f64) -> f64 {
        if !alpha.is_finite() {
            return 0.0;
        }
        self.volume_at(speed, &ImpactAngle::of(alpha), diameter_m)
    }

    /// [`ErosionModel::volume_per_mass`] at an impact angle given with its sine and cosine.
    #[inline]
    pub fn volume_at(&self, speed: f64, a: &ImpactAngle, diameter_m: f64) -> f64 {
        if !(speed > 0.0 && speed.is_finite()) {
            return 0.0;
        }
        let v = match self {
            ErosionModel::Finnie(m) => m.volume_per_mass_sc(speed, a.sin, a.cos),
            ErosionModel::Dnv(m) => m.volume_per_mass_s(speed, a.alpha, a.sin),
            ErosionModel::Oka(m) => m.volume_per_mass_s(speed, a.sin, diameter_m),
        };
        if v.is_finite() {
            v.max(0.0)
        } else {
            0.0
        }
    }

    /// The model's name in case files.
    pub fn name(&self) -> &'static str {
        match self {
            ErosionModel::Finnie(_) => "finnie",
            ErosionModel::Dnv(_) => "dnv",
            ErosionModel::Oka(_) => "oka",
        }
    }
}

/// What a run needs to tally erosion: the law and the particle mass (for the volume per
/// particle).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErosionSetup {
    /// The erosion law and its parameters.
    pub model: ErosionModel,
    /// Mass of one particle (kg): the volume removed per particle is this times the volume
    /// per unit particle mass the law gives.
    pub particle_mass_kg: f64,
    /// Particle diameter (m), for laws with a size effect (Oka).
    pub diameter_m: f64,
}

impl ErosionSetup {
    /// The local impact angle (to the element of unit normal `n`) of velocity `u` of
    /// magnitude `speed`, and the wall volume per unit particle mass (m³/kg) that impact
    /// removes.
    #[inline]
    pub fn impact(
        &self,
        u: &nalgebra::Vector3<f64>,
        speed: f64,
        n: &nalgebra::Vector3<f64>,
    ) -> (ImpactAngle, f64) {
        let a = ImpactAngle::of_velocity(u, speed, n);
        (a, self.model.volume_at(speed, &a, self.diameter_m))
    }
}

/// An impact angle `α` to the local wall plane, in `[0, π/2]`, with its sine and cosine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactAngle {
    /// The impact angle `α` between the velocity and the local wall plane (radians, in
    /// `[0, π/2]`; 0 for no impact).
    pub alpha: f64,
    /// `sin α`, in `[0, 1]`.
    pub sin: f64,
    /// `cos α`, in `[0, 1]` (exactly 0 at normal incidence).
    pub cos: f64,
}

impl ImpactAngle {
    /// The angle `alpha` (rad), clamped into `[0, π/2]`.
    #[inline]
    pub fn of(alpha: f64) -> ImpactAngle {
        let alpha = alpha.clamp(0.0, std::f64::consts::FRAC_PI_2);
        let (sin, cos) = alpha.sin_cos();
        ImpactAngle { alpha, sin, cos }
    }

    /// The impact angle of velocity `u` (of magnitude `speed`) arriving on an element of
    /// unit normal `n` (pointing into the flow): `sin α = −u·n/|u|`, `cos α = √(1 − sin²α)`
    /// (exactly 0 at normal incidence). A velocity leaving the element, or a zero one, has
    /// `α = 0`.
    #[inline]
    pub fn of_velocity(
        u: &nalgebra::Vector3<f64>,
        speed: f64,
        n: &nalgebra::Vector3<f64>,
    ) -> ImpactAngle {
        let s = if speed > 0.0 {
            (-u.dot(n) / speed).clamp(0.0, 1.0)
        } else {
            0.0
        };
        // NaN (a non-finite velocity) is no impact.
        let s = if s.is_nan() { 0.0 } else { s };
        ImpactAngle {
            alpha: s.asin(),
            sin: s,
            cos: ((1.0 - s) * (1.0 + s)).sqrt(),
        }
    }
}

impl ImpactAngle {
    /// The impact angle on the virtual wall element a rough-wall model drew: velocity `u`
    /// (of magnitude `speed`) in the wall's frame (mean wall `y = 0`, `x` along the lay)
    /// arriving on the element of inclinations `γ` in the incident plane and `γ*` normal to
    /// it (Radenkovic & Simonin 2021, Eqs. 20–21: what `rw_result.gamma` and `gamma_star`
    /// report), whose unit normal follows from them by Eqs. (23) and (10) at the incident
    /// direction `β⁻` (docs/physics.md §2): the normal the model collided with. With `γ* = 0`
    /// it is `α⁻ + γ` to first order.
    pub fn on_element(
        u: &nalgebra::Vector3<f64>,
        speed: f64,
        gamma: f64,
        gamma_star: f64,
    ) -> ImpactAngle {
        let (_, beta) = crate::angles::incident_angles(u);
        let n = crate::angles::normal_from_gamma(gamma, gamma_star, beta);
        ImpactAngle::of_velocity(u, speed, &n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn the_elements_angle_is_alpha_plus_gamma_in_plane() {
        let at = |alpha: f64, beta: f64, g: f64, gs: f64| {
            let u = crate::angles::velocity_from_angles(3.0, -alpha, beta);
            ImpactAngle::on_element(&u, 3.0, g, gs).alpha
        };
        assert!((at(0.1, 0.0, 0.05, 0.0) - 0.15).abs() < 1e-14);
        // Along the lay or across it, the same element in the incident frame.
        assert!((at(0.1, 1.2, 0.05, 0.0) - 0.15).abs() < 1e-3);
        // Tilted away by more than α: the particle does not reach the element's face.
        assert_eq!(at(0.1, 0.0, -0.2, 0.0), 0.0);
        // γ* tilts the element about the incident direction: the angle drops, evenly in ±γ*.
        let (p, m) = (at(0.3, 0.0, 0.0, 0.2), at(0.3, 0.0, 0.0, -0.2));
        assert!(p < 0.3 && (p - m).abs() < 1e-15);
    }

    /// The angle from `(γ, γ*)` and the incident direction (what the C library reports) is
    /// the angle on the accepted element's own normal, for the paper's model on an
    /// anisotropic wall, from any direction.
    #[test]
    fn the_elements_angle_from_gammas_is_the_angle_on_its_normal() {
        use crate::models::{rebound_with, AnyModel};
        use crate::stochastic::Contact;
        let wall = crate::Deviations {
            delta_xi: 3.8f64.to_radians(),
            delta_zeta: 7.5f64.to_radians(),
        };
        let law = crate::CollisionLaw::Elastic;
        let contact = Contact {
            wall: &wall,
            law: &law,
            psi: 2.0,
            diameter_m: 0.0,
        };
        for i in 0..2000u64 {
            let mut r = crate::rng::stream(11, &[i]);
            let alpha = (1.0 + (i % 60) as f64).to_radians();
            let beta = ((i * 37) % 360) as f64 * std::f64::consts::PI / 180.0 - 3.0;
            let u = crate::angles::velocity_from_angles(7.0, -alpha, beta);
            let reb = rebound_with(&AnyModel::PAPER, u, Vector3::zeros(), &contact, &mut r);
            let on_normal = ImpactAngle::of_velocity(&u, 7.0, &reb.normal);
            let from_gammas = ImpactAngle::on_element(&u, 7.0, reb.gamma, reb.gamma_star);
            assert!(
                (on_normal.alpha - from_gammas.alpha).abs() < 1e-12,
                "{i}: {on_normal:?} {from_gammas:?}"
            );
        }
    }

    fn models() -> [ErosionModel; 4] {
        [
            ErosionModel::Finnie(finnie::Finnie {
                flow_stress_pa: 1e9,
                psi: 2.0,
                k: 2.0,
            }),
            ErosionModel::Dnv(dnv::Dnv {
                k: 2e-9,
                n: 2.6,
                target_density_kg_m3: 7800.0,
                angle_dependency: dnv::AngleDependency::Ductile,
            }),
            ErosionModel::Dnv(dnv::Dnv {
                k: 2e-9,
                n: 2.6,
                target_density_kg_m3: 7800.0,
                angle_dependency: dnv::AngleDependency::Brittle,
            }),
            ErosionModel::Oka(
                oka::OkaInput {
                    hardness_gpa: 1.5,
                    ..Default::default()
                }
                .resolve(),
            ),
        ]
    }

    #[test]
    fn zero_speed_removes_nothing_and_nothing_is_ever_nan() {
        for m in models() {
            for a in [0.0, 0.3, std::f64::consts::FRAC_PI_2] {
                assert_eq!(m.volume_per_mass(0.0, a, 1e-4), 0.0, "{}", m.name());
                assert_eq!(m.volume_per_mass(-1.0, a, 1e-4), 0.0);
            }
            for (u, a) in [
                (f64::NAN, 0.3),
                (f64::INFINITY, 0.3),
                (10.0, f64::NAN),
                (10.0, -1.0),
                (10.0, 4.0),
                (1e300, 0.3),
            ] {
                let v = m.volume_per_mass(u, a, 1e-4);
                assert!(v.is_finite() && v >= 0.0, "{} {u} {a}: {v}", m.name());
            }
            // Grazing: zero at α = 0, small and positive just above.
            assert_eq!(m.volume_per_mass(10.0, 0.0, 1e-4), 0.0, "{}", m.name());
            let g = m.volume_per_mass(10.0, 0.01f64.to_radians(), 1e-4);
            assert!(g > 0.0 && g < 0.01 * m.volume_per_mass(10.0, 0.5, 1e-4));
        }
    }

    #[test]
    fn normal_incidence() {
        let [finnie, ductile, brittle, oka] = models();
        let n = ImpactAngle::of(std::f64::consts::FRAC_PI_2);
        let v = ImpactAngle::of_velocity(
            &Vector3::new(0.0, -10.0, 0.0),
            10.0,
            &Vector3::new(0.0, 1.0, 0.0),
        );
        // Finnie's ductile cutting removes nothing at normal incidence (cos α = 0 exactly
        // from the velocity; cos(π/2) ≈ 6e-17 from the angle).
        assert_eq!(finnie.volume_at(10.0, &v, 1e-4), 0.0);
        assert!(finnie.volume_at(10.0, &n, 1e-4) < 1e-30);
        // DNV: F(90°) = 0.6 (1 − e^(−10π)) ductile, 1 brittle; Oka: g(90°) = 1.
        let scale = 2e-9 * 10f64.powf(2.6) / 7800.0;
        let f90 = 0.6 * (1.0 - (-10.0 * std::f64::consts::PI).exp());
        assert!((ductile.volume_at(10.0, &v, 1e-4) / (scale * f90) - 1.0).abs() < 1e-14);
        assert!((brittle.volume_at(10.0, &v, 1e-4) / scale - 1.0).abs() < 1e-14);
        if let ErosionModel::Oka(o) = oka {
            let e90 = o.normal_volume_per_mass(10.0, 1e-4);
            assert!((oka.volume_at(10.0, &v, 1e-4) / e90 - 1.0).abs() < 1e-14);
        }
    }

    #[test]
    fn velocity_and_angle_paths_agree() {
        let nrm = Vector3::new(0.1f64, 1.0, -0.2).normalize();
        for m in models() {
            for deg in [0.5f64, 5.0, 18.43, 45.0, 89.0] {
                let a = deg.to_radians();
                // A velocity making angle a with the element's plane.
                let t = Vector3::new(1.0, 0.0, 0.0) - nrm * nrm.x;
                let u = (t.normalize() * a.cos() - nrm * a.sin()) * 12.0;
                let got = m.volume_at(12.0, &ImpactAngle::of_velocity(&u, 12.0, &nrm), 1e-4);
                let want = m.volume_per_mass(12.0, a, 1e-4);
                assert!(
                    (got / want - 1.0).abs() < 1e-10,
                    "{} {deg}: {got} {want}",
                    m.name()
                );
            }
        }
    }
}
