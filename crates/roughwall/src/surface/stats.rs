//! Statistics of a triangulated surface: rms height, rms slopes and the normal-vector
//! angles of Radenkovic & Simonin 2021, Table 1 (Eqs. 7–8, 14), in the principal frame
//! and in frames rotated by `β*` about `y` (docs/physics.md §1).
//!
//! The paper samples the normal along lines in the `x*` direction with steps of about
//! 0.1 µm. Every such point lies in one triangle of the shared triangulation
//! ([`HeightField::cell_normals`]) and takes that triangle's normal; lines of uniform
//! step cover the plane uniformly, so their statistics converge to the statistics over
//! all triangles, each weighted by its (equal) projected area. This module uses every
//! triangle once — the same statistic, without sampling noise and for any `β*` alike.
//!
//! Work is split in fixed chunks of grid rows (never by thread count) and the partial
//! moments are merged in chunk order, so results are bit-identical for any thread count.

use crate::surface::{HeightField, Triangulation};
use rayon::prelude::*;
use std::ops::Range;

/// Grid rows per statistics task (fixed: determines the merge order).
const ROWS_PER_CHUNK: usize = 16;

/// Histogram of an angle fluctuation (radians) on `[−half_range, half_range)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Histogram {
    /// Half-width of the binned range (rad).
    pub half_range: f64,
    /// Counts per bin (equal widths `2·half_range / counts.len()`).
    pub counts: Vec<u64>,
    /// Samples that fell outside the range.
    pub outside: u64,
}

impl Histogram {
    pub(crate) fn new(half_range: f64, bins: usize) -> Self {
        Self {
            half_range,
            counts: vec![0; bins],
            outside: 0,
        }
    }

    #[inline]
    pub(crate) fn add(&mut self, x: f64) {
        let n = self.counts.len();
        let u = (x + self.half_range) * (0.5 * n as f64 / self.half_range);
        if u >= 0.0 && u < n as f64 {
            self.counts[u as usize] += 1;
        } else {
            self.outside += 1;
        }
    }

    /// [`Histogram::add`] of every value of `xs`.
    #[inline(always)]
    pub(crate) fn add_all(&mut self, xs: &[f64]) {
        let n = self.counts.len();
        let (half, scale) = (self.half_range, 0.5 * n as f64 / self.half_range);
        for &x in xs {
            let u = (x + half) * scale;
            if u >= 0.0 && u < n as f64 {
                self.counts[u as usize] += 1;
            } else {
                self.outside += 1;
            }
        }
    }

    pub(crate) fn merge(&mut self, o: &Self) {
        for (a, b) in self.counts.iter_mut().zip(&o.counts) {
            *a += b;
        }
        self.outside += o.outside;
    }

    /// Bin width (rad).
    pub fn bin_width(&self) -> f64 {
        2.0 * self.half_range / self.counts.len() as f64
    }

    /// `(bin centre, probability density)` pairs (rad, 1/rad), normalised by all
    /// samples including those outside the range.
    pub fn density(&self) -> Vec<(f64, f64)> {
        let total = self.counts.iter().sum::<u64>() + self.outside;
        let w = self.bin_width();
        self.counts
            .iter()
            .enumerate()
            .map(|(i, &c)| {
                let x = -self.half_range + (i as f64 + 0.5) * w;
                (x, c as f64 / (total.max(1) as f64 * w))
            })
            .collect()
    }
}

/// Requested histograms: `bins` bins on `[−half_range, half_range)` (rad) for the
/// fluctuations `ξ* − 90°` and `ζ* − 90°` at every `β*`. They are meant for figures:
/// on large grids they take every k-th grid row so as to see about 8 million triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HistogramSpec {
    /// Half-width of the histogram range `[−half_range, half_range)` (rad).
    pub half_range: f64,
    /// Number of bins across that range.
    pub bins: usize,
}

/// Normal-angle statistics in the frame rotated by `β*` (one row of Table 1).
#[derive(Clone, Debug, PartialEq)]
pub struct RotatedStats {
    /// `β*` (rad).
    pub beta_star: f64,
    /// Standard deviation of `ξ*` (rad).
    pub delta_xi_star: f64,
    /// Standard deviation of `ζ*` (rad).
    pub delta_zeta_star: f64,
    /// Correlation coefficient of `ξ*` and `ζ*` (Eq. 8); 0 when either is constant.
    pub rho_xi_zeta: f64,
    /// Correlation coefficient of `ξ*` and `η*`.
    pub rho_xi_eta: f64,
    /// Correlation coefficient of `η*` and `ζ*`.
    pub rho_eta_zeta: f64,
    /// Histogram of `ξ* − 90°` (rad), when requested.
    pub hist_xi: Option<Histogram>,
    /// Histogram of `ζ* − 90°` (rad), when requested.
    pub hist_zeta: Option<Histogram>,
}

/// Summary statistics of a triangulated surface (Table 1, Eq. 14, Fig. 4).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceStats {
    /// Number of triangles used (two per cell).
    pub triangles: u64,
    /// rms height about the mean plane over all nodes (m).
    pub rms_height_m: f64,
    /// Highest node (m).
    pub max_height_m: f64,
    /// rms of `s_x = −n_x/n_y` over all triangles (Radenkovic & Simonin 2021, Sec. 2.4).
    pub rms_slope_x: f64,
    /// rms of `s_z = −n_z/n_y` over all triangles.
    pub rms_slope_z: f64,
    /// Standard deviation of `ξ` (rad), the `β* = 0` value of Eq. (15).
    pub delta_xi: f64,
    /// Standard deviation of `ζ` (rad).
    pub delta_zeta: f64,
    /// One entry per requested `β*`, in the order given.
    pub rotated: Vec<RotatedStats>,
}

