//! The lay of a scan and its normal-angle deviations along and across it: the `Δξ`, `Δζ` of
//! Radenkovic & Simonin 2021 (Eq. 15; docs/physics.md §1, §4) in the frame of the lay,
//! measured like Table 1 over the triangles of the grid.
//!
//! Each cell whose four corners are valid is split into two triangles along alternating
//! diagonals, as the deterministic model triangulates a wall
//! ([`crate::surface::Triangulation::Alternating`]). For a triangle's upward unit normal
//! `n`, `(a, b) = (n·x, n·y)` in the scan's axes. The lay is the direction `l = (cos φ, sin
//! φ)` along which the normal's component `n·l` varies least (the smallest eigenvector of
//! the covariance of `(a, b)`): the direction of the grooves of a ground, milled or rolled
//! wall, the axis of the longest correlation length of a Gaussian one. ISO 25178-2 §4.5.3
//! defines the texture direction `Std` from the angular power spectrum instead; on a
//! Gaussian surface both give the axis of the autocorrelation's longest extent.
//!
//! In the lay's frame `ξ' = −asin(n·l)` (along) and `ζ' = −asin(n·t)`, `t = (−sin φ, cos φ)`
//! (across); `Δξ`, `Δζ` are their standard deviations, the deviations the stochastic model
//! and `rw_wall_params` take, with `β⁻` measured from the lay.

use super::ScanField;
// Branch-free asin, 1e-15 absolute: the per-triangle angles are the scan's hot loop.
use crate::surface::stats::asin_fast;
use crate::surface::stats::{Histogram, HistogramSpec};
use rayon::prelude::*;

/// The lay and the normal-angle statistics along and across it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lay {
    /// Triangles used.
    pub triangles: u64,
    /// Angle `φ` of the lay from the scan's `x` towards its `y` (rad, in `(−π/2, π/2]`);
    /// the models' `β*` of the lay ([`ScanField`]).
    pub angle: f64,
    /// `Δξ`: standard deviation of `ξ'` along the lay (rad).
    pub delta_xi: f64,
    /// `Δζ`: standard deviation of `ζ'` across the lay (rad).
    pub delta_zeta: f64,
    /// Correlation of `ξ'` and `ζ'` in the lay's frame (0 up to the nonlinearity of asin).
    pub rho: f64,
    /// Skewness of `ξ'` and of `ζ'` (0 for Gaussian slopes).
    pub skewness: [f64; 2],
    /// Kurtosis of `ξ'` and of `ζ'` (3 for Gaussian slopes).
    pub kurtosis: [f64; 2],
    /// `Δξ` and `Δζ` along the scan's own `x` and `y`.
    pub delta_scan_axes: [f64; 2],
}

/// The upward unit normals' `(n·x, n·y)` of the valid triangles of cell row `iy`, passed to
/// `visit`.
fn row_normals(f: &ScanField, iy: usize, mut visit: impl FnMut(f64, f64)) {
    let (dx, dy) = (f.dx, f.dy);
    for ix in 0..f.nx - 1 {
        let (Some(h00), Some(h10), Some(h01), Some(h11)) = (
            f.at(ix, iy),
            f.at(ix + 1, iy),
            f.at(ix, iy + 1),
            f.at(ix + 1, iy + 1),
        ) else {
            continue;
        };
        // Gradients (∂h/∂x, ∂h/∂y) of the two triangles: split along (0,0)–(1,1) when
        // ix + iy is even, along (1,0)–(0,1) otherwise.
        let grads = if (ix + iy).is_multiple_of(2) {
            [
                ((h10 - h00) / dx, (h11 - h10) / dy),
                ((h11 - h01) / dx, (h01 - h00) / dy),
            ]
        } else {
            [
                ((h10 - h00) / dx, (h01 - h00) / dy),
                ((h11 - h01) / dx, (h11 - h10) / dy),
            ]
        };
        for (gx, gy) in grads {
            // n ∝ (−∂h/∂x, −∂h/∂y, 1); a = n·x, b = n·y.
            let norm = (1.0 + gx * gx + gy * gy).sqrt();
            visit(-gx / norm, -gy / norm);
        }
    }
}

