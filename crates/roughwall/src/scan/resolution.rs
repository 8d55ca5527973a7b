//! Whether a scan is large enough and fine enough for the deviations a particle of a given
//! diameter sees on it (the wall card's per-diameter notes, docs/models.md "Measured walls").
//!
//! **The length a particle's view decorrelates over.** A point particle (`D = 0`) sees the
//! wall's own slopes, which decorrelate over the correlation lengths `c_L` (Radenkovic &
//! Simonin 2021, Eqs. 1–2: `R(τ) = h² exp(−τ²/c_L²)`). A sphere of radius `R = D/2` rides on
//! its centre surface ([`super::centre_surface`]), made of paraboloid caps `−r²/2R` around
//! the asperity tops it rests on: caps on tops whose heights differ by about `Sq` meet about
//! the **footprint** `a = √(2R·Sq) = √(D·Sq)` apart, so the caps are about `a` wide (their
//! slopes `r/R` span `±2√(Sq/D)`, the `Δ_eff ≈ √(h/D)` of large spheres, docs/models.md
//! "Sphere contact and effective roughness"). `Sq`, not the peak-to-valley `Δh`: `Δh` is set
//! by the highest and lowest points and grows with the scan, which is why the reach `√(2RΔh)`
//! bounds where a sphere may rest but is not its typical cap. The centre surface decorrelates
//! over `ℓ = √(c_L² + D·Sq)` along and across the lay: on the Sec. 3 wall (c_L = 33 and
//! 10.5 µm measured, Sq = 1 µm) its `1/e` lengths across the lay are 11.9, 17.8, 25.6, 43.9
//! and 83.1 µm at D = 50, 200, 500, 2000 and 8000 µm, against `ℓ` = 12.6, 17.6, 24.6, 45.8
//! and 89.7 µm (along: within 18 %).
//!
//! **Too small.** Over an area `A`, the mean of a Gaussian slope's square has variance
//! `(2/A) ∫ C_s(τ)² dτ` (the fourth moments of Isserlis, Biometrika 12 (1918) 134–139); for
//! the slope along `x` of `R` above, `C_s ∝ (1 − 2τ_x²/c_Lx²) exp(−τ_x²/c_Lx² − τ_z²/c_Lz²)`
//! and `∫ C_s² dτ / C_s(0)² = (3π/8) c_Lx c_Lz`, so `se(Δ)/Δ = √(3π/16)/√N ≈ 0.77/√N` with
//! `N = A/(ℓ_along ℓ_across)` the correlation areas of the exact part of the centre surface.
//! The scan is too small for a diameter when `N < 250` (`Δ` uncertain by more than 5 %) or
//! when less than half of it is exact (the edges lose a band of `√(2RΔh)` each; a few spikes
//! or pits make `Δh` large). A direction whose autocorrelation does not fall to `1/e` within
//! a quarter of the scan counts a quarter of the scan as its `c_L`: `N` is then an upper
//! bound. A wall whose heights correlate farther than its slopes (a waviness under the
//! roughness) gets a lower `N` than its slopes would: the note errs on the safe side.
//!
//! **Resolution-limited: measured, not assumed.** A triangle's slope is a finite difference
//! over the pixel `δ`; on a Gaussian wall its variance is `2h²(1 − e^(−δ²/c²))/δ²` against
//! `2h²/c²` (docs/physics.md §4), so `Δ` would come out low by `√((1 − e^(−x²))/x²)`,
//! `x = δ/c_L`. Real walls are multi-scale: a criterion on the Gaussian `1/e` length (4 pixels
//! per `c_L`) never fired on 17 real scans whose point-particle deviations fell by 2–32 % when
//! the pixel was doubled (issue 39). So each row measures instead: the same deviations on the
//! scan read at twice its pixel (every other point along `x` and `y`, [`decimated`]), and
//! their relative change ([`SeenBy::resolution_change`]). A change beyond
//! [`MAX_RESOLUTION_CHANGE`] (5 %) means the deviations are still those of the pixel, not the
//! wall's (the point particle's, by construction, always are the pixel's: it sees every
//! triangle); a finer pixel, or a larger particle whose footprint spans many pixels, is
//! what to measure. Measured on the Sec. 3 wall (a Gaussian wall): at 8
//! nodes per `c_Lz` the point's Δζ changes by −1.0 % at twice the pixel (the formula: −1.2 %)
//! and a 500 µm sphere's by −2.2 % (it rests on summits the pixel must resolve); at 2 nodes
//! per `c_Lz` by −15.8 % (formula −15.5 %) and −8.4 %: both resolution-limited.

