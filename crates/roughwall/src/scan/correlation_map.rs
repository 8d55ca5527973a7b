//! The areal autocorrelation of a (levelled) scan over a window of lags along the scan's `x`
//! and `y`: the 2-D map whose `1/e` contour is the correlation ellipse of a Gaussian wall
//! (`R(τ) = h² exp(−τ_x²/c_Lx² − τ_z²/c_Lz²)`, Radenkovic & Simonin 2021, Eqs. 1–2;
//! docs/physics.md §4), its long axis along the lay.
//!
//! `R(τ) = Σ h(p) h(p + τ) / Σ m(p) m(p + τ)` over the points `p` where both heights are
//! valid (`m` = 1 at a valid point, 0 at a missing one, whose height counts as 0). Both sums
//! are circular autocorrelations of the zero-padded grids, taken as the inverse FFT of the
//! power spectrum (Wiener–Khinchin); dividing by the count of valid pairs at each lag, itself
//! the autocorrelation of the mask, is the masked normalisation of Padfield, "Masked FFT
//! registration" (IEEE CVPR 2010). Padding each axis by the largest lag wanted keeps the
//! circular sums free of wrap-around, so every value is the exact lagged mean product.
//!
//! A scan of more than [`MAX_MAP_POINTS`] points is read every `s`-th point along both axes
//! (no averaging: the lags stay exact, only fewer pairs enter), so the memory, one half
//! spectrum of the padded grid, is about 8 bytes per point read, at most about 32 MB
//! ([`map_bytes`]): a quarter of the heights of a 4096² scan. Each row and column is transformed on its own with
//! one plan: the map is the same bits for any thread count.

use super::ScanField;
use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::RealFftPlanner;

/// Most points of the grid the map is computed on.
pub const MAX_MAP_POINTS: usize = 1 << 21;

/// Most lags on each side of the origin along each axis (a figure of at most 513 × 513).
pub const MAX_HALF_LAGS: usize = 256;

/// Columns of the half spectrum transformed per parallel batch.
const COLUMN_BATCH: usize = 64;

/// The autocorrelation `R(τ)/R(0)` on a window of lags along the scan's `x` and `y`.
#[derive(Clone, Debug, PartialEq)]
pub struct CorrelationMap {
    /// Every `stride`-th point of the scan along each axis was read.
    pub stride: usize,
    /// The lag steps along `x` and `y` (m): `stride · dx`, `stride · dy`.
    pub step_m: [f64; 2],
    /// Lags on each side of the origin along `x` and `y`: the map is `2 half[0] + 1` lags
    /// wide and `2 half[1] + 1` high.
    pub half: [usize; 2],
    /// `R(τ)/R(0)`, row-major from lag `−half[1]` along `y`, `x` fastest from `−half[0]`;
    /// NaN where no pair of valid points is that far apart.
    pub values: Vec<f64>,
}

impl CorrelationMap {
    /// The value at lag `(kx, ky)` steps; NaN outside the window or without a pair.
    pub fn at(&self, kx: isize, ky: isize) -> f64 {
        let [hx, hy] = self.half.map(|h| h as isize);
        if kx.abs() > hx || ky.abs() > hy {
            return f64::NAN;
        }
        self.values[((ky + hy) * (2 * hx + 1) + kx + hx) as usize]
    }

