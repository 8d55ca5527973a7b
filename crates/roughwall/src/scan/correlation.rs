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
    /// Lags (m), from 0 in steps of the smaller grid spacing (coarser where a quarter of the
    /// scan holds more than 256 of them).
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

/// Lags at most. The lag step is the smaller grid spacing, coarsened when a quarter of the
/// scan holds more steps than this: a very anisotropic pixel (1 m × 1 µm) would otherwise ask
/// for 10⁵ lags and minutes of work (issue 42). Scans up to 1024 points along their shorter
/// side with square pixels keep the grid's step; a larger one a step of at most 1/1024 of
/// that side, still well below the correlation lengths a scan resolves.
const MAX_LAGS: usize = 256;

/// The stride at which sample points are taken, along both axes: at most [`MAX_SAMPLES`]
/// points on a scan of ordinary shape; on a strip (a few points across, 10⁵ or more along),
/// where the first choice would keep every row, coarser, until the sample rows and points
/// together are at most twice that (the work per lag is one pass over both).
fn sample_stride(nx: usize, ny: usize) -> usize {
    let mut s = ((nx * ny) as f64 / MAX_SAMPLES as f64)
        .sqrt()
        .ceil()
        .max(1.0) as usize;
    while nx.div_ceil(s) * ny.div_ceil(s) + ny.div_ceil(s) > 2 * MAX_SAMPLES {
        s += 1;
    }
    s
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
    // Sample rows a chunk at a time, each row's sums added in row order.
    let sample_rows = f.ny.div_ceil(stride);
    let mut sums = vec![(0.0, 0usize); shifts.len()];
    super::in_row_chunks(
        sample_rows,
        |chunk| {
            chunk
                .into_par_iter()
                .map(|r| {
                    let iy = r * stride;
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
                .collect()
        },
        |row: Vec<(f64, usize)>| {
            for (a, r) in sums.iter_mut().zip(&row) {
                *a = (a.0 + r.0, a.1 + r.1);
            }
        },
    );
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
    let stride = sample_stride(f.nx, f.ny);
    let max_lag = 0.25 * (f.nx as f64 * f.dx).min(f.ny as f64 * f.dy);
    let step = f.dx.min(f.dy).max(max_lag / MAX_LAGS as f64);
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

    /// A strip of very anisotropic pixels (1 m × 1 µm, issue 42) is characterised in a
    /// bounded number of lags: 2 × 100 000 points took minutes with one lag per micrometre.
    #[test]
    fn anisotropic_pixels_keep_the_lags_bounded() {
        let ny = 100_000;
        let h: Vec<f64> = (0..2 * ny)
            .map(|i| 1e-7 * ((i as f64 * 0.37).sin() + (i as f64 * 1.91).cos()))
            .collect();
        let f = ScanField::new(2, ny, 1.0, 1e-6, h).unwrap();
        let r = correlation(&f, 0.0);
        assert!(r.lags_m.len() <= MAX_LAGS + 1, "{} lags", r.lags_m.len());
        assert!(r.along.iter().chain(&r.across).all(|v| !v.is_infinite()));
        // A strip's samples stay bounded; an ordinary scan keeps the first choice.
        assert_eq!(sample_stride(4096, 4096), 8);
        assert_eq!(sample_stride(650, 650), 2);
        let s = sample_stride(2, 1 << 27);
        assert!(
            2usize.div_ceil(s) * (1usize << 27).div_ceil(s) <= 2 * MAX_SAMPLES,
            "{s}"
        );
        // A scan of square pixels keeps the grid's step.
        let g = ScanField::new(
            64,
            64,
            1e-6,
            1e-6,
            (0..4096).map(|i| 1e-7 * (i as f64).sin()).collect(),
        )
        .unwrap();
        let r = correlation(&g, 0.0);
        assert!((r.lags_m[1] - 1e-6).abs() < 1e-18, "{:?}", &r.lags_m[..2]);
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