use super::centre_surface::{seen_deviations, SeenDeviations};
#[cfg(test)]
use super::lay::Lay;
use super::{Characterisation, ScanField};

/// Fewest correlation areas the exact part must hold: `Δ` to 5 % (`0.77/√250`).
pub const MIN_CORRELATION_AREAS: f64 = 250.0;

/// Smallest fraction of the scan the centre surface must be exact on.
pub const MIN_EXACT_FRACTION: f64 = 0.5;

/// Largest relative change of a row's `Δξ` or `Δζ` when the pixel is doubled that still
/// counts the deviations as the wall's; beyond it the row is resolution-limited.
pub const MAX_RESOLUTION_CHANGE: f64 = 0.05;

/// `se(Δ)/Δ · √N` for a Gaussian wall: `√(3π/16)`.
pub fn relative_error_per_sqrt_area() -> f64 {
    (3.0 * std::f64::consts::PI / 16.0).sqrt()
}

// `Δ` of a Gaussian wall's finite differences over the pixel against the wall's own: the
// one formula of `surface::normal_angles` (docs/physics.md §4), what the tests hold the
// measured check to.
#[cfg(test)]
use crate::surface::normal_angles::finite_difference_ratio;

/// The footprint `√(2R·Sq) = √(D·Sq)` (m) of a sphere of diameter `diameter_m` on a wall of
/// rms height `sq_m`: how wide the caps of its centre surface are.
pub fn footprint(diameter_m: f64, sq_m: f64) -> f64 {
    (diameter_m.max(0.0) * sq_m.max(0.0)).sqrt()
}

/// How well a scan serves a particle of one diameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolution {
    /// Fraction of the scan's points where the centre surface is exact.
    pub exact_fraction: f64,
    /// The footprint `√(D·Sq)` (m); 0 for a point.
    pub footprint_m: f64,
    /// The wall's correlation lengths `c_L` along and across the lay (m), or a quarter of
    /// the scan where the autocorrelation does not fall to `1/e` within it.
    pub correlation_m: [f64; 2],
    /// Whether `c_L` along and across was only bounded by a quarter of the scan.
    pub bounded: [bool; 2],
    /// The lengths `ℓ = √(c_L² + D·Sq)` the centre surface decorrelates over, along and
    /// across the lay (m).
    pub sampling_m: [f64; 2],
    /// The pixel projected on the lay and across it (m).
    pub pixel_m: [f64; 2],
    /// Correlation areas `ℓ_along ℓ_across` in the exact part.
    pub correlation_areas: f64,
}

impl Resolution {
    /// The relative standard error of `Δ` expected from [`Resolution::correlation_areas`]
    /// (infinite without any).
    pub fn relative_error(&self) -> f64 {
        relative_error_per_sqrt_area() / self.correlation_areas.sqrt()
    }

    /// Too few correlation areas, or too little of the scan exact.
    pub fn too_small(&self) -> bool {
        self.exact_fraction < MIN_EXACT_FRACTION || self.correlation_areas < MIN_CORRELATION_AREAS
    }
}

