//! The shadow-effect law of the first wall inclination `γ` seen by a particle
//! (Sommerfeld & Huber 1999, as used by Radenkovic & Simonin 2021, Eqs. (31)–(33)):
//!
//! `P_eff(γ | α⁻) ∝ sin(γ − α⁻) · exp(−γ² / 2Δγ²)` on `(α⁻, π/2]`, zero for `γ ≤ α⁻`.
//!
//! (Eq. (32) writes `sin(α⁻ − γ)/sin(α⁻)`; both factors are negative on the support,
//! so this is the same positive function.)
//!
//! # The exact sampler
//!
//! Work in `x = γ − α⁻ ∈ (0, x_max]`, `x_max = π/2 − α⁻ ≤ π`, `a = α⁻ < 0`, `s = Δγ`:
//! the target is `T(x) = sin(x) · exp(−(x + a)² / 2s²)`.
//!
//! **Envelope.** `g(x) = ln(sin x / x)` is concave on `(0, π)`:
//! `g''(x) = 1/x² − 1/sin² x ≤ 0` because `sin x ≤ x`. Its tangent at any `x₀ ∈ (0, π)`
//! bounds it from above, `sin x / x ≤ (sin x₀ / x₀) · exp(k (x − x₀))` with
//! `k = g'(x₀) = cot x₀ − 1/x₀ ≤ 0`, hence
//! `T(x) ≤ C · x · exp(−(x − μ)² / 2s²)`, `μ = −a + k s²`
//! (complete the square). The proposal is this "Rayleigh-type" law
//! `q(x) ∝ x · exp(−(x − μ)²/2s²)` on `x > 0`, and a proposal is accepted with
//! `r(x) = (sin x / x) / ((sin x₀/x₀) e^{k(x − x₀)}) ∈ [0, 1]` (and rejected if
//! `x > x_max`). That is ordinary rejection sampling, hence exact. `x₀` is the mode of
//! the untilted law `x·exp(−(x + a)²/2s²)`, `x₀ = (−a + √(a² + 4s²))/2` — close to the
//! mode of the target, computed in closed form, no table.
//!
//! **Sampling `q` exactly.** With `x = s·y`, `m = μ/s`, `q(y) ∝ y e^{−(y−m)²/2}` on `y > 0`.
//! * `m ≤ 0`: `y ≤ y − m` on `y > 0`, so propose `t = y − m` from the Rayleigh law
//!   `t e^{−t²/2}` conditioned on `t > −m` (exactly `t = √(m² + 2E)`, `E ~ Exp(1)`) and
//!   accept with `y / t`. Acceptance `A₋(m) = 1 − |m| √(2π) Φ(m) e^{m²/2} ≥ 1 − 1.26 |m|`.
//! * `m > 0`: `y e^{−(y−m)²/2} ≤ (max(y − m, 0) + m) e^{−(y−m)²/2}`: a mixture of the
//!   Rayleigh law beyond `m` (weight 1, `y = m + √(2E)`, always accepted) and the normal
//!   `N(m, 1)` (weight `m√(2π)`, accepted with `y/m` if `0 < y < m`, always if `y ≥ m`).
//!   Acceptance `A₊(m) = (e^{−m²/2} + m√(2π) Φ(m)) / (1 + m√(2π))`, which is 1 at `m = 0`,
//!   tends to 1 as `m → ∞` and has its minimum `0.767` near `m ≈ 0.75`.
//!
//! **Bound on the expected number of proposals.** The expected number of proposals per
//! accepted `γ` is `1 / (A_q · A_r)` with `A_q = A±(m)` above and
//! `A_r = E_q[r(x) 1{x ≤ x_max}]`. For `A_r`: `ln r(x) = −∫_{x₀}^{x} (x − w)(−g''(w)) dw`
//! and `−g''(w) = 1/sin²w − 1/w²` is increasing on `(0, π)`, equal to `1/3` at `0⁺`
//! and `≤ 0.96` for `w ≤ 2`, so `r(x) ≥ exp(−0.48 (x − x₀)²)` whenever `x, x₀ ≤ 2`.
//! By Jensen (`exp` is convex), `A_r ≥ P_q(x ≤ 2) · exp(−0.48 E_q[(x − x₀)² | x ≤ 2])`.
//! Under `q`, `x − x₀` has spread `≲ s` and the tilt moves the mode by
//! `|k| s² ≤ 0.69 s²`, so `E_q[(x − x₀)²] ≤ (1.25 s)²` for `s ≤ 20° = 0.349 rad`, giving
//! `A_r ≥ 0.91 · P_q(x ≤ 2)`. `P_q(x ≤ 2)` is 1 up to `10⁻⁶` for `|α⁻| ≤ 45°`; for
//! `|α⁻| → 90°`, `x₀ → π/2` and the normal-like `q` (spread `s`) puts at least `0.88`
//! of its mass below 2 rad. Together with `A_q ≥ 0.767`, `1/(A_q A_r) ≤ 1/(0.767 · 0.91 · 0.88) < 1.7`
//! proposals everywhere on `α⁻ ∈ [−90°, 0)`, `Δγ ∈ (0, 20°]` — including grazing
//! incidence, where `a → 0`, `m → −s²/3 ≈ 0` and both factors tend to ≥ 0.96.
//! The measured worst case (test `proposals_are_bounded_on_a_grid`, bench
//! `stochastic`) is ≈ 1.3 proposals per sample.
//!
//! `Δγ = 0` gives `γ = 0` without drawing anything.

