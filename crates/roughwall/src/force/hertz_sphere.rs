//! Hertz sphere against a rigid wall (Hu et al. 2021, Eqs. 1–3).
use super::{hertz_impact, ForceResult, Particle};
use crate::error::{Error, Result};

/// The coefficient of Hu et al. 2021, Eq. (3), in closed form:
/// `(4/3)·2^(−1/5)·(15π/96)^(3/5) = 0.757381…`, printed as 0.7574 in the paper (docs/physics.md §7).
/// The test `sphere_constant_follows_from_eqs_1_2` derives it from Eqs. (1)–(2).
pub fn xi_sphere() -> f64 {
    // Written as a constant so the closed-form models stay cheap; checked against the formula in tests.
    XI_SPHERE
}

/// See [`xi_sphere`].
pub const XI_SPHERE: f64 = 0.757_381_472_059_867_4;

/// Hertz stiffness of a sphere of radius `r` on a rigid wall, `F = k y^{3/2}`,
/// `k = 4 E √R / (3 (1 − σ²))` (Hu et al. 2021, Eq. 1).
pub fn stiffness(e_star: f64, radius: f64) -> f64 {
    4.0 / 3.0 * e_star * radius.sqrt()
}

/// `hertz-sphere` covers λ = 1 only.
pub fn check_lambda(lambda: f64) -> Result<()> {
    if lambda == 1.0 {
        Ok(())
    } else {
        Err(Error::invalid(
            "lambda",
            lambda,
            "1 for model `hertz-sphere` (use `hertz-rigid` or `hertz-dynamic` for spheroids)",
        ))
    }
}

/// Hu et al. 2021, Eq. (3): `F_max = 0.7574 ρ^0.6 U_N^1.2 D² [E/(1−σ²)]^0.4`; the contact time is
/// Hertz's, `t_c = 2.9433 h / U_N` with `h` from Eq. (2).
pub fn evaluate(p: &Particle, u_n: f64) -> ForceResult {
    let f_max = XI_SPHERE * p.force_scale(u_n);
    let contact_time = if u_n > 0.0 {
        hertz_impact(stiffness(p.e_star(), 0.5 * p.diameter), p.mass(), u_n).1
    } else {
        None
    };
    ForceResult {
        f_max,
        xi: XI_SPHERE,
        contact_time,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Hu et al. 2021, Eqs. (1)–(2) with ρ = U = D = E* = 1: h^{5/2} = 15 m U² / (16 √R E*^{-1}),
    /// F = (4/3) E* √R h^{3/2}; the result is the coefficient of Eq. (3).
    #[test]
    fn sphere_constant_follows_from_eqs_1_2() {
        let (rho, u, d, e_star) = (1.0_f64, 1.0_f64, 1.0_f64, 1.0_f64);
        let r = d / 2.0;
        let m = rho * PI * d.powi(3) / 6.0;
        let h = (15.0 * m * u * u / (16.0 * r.sqrt() / e_star)).powf(0.4);
        let f = 4.0 * e_star * r.sqrt() / 3.0 * h.powf(1.5);
        assert_eq!(format!("{f:.4}"), "0.7574");
        assert!((f - XI_SPHERE).abs() < 1e-15, "{f}");
        // The closed form of docs/physics.md §7.
        let closed = 4.0 / 3.0 * 2f64.powf(-0.2) * (15.0 * PI / 96.0).powf(0.6);
        assert!((closed - XI_SPHERE).abs() < 1e-15);
        // Eq. (2) is the energy balance ½ m U² = ∫ F dy = (2/5)(4/3) E* √R h^{5/2}.
        assert!((0.5 * m * u * u - 0.4 * stiffness(e_star, r) * h.powf(2.5)).abs() < 1e-15);
    }

    #[test]
    fn hertz_contact_time_constant() {
        // TAU_HERTZ = 2 ∫₀¹ dx/√(1 − x^{5/2}); substitute x = 1 − s² to remove the end singularity.
        let n = 200_000;
        let mut sum = 0.0;
        for i in 0..n {
            let s = (i as f64 + 0.5) / n as f64;
            let x: f64 = 1.0 - s * s;
            sum += 2.0 * s / (1.0 - x.powf(2.5)).sqrt() / n as f64;
        }
        assert!(
            (2.0 * sum - super::super::TAU_HERTZ).abs() < 1e-6,
            "{}",
            2.0 * sum
        );
    }

    #[test]
    fn zero_speed_gives_zero_force() {
        let p = Particle {
            density: 2500.0,
            youngs: 64e9,
            poisson: 0.24,
            diameter: 2.45e-6,
        };
        let r = evaluate(&p, 0.0);
        assert_eq!(r.f_max, 0.0);
        assert_eq!(r.contact_time, None);
        assert!(r.xi.is_finite());
    }
}