/// How well the characterised scan `c` serves a particle of diameter `diameter_m` (0: a
/// point), whose centre surface is exact on `exact_fraction` of the scan, with the lay at
/// `lay_angle` (rad).
pub fn resolution(
    c: &Characterisation,
    lay_angle: f64,
    diameter_m: f64,
    exact_fraction: f64,
) -> Resolution {
    let f = &c.levelled;
    let (lx, ly) = (f.nx as f64 * f.dx, f.ny as f64 * f.dy);
    // `correlation` looks for the 1/e crossing out to a quarter of the shorter side.
    let bound = 0.25 * lx.min(ly);
    let lengths = [c.correlation.length_along_m, c.correlation.length_across_m];
    let correlation_m = lengths.map(|l| l.unwrap_or(bound));
    let footprint_m = footprint(diameter_m, c.parameters.sq_m);
    let sampling_m = correlation_m.map(|l| l.hypot(footprint_m));
    let (cs, sn) = (lay_angle.cos().abs(), lay_angle.sin().abs());
    let pixel_m = [(cs * f.dx).max(sn * f.dy), (sn * f.dx).max(cs * f.dy)];
    Resolution {
        exact_fraction,
        footprint_m,
        correlation_m,
        bounded: lengths.map(|l| l.is_none()),
        sampling_m,
        pixel_m,
        correlation_areas: exact_fraction * lx * ly / (sampling_m[0] * sampling_m[1]),
    }
}

/// What a particle of one diameter sees on a scan, and how well the scan serves it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeenBy {
    /// The deviations of its centre surface.
    pub seen: SeenDeviations,
    /// How well the scan serves it.
    pub resolution: Resolution,
    /// The same deviations on the scan at twice its pixel ([`decimated`]); `None` when that
    /// scan is too small for them.
    pub at_double_pixel: Option<super::lay::Lay>,
}

impl SeenBy {
    /// The relative change of `Δξ` and `Δζ` when the pixel is doubled (`Δ(2δ)/Δ(δ) − 1`);
    /// `None` without both, or for a deviation of zero.
    pub fn resolution_change(&self) -> Option<[f64; 2]> {
        let (a, b) = (self.seen.lay?, self.at_double_pixel?);
        let change = |x: f64, y: f64| (x > 0.0).then(|| y / x - 1.0);
        Some([
            change(a.delta_xi, b.delta_xi)?,
            change(a.delta_zeta, b.delta_zeta)?,
        ])
    }

    /// Whether `Δξ` or `Δζ` changes by more than [`MAX_RESOLUTION_CHANGE`] at twice the
    /// pixel: the deviations are still the pixel's, not the wall's.
    pub fn resolution_limited(&self) -> bool {
        self.resolution_change()
            .is_some_and(|c| c.iter().any(|x| x.abs() > MAX_RESOLUTION_CHANGE))
    }
}

/// The scan at twice its pixel: every other point along `x` and `y` (no averaging: the
/// heights an instrument of twice the pixel would sample); `None` below 3 × 3 points.
pub fn decimated(f: &ScanField) -> Option<ScanField> {
    let (nx, ny) = (f.nx.div_ceil(2), f.ny.div_ceil(2));
    if nx < 3 || ny < 3 {
        return None;
    }
    let heights = (0..ny)
        .flat_map(|iy| (0..nx).map(move |ix| f.heights[2 * iy * f.nx + 2 * ix]))
        .collect();
    Some(ScanField {
        nx,
        ny,
        dx: 2.0 * f.dx,
        dy: 2.0 * f.dy,
        heights,
    })
}

