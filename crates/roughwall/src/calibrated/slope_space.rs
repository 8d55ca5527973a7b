//! The `calibrated` model's coordinates: the wall's *slopes*, not its normal's angles.
//!
//! Why: a point particle's first hit is decided by the height profile under its path
//! alone, and stretching the heights by `k` maps the path of slope `tan α` and a profile
//! of slope spread `σ` onto `k tan α` and `k σ` with the same hit points. So the first
//! element's slope along the path, over `σ(β)` (the profile's slope spread along the
//! direction `β`), has one law for every wall and direction at one `tan α / σ(β)`
//! (Gaussian surface of Gaussian correlation: its profiles differ only by these scales).
//! The normal's angles `(γ, γ*)` of Radenkovic & Simonin 2021 (Eqs. 20–21) are not that
//! variable: `γ = asin(s_l/N)` with `N = √(1 + s_l² + s_t²)` shrinks with the transverse
//! slope `s_t`, so at one `α/Δγ` the law of `γ/Δγ` moves with `Δγ*`, and a table measured on
//! one wall did not transfer to another (docs/design-notes.md, "Slopes, not angles": at
//! α⁻ = −5°, `Δγ` = 6.5°, the angle tables' bias in mean α⁺ went from −0.003° to −0.088° as
//! `Δγ*` went from 2.5° to 8.7°, the slope tables' to −0.049°). The transverse slope given the
//! profile is exactly Gaussian too: `s_t = (Cov/σ_l²) s_l + N(0, σ_t² − Cov²/σ_l²)`
//! (Eq. 30 in slopes; a Gaussian correlation's cross-covariances with the profile are
//! proportional to the along-path slope's), so no shrink factor is needed there either.
//!
//! The wall is given by its normal-angle deviations `(Δξ, Δζ)` (Eq. 15, as measured on a
//! surface: the RMS of `asin` of the normal's components); [`slope_deviations`] turns them
//! into the slope spreads `(σ_x, σ_z)` of a Gaussian slope field with those angle spreads.

use super::constants::{CACHED_WALLS, ITERATIONS, NODES, PROPOSAL_EPS, PROPOSAL_X_MAX, STEP};
use crate::stochastic::shadow_effect::ShadowSampler;
use crate::wall::{delta_gamma_sq_of_direction, Deviations};
use nalgebra::Vector3;
use std::cell::RefCell;

/// The slope spreads `(σ_x, σ_z)` (tangents) of a Gaussian slope field whose normal
/// angles have the RMS `(Δξ, Δζ)` of `dev` (`ξ' = asin(h_x/N)`, `N = √(1 + h_x² + h_z²)`;
/// the measurement of `crate::surface::stats::measured_deviations`). A fixed point of
/// `σ ← σ Δ/RMS(σ)` (about 1 ms: some 10 steps of a 57 × 57 rule), kept per thread for the
/// last `CACHED_WALLS` walls: a CFD code calls the model once per wall hit, often
/// alternating between a few walls (a thread cycling through more pays the 1 ms per hit).
pub fn slope_deviations(dev: &Deviations) -> Deviations {
    thread_local! {
        static CACHE: RefCell<WallCache> = const { RefCell::new(([None; CACHED_WALLS], 0)) };
    }
    CACHE.with(|cache| {
        let mut cache = cache.borrow_mut();
        if let Some((_, s)) = cache.0.iter().flatten().find(|(d, _)| d == dev) {
            return *s;
        }
        let s = invert_angle_rms(dev);
        let next = cache.1;
        cache.0[next] = Some((*dev, s));
        cache.1 = (next + 1) % CACHED_WALLS;
        s
    })
}

/// `(angle deviations, slope spreads)` of the walls kept, and the next slot to replace.
type WallCache = ([Option<(Deviations, Deviations)>; CACHED_WALLS], usize);

fn invert_angle_rms(dev: &Deviations) -> Deviations {
    invert_counted(dev).0
}

/// [`invert_angle_rms`] and the fixed-point steps it took.
fn invert_counted(dev: &Deviations) -> (Deviations, usize) {
    let clean = |d: f64| if d.is_finite() && d > 0.0 { d } else { 0.0 };
    let (dx, dz) = (clean(dev.delta_xi), clean(dev.delta_zeta));
    let (mut sx, mut sz) = (dx.tan(), dz.tan());
    let mut steps = 0;
    for _ in 0..ITERATIONS {
        steps += 1;
        let (rx, rz) = angle_rms(sx, sz);
        let nx = if rx > 0.0 { sx * dx / rx } else { sx };
        let nz = if rz > 0.0 { sz * dz / rz } else { sz };
        // Angles saturate at 90°: a spread no slope field reaches keeps the last finite step.
        if !(nx.is_finite() && nz.is_finite()) {
            break;
        }
        let done = (nx - sx).abs() <= 1e-15 * sx && (nz - sz).abs() <= 1e-15 * sz;
        (sx, sz) = (nx, nz);
        if done {
            break;
        }
    }
    (
        Deviations {
            delta_xi: sx,
            delta_zeta: sz,
        },
        steps,
    )
}

