//! The deterministic tests' helpers: a small Gaussian-surface synthesiser
//! (independent of `crate::surface::generate`) and angle helpers.

use rand::SeedableRng;
use rand_distr::{Distribution, StandardNormal};
use rand_xoshiro::Xoshiro256PlusPlus;
use roughwall::HeightField;
use rustfft::num_complex::Complex;
use rustfft::FftPlanner;

/// A periodic Gaussian random surface on `n × n` nodes of spacing `d` with
/// autocorrelation `h² exp(−x²/cx² − z²/cz²)` (spectral synthesis: complex
/// Gaussian modes weighted by the Gaussian spectrum, inverse 2-D FFT, real part,
/// rescaled to rms `h`). `None`: constant along that axis (stored with `nz = 1`
/// when constant along z).
pub fn gaussian_surface(
    n: usize,
    d: f64,
    h: f64,
    cx: Option<f64>,
    cz: Option<f64>,
    seed: u64,
) -> HeightField {
    let l = n as f64 * d;
    let weight = |m: usize, c: Option<f64>| -> f64 {
        let k = if m <= n / 2 {
            m as f64
        } else {
            m as f64 - n as f64
        };
        match c {
            Some(c) => {
                let q = std::f64::consts::TAU * k / l;
                (-(q * c).powi(2) / 8.0).exp() // sqrt of exp(−q²c²/4)
            }
            None => {
                if m == 0 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    };
    let nz = if cz.is_none() { 1 } else { n };
    let mut r = Xoshiro256PlusPlus::seed_from_u64(seed);
    let mut buf: Vec<Complex<f64>> = Vec::with_capacity(n * nz);
    for mz in 0..nz {
        for mx in 0..n {
            let w = weight(mx, cx) * if nz == 1 { 1.0 } else { weight(mz, cz) };
            let re: f64 = StandardNormal.sample(&mut r);
            let im: f64 = StandardNormal.sample(&mut r);
            buf.push(Complex::new(re * w, im * w));
        }
    }
    buf[0] = Complex::new(0.0, 0.0);
    let mut planner = FftPlanner::new();
    let fx = planner.plan_fft_inverse(n);
    for row in buf.chunks_mut(n) {
        fx.process(row);
    }
    if nz > 1 {
        let fz = planner.plan_fft_inverse(nz);
        let mut col = vec![Complex::new(0.0, 0.0); nz];
        for ix in 0..n {
            for iz in 0..nz {
                col[iz] = buf[iz * n + ix];
            }
            fz.process(&mut col);
            for iz in 0..nz {
                buf[iz * n + ix] = col[iz];
            }
        }
    }
    let mut heights: Vec<f64> = buf.iter().map(|c| c.re).collect();
    let rms = (heights.iter().map(|y| y * y).sum::<f64>() / heights.len() as f64).sqrt();
    let s = if rms > 0.0 { h / rms } else { 0.0 };
    heights.iter_mut().for_each(|y| *y *= s);
    HeightField {
        nx: n,
        nz,
        dx: d,
        dz: d,
        heights,
        triangulation: Default::default(),
    }
}

/// `(α, β)` of a velocity (docs/physics.md §1), radians.
pub fn angles(u: &nalgebra::Vector3<f64>) -> (f64, f64) {
    let s = u.norm();
    let a = (u.y / s).clamp(-1.0, 1.0).asin();
    let hz = (u.x * u.x + u.z * u.z).sqrt();
    let b = if hz > 0.0 { (-u.z).atan2(u.x) } else { 0.0 };
    (a, b)
}

/// Wraps into (−π, π].
pub fn wrap(x: f64) -> f64 {
    let mut y = x.rem_euclid(std::f64::consts::TAU);
    if y > std::f64::consts::PI {
        y -= std::f64::consts::TAU;
    }
    y
}

/// Mean and standard error.
pub fn mean_se(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let m = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0);
    (m, (var / n).sqrt())
}

/// Standard deviation.
pub fn std(v: &[f64]) -> f64 {
    let (m, _) = mean_se(v);
    (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (v.len() as f64 - 1.0)).sqrt()
}

use roughwall::deterministic::{run_condition, ConditionRun, ModelSetup};
use roughwall::CollisionLaw;
use roughwall::Deviations;
use roughwall::Tracker;
use roughwall::{IncidentCondition, SpeedLaw};

/// A Gaussian wall with normal-angle deviations `(Δξ, Δζ)` in degrees (Eq. 15,
/// `c_L = √2 h / Δ`, `h = 1`), spacing `c_L,min / per_c`, side `≥ side · c_L,max`.
pub fn wall(dxi_deg: f64, dzeta_deg: f64, per_c: f64, side: f64, seed: u64) -> HeightField {
    let c = |d: f64| (d > 0.0).then(|| 2f64.sqrt() / d.to_radians());
    let (cx, cz) = (c(dxi_deg), c(dzeta_deg));
    let cs: Vec<f64> = [cx, cz].into_iter().flatten().collect();
    let cmin = cs.iter().copied().fold(f64::INFINITY, f64::min);
    let cmax = cs.iter().copied().fold(0.0, f64::max);
    let d = cmin / per_c;
    let n = ((side * cmax / d).ceil() as usize).div_ceil(8) * 8;
    gaussian_surface(n, d, 1.0, cx, cz, seed)
}

/// `dev` belongs to the whole harness; re-exported for the deterministic tests.
#[allow(unused_imports)] // unused in the binaries without deterministic tests
/// Wall deviations `(Δξ, Δζ)` given in degrees.
pub fn dev(dxi_deg: f64, dzeta_deg: f64) -> Deviations {
    Deviations {
        delta_xi: dxi_deg.to_radians(),
        delta_zeta: dzeta_deg.to_radians(),
    }
}

/// Runs one condition (angles in degrees) with 1-degree bins and ψ = 2.
#[allow(clippy::too_many_arguments)]
pub fn run(
    tracker: &Tracker<'_>,
    law: &CollisionLaw,
    dv: &Deviations,
    alpha_deg: f64,
    beta_deg: f64,
    index: u64,
    count: usize,
    speed: SpeedLaw,
) -> ConditionRun {
    let setup = ModelSetup {
        law: *law,
        diameter_m: 500e-6,
        speed,
        wall: *dv,
        psi: 2.0,
        erosion: None,
        spin: Default::default(),
    };
    run_condition(
        tracker,
        &setup,
        IncidentCondition::from_degrees(alpha_deg, beta_deg),
        index,
        count,
        42,
    )
}

pub const UNIT: SpeedLaw = SpeedLaw::horizontal(1.0, 0.0);

pub fn deg(v: impl Iterator<Item = f64>) -> Vec<f64> {
    v.map(f64::to_degrees).collect()
}