/// Sums per row, added in row order (the same bits for any thread count).
fn row_sums<const K: usize>(
    f: &ScanField,
    per: impl Fn(f64, f64, &mut [f64; K]) + Sync,
) -> [f64; K] {
    let rows: Vec<[f64; K]> = (0..f.ny - 1)
        .into_par_iter()
        .map(|iy| {
            let mut s = [0.0; K];
            row_normals(f, iy, |a, b| per(a, b, &mut s));
            s
        })
        .collect();
    rows.iter().fold([0.0; K], |mut acc, r| {
        for (a, x) in acc.iter_mut().zip(r) {
            *a += x;
        }
        acc
    })
}

/// The lay of a scan and the deviations along and across it; `None` without a triangle
/// (no cell with four valid corners).
pub fn lay(f: &ScanField) -> Option<Lay> {
    // One pass gives both the angle and the mean normal the moments are taken about.
    let (angle, mean) = angle_and_mean(f)?;
    Some(moments_at(f, angle, mean))
}

/// The lay's angle `φ` (rad, in `(−π/2, π/2]`): the direction along which the triangle
/// normals' component varies least; `None` with fewer than two triangles.
pub fn lay_angle(f: &ScanField) -> Option<f64> {
    angle_and_mean(f).map(|(angle, _)| angle)
}

/// The count and mean of the triangle normals' `(a, b)`.
struct MeanNormal {
    n: f64,
    a: f64,
    b: f64,
}

/// [`lay_angle`] and the mean normal, from one pass over the triangles.
fn angle_and_mean(f: &ScanField) -> Option<(f64, MeanNormal)> {
    // The covariance of (a, b).
    let [n, sa, sb, saa, sbb, sab] = row_sums::<6>(f, |a, b, s| {
        s[0] += 1.0;
        s[1] += a;
        s[2] += b;
        s[3] += a * a;
        s[4] += b * b;
        s[5] += a * b;
    });
    if n < 2.0 {
        return None;
    }
    let (ma, mb) = (sa / n, sb / n);
    let (caa, cbb, cab) = (saa / n - ma * ma, sbb / n - mb * mb, sab / n - ma * mb);
    // Principal axes of the 2 × 2 covariance: the major one at ψ = ½ atan2(2c_ab, c_aa − c_bb);
    // the lay (least variance of n·l) is perpendicular to it.
    let major = 0.5 * (2.0 * cab).atan2(caa - cbb);
    let mut angle = major + std::f64::consts::FRAC_PI_2;
    if angle > std::f64::consts::FRAC_PI_2 {
        angle -= std::f64::consts::PI;
    }
    Some((angle, MeanNormal { n, a: ma, b: mb }))
}

/// The deviations along and across the direction `angle` (rad, from the scan's `x` towards
/// its `y`; [`lay_angle`] for the scan's own lay, or the lay of another surface, e.g. the
/// scan a sphere's centre surface came from); `None` with fewer than two triangles.
pub fn lay_at(f: &ScanField, angle: f64) -> Option<Lay> {
    let [n, sa, sb] = row_sums::<3>(f, |a, b, s| {
        s[0] += 1.0;
        s[1] += a;
        s[2] += b;
    });
    if n < 2.0 {
        return None;
    }
    Some(moments_at(
        f,
        angle,
        MeanNormal {
            n,
            a: sa / n,
            b: sb / n,
        },
    ))
}