/// RMS of `asin(h_x/N)` and `asin(h_z/N)` for independent `h_x ~ N(0, σ_x²)`,
/// `h_z ~ N(0, σ_z²)`.
fn angle_rms(sx: f64, sz: f64) -> (f64, f64) {
    let weights: [f64; (2 * NODES + 1) as usize] = std::array::from_fn(|k| {
        let t = (k as i32 - NODES) as f64 * STEP;
        (-0.5 * t * t).exp()
    });
    let (mut ax, mut az, mut wsum) = (0.0, 0.0, 0.0);
    for (i, wi) in (-NODES..=NODES).zip(weights) {
        let hx = sx * (i as f64 * STEP);
        for (j, wj) in (-NODES..=NODES).zip(weights) {
            let w = wi * wj;
            let hz = sz * (j as f64 * STEP);
            let n = (1.0 + hx * hx + hz * hz).sqrt();
            ax += w * (hx / n).asin().powi(2);
            az += w * (hz / n).asin().powi(2);
            wsum += w;
        }
    }
    ((ax / wsum).sqrt(), (az / wsum).sqrt())
}

/// The slopes `(s_l, s_t)` of the element of unit normal `n` along and across the
/// direction `β` (`s_l ≈ γ`, `s_t ≈ γ*` of Eqs. 20–21 at small angles; heights `h` with
/// `n ∝ (−h_x, 1, −h_z)`). A normal in the mean plane gives infinite slopes.
#[inline]
pub fn slopes_from_normal(n: &Vector3<f64>, beta: f64) -> (f64, f64) {
    let (s, c) = beta.sin_cos();
    let (hx, hz) = (-n.x / n.y, -n.z / n.y);
    (c * hx - s * hz, s * hx + c * hz)
}

/// The unit normal of slopes `(s_l, s_t)` seen from direction `β` (`(sin β, cos β)`
/// given): the inverse of [`slopes_from_normal`], the exact form of Radenkovic & Simonin
/// 2021, Eq. (23) with slopes for the angles `(γ, γ*)`.
#[inline]
pub fn normal_from_slopes(s_l: f64, s_t: f64, (s, c): (f64, f64)) -> Vector3<f64> {
    let hx = c * s_l + s * s_t;
    let hz = -s * s_l + c * s_t;
    Vector3::new(-hx, 1.0, -hz) / (1.0 + hx * hx + hz * hz).sqrt()
}

/// `tan α / σ(β)` of the velocity `u` on the wall of slope spreads `slopes`
/// ([`slope_deviations`]; `σ(β)` of Eq. 35 with slopes for angles): the reduced incidence
/// of the calibrated tables. A wall without slope in that plane gives `±∞`, a vertical
/// velocity `±10¹²/σ`.
#[inline]
pub fn reduced_slope(u: &Vector3<f64>, slopes: &Deviations) -> f64 {
    let h = (u.x * u.x + u.z * u.z).sqrt();
    let tan_alpha = u.y / h.max(1e-12 * u.y.abs());
    tan_alpha / delta_gamma_sq_of_direction(u.x, u.z, slopes).sqrt()
}

