//! Frames and angles (docs/physics.md §1; Radenkovic & Simonin 2021, Sec. 3.1, Eqs. 17–24, 43).
//!
//! Mean wall plane `y = 0`, `j` into the flow; `x`, `z` the principal directions of
//! the roughness. Everything is in radians; degrees are for people.

use nalgebra::Vector3;
use std::f64::consts::{FRAC_PI_2, PI};

/// Vertical and transverse angles `(α, β)` of a velocity (Radenkovic & Simonin 2021, Sec. 3.1).
///
/// `α = asin(v/|U|)`, `β = −sgn(w)·acos(u/(|U| cos α))`, written as `atan2(−w, u)`, which is
/// the same angle and stays defined for `w = 0`. With no horizontal speed (`α = ±90°`) `β` is
/// undefined and taken as 0 (docs/physics.md §1). A zero velocity gives `(0, 0)`.
pub fn incident_angles(u: &Vector3<f64>) -> (f64, f64) {
    let speed = u.norm();
    if speed == 0.0 {
        return (0.0, 0.0);
    }
    let alpha = (u.y / speed).clamp(-1.0, 1.0).asin();
    let beta = if u.x == 0.0 && u.z == 0.0 {
        0.0
    } else {
        (-u.z).atan2(u.x)
    };
    (alpha, beta)
}

/// The velocity of speed `speed` with angles `(α, β)`: the inverse of [`incident_angles`].
pub fn velocity_from_angles(speed: f64, alpha: f64, beta: f64) -> Vector3<f64> {
    Vector3::new(
        speed * alpha.cos() * beta.cos(),
        speed * alpha.sin(),
        -speed * alpha.cos() * beta.sin(),
    )
}

/// Wraps an angle into `(−π, π]` (docs/physics.md §1: transverse deviation `β⁺ − β⁻`).
pub fn wrap_pi(x: f64) -> f64 {
    let mut y = x.rem_euclid(2.0 * PI);
    if y > PI {
        y -= 2.0 * PI;
    }
    y
}

/// Rebound angle in the `x–y` plane, `α⁺_xy = arctan(tan α⁺ / cos β⁺)` (Radenkovic & Simonin 2021, Eq. 43).
///
/// At `cos β⁺ = 0` the arctangent tends to `±90°`; the `0/0` case (grazing rebound
/// at `β⁺ = ±90°`) is taken as 0 instead of NaN.
pub fn alpha_xy(alpha_out: f64, beta_out: f64) -> f64 {
    let (t, c) = (alpha_out.tan(), beta_out.cos());
    if t == 0.0 {
        return 0.0;
    }
    if c == 0.0 {
        return FRAC_PI_2.copysign(t);
    }
    (t / c).atan()
}

/// `α⁺_xy` of Eq. (43) from the velocity itself: `tan α⁺ / cos β⁺ = v/u`, so
/// `α⁺_xy = arctan(v/u)` (one arctangent, no round trip through the angles); `±90°` for
/// `u = 0`, `v ≠ 0`, and 0 for a velocity in the wall plane.
#[inline]
pub fn alpha_xy_of_velocity(u: &Vector3<f64>) -> f64 {
    if u.y == 0.0 {
        0.0
    } else if u.x == 0.0 {
        FRAC_PI_2.copysign(u.y)
    } else {
        (u.y / u.x).atan()
    }
}

/// Horizontal unit vector along the incident plane, `t_p = cos β i − sin β k` (Radenkovic & Simonin 2021, Eq. 18).
pub fn t_p(beta: f64) -> Vector3<f64> {
    Vector3::new(beta.cos(), 0.0, -beta.sin())
}

/// Unit vector orthogonal to the incident plane, `s_p = t_p × j` (Radenkovic & Simonin 2021, Eq. 22).
pub fn s_p(beta: f64) -> Vector3<f64> {
    t_p(beta).cross(&Vector3::y())
}

/// Normal-vector angle fluctuations `(ξ', ζ')` from `(γ, γ*)` (Radenkovic & Simonin 2021, Eq. 23).
pub fn xi_zeta_from_gamma(gamma: f64, gamma_star: f64, beta_in: f64) -> (f64, f64) {
    xi_zeta_rotated(gamma, gamma_star, beta_in.sin_cos())
}

/// Eq. (23) with `(sin β⁻, cos β⁻)` given (computed once per incident direction).
#[inline]
pub fn xi_zeta_rotated(gamma: f64, gamma_star: f64, (s, c): (f64, f64)) -> (f64, f64) {
    (c * gamma + s * gamma_star, -s * gamma + c * gamma_star)
}

/// Unit wall normal from the sampled angles (Radenkovic & Simonin 2021, Eqs. 3, 10, 23; docs/physics.md §2).
///
/// `ξ = π/2 + ξ'`, `ζ = π/2 + ζ'`, `n = (cos ξ, cos η, cos ζ)` with `cos η = sqrt(1 − cos²ξ − cos²ζ)`,
/// an exact unit vector (Eq. 24 is only its small-angle value). If the angles are so large
/// that `cos²ξ + cos²ζ > 1` (far outside the low-roughness range) the tangential part is
/// rescaled onto the unit sphere with `n_y = 0` rather than returning NaN.
pub fn normal_from_gamma(gamma: f64, gamma_star: f64, beta_in: f64) -> Vector3<f64> {
    let (xi_p, zeta_p) = xi_zeta_from_gamma(gamma, gamma_star, beta_in);
    normal_from_xi_zeta(xi_p, zeta_p)
}

