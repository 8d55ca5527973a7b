//! The surface a finite sphere's centre rides on: the dilation of the height field by a
//! sphere of radius `R` (issue "the particle as a sphere"). A sphere resting on the wall
//! above `(x, z)` has its centre at height `R + c(x, z)` with
//!
//! `c(x, z) = max over (x′, z′) of [h(x′, z′) + √(R² − r²)] − R`, `r² = (x − x′)² + (z − z′)²`,
//!
//! (the exact sphere, [`dilate_sphere_exact`]). For `R ≫ h` the cap is the paraboloid
//! `√(R² − r²) − R ≈ −r²/2R`, which separates in `x` and `z`:
//! `c(x, z) = max_z′ [max_x′ (h(x′, z′) − (x − x′)²/2R) − (z − z′)²/2R]`
//! ([`dilate_paraboloid`]). Each 1-D max-plus convolution with a parabola is the lower
//! envelope of parabolas of Felzenszwalb & Huttenlocher (*Distance transforms of sampled
//! functions*, Theory of Computing 8 (2012) 415–428, Sec. 3, algorithm DT), O(N) per line,
//! so the dilated surface costs O(N²) on an N × N grid. The wall is periodic: a line is
//! extended by the nodes that can still win, those within `√(2R Δh)` with `Δh` the height
//! range (farther ones lie below every near one, `Δh − d²/2R < 0`).
//!
//! The sphere touches the wall at the node that attains the maximum; [`Dilated`] keeps the
//! fraction of nodes that some resting sphere touches.

use super::HeightField;
use rayon::prelude::*;

impl Dilated {
    /// The surface itself: a point touches every node.
    fn point(f: &HeightField) -> Dilated {
        Dilated {
            field: f.clone(),
            contact_fraction: 1.0,
        }
    }

    /// The centre surface `heights` on `f`'s grid, and the contact node of each node.
    fn of(f: &HeightField, heights: Vec<f64>, contacts: impl Iterator<Item = usize>) -> Dilated {
        let mut touched = vec![false; f.nx * f.nz];
        for q in contacts {
            touched[q] = true;
        }
        let count = touched.iter().filter(|&&t| t).count();
        Dilated {
            field: HeightField {
                nx: f.nx,
                nz: f.nz,
                dx: f.dx,
                dz: f.dz,
                heights,
                triangulation: f.triangulation,
            },
            contact_fraction: count as f64 / touched.len() as f64,
        }
    }
}

/// Bytes per node [`dilate_paraboloid`] holds at its peak, besides the surface itself.
pub const BYTES_PER_NODE: u64 = 32;

/// A dilated surface and the fraction of the original nodes a resting sphere touches.
#[derive(Clone, Debug)]
pub struct Dilated {
    /// The centre surface `c(x, z)` on the original grid (heights in m): a resting sphere's
    /// centre is `R` above it (the surface itself for a point).
    pub field: HeightField,
    /// Fraction of the original nodes that some resting sphere touches, in `(0, 1]` (1 for a
    /// point).
    pub contact_fraction: f64,
}

/// The centre surface of a sphere of diameter `diameter_m` on `f` for a run: refused (one
/// line naming `particles.diameter_um`, `why` saying for what) when the sphere is wider than
/// the surface's period — it would rest on its own images — or its buffers do not fit in
/// memory. A 2-D surface stored as one row (or column) has no period along that axis.
pub fn sphere_centre_surface(
    f: &HeightField,
    diameter_m: f64,
    why: &str,
) -> crate::error::Result<Dilated> {
    let side = match (f.nx > 1, f.nz > 1) {
        (true, true) => f.length_x().min(f.length_z()),
        (true, false) => f.length_x(),
        (false, _) => f.length_z(),
    };
    if diameter_m > side {
        return Err(crate::error::Error::invalid(
            "particles.diameter_um",
            crate::format::fmt_num(diameter_m * 1e6),
            &format!(
                "at most the surface side, {} µm, for {why} (a wider sphere rests on its own periodic images; enlarge deterministic.side_per_corr_length)",
                crate::format::fmt_num(side * 1e6)
            ),
        ));
    }
    crate::memory::require(
        "particles.diameter_um",
        diameter_m * 1e6,
        (f.heights.len() as u64).saturating_mul(BYTES_PER_NODE),
        "the centre surface of the sphere",
    )?;
    Ok(dilate_paraboloid(f, 0.5 * diameter_m))
}