/// Means and co-moments of three variables, mergeable in a fixed order
/// (Chan, Golub & LeVeque's pairwise update).
#[derive(Clone, Copy, Debug, Default)]
struct Moments3 {
    n: f64,
    mean: [f64; 3],
    /// Sums of products of deviations: `m[i][j] = Σ (x_i − mean_i)(x_j − mean_j)`.
    m: [[f64; 3]; 3],
}

impl Moments3 {
    /// From raw sums `s[i] = Σ x_i`, `ss[i][j] = Σ x_i x_j` of a small batch.
    fn from_sums(n: f64, s: &[f64; 3], ss: &[[f64; 3]; 3]) -> Self {
        if n == 0.0 {
            return Self::default();
        }
        let mean = [s[0] / n, s[1] / n, s[2] / n];
        let mut m = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] = ss[i][j] - n * mean[i] * mean[j];
            }
        }
        Self { n, mean, m }
    }

    fn merge(&mut self, o: &Self) {
        if o.n == 0.0 {
            return;
        }
        if self.n == 0.0 {
            *self = *o;
            return;
        }
        let n = self.n + o.n;
        let d = [
            o.mean[0] - self.mean[0],
            o.mean[1] - self.mean[1],
            o.mean[2] - self.mean[2],
        ];
        let f = self.n * o.n / n;
        for i in 0..3 {
            for j in 0..3 {
                self.m[i][j] += o.m[i][j] + f * d[i] * d[j];
            }
        }
        for (i, di) in d.iter().enumerate() {
            self.mean[i] += di * o.n / n;
        }
        self.n = n;
    }

    fn std(&self, i: usize) -> f64 {
        if self.n == 0.0 {
            0.0
        } else {
            (self.m[i][i].max(0.0) / self.n).sqrt()
        }
    }

    /// Correlation coefficient; 0 when either variable has no spread.
    fn rho(&self, i: usize, j: usize) -> f64 {
        let d = self.m[i][i] * self.m[j][j];
        if d > 0.0 {
            (self.m[i][j] / d.sqrt()).clamp(-1.0, 1.0)
        } else {
            0.0
        }
    }
}

/// Raw sums of one chunk of rows.
#[derive(Clone)]
struct Chunk {
    n: f64,
    /// Σ s_x², Σ s_z² (slopes have zero mean on a periodic surface: rms, not std).
    slope2: [f64; 2],
    /// Per rotation (the principal frame first, then each β*): sums of
    /// (ξ*', ζ*', η, ξ*'², ζ*'², η², ξ*'ζ*', ξ*'η, ζ*'η), a prime meaning minus 90°.
    rot: Vec<[f64; 9]>,
    hists: Vec<(Histogram, Histogram)>,
}

impl Chunk {
    fn moments(&self, k: usize) -> Moments3 {
        let r = &self.rot[k];
        let ss = [[r[3], r[6], r[7]], [r[6], r[4], r[8]], [r[7], r[8], r[5]]];
        Moments3::from_sums(self.n, &[r[0], r[1], r[2]], &ss)
    }
}

/// Per-row work buffers (structure of arrays, one entry per triangle).
struct RowBuf {
    gx: Vec<f64>,
    gz: Vec<f64>,
    nx: Vec<f64>,
    nz: Vec<f64>,
    eta: Vec<f64>,
    a: Vec<f64>,
    b: Vec<f64>,
}

impl RowBuf {
    fn new(triangles: usize) -> Self {
        let v = || vec![0.0; triangles];
        Self {
            gx: v(),
            gz: v(),
            nx: v(),
            nz: v(),
            eta: v(),
            a: v(),
            b: v(),
        }
    }
}

/// Writes the components `t[0]`, `t[2]` of [`HeightField::cell_normals`] for every
/// triangle of grid row `iz` (triangle 0 of cell `ix` at `ix`, triangle 1 at `nx + ix`).
///
/// Interior cells use the row slices with exactly the floating-point operations of
/// `cell_normals` (a unit test checks bit-for-bit equality on every cell); the last
/// cell of the row, which wraps around, calls `cell_normals` itself.
#[inline(always)]
fn row_gradients(f: &HeightField, iz: usize, gx: &mut [f64], gz: &mut [f64]) {
    let n = f.nx;
    let r0 = &f.heights[iz * n..(iz + 1) * n];
    let iz1 = (iz + 1) % f.nz;
    let r1 = &f.heights[iz1 * n..(iz1 + 1) * n];
    let (dx, dz) = (f.dx, f.dz);
    let (gx0, gx1) = gx.split_at_mut(n);
    let (gz0, gz1) = gz.split_at_mut(n);
    for ix in 0..n - 1 {
        let (h00, h10, h01, h11) = (r0[ix], r0[ix + 1], r1[ix], r1[ix + 1]);
        gx0[ix] = -(h10 - h00) / dx;
        gz0[ix] = -(h11 - h10) / dz;
        gx1[ix] = -(h11 - h01) / dx;
        gz1[ix] = -(h01 - h00) / dz;
    }
    let [t0, t1] = f.cell_normals(n - 1, iz);
    gx0[n - 1] = t0[0];
    gz0[n - 1] = t0[2];
    gx1[n - 1] = t1[0];
    gz1[n - 1] = t1[2];
    // A flipped cell's triangles pair the same x-slopes with each other's z-slope.
    if f.triangulation == Triangulation::Alternating {
        for ix in 0..n - 1 {
            if f.flipped(ix, iz) {
                std::mem::swap(&mut gz0[ix], &mut gz1[ix]);
            }
        }
    }
}