/// Unit wall normal from the fluctuations `(ξ', ζ')` (Radenkovic & Simonin 2021, Eqs. 3, 10;
/// see [`normal_from_gamma`]).
#[inline]
pub fn normal_from_xi_zeta(xi_p: f64, zeta_p: f64) -> Vector3<f64> {
    // cos(π/2 + a) = −sin a
    let nx = -xi_p.sin();
    let nz = -zeta_p.sin();
    let t2 = nx * nx + nz * nz;
    if t2 >= 1.0 {
        let s = t2.sqrt();
        return Vector3::new(nx / s, 0.0, nz / s);
    }
    Vector3::new(nx, (1.0 - t2).sqrt(), nz)
}

/// Fluctuations `(ξ', ζ') = (ξ − π/2, ζ − π/2)` of a unit normal's angles with `x` and `z` (docs/physics.md §1).
pub fn xi_zeta_of_normal(n: &Vector3<f64>) -> (f64, f64) {
    (
        n.x.clamp(-1.0, 1.0).acos() - FRAC_PI_2,
        n.z.clamp(-1.0, 1.0).acos() - FRAC_PI_2,
    )
}

/// Wall inclination angles `(γ, γ*)` of a unit normal seen from incidence `β⁻`
/// (Radenkovic & Simonin 2021, Eqs. 20–21 as corrected in docs/physics.md §2).
pub fn gamma_from_normal(n: &Vector3<f64>, beta_in: f64) -> (f64, f64) {
    let (xi_p, zeta_p) = xi_zeta_of_normal(n);
    gamma_rotated(xi_p, zeta_p, beta_in.sin_cos())
}

/// Eqs. (20–21) from `(ξ', ζ')` with `(sin β⁻, cos β⁻)` given (computed once per incident
/// direction): the inverse of [`xi_zeta_rotated`].
#[inline]
pub fn gamma_rotated(xi_p: f64, zeta_p: f64, (s, c): (f64, f64)) -> (f64, f64) {
    (c * xi_p - s * zeta_p, s * xi_p + c * zeta_p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_round_trip() {
        for &a in &[-0.01f64, -12.5, -45.0, -89.0] {
            for &b in &[-170.0f64, -60.0, 0.0, 30.0, 90.0, 180.0] {
                let u = velocity_from_angles(3.0, a.to_radians(), b.to_radians());
                let (a2, b2) = incident_angles(&u);
                assert!((a2 - a.to_radians()).abs() < 1e-12);
                assert!(wrap_pi(b2 - b.to_radians()).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn beta_sign_convention() {
        // docs/physics.md §1: β⁻ = +60° means w < 0
        let u = velocity_from_angles(1.0, -0.2, 60f64.to_radians());
        assert!(u.z < 0.0);
    }

    #[test]
    fn gamma_normal_round_trip_is_exact_for_the_angles_used() {
        let beta = 0.7;
        let n = normal_from_gamma(0.05, -0.03, beta);
        assert!((n.norm() - 1.0).abs() < 1e-14);
        let (g, gs) = gamma_from_normal(&n, beta);
        // ξ' = acos(n_x) − π/2 = −asin(n_x) = ξ' exactly, likewise ζ'.
        assert!((g - 0.05).abs() < 1e-12 && (gs + 0.03).abs() < 1e-12);
    }

    #[test]
    fn wrap_into_half_open_interval() {
        assert!((wrap_pi(PI) - PI).abs() < 1e-15);
        assert!((wrap_pi(-PI) - PI).abs() < 1e-15);
        assert!((wrap_pi(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-12);
    }

    #[test]
    fn alpha_xy_from_the_velocity_is_eq43() {
        for (a, b) in [(0.3, 0.0), (0.3, 0.5), (1.2, -2.0), (0.01, 3.0), (1.5, 1.0)] {
            let u = velocity_from_angles(2.5, a, b);
            assert!(
                (alpha_xy_of_velocity(&u) - alpha_xy(a, b)).abs() < 1e-12,
                "{a} {b}"
            );
        }
        assert_eq!(
            alpha_xy_of_velocity(&Vector3::new(0.0, 1.0, 2.0)),
            FRAC_PI_2
        );
        assert_eq!(alpha_xy_of_velocity(&Vector3::new(1.0, 0.0, 2.0)), 0.0);
    }

    #[test]
    fn alpha_xy_limits() {
        assert!((alpha_xy(0.3, 0.0) - 0.3).abs() < 1e-15);
        assert_eq!(alpha_xy(0.0, FRAC_PI_2), 0.0);
        assert!(alpha_xy(0.3, 0.5).is_finite());
    }
}
