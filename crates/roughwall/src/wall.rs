//! The statistical wall: normal-angle deviations and their moments
//! (Radenkovic & Simonin 2021, Eqs. 9, 15, 26, 30, 35; docs/physics.md §2).

use crate::error::{Error, Result};
use crate::warning::Warning;

/// Standard deviations `(Δξ, Δζ)` of the wall normal's angles with the principal
/// roughness directions `x` and `z` (radians). `Δζ = 0` is 2-D roughness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deviations {
    /// `Δξ`: standard deviation of `ξ' = ξ − π/2`, the fluctuation of the normal's angle `ξ` with
    /// the principal roughness direction `x` (radians; Radenkovic & Simonin 2021, Eqs. 4, 15:
    /// `Δξ = √2 h/c_Lx`).
    pub delta_xi: f64,
    /// `Δζ`: standard deviation of `ζ' = ζ − π/2`, the fluctuation of the normal's angle `ζ` with
    /// the principal roughness direction `z` (radians; Radenkovic & Simonin 2021, Eqs. 4, 15:
    /// `Δζ = √2 h/c_Lz`). 0 is 2-D roughness.
    pub delta_zeta: f64,
}

impl Deviations {
    /// Whether the wall is smooth (`Δξ = Δζ = 0`): every rough-wall model then collides with
    /// the mean wall (docs/physics.md §9).
    pub fn is_smooth(&self) -> bool {
        self.delta_xi == 0.0 && self.delta_zeta == 0.0
    }
}

/// Above this deviation the low-roughness approximation (Radenkovic & Simonin 2021, Eq. 6) is
/// stretched: run, but warn (the paper finds Eq. 14 exact up to about 0.13 rad = 7.5°, Sec.
/// 2.4, Fig. 4, and writes Eq. 15 for that range).
pub const LOW_ROUGHNESS_LIMIT_DEG: f64 = 7.5;
/// Beyond this deviation the wall models are not meant to be used at all: a bound chosen
/// here (the paper validates its approximations only up to 7.5°, Sec. 2.4).
pub const MAX_DEVIATION_DEG: f64 = 20.0;

/// A deviation given in degrees under `key`, checked (0 to [`MAX_DEVIATION_DEG`]; beyond
/// [`LOW_ROUGHNESS_LIMIT_DEG`] a warning), in radians.
pub fn checked_deviation(key: &str, v: f64, warnings: &mut Vec<Warning>) -> Result<f64> {
    if !(0.0..=MAX_DEVIATION_DEG).contains(&v) {
        return Err(Error::invalid(
            key,
            v,
            &format!("0 to {MAX_DEVIATION_DEG} degrees"),
        ));
    }
    if v > LOW_ROUGHNESS_LIMIT_DEG {
        warnings.push(Warning(format!(
            "`{key}` = {v}° is beyond the low-roughness approximation (Eq. 6, up to ~{LOW_ROUGHNESS_LIMIT_DEG}°); results are extrapolated"
        )));
    }
    Ok(v.to_radians())
}

/// Second moments `(Var a, Var b, Cov(a, b))` of a pair of angles in a rotated frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moments {
    /// Variance of the first angle `a` (rad²): `Δξ*²` of Eq. (9) or `Δγ²` of Eq. (26),
    /// `cos²β Δξ² + sin²β Δζ²` for the rotation by `β` about `y` (Radenkovic & Simonin 2021).
    pub var_a: f64,
    /// Variance of the second angle `b` (rad²): `Δζ*²` of Eq. (9) or `Δγ*²` of Eq. (26),
    /// `sin²β Δξ² + cos²β Δζ²` (Radenkovic & Simonin 2021).
    pub var_b: f64,
    /// Covariance of `a` and `b` (rad²): `Cov(ξ*, ζ*)` of Eq. (9) or `Cov(γ, γ*)` of Eq. (26),
    /// `sin β cos β (Δξ² − Δζ²)` (Radenkovic & Simonin 2021).
    pub cov: f64,
}

impl Moments {
    /// Correlation coefficient, 0 when either variance vanishes (Eqs. 8, 27).
    pub fn rho(&self) -> f64 {
        let d = (self.var_a * self.var_b).sqrt();
        if d > 0.0 {
            (self.cov / d).clamp(-1.0, 1.0)
        } else {
            0.0
        }
    }

    /// `Δγ = √Var a`: the roughness angle in the plane of the rotation (Eq. 26's first line).
    pub fn delta_gamma(&self) -> f64 {
        self.var_a.max(0.0).sqrt()
    }
}

/// Normal-angle deviation from surface parameters, `Δ = √2 h / c_L` (Radenkovic & Simonin 2021, Eq. 15).
pub fn deviation_from_surface(rms_height: f64, corr_length: f64) -> f64 {
    std::f64::consts::SQRT_2 * rms_height / corr_length
}

/// Correlation length for a wanted deviation, `c_L = √2 h / Δ` (inverse of Eq. 15); `None` for `Δ = 0`
/// (infinite correlation length: the surface is constant along that axis).
pub fn corr_length_from_deviation(rms_height: f64, delta: f64) -> Option<f64> {
    (delta > 0.0).then(|| std::f64::consts::SQRT_2 * rms_height / delta)
}

/// Variances and covariance in a frame rotated by `β` about `y`
/// (Radenkovic & Simonin 2021, Eq. 9 for `(ξ*, ζ*)` with `β*`, and Eq. 26 for `(γ, γ*)` with `β⁻`).
pub fn rotated_moments(dev: &Deviations, beta: f64) -> Moments {
    let (s, c) = beta.sin_cos();
    let (x2, z2) = (dev.delta_xi.powi(2), dev.delta_zeta.powi(2));
    Moments {
        var_a: c * c * x2 + s * s * z2,
        var_b: s * s * x2 + c * c * z2,
        cov: s * c * (x2 - z2),
    }
}