/// For the point particle and then each of `diameters_m` (m, `> 0`): the deviations along and
/// across the scan's lay of the particle's centre surface (`seen_deviations`; the point's
/// are the scan's own, with no dilation), and the scan's `resolution` for it. `None`
/// without a lay (no cell with four valid corners).
pub fn seen_by(c: &Characterisation, diameters_m: &[f64]) -> Option<Vec<SeenBy>> {
    let lay = c.lay?;
    let f = &c.levelled;
    let point = SeenDeviations {
        diameter_m: 0.0,
        lay: Some(lay),
        exact_fraction: c.parameters.valid_points as f64 / (f.nx * f.ny) as f64,
        reach: [0, 0],
    };
    let spheres = seen_deviations(f, lay.angle, diameters_m);
    // The same rows at twice the pixel, with the lay of the full scan.
    let coarse = decimated(f);
    let at_double: Vec<Option<super::lay::Lay>> = match &coarse {
        Some(g) => std::iter::once(super::lay::lay_at(g, lay.angle))
            .chain(
                seen_deviations(g, lay.angle, diameters_m)
                    .into_iter()
                    .map(|s| s.lay),
            )
            .collect(),
        None => vec![None; diameters_m.len() + 1],
    };
    drop(coarse);
    Some(
        std::iter::once(point)
            .chain(spheres)
            .zip(at_double)
            .map(|(seen, at_double_pixel)| SeenBy {
                seen,
                resolution: resolution(c, lay.angle, seen.diameter_m, seen.exact_fraction),
                at_double_pixel,
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scan::{characterise, tests::sec3_wall, ScanField};

    /// The Sec. 3 wall (h = 1 µm, c_Lx = 32.4 µm, c_Lz = 10.8 µm, 8 nodes per c_Lz) on
    /// `nodes²` nodes, read every `every`-th node, as a characterised scan; `spike` (m) is
    /// added to its middle node.
    fn wall(nodes: usize, every: usize, spike: f64) -> Characterisation {
        let g = sec3_wall(nodes, 11);
        let (nx, ny) = (g.nx.div_ceil(every), g.nz.div_ceil(every));
        let mut h: Vec<f64> = (0..ny)
            .flat_map(|iy| (0..nx).map(move |ix| (ix, iy)))
            .map(|(ix, iy)| g.heights[iy * every * g.nx + ix * every])
            .collect();
        h[ny / 2 * nx + nx / 2] += spike;
        let f = ScanField::new(nx, ny, g.dx * every as f64, g.dz * every as f64, h).unwrap();
        characterise(f, 1).unwrap()
    }

    #[test]
    fn the_finite_difference_ratio_and_the_standard_error_are_the_gaussian_walls() {
        // docs/physics.md §4: 0.985 at δ = c_L/4.
        assert!((finite_difference_ratio(0.25) - 0.984576).abs() < 1e-6);
        assert!((finite_difference_ratio(0.5) - 0.940636).abs() < 1e-6);
        assert_eq!(finite_difference_ratio(0.0), 1.0);
        assert!((relative_error_per_sqrt_area() - 0.767495).abs() < 1e-6);
        assert!((footprint(100e-6, 1e-6) - 1e-5).abs() < 1e-20);
    }

    /// Deviations fall with the diameter; the point particle on a 21 × 64 c_L wall at 8
    /// nodes per c_Lz is served, and a sphere wider than the scan is too small for it, with
    /// nothing exact.
    #[test]
    fn deviations_fall_with_the_diameter_and_a_too_wide_sphere_is_too_small() {
        let c = wall(512, 1, 0.0);
        let seen = seen_by(&c, &[200e-6, 1e-3, 4e-3, 1.0]).unwrap();
        assert_eq!(seen.len(), 5);
        for pick in [|l: &Lay| l.delta_xi, |l: &Lay| l.delta_zeta] {
            let d: Vec<f64> = seen[..4]
                .iter()
                .map(|s| pick(&s.seen.lay.unwrap()))
                .collect();
            assert!(d.windows(2).all(|w| w[1] < w[0]), "{d:?}");
        }
        let point = seen[0].resolution;
        assert!(!point.too_small(), "{point:?}");
        assert_eq!((point.exact_fraction, point.footprint_m), (1.0, 0.0));
        assert_eq!(point.sampling_m, point.correlation_m);
        let wide = seen[4];
        assert_eq!((wide.seen.lay, wide.seen.exact_fraction), (None, 0.0));
        assert!(wide.resolution.too_small() && wide.resolution.correlation_areas == 0.0);
        assert!(wide.resolution.relative_error().is_infinite());
    }

    /// Each trigger of "too small": too few correlation areas with the scan all exact (a
    /// point on a wall of 3 × 10 correlation lengths), and too little of the scan exact
    /// with enough areas (a 250 µm spike on the 512² wall makes the reach of a 50 µm sphere
    /// 112 µm, a sixth of the side).
    #[test]
    fn too_small_is_too_few_correlation_areas_or_too_little_exact() {
        let small = wall(80, 1, 0.0);
        let s = seen_by(&small, &[]).unwrap()[0].resolution;
        assert_eq!(s.exact_fraction, 1.0);
        assert!(s.correlation_areas < MIN_CORRELATION_AREAS, "{s:?}");
        assert!(s.too_small());
        // se(Δ)/Δ of the estimate ≈ 0.77/√N: above 5 %.
        assert!(s.relative_error() > 0.05);
        let spiked = wall(512, 1, 250e-6);
        let s = seen_by(&spiked, &[50e-6]).unwrap()[1];
        let r = s.resolution;
        assert!(r.exact_fraction < MIN_EXACT_FRACTION, "{r:?}");
        assert!(r.correlation_areas > MIN_CORRELATION_AREAS, "{r:?}");
        assert!(r.too_small());
        assert!(s.seen.reach[0] > 80, "{s:?}");
    }

    /// The measured resolution check: on the Gaussian Sec. 3 wall at 8 nodes per c_Lz the
    /// point's Δζ changes at twice the pixel as the finite-difference formula says (−1.0 %
    /// measured, −1.2 % predicted), under the 5 % bound; read every 4th node (2 per c_Lz),
    /// doubling the pixel again takes Δζ down by −15.8 % (predicted −15.5 %):
    /// resolution-limited, and so is a 500 µm sphere there.
    #[test]
    fn the_resolution_check_is_the_change_at_twice_the_pixel() {
        let d = 500e-6;
        let fine = seen_by(&wall(512, 1, 0.0), &[d]).unwrap();
        let coarse = seen_by(&wall(512, 4, 0.0), &[d]).unwrap();
        let [xi, zeta] = fine[0].resolution_change().unwrap();
        let expect = finite_difference_ratio(0.25) / finite_difference_ratio(0.125) - 1.0;
        assert!((zeta - expect).abs() < 0.02, "{zeta} vs {expect}");
        assert!(xi.abs() < zeta.abs(), "{xi} {zeta}");
        assert!(
            !fine[0].resolution_limited(),
            "{:?}",
            fine[0].resolution_change()
        );
        let [_, zeta4] = coarse[0].resolution_change().unwrap();
        let expect4 = finite_difference_ratio(1.0) / finite_difference_ratio(0.5) - 1.0;
        assert!((zeta4 - expect4).abs() < 0.04, "{zeta4} vs {expect4}");
        assert!(coarse[0].resolution_limited());
        // The 500 µm sphere: −2.2 % at 8 pixels per c_Lz (more than the point's −1.0 %: it
        // rests on summits the pixel must resolve), −8.4 % at 2 (less than the point's).
        assert!(
            !fine[1].resolution_limited(),
            "{:?}",
            fine[1].resolution_change()
        );
        assert!(
            coarse[1].resolution_limited(),
            "{:?}",
            coarse[1].resolution_change()
        );
        // Twice the pixel of a 5 × 5 scan is too small to measure: no change, not limited.
        let tiny = ScanField::new(
            4,
            4,
            1e-6,
            1e-6,
            (0..16).map(|i| 1e-7 * (i % 3) as f64).collect(),
        )
        .unwrap();
        assert!(decimated(&tiny).is_none());
    }
}