/// Lowest and highest height of `f`.
fn height_range(f: &HeightField) -> (f64, f64) {
    f.heights
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &h| {
            (a.min(h), b.max(h))
        })
}

/// The nodes around a line's node that can attain its maximum: `⌈√(2RΔh)/δ⌉ + 1`.
fn reach(radius_m: f64, height_range: f64, spacing: f64) -> usize {
    let r = (2.0 * radius_m * height_range.max(0.0)).sqrt() / spacing;
    if r.is_finite() {
        r.ceil() as usize + 1
    } else {
        usize::MAX
    }
}

/// `out[p] = max_q (f[q] − a (p − q)²)` over the periodic line `f` (only `q` within `reach`
/// of `p` can win), and `arg[p]` the winning `q` (in `0..n`). Felzenszwalb & Huttenlocher's
/// lower envelope, on `−f/a`, over the line extended by `reach` nodes each side.
#[allow(clippy::too_many_arguments)]
fn max_plus_line(
    f: &[f64],
    a: f64,
    reach: usize,
    out: &mut [f64],
    arg: &mut [u32],
    ext: &mut Vec<f64>,
    v: &mut Vec<usize>,
    z: &mut Vec<f64>,
) {
    let n = f.len();
    let w = reach.min(2 * n);
    ext.clear();
    // g[i] = −f[(i − w) mod n] / a, on i in 0..n + 2w.
    ext.extend((0..n + 2 * w).map(|i| -f[(i + n * (w / n + 1) - w) % n] / a));
    let m = ext.len();
    v.clear();
    z.clear();
    v.push(0);
    z.push(f64::NEG_INFINITY);
    z.push(f64::INFINITY);
    let key = |q: usize, g: &[f64]| g[q] + (q * q) as f64;
    for q in 1..m {
        loop {
            let k = v.len() - 1;
            let p = v[k];
            let s = (key(q, ext) - key(p, ext)) / (2.0 * (q as f64 - p as f64));
            if s <= z[k] && k > 0 {
                v.pop();
                z.pop();
                continue;
            }
            if s <= z[k] {
                // k == 0: the new parabola replaces the first.
                v[0] = q;
                break;
            }
            v.push(q);
            z[k + 1] = s;
            z.push(f64::INFINITY);
            break;
        }
    }
    let mut k = 0;
    for p in w..w + n {
        while z[k + 1] < p as f64 {
            k += 1;
        }
        let q = v[k];
        let d = p as f64 - q as f64;
        let src = (q + n * (w / n + 1) - w) % n;
        // From the original height, so a node that wins for itself keeps its bits.
        out[p - w] = f[src] - a * d * d;
        arg[p - w] = src as u32;
    }
}

/// Rows of `src` (`nx` wide) dilated along the row with weight `a` per squared index step.
fn rows_pass(src: &[f64], nx: usize, a: f64, reach: usize, out: &mut [f64], arg: &mut [u32]) {
    out.par_chunks_mut(nx)
        .zip(arg.par_chunks_mut(nx))
        .zip(src.par_chunks(nx))
        .for_each_init(
            || (Vec::new(), Vec::new(), Vec::new()),
            |(ext, v, z), ((o, g), row)| max_plus_line(row, a, reach, o, g, ext, v, z),
        );
}

/// The transpose of an `nz × nx` row-major array, in cache-sized tiles.
fn transpose<T: Copy + Default + Send + Sync>(src: &[T], nx: usize, nz: usize) -> Vec<T> {
    const B: usize = 64;
    let mut dst = vec![T::default(); src.len()];
    dst.par_chunks_mut(nz * B)
        .enumerate()
        .for_each(|(bx, chunk)| {
            let x0 = bx * B;
            let x1 = (x0 + B).min(nx);
            for z0 in (0..nz).step_by(B) {
                for x in x0..x1 {
                    for zz in z0..(z0 + B).min(nz) {
                        chunk[(x - x0) * nz + zz] = src[zz * nx + x];
                    }
                }
            }
        });
    dst
}

