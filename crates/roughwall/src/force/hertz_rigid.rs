//! `hertz-rigid`: a rigid prolate spheroid in elliptical Hertz contact with a rigid wall,
//! effective mass from its lever arm, energy balance (docs/physics.md §7). No fitted constants.
//!
//! 1. Lowest point, lever arm `d`, principal radii `R'`, `R''` ([`Spheroid::lowest_point`]).
//! 2. Effective mass at the contact, `1/m_eff = 1/m + d²/I` (frictionless contact: the normal
//!    impulse acts along the wall normal through the lowest point).
//! 3. Elliptical Hertz contact (Johnson 1985, *Contact Mechanics*, §4.2): `F = k δ^{3/2}`,
//!    `k = (4/3) E* √R_e F₂^{−3/2}` with `R_e = √(R'R'')` and Johnson's approximation of the
//!    ellipticity factor, `F₂ ≈ 1 − [(R'/R'')^0.0684 − 1]^1.531` (R' ≥ R''; Johnson 1985, §4.2,
//!    after Fig. 4.4). [`stiffness_exact`] solves the elliptic-integral equations instead; the
//!    test `johnson_f2_against_exact_elliptic_solution` bounds the approximation's error, and
//!    beyond `R'/R''` = 100 (λ > 10 lying flat), where the approximation degrades, the exact
//!    solution is used.
//! 4. Energy balance `½ m_eff U_N² = (2/5) k δ_max^{5/2}`, `F_max = k δ_max^{3/2}` (as Eqs. 1–2 of
//!    Hu et al. 2021 for the sphere).
//!
//! Hence `F_max = ξ(λ, β) ρ^0.6 U_N^1.2 D² E*^0.4` exactly, as in Hu et al. 2021, Eq. (7).
use super::hertz_sphere::XI_SPHERE;
use super::spheroid::Spheroid;
use super::{ForceResult, Impact, Particle, TAU_HERTZ};
use std::f64::consts::PI;

/// Johnson 1985, §4.2: approximation of the approach factor F₂ of an elliptical Hertz contact,
/// `F₂ ≈ 1 − [(R'/R'')^0.0684 − 1]^1.531`, `R'/R''` ≥ 1 the ratio of principal relative radii.
pub fn johnson_f2(ratio: f64) -> f64 {
    let r = if ratio >= 1.0 { ratio } else { 1.0 / ratio };
    1.0 - (r.powf(0.0684) - 1.0).powf(1.531)
}

/// Largest radius ratio `R'/R''` for which Johnson's F₂ approximation is used. Measured against
/// [`stiffness_exact`]: stiffness error ≤ 0.9 % up to 100 (force error ≤ 0.35 %), but 7 % at 300,
/// 25 % at 1000 and F₂ < 0 beyond ≈ 25 000 (λ ≳ 160 lying flat). Above it the exact elliptic
/// solution is used, so `hertz-rigid` holds for any λ ≥ 1 (a ≤ 0.35 % step at the switch, λ = 10
/// lying flat).
pub const JOHNSON_MAX_RATIO: f64 = 100.0;

/// Johnson 1985, §4.2: Hertz stiffness `k` of `F = k δ^{3/2}` for a body of principal radii
/// `r1`, `r2` on a rigid plane, with Johnson's F₂ approximation (see [`johnson_f2`]).
/// Beyond `R'/R''` = 100 the exact elliptic solution is used instead ([`JOHNSON_MAX_RATIO`]).
pub fn stiffness(e_star: f64, r1: f64, r2: f64) -> f64 {
    let ratio = if r1 >= r2 { r1 / r2 } else { r2 / r1 };
    if ratio > JOHNSON_MAX_RATIO {
        return stiffness_exact(e_star, r1, r2);
    }
    let f2 = johnson_f2(ratio);
    4.0 / 3.0 * e_star * (r1 * r2).sqrt().sqrt() / (f2 * f2.sqrt())
}

/// Complete elliptic integrals K(m), E(m) (parameter m = e²) by the arithmetic–geometric mean
/// (Abramowitz & Stegun 1964, §17.6), for the exact Hertz ellipse (Johnson 1985, §4.2).
#[cfg(test)]
fn elliptic_ke(m: f64) -> (f64, f64) {
    elliptic_ke_kp(m, (1.0 - m).sqrt())
}