use rand::Rng;
use rand_distr::{Exp1, StandardNormal};
use std::f64::consts::{FRAC_PI_2, PI};

/// `1/3 − 1/π²`: `−g''(w) − 1/(π − w)² = Σ_{k ∉ {0, 1}} (w − kπ)^{−2}` is convex on
/// `(0, π)` and takes this value at both ends, so it never exceeds it.
const SQUEEZE_C0: f64 = 1.0 / 3.0 - 1.0 / (PI * PI);

/// `sin(x)/x`, accurate also for tiny `x`.
#[inline]
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        1.0 - x * x / 6.0
    } else {
        x.sin() / x
    }
}

/// `d/dx ln(sin x / x) = cot x − 1/x`, accurate also for tiny `x`.
#[inline]
fn dlog_sinc(x: f64) -> f64 {
    if x < 1e-3 {
        -x / 3.0 - x * x * x / 45.0
    } else {
        1.0 / x.tan() - 1.0 / x
    }
}

/// A precomputed shadow-effect law for one `(α⁻, Δγ)`: the proposal parameters of the
/// sampler (a handful of numbers computed in closed form — no table).
#[derive(Clone, Copy, Debug)]
pub struct ShadowSampler {
    alpha: f64,
    s: f64,
    x_max: f64,
    x0: f64,
    sinc_x0: f64,
    k: f64,
    /// `m = μ/s` of the proposal `y e^{−(y−m)²/2}`.
    m: f64,
    /// Probability of the Rayleigh component when `m > 0`.
    p_rayleigh: f64,
}

impl ShadowSampler {
    /// Sampler of `P_eff(γ | α⁻)` (Radenkovic & Simonin 2021, Eqs. (31)–(33)).
    ///
    /// `alpha_in` is `α⁻` in radians, clamped into `[−π/2, −1e−12]`; `delta_gamma` is
    /// `Δγ ≥ 0` in radians (Eq. 26).
    pub fn new(alpha_in: f64, delta_gamma: f64) -> Self {
        Self::build(alpha_in.clamp(-FRAC_PI_2, -1e-12), delta_gamma)
    }

    /// The same law for a particle that meets the wall again while *rising* at `α > 0`
    /// (the `calibrated` model's later collisions): `sin(γ − α)·exp(−γ²/2Δγ²)` on
    /// `γ > α`, the elements steeper than the trajectory, weighted by the rate at which it
    /// meets them — Eq. (32) continued to `α > 0`. `alpha` is clamped into
    /// `[−π/2, π/2 − 10⁻³]`. The sampler above stays exact (`a > 0` only makes `m < 0`);
    /// it needs about `1 + (α/Δγ)²` proposals, and the model asks for it only while its
    /// reduced incidence is below 4 (a rebound beyond `x_out = 4` always leaves).
    pub fn rising(alpha: f64, delta_gamma: f64) -> Self {
        Self::build(alpha.clamp(-FRAC_PI_2, FRAC_PI_2 - 1e-3), delta_gamma)
    }