/// Lanes of the partial sums: a fixed width, so the summation order (and thus every
/// bit of the result) does not depend on the CPU's vector width.
pub(crate) const LANES: usize = 8;

pub(crate) type Lanes = [f64; LANES];

/// `LANES` triangles: unit normals, `η`, and the squared slopes added to `acc`.
#[inline(always)]
fn normals_block(
    gx: &Lanes,
    gz: &Lanes,
    nx: &mut Lanes,
    nz: &mut Lanes,
    eta: &mut Lanes,
    acc: &mut [Lanes; 2],
) {
    for l in 0..LANES {
        // t = (gx, 1, gz): s_x = −t_x/t_y = −gx, s_z = −gz (Sec. 2.4).
        acc[0][l] += gx[l] * gx[l];
        acc[1][l] += gz[l] * gz[l];
        let inv = 1.0 / (gx[l] * gx[l] + 1.0 + gz[l] * gz[l]).sqrt();
        nx[l] = gx[l] * inv;
        nz[l] = gz[l] * inv;
    }
    // η = acos(n_y), from the horizontal part for precision near 0.
    let mut r = [0.0; LANES];
    for l in 0..LANES {
        r[l] = (nx[l] * nx[l] + nz[l] * nz[l]).sqrt().min(1.0);
    }
    asin_lanes(&r, eta);
}

/// `LANES` triangles in the frame rotated by `β*` (`c = cos β*`, `s = sin β*`):
/// `a = ξ* − 90° = −asin(n·x*)`, `b = ζ* − 90° = −asin(n·z*)` (Eq. 7, docs/physics.md §1), and
/// their sums in the order of [`Chunk::rot`] added to `acc`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn rotated_block(
    nx: &Lanes,
    nz: &Lanes,
    e: &Lanes,
    c: f64,
    s: f64,
    a: &mut Lanes,
    b: &mut Lanes,
    acc: &mut [Lanes; 9],
) {
    let (mut xa, mut xb) = ([0.0; LANES], [0.0; LANES]);
    for l in 0..LANES {
        xa[l] = -(c * nx[l] - s * nz[l]).clamp(-1.0, 1.0);
        xb[l] = -(s * nx[l] + c * nz[l]).clamp(-1.0, 1.0);
    }
    asin_lanes(&xa, a);
    asin_lanes(&xb, b);
    for l in 0..LANES {
        acc[0][l] += a[l];
        acc[1][l] += b[l];
        acc[2][l] += e[l];
        acc[3][l] += a[l] * a[l];
        acc[4][l] += b[l] * b[l];
        acc[5][l] += e[l] * e[l];
        acc[6][l] += a[l] * b[l];
        acc[7][l] += a[l] * e[l];
        acc[8][l] += b[l] * e[l];
    }
}

/// Copies the tail `src` (shorter than `LANES`) into zero-padded lanes. Zero normals add
/// exact zeros to every sum, so the padding does not change any result.
fn padded(src: &[f64]) -> Lanes {
    let mut x = [0.0; LANES];
    x[..src.len()].copy_from_slice(src);
    x
}

fn lanes(x: &[f64]) -> &Lanes {
    x.try_into().expect("chunks_exact yields LANES elements")
}

fn lanes_mut(x: &mut [f64]) -> &mut Lanes {
    x.try_into().expect("chunks_exact yields LANES elements")
}

/// Unit normals and `η` of one row; returns `(Σ s_x², Σ s_z²)`.
#[inline(always)]
fn row_normals(buf: &mut RowBuf) -> [f64; 2] {
    let mut acc = [[0.0f64; LANES]; 2];
    let n = buf.gx.len();
    let full = n / LANES * LANES;
    for ((((gx, gz), nx), nz), eta) in buf.gx[..full]
        .chunks_exact(LANES)
        .zip(buf.gz[..full].chunks_exact(LANES))
        .zip(buf.nx[..full].chunks_exact_mut(LANES))
        .zip(buf.nz[..full].chunks_exact_mut(LANES))
        .zip(buf.eta[..full].chunks_exact_mut(LANES))
    {
        normals_block(
            lanes(gx),
            lanes(gz),
            lanes_mut(nx),
            lanes_mut(nz),
            lanes_mut(eta),
            &mut acc,
        );
    }
    if full < n {
        let (gx, gz) = (padded(&buf.gx[full..]), padded(&buf.gz[full..]));
        let (mut nx, mut nz, mut eta) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
        normals_block(&gx, &gz, &mut nx, &mut nz, &mut eta, &mut acc);
        buf.nx[full..].copy_from_slice(&nx[..n - full]);
        buf.nz[full..].copy_from_slice(&nz[..n - full]);
        buf.eta[full..].copy_from_slice(&eta[..n - full]);
    }
    [acc[0].iter().sum(), acc[1].iter().sum()]
}

