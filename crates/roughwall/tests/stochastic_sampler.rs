//! The shadow-effect sampler against the numerically integrated density
//! (Radenkovic & Simonin 2021, Eqs. (31)–(33)): χ² and Kolmogorov–Smirnov tests at
//! grazing, moderate and normal incidence and Δγ ∈ {0.5°, 3.8°, 15°}.
use rand::SeedableRng;
use rand_xoshiro::Xoshiro256PlusPlus;
use roughwall::stochastic::{bin_probability, density, ShadowSampler};

const N: usize = 40_000;
const BINS: usize = 40;

/// χ² statistic and KS distance of `N` samples against the model, on `BINS` equal-mass-ish
/// bins spanning the bulk of the law.
fn check(alpha_deg: f64, dgamma_deg: f64, seed: u64) -> (f64, f64) {
    let a = alpha_deg.to_radians();
    let s = dgamma_deg.to_radians();
    let sampler = ShadowSampler::new(a, s);
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    let mut xs: Vec<f64> = (0..N).map(|_| sampler.sample(&mut rng)).collect();
    xs.sort_by(|p, q| p.total_cmp(q));
    let lo = a.max(-8.0 * s);
    let hi = (8.0 * s).min(std::f64::consts::FRAC_PI_2);
    let w = (hi - lo) / BINS as f64;
    // χ²: bins with expected count ≥ 5, plus the two tails merged into the ends.
    let mut counts = vec![0usize; BINS];
    for &x in &xs {
        let i = (((x - lo) / w).floor() as isize).clamp(0, BINS as isize - 1) as usize;
        counts[i] += 1;
    }
    let mut chi2 = 0.0;
    let mut cdf = 0.0;
    let mut ks: f64 = 0.0;
    let mut seen = 0usize;
    for (i, &c) in counts.iter().enumerate() {
        let b0 = if i == 0 { a } else { lo + i as f64 * w };
        let b1 = if i == BINS - 1 {
            std::f64::consts::FRAC_PI_2
        } else {
            lo + (i + 1) as f64 * w
        };
        let p = bin_probability(b0, b1, a, s);
        let e = p * N as f64;
        if e >= 5.0 {
            chi2 += (c as f64 - e).powi(2) / e;
        }
        cdf += p;
        seen += c;
        ks = ks.max((cdf - seen as f64 / N as f64).abs());
    }
    (chi2, ks)
}

#[test]
fn sampler_matches_density_chi2_and_ks() {
    let mut seed = 11;
    for &alpha in &[-0.01, -12.5, -90.0] {
        for &dg in &[0.5, 3.8, 15.0] {
            seed += 1;
            let (chi2, ks) = check(alpha, dg, seed);
            eprintln!("α⁻={alpha} Δγ={dg}: chi2={chi2:.1} ks={ks:.4}");
            // ≤ 40 degrees of freedom: χ² > 80 has p < 1e-4; KS at N = 40000:
            // 1.95/√N (p = 0.001) ≈ 0.0098.
            assert!(chi2 < 80.0, "α⁻={alpha}° Δγ={dg}°: χ² = {chi2}");
            assert!(ks < 0.0098, "α⁻={alpha}° Δγ={dg}°: KS = {ks}");
        }
    }
}

#[test]
fn grazing_density_has_the_rayleigh_shape() {
    // α⁻ → 0: sin(γ − α⁻) ≈ γ, P_eff → γ/Δγ² · exp(−γ²/2Δγ²) (Rayleigh), mode at Δγ.
    let s = 3.8_f64.to_radians();
    let a = -0.01_f64.to_radians();
    let p = |g: f64| density(g, a, s);
    let rayleigh = |g: f64| g / (s * s) * (-(g * g) / (2.0 * s * s)).exp();
    for k in [0.5, 1.0, 2.0, 3.0] {
        let g = k * s;
        assert!((p(g) - rayleigh(g)).abs() / rayleigh(g) < 0.01, "k={k}");
    }
    assert_eq!(p(-0.001), 0.0);
}