    /// The law for a trajectory at `alpha` (rad), whichever way it moves: [`Self::new`]
    /// for a particle coming down (`α ≤ 0`), [`Self::rising`] for one going up (`α > 0`).
    pub fn for_trajectory(alpha: f64, delta_gamma: f64) -> Self {
        if alpha > 0.0 {
            Self::rising(alpha, delta_gamma)
        } else {
            Self::new(alpha, delta_gamma)
        }
    }

    fn build(a: f64, delta_gamma: f64) -> Self {
        let s = if delta_gamma.is_finite() {
            delta_gamma.max(0.0)
        } else {
            0.0
        };
        let x_max = FRAC_PI_2 - a;
        if s == 0.0 {
            return Self {
                alpha: a,
                s,
                x_max,
                x0: 0.0,
                sinc_x0: 1.0,
                k: 0.0,
                m: 0.0,
                p_rayleigh: 1.0,
            };
        }
        // Mode of x·exp(−(x+a)²/2s²): root of x² + a x − s² = 0, in the form without
        // cancellation for either sign of a.
        let root = (a * a + 4.0 * s * s).sqrt();
        let x0 = if a <= 0.0 {
            (-a + root) * 0.5
        } else {
            2.0 * s * s / (a + root)
        }
        .min(PI - 1e-3);
        // k = g'(x0) = cot x0 − 1/x0 and sin x0 / x0 from one sin_cos (series near 0).
        let (k, sinc_x0) = if x0 < 1e-3 {
            (dlog_sinc(x0), sinc(x0))
        } else {
            let (sn, cs) = x0.sin_cos();
            (cs / sn - 1.0 / x0, sn / x0)
        };
        let mu = -a + k * s * s;
        let m = mu / s;
        let p_rayleigh = if m > 0.0 {
            1.0 / (1.0 + m * (2.0 * PI).sqrt())
        } else {
            1.0
        };
        Self {
            alpha: a,
            s,
            x_max,
            x0,
            sinc_x0,
            k,
            m,
            p_rayleigh,
        }
    }

    /// `α⁻` used (radians).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// `Δγ` used (radians).
    pub fn delta_gamma(&self) -> f64 {
        self.s
    }

    /// One draw of `y ~ y e^{−(y−m)²/2}` on `y > 0`, returned as `d = y − m` (so that
    /// `γ = s·d + k s²` keeps its relative precision when `Δγ ≪ |α⁻|`); `None` when the
    /// proposal is rejected.
    #[inline]
    fn propose_d<R: Rng + ?Sized>(&self, rng: &mut R) -> Option<f64> {
        let m = self.m;
        if m <= 0.0 {
            let e: f64 = rng.sample(Exp1);
            let t = (m * m + 2.0 * e).sqrt();
            let y = t + m;
            // Accept with y/t.
            if y > 0.0 && rng.gen::<f64>() * t < y {
                Some(t)
            } else {
                None
            }
        } else if rng.gen::<f64>() < self.p_rayleigh {
            let e: f64 = rng.sample(Exp1);
            Some((2.0 * e).sqrt())
        } else {
            let z: f64 = rng.sample(StandardNormal);
            let y = m + z;
            if z >= 0.0 || (y > 0.0 && rng.gen::<f64>() * m < y) {
                Some(z)
            } else {
                None
            }
        }
    }

    /// Acceptance ratio `r(x) = sinc(x) / (sinc(x0) e^{k(x − x0)})` of a proposal `x = γ − α⁻`.
    #[inline]
    fn ratio(&self, x: f64) -> f64 {
        sinc(x) / (self.sinc_x0 * (self.k * (x - self.x0)).exp())
    }

    /// A cheap lower bound of [`Self::ratio`]: `1 − C(w)(x − x0)²/2`, `w = max(x, x0)`.
    #[inline]
    fn squeeze(&self, x: f64) -> f64 {
        let pw = PI - x.max(self.x0);
        let dx = x - self.x0;
        if pw > 0.1 {
            1.0 - 0.5 * (1.0 / (pw * pw) + SQUEEZE_C0) * dx * dx
        } else {
            0.0
        }
    }

