//! The surface a sphere's centre rides on over a measured scan: the paraboloid dilation of
//! [`crate::surface::dilation`] (`c(x, y) = max over (x′, y′) of [h(x′, y′) − r²/2R]`, the
//! lower envelope of parabolas of Felzenszwalb & Huttenlocher, Theory of Computing 8 (2012)
//! 415–428, Sec. 3), on a grid that is neither periodic nor complete.
//!
//! Only valid points can win. A node whose winner might lie off the scan or on a missing
//! point is not known: only nodes within `√(2RΔh)` (`Δh` the height range) can win, so the
//! centre surface is exact at a node when every node within that reach is on the scan and
//! valid, and NaN (missing) elsewhere. The edges therefore lose a band of that width, and a
//! missing point a square of it: the deviations a sphere sees are measured on what is left
//! ([`CentreSurface::exact_fraction`] says how much).

use super::ScanField;
use rayon::prelude::*;

/// A sphere's centre surface over a scan.
#[derive(Clone, Debug, PartialEq)]
pub struct CentreSurface {
    /// Sphere diameter (m).
    pub diameter_m: f64,
    /// The centre surface on the scan's grid (heights in m; the centre is `R` above it),
    /// NaN where it is not exact.
    pub field: ScanField,
    /// Fraction of the scan's points where it is exact.
    pub exact_fraction: f64,
    /// The reach `⌈√(2RΔh)/δ⌉ + 1` along `x` and `y` (points).
    pub reach: [usize; 2],
}

/// Bytes the centre surface of one sphere needs beside the levelled `nx × ny` scan: per
/// point, the two passes of the dilation and the exact field (f64) and the masks of the
/// edges (bytes). Callers check it against [`crate::memory::require`] before dilating.
pub fn centre_surface_bytes(nx: usize, ny: usize) -> u64 {
    (2 * 8 + 2) * (nx as u64).saturating_mul(ny as u64)
}

/// `out[p] = max over valid q of (f[q] − a (p − q)²)` along an open line (NaN: missing; all
/// missing: NaN everywhere). Felzenszwalb & Huttenlocher's lower envelope on `−f/a`.
fn max_plus_open(f: &[f64], a: f64, out: &mut [f64], v: &mut Vec<usize>, z: &mut Vec<f64>) {
    v.clear();
    z.clear();
    let key = |q: usize| -f[q] / a + (q * q) as f64;
    for q in (0..f.len()).filter(|&q| !f[q].is_nan()) {
        if v.is_empty() {
            v.push(q);
            z.push(f64::NEG_INFINITY);
            z.push(f64::INFINITY);
            continue;
        }
        loop {
            let k = v.len() - 1;
            let p = v[k];
            let s = (key(q) - key(p)) / (2.0 * (q as f64 - p as f64));
            if s <= z[k] && k > 0 {
                v.pop();
                z.pop();
                continue;
            }
            if s <= z[k] {
                v[0] = q;
                break;
            }
            v.push(q);
            z[k + 1] = s;
            z.push(f64::INFINITY);
            break;
        }
    }
    if v.is_empty() {
        out.fill(f64::NAN);
        return;
    }
    let mut k = 0;
    for (p, o) in out.iter_mut().enumerate() {
        while z[k + 1] < p as f64 {
            k += 1;
        }
        let q = v[k];
        let d = p as f64 - q as f64;
        *o = f[q] - a * d * d;
    }
}

/// Whether each node of each line has a missing point, or the line's end, within `reach`.
fn near_gap(bad: &[bool], n: usize, reach: usize) -> Vec<bool> {
    let mut prefix = vec![0u32; n + 1];
    for (i, &b) in bad.iter().enumerate() {
        prefix[i + 1] = prefix[i] + b as u32;
    }
    (0..n)
        .map(|p| {
            if p < reach || p + reach >= n {
                return true;
            }
            prefix[p + reach + 1] - prefix[p - reach] > 0
        })
        .collect()
}

/// `max over q of (h[q] − ax (Δi)² − ay (Δj)²)` on an open `nx × ny` grid (NaN: missing),
/// separably: along `x` row by row, then along `y`; returned column by column (`[ix][iy]`).
/// The dilation of [`centre_surface`] and, on `−c`, the opening of [`contact_fraction`].
fn max_plus_2d(h: &[f64], nx: usize, ny: usize, ax: f64, ay: f64) -> Vec<Vec<f64>> {
    let mut rows = vec![0.0; nx * ny];
    rows.par_chunks_mut(nx).zip(h.par_chunks(nx)).for_each_init(
        || (Vec::new(), Vec::new()),
        |(v, z), (out, row)| max_plus_open(row, ax, out, v, z),
    );
    (0..nx)
        .into_par_iter()
        .map_init(
            || (Vec::new(), Vec::new()),
            |(v, z), ix| {
                let col: Vec<f64> = (0..ny).map(|iy| rows[iy * nx + ix]).collect();
                let mut out = vec![0.0; ny];
                max_plus_open(&col, ay, &mut out, v, z);
                out
            },
        )
        .collect()
}