/// The deviations along and across `angle`, about the mean normal `mean` (at least two
/// triangles).
fn moments_at(f: &ScanField, angle: f64, mean: MeanNormal) -> Lay {
    let MeanNormal { n, a: ma, b: mb } = mean;
    let (c, s) = (angle.cos(), angle.sin());
    // Pass 2: moments of ξ' = −asin(n·l), ζ' = −asin(n·t), and of the scan axes, each
    // about the angle of the mean normal (so that a tilted scan loses no precision).
    let xi0 = -(ma * c + mb * s).clamp(-1.0, 1.0).asin();
    let zeta0 = -(-ma * s + mb * c).clamp(-1.0, 1.0).asin();
    let (xa0, yb0) = (-ma.clamp(-1.0, 1.0).asin(), -mb.clamp(-1.0, 1.0).asin());
    let m = row_sums::<13>(f, |a, b, acc| {
        let xi = -asin_fast((a * c + b * s).clamp(-1.0, 1.0)) - xi0;
        let zeta = -asin_fast((-a * s + b * c).clamp(-1.0, 1.0)) - zeta0;
        acc[0] += xi;
        acc[1] += xi * xi;
        acc[2] += xi * xi * xi;
        acc[3] += xi * xi * xi * xi;
        acc[4] += zeta;
        acc[5] += zeta * zeta;
        acc[6] += zeta * zeta * zeta;
        acc[7] += zeta * zeta * zeta * zeta;
        acc[8] += xi * zeta;
        let (xa, yb) = (-asin_fast(a) - xa0, -asin_fast(b) - yb0);
        acc[9] += xa;
        acc[10] += xa * xa;
        acc[11] += yb;
        acc[12] += yb * yb;
    });
    let (mxi, vxi, skx, kux) = moments4(n, &m[0..4]);
    let (mze, vze, skz, kuz) = moments4(n, &m[4..8]);
    let cov = m[8] / n - mxi * mze;
    let var = |s1: f64, s2: f64| (s2 / n - (s1 / n) * (s1 / n)).max(0.0);
    let rho = if vxi > 1e-24 && vze > 1e-24 {
        cov / (vxi * vze).sqrt()
    } else {
        0.0
    };
    Lay {
        triangles: n as u64,
        angle,
        delta_xi: vxi.sqrt(),
        delta_zeta: vze.sqrt(),
        rho,
        skewness: [skx, skz],
        kurtosis: [kux, kuz],
        delta_scan_axes: [var(m[9], m[10]).sqrt(), var(m[11], m[12]).sqrt()],
    }
}

/// Cell rows per partial histogram of [`angle_histograms`]: a fixed split, whatever the
/// thread count.
const HISTOGRAM_ROWS: usize = 64;

/// Fixed-width histograms of `ξ' = −asin(n·l)` (along the direction `l = (cos φ, sin φ)`,
/// `φ = angle` from the scan's `x` towards its `y`) and `ζ' = −asin(n·t)` (across it, `t =
/// (−sin φ, cos φ)`) over the triangles [`lay`] measures, not centred: at `angle =`
/// [`Lay::angle`] the samples whose standard deviations are [`Lay::delta_xi`] and
/// [`Lay::delta_zeta`] (Radenkovic & Simonin 2021, Eq. 15), to be drawn against the normal
/// law of Eqs. (12)–(13). `spec` gives the range `[−half_range, half_range)` (rad) and the
/// bin count (at least 1); a sample outside it counts in [`Histogram::outside`]. Blocks of
/// rows are binned apart and merged in row order: the same counts for any thread count.
pub fn angle_histograms(f: &ScanField, angle: f64, spec: HistogramSpec) -> [Histogram; 2] {
    let (c, s) = (angle.cos(), angle.sin());
    let bins = spec.bins.max(1);
    let cell_rows = f.ny - 1;
    let blocks: Vec<[Histogram; 2]> = (0..cell_rows.div_ceil(HISTOGRAM_ROWS))
        .into_par_iter()
        .map(|b| {
            let mut h = [
                Histogram::new(spec.half_range, bins),
                Histogram::new(spec.half_range, bins),
            ];
            let rows = b * HISTOGRAM_ROWS..((b + 1) * HISTOGRAM_ROWS).min(cell_rows);
            for iy in rows {
                row_normals(f, iy, |a, bb| {
                    h[0].add(-asin_fast((a * c + bb * s).clamp(-1.0, 1.0)));
                    h[1].add(-asin_fast((-a * s + bb * c).clamp(-1.0, 1.0)));
                });
            }
            h
        })
        .collect();
    let mut out = [
        Histogram::new(spec.half_range, bins),
        Histogram::new(spec.half_range, bins),
    ];
    for block in &blocks {
        out[0].merge(&block[0]);
        out[1].merge(&block[1]);
    }
    out
}

