//! Oka, Okamura & Yoshida, *Practical estimation of erosion damage caused by solid particle
//! impact*, Part 1 (Y.I. Oka, K. Okamura, T. Yoshida, Wear 259 (2005) 95–101: the angle
//! function) and Part 2 (Y.I. Oka, T. Yoshida, Wear 259 (2005) 102–109: the erosion at
//! normal incidence from the wall's Vickers hardness):
//!
//! `E(α) = g(α) · E90` (Part 1, Eq. 1),
//! `g(α) = (sin α)^n1 · (1 + Hv (1 − sin α))^n2` (Part 1, Eq. 2),
//! `E90 = K · Hv^k1 · (U/U')^k2 · (D/D')^k3` (Part 2, Eq. 1),
//!
//! with `E` in mm³ per kg of particles and `Hv` in GPa. The constants default to Part 2's
//! correlations for SiO2 sand (`K = 65`, `k1 = −0.12`, `k2 = 2.3 Hv^0.038`, `k3 = 0.19`,
//! `n1 = 0.71 Hv^0.14`, `n2 = 2.4 Hv^−0.94`, `U' = 104 m/s`, `D' = 326 µm`); each can be set.

/// Oka's law with its constants resolved (no defaults left).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Oka {
    /// Vickers hardness of the wall `Hv` (GPa).
    pub hardness_gpa: f64,
    /// `K`: particle-property factor (mm³/kg; 65 for SiO2).
    pub k: f64,
    /// `k1`: exponent of the hardness `Hv` in `E90` (Part 2, Eq. 1; −0.12 for SiO2).
    pub k1: f64,
    /// `k2`: exponent of the speed ratio `U/U'` in `E90` (Part 2, Eq. 1; `2.3 Hv^0.038` for
    /// SiO2).
    pub k2: f64,
    /// `k3`: exponent of the diameter ratio `D/D'` in `E90` (Part 2, Eq. 1; 0.19 for SiO2).
    pub k3: f64,
    /// `n1`: exponent of `sin α` in `g(α)` (Part 1, Eq. 2; `0.71 Hv^0.14` for SiO2).
    pub n1: f64,
    /// `n2`: exponent of `1 + Hv (1 − sin α)` in `g(α)` (Part 1, Eq. 2; `2.4 Hv^−0.94` for
    /// SiO2).
    pub n2: f64,
    /// Reference impact speed `U'` (m/s).
    pub reference_speed_m_s: f64,
    /// Reference particle diameter `D'` (m).
    pub reference_diameter_m: f64,
}

/// Part 2's SiO2 defaults for the constants not given, from the hardness `Hv` (GPa).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OkaInput {
    /// Vickers hardness of the wall `Hv` (GPa); required: the SiO2 defaults of `k2`, `n1`
    /// and `n2` follow from it.
    pub hardness_gpa: f64,
    /// `K` (mm³/kg); `None`: 65.
    pub k: Option<f64>,
    /// `k1`, exponent of `Hv` in `E90`; `None`: −0.12.
    pub k1: Option<f64>,
    /// `k2`, exponent of `U/U'` in `E90`; `None`: `2.3 Hv^0.038`.
    pub k2: Option<f64>,
    /// `k3`, exponent of `D/D'` in `E90`; `None`: 0.19.
    pub k3: Option<f64>,
    /// `n1`, exponent of `sin α` in `g(α)`; `None`: `0.71 Hv^0.14`.
    pub n1: Option<f64>,
    /// `n2`, exponent of `1 + Hv (1 − sin α)` in `g(α)`; `None`: `2.4 Hv^−0.94`.
    pub n2: Option<f64>,
    /// Reference impact speed `U'` (m/s); `None`: 104 m/s.
    pub reference_speed_m_s: Option<f64>,
    /// Reference particle diameter `D'` (m); `None`: 326 µm.
    pub reference_diameter_m: Option<f64>,
}

impl OkaInput {
    /// Fill in Oka & Yoshida's (2005, Part 2) SiO2 correlations for what is not given.
    pub fn resolve(&self) -> Oka {
        let hv = self.hardness_gpa;
        Oka {
            hardness_gpa: hv,
            k: self.k.unwrap_or(65.0),
            k1: self.k1.unwrap_or(-0.12),
            k2: self.k2.unwrap_or_else(|| 2.3 * hv.powf(0.038)),
            k3: self.k3.unwrap_or(0.19),
            n1: self.n1.unwrap_or_else(|| 0.71 * hv.powf(0.14)),
            n2: self.n2.unwrap_or_else(|| 2.4 * hv.powf(-0.94)),
            reference_speed_m_s: self.reference_speed_m_s.unwrap_or(104.0),
            reference_diameter_m: self.reference_diameter_m.unwrap_or(326e-6),
        }
    }
}