    /// `R/R(0)` at the lag `(τx, τy)` (m), bilinear between the four lags around it; `None`
    /// outside the window or next to a lag without a pair.
    pub fn value_at(&self, tau_x_m: f64, tau_y_m: f64) -> Option<f64> {
        let (u, v) = (tau_x_m / self.step_m[0], tau_y_m / self.step_m[1]);
        let [hx, hy] = self.half.map(|h| h as f64);
        // Up to round-off beyond the last lag (a position computed to land on it).
        let inside = |w: f64, h: f64| w.abs() <= h * (1.0 + 1e-12);
        if !(inside(u, hx) && inside(v, hy)) {
            return None;
        }
        let (u, v) = (u.clamp(-hx, hx), v.clamp(-hy, hy));
        if self.half[0] == 0 || self.half[1] == 0 {
            // A window one lag wide along an axis: nothing to interpolate across it.
            let r = self.at(u.round() as isize, v.round() as isize);
            return (!r.is_nan()).then_some(r);
        }
        // The lower corner, kept one step inside the window so that its neighbours exist.
        let corner = |w: f64, h: f64| (w.floor() as isize).clamp(-(h as isize), h as isize - 1);
        let (i, j) = (corner(u, hx), corner(v, hy));
        let (fu, fv) = (u - i as f64, v - j as f64);
        let r = [
            self.at(i, j),
            self.at(i + 1, j),
            self.at(i, j + 1),
            self.at(i + 1, j + 1),
        ];
        if r.iter().any(|x| x.is_nan()) {
            return None;
        }
        Some((1.0 - fv) * ((1.0 - fu) * r[0] + fu * r[1]) + fv * ((1.0 - fu) * r[2] + fu * r[3]))
    }

    /// `R/R(0)` at lag `tau_m` (m) along the direction `angle` (rad, from the scan's `x`
    /// towards its `y`).
    pub fn along(&self, angle: f64, tau_m: f64) -> Option<f64> {
        self.value_at(tau_m * angle.cos(), tau_m * angle.sin())
    }

    /// Where the map first falls to `1/e` along the direction `angle` (rad): the radius of the
    /// `1/e` contour there, the correlation length along it (m), linear between samples a
    /// quarter of the finer lag step apart; `None` when it does not within the window.
    pub fn length_along(&self, angle: f64) -> Option<f64> {
        let level = (-1.0f64).exp();
        let dt = 0.25 * self.step_m[0].min(self.step_m[1]);
        let (mut t0, mut r0) = (0.0, self.along(angle, 0.0)?);
        for k in 1.. {
            let t = k as f64 * dt;
            let r = self.along(angle, t)?;
            if r0 > level && r <= level {
                return Some(t0 + (r0 - level) / (r0 - r) * (t - t0));
            }
            (t0, r0) = (t, r);
        }
        None
    }
}

/// The stride at which a scan of `points` points is read: the smallest that leaves at most
/// `max_points` of them.
fn stride_for(points: usize, max_points: usize) -> usize {
    let mut s = ((points as f64 / max_points as f64).sqrt().ceil() as usize).max(1);
    while points.div_ceil(s * s) > max_points {
        s += 1;
    }
    s
}

/// The smallest length `≥ n` whose only prime factors are 2, 3 and 5 (a fast FFT length).
fn fast_length(n: usize) -> usize {
    (n.max(1)..)
        .find(|&m| {
            let mut m = m;
            for p in [2, 3, 5] {
                while m % p == 0 {
                    m /= p;
                }
            }
            m == 1
        })
        .unwrap_or(n)
}

/// Bytes [`correlation_map`] allocates for a scan of `nx × ny` points (the half spectrum of
/// the padded grid and the window), whatever the window asked for.
pub fn map_bytes(nx: usize, ny: usize) -> u64 {
    let s = stride_for(nx * ny, MAX_MAP_POINTS);
    let (mx, my) = (nx.div_ceil(s), ny.div_ceil(s));
    let (px, py) = (
        fast_length(mx + MAX_HALF_LAGS.min(mx)),
        fast_length(my + MAX_HALF_LAGS.min(my)),
    );
    let spectrum = 16 * (px / 2 + 1) * py;
    // The window holds the lags −hy … hy, hy at most MAX_HALF_LAGS and my − 1 (a strip two
    // rows high has 3 rows of lags, not 513).
    let window = 16 * (px / 2 + 1) * (2 * MAX_HALF_LAGS.min(my - 1) + 1);
    (spectrum + window) as u64
}

/// The autocorrelation `R(τ)/R(0)` of the levelled scan `f` (mean 0) for the lags within
/// `half_width_m` (m) of the origin along the scan's `x` and `y` (at most `MAX_HALF_LAGS`
/// steps and the scan's own extent).
pub fn correlation_map(f: &ScanField, half_width_m: [f64; 2]) -> CorrelationMap {
    correlation_map_within(f, half_width_m, MAX_MAP_POINTS)
}