/// Mean, variance, skewness and kurtosis from the raw sums `Σx, Σx², Σx³, Σx⁴` of `n`
/// values (skewness and kurtosis 0 for a constant). The angles are small and centred near
/// 0, so forming central moments from raw ones loses little.
fn moments4(n: f64, s: &[f64]) -> (f64, f64, f64, f64) {
    let mu = s[0] / n;
    let v = (s[1] / n - mu * mu).max(0.0);
    let m3 = s[2] / n - 3.0 * mu * s[1] / n + 2.0 * mu.powi(3);
    let m4 = s[3] / n - 4.0 * mu * s[2] / n + 6.0 * mu * mu * s[1] / n - 3.0 * mu.powi(4);
    // Below 10⁻¹² rad the spread is round-off (a plane): no shape to speak of.
    if v > 1e-24 {
        (mu, v, m3 / v.powf(1.5), m4 / (v * v))
    } else {
        (mu, v, 0.0, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A generated Garcia–Stoll wall with its `x` along the grooves, read as a scan: the lay
    /// is the scan's `x`, the deviations those the generator measures; the same wall
    /// transposed has its lay along the scan's `y`.
    #[test]
    fn the_lay_of_a_generated_wall_is_its_smooth_axis() {
        // h = 1 µm, Δξ = 2.5°, Δζ = 7.5° (c_L = √2 h/Δ, Eq. 15), 8 nodes per c_Lz: a
        // surface of 64 c_Lz by 21 c_Lx.
        let g = crate::surface::scan::tests::sec3_wall(512, 11);
        let scan = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights.clone()).unwrap();
        let l = lay(&scan).unwrap();
        assert!(
            l.angle.abs() < 2f64.to_radians(),
            "{}",
            l.angle.to_degrees()
        );
        let measured = crate::surface::stats::measured_deviations(&g);
        // Same triangles but for the periodic seam: within a few per cent.
        assert!(
            (l.delta_xi / measured.delta_xi - 1.0).abs() < 0.05,
            "{l:?} {measured:?}"
        );
        assert!(
            (l.delta_zeta / measured.delta_zeta - 1.0).abs() < 0.05,
            "{l:?} {measured:?}"
        );
        assert!(l.rho.abs() < 0.1);
        // Gaussian slopes; a 64 × 21 c_L surface holds about 1 400 independent cells, so
        // skewness and kurtosis are known to ±0.07 and ±0.13.
        for k in 0..2 {
            assert!(
                l.skewness[k].abs() < 0.2 && (l.kurtosis[k] - 3.0).abs() < 0.4,
                "{l:?}"
            );
        }
        // Transposed: the grooves run along the scan's y.
        let mut t = vec![0.0; g.heights.len()];
        for iy in 0..g.nz {
            for ix in 0..g.nx {
                t[ix * g.nz + iy] = g.heights[iy * g.nx + ix];
            }
        }
        let ts = ScanField::new(g.nz, g.nx, g.dz, g.dx, t).unwrap();
        let lt = lay(&ts).unwrap();
        assert!(
            (lt.angle.abs() - std::f64::consts::FRAC_PI_2).abs() < 2f64.to_radians(),
            "{}",
            lt.angle.to_degrees()
        );
        assert!((lt.delta_xi / l.delta_xi - 1.0).abs() < 0.02);
        assert!((lt.delta_zeta / l.delta_zeta - 1.0).abs() < 0.02);
    }

    /// The histograms of a generated wall hold every triangle, spread as the deviations
    /// say, with the same counts for any thread count; a tilted plane fills one bin.
    #[test]
    fn angle_histograms_hold_every_triangle_whatever_the_threads() {
        let g = crate::surface::scan::tests::sec3_wall(256, 5);
        let mut h = g.heights.clone();
        h[300] = f64::NAN;
        let scan = ScanField::new(g.nx, g.nz, g.dx, g.dz, h).unwrap();
        let l = lay(&scan).unwrap();
        let hs = HistogramSpec {
            half_range: 4.0 * l.delta_zeta,
            bins: 100,
        };
        let in_pool = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| angle_histograms(&scan, l.angle, hs))
        };
        let [xi, zeta] = in_pool(1);
        assert_eq!(in_pool(3), [xi.clone(), zeta.clone()]);
        for (h, delta) in [(&xi, l.delta_xi), (&zeta, l.delta_zeta)] {
            assert_eq!(h.counts.iter().sum::<u64>() + h.outside, l.triangles);
            // The binned standard deviation (bin centres, about the binned mean) is the
            // deviation up to the binning (1/12 of a bin width squared) and the tails.
            let w = h.bin_width();
            let n = l.triangles as f64;
            let centre = |i: usize| -h.half_range + (i as f64 + 0.5) * w;
            let m: f64 = h
                .counts
                .iter()
                .enumerate()
                .map(|(i, &k)| k as f64 * centre(i))
                .sum::<f64>()
                / n;
            let v: f64 = h
                .counts
                .iter()
                .enumerate()
                .map(|(i, &k)| k as f64 * (centre(i) - m).powi(2))
                .sum::<f64>()
                / n;
            assert!(
                (v.sqrt() / delta - 1.0).abs() < 0.02,
                "{} {delta}",
                v.sqrt()
            );
        }
        // Along the lay the spread is the smaller one: ξ' fills fewer bins.
        let occupied = |h: &Histogram| h.counts.iter().filter(|&&k| k > 0).count();
        assert!(occupied(&xi) < occupied(&zeta));
        // A plane tilted along x: one normal, all of ξ' in one bin, ζ' in the middle one.
        let plane: Vec<f64> = (0..40).map(|i| 0.015 * (i % 8) as f64).collect();
        let p = ScanField::new(8, 5, 1.0, 1.0, plane).unwrap();
        let [px, pz] = angle_histograms(
            &p,
            0.0,
            HistogramSpec {
                half_range: 0.1,
                bins: 20,
            },
        );
        assert_eq!(occupied(&px), 1);
        assert_eq!(px.counts.iter().sum::<u64>(), 56);
        // ξ' = −asin(n·x) = asin(0.015/√1.000225) ≈ 0.015 rad: bin 11 of 20 over ±0.1.
        assert_eq!(px.counts[11], 56);
        assert_eq!(pz.counts[10], 56);
    }

    /// A tilted plane has one normal: no spread, and missing corners drop their cells.
    #[test]
    fn a_plane_has_no_spread_and_holes_drop_cells() {
        let mut h: Vec<f64> = (0..20).map(|i| 0.1 * (i % 5) as f64).collect();
        let full = lay(&ScanField::new(5, 4, 1.0, 1.0, h.clone()).unwrap()).unwrap();
        assert_eq!(full.triangles, 24);
        assert!(full.delta_xi < 1e-12 && full.delta_zeta < 1e-12, "{full:?}");
        h[6] = f64::NAN;
        let holed = lay(&ScanField::new(5, 4, 1.0, 1.0, h).unwrap()).unwrap();
        assert_eq!(holed.triangles, 16);
        let none = ScanField::new(2, 2, 1.0, 1.0, vec![0.0, 0.0, 0.0, f64::NAN]).unwrap();
        assert_eq!(lay(&none), None);
    }
}
