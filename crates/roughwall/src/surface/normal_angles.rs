//! What a wall's deviations `Δξ`, `Δζ` are, and the Garcia–Stoll surface whose triangles
//! have them (docs/physics.md §4, "The deviations a wall is given by").
//!
//! The stochastic models draw the angles of the wall's normal (Radenkovic & Simonin 2021,
//! Eqs. 20–21 from the moments of `ξ'`, `ζ'`, Eqs. 4, 7–9), and `surface`, `deterministic`
//! and `scan` measure `Δξ`, `Δζ` as the standard deviations of those angles over the
//! triangles. Eq. (15), `Δ = √2 h/c_L`, is their first-order value: it is the rms *slope*
//! of the continuous surface (Eq. 14). A triangulated grid has less, for two reasons:
//!
//! - a triangle's slope is a finite difference over the spacing `δ`, with rms
//!   `√2 h/c_L · √((c_L/δ)² (1 − e^(−δ²/c_L²)))` (from the autocorrelation of Eqs. 1–2);
//! - the angle is not the slope: `sin ξ' = s_x / √(1 + s_x² + s_z²)` (Eqs. 3–4), which
//!   bends the tails in, and more so when the other slope is large.
//!
//! On the automatic grid (`δ = c_L,min/8`) the two take 0.3–2.1 % off ([`expected_deviations`]:
//! (4°, 1°) → (3.965°, 0.997°); (2.5°, 7.5°) → (2.474°, 7.344°)).
//! [`expected_deviations`] predicts what the triangles of a generated surface measure, and
//! [`slopes_for_deviations`] inverts it: the rms slopes (hence `c_L = √2 h/slope`) that give
//! the triangles the deviations wanted.

use crate::wall::Deviations;

/// Half-width of the quadrature in standard deviations (the Gaussian weight beyond is
/// `< 1e−17`).
const QUADRATURE_HALF_WIDTH: f64 = 9.0;

/// Quadrature nodes per axis. The trapezoid rule on a Gaussian weight converges
/// exponentially in the node count; with 181 nodes (step 0.1 σ) the result is exact to
/// round-off for the smooth `asin` integrand.
const QUADRATURE_NODES: usize = 181;

/// rms finite-difference slope over a spacing `δ` of a Gaussian-correlated field of rms
/// height `h` and correlation length `c_L` (`R = h² e^(−τ²/c_L²)`, Radenkovic & Simonin
/// 2021, Eqs. 1–2 and 14; docs/physics.md §4): `√2 h/c_L · √((c_L/δ)² (1 − e^(−δ²/c_L²)))`,
/// written with the continuous rms slope `s = √2 h/c_L`.
pub fn grid_slope_rms(slope_rms: f64, corr_length: f64, spacing: f64) -> f64 {
    slope_rms * finite_difference_ratio(spacing / corr_length)
}

/// The factor `√((1 − e^(−x²))/x²)`, `x = δ/c_L`, by which finite differences over `δ` lower
/// the rms slope of a Gaussian-correlated field (docs/physics.md §4); 1 at `x = 0`.
pub fn finite_difference_ratio(spacing_over_corr_length: f64) -> f64 {
    let x2 = spacing_over_corr_length * spacing_over_corr_length;
    // (1 − e^(−x²))/x² without cancellation for small x.
    let ratio = if x2 < 1e-8 {
        1.0 - 0.5 * x2
    } else {
        -(-x2).exp_m1() / x2
    };
    ratio.sqrt()
}

/// Standard deviations of the normal's angles `ξ'`, `ζ'` (Radenkovic & Simonin 2021,
/// Eqs. 3–4: `sin ξ' = s_x/√(1 + s_x² + s_z²)`, the same for `ζ'` with `s_z`) when the
/// slopes `(s_x, s_z)` are independent centred Gaussians of rms `slope_rms`.
///
/// Within a triangle the two slopes correlate by `½ √((1 − e^(−δ²/c_Lx²))(1 − e^(−δ²/c_Lz²)))`
/// (`< 0.003` on the automatic grid), which moves the result by its square: it is ignored.
pub fn normal_angle_deviations(slope_rms: [f64; 2]) -> Deviations {
    let n = QUADRATURE_NODES;
    let step = 2.0 * QUADRATURE_HALF_WIDTH / (n - 1) as f64;
    let u: Vec<f64> = (0..n)
        .map(|i| -QUADRATURE_HALF_WIDTH + i as f64 * step)
        .collect();
    let w: Vec<f64> = u.iter().map(|u| (-0.5 * u * u).exp()).collect();
    let norm: f64 = w.iter().sum();
    let (mut xi2, mut zeta2) = (0.0, 0.0);
    for (ux, wx) in u.iter().zip(&w) {
        let sx = ux * slope_rms[0];
        let (mut ax, mut az) = (0.0, 0.0);
        for (uz, wz) in u.iter().zip(&w) {
            let sz = uz * slope_rms[1];
            let r = (1.0 + sx * sx + sz * sz).sqrt();
            ax += wz * (sx / r).asin().powi(2);
            az += wz * (sz / r).asin().powi(2);
        }
        xi2 += wx * ax;
        zeta2 += wx * az;
    }
    let norm2 = norm * norm;
    Deviations {
        delta_xi: (xi2 / norm2).sqrt(),
        delta_zeta: (zeta2 / norm2).sqrt(),
    }
}