/// K, E from m and the complementary modulus `kp = √(1 − m)` (given separately to keep its
/// precision when m → 1).
fn elliptic_ke_kp(m: f64, kp: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0_f64, kp);
    let mut c2_sum = 0.5 * m; // 2^{n−1} c_n², n = 0
    let mut pow2 = 0.5;
    for _ in 0..40 {
        let c = 0.5 * (a - b);
        let (an, bn) = (0.5 * (a + b), (a * b).sqrt());
        pow2 *= 2.0;
        c2_sum += pow2 * c * c;
        a = an;
        b = bn;
        if c.abs() < 1e-17 {
            break;
        }
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - c2_sum))
}

/// Exact Hertz stiffness of an elliptical contact (Johnson 1985, Eqs. 4.39–4.40): with
/// A = 1/(2R'), B = 1/(2R''), A ≤ B, the ellipticity e of the contact solves
/// `B/A = [(a/b)² E(e) − K(e)] / [K(e) − E(e)]`; then `δ = p₀ b K(e)/E*`,
/// `P = (2π/3) p₀ a b`, `A = (p₀/E*)(b/(e²a²))[K − E]`, which give
/// `k = (2π/3) E* [A e²/(K − E)]^{−1/2} K^{−3/2}`. Bisection on ln(b/a) of the contact ellipse.
/// Used by [`stiffness`] beyond [`JOHNSON_MAX_RATIO`] and as the reference in tests.
pub fn stiffness_exact(e_star: f64, r1: f64, r2: f64) -> f64 {
    let (rl, rs) = if r1 >= r2 { (r1, r2) } else { (r2, r1) };
    let ratio = rl / rs;
    if ratio < 1.0 + 1e-9 {
        return 4.0 / 3.0 * e_star * (rl * rs).sqrt().sqrt();
    }
    // Bisection on ln(b/a) of the contact ellipse, kp = b/a ∈ [1e-12, 1): m = 1 − kp².
    let ke = |ln_kp: f64| {
        let kp = ln_kp.exp();
        let m = (1.0 - kp) * (1.0 + kp);
        let (k, e) = elliptic_ke_kp(m, kp);
        (m, kp, k, e)
    };
    let ratio_of = |ln_kp: f64| {
        let (_, kp, k, e) = ke(ln_kp);
        (e / (kp * kp) - k) / (k - e)
    };
    // B/A decreases as kp grows: ratio_of(ln kp) > ratio ⇒ the root has a larger kp.
    let (mut lo, mut hi) = (-27.6, -1e-9);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if ratio_of(mid) > ratio {
            lo = mid
        } else {
            hi = mid
        }
    }
    let (m, _, k, e) = ke(0.5 * (lo + hi));
    let a_curv = 0.5 / rl;
    2.0 * PI / 3.0 * e_star / (a_curv * m / (k - e)).sqrt() / (k * k.sqrt())
}

/// Effective mass ratio `m_eff/m = 1 / (1 + d²/(I/m))` at the lowest point (docs/physics.md §7:
/// `1/m_eff = 1/m + d²/I`, impulse at lever arm `d` on a body free to rotate).
pub fn mass_ratio(s: &Spheroid, lever_arm: f64) -> f64 {
    1.0 / (1.0 + lever_arm * lever_arm / s.inertia_per_mass())
}

/// ξ(λ, β) of the rigid-spheroid Hertz model: F_max at ρ = U_N = D = E* = 1.
pub fn xi(lambda: f64, beta: f64) -> f64 {
    xi_and_mass_ratio(lambda, beta).0
}

