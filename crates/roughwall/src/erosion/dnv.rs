//! DNV RP-O501 (*Managing sand production and erosion*, DNV GL, August 2015), Sec. 3, as
//! implemented in Equinor's `pysand` (`pysand/erosion.py`, functions `F` and the geometry
//! models' `K * F * U**n / rho_t`):
//!
//! `E_m = K · U^n · F(α)` (kg of wall per kg of particles), RP-O501 Eq. (3.1) per unit mass,
//! `E_v = E_m / ρ_t` (m³ per kg),
//!
//! with the ductile angle function of Eq. (3.3),
//! `F(α) = A (sin α + B (sin α − sin²α))^k (1 − e^(−Cα))`, `A = 0.6, B = 7.2, C = 20, k = 0.6`,
//! and pysand's brittle one, `F(α) = 2α/π`. `α` is in radians; the evaluation order follows
//! pysand's so the committed reference (`tests/data/dnv_pysand.csv`) is met to rounding.

/// Which angle function RP-O501 prescribes for the wall material.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngleDependency {
    /// Steels and other ductile materials: Eq. (3.3).
    Ductile,
    /// Ceramics and other brittle materials: `2α/π`.
    Brittle,
}

/// DNV RP-O501 with its material constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dnv {
    /// Material erosion constant `K`, in (m/s)^−n (steels: 2e-9).
    pub k: f64,
    /// Velocity exponent `n` (steels: 2.6).
    pub n: f64,
    /// Density of the wall material `ρ_t` (kg/m³).
    pub target_density_kg_m3: f64,
    /// Which angle function `F(α)` applies: ductile (Eq. 3.3) or brittle (`2α/π`, pysand's
    /// brittle function, not an equation of RP-O501: see the module docs).
    pub angle_dependency: AngleDependency,
}

const A: f64 = 0.6;
const B: f64 = 7.2;
const C: f64 = 20.0;
const EXPONENT: f64 = 0.6;

impl Dnv {
    /// The angle function `F(α)` of RP-O501 Eq. (3.3) (ductile) or `2α/π` (brittle).
    #[inline]
    pub fn angle_function(&self, alpha: f64) -> f64 {
        self.angle_function_s(alpha, alpha.sin())
    }

    /// [`Dnv::angle_function`] with `sin α` given.
    #[inline]
    pub fn angle_function_s(&self, alpha: f64, s: f64) -> f64 {
        match self.angle_dependency {
            AngleDependency::Ductile => {
                A * (s + B * (s - s * s)).powf(EXPONENT) * (1.0 - (-C * alpha).exp())
            }
            AngleDependency::Brittle => 2.0 * alpha / std::f64::consts::PI,
        }
    }

    /// Wall volume removed per unit particle mass (m³/kg): `K F(α) U^n / ρ_t`.
    #[inline]
    pub fn volume_per_mass(&self, speed: f64, alpha: f64) -> f64 {
        self.volume_per_mass_s(speed, alpha, alpha.sin())
    }

    /// [`Dnv::volume_per_mass`] with `sin α` given.
    #[inline]
    pub fn volume_per_mass_s(&self, speed: f64, alpha: f64, s: f64) -> f64 {
        self.k * self.angle_function_s(alpha, s) * speed.powf(self.n) / self.target_density_kg_m3
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Dnv = Dnv {
        k: 2e-9,
        n: 2.6,
        target_density_kg_m3: 7800.0,
        angle_dependency: AngleDependency::Ductile,
    };

    #[test]
    fn angle_function_limits() {
        assert_eq!(STEEL.angle_function(0.0), 0.0);
        // Not normalised: F(90°) = 0.6 (1 − e^(−10π)).
        let f90 = STEEL.angle_function(std::f64::consts::FRAC_PI_2);
        assert!((f90 - 0.6 * (1.0 - (-10.0 * std::f64::consts::PI).exp())).abs() < 1e-15);
        // Its peak (≈ 0.99) lies between 20° and 40°.
        let peak = (1..90)
            .map(|d| (d, STEEL.angle_function((d as f64).to_radians())))
            .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
        assert!(
            (20..=40).contains(&peak.0) && peak.1 > 0.95 && peak.1 < 1.05,
            "{peak:?}"
        );
        let brittle = Dnv {
            angle_dependency: AngleDependency::Brittle,
            ..STEEL
        };
        assert!((brittle.angle_function(std::f64::consts::FRAC_PI_2) - 1.0).abs() < 1e-15);
    }
}
