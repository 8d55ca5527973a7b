//! The autocorrelation of a (levelled) scan along and across its lay, and the correlation
//! lengths: the lag at which it falls to `1/e` of its value at 0, the `c_L` of the
//! Gaussian autocorrelation `R(τ) = h² exp(−τ²/c_L²)` of the generated walls (Radenkovic &
//! Simonin 2021, Eqs. 1–2; docs/physics.md §4), so a Gaussian wall gives back its own `c_L`.
//!
//! `R(τ) = mean of h(p) h(p + τ l)` over sample points `p` of the scan with both heights
//! valid, `l` the unit vector of the direction, `h(p + τ l)` interpolated bilinearly between
//! the four nodes around it (all valid). Sample points are every `s`-th node along both
//! axes, `s` chosen so that at most 2¹⁸ are used: the memory is the scan's own, and the
//! estimate's noise is far below that of the scan's finite size.

use super::ScanField;
use rayon::prelude::*;

/// Sample points at most: 2¹⁸ pairs per lag put the estimate's own noise well below the
/// spread a finite scan has anyway (a 4096² scan is read every 8th point along each axis).
const MAX_SAMPLES: usize = 1 << 18;

/// The autocorrelation along and across a direction, normalised by its value at lag 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Correlation {
    /// The direction `φ` (rad, from the scan's `x` towards its `y`) of "along".
    pub angle: f64,
    /// Lags (m), from 0 in steps of the smaller grid spacing.
    pub lags_m: Vec<f64>,
    /// `R(τ)/R(0)` along the direction, one per lag (NaN where no pair was valid).
    pub along: Vec<f64>,
    /// `R(τ)/R(0)` across it.
    pub across: Vec<f64>,
    /// Lag (m) at which `along` first falls to `1/e` (linear between lags); `None` when it
    /// does not within a quarter of the scan.
    pub length_along_m: Option<f64>,
    /// The same across.
    pub length_across_m: Option<f64>,
}

/// Height at the fractional node position `(u, v)` (in grid steps), bilinear between four
/// valid nodes; `None` off the scan or next to a missing point.
#[inline]
pub(crate) fn bilinear(f: &ScanField, u: f64, v: f64) -> Option<f64> {
    // Up to round-off beyond the last row or column (a position computed to land on it).
    let (um, vm) = ((f.nx - 1) as f64, (f.ny - 1) as f64);
    if !(u >= 0.0 && v >= 0.0 && u <= um * (1.0 + 1e-12) && v <= vm * (1.0 + 1e-12)) {
        return None;
    }
    // `u`, `v` ≥ 0: truncation is the floor (without a call to libm's floor).
    let (i, j) = ((u as usize).min(f.nx - 2), (v as usize).min(f.ny - 2));
    let (fu, fv) = ((u - i as f64).min(1.0), (v - j as f64).min(1.0));
    let h00 = f.at(i, j)?;
    let h10 = f.at(i + 1, j)?;
    let h01 = f.at(i, j + 1)?;
    let h11 = f.at(i + 1, j + 1)?;
    Some((1.0 - fv) * ((1.0 - fu) * h00 + fu * h10) + fv * ((1.0 - fu) * h01 + fu * h11))
}

/// Lags computed together (one read of the scan's rows for all of them): at most this
/// many past the last lag needed are computed in vain.
const LAG_BATCH: usize = 16;