/// mm³ → m³.
const MM3: f64 = 1e-9;

impl Oka {
    /// `g(α) = (sin α)^n1 (1 + Hv (1 − sin α))^n2` (Part 1, Eq. 2); `g(90°) = 1`.
    #[inline]
    pub fn angle_function(&self, alpha: f64) -> f64 {
        self.angle_function_s(alpha.sin())
    }

    /// [`Oka::angle_function`] of `sin α`.
    #[inline]
    pub fn angle_function_s(&self, s: f64) -> f64 {
        s.powf(self.n1) * (1.0 + self.hardness_gpa * (1.0 - s)).powf(self.n2)
    }

    /// `E90` (m³/kg) at normal incidence (Part 2, Eq. 1).
    #[inline]
    pub fn normal_volume_per_mass(&self, speed: f64, diameter_m: f64) -> f64 {
        self.k
            * self.hardness_gpa.powf(self.k1)
            * (speed / self.reference_speed_m_s).powf(self.k2)
            * (diameter_m / self.reference_diameter_m).powf(self.k3)
            * MM3
    }

    /// Wall volume removed per unit particle mass (m³/kg): `g(α) E90`.
    #[inline]
    pub fn volume_per_mass(&self, speed: f64, alpha: f64, diameter_m: f64) -> f64 {
        self.volume_per_mass_s(speed, alpha.sin(), diameter_m)
    }

    /// [`Oka::volume_per_mass`] of `sin α`.
    #[inline]
    pub fn volume_per_mass_s(&self, speed: f64, s: f64, diameter_m: f64) -> f64 {
        self.angle_function_s(s) * self.normal_volume_per_mass(speed, diameter_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel() -> Oka {
        OkaInput {
            hardness_gpa: 1.5,
            ..Default::default()
        }
        .resolve()
    }

    #[test]
    fn reference_conditions_give_k_hv_k1() {
        let o = steel();
        let e = o.normal_volume_per_mass(104.0, 326e-6);
        assert!((e - 65.0 * 1.5f64.powf(-0.12) * 1e-9).abs() < 1e-22);
        assert!((o.angle_function(std::f64::consts::FRAC_PI_2) - 1.0).abs() < 1e-15);
        assert_eq!(o.angle_function(0.0), 0.0);
    }

    fn peak_deg(hardness_gpa: f64) -> (u32, f64) {
        let o = OkaInput {
            hardness_gpa,
            ..Default::default()
        }
        .resolve();
        (1..=90)
            .map(|d| (d, o.angle_function((d as f64).to_radians())))
            .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a })
    }

    #[test]
    fn erosion_peak_moves_toward_normal_as_the_wall_hardens() {
        // Soft (ductile) metals erode most at oblique angles, harder walls closer to normal
        // incidence (Part 1, Fig. 6). With the SiO2 exponents the maximum of
        // s^n1 (1 + Hv(1 − s))^n2 is at s = n1 (1 + Hv) / (Hv (n1 + n2)), s = sin α:
        // 27.1° for Hv = 1 GPa, 59.1° for Hv = 10 GPa.
        for (hv, expect) in [(1.0, 27), (10.0, 59)] {
            let o = OkaInput {
                hardness_gpa: hv,
                ..Default::default()
            }
            .resolve();
            let s = o.n1 * (1.0 + hv) / (hv * (o.n1 + o.n2));
            let analytic = s.asin().to_degrees();
            let (peak, g) = peak_deg(hv);
            assert!((analytic - expect as f64).abs() < 0.6, "{hv}: {analytic}");
            assert!(
                (peak as f64 - analytic).abs() <= 1.0 && g > 1.0,
                "{hv}: {peak} {g}"
            );
        }
        assert!(peak_deg(1.0).0 < peak_deg(3.0).0 && peak_deg(3.0).0 < peak_deg(10.0).0);
    }

    #[test]
    fn velocity_and_size_exponents() {
        let o = steel();
        let r = o.volume_per_mass(50.0, 0.5, 1e-4) / o.volume_per_mass(25.0, 0.5, 1e-4);
        assert!((r - 2f64.powf(o.k2)).abs() < 1e-12);
        let r = o.volume_per_mass(50.0, 0.5, 2e-4) / o.volume_per_mass(50.0, 0.5, 1e-4);
        assert!((r - 2f64.powf(0.19)).abs() < 1e-12);
    }
}