/// ξ(λ, β) and m_eff/m, in one pass (the hot path of `force-sweep`).
///
/// With D = 1: `a = ½ λ^(−1/3)`, `b = λ a`, `h² = a² g` with `g = λ² sin²β + cos²β`, so
/// `R'/R'' = b²/h² = λ²/g`, `2R_e = 2√(R'R'') = 2a²b/h² = λ^{2/3}/g` and
/// `m/m_eff = 1 + d²/(I/m) = 1 + 5 (λ² − 1)² sin²β cos²β / (g (1 + λ²))` (a cancels).
/// From `F_max = k^{2/5} (5 m_eff U²/4)^{3/5}` with `k = (4/3) E* √R_e F₂^{−3/2}`:
/// `ξ = ξ_sphere · [2R_e (m_eff/m / F₂)³]^{1/5} = ξ_sphere · [λ² r⁹ / g³]^{1/15}`, `r = (m_eff/m)/F₂`
/// (`ξ_sphere` of Eq. 3, since 2R_e = 1 for the unit sphere). Equal to the step-by-step
/// construction (test `fast_path_matches`).
#[inline]
pub fn xi_and_mass_ratio(lambda: f64, beta: f64) -> (f64, f64) {
    let (sn, cs) = beta.sin_cos();
    let (s2, c2, l2) = (sn * sn, cs * cs, lambda * lambda);
    let g = l2 * s2 + c2;
    let m_ratio = 1.0 / (1.0 + 5.0 * (l2 - 1.0) * (l2 - 1.0) * s2 * c2 / (g * (1.0 + l2)));
    if l2 / g > JOHNSON_MAX_RATIO {
        // Very slender contact: exact elliptic stiffness (see `stiffness`).
        let s = Spheroid::from_volume_diameter(1.0, lambda);
        let lp = s.lowest_point(beta);
        let k = stiffness(1.0, lp.r_in_plane, lp.r_out_of_plane);
        return (super::hertz_impact(k, PI / 6.0 * m_ratio, 1.0).0, m_ratio);
    }
    // Johnson's F₂ at R'/R'' = λ²/g ≥ 1.
    let x = (0.0684 * (l2 / g).ln()).exp() - 1.0;
    let f2 = if x > 0.0 {
        1.0 - (1.531 * x.ln()).exp()
    } else {
        1.0
    };
    let r = m_ratio / f2;
    let r3 = r * r * r;
    let q = l2 * r3 * r3 * r3 / (g * g * g);
    (XI_SPHERE * (q.ln() * (1.0 / 15.0)).exp(), m_ratio)
}

/// Stiffness `k` of `F = k δ^{3/2}` (Johnson 1985, §4.2, elliptical contact) and effective mass
/// `m_eff` (docs/physics.md §7) of the contact at inclination β (SI).
pub fn contact_parameters(p: &Particle, lambda: f64, beta: f64) -> (f64, f64) {
    let s = Spheroid::from_volume_diameter(p.diameter, lambda);
    let lp = s.lowest_point(beta);
    (
        stiffness(p.e_star(), lp.r_in_plane, lp.r_out_of_plane),
        p.mass() * mass_ratio(&s, lp.lever_arm),
    )
}