/// The calibrated model's proposal for the element at reduced incidence `x`: the shadow law
/// of Radenkovic & Simonin 2021, Eq. (32) (continued to rising particles, `x > 0`), at the
/// roughness [`PROPOSAL_EPS`] and the angle `x ε` (`x` clamped to `±`[`PROPOSAL_X_MAX`]; a
/// NaN counts as grazing). A draw over `ε` is the element's slope along the path over `σ(β)`.
/// The model and `rebound calibrate` both draw from it.
#[inline]
pub fn proposal(x: f64) -> ShadowSampler {
    let x_law = if x.is_nan() { 0.0 } else { x };
    let alpha = x_law.clamp(-PROPOSAL_X_MAX, PROPOSAL_X_MAX) * PROPOSAL_EPS;
    ShadowSampler::for_trajectory(alpha, PROPOSAL_EPS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_spreads_reproduce_the_angle_spreads() {
        for (dx, dz) in [
            (2.5f64, 7.5f64),
            (6.5, 8.7),
            (3.8, 0.0),
            (5.0, 5.0),
            (20.0, 1.0),
        ] {
            let dev = Deviations {
                delta_xi: dx.to_radians(),
                delta_zeta: dz.to_radians(),
            };
            let s = slope_deviations(&dev);
            let (rx, rz) = angle_rms(s.delta_xi, s.delta_zeta);
            assert!((rx - dev.delta_xi).abs() < 1e-12, "{dx} {dz}: {rx}");
            assert!((rz - dev.delta_zeta).abs() < 1e-12, "{dx} {dz}: {rz}");
            // A slope spreads more than its angle, and more so with transverse slope.
            assert!(s.delta_xi >= dev.delta_xi.tan() - 1e-15);
        }
        // The series' first terms: RMS² = σ_x²(1 − 2σ_x² − σ_z²) + O(σ⁶).
        let s = 0.1f64;
        let (r, _) = angle_rms(s, 0.0);
        assert!((r * r - s * s * (1.0 - 2.0 * s * s)).abs() < 20.0 * s.powi(6));
        let (r, _) = angle_rms(s, s);
        assert!((r * r - s * s * (1.0 - 3.0 * s * s)).abs() < 20.0 * s.powi(6));
    }

    #[test]
    fn the_inversion_converges_in_a_few_steps_and_takes_any_input() {
        // Each step shrinks the error by about 2σ²: few steps in the low-roughness range,
        // more far beyond it.
        for (dx, dz, most) in [
            (2.5f64, 7.5f64, 12),
            (3.8, 0.0, 12),
            (0.0, 0.0, 2),
            (10.0, 10.0, 20),
            (30.0, 30.0, 60),
        ] {
            let dev = Deviations {
                delta_xi: dx.to_radians(),
                delta_zeta: dz.to_radians(),
            };
            let (s, steps) = invert_counted(&dev);
            assert!(steps <= most, "({dx}, {dz}): {steps} steps");
            assert!(s.delta_xi.is_finite() && s.delta_zeta.is_finite());
        }
        // Angles no slope field reaches, or no number: finite spreads, no hang.
        for d in [f64::NAN, f64::INFINITY, -1.0, 1.6, 3.0] {
            let (s, steps) = invert_counted(&Deviations {
                delta_xi: d,
                delta_zeta: 0.1,
            });
            assert!(steps <= ITERATIONS && s.delta_xi.is_finite() && s.delta_zeta.is_finite());
        }
    }

    #[test]
    fn the_cache_gives_the_inversion_for_any_order_of_walls() {
        let walls: Vec<Deviations> = (0..2 * CACHED_WALLS)
            .map(|k| Deviations {
                delta_xi: (1.0 + 0.3 * k as f64).to_radians(),
                delta_zeta: (8.0 - 0.2 * k as f64).to_radians(),
            })
            .collect();
        // Cycling through more walls than are kept, and back: every answer is the inversion's.
        for w in walls
            .iter()
            .chain(walls.iter().rev())
            .chain(walls.iter().step_by(3))
        {
            assert_eq!(slope_deviations(w), invert_angle_rms(w));
        }
    }

    #[test]
    fn slopes_and_normals_round_trip() {
        for beta in [-2.0f64, -0.3, 0.0, 0.7, std::f64::consts::FRAC_PI_2, 3.0] {
            for (sl, st) in [(0.0, 0.0), (0.12, -0.05), (-0.4, 0.3), (1.5, 2.0)] {
                let n = normal_from_slopes(sl, st, beta.sin_cos());
                assert!((n.norm() - 1.0).abs() < 1e-14);
                let (a, b) = slopes_from_normal(&n, beta);
                assert!(
                    (a - sl).abs() < 1e-13 && (b - st).abs() < 1e-13,
                    "{beta} {sl} {st}"
                );
            }
        }
        // Small angles: the slopes are the paper's (γ, γ*).
        let n = crate::angles::normal_from_gamma(1e-4, -2e-4, 0.6);
        let (sl, st) = slopes_from_normal(&n, 0.6);
        assert!((sl - 1e-4).abs() < 1e-11 && (st + 2e-4).abs() < 1e-11);
    }

    #[test]
    fn reduced_slope_is_tan_alpha_over_the_profile_spread() {
        let slopes = Deviations {
            delta_xi: 0.05,
            delta_zeta: 0.15,
        };
        let u = crate::angles::velocity_from_angles(2.0, (-10f64).to_radians(), 0.0);
        let x = reduced_slope(&u, &slopes);
        assert!((x - (-10f64).to_radians().tan() / 0.05).abs() < 1e-12);
        let u = crate::angles::velocity_from_angles(2.0, (-10f64).to_radians(), 1.0);
        let sigma = (1f64.cos().powi(2) * 0.05f64.powi(2) + 1f64.sin().powi(2) * 0.0225).sqrt();
        assert!((reduced_slope(&u, &slopes) - (-10f64).to_radians().tan() / sigma).abs() < 1e-12);
        let down = reduced_slope(&Vector3::new(0.0, -1.0, 0.0), &slopes);
        assert!(down.is_finite() && down < -1e12);
    }
}
