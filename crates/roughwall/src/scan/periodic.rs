//! A measured scan as a wall the deterministic model can bounce on (issue 29, part 4): turned
//! so that its lay is the models' `x`, cropped to the largest rectangle inside it, and made
//! periodic by mirrored tiling.
//!
//! The tracker follows a particle over a periodic [`HeightField`]; a scan is neither periodic
//! nor, in general, aligned with its lay. The scan is resampled (bilinear between valid
//! nodes, [`super::correlation`]) on a grid along the lay `l = (cos φ, sin φ)` and the models'
//! `z*` of it, `(sin φ, −cos φ)` in the scan's axes ([`ScanField`]: the scan's `y` is the
//! models' `−z`), at the scan's finer spacing, over the largest rectangle with those axes
//! inside the scan. Mirrored tiling then reflects the rectangle about its last row and column
//! (without repeating them): the wall is continuous and periodic with twice the rectangle's
//! size less one spacing, and each reflected copy is the mirror image of the scan. The price
//! is a kink along every mirror line and mirror-symmetric statistics: a texture that is not
//! its own mirror image (a sawtooth, a tilted lay of scratches) loses that asymmetry. The
//! deterministic model needs every node: a missing point inside the rectangle is refused.

use super::correlation::bilinear;
use super::ScanField;
use crate::error::{Error, Result};
use crate::surface::{HeightField, Triangulation};

/// How a scan became a wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MirroredWall {
    /// The lay angle the scan was turned by (rad, from its `x` towards its `y`).
    pub lay_angle: f64,
    /// Nodes of the rectangle along the lay and across it, before tiling.
    pub rectangle: [usize; 2],
    /// Grid spacing (m), the scan's finer one.
    pub spacing_m: f64,
    /// Fraction of the scan's area the rectangle covers.
    pub area_fraction: f64,
}

/// Half-sides `(A, B)` of the largest rectangle with axes `l = (c, s)` and `t = (s, −c)`,
/// centred on a `lx × ly` rectangle, inside it: `A|c| + B|s| ≤ lx/2`, `A|s| + B|c| ≤ ly/2`.
fn inscribed(lx: f64, ly: f64, angle: f64) -> (f64, f64) {
    let (c, s) = (angle.cos().abs(), angle.sin().abs());
    let (hx, hy) = (0.5 * lx, 0.5 * ly);
    if s < 1e-12 {
        return (hx, hy);
    }
    if c < 1e-12 {
        return (hy, hx);
    }
    let fits =
        |a: f64, b: f64| a * c + b * s <= hx * (1.0 + 1e-12) && a * s + b * c <= hy * (1.0 + 1e-12);
    // The product A·B is largest on one constraint at its midpoint, or where both meet.
    let mut best = (0.0, 0.0);
    let det = c * c - s * s;
    let mut candidates = vec![
        (hx / (2.0 * c), hx / (2.0 * s)),
        (hy / (2.0 * s), hy / (2.0 * c)),
    ];
    if det.abs() > 1e-12 {
        candidates.push(((hx * c - hy * s) / det, (hy * c - hx * s) / det));
    }
    for (a, b) in candidates {
        if a > 0.0 && b > 0.0 && fits(a, b) && a * b > best.0 * best.1 {
            best = (a, b);
        }
    }
    best
}