/// Angle fluctuations in the frame rotated by `β*` (`c = cos β*`, `s = sin β*`) for one
/// row, written to `buf.a`, `buf.b`; returns their sums in the order of [`Chunk::rot`].
#[inline(always)]
fn row_rotated(buf: &mut RowBuf, c: f64, s: f64) -> [f64; 9] {
    let mut acc = [[0.0f64; LANES]; 9];
    let n = buf.nx.len();
    let full = n / LANES * LANES;
    for ((((nx, nz), e), a), b) in buf.nx[..full]
        .chunks_exact(LANES)
        .zip(buf.nz[..full].chunks_exact(LANES))
        .zip(buf.eta[..full].chunks_exact(LANES))
        .zip(buf.a[..full].chunks_exact_mut(LANES))
        .zip(buf.b[..full].chunks_exact_mut(LANES))
    {
        rotated_block(
            lanes(nx),
            lanes(nz),
            lanes(e),
            c,
            s,
            lanes_mut(a),
            lanes_mut(b),
            &mut acc,
        );
    }
    if full < n {
        let (nx, nz, e) = (
            padded(&buf.nx[full..]),
            padded(&buf.nz[full..]),
            padded(&buf.eta[full..]),
        );
        let (mut a, mut b) = ([0.0; LANES], [0.0; LANES]);
        rotated_block(&nx, &nz, &e, c, s, &mut a, &mut b, &mut acc);
        buf.a[full..].copy_from_slice(&a[..n - full]);
        buf.b[full..].copy_from_slice(&b[..n - full]);
    }
    acc.map(|a| a.iter().sum())
}

/// A frame rotation about `y`.
#[derive(Clone, Copy, Debug)]
enum Rotation {
    /// `β* = q·90°`: `(ξ*', ζ*')` is a signed permutation of `(ξ', ζ')`, taken exactly
    /// from the principal frame (`cos`, `sin` are then exactly 0 or ±1, so this equals
    /// the general formula bit for bit).
    Quarter(u8),
    /// Any other `β*`: `(cos β*, sin β*)`.
    General(f64, f64),
}

impl Rotation {
    fn new(beta_star: f64) -> Self {
        let q = beta_star / std::f64::consts::FRAC_PI_2;
        if (q - q.round()).abs() < 1e-12 {
            Rotation::Quarter(q.round().rem_euclid(4.0) as u8)
        } else {
            Rotation::General(beta_star.cos(), beta_star.sin())
        }
    }
}

/// `(a, b)` of the quarter turn `q` from the principal-frame `(a0, b0)`:
/// `x* = cos β* i − sin β* k`, `z* = sin β* i + cos β* k` (docs/physics.md §1).
#[inline(always)]
fn quarter(q: u8, a0: f64, b0: f64) -> (f64, f64) {
    match q {
        0 => (a0, b0),
        1 => (-b0, a0),
        2 => (-a0, -b0),
        _ => (b0, -a0),
    }
}

/// The sums of [`Chunk::rot`] for quarter turn `q`, from those of the principal frame.
fn quarter_sums(q: u8, s: &[f64; 9]) -> [f64; 9] {
    match q {
        0 => *s,
        // (a, b) = (−b0, a0)
        1 => [-s[1], s[0], s[2], s[4], s[3], s[5], -s[6], -s[8], s[7]],
        // (a, b) = (−a0, −b0)
        2 => [-s[0], -s[1], s[2], s[3], s[4], s[5], s[6], -s[7], -s[8]],
        // (a, b) = (b0, −a0)
        _ => [s[1], -s[0], s[2], s[4], s[3], s[5], -s[6], s[8], -s[7]],
    }
}