/// `hertz-rigid`: F_max = ξ(λ, β) × ρ^0.6 U_N^1.2 D² E*^0.4; contact time of the Hertzian
/// impact of m_eff, `t_c = 2.9433 δ_max/U_N` with `δ_max = (5/4) m_eff U_N² / F_max`
/// (the energy balance `½ m_eff U² = (2/5) F_max δ_max`).
pub fn evaluate(p: &Particle, imp: &Impact) -> ForceResult {
    let (xi, m_ratio) = xi_and_mass_ratio(imp.lambda, imp.beta);
    let f_max = xi * p.force_scale(imp.u_n);
    let contact_time = if imp.u_n > 0.0 && f_max > 0.0 {
        let t = TAU_HERTZ * 1.25 * m_ratio * p.mass() * imp.u_n / f_max;
        t.is_finite().then_some(t)
    } else {
        None
    };
    ForceResult {
        f_max,
        xi,
        contact_time,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::force::hertz_impact;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn elliptic_integrals() {
        let (k, e) = elliptic_ke(0.0);
        assert!((k - FRAC_PI_2).abs() < 1e-15 && (e - FRAC_PI_2).abs() < 1e-15);
        // A&S Table 17.1: K(0.5) = 1.854074677301372, E(0.5) = 1.350643881047675.
        let (k, e) = elliptic_ke(0.5);
        assert!((k - 1.854_074_677_301_372).abs() < 1e-13);
        assert!((e - 1.350_643_881_047_675).abs() < 1e-13);
    }

    /// Johnson's F₂ approximation against the exact elliptic-integral solution over the
    /// range of radius ratios met by spheroids up to λ = 3 (R'/R'' ≤ λ² = 9) and beyond.
    #[test]
    fn johnson_f2_against_exact_elliptic_solution() {
        let mut worst: f64 = 0.0;
        for ratio in [1.0, 1.01, 1.5, 2.0, 4.0, 9.0, 20.0] {
            let approx = stiffness(1.0, ratio, 1.0);
            let exact = stiffness_exact(1.0, ratio, 1.0);
            worst = worst.max((approx / exact - 1.0).abs());
        }
        // F_max ∝ k^0.4: a stiffness error ε is a force error 0.4 ε.
        assert!(worst < 0.02, "worst relative stiffness error {worst}");
    }

    /// The one-pass ξ against the step-by-step construction (geometry → k, m_eff → energy
    /// balance), and the contact time against the closed form of the Hertzian impact.
    #[test]
    fn fast_path_matches() {
        for lambda in [1.0, 1.5, 2.0, 3.0, 9.0, 30.0] {
            for deg in [0.0, 1.0, 30.0, 45.0, 77.0, 90.0] {
                let beta = f64::to_radians(deg);
                let s = Spheroid::from_volume_diameter(1.0, lambda);
                let lp = s.lowest_point(beta);
                let m_eff = PI / 6.0 * mass_ratio(&s, lp.lever_arm);
                let k = stiffness(1.0, lp.r_in_plane, lp.r_out_of_plane);
                let slow = hertz_impact(k, m_eff, 1.0).0;
                assert!(
                    (xi(lambda, beta) / slow - 1.0).abs() < 1e-13,
                    "λ={lambda} β={deg}"
                );
                let p = Particle {
                    density: 2500.0,
                    youngs: 64e9,
                    poisson: 0.24,
                    diameter: 2.45e-6,
                };
                let imp = Impact {
                    lambda,
                    beta,
                    u_n: 0.3,
                };
                let (k, m_eff) = contact_parameters(&p, lambda, beta);
                let (f, t) = hertz_impact(k, m_eff, 0.3);
                let r = evaluate(&p, &imp);
                assert!((r.f_max / f - 1.0).abs() < 1e-12);
                assert!((r.contact_time.unwrap() / t.unwrap() - 1.0).abs() < 1e-12);
            }
        }
    }

    /// The switch to the exact solution at R'/R'' = 100 is a step of at most 0.35 % in F_max,
    /// and slender spheroids (λ up to 10⁴) give finite, positive forces.
    #[test]
    fn slender_spheroids() {
        let below = stiffness(1.0, JOHNSON_MAX_RATIO * (1.0 - 1e-12), 1.0);
        let above = stiffness(1.0, JOHNSON_MAX_RATIO * (1.0 + 1e-12), 1.0);
        assert!(((below / above).powf(0.4) - 1.0).abs() < 0.0035);
        for lambda in [9.9, 10.1, 30.0, 1e3, 1e4] {
            for deg in [0.0, 0.01, 1.0, 45.0, 90.0] {
                let x = xi(lambda, f64::to_radians(deg));
                assert!(x.is_finite() && x > 0.0, "λ={lambda} β={deg}: {x}");
            }
        }
        // The exact solution for a very slender contact is still monotone in the ratio.
        assert!(stiffness_exact(1.0, 1e8, 1.0) > stiffness_exact(1.0, 1e6, 1.0));
    }

    #[test]
    fn lambda_one_is_hertz_sphere() {
        for beta in [0.0, 0.4, FRAC_PI_2] {
            assert!(
                (xi(1.0, beta) - XI_SPHERE).abs() < 1e-14,
                "{}",
                xi(1.0, beta)
            );
        }
    }

    /// At β = 0 and 90° the lever arm is zero, so m_eff = m and only the curvature matters:
    /// ξ = ξ_sphere (R_e/(D/2))^{1/5} F₂^{−3/5}, with R_e = b at β = 0 and a²/b at 90°.
    #[test]
    fn end_orientations_closed_forms() {
        for lambda in [1.5_f64, 2.0, 3.0] {
            let flat = XI_SPHERE * lambda.powf(2.0 / 15.0) * johnson_f2(lambda * lambda).powf(-0.6);
            assert!((xi(lambda, 0.0) - flat).abs() < 1e-13);
            let tip = XI_SPHERE * lambda.powf(-4.0 / 15.0);
            assert!((xi(lambda, FRAC_PI_2) - tip).abs() < 1e-13);
        }
    }
}