/// The centre surface of a sphere of diameter `diameter_m` over the (levelled) scan `f`
/// (paraboloid cap: valid for `R ≫` the heights, as on generated walls,
/// docs/models.md "Sphere contact"). `diameter_m = 0` is the scan itself.
pub fn centre_surface(f: &ScanField, diameter_m: f64) -> CentreSurface {
    let (nx, ny) = (f.nx, f.ny);
    let radius = 0.5 * diameter_m;
    if radius <= 0.0 {
        return CentreSurface {
            diameter_m,
            field: f.clone(),
            exact_fraction: f.valid_count() as f64 / (nx * ny) as f64,
            reach: [0, 0],
        };
    }
    let (lo, hi) = f
        .heights
        .iter()
        .filter(|h| !h.is_nan())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
            (a.min(h), b.max(h))
        });
    let span = (2.0 * radius * (hi - lo).max(0.0)).sqrt();
    let reach = |d: f64| ((span / d).ceil() as usize).saturating_add(1);
    let (rx, ry) = (reach(f.dx), reach(f.dy));
    let cols = max_plus_2d(
        &f.heights,
        nx,
        ny,
        f.dx * f.dx / (2.0 * radius),
        f.dy * f.dy / (2.0 * radius),
    );
    // Exact where no gap lies within reach: along x, then along y of that.
    let bad_x: Vec<bool> = f
        .heights
        .par_chunks(nx)
        .flat_map_iter(|row| {
            let bad: Vec<bool> = row.iter().map(|h| h.is_nan()).collect();
            near_gap(&bad, nx, rx)
        })
        .collect();
    let bad_cols: Vec<Vec<bool>> = (0..nx)
        .into_par_iter()
        .map(|ix| {
            let col: Vec<bool> = (0..ny).map(|iy| bad_x[iy * nx + ix]).collect();
            near_gap(&col, ny, ry)
        })
        .collect();
    let mut heights = vec![f64::NAN; nx * ny];
    let mut exact = 0usize;
    for iy in 0..ny {
        for ix in 0..nx {
            if !bad_cols[ix][iy] {
                heights[iy * nx + ix] = cols[ix][iy];
                exact += 1;
            }
        }
    }
    CentreSurface {
        diameter_m,
        // Built field by field: `..f.clone()` would copy the scan's heights only to drop them.
        field: ScanField {
            nx,
            ny,
            dx: f.dx,
            dy: f.dy,
            heights,
        },
        exact_fraction: exact as f64 / (nx * ny) as f64,
        reach: [rx, ry],
    }
}

/// The share of the points where the centre surface `c` of a sphere over the scan `f` is
/// exact that a resting sphere touches: the points the opening `min over p of [c(p) +
/// |p − q|²/2R]` brings back to the scan's height (it lies above the scan elsewhere;
/// Felzenszwalb & Huttenlocher's envelope on `−c`, as for the dilation). 1 for a point.
/// The same quantity as [`crate::surface::dilation::Dilated::contact_fraction`], counted on
/// the exact region only.
pub fn contact_fraction(f: &ScanField, c: &CentreSurface) -> f64 {
    let (nx, ny) = (f.nx, f.ny);
    let radius = 0.5 * c.diameter_m;
    if radius <= 0.0 {
        return 1.0;
    }
    let neg: Vec<f64> = c.field.heights.iter().map(|h| -h).collect();
    let cols = max_plus_2d(
        &neg,
        nx,
        ny,
        f.dx * f.dx / (2.0 * radius),
        f.dy * f.dy / (2.0 * radius),
    );
    drop(neg);
    let (lo, hi) = f
        .heights
        .iter()
        .filter(|h| h.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
            (a.min(h), b.max(h))
        });
    // Rounding of the parabolas' terms, far below any height step a scan resolves.
    let tol = 1e-9 * (hi - lo).max(f64::MIN_POSITIVE);
    let (touched, exact) = cols
        .par_iter()
        .enumerate()
        .map(|(ix, out)| {
            let mut counts = (0u64, 0u64);
            for (iy, o) in out.iter().enumerate() {
                let p = iy * nx + ix;
                if c.field.heights[p].is_finite() {
                    counts.1 += 1;
                    // The opening is −out: at least the scan's height, equal where touched.
                    if -o - f.heights[p] <= tol {
                        counts.0 += 1;
                    }
                }
            }
            counts
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    if exact == 0 {
        return 0.0;
    }
    touched as f64 / exact as f64
}

/// The deviations a sphere of one diameter sees on a scan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeenDeviations {
    /// Sphere diameter (m); 0 for a point (the scan itself).
    pub diameter_m: f64,
    /// Deviations of the centre surface along and across the scan's lay (its `angle` is the
    /// lay given); `None` when no triangle of the centre surface is exact (the sphere is too
    /// wide for the scan).
    pub lay: Option<super::lay::Lay>,
    /// Fraction of the scan's points where the centre surface is exact.
    pub exact_fraction: f64,
    /// The reach `⌈√(2RΔh)/δ⌉ + 1` along `x` and `y` (points): the band the edges lose.
    pub reach: [usize; 2],
}

