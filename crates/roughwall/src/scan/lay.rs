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
use crate::surface::stats::{asin_fast, asin_lanes, Lanes, LANES};
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

/// The upward unit normals `n` of the valid triangles of one cell row, as `(a, b) = (n·x,
/// n·y)`: `a[0][i]`, `b[0][i]` of the first triangle of the row's `i`-th cell with four
/// valid corners, `a[1][i]`, `b[1][i]` of its second; a pass takes them in that order (cell
/// by cell, first triangle first). With room for what a pass computes from them.
#[derive(Default)]
struct RowBuf {
    a: [Vec<f64>; 2],
    b: [Vec<f64>; 2],
    /// `(h[ix, iy+1] − h[ix, iy])/dy` along the row.
    dy: Vec<f64>,
    /// Per-triangle values of a pass (angles), as `a` and `b`.
    v: [[Vec<f64>; 2]; 4],
}

impl RowBuf {
    /// Valid cells of the row.
    fn cells(&self) -> usize {
        self.a[0].len()
    }

    /// The normals of cell row `iy` (`iy + 1 < f.ny`).
    #[inline(always)]
    fn fill(&mut self, f: &ScanField, iy: usize) {
        let (nx, dx, dy) = (f.nx, f.dx, f.dy);
        let r0 = &f.heights[iy * nx..(iy + 1) * nx];
        let r1 = &f.heights[(iy + 1) * nx..(iy + 2) * nx];
        let [a0, a1] = &mut self.a;
        let [b0, b1] = &mut self.b;
        for v in [&mut *a0, &mut *a1, &mut *b0, &mut *b1] {
            v.clear();
        }
        // Gradients (∂h/∂x, ∂h/∂y) of the two triangles of each cell: split along
        // (0,0)–(1,1) when ix + iy is even, along (1,0)–(0,1) otherwise.
        if r0.iter().chain(r1).fold(false, |m, h| m | h.is_nan()) {
            // Cells with a missing corner drop out.
            for ix in 0..nx - 1 {
                let (h00, h10, h01, h11) = (r0[ix], r0[ix + 1], r1[ix], r1[ix + 1]);
                if h00.is_nan() || h10.is_nan() || h01.is_nan() || h11.is_nan() {
                    continue;
                }
                let [(g0x, g0y), (g1x, g1y)] = if (ix + iy).is_multiple_of(2) {
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
                a0.push(g0x);
                b0.push(g0y);
                a1.push(g1x);
                b1.push(g1y);
            }
        } else {
            // Every cell: the same differences, taken along whole rows.
            let m = nx - 1;
            self.dy.clear();
            self.dy
                .extend(r0.iter().zip(r1).map(|(&h0, &h1)| (h1 - h0) / dy));
            for v in [&mut *a0, &mut *a1, &mut *b0, &mut *b1] {
                v.resize(m, 0.0);
            }
            let (left, right) = (&self.dy[..m], &self.dy[1..]);
            let (h00, h10, h01, h11) = (&r0[..m], &r0[1..], &r1[..m], &r1[1..]);
            for (g, (hi, lo)) in a0.iter_mut().zip(h10.iter().zip(h00)) {
                *g = (hi - lo) / dx;
            }
            for (g, (hi, lo)) in a1.iter_mut().zip(h11.iter().zip(h01)) {
                *g = (hi - lo) / dx;
            }
            // Cell ix + iy even: the first triangle takes the right edge's y-difference.
            let odd = iy % 2;
            for (ix, ((g0, g1), (&l, &r))) in b0
                .iter_mut()
                .zip(b1.iter_mut())
                .zip(left.iter().zip(right))
                .enumerate()
            {
                let even = ix % 2 == odd;
                *g0 = if even { r } else { l };
                *g1 = if even { l } else { r };
            }
        }
        // n ∝ (−∂h/∂x, −∂h/∂y, 1).
        for t in 0..2 {
            for (a, b) in self.a[t].iter_mut().zip(self.b[t].iter_mut()) {
                let (gx, gy) = (*a, *b);
                let norm = (1.0 + gx * gx + gy * gy).sqrt();
                *a = -gx / norm;
                *b = -gy / norm;
            }
        }
    }

    /// `v[k][t][i] = −asin((a·c + b·s) clamped to [−1, 1]) − shift` for every triangle.
    #[inline(always)]
    fn neg_asin(&mut self, k: usize, c: f64, s: f64, shift: f64) {
        for t in 0..2 {
            let (a, b, v) = (&self.a[t], &self.b[t], &mut self.v[k][t]);
            v.clear();
            v.extend(
                a.iter()
                    .zip(b)
                    .map(|(&a, &b)| (a * c + b * s).clamp(-1.0, 1.0)),
            );
            neg_asin_in_place(v, shift);
        }
    }
}

impl RowBuf {
    /// `v[k][t][i] = −asin(b) − shift` (`of_b`) or `−asin(a) − shift` for every triangle.
    #[inline(always)]
    fn neg_asin_of(&mut self, k: usize, of_b: bool, shift: f64) {
        for t in 0..2 {
            let src = if of_b { &self.b[t] } else { &self.a[t] };
            let v = &mut self.v[k][t];
            v.clear();
            v.extend_from_slice(src);
            neg_asin_in_place(v, shift);
        }
    }
}

/// `x ← −asin x − shift`, [`asin_fast`] bit for bit, [`LANES`] values at a time.
#[inline(always)]
fn neg_asin_in_place(v: &mut [f64], shift: f64) {
    let mut blocks = v.chunks_exact_mut(LANES);
    for x in &mut blocks {
        let lanes: &mut Lanes = x.try_into().expect("chunks_exact yields LANES values");
        let mut y = [0.0; LANES];
        asin_lanes(lanes, &mut y);
        for l in 0..LANES {
            lanes[l] = -y[l] - shift;
        }
    }
    for x in blocks.into_remainder() {
        *x = -asin_fast(*x) - shift;
    }
}

/// One pass's work on one cell row (its normals in a [`RowBuf`]).
trait RowKernel {
    type Out;
    /// Implementations are `#[inline(always)]`, so that [`run_row`] compiles them for AVX2.
    fn row(&mut self, f: &ScanField, iy: usize, buf: &mut RowBuf) -> Self::Out;
}

/// `kernel` on cell row `iy`, compiled once for the baseline CPU and once with AVX2 (chosen
/// at run time); no fused multiply-adds are used, so both give the same bits.
fn run_row<K: RowKernel>(kernel: &mut K, f: &ScanField, iy: usize, buf: &mut RowBuf) -> K::Out {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2 (checked just above).
        return unsafe { run_row_avx2(kernel, f, iy, buf) };
    }
    kernel.row(f, iy, buf)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn run_row_avx2<K: RowKernel>(
    kernel: &mut K,
    f: &ScanField,
    iy: usize,
    buf: &mut RowBuf,
) -> K::Out {
    kernel.row(f, iy, buf)
}

/// Sums over the triangles, `per(a, b, sums)` for each in turn.
#[derive(Clone)]
struct Sums<F, const K: usize>(F);

impl<F: Fn(f64, f64, &mut [f64; K]), const K: usize> RowKernel for Sums<F, K> {
    type Out = [f64; K];
    #[inline(always)]
    fn row(&mut self, f: &ScanField, iy: usize, buf: &mut RowBuf) -> [f64; K] {
        buf.fill(f, iy);
        let mut s = [0.0; K];
        for i in 0..buf.cells() {
            for t in 0..2 {
                (self.0)(buf.a[t][i], buf.b[t][i], &mut s);
            }
        }
        s
    }
}

/// Row partial sums of `kernel`, each over the row's triangles in order, added in row
/// order (the same bits for any thread count), a chunk of rows at a time.
fn row_sums<K, const N: usize>(f: &ScanField, kernel: K) -> [f64; N]
where
    K: RowKernel<Out = [f64; N]> + Clone + Send + Sync,
{
    let mut acc = [0.0; N];
    super::in_row_chunks(
        f.ny - 1,
        |rows| {
            rows.into_par_iter()
                .map_init(
                    || (kernel.clone(), RowBuf::default()),
                    |(k, buf), iy| run_row(k, f, iy, buf),
                )
                .collect()
        },
        |r: [f64; N]| {
            for (a, x) in acc.iter_mut().zip(&r) {
                *a += x;
            }
        },
    );
    acc
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
pub(super) struct MeanNormal {
    n: f64,
    a: f64,
    b: f64,
}

/// [`lay_angle`] and the mean normal, from one pass over the triangles.
pub(super) fn angle_and_mean(f: &ScanField) -> Option<(f64, MeanNormal)> {
    // The covariance of (a, b).
    let [n, sa, sb, saa, sbb, sab] = row_sums(
        f,
        Sums(|a: f64, b: f64, s: &mut [f64; 6]| {
            s[0] += 1.0;
            s[1] += a;
            s[2] += b;
            s[3] += a * a;
            s[4] += b * b;
            s[5] += a * b;
        }),
    );
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
    let [n, sa, sb] = row_sums(
        f,
        Sums(|a: f64, b: f64, s: &mut [f64; 3]| {
            s[0] += 1.0;
            s[1] += a;
            s[2] += b;
        }),
    );
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

/// The sums of the moments of [`moments_at`] over the triangles: of `ξ' − ξ'₀` (powers 1 to
/// 4), of `ζ' − ζ'₀` (1 to 4), their product, and of the angles along the scan's `x` and `y`
/// less theirs (powers 1 and 2), `ξ'₀` … the angles of the mean normal (`shift`).
#[derive(Clone)]
struct Moments {
    c: f64,
    s: f64,
    shift: [f64; 4],
}

impl RowKernel for Moments {
    type Out = [f64; 13];
    #[inline(always)]
    fn row(&mut self, f: &ScanField, iy: usize, buf: &mut RowBuf) -> [f64; 13] {
        let (c, s) = (self.c, self.s);
        let [xi0, zeta0, xa0, yb0] = self.shift;
        buf.fill(f, iy);
        // ξ' = −asin(n·l), ζ' = −asin(n·t); along the scan's axes −asin(a), −asin(b).
        buf.neg_asin(0, c, s, xi0);
        buf.neg_asin(1, -s, c, zeta0);
        buf.neg_asin_of(2, false, xa0);
        buf.neg_asin_of(3, true, yb0);
        let [xi, zeta, xa, yb] = &buf.v;
        let mut acc = [0.0; 13];
        for i in 0..buf.cells() {
            for t in 0..2 {
                let (xi, zeta) = (xi[t][i], zeta[t][i]);
                acc[0] += xi;
                acc[1] += xi * xi;
                acc[2] += xi * xi * xi;
                acc[3] += xi * xi * xi * xi;
                acc[4] += zeta;
                acc[5] += zeta * zeta;
                acc[6] += zeta * zeta * zeta;
                acc[7] += zeta * zeta * zeta * zeta;
                acc[8] += xi * zeta;
                let (xa, yb) = (xa[t][i], yb[t][i]);
                acc[9] += xa;
                acc[10] += xa * xa;
                acc[11] += yb;
                acc[12] += yb * yb;
            }
        }
        acc
    }
}

/// The sums of [`deviations_at`] over the triangles: of `ξ' − ξ'₀`, its square, `ζ' − ζ'₀`
/// and its square (the first, second, fifth and sixth of [`Moments`], bit for bit).
#[derive(Clone)]
struct Spread {
    c: f64,
    s: f64,
    shift: [f64; 2],
}

impl RowKernel for Spread {
    type Out = [f64; 4];
    #[inline(always)]
    fn row(&mut self, f: &ScanField, iy: usize, buf: &mut RowBuf) -> [f64; 4] {
        let (c, s) = (self.c, self.s);
        buf.fill(f, iy);
        buf.neg_asin(0, c, s, self.shift[0]);
        buf.neg_asin(1, -s, c, self.shift[1]);
        let [xi, zeta, ..] = &buf.v;
        let mut acc = [0.0; 4];
        for i in 0..buf.cells() {
            for t in 0..2 {
                let (xi, zeta) = (xi[t][i], zeta[t][i]);
                acc[0] += xi;
                acc[1] += xi * xi;
                acc[2] += zeta;
                acc[3] += zeta * zeta;
            }
        }
        acc
    }
}

/// `(Δξ, Δζ)` along and across `angle`, about the mean normal `mean` (at least two
/// triangles): [`moments_at`]'s deviations, bit for bit, for half its arcsines (no shape, no
/// scan axes), for the sub-patches of [`super::lay_uncertainty`].
pub(super) fn deviations_at(f: &ScanField, angle: f64, mean: MeanNormal) -> (f64, f64) {
    let MeanNormal { n, a: ma, b: mb } = mean;
    let (c, s) = (angle.cos(), angle.sin());
    let xi0 = -(ma * c + mb * s).clamp(-1.0, 1.0).asin();
    let zeta0 = -(-ma * s + mb * c).clamp(-1.0, 1.0).asin();
    let m = row_sums(
        f,
        Spread {
            c,
            s,
            shift: [xi0, zeta0],
        },
    );
    let var = |s1: f64, s2: f64| {
        let mu = s1 / n;
        (s2 / n - mu * mu).max(0.0)
    };
    (var(m[0], m[1]).sqrt(), var(m[2], m[3]).sqrt())
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
    let m = row_sums(
        f,
        Moments {
            c,
            s,
            shift: [xi0, zeta0, xa0, yb0],
        },
    );
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
/// (−sin φ, cos φ)`) over the triangles `lay` measures, not centred: at `angle =`
/// [`Lay::angle`] the samples whose standard deviations are [`Lay::delta_xi`] and
/// [`Lay::delta_zeta`] (Radenkovic & Simonin 2021, Eq. 15), to be drawn against the normal
/// law of Eqs. (12)–(13). `spec` gives the range `[−half_range, half_range)` (rad) and the
/// bin count (at least 1); a sample outside it counts in [`Histogram::outside`]. Blocks of
/// rows are binned apart and merged in row order: the same counts for any thread count.
pub fn angle_histograms(f: &ScanField, angle: f64, spec: HistogramSpec) -> [Histogram; 2] {
    let (c, s) = (angle.cos(), angle.sin());
    let bins = spec.bins.max(1);
    let cell_rows = f.ny - 1;
    let mut out = [
        Histogram::new(spec.half_range, bins),
        Histogram::new(spec.half_range, bins),
    ];
    super::in_row_chunks(
        cell_rows.div_ceil(HISTOGRAM_ROWS),
        |blocks| {
            blocks
                .into_par_iter()
                .map(|b| {
                    let mut kernel = Binned {
                        c,
                        s,
                        h: [
                            Histogram::new(spec.half_range, bins),
                            Histogram::new(spec.half_range, bins),
                        ],
                    };
                    let mut buf = RowBuf::default();
                    let rows = b * HISTOGRAM_ROWS..((b + 1) * HISTOGRAM_ROWS).min(cell_rows);
                    for iy in rows {
                        run_row(&mut kernel, f, iy, &mut buf);
                    }
                    kernel.h
                })
                .collect()
        },
        |block: [Histogram; 2]| {
            out[0].merge(&block[0]);
            out[1].merge(&block[1]);
        },
    );
    out
}

/// The histograms of [`angle_histograms`] (`c`, `s`: the cosine and sine of the direction).
struct Binned {
    c: f64,
    s: f64,
    h: [Histogram; 2],
}

impl RowKernel for Binned {
    type Out = ();
    #[inline(always)]
    fn row(&mut self, f: &ScanField, iy: usize, buf: &mut RowBuf) {
        buf.fill(f, iy);
        buf.neg_asin(0, self.c, self.s, 0.0);
        buf.neg_asin(1, -self.s, self.c, 0.0);
        for (h, [v0, v1]) in self.h.iter_mut().zip(&buf.v) {
            h.add_all(v0);
            h.add_all(v1);
        }
    }
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
        let g = crate::scan::tests::sec3_wall(512, 11);
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
        let g = crate::scan::tests::sec3_wall(256, 5);
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

    /// The sub-patches' lighter pass gives the full pass's deviations bit for bit, holes and
    /// all, at the scan's own lay and at another angle.
    #[test]
    fn deviations_at_are_the_moments_deviations_bit_for_bit() {
        let g = crate::scan::tests::sec3_wall(128, 4);
        let mut h = g.heights.clone();
        h[300] = f64::NAN;
        let scan = ScanField::new(g.nx, g.nz, g.dx, g.dz, h).unwrap();
        for angle in [lay_angle(&scan).unwrap(), 0.7] {
            let (_, mean) = angle_and_mean(&scan).unwrap();
            let (_, again) = angle_and_mean(&scan).unwrap();
            let full = moments_at(&scan, angle, mean);
            let (xi, zeta) = deviations_at(&scan, angle, again);
            assert_eq!(
                (xi.to_bits(), zeta.to_bits()),
                (full.delta_xi.to_bits(), full.delta_zeta.to_bits())
            );
        }
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

    /// The normals of cell row `iy` cell by cell, as the triangles were first walked: the
    /// reference the row kernels must match bit for bit.
    fn reference_normals(f: &ScanField, iy: usize) -> Vec<(f64, f64)> {
        let (dx, dy) = (f.dx, f.dy);
        let mut out = Vec::new();
        for ix in 0..f.nx - 1 {
            let (Some(h00), Some(h10), Some(h01), Some(h11)) = (
                f.at(ix, iy),
                f.at(ix + 1, iy),
                f.at(ix, iy + 1),
                f.at(ix + 1, iy + 1),
            ) else {
                continue;
            };
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
                let norm = (1.0 + gx * gx + gy * gy).sqrt();
                out.push((-gx / norm, -gy / norm));
            }
        }
        out
    }

    /// Rows with and without missing points, steep and gentle: the row kernels (whole-row
    /// differences, angles [`LANES`] at a time, compiled for AVX2 where the CPU has it) give
    /// the bits of the triangle-by-triangle reference with [`asin_fast`], and the same bits
    /// compiled for the baseline CPU.
    #[test]
    fn row_kernels_give_the_bits_of_the_triangle_by_triangle_reference() {
        let g = crate::scan::tests::sec3_wall(67, 2);
        let mut h: Vec<f64> = g.heights.iter().map(|h| 8.0 * h).collect();
        for k in [5, 67 * 7, 67 * 7 + 66, 67 * 30 + 31] {
            h[k] = f64::NAN;
        }
        let f = ScanField::new(g.nx, g.nz, g.dx, g.dz, h).unwrap();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        let (angle, shift) = (0.3f64, [0.01, -0.02, 0.003, 0.0]);
        let (c, s) = (angle.cos(), angle.sin());
        let moments = Moments { c, s, shift };
        let spec = (0.5, 37);
        let binned = || Binned {
            c,
            s,
            h: [
                Histogram::new(spec.0, spec.1),
                Histogram::new(spec.0, spec.1),
            ],
        };
        let (mut dispatched, mut generic) = (binned(), binned());
        let mut reference_hists = binned().h;
        let mut steep = 0;
        for iy in 0..f.ny - 1 {
            let normals = reference_normals(&f, iy);
            let mut buf = RowBuf::default();
            buf.fill(&f, iy);
            let filled: Vec<(f64, f64)> = (0..buf.cells())
                .flat_map(|i| [(buf.a[0][i], buf.b[0][i]), (buf.a[1][i], buf.b[1][i])])
                .collect();
            assert_eq!(
                bits(&filled.iter().flat_map(|&(a, b)| [a, b]).collect::<Vec<_>>()),
                bits(
                    &normals
                        .iter()
                        .flat_map(|&(a, b)| [a, b])
                        .collect::<Vec<_>>()
                ),
                "row {iy}"
            );
            let mut acc = [0.0; 13];
            for &(a, b) in &normals {
                let xi = -asin_fast((a * c + b * s).clamp(-1.0, 1.0)) - shift[0];
                let zeta = -asin_fast((-a * s + b * c).clamp(-1.0, 1.0)) - shift[1];
                steep += usize::from((-a * s + b * c).abs() > 0.5);
                acc[0] += xi;
                acc[1] += xi * xi;
                acc[2] += xi * xi * xi;
                acc[3] += xi * xi * xi * xi;
                acc[4] += zeta;
                acc[5] += zeta * zeta;
                acc[6] += zeta * zeta * zeta;
                acc[7] += zeta * zeta * zeta * zeta;
                acc[8] += xi * zeta;
                let (xa, yb) = (-asin_fast(a) - shift[2], -asin_fast(b) - shift[3]);
                acc[9] += xa;
                acc[10] += xa * xa;
                acc[11] += yb;
                acc[12] += yb * yb;
                reference_hists[0].add(-asin_fast((a * c + b * s).clamp(-1.0, 1.0)));
                reference_hists[1].add(-asin_fast((-a * s + b * c).clamp(-1.0, 1.0)));
            }
            let mut buf = RowBuf::default();
            assert_eq!(
                bits(&run_row(&mut moments.clone(), &f, iy, &mut buf)),
                bits(&acc),
                "row {iy}"
            );
            assert_eq!(
                bits(&moments.clone().row(&f, iy, &mut buf)),
                bits(&acc),
                "row {iy}"
            );
            run_row(&mut dispatched, &f, iy, &mut buf);
            generic.row(&f, iy, &mut buf);
        }
        // Both branches of the arcsine were taken.
        assert!(steep > 100 && steep < 8000, "{steep}");
        assert_eq!(dispatched.h, reference_hists);
        assert_eq!(generic.h, reference_hists);
    }
}