    /// One proposal: `Some(γ)` if accepted. Exposed so that the bench and tests can
    /// count proposals per accepted sample.
    #[inline]
    pub fn try_sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Option<f64> {
        if self.s == 0.0 {
            return Some(0.0);
        }
        let d = self.propose_d(rng)?;
        // x = s·y = μ + s·d, γ = x + α⁻ = s·d + k s² (μ = −α⁻ + k s²).
        let x = self.s * self.m + self.s * d;
        if x > self.x_max || x <= 0.0 {
            return None;
        }
        // Accept with r(x) = sinc(x) / (sinc(x0) e^{k(x − x0)}) ∈ [0, 1]. Squeeze first:
        // ln r ≥ −C(w)(x − x0)²/2 with w = max(x, x0) and C(w) = 1/(π − w)² + 1/3 − 1/π²
        // ≥ −g''(w) (module doc), and e^{−t} ≥ 1 − t, so most proposals are accepted
        // without sin/exp. Same decision for the same uniform: the samples are unchanged.
        let u: f64 = rng.gen();
        if u < self.squeeze(x) || u < self.ratio(x) {
            let gamma = self.s * d + self.k * self.s * self.s;
            // γ ≤ α⁻ only by rounding when x is a few ulps: a null event, rejected.
            (gamma > self.alpha).then_some(gamma.min(FRAC_PI_2))
        } else {
            None
        }
    }

    /// An exact draw of `γ` (radians) and the number of proposals it took.
    #[inline]
    pub fn sample_counted<R: Rng + ?Sized>(&self, rng: &mut R) -> (f64, u32) {
        let mut n = 0u32;
        loop {
            n = n.saturating_add(1);
            if let Some(g) = self.try_sample(rng) {
                return (g, n);
            }
        }
    }

    /// An exact draw of `γ` (radians).
    #[inline]
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> f64 {
        self.sample_counted(rng).0
    }
}

/// Draw `γ` from `P_eff(γ | α⁻)` (Radenkovic & Simonin 2021, Eqs. (31)–(32)); radians.
#[inline]
pub fn sample_gamma<R: Rng + ?Sized>(alpha_in: f64, delta_gamma: f64, rng: &mut R) -> f64 {
    ShadowSampler::new(alpha_in, delta_gamma).sample(rng)
}

/// Unnormalised `sin(γ − α⁻) exp(−γ²/2Δγ²)` on `(α⁻, π/2]`, zero elsewhere (Eqs. 31–32).
fn unnormalised(gamma: f64, a: f64, s: f64) -> f64 {
    if gamma <= a || gamma > FRAC_PI_2 {
        0.0
    } else {
        (gamma - a).sin() * (-(gamma * gamma) / (2.0 * s * s)).exp()
    }
}

/// Integration range that holds all the mass of `P_eff` (the Gaussian factor is below
/// `e^{−60}` outside `±11 Δγ`).
fn support(a: f64, s: f64) -> (f64, f64) {
    (a.max(-11.0 * s), FRAC_PI_2.min(11.0 * s))
}

/// `1/g(α⁻, Δγ)` up to the constant `1/√(2π Δγ²)`: `∫ sin(γ − α⁻) e^{−γ²/2Δγ²} dγ`
/// over `(α⁻, π/2]` (Radenkovic & Simonin 2021, Eq. 33), by composite Gauss–Legendre
/// quadrature (relative accuracy ~1e−12 for the smooth integrand).
pub fn normaliser(alpha_in: f64, delta_gamma: f64) -> f64 {
    let a = alpha_in.clamp(-FRAC_PI_2, -1e-12);
    let s = delta_gamma;
    if s <= 0.0 {
        return 0.0;
    }
    let (lo, hi) = support(a, s);
    if hi <= lo {
        return 0.0;
    }
    integrate(|g| unnormalised(g, a, s), lo, hi, 400)
}

/// Composite 5-point Gauss–Legendre rule on `n` panels.
pub(crate) fn integrate(f: impl Fn(f64) -> f64, lo: f64, hi: f64, n: usize) -> f64 {
    const X: [f64; 5] = [
        0.0,
        -0.538_469_310_105_683_1,
        0.538_469_310_105_683_1,
        -0.906_179_845_938_664,
        0.906_179_845_938_664,
    ];
    const W: [f64; 5] = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
        0.236_926_885_056_189_1,
    ];
    let h = (hi - lo) / n as f64;
    let mut sum = 0.0;
    for i in 0..n {
        let c = lo + (i as f64 + 0.5) * h;
        for j in 0..5 {
            sum += W[j] * f(c + 0.5 * h * X[j]);
        }
    }
    sum * 0.5 * h
}