/// [`correlation_map`] reading at most `max_points` points.
fn correlation_map_within(
    f: &ScanField,
    half_width_m: [f64; 2],
    max_points: usize,
) -> CorrelationMap {
    let s = stride_for(f.nx * f.ny, max_points);
    let (mx, my) = (f.nx.div_ceil(s), f.ny.div_ceil(s));
    let step_m = [s as f64 * f.dx, s as f64 * f.dy];
    let half_lags = |w: f64, step: f64, m: usize| {
        let k = if w.is_finite() && w > 0.0 {
            (w / step).floor().min(MAX_HALF_LAGS as f64) as usize
        } else {
            0
        };
        k.min(m - 1)
    };
    let (hx, hy) = (
        half_lags(half_width_m[0], step_m[0], mx),
        half_lags(half_width_m[1], step_m[1], my),
    );
    let read = |ix: usize, iy: usize| f.heights[iy * s * f.nx + ix * s];
    let heights = lagged_sums(mx, my, [hx, hy], |ix, iy| {
        let h = read(ix, iy);
        if h.is_nan() {
            0.0
        } else {
            h
        }
    });
    let pairs = lagged_sums(mx, my, [hx, hy], |ix, iy| {
        if read(ix, iy).is_nan() {
            0.0
        } else {
            1.0
        }
    });
    // The pair counts are integers up to the FFT's round-off.
    let mean = |k: usize| (pairs[k] >= 0.5).then(|| heights[k] / pairs[k]);
    let origin = hy * (2 * hx + 1) + hx;
    let r0 = mean(origin).filter(|&r| r > 0.0);
    let values = (0..heights.len())
        .map(|k| match (mean(k), r0) {
            (Some(r), Some(r0)) => r / r0,
            _ => f64::NAN,
        })
        .collect();
    CorrelationMap {
        stride: s,
        step_m,
        half: [hx, hy],
        values,
    }
}