/// Conditional mean and variance of `γ*` given `γ` (Radenkovic & Simonin 2021, Eq. 30; docs/physics.md §2):
/// mean `Cov/Δγ² · γ`, variance `Δγ*² − Cov²/Δγ²`. With `Δγ = 0`, `γ` carries no
/// information and the law of `γ*` is its marginal; the variance is clamped at 0 so that
/// `ρ = ±1` gives an exactly deterministic `γ*`.
pub fn conditional_gamma_star(m: &Moments, gamma: f64) -> (f64, f64) {
    if m.var_a > 0.0 {
        let mean = m.cov / m.var_a * gamma;
        let var = (m.var_b - m.cov * m.cov / m.var_a).max(0.0);
        (mean, var)
    } else {
        (0.0, m.var_b)
    }
}

/// A draw of `γ*` given `γ` from Eq. (30) ([`conditional_gamma_star`]): the conditional mean
/// plus the conditional spread times `z()`, a standard normal asked for only where there is a
/// spread (so a degenerate direction uses no random number).
#[inline]
pub fn draw_gamma_star(m: &Moments, gamma: f64, z: impl FnOnce() -> f64) -> f64 {
    let (mean, var) = conditional_gamma_star(m, gamma);
    if var > 0.0 {
        mean + var.sqrt() * z()
    } else {
        mean
    }
}

/// Standard deviation of the wall inclination in the plane of direction `β`,
/// `Δγ(β) = sqrt(cos²β Δξ² + sin²β Δζ²)` (Radenkovic & Simonin 2021, Eq. 35; root of Eq. 26's first line).
pub fn delta_gamma(dev: &Deviations, beta: f64) -> f64 {
    rotated_moments(dev, beta).delta_gamma()
}

/// `Δγ(β)²` of Eq. (35) for the direction of a velocity with horizontal components
/// `(u, w)`: `cos²β = u²/(u² + w²)` from the velocity, no trigonometry; a vertical velocity
/// takes `β = 0` (docs/physics.md §1).
#[inline]
pub fn delta_gamma_sq_of_direction(u: f64, w: f64, dev: &Deviations) -> f64 {
    let h2 = u * u + w * w;
    if h2 > 0.0 {
        (u * u * dev.delta_xi * dev.delta_xi + w * w * dev.delta_zeta * dev.delta_zeta) / h2
    } else {
        dev.delta_xi * dev.delta_xi
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deg(x: f64) -> f64 {
        x.to_radians()
    }

    #[test]
    fn table1_model_columns() {
        // Radenkovic & Simonin 2021, Table 1, statistical model, (2.5°, 7.5°) wall.
        // The paper prints (4.53°, 6.53°) at β* = 30° and (6.53°, 4.53°) at 60°; those pairs
        // break the rotation invariant Δξ*² + Δζ*² = Δξ² + Δζ² (62.5 deg²) that Eq. (9)
        // implies, so they are misprints: Eq. (9) gives (4.33°, 6.61°). ρ = −0.76 as printed.
        let dev = Deviations {
            delta_xi: deg(2.5),
            delta_zeta: deg(7.5),
        };
        let expect = [
            (0.0, 2.50, 7.50, 0.00),
            (30.0, 4.33, 6.61, -0.76),
            (60.0, 6.61, 4.33, -0.76),
            (90.0, 7.50, 2.50, 0.00),
        ];
        for (b, dx, dz, rho) in expect {
            let m = rotated_moments(&dev, deg(b));
            assert!((m.var_a.sqrt().to_degrees() - dx).abs() < 0.006, "{b}");
            assert!((m.var_b.sqrt().to_degrees() - dz).abs() < 0.006, "{b}");
            assert!((m.rho() - rho).abs() < 0.006, "{b}");
            let trace = (m.var_a + m.var_b).to_degrees().to_degrees();
            assert!((trace - 62.5).abs() < 1e-9);
        }
    }

    #[test]
    fn eq15_matches_table1_surface() {
        // h = 0.37 µm, c_Lx = 12 µm → 2.50°; c_Lz = 4 µm → 7.49°.
        assert!((deviation_from_surface(0.37, 12.0).to_degrees() - 2.498).abs() < 0.001);
        assert!((deviation_from_surface(0.37, 4.0).to_degrees() - 7.495).abs() < 0.001);
        let c = corr_length_from_deviation(0.37, deviation_from_surface(0.37, 4.0)).unwrap();
        assert!((c - 4.0).abs() < 1e-12);
        assert_eq!(corr_length_from_deviation(0.37, 0.0), None);
    }

    #[test]
    fn conditional_law_handles_perfect_correlation_and_zero_spread() {
        // Δζ = 0, β = 60°: ρ = ±1, γ* is a deterministic multiple of γ.
        let dev = Deviations {
            delta_xi: deg(3.8),
            delta_zeta: 0.0,
        };
        let m = rotated_moments(&dev, deg(60.0));
        assert!((m.rho().abs() - 1.0).abs() < 1e-12);
        let (mean, var) = conditional_gamma_star(&m, 0.01);
        assert!(var.abs() < 1e-18);
        assert!((mean - deg(60.0).tan() * 0.01).abs() < 1e-12);
        // Δγ = 0 (β = 90° on a 2-D wall): marginal law, no division by zero.
        let m = rotated_moments(&dev, deg(90.0));
        let (mean, var) = conditional_gamma_star(&m, 0.0);
        assert!(mean.is_finite() && var.is_finite());
    }
}