/// The normalised density `P_eff(γ | α⁻)` in 1/rad (Radenkovic & Simonin 2021,
/// Eqs. (31)–(33), normalised by numerical integration). For `Δγ = 0` the law is a
/// point mass at `γ = 0`; this function then returns 0 (use [`bin_probability`]).
pub fn density(gamma: f64, alpha_in: f64, delta_gamma: f64) -> f64 {
    let z = normaliser(alpha_in, delta_gamma);
    if z <= 0.0 || !z.is_finite() {
        return 0.0;
    }
    let a = alpha_in.clamp(-FRAC_PI_2, -1e-12);
    unnormalised(gamma, a, delta_gamma) / z
}

/// The density at many points with one normalisation (for model curves).
pub fn density_curve(gammas: &[f64], alpha_in: f64, delta_gamma: f64) -> Vec<f64> {
    let z = normaliser(alpha_in, delta_gamma);
    let a = alpha_in.clamp(-FRAC_PI_2, -1e-12);
    gammas
        .iter()
        .map(|&g| {
            if z <= 0.0 || !z.is_finite() {
                0.0
            } else {
                unnormalised(g, a, delta_gamma) / z
            }
        })
        .collect()
}

/// `P(lo < γ ≤ hi)` under `P_eff(γ | α⁻)` (Eqs. 31–33); handles `Δγ = 0` (point mass at 0).
pub fn bin_probability(lo: f64, hi: f64, alpha_in: f64, delta_gamma: f64) -> f64 {
    if delta_gamma <= 0.0 {
        return if lo < 0.0 && 0.0 <= hi { 1.0 } else { 0.0 };
    }
    let a = alpha_in.clamp(-FRAC_PI_2, -1e-12);
    let z = normaliser(a, delta_gamma);
    if z <= 0.0 {
        return 0.0;
    }
    let (slo, shi) = support(a, delta_gamma);
    let l = lo.max(slo);
    let h = hi.min(shi);
    if h <= l {
        return 0.0;
    }
    integrate(|g| unnormalised(g, a, delta_gamma), l, h, 40) / z
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_xoshiro::Xoshiro256PlusPlus;

    fn deg(x: f64) -> f64 {
        x.to_radians()
    }

    #[test]
    fn density_integrates_to_one() {
        for &a in &[-0.01, -2.5, -12.5, -45.0, -90.0] {
            for &s in &[0.5, 3.8, 15.0, 20.0] {
                let (lo, hi) = support(deg(a), deg(s));
                let total = integrate(|g| density(g, deg(a), deg(s)), lo, hi, 200);
                assert!((total - 1.0).abs() < 1e-9, "a={a} s={s} total={total}");
            }
        }
    }

    #[test]
    fn large_incidence_is_nearly_normal() {
        // |α⁻| ≫ Δγ: the shadow factor sin(γ − α⁻) varies slowly, P_eff ≈ N(0, Δγ²)
        // with the mean shifted by Δγ² cot(−α⁻) (first order).
        let (a, s) = (deg(-60.0), deg(2.0));
        let mean = integrate(|g| g * density(g, a, s), -0.5, 0.5, 400);
        let expect = s * s / (-a).tan();
        assert!((mean - expect).abs() < 1e-5, "{mean} {expect}");
    }

    #[test]
    fn zero_deviation_is_zero_gamma() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(1);
        for &a in &[-0.01, -30.0, -90.0] {
            assert_eq!(sample_gamma(deg(a), 0.0, &mut rng), 0.0);
        }
        assert_eq!(bin_probability(-0.1, 0.1, deg(-10.0), 0.0), 1.0);
    }

    #[test]
    fn samples_stay_in_support() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(2);
        for &a in &[-0.01, -1.0, -12.5, -89.99, -90.0] {
            for &s in &[0.001, 0.5, 3.8, 20.0] {
                let sm = ShadowSampler::new(deg(a), deg(s));
                for _ in 0..2000 {
                    let g = sm.sample(&mut rng);
                    assert!(g > deg(a) && g <= FRAC_PI_2 && g.is_finite());
                }
            }
        }
    }

    #[test]
    fn squeeze_is_below_the_acceptance_ratio() {
        for &a in &[-0.01, -1.0, -12.5, -45.0, -80.0, -90.0] {
            for &s in &[0.01, 1.0, 3.8, 10.0, 20.0] {
                let sm = ShadowSampler::new(deg(a), deg(s));
                for i in 1..2000 {
                    let x = sm.x_max * i as f64 / 2000.0;
                    let (q, r) = (sm.squeeze(x), sm.ratio(x));
                    assert!(q <= r * (1.0 + 1e-12), "a={a} s={s} x={x}: {q} > {r}");
                    assert!(r <= 1.0 + 1e-12, "a={a} s={s} x={x}: r = {r}");
                }
            }
        }
    }

    #[test]
    fn tiny_deviation_keeps_relative_precision() {
        // Δγ ≪ |α⁻| (e.g. Δγ from cos 90° ≈ 6e−17 on a 2-D wall): γ/Δγ is still ~N(0, 1).
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(4);
        let s = 1e-18;
        let sm = ShadowSampler::new(deg(-45.0), s);
        let n = 20_000;
        let xs: Vec<f64> = (0..n).map(|_| sm.sample(&mut rng) / s).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
        assert!(
            mean.abs() < 0.05 && (var - 1.0).abs() < 0.05,
            "{mean} {var}"
        );
    }

    #[test]
    fn proposals_are_bounded_on_a_grid() {
        let mut rng = Xoshiro256PlusPlus::seed_from_u64(3);
        let mut worst: f64 = 0.0;
        for &a in &[
            -0.01, -0.1, -0.5, -1.0, -2.5, -5.0, -12.5, -25.0, -45.0, -70.0, -89.99, -90.0,
        ] {
            for &s in &[0.01, 0.5, 1.0, 2.0, 3.8, 7.5, 10.0, 15.0, 20.0] {
                let sm = ShadowSampler::new(deg(a), deg(s));
                let n = 20_000;
                let total: u64 = (0..n).map(|_| sm.sample_counted(&mut rng).1 as u64).sum();
                let per = total as f64 / n as f64;
                if per > worst {
                    worst = per;
                    eprintln!("worst so far: a={a} s={s}: {per:.4} proposals/sample");
                }
                assert!(per <= 2.0, "a={a} s={s}: {per} proposals/sample");
            }
        }
        assert!(worst < 1.5, "worst {worst}");
    }

    #[test]
    fn the_rising_law_is_sampled_exactly() {
        // sin(γ − α)·exp(−γ²/2s²) on (α, π/2] for α > 0: binned frequencies against the
        // quadrature of the same function, within 5 binomial standard errors.
        for (a, s) in [
            (deg(1.0), deg(4.0)),
            (deg(6.0), deg(3.0)),
            (deg(10.0), deg(7.5)),
        ] {
            let f = |g: f64| {
                if g > a {
                    (g - a).sin() * (-g * g / (2.0 * s * s)).exp()
                } else {
                    0.0
                }
            };
            let hi = (a + 8.0 * s).min(FRAC_PI_2);
            let z = integrate(f, a, hi, 400);
            let sampler = ShadowSampler::rising(a, s);
            let mut rng = Xoshiro256PlusPlus::seed_from_u64(11);
            let n = 200_000;
            let bins = 20;
            let width = (hi - a) / bins as f64;
            let mut counts = vec![0u32; bins];
            for _ in 0..n {
                let g = sampler.sample(&mut rng);
                assert!(g > a && g <= FRAC_PI_2);
                counts[(((g - a) / width) as usize).min(bins - 1)] += 1;
            }
            for (k, &c) in counts.iter().enumerate() {
                let lo = a + k as f64 * width;
                let p = integrate(f, lo, lo + width, 20) / z;
                let se = (p * (1.0 - p) / n as f64).sqrt().max(1e-6);
                let freq = c as f64 / n as f64;
                assert!(
                    (freq - p).abs() < 5.0 * se,
                    "α = {a}, bin {k}: {freq} vs {p}"
                );
            }
        }
    }
}