/// `Σ g(p) g(p + τ)` over the `mx × my` grid `g` (read through `value`), for every lag `τ`
/// of the window `±half` (steps), row-major from `−half[1]`: the inverse FFT of `|G|²` of
/// the grid zero-padded by the window (Wiener–Khinchin), so no sum wraps around.
fn lagged_sums(
    mx: usize,
    my: usize,
    half: [usize; 2],
    value: impl Fn(usize, usize) -> f64 + Sync,
) -> Vec<f64> {
    let [hx, hy] = half;
    let (px, py) = (fast_length(mx + hx), fast_length(my + hy));
    let cols = px / 2 + 1;
    let mut real_planner = RealFftPlanner::<f64>::new();
    let r2c = real_planner.plan_fft_forward(px);
    let c2r = real_planner.plan_fft_inverse(px);
    let mut planner = rustfft::FftPlanner::<f64>::new();
    let (forward, inverse) = (planner.plan_fft_forward(py), planner.plan_fft_inverse(py));
    // Along x: the half spectrum of each row of the grid (rows beyond `my` are padding).
    let mut spectrum = vec![Complex::new(0.0, 0.0); cols * py];
    spectrum
        .par_chunks_mut(cols)
        .take(my)
        .enumerate()
        .for_each_init(
            || (vec![0.0; px], r2c.make_scratch_vec()),
            |(row, scratch), (iy, out)| {
                row.fill(0.0);
                for (ix, r) in row[..mx].iter_mut().enumerate() {
                    *r = value(ix, iy);
                }
                // Lengths match the plan: no error is possible.
                let _ = r2c.process_with_scratch(row, out, scratch);
            },
        );
    // Along y: each column forward, |·|², back, keeping only the window's rows (lags
    // −hy … hy, stored circularly). Batches of columns are read in parallel and written in
    // order.
    let rows = 2 * hy + 1;
    let mut window = vec![Complex::new(0.0, 0.0); rows * cols];
    let scratch_len = forward
        .get_inplace_scratch_len()
        .max(inverse.get_inplace_scratch_len());
    for first in (0..cols).step_by(COLUMN_BATCH) {
        let batch: Vec<Vec<Complex<f64>>> = (first..(first + COLUMN_BATCH).min(cols))
            .into_par_iter()
            .map_init(
                || {
                    (
                        vec![Complex::new(0.0, 0.0); py],
                        vec![Complex::new(0.0, 0.0); scratch_len],
                    )
                },
                |(col, scratch), k| {
                    for (iy, c) in col.iter_mut().enumerate() {
                        *c = spectrum[iy * cols + k];
                    }
                    forward.process_with_scratch(col, scratch);
                    for c in col.iter_mut() {
                        *c = Complex::new(c.norm_sqr(), 0.0);
                    }
                    inverse.process_with_scratch(col, scratch);
                    (0..rows)
                        .map(|r| col[(r + py - hy) % py])
                        .collect::<Vec<_>>()
                },
            )
            .collect();
        for (j, col) in batch.iter().enumerate() {
            for (r, c) in col.iter().enumerate() {
                window[r * cols + first + j] = *c;
            }
        }
    }
    drop(spectrum);
    // Along x, back: each window row to the lags −hx … hx; both transforms are unnormalised.
    let scale = 1.0 / (px * py) as f64;
    let width = 2 * hx + 1;
    let mut out = vec![0.0; rows * width];
    out.par_chunks_mut(width)
        .zip(window.par_chunks_mut(cols))
        .for_each_init(
            || (vec![0.0; px], c2r.make_scratch_vec()),
            |(line, scratch), (o, w)| {
                // An autocorrelation is real: the first (and, for an even length, the last)
                // coefficient's imaginary part is round-off.
                w[0].im = 0.0;
                if px % 2 == 0 {
                    w[cols - 1].im = 0.0;
                }
                let _ = c2r.process_with_scratch(w, line, scratch);
                for (c, x) in o.iter_mut().enumerate() {
                    *x = line[(c + px - hx) % px] * scale;
                }
            },
        );
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scan::correlation::correlation;
    use crate::scan::lay::lay_angle;
    use crate::scan::tests::sec3_wall;

    /// The lagged mean products, pair by pair.
    fn brute_force(f: &ScanField, s: usize, hx: usize, hy: usize) -> Vec<f64> {
        let (mx, my) = (f.nx.div_ceil(s), f.ny.div_ceil(s));
        let g = |ix: usize, iy: usize| f.at(ix * s, iy * s);
        let mut sums = Vec::new();
        for ky in -(hy as isize)..=hy as isize {
            for kx in -(hx as isize)..=hx as isize {
                let (mut sum, mut n) = (0.0, 0usize);
                for iy in 0..my as isize {
                    for ix in 0..mx as isize {
                        let (jx, jy) = (ix + kx, iy + ky);
                        if jx < 0 || jy < 0 || jx >= mx as isize || jy >= my as isize {
                            continue;
                        }
                        let a = g(ix as usize, iy as usize);
                        let b = g(jx as usize, jy as usize);
                        if let (Some(a), Some(b)) = (a, b) {
                            sum += a * b;
                            n += 1;
                        }
                    }
                }
                sums.push((n > 0).then(|| sum / n as f64));
            }
        }
        let r0 = sums[sums.len() / 2].unwrap();
        sums.iter()
            .map(|r| r.map_or(f64::NAN, |r| r / r0))
            .collect()
    }

    /// A small scan with missing points, read whole and every 3rd point: the map is the
    /// pair-by-pair mean product at every lag of the window (a lag with no pair is NaN).
    #[test]
    fn the_map_is_the_masked_lagged_mean_product() {
        let (nx, ny) = (37, 23);
        let mut h: Vec<f64> = (0..nx * ny)
            .map(|i| ((i * 7919) % 101) as f64 / 50.0 - 1.0 + (i % nx) as f64 * 0.01)
            .collect();
        for k in [0, 5, 40, 41, 300, 301, 302, 500] {
            h[k] = f64::NAN;
        }
        let f = ScanField::new(nx, ny, 1e-6, 2e-6, h).unwrap();
        for (max_points, s) in [(MAX_MAP_POINTS, 1), ((nx * ny).div_ceil(9), 3)] {
            let m = correlation_map_within(&f, [9e-6 * s as f64, 8e-6 * s as f64], max_points);
            assert_eq!((m.stride, m.half), (s, [9, 4]));
            assert_eq!(m.step_m, [s as f64 * 1e-6, s as f64 * 2e-6]);
            let want = brute_force(&f, s, 9, 4);
            for (k, (a, b)) in m.values.iter().zip(&want).enumerate() {
                assert!(
                    (a - b).abs() < 1e-12 || (a.is_nan() && b.is_nan()),
                    "stride {s}, lag {k}: {a} vs {b}"
                );
            }
            assert_eq!(m.at(0, 0), 1.0);
            // R(τ) = R(−τ).
            assert!((m.at(3, -2) - m.at(-3, 2)).abs() < 1e-12);
        }
        // A window wider than the scan stops at its extent.
        let m = correlation_map(&f, [1.0, 1.0]);
        assert_eq!(m.half, [MAX_HALF_LAGS.min(nx - 1), ny - 1]);
        assert!(m.at(nx as isize - 1, 0).is_finite());
    }

    #[test]
    fn strides_leave_at_most_the_points_allowed_and_lengths_are_fast() {
        assert_eq!(stride_for(4096 * 4096, MAX_MAP_POINTS), 3);
        assert_eq!(stride_for(1 << 21, MAX_MAP_POINTS), 1);
        assert_eq!(stride_for((1 << 21) + 1, MAX_MAP_POINTS), 2);
        for points in [1usize, 7, 1 << 22, 12345678, 1 << 28] {
            let s = stride_for(points, MAX_MAP_POINTS);
            assert!(points.div_ceil(s * s) <= MAX_MAP_POINTS, "{points}");
        }
        assert_eq!(
            [1, 7, 11, 13, 97, 1025].map(fast_length),
            [1, 8, 12, 15, 100, 1080]
        );
        // The 4096² scan of docs/performance.md: a few tens of MB against its 128 MiB.
        assert!(
            map_bytes(4096, 4096) < 40 << 20,
            "{}",
            map_bytes(4096, 4096)
        );
    }

    /// On a generated Sec. 3 wall (c_Lx = 32.4 µm, c_Lz = 10.8 µm, 42 × 128 c_L), the
    /// map's 1/e contour along and across the lay gives back the generator's correlation
    /// lengths to the wall's own scatter (over seeds 1–8: up to 4.9 % along, 3.3 % across),
    /// and along and across the lay the map is the 1-D autocorrelation of `correlation` up to
    /// the interpolation (of the heights there, of the map here): 6·10⁻⁴ at most over those
    /// seeds, and the same lengths to 0.1 %.
    #[test]
    fn the_contour_gives_the_generators_lengths_and_the_curves_of_correlation() {
        let g = sec3_wall(1024, 4);
        let f = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights).unwrap();
        let c = |deg: f64| 2f64.sqrt() * 1e-6 / deg.to_radians();
        let angle = lay_angle(&f).unwrap();
        let across_lay = angle + std::f64::consts::FRAC_PI_2;
        let m = correlation_map(&f, [3.0 * c(2.5); 2]);
        assert_eq!((m.stride, m.half), (1, [72, 72]));
        let along = m.length_along(angle).unwrap();
        let across = m.length_along(across_lay).unwrap();
        assert!((along / c(2.5) - 1.0).abs() < 0.05, "{along} vs {}", c(2.5));
        assert!(
            (across / c(7.5) - 1.0).abs() < 0.04,
            "{across} vs {}",
            c(7.5)
        );
        let r = correlation(&f, angle);
        let mut worst: f64 = 0.0;
        for (t, (a, b)) in r.lags_m.iter().zip(r.along.iter().zip(&r.across)) {
            worst = worst.max((m.along(angle, *t).unwrap() - a).abs());
            worst = worst.max((m.along(across_lay, *t).unwrap() - b).abs());
        }
        assert!(worst < 1e-3, "{worst}");
        assert!((r.length_along_m.unwrap() / along - 1.0).abs() < 2e-3);
        assert!((r.length_across_m.unwrap() / across - 1.0).abs() < 2e-3);
    }
}