/// One chunk of rows. Compiled once for the baseline CPU and once with AVX2 (chosen at
/// run time); no fused multiply-adds are used, so both give bit-identical results.
/// Histograms take every `hist_stride`-th row.
#[inline(always)]
fn chunk_kernel(
    f: &HeightField,
    rows: Range<usize>,
    rots: &[Rotation],
    hist_stride: usize,
    acc: &mut Chunk,
    buf: &mut RowBuf,
) {
    for iz in rows {
        let with_hist = !acc.hists.is_empty() && iz % hist_stride == 0;
        row_gradients(f, iz, &mut buf.gx, &mut buf.gz);
        let s2 = row_normals(buf);
        acc.n += buf.gx.len() as f64;
        acc.slope2[0] += s2[0];
        acc.slope2[1] += s2[1];
        // The principal frame first: its angles serve every quarter turn.
        let base = row_rotated(buf, 1.0, 0.0);
        for (k, rot) in rots.iter().enumerate() {
            let Rotation::Quarter(q) = *rot else { continue };
            let sums = quarter_sums(q, &base);
            for (a, v) in acc.rot[k].iter_mut().zip(sums) {
                *a += v;
            }
            // Histograms belong to the β* rotations (k ≥ 1).
            if with_hist && k >= 1 {
                let h = &mut acc.hists[k - 1];
                for (&a0, &b0) in buf.a.iter().zip(&buf.b) {
                    let (a, b) = quarter(q, a0, b0);
                    h.0.add(a);
                    h.1.add(b);
                }
            }
        }
        for (k, rot) in rots.iter().enumerate() {
            let Rotation::General(c, s) = *rot else {
                continue;
            };
            let sums = row_rotated(buf, c, s);
            for (a, v) in acc.rot[k].iter_mut().zip(sums) {
                *a += v;
            }
            if with_hist && k >= 1 {
                let h = &mut acc.hists[k - 1];
                buf.a.iter().for_each(|&x| h.0.add(x));
                buf.b.iter().for_each(|&x| h.1.add(x));
            }
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn chunk_kernel_avx2(
    f: &HeightField,
    rows: Range<usize>,
    rots: &[Rotation],
    hist_stride: usize,
    acc: &mut Chunk,
    buf: &mut RowBuf,
) {
    chunk_kernel(f, rows, rots, hist_stride, acc, buf)
}

fn run_chunk(
    f: &HeightField,
    rows: Range<usize>,
    rots: &[Rotation],
    hist_stride: usize,
    acc: &mut Chunk,
    buf: &mut RowBuf,
) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2 (checked just above).
        return unsafe { chunk_kernel_avx2(f, rows, rots, hist_stride, acc, buf) };
    }
    chunk_kernel(f, rows, rots, hist_stride, acc, buf)
}

/// `asin` of `LANES` values, bit-identical to [`asin_fast`] lane by lane. When no lane
/// exceeds 0.5 in magnitude (nearly always for walls of low roughness) the reduction
/// branch and its square root are skipped for the whole block.
#[inline(always)]
pub(crate) fn asin_lanes(x: &Lanes, out: &mut Lanes) {
    let mut big = false;
    for v in x {
        big |= v.abs() > 0.5;
    }
    if big {
        for l in 0..LANES {
            out[l] = asin_fast(x[l]);
        }
    } else {
        for l in 0..LANES {
            out[l] = asin_small(x[l]);
        }
    }
}

/// [`asin_fast`] for `|x| ≤ 0.5` only (the same operations, hence the same bits).
#[inline(always)]
fn asin_small(x: f64) -> f64 {
    let ax = x.abs();
    let z = ax * ax;
    let y = ax + ax * asin_ratio(z);
    y.copysign(x)
}

/// fdlibm's rational `R(z) = p(z)/q(z)` with `asin x = x + x R(x²)` on `|x| ≤ 0.5`.
#[inline(always)]
#[allow(clippy::excessive_precision)] // fdlibm's coefficients, digits as published
fn asin_ratio(z: f64) -> f64 {
    const PS0: f64 = 1.666_666_666_666_666_57e-1;
    const PS1: f64 = -3.255_658_186_224_009_15e-1;
    const PS2: f64 = 2.012_125_321_348_629_26e-1;
    const PS3: f64 = -4.005_553_450_067_941_14e-2;
    const PS4: f64 = 7.915_349_942_898_145_32e-4;
    const PS5: f64 = 3.479_331_075_960_211_68e-5;
    const QS1: f64 = -2.403_394_911_734_414_22;
    const QS2: f64 = 2.020_945_760_233_505_69;
    const QS3: f64 = -6.882_839_716_054_532_93e-1;
    const QS4: f64 = 7.703_815_055_590_193_53e-2;
    let p = z * (PS0 + z * (PS1 + z * (PS2 + z * (PS3 + z * (PS4 + z * PS5)))));
    let q = 1.0 + z * (QS1 + z * (QS2 + z * (QS3 + z * QS4)));
    p / q
}

/// `asin x` for `|x| ≤ 1` without branches (so that it vectorises): the rational
/// approximation of fdlibm's `__ieee754_asin` on `[0, 0.5]` and its reduction
/// `asin x = π/2 − 2 asin √((1 − x)/2)` above. Absolute error below 1e-15.
#[inline(always)]
pub fn asin_fast(x: f64) -> f64 {
    let ax = x.abs();
    let big = ax > 0.5;
    let z = if big { 0.5 - 0.5 * ax } else { ax * ax };
    let r = asin_ratio(z);
    let s = if big { z.sqrt() } else { ax };
    let y = s + s * r;
    let y = if big {
        std::f64::consts::FRAC_PI_2 - 2.0 * y
    } else {
        y
    };
    y.copysign(x)
}

/// Table 1 statistics of `f` for the frame rotations `beta_stars` (rad), with optional
/// histograms of `ξ* − 90°`, `ζ* − 90°` (Radenkovic & Simonin 2021, Sec. 2.2, Eqs. 7–8;
/// slopes as in Sec. 2.4, Eq. 14).
///
/// Angles follow Eq. (7) with the unit normal `n` of each triangle:
/// `ξ* = acos(n·x*)`, `η* = acos(n·j)`, `ζ* = acos(n·z*)`, where
/// `x* = cos β* i − sin β* k`, `z* = sin β* i + cos β* k` (docs/physics.md §1). They are
/// evaluated as `ξ* − 90° = −asin(n·x*)`, which keeps full precision near 90°.
pub fn surface_stats(
    f: &HeightField,
    beta_stars: &[f64],
    hist: Option<HistogramSpec>,
) -> SurfaceStats {
    // Rotation 0 is the principal frame (Δξ, Δζ); then one per β*.
    let trig: Vec<Rotation> = std::iter::once(Rotation::Quarter(0))
        .chain(beta_stars.iter().map(|&b| Rotation::new(b)))
        .collect();
    // Histograms are for figures: about 8 M triangles are plenty.
    let hist_stride = (2 * f.nx * f.nz / 8_000_000).max(1);
    let empty = Chunk {
        n: 0.0,
        slope2: [0.0; 2],
        rot: vec![[0.0; 9]; trig.len()],
        hists: match hist {
            Some(h) => {
                let bins = h.bins.max(1);
                let one = Histogram::new(h.half_range, bins);
                vec![(one.clone(), one); beta_stars.len()]
            }
            None => Vec::new(),
        },
    };
    let chunks: Vec<Chunk> = if f.nx == 0 {
        Vec::new()
    } else {
        (0..f.nz.div_ceil(ROWS_PER_CHUNK))
            .into_par_iter()
            .map_init(
                || RowBuf::new(2 * f.nx),
                |buf, c| {
                    let mut acc = empty.clone();
                    let rows = c * ROWS_PER_CHUNK..((c + 1) * ROWS_PER_CHUNK).min(f.nz);
                    run_chunk(f, rows, &trig, hist_stride, &mut acc, buf);
                    acc
                },
            )
            .collect()
    };

    let mut slope2 = [0.0; 2];
    let mut ntot = 0.0;
    let mut rot = vec![Moments3::default(); trig.len()];
    let mut hists = empty.hists;
    for c in &chunks {
        ntot += c.n;
        slope2[0] += c.slope2[0];
        slope2[1] += c.slope2[1];
        for (k, r) in rot.iter_mut().enumerate() {
            r.merge(&c.moments(k));
        }
        for (h, ch) in hists.iter_mut().zip(&c.hists) {
            h.0.merge(&ch.0);
            h.1.merge(&ch.1);
        }
    }

    let heights = height_moments(&f.heights);
    let rms = |s: f64| if ntot > 0.0 { (s / ntot).sqrt() } else { 0.0 };
    let mut hists = hists.into_iter();
    SurfaceStats {
        triangles: ntot as u64,
        rms_height_m: heights.0,
        max_height_m: heights.1,
        rms_slope_x: rms(slope2[0]),
        rms_slope_z: rms(slope2[1]),
        delta_xi: rot[0].std(0),
        delta_zeta: rot[0].std(1),
        rotated: beta_stars
            .iter()
            .zip(&rot[1..])
            .map(|(&beta_star, m)| {
                let (hist_xi, hist_zeta) = match hists.next() {
                    Some((a, b)) => (Some(a), Some(b)),
                    None => (None, None),
                };
                RotatedStats {
                    beta_star,
                    delta_xi_star: m.std(0),
                    delta_zeta_star: m.std(1),
                    rho_xi_zeta: m.rho(0, 1),
                    rho_xi_eta: m.rho(0, 2),
                    rho_eta_zeta: m.rho(2, 1),
                    hist_xi,
                    hist_zeta,
                }
            })
            .collect(),
    }
}

/// rms about the mean and maximum of the heights (merged in fixed chunks).
fn height_moments(h: &[f64]) -> (f64, f64) {
    if h.is_empty() {
        return (0.0, 0.0);
    }
    let parts: Vec<(f64, f64, f64, f64)> = h
        .par_chunks(1 << 16)
        .map(|c| {
            let n = c.len() as f64;
            let mean = c.iter().sum::<f64>() / n;
            let m2 = c.iter().map(|y| (y - mean) * (y - mean)).sum::<f64>();
            let max = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            (n, mean, m2, max)
        })
        .collect();
    let (mut n, mut mean, mut m2, mut max) = (0.0, 0.0, 0.0, f64::NEG_INFINITY);
    for &(nb, mb, m2b, maxb) in &parts {
        let tot = n + nb;
        let d = mb - mean;
        m2 += m2b + d * d * n * nb / tot;
        mean += d * nb / tot;
        n = tot;
        max = max.max(maxb);
    }
    ((m2 / n).sqrt(), max)
}

/// RMS of the triangle normals' angle fluctuations `(ξ − 90°, ζ − 90°)` (rad): the
/// deviations the surface really has (Radenkovic & Simonin 2021, Sec. 2.2). Rows in
/// parallel, summed in row order (the same bits for any thread count).
pub fn measured_deviations(f: &HeightField) -> crate::wall::Deviations {
    pooled_deviations(&[f])
}

/// [`measured_deviations`] of several realisations taken together: the RMS over all their
/// triangles (for one surface, the same bits as `measured_deviations`).
pub fn pooled_deviations(fields: &[&HeightField]) -> crate::wall::Deviations {
    let mut sums = AngleSums::default();
    for f in fields {
        sums.add(f);
    }
    sums.deviations()
}

/// The squared normal-angle fluctuations summed over the triangles of one or more surfaces,
/// for [`pooled_deviations`] of surfaces that need not be held together.
#[derive(Clone, Copy, Debug, Default)]
pub struct AngleSums {
    xi: f64,
    zeta: f64,
    triangles: f64,
}

impl AngleSums {
    /// Adds every triangle of `f`.
    pub fn add(&mut self, f: &HeightField) {
        let (x, z) = squared_angle_sums(f);
        self.xi += x;
        self.zeta += z;
        self.triangles += (2 * f.nx * f.nz) as f64;
    }

    /// The RMS deviations `(Δξ, Δζ)` over the triangles added.
    pub fn deviations(&self) -> crate::wall::Deviations {
        crate::wall::Deviations {
            delta_xi: (self.xi / self.triangles).sqrt(),
            delta_zeta: (self.zeta / self.triangles).sqrt(),
        }
    }
}

/// The sums of `(ξ − 90°)²` and `(ζ − 90°)²` over a surface's triangles.
fn squared_angle_sums(f: &HeightField) -> (f64, f64) {
    use rayon::prelude::*;
    let rows: Vec<(f64, f64)> = (0..f.nz)
        .into_par_iter()
        .map(|iz| {
            let (mut sx, mut sz) = (0.0, 0.0);
            for ix in 0..f.nx {
                for t in f.cell_normals(ix, iz) {
                    let norm = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
                    let xi = (t[0] / norm).clamp(-1.0, 1.0).asin();
                    let ze = (t[2] / norm).clamp(-1.0, 1.0).asin();
                    sx += xi * xi;
                    sz += ze * ze;
                }
            }
            (sx, sz)
        })
        .collect();
    rows.iter().fold((0.0, 0.0), |a, r| (a.0 + r.0, a.1 + r.1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(nx: usize, nz: usize, heights: Vec<f64>) -> HeightField {
        HeightField {
            nx,
            nz,
            dx: 1.0,
            dz: 1.0,
            heights,
            triangulation: Default::default(),
        }
    }

    /// Pooled deviations are the RMS over all triangles: for two surfaces of one grid, the
    /// root of the mean of their squared deviations; for one, its own bits.
    #[test]
    fn pooled_deviations_are_the_rms_over_all_realisations() {
        let wavy = |a: f64, b: f64| {
            let h = (0..64)
                .map(|k| {
                    let (i, j) = ((k % 8) as f64, (k / 8) as f64);
                    a * (0.8 * i).sin() + b * (1.3 * j).cos() + 0.1 * a * (i * j).sin()
                })
                .collect();
            field(8, 8, h)
        };
        let (f, g) = (wavy(0.05, 0.02), wavy(0.01, 0.09));
        let (df, dg) = (measured_deviations(&f), measured_deviations(&g));
        assert_eq!(pooled_deviations(&[&f]), df);
        let p = pooled_deviations(&[&f, &g]);
        let rms = |a: f64, b: f64| ((a * a + b * b) / 2.0).sqrt();
        assert!((p.delta_xi - rms(df.delta_xi, dg.delta_xi)).abs() < 1e-14);
        assert!((p.delta_zeta - rms(df.delta_zeta, dg.delta_zeta)).abs() < 1e-14);
        assert!(df.delta_zeta < p.delta_zeta && p.delta_zeta < dg.delta_zeta);
    }

    #[test]
    fn row_gradients_are_bit_identical_to_cell_normals() {
        let (nx, nz) = (7, 5);
        let mut rng = crate::rng::stream(3, &[99]);
        let heights: Vec<f64> = (0..nx * nz)
            .map(|_| rand::Rng::gen_range(&mut rng, -1.0..1.0))
            .collect();
        for triangulation in [Triangulation::Uniform, Triangulation::Alternating] {
            let f = HeightField {
                nx,
                nz,
                dx: 0.3,
                dz: 0.7,
                heights: heights.clone(),
                triangulation,
            };
            let (mut gx, mut gz) = (vec![0.0; 2 * nx], vec![0.0; 2 * nx]);
            for iz in 0..nz {
                row_gradients(&f, iz, &mut gx, &mut gz);
                for ix in 0..nx {
                    let [t0, t1] = f.cell_normals(ix, iz);
                    assert_eq!((gx[ix], gz[ix]), (t0[0], t0[2]));
                    assert_eq!((gx[nx + ix], gz[nx + ix]), (t1[0], t1[2]));
                }
            }
        }
    }

    #[test]
    fn fast_asin_matches_libm() {
        for i in -100_000..=100_000 {
            let x = i as f64 / 100_000.0;
            assert!((asin_fast(x) - x.asin()).abs() < 1e-15, "{x}");
        }
        assert_eq!(asin_fast(0.0), 0.0);
        // The block version is bit-identical whichever branch a block takes.
        let mut rng = crate::rng::stream(5, &[2]);
        for scale in [0.1, 0.5, 1.0] {
            let x: Lanes = std::array::from_fn(|_| rand::Rng::gen_range(&mut rng, -scale..scale));
            let mut y = [0.0; LANES];
            asin_lanes(&x, &mut y);
            for l in 0..LANES {
                assert_eq!(y[l], asin_fast(x[l]));
                assert_eq!(asin_fast(-x[l]), -asin_fast(x[l]));
            }
        }
        assert_eq!(asin_fast(1.0), std::f64::consts::FRAC_PI_2);
    }

    #[test]
    fn flat_wall_has_zero_statistics() {
        let f = field(8, 1, vec![0.0; 8]);
        let s = surface_stats(&f, &[0.0, 0.5], None);
        assert_eq!(s.triangles, 16);
        assert_eq!((s.rms_height_m, s.rms_slope_x, s.delta_xi), (0.0, 0.0, 0.0));
        for r in &s.rotated {
            assert_eq!((r.delta_xi_star, r.delta_zeta_star), (0.0, 0.0));
            assert_eq!(
                (r.rho_xi_zeta, r.rho_xi_eta, r.rho_eta_zeta),
                (0.0, 0.0, 0.0)
            );
        }
    }

    #[test]
    fn a_corrugation_rotated_by_beta_star_projects_like_a_vector() {
        // Heights ±a alternating along x, constant along z: every triangle has slope
        // ±2a along x and 0 along z. In the frame rotated by β*, n·x* = cos β* n_x and
        // n·z* = sin β* n_x, so Δξ* = asin(cos β* sin θ), Δζ* = asin(sin β* sin θ),
        // ρ = sign(cos β* sin β*) — Eq. (9) with Δζ = 0, here exactly.
        let (n, a) = (8, 0.05);
        let heights = (0..n).map(|i| if i % 2 == 0 { a } else { -a }).collect();
        let f = field(n, 1, heights);
        let b = 0.5f64;
        let s = surface_stats(&f, &[0.0, b, -b], None);
        let theta = (2.0 * a).atan();
        assert!((s.rms_slope_x - 2.0 * a).abs() < 1e-15);
        assert_eq!(s.rms_slope_z, 0.0);
        assert!((s.delta_xi - theta).abs() < 1e-15);
        assert!((s.rms_height_m - a).abs() < 1e-15);
        let r = &s.rotated[1];
        assert!((r.delta_xi_star - (b.cos() * theta.sin()).asin()).abs() < 1e-15);
        assert!((r.delta_zeta_star - (b.sin() * theta.sin()).asin()).abs() < 1e-15);
        assert!((r.rho_xi_zeta - 1.0).abs() < 1e-12);
        assert!((s.rotated[2].rho_xi_zeta + 1.0).abs() < 1e-12);
        assert_eq!(s.rotated[0].delta_zeta_star, 0.0);
        assert_eq!(s.rotated[0].rho_xi_zeta, 0.0);
    }

    #[test]
    fn inclined_plane_angles_are_exact() {
        // A plane y = gx·x + gz·z seen through one row of its triangles.
        let (gx, gz) = (0.1, -0.2);
        let mut buf = RowBuf::new(2);
        buf.gx.fill(-gx);
        buf.gz.fill(-gz);
        let s2 = row_normals(&mut buf);
        let sums = row_rotated(&mut buf, 1.0, 0.0);
        let nrm = (1.0 + gx * gx + gz * gz).sqrt();
        let xi = (-gx / nrm).acos() - std::f64::consts::FRAC_PI_2;
        let zeta = (-gz / nrm).acos() - std::f64::consts::FRAC_PI_2;
        let eta = (1.0 / nrm).acos();
        assert!((sums[0] / 2.0 - xi).abs() < 1e-15);
        assert!((sums[1] / 2.0 - zeta).abs() < 1e-15);
        assert!((sums[2] / 2.0 - eta).abs() < 1e-15);
        assert!((s2[0] / 2.0 - gx * gx).abs() < 1e-15);
        // β* = 90°: x* = −k, z* = i, so ξ* − 90° = −(ζ − 90°) and ζ* − 90° = ξ − 90°.
        let (c, s) = (0.0, 1.0);
        let sums = row_rotated(&mut buf, c, s);
        assert!((sums[0] / 2.0 + zeta).abs() < 1e-15);
        assert!((sums[1] / 2.0 - xi).abs() < 1e-15);
    }

    #[test]
    fn quarter_turns_equal_the_general_formula_bit_for_bit() {
        let mut rng = crate::rng::stream(4, &[1]);
        let mut buf = RowBuf::new(21);
        for i in 0..21 {
            buf.gx[i] = rand::Rng::gen_range(&mut rng, -0.3..0.3);
            buf.gz[i] = rand::Rng::gen_range(&mut rng, -0.3..0.3);
        }
        row_normals(&mut buf);
        let base = row_rotated(&mut buf, 1.0, 0.0);
        let (a0, b0) = (buf.a.clone(), buf.b.clone());
        for (q, (c, s)) in [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]
            .into_iter()
            .enumerate()
        {
            let direct = row_rotated(&mut buf, c, s);
            assert_eq!(direct, quarter_sums(q as u8, &base), "q {q}");
            for i in 0..21 {
                assert_eq!((buf.a[i], buf.b[i]), quarter(q as u8, a0[i], b0[i]));
            }
            let beta = q as f64 * std::f64::consts::FRAC_PI_2;
            assert!(matches!(Rotation::new(beta), Rotation::Quarter(k) if k as usize == q));
            assert!(
                matches!(Rotation::new(-beta - 2.0 * std::f64::consts::PI), Rotation::Quarter(k) if k as usize == (4 - q) % 4)
            );
        }
    }

    #[test]
    fn histograms_are_normalised_densities() {
        let mut h = Histogram::new(1.0, 4);
        for x in [-0.9, -0.1, 0.1, 0.2, 2.0] {
            h.add(x);
        }
        assert_eq!(h.counts, vec![1, 1, 2, 0]);
        assert_eq!(h.outside, 1);
        let integral: f64 = h.density().iter().map(|p| p.1 * h.bin_width()).sum();
        assert!((integral - 0.8).abs() < 1e-15);
    }
}