/// For each diameter (m), the deviations along and across `lay_angle` (rad; the scan's own
/// lay, [`super::lay::lay_angle`]) of the sphere's centre surface over `f`.
pub fn seen_deviations(f: &ScanField, lay_angle: f64, diameters_m: &[f64]) -> Vec<SeenDeviations> {
    diameters_m
        .iter()
        .map(|&d| {
            let c = centre_surface(f, d);
            SeenDeviations {
                diameter_m: d,
                lay: super::lay::lay_at(&c.field, lay_angle),
                exact_fraction: c.exact_fraction,
                reach: c.reach,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::dilation::dilate_paraboloid;

    /// Inside the band the edges lose, the open dilation of a generated wall equals the
    /// periodic one of `surface::dilation` bit for bit; a missing point blanks its
    /// neighbourhood and nothing else.
    #[test]
    fn equals_the_periodic_dilation_away_from_edges_and_gaps() {
        let g = crate::scan::tests::sec3_wall(256, 5);
        let scan = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights.clone()).unwrap();
        let d = 50e-6;
        let open = centre_surface(&scan, d);
        let periodic = dilate_paraboloid(&g, 0.5 * d);
        let [rx, ry] = open.reach;
        assert!(rx > 1 && rx < 60 && ry > 1, "{rx} {ry}");
        let mut compared = 0;
        for iy in 0..g.nz {
            for ix in 0..g.nx {
                let inside = ix >= rx && ix + rx < g.nx && iy >= ry && iy + ry < g.nz;
                let h = open.field.heights[iy * g.nx + ix];
                assert_eq!(!h.is_nan(), inside, "({ix}, {iy})");
                if inside {
                    assert_eq!(h, periodic.field.heights[iy * g.nx + ix], "({ix}, {iy})");
                    compared += 1;
                }
            }
        }
        assert!(compared > 1000);
        // A hole in the middle: a (2rx+1) × (2ry+1) square more is lost.
        let mut holed = scan.clone();
        holed.heights[128 * g.nx + 128] = f64::NAN;
        let h = centre_surface(&holed, d);
        let lost = open.exact_fraction - h.exact_fraction;
        let square = ((2 * rx + 1) * (2 * ry + 1)) as f64 / (g.nx * g.nz) as f64;
        assert!((lost - square).abs() < 1e-12, "{lost} vs {square}");
        // Diameter 0: the scan itself.
        assert_eq!(centre_surface(&scan, 0.0).field, scan);
    }

    /// What a sphere sees on a scan is what it sees on the periodic wall, less the edges: the
    /// deviations agree with `effective_roughness` within a few per cent, fall with the
    /// diameter, and a sphere wider than the scan sees nothing exact.
    #[test]
    fn seen_deviations_follow_the_periodic_ones() {
        let g = crate::scan::tests::sec3_wall(512, 9);
        let scan = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights.clone()).unwrap();
        let angle = super::super::lay::lay_angle(&scan).unwrap();
        let ds = [0.0, 50e-6, 200e-6, 1.0];
        let seen = seen_deviations(&scan, angle, &ds);
        let periodic = crate::surface::dilation::effective_roughness(&g, &ds[..3]);
        for (s, p) in seen.iter().zip(&periodic) {
            let l = s.lay.unwrap();
            assert!((l.delta_xi / p.delta_xi - 1.0).abs() < 0.05, "{s:?} {p:?}");
            assert!(
                (l.delta_zeta / p.delta_zeta - 1.0).abs() < 0.05,
                "{s:?} {p:?}"
            );
        }
        let z: Vec<f64> = seen[..3]
            .iter()
            .map(|s| s.lay.unwrap().delta_zeta)
            .collect();
        assert!(z[0] > z[1] && z[1] > z[2], "{z:?}");
        assert!(seen[1].exact_fraction < 1.0 && seen[1].exact_fraction > 0.5);
        assert_eq!((seen[3].lay, seen[3].exact_fraction), (None, 0.0));
    }
}