/// The centre surface of a sphere of radius `radius_m` in the paraboloid approximation
/// (`√(R² − r²) − R ≈ −r²/2R`), exactly separable; O(N²) with the lower envelope of
/// parabolas. `radius_m = 0` returns the surface itself (every node touched).
pub fn dilate_paraboloid(f: &HeightField, radius_m: f64) -> Dilated {
    let (nx, nz) = (f.nx, f.nz);
    if radius_m <= 0.0 || nx == 0 || nz == 0 {
        return Dilated::point(f);
    }
    let (lo, hi) = height_range(f);
    let range = hi - lo;
    // Along x: weight δx²/2R per squared index step.
    let ax = f.dx * f.dx / (2.0 * radius_m);
    let mut rows = vec![0.0; nx * nz];
    let mut arg_x = vec![0u32; nx * nz];
    rows_pass(
        &f.heights,
        nx,
        ax,
        reach(radius_m, range, f.dx),
        &mut rows,
        &mut arg_x,
    );
    // Along z, on the transpose.
    // Buffers are freed as soon as they are used: the peak is about 32 bytes per node.
    let az = f.dz * f.dz / (2.0 * radius_m);
    let t = transpose(&rows, nx, nz);
    drop(rows);
    let mut cols = vec![0.0; nx * nz];
    let mut arg_z = vec![0u32; nx * nz];
    rows_pass(
        &t,
        nz,
        az,
        reach(radius_m, range, f.dz),
        &mut cols,
        &mut arg_z,
    );
    drop(t);
    let heights = transpose(&cols, nz, nx);
    drop(cols);
    let arg_z = transpose(&arg_z, nz, nx);
    // The node touched above (x, z): row arg_z, column arg_x of that row.
    let contacts = (0..nx * nz).map(|p| {
        let qz = arg_z[p] as usize;
        qz * nx + arg_x[qz * nx + p % nx] as usize
    });
    Dilated::of(f, heights, contacts)
}

/// The centre surface of an exact sphere of radius `radius_m`, by brute force over the
/// nodes that can win (within `√(R² − (R − Δh)²)`): O(N² (√(2RΔh)/δ)²), for checking the
/// paraboloid and for small grids.
pub fn dilate_sphere_exact(f: &HeightField, radius_m: f64) -> Dilated {
    let (nx, nz) = (f.nx, f.nz);
    if radius_m <= 0.0 || nx == 0 || nz == 0 {
        return Dilated::point(f);
    }
    let (lo, hi) = height_range(f);
    let dh = (hi - lo).min(radius_m);
    let r_max = (radius_m * radius_m - (radius_m - dh) * (radius_m - dh)).sqrt();
    let wx = ((r_max / f.dx).ceil() as usize + 1).min(nx);
    let wz = ((r_max / f.dz).ceil() as usize + 1).min(nz);
    let r2 = radius_m * radius_m;
    let best: Vec<(f64, usize)> = (0..nz * nx)
        .into_par_iter()
        .map(|p| {
            let (iz, ix) = (p / nx, p % nx);
            let mut b = (f64::NEG_INFINITY, p);
            for dz in -(wz as isize)..=(wz as isize) {
                let z = dz as f64 * f.dz;
                let qz = (iz as isize + dz).rem_euclid(nz as isize) as usize;
                for dx in -(wx as isize)..=(wx as isize) {
                    let x = dx as f64 * f.dx;
                    let d2 = x * x + z * z;
                    if d2 > r2 {
                        continue;
                    }
                    let qx = (ix as isize + dx).rem_euclid(nx as isize) as usize;
                    let q = qz * nx + qx;
                    let c = f.heights[q] + (r2 - d2).sqrt() - radius_m;
                    if c > b.0 {
                        b = (c, q);
                    }
                }
            }
            b
        })
        .collect();
    let contacts: Vec<usize> = best.iter().map(|b| b.1).collect();
    Dilated::of(
        f,
        best.into_iter().map(|b| b.0).collect(),
        contacts.into_iter(),
    )
}