/// `R(τ)` along each unit vector `(cx, cy)` of `dirs` at each lag `tau` (m) of `taus`, over
/// the sample points: `out[d][k]`, `None` where no pair was valid. Each is summed over each
/// sample row in node order, and the rows' sums in row order (the same bits for any thread
/// count, and for any lags computed alongside).
fn autocorrelations(
    f: &ScanField,
    stride: usize,
    dirs: &[(f64, f64)],
    taus: &[f64],
) -> Vec<Vec<Option<f64>>> {
    let shifts: Vec<(f64, f64)> = dirs
        .iter()
        .flat_map(|&(cx, cy)| {
            taus.iter()
                .map(move |&tau| (tau * cx / f.dx, tau * cy / f.dy))
        })
        .collect();
    let rows: Vec<Vec<(f64, usize)>> = (0..f.ny)
        .into_par_iter()
        .step_by(stride)
        .map(|iy| {
            let nx = f.nx;
            let row = &f.heights[iy * nx..(iy + 1) * nx];
            shifts
                .iter()
                .map(|&(du, dv)| {
                    // `bilinear` at (ix + du, iy + dv) for each sample ix of the row, its
                    // checks and row interpolation along y taken once for the row.
                    let (mut s, mut n) = (0.0, 0usize);
                    let (um, vm) = ((nx - 1) as f64, (f.ny - 1) as f64);
                    let v = iy as f64 + dv;
                    if !(v >= 0.0 && v <= vm * (1.0 + 1e-12)) {
                        return (s, n);
                    }
                    let j = (v as usize).min(f.ny - 2);
                    let fv = (v - j as f64).min(1.0);
                    let r0 = &f.heights[j * nx..(j + 1) * nx];
                    let r1 = &f.heights[(j + 1) * nx..(j + 2) * nx];
                    for ix in (0..nx).step_by(stride) {
                        let h = row[ix];
                        let u = ix as f64 + du;
                        if h.is_nan() || !(u >= 0.0 && u <= um * (1.0 + 1e-12)) {
                            continue;
                        }
                        let i = (u as usize).min(nx - 2);
                        let fu = (u - i as f64).min(1.0);
                        let (h00, h10, h01, h11) = (r0[i], r0[i + 1], r1[i], r1[i + 1]);
                        if h00.is_nan() || h10.is_nan() || h01.is_nan() || h11.is_nan() {
                            continue;
                        }
                        let g = (1.0 - fv) * ((1.0 - fu) * h00 + fu * h10)
                            + fv * ((1.0 - fu) * h01 + fu * h11);
                        s += h * g;
                        n += 1;
                    }
                    (s, n)
                })
                .collect()
        })
        .collect();
    let sums = rows.iter().fold(vec![(0.0, 0); shifts.len()], |mut a, r| {
        for (a, r) in a.iter_mut().zip(r) {
            *a = (a.0 + r.0, a.1 + r.1);
        }
        a
    });
    sums.chunks(taus.len().max(1))
        .map(|d| {
            d.iter()
                .map(|&(s, n)| (n > 0).then(|| s / n as f64))
                .collect()
        })
        .collect()
}

/// The first lag where `r` falls to `level`, linear between lags.
fn crossing(lags: &[f64], r: &[f64], level: f64) -> Option<f64> {
    (1..r.len()).find_map(|k| {
        let (a, b) = (r[k - 1], r[k]);
        (a > level && b <= level)
            .then(|| lags[k - 1] + (a - level) / (a - b) * (lags[k] - lags[k - 1]))
    })
}