/// The scan `f` (levelled) turned to its lay `lay_angle`, cropped and mirror-tiled into a
/// periodic wall with its lay along `x` (the deterministic model's `Δξ` direction).
pub fn mirrored_wall(f: &ScanField, lay_angle: f64) -> Result<(HeightField, MirroredWall)> {
    let spacing = f.dx.min(f.dy);
    let (lx, ly) = ((f.nx - 1) as f64 * f.dx, (f.ny - 1) as f64 * f.dy);
    let (a, b) = inscribed(lx, ly, lay_angle);
    let (n, m) = (
        ((2.0 * a / spacing).floor() as usize).saturating_add(1),
        ((2.0 * b / spacing).floor() as usize).saturating_add(1),
    );
    if n < 3 || m < 3 {
        return Err(Error::Input(format!(
            "scan of {} × {} points turned by {:.1}° to its lay leaves a rectangle of {n} × {m} points: at least 3 × 3 are needed",
            f.nx,
            f.ny,
            lay_angle.to_degrees()
        )));
    }
    // Resampled at the finer spacing, a scan of very unequal pixels (1 m × 1 nm) asks for
    // far more points than it has: refused by size, then by memory, before anything is
    // allocated (issue 42: 392 GB were asked for and the process aborted).
    let tiled = n
        .checked_mul(m)
        .and_then(|p| p.checked_mul(4))
        .filter(|&p| p as u64 <= crate::surface::heights_io::MAX_NODES);
    let Some(tiled) = tiled else {
        return Err(Error::Input(format!(
            "scan of {} × {} points of {:e} m × {:e} m resampled along its lay at its finer spacing gives a rectangle of {n} × {m} points, a mirror-tiled wall of more than {} nodes: allowed pixels whose sizes differ less, or a scan cropped to fewer points",
            f.nx,
            f.ny,
            f.dx,
            f.dy,
            crate::surface::heights_io::MAX_NODES
        )));
    };
    crate::memory::require(
        "scan",
        format!("{} × {} points", f.nx, f.ny),
        8 * (tiled + tiled / 4) as u64,
        &format!(
            "its mirror-tiled wall of {} × {} nodes",
            2 * (n - 1),
            2 * (m - 1)
        ),
    )?;
    let (c, s) = (lay_angle.cos(), lay_angle.sin());
    let centre = (0.5 * lx, 0.5 * ly);
    let (a0, b0) = (
        0.5 * (n - 1) as f64 * spacing,
        0.5 * (m - 1) as f64 * spacing,
    );
    let mut rect = Vec::with_capacity(n * m);
    let mut missing = 0usize;
    for j in 0..m {
        let v = j as f64 * spacing - b0;
        for i in 0..n {
            let u = i as f64 * spacing - a0;
            // p = centre + u l + v t, t = (s, −c).
            let (x, y) = (centre.0 + u * c + v * s, centre.1 + u * s - v * c);
            let h = bilinear(
                f,
                (x / f.dx).clamp(0.0, (f.nx - 1) as f64),
                (y / f.dy).clamp(0.0, (f.ny - 1) as f64),
            );
            match h {
                Some(h) => rect.push(h),
                None => {
                    missing += 1;
                    rect.push(0.0);
                }
            }
        }
    }
    if missing > 0 {
        return Err(Error::Input(format!(
            "scan: {missing} points of the {n} × {m} rectangle along its lay lie next to a missing point; the deterministic model needs a complete wall (crop the scan to a complete region or fill its gaps)"
        )));
    }
    // Mirrored tiling about the last row and column, which are not repeated.
    let (nx, nz) = (2 * (n - 1), 2 * (m - 1));
    let fold = |k: usize, len: usize| if k < len { k } else { 2 * (len - 1) - k };
    let mut heights = Vec::with_capacity(nx * nz);
    for jz in 0..nz {
        let j = fold(jz, m);
        for ix in 0..nx {
            heights.push(rect[j * n + fold(ix, n)]);
        }
    }
    let wall = HeightField {
        nx,
        nz,
        dx: spacing,
        dz: spacing,
        heights,
        triangulation: Triangulation::Alternating,
    };
    let area = ((n - 1) as f64 * spacing) * ((m - 1) as f64 * spacing) / (lx * ly);
    Ok((
        wall,
        MirroredWall {
            lay_angle,
            rectangle: [n, m],
            spacing_m: spacing,
            area_fraction: area,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scan::lay::lay;

    #[test]
    fn the_inscribed_rectangle() {
        // Aligned: the whole scan; turned by 90°: the sides swap.
        assert_eq!(inscribed(4.0, 2.0, 0.0), (2.0, 1.0));
        let (a, b) = inscribed(4.0, 2.0, std::f64::consts::FRAC_PI_2);
        assert!((a - 1.0).abs() < 1e-12 && (b - 2.0).abs() < 1e-12);
        // A square turned by 45°: the inscribed square of side L/√2.
        let (a, b) = inscribed(2.0, 2.0, std::f64::consts::FRAC_PI_4);
        assert!(
            (a - 0.5f64.sqrt()).abs() < 1e-12 && (b - a).abs() < 1e-12,
            "{a} {b}"
        );
    }

    /// A generated wall turned by 30° and read back along its lay: the mirrored wall is
    /// periodic and continuous, its lay along x, and its deviations those of the scan.
    #[test]
    fn a_turned_wall_comes_back_along_its_lay() {
        let g = crate::scan::tests::sec3_wall(512, 4);
        // Turn the periodic wall by φ = 30°: the scan's node (x, y) samples the wall at
        // u = x cos φ + y sin φ along its x and w = x sin φ − y cos φ along its z.
        let phi = 30f64.to_radians();
        let (nx, ny) = (300, 300);
        let mut h = Vec::with_capacity(nx * ny);
        for iy in 0..ny {
            for ix in 0..nx {
                let (x, y) = (ix as f64 * g.dx, iy as f64 * g.dx);
                let (u, w) = (x * phi.cos() + y * phi.sin(), x * phi.sin() - y * phi.cos());
                let (fu, fw) = (u / g.dx, w.rem_euclid(g.length_z()) / g.dz);
                let (i, j) = (fu.floor(), fw.floor());
                let (tu, tw) = (fu - i, fw - j);
                let at = |di: usize, dj: usize| g.at(i as usize + di, j as usize + dj);
                h.push(
                    (1.0 - tw) * ((1.0 - tu) * at(0, 0) + tu * at(1, 0))
                        + tw * ((1.0 - tu) * at(0, 1) + tu * at(1, 1)),
                );
            }
        }
        let scan = ScanField::new(nx, ny, g.dx, g.dx, h).unwrap();
        let l = lay(&scan).unwrap();
        assert!(
            (l.angle - phi).abs() < 3f64.to_radians(),
            "{}",
            l.angle.to_degrees()
        );
        let (wall, info) = mirrored_wall(&scan, l.angle).unwrap();
        assert!(
            info.area_fraction > 0.3 && info.area_fraction < 0.6,
            "{info:?}"
        );
        assert_eq!((wall.nx % 2, wall.nz % 2), (0, 0));
        // Periodic and continuous: the node after the last is the first's neighbour mirror.
        let [n, _] = info.rectangle;
        assert_eq!(wall.at(n - 2, 0), wall.at(n, 0));
        assert_eq!(wall.at(0, 1), wall.at(0, wall.nz - 1));
        let back = crate::surface::stats::measured_deviations(&wall);
        assert!(
            (back.delta_xi / l.delta_xi - 1.0).abs() < 0.1,
            "{back:?} {l:?}"
        );
        assert!(
            (back.delta_zeta / l.delta_zeta - 1.0).abs() < 0.1,
            "{back:?} {l:?}"
        );
        assert!(back.delta_zeta > 2.0 * back.delta_xi);
        // A missing point inside: refused, saying so.
        let mut holed = scan.clone();
        holed.heights[150 * nx + 150] = f64::NAN;
        let e = mirrored_wall(&holed, l.angle).unwrap_err().to_string();
        assert!(e.contains("needs a complete wall"), "{e}");
    }
}