/// The deviations (rad) the triangles of a generated Garcia–Stoll surface have on average:
/// rms height `h`, correlation lengths `c_L` (`None`: flat along that axis), spacing `δ`.
pub fn expected_deviations(
    rms_height: f64,
    corr_length: [Option<f64>; 2],
    spacing: f64,
) -> Deviations {
    let slope = |c: Option<f64>| {
        c.map_or(0.0, |c| {
            grid_slope_rms(
                crate::wall::deviation_from_surface(rms_height, c),
                c,
                spacing,
            )
        })
    };
    normal_angle_deviations([slope(corr_length[0]), slope(corr_length[1])])
}

/// Largest deviation (rad) a wall may be given: the models' limit of 20°.
const MAX_TARGET_RAD: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// The continuous rms slopes `√2 h/c_L` (Eq. 14) along `x` and `z` whose surface, generated
/// on a grid of spacing `c_L,min / spacing_per_corr_length`, has triangles with the normal
/// angle deviations `target` (rad) on average ([`expected_deviations`]). A zero deviation
/// stays zero (a flat axis). `None` when a deviation is negative, beyond 20° or not finite.
///
/// Fixed point on `slope ← slope · target/expected` per axis: the map is within a few per
/// cent of the identity, so it converges to round-off in a handful of steps.
pub fn slopes_for_deviations(target: Deviations, spacing_per_corr_length: f64) -> Option<[f64; 2]> {
    let t = [target.delta_xi, target.delta_zeta];
    if t.iter()
        .any(|&d| !(d.is_finite() && (0.0..=MAX_TARGET_RAD).contains(&d)))
        || !(spacing_per_corr_length.is_finite() && spacing_per_corr_length >= 1.0)
    {
        return None;
    }
    let mut s = t;
    for _ in 0..100 {
        // Correlation lengths for h = 1 (only h/c_L and δ/c_L matter).
        let c = s.map(|s| (s > 0.0).then(|| std::f64::consts::SQRT_2 / s));
        let c_min = c.iter().flatten().copied().fold(f64::INFINITY, f64::min);
        if !c_min.is_finite() {
            return Some([0.0; 2]);
        }
        let e = expected_deviations(1.0, c, c_min / spacing_per_corr_length);
        let e = [e.delta_xi, e.delta_zeta];
        let mut worst = 0.0f64;
        for k in 0..2 {
            if t[k] > 0.0 {
                worst = worst.max((e[k] / t[k] - 1.0).abs());
                s[k] *= t[k] / e[k];
            }
        }
        if worst < 1e-13 {
            return Some(s);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deg(d: Deviations) -> [f64; 2] {
        [d.delta_xi.to_degrees(), d.delta_zeta.to_degrees()]
    }

    #[test]
    fn small_slopes_are_their_own_angles() {
        // Eq. (15) is the first order: at 0.01° the angle is the slope to O(σ²) ≈ 1e-7.
        let s = 0.01f64.to_radians();
        let d = normal_angle_deviations([s, 2.0 * s]);
        assert!((d.delta_xi / s - 1.0).abs() < 5e-7);
        assert!((d.delta_zeta / (2.0 * s) - 1.0).abs() < 5e-7);
    }

    #[test]
    fn a_profile_is_the_std_of_atan() {
        // With s_z = 0, ξ' = atan(s_x): E[atan² s] for σ = 0.3 by a fine independent
        // quadrature (Simpson on ±12σ, 24 001 points).
        let sigma = 0.3f64;
        let n = 24_000;
        let (a, b) = (-12.0 * sigma, 12.0 * sigma);
        let h = (b - a) / n as f64;
        let f = |s: f64| s.atan().powi(2) * (-0.5 * (s / sigma).powi(2)).exp();
        let mut sum = f(a) + f(b);
        for i in 1..n {
            let x = a + i as f64 * h;
            sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(x);
        }
        let var = sum * h / 3.0 / (sigma * (2.0 * std::f64::consts::PI).sqrt());
        let d = normal_angle_deviations([sigma, 0.0]);
        assert!(
            (d.delta_xi - var.sqrt()).abs() < 1e-12,
            "{} {}",
            d.delta_xi,
            var.sqrt()
        );
        assert_eq!(d.delta_zeta, 0.0);
    }

    #[test]
    fn the_other_slope_bends_the_angle_in() {
        // A steep cross slope lowers Δξ (the normal tilts away from x): second order.
        let a = normal_angle_deviations([0.05, 0.0]).delta_xi;
        let b = normal_angle_deviations([0.05, 0.15]).delta_xi;
        assert!(
            b < a && a - b > 0.5 * 0.05 * 0.15f64.powi(2) * 0.9,
            "{a} {b}"
        );
    }

    #[test]
    fn mirror_and_swap_symmetric() {
        let d = normal_angle_deviations([0.04, 0.13]);
        let e = normal_angle_deviations([0.13, 0.04]);
        assert!((d.delta_xi - e.delta_zeta).abs() < 1e-15);
        assert!((d.delta_zeta - e.delta_xi).abs() < 1e-15);
    }

    #[test]
    fn the_grid_factor_is_physics_md_s() {
        // 0.985 at δ = c_L/4 (docs/physics.md §4), 1 as δ → 0.
        let r = grid_slope_rms(1.0, 4.0, 1.0);
        assert!((r - 0.98458).abs() < 1e-5, "{r}");
        assert!((grid_slope_rms(1.0, 1.0, 1e-6) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_sec3_wall_on_the_automatic_grid() {
        // (2.5°, 7.5°) with c_L from Eq. (15), δ = c_Lz/8: the triangles have
        // (2.474°, 7.344°); the 64-surface ensembles of results/calibration measured
        // 2.485° ± 0.01° and 7.331° ± 0.02° on such grids.
        let c = [
            crate::wall::corr_length_from_deviation(1.0, 2.5f64.to_radians()),
            crate::wall::corr_length_from_deviation(1.0, 7.5f64.to_radians()),
        ];
        let e = deg(expected_deviations(1.0, c, c[1].unwrap() / 8.0));
        assert!(
            (e[0] - 2.474).abs() < 0.001 && (e[1] - 7.344).abs() < 0.001,
            "{e:?}"
        );
    }

    #[test]
    fn the_inverse_gives_the_target_back() {
        for (xi, zeta) in [
            (2.5, 7.5),
            (5.0, 5.0),
            (4.0, 1.0),
            (3.8, 0.0),
            (0.0, 6.0),
            (20.0, 1.0),
        ] {
            let t = Deviations {
                delta_xi: f64::to_radians(xi),
                delta_zeta: f64::to_radians(zeta),
            };
            let s = slopes_for_deviations(t, 8.0).unwrap();
            let c = s.map(|s| (s > 0.0).then(|| std::f64::consts::SQRT_2 / s));
            let c_min = c.iter().flatten().copied().fold(f64::INFINITY, f64::min);
            let e = expected_deviations(1.0, c, c_min / 8.0);
            assert!((e.delta_xi - t.delta_xi).abs() < 1e-12 * (1.0 + t.delta_xi));
            assert!((e.delta_zeta - t.delta_zeta).abs() < 1e-12 * (1.0 + t.delta_zeta));
            // The slopes are steeper than the angles: by a few per cent up to 7.5°, 12.6 % at
            // 20° (the asin's tails).
            for k in 0..2 {
                let tk = [t.delta_xi, t.delta_zeta][k];
                assert!(s[k] >= tk && s[k] <= tk * 1.13, "{xi} {zeta}: {s:?}");
            }
        }
        let flat = Deviations {
            delta_xi: 0.0,
            delta_zeta: 0.0,
        };
        assert_eq!(slopes_for_deviations(flat, 8.0), Some([0.0; 2]));
        let bad = Deviations {
            delta_xi: f64::NAN,
            delta_zeta: 0.0,
        };
        assert_eq!(slopes_for_deviations(bad, 8.0), None);
        let steep = Deviations {
            delta_xi: 0.4,
            delta_zeta: 0.0,
        };
        assert_eq!(slopes_for_deviations(steep, 8.0), None);
    }
}