/// The roughness a sphere of diameter `diameter_m` sees: the measured normal-angle
/// deviations of its centre surface (paraboloid dilation) and the fraction of nodes a
/// resting sphere touches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EffectiveRoughness {
    /// Sphere diameter `D` (m); 0 is the surface itself.
    pub diameter_m: f64,
    /// Measured `Δξ` of the centre surface (rad): RMS of the triangle normals' `ξ − 90°`.
    pub delta_xi: f64,
    /// Measured `Δζ` of the centre surface (rad): RMS of the triangle normals' `ζ − 90°`.
    pub delta_zeta: f64,
    /// Fraction of the surface's nodes that some resting sphere touches, in `(0, 1]`.
    pub contact_fraction: f64,
}

/// [`EffectiveRoughness`] of `f` for each diameter (m); `0` gives the surface's own.
pub fn effective_roughness(f: &HeightField, diameters_m: &[f64]) -> Vec<EffectiveRoughness> {
    diameters_m
        .iter()
        .map(|&d| {
            let dil = dilate_paraboloid(f, 0.5 * d);
            let m = super::stats::measured_deviations(&dil.field);
            EffectiveRoughness {
                diameter_m: d,
                delta_xi: m.delta_xi,
                delta_zeta: m.delta_zeta,
                contact_fraction: dil.contact_fraction,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(nx: usize, nz: usize, seed: u64) -> HeightField {
        // A rough periodic test field: sums of sines with incommensurate phases.
        let mut h = Vec::with_capacity(nx * nz);
        for iz in 0..nz {
            for ix in 0..nx {
                let (x, z) = (ix as f64 / nx as f64, iz as f64 / nz as f64);
                let t = std::f64::consts::TAU;
                let s = seed as f64;
                h.push(
                    1e-6 * ((t * (3.0 * x + 0.3 * s)).sin()
                        + 0.5 * (t * (7.0 * x + 2.0 * z + s)).sin()
                        + 0.3 * (t * (11.0 * z + 0.7 * s)).cos()
                        + 0.2 * (t * (17.0 * x - 13.0 * z)).sin()),
                );
            }
        }
        HeightField {
            nx,
            nz,
            dx: 1e-6,
            dz: 0.7e-6,
            heights: h,
            triangulation: Default::default(),
        }
    }

    /// The paraboloid dilation by brute force over the whole periodic grid.
    fn brute_paraboloid(f: &HeightField, r: f64) -> Vec<f64> {
        let (nx, nz) = (f.nx, f.nz);
        (0..nx * nz)
            .map(|p| {
                let (iz, ix) = (p / nx, p % nx);
                let mut b = f64::NEG_INFINITY;
                for qz in 0..nz {
                    for qx in 0..nx {
                        // Nearest periodic images.
                        let dx = {
                            let d = (ix as isize - qx as isize).rem_euclid(nx as isize);
                            d.min(nx as isize - d) as f64 * f.dx
                        };
                        let dz = {
                            let d = (iz as isize - qz as isize).rem_euclid(nz as isize);
                            d.min(nz as isize - d) as f64 * f.dz
                        };
                        b = b.max(f.heights[qz * nx + qx] - (dx * dx + dz * dz) / (2.0 * r));
                    }
                }
                b
            })
            .collect()
    }

    #[test]
    fn lower_envelope_equals_brute_force() {
        for (nx, nz, r) in [(40, 30, 5e-6), (33, 17, 40e-6), (24, 24, 1e-3)] {
            let f = field(nx, nz, 3);
            let d = dilate_paraboloid(&f, r);
            let b = brute_paraboloid(&f, r);
            for (x, y) in d.field.heights.iter().zip(&b) {
                assert!((x - y).abs() < 1e-18, "R = {r}: {x} vs {y}");
            }
            // Dilation lifts (or keeps) every node; a resting sphere touches some nodes.
            assert!(d.field.heights.iter().zip(&f.heights).all(|(c, h)| c >= h));
            assert!(d.contact_fraction > 0.0 && d.contact_fraction <= 1.0);
        }
    }

    #[test]
    fn small_spheres_see_the_surface_and_large_ones_a_smoother_one() {
        let f = field(64, 64, 1);
        let tiny = dilate_paraboloid(&f, 1e-12);
        assert_eq!(tiny.field.heights, f.heights);
        assert_eq!(tiny.contact_fraction, 1.0);
        let zero = dilate_paraboloid(&f, 0.0);
        assert_eq!(zero.field.heights, f.heights);
        let mut last = 1.0;
        for r in [2e-6, 20e-6, 200e-6, 2e-3] {
            let d = dilate_paraboloid(&f, r);
            assert!(d.contact_fraction <= last, "{r}");
            last = d.contact_fraction;
        }
        assert!(last < 0.1, "{last}");
    }

    /// Largest `|a − b|` over two height grids.
    fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn paraboloid_approaches_the_exact_sphere_for_large_radii() {
        let f = field(48, 48, 2);
        let mut errs = Vec::new();
        for r in [5e-6, 50e-6, 500e-6] {
            let p = dilate_paraboloid(&f, r);
            let e = dilate_sphere_exact(&f, r);
            let err = max_abs_diff(&p.field.heights, &e.field.heights);
            // The paraboloid lies above the cap: it can only be higher.
            assert!(p
                .field
                .heights
                .iter()
                .zip(&e.field.heights)
                .all(|(a, b)| a >= &(b - 1e-18)));
            errs.push(err);
        }
        assert!(errs[0] > errs[1] && errs[1] > errs[2], "{errs:?}");
        assert!(errs[2] < 1e-9, "{errs:?}");
    }

    /// The paraboloid against the exact sphere on a Table 1-like surface (h = 0.37 µm,
    /// c_L = 12 × 4 µm, δ = 1 µm): the largest height error over the grid relative to the
    /// rms height, and the effective deviations of both.
    #[test]
    fn paraboloid_error_on_a_generated_surface() {
        let spec = crate::surface::SurfaceSpec {
            length_m: 128e-6,
            nodes: 128,
            rms_height_m: 0.37e-6,
            corr_length_x_m: Some(12e-6),
            corr_length_z_m: Some(4e-6),
        };
        let f = crate::surface::generate(&spec, 1);
        for (d, bound, dev_bound) in [
            (5e-6, 0.05, 0.002),
            (50e-6, 0.15, 0.01),
            (500e-6, 0.02, 0.002),
        ] {
            let t = std::time::Instant::now();
            let p = dilate_paraboloid(&f, 0.5 * d);
            let tp = t.elapsed().as_secs_f64();
            let e = dilate_sphere_exact(&f, 0.5 * d);
            let te = t.elapsed().as_secs_f64() - tp;
            let err = max_abs_diff(&p.field.heights, &e.field.heights) / spec.rms_height_m;
            let mp = super::super::stats::measured_deviations(&p.field);
            let me = super::super::stats::measured_deviations(&e.field);
            let dev = (mp.delta_zeta / me.delta_zeta - 1.0).abs();
            eprintln!(
                "D = {d}: max error {err} h, Δζ_eff relative {dev}, {tp:.4} s vs exact {te:.4} s"
            );
            assert!(err < bound, "D = {d}: max error {err} h");
            assert!(dev < dev_bound, "D = {d}: Δζ_eff differs by {dev}");
        }
    }

    #[test]
    fn a_flat_wall_stays_flat_and_a_ridge_keeps_its_height() {
        let mut f = field(16, 16, 0);
        f.heights.iter_mut().for_each(|h| *h = 3e-7);
        let d = dilate_paraboloid(&f, 1e-4);
        assert!(d.field.heights.iter().all(|&h| (h - 3e-7).abs() < 1e-20));
        // 2-D roughness (constant along z) stays 2-D.
        let g = HeightField {
            heights: (0..16 * 16)
                .map(|p| 1e-6 * ((p % 16) as f64 * 0.7).sin())
                .collect(),
            ..f
        };
        let d = dilate_paraboloid(&g, 5e-5);
        for iz in 1..16 {
            assert_eq!(
                d.field.heights[iz * 16..iz * 16 + 16],
                d.field.heights[..16]
            );
        }
    }
}