/// The autocorrelation of `f` (levelled: mean 0) along `angle` and across it, out to twice
/// the farther `1/e` crossing or a quarter of the scan's shorter side.
pub fn correlation(f: &ScanField, angle: f64) -> Correlation {
    let stride = ((f.nx * f.ny) as f64 / MAX_SAMPLES as f64)
        .sqrt()
        .ceil()
        .max(1.0) as usize;
    let step = f.dx.min(f.dy);
    let max_lag = 0.25 * (f.nx as f64 * f.dx).min(f.ny as f64 * f.dy);
    let (c, s) = (angle.cos(), angle.sin());
    let level = (-1.0f64).exp();
    let r0 = autocorrelations(f, stride, &[(c, s)], &[0.0])[0][0].unwrap_or(0.0);
    let mut out = Correlation {
        angle,
        lags_m: vec![0.0],
        along: vec![1.0],
        across: vec![1.0],
        length_along_m: None,
        length_across_m: None,
    };
    if r0 <= 0.0 {
        return out;
    }
    // Lags k = 1, 2, … (τ = k·step) up to a quarter of the scan, until τ reaches twice both
    // crossings; computed in batches, taken one by one.
    let mut k = 1usize;
    'lags: loop {
        let done = |tau: f64| match (out.length_along_m, out.length_across_m) {
            (Some(a), Some(b)) => tau >= 2.0 * a.max(b),
            _ => false,
        };
        let mut taus = Vec::with_capacity(LAG_BATCH);
        for j in k..k + LAG_BATCH {
            let tau = j as f64 * step;
            if tau > max_lag {
                break;
            }
            taus.push(tau);
            if done(tau) {
                break;
            }
        }
        if taus.is_empty() {
            break;
        }
        let r = autocorrelations(f, stride, &[(c, s), (-s, c)], &taus);
        for (j, &tau) in taus.iter().enumerate() {
            let along = r[0][j].map_or(f64::NAN, |r| r / r0);
            let across = r[1][j].map_or(f64::NAN, |r| r / r0);
            out.lags_m.push(tau);
            out.along.push(along);
            out.across.push(across);
            out.length_along_m = out
                .length_along_m
                .or_else(|| crossing(&out.lags_m, &out.along, level));
            out.length_across_m = out
                .length_across_m
                .or_else(|| crossing(&out.lags_m, &out.across, level));
            if let (Some(a), Some(b)) = (out.length_along_m, out.length_across_m) {
                if tau >= 2.0 * a.max(b) {
                    break 'lags;
                }
            }
        }
        k += taus.len();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{generate, SurfaceSpec};

    /// A generated Gaussian wall gives back its correlation lengths along and across its
    /// lay, and the autocorrelation is `exp(−τ²/c²)` near the origin.
    #[test]
    fn a_generated_wall_gives_back_its_correlation_lengths() {
        let (cx, cz) = (24e-6, 8e-6);
        let spec = SurfaceSpec {
            length_m: 512.0 * 1e-6,
            nodes: 512,
            rms_height_m: 1e-6,
            corr_length_x_m: Some(cx),
            corr_length_z_m: Some(cz),
        };
        let g = generate(&spec, 3);
        let scan = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights.clone()).unwrap();
        let r = correlation(&scan, 0.0);
        let (a, b) = (r.length_along_m.unwrap(), r.length_across_m.unwrap());
        // A 21 × 64 c_L surface: its own c_L are known to a few per cent.
        assert!((a / cx - 1.0).abs() < 0.08, "{a} vs {cx}");
        assert!((b / cz - 1.0).abs() < 0.05, "{b} vs {cz}");
        let k = r.lags_m.iter().position(|&t| t >= 4e-6).unwrap();
        let gauss = (-(r.lags_m[k] / cz).powi(2)).exp();
        assert!(
            (r.across[k] - gauss).abs() < 0.03,
            "{} vs {gauss}",
            r.across[k]
        );
        // Turned by 90°: the lengths swap.
        let t = correlation(&scan, std::f64::consts::FRAC_PI_2);
        assert!((t.length_along_m.unwrap() - b).abs() < 1e-3 * b);
        assert!((t.length_across_m.unwrap() - a).abs() < 1e-3 * a);
    }

    #[test]
    fn bilinear_is_exact_on_a_plane_and_refuses_gaps() {
        let mut h: Vec<f64> = (0..12)
            .map(|i| (i % 4) as f64 + 10.0 * (i / 4) as f64)
            .collect();
        let f = ScanField::new(4, 3, 1.0, 1.0, h.clone()).unwrap();
        assert_eq!(bilinear(&f, 1.5, 0.25), Some(1.5 + 2.5));
        assert_eq!(bilinear(&f, 3.0, 2.0), Some(23.0));
        assert_eq!(bilinear(&f, 3.5, 0.0), None);
        h[5] = f64::NAN;
        let g = ScanField::new(4, 3, 1.0, 1.0, h).unwrap();
        assert_eq!(bilinear(&g, 0.5, 0.5), None);
    }
}
