//! A measured wall: a profilometer, confocal or AFM scan, levelled and characterised in the
//! terms the models use (issue 29, "your own wall").
//!
//! Unlike a generated surface ([`crate::surface::HeightField`]) a scan is not periodic and may miss
//! points (masked or unmeasured: NaN here). Every statistic is taken over the valid points,
//! or over the triangles and differences whose nodes are all valid, and partial sums are
//! formed row by row and added in row order, so the results do not depend on the thread
//! count.
//!
//! * `levelling`: least-squares polynomial form removal (plane and up to cubic).
//! * `parameters`: ISO 25178-2 height and gradient parameters (Sq, Ssk, Sku, Sdq).
//! * `lay`: the lay direction and the normal-angle deviations along and across it, the
//!   `Δξ`, `Δζ` of Radenkovic & Simonin 2021 (Eq. 15) measured on the scan's triangles.
//! * `lay_uncertainty`: how well the scan fixes its lay, and whether its anisotropy is
//!   significant (sub-patches as clusters).
//! * `correlation`: the autocorrelation along and across the lay, and the correlation
//!   lengths.
//! * `periodic`: the scan turned to its lay, cropped and mirror-tiled into a periodic wall
//!   the deterministic model bounces on.
//! * `centre_surface`: the surface a sphere's centre rides on, for the deviations a
//!   particle of each diameter sees.
//! * `resolution`: whether the scan is large and fine enough for those deviations.
//! * [`correlation_map`]: the areal autocorrelation over a window of lags.
//! * [`notes`]: the wall card's notes, in words: where the wall or the scan falls outside
//!   what the models assume or what the deviations need.

pub(crate) mod centre_surface;
pub(crate) mod correlation;
pub(crate) mod correlation_map;
pub(crate) mod lay;
pub(crate) mod lay_uncertainty;
pub(crate) mod levelling;
pub(crate) mod notes;
pub(crate) mod parameters;
pub(crate) mod periodic;
pub(crate) mod quantization;
pub(crate) mod resolution;

pub use centre_surface::{
    centre_surface, centre_surface_bytes, contact_fraction, CentreSurface, SeenDeviations,
};
pub use correlation::Correlation;
pub use correlation_map::{correlation_map, map_bytes, CorrelationMap};
pub use lay::{angle_histograms, lay_angle, lay_at, Lay};
pub use lay_uncertainty::{lay_uncertainty, LayUncertainty, ANISOTROPY_T, PATCHES_PER_SIDE};
pub use levelling::{level, MAX_DEGREE};
pub use notes::{criteria, labelled, missing_fraction, notes, reach_um, spread, ShapeEffect};
pub use parameters::{area_parameters, AreaParameters};
pub use periodic::{mirrored_wall, MirroredWall};
pub use quantization::height_step;
pub use resolution::{decimated, seen_by, Resolution, SeenBy, MAX_RESOLUTION_CHANGE};

use crate::error::{Error, Result};
use std::ops::Range;

/// Rows whose partial results are held at once by [`in_row_chunks`].
const ROWS_PER_CHUNK: usize = 4096;

/// Rows `0..n` a chunk of [`ROWS_PER_CHUNK`] at a time: `chunk(range)` computes the chunk's
/// per-row results (in parallel, in row order), then `each` takes them in row order before
/// the next chunk. A fold through `each` has the bits of a row-by-row fold for any thread
/// count, and the memory does not grow with the row count: a 2 × 2²⁷ strip held one result per
/// row, gigabytes, and aborted (issue 42).
pub(crate) fn in_row_chunks<T>(
    n: usize,
    chunk: impl Fn(Range<usize>) -> Vec<T>,
    mut each: impl FnMut(T),
) {
    let mut start = 0;
    while start < n {
        let end = n.min(start + ROWS_PER_CHUNK);
        chunk(start..end).into_iter().for_each(&mut each);
        start = end;
    }
}

/// Largest scan accepted (points): 2²⁸, 2 GiB of heights.
pub const MAX_POINTS: usize = 1 << 28;

/// Largest height accepted (m, either sign): 1 km. No wall's heights come near it, even
/// with an instrument's offset; beyond it lie unit mistakes and offsets (1e300 m) that leave
/// no digits for the roughness, and past ~1e75 m the fourth moments overflow (2²⁸ · h⁴ >
/// 1.8e308; issue 42).
pub const MAX_HEIGHT_M: f64 = 1e3;

/// Spacings accepted (m): from 1 pm (below any instrument's lateral resolution) to 1 m.
/// Inside these and [`MAX_HEIGHT_M`] every slope, sum and lag the characterisation forms is
/// finite.
pub const SPACING_RANGE_M: (f64, f64) = (1e-12, 1.0);

/// A measured height field in the scan's own axes: `nx × ny` points of spacings `dx`, `dy`
/// (metres), row-major with `x` fastest (`heights[iy * nx + ix]`, point `(ix, iy)` at
/// `(ix·dx, iy·dy)`), heights along the outward normal; not periodic; a NaN height is a
/// missing point. In the models' frame (docs/physics.md §1: `y` is the wall normal) the
/// scan's `x` is `x` and its `y` is `−z`, which keeps the handedness: a direction at angle
/// `φ` from the scan's `x` towards its `y` is the models' `x*` of `β* = φ`.
#[derive(Clone, Debug, PartialEq)]
pub struct ScanField {
    /// Points along `x`.
    pub nx: usize,
    /// Points along `y`.
    pub ny: usize,
    /// Spacing along `x` (m).
    pub dx: f64,
    /// Spacing along `y` (m).
    pub dy: f64,
    /// Heights (m); NaN where the instrument measured nothing.
    pub heights: Vec<f64>,
}

impl ScanField {
    /// Checks the grid: at least 2 × 2 points, at most [`MAX_POINTS`], spacings within
    /// [`SPACING_RANGE_M`], `nx · ny` heights of which at least three are valid, none beyond
    /// [`MAX_HEIGHT_M`].
    pub fn new(nx: usize, ny: usize, dx: f64, dy: f64, heights: Vec<f64>) -> Result<ScanField> {
        let points = nx.checked_mul(ny).filter(|&n| n <= MAX_POINTS);
        if nx < 2 || ny < 2 || points.is_none() {
            return Err(Error::Input(format!(
                "scan of {nx} × {ny} points: allowed 2 × 2 up to {MAX_POINTS} points"
            )));
        }
        let (lo, hi) = SPACING_RANGE_M;
        for (key, d) in [("x", dx), ("y", dy)] {
            if !(d.is_finite() && d > 0.0) {
                return Err(Error::invalid(
                    &format!("scan spacing along {key} (m)"),
                    d,
                    "a finite length > 0",
                ));
            }
            if !(lo..=hi).contains(&d) {
                return Err(Error::invalid(
                    &format!("scan spacing along {key} (m)"),
                    d,
                    &format!(
                        "{lo:e} m to {hi} m (a pixel outside this is a unit mistake in the file or its header)"
                    ),
                ));
            }
        }
        if heights.len() != nx * ny {
            return Err(Error::Input(format!(
                "scan of {nx} × {ny} points holds {} heights",
                heights.len()
            )));
        }
        if heights.iter().any(|h| h.is_infinite()) {
            return Err(Error::Input(
                "scan has an infinite height (an overflow where the file's values were converted to metres): allowed finite heights, NaN for a missing point"
                    .into(),
            ));
        }
        // NaN (missing) compares false and passes.
        if let Some(h) = heights.iter().find(|h| h.abs() > MAX_HEIGHT_M) {
            return Err(Error::Input(format!(
                "scan has a height of {h:e} m: allowed |height| ≤ {MAX_HEIGHT_M} m (a larger one is a unit mistake in the file or its header, or an offset that leaves no digits for the roughness and overflows the levelling)"
            )));
        }
        let f = ScanField {
            nx,
            ny,
            dx,
            dy,
            heights,
        };
        if f.valid_count() < 3 {
            return Err(Error::Input(format!(
                "scan of {nx} × {ny} points has {} valid points: at least 3 are needed",
                f.valid_count()
            )));
        }
        Ok(f)
    }

    /// Height at `(ix, iy)`, `None` where missing.
    #[inline]
    pub fn at(&self, ix: usize, iy: usize) -> Option<f64> {
        let h = self.heights[iy * self.nx + ix];
        (!h.is_nan()).then_some(h)
    }

    /// Points with a height.
    pub fn valid_count(&self) -> usize {
        self.heights.iter().filter(|h| !h.is_nan()).count()
    }
}

/// A scan levelled and characterised: what `rebound scan` writes and the wall card holds.
#[derive(Clone, Debug, PartialEq)]
pub struct Characterisation {
    /// The scan with its form removed.
    pub levelled: ScanField,
    /// Degree of the form removed (1: plane).
    pub degree: u32,
    /// Height and gradient parameters of the levelled scan.
    pub parameters: parameters::AreaParameters,
    /// Lay and deviations; `None` without a cell of four valid corners.
    pub lay: Option<lay::Lay>,
    /// How well the scan fixes that lay, from 4 × 4 sub-patches; `None` without a lay or
    /// when the scan is too small to cut.
    pub lay_uncertainty: Option<lay_uncertainty::LayUncertainty>,
    /// Autocorrelation along and across the lay (along the scan's `x` without a lay).
    pub correlation: correlation::Correlation,
    /// The step (m) the scan's heights were written in, as read ([`height_step`]); `None`
    /// when they are not in whole steps of one size.
    pub height_step_m: Option<f64>,
}

/// Bytes [`characterise`] needs beside the scan's own heights, which it levels in place: the
/// levelling's Legendre table (32 per column) and, per thread, the lay's row buffers (13
/// values per column); rows are summed a chunk at a time (`in_row_chunks`). Small for a
/// scan, large for a strip 10⁸ points wide.
pub fn characterisation_bytes(nx: usize) -> u64 {
    let threads = rayon::current_num_threads() as u64;
    (nx as u64).saturating_mul(32 + 13 * 8 * threads)
}

/// Levels `f` by its least-squares polynomial of total degree `degree` (1 … 3) and
/// characterises what remains (`f` becomes [`Characterisation::levelled`]: no copy of the
/// heights is made). Refused, before anything is allocated, when the process cannot hold
/// what it needs ([`characterisation_bytes`], [`crate::memory::require`]).
pub fn characterise(f: ScanField, degree: u32) -> Result<Characterisation> {
    crate::memory::require(
        "scan",
        format!("{} × {} points", f.nx, f.ny),
        characterisation_bytes(f.nx),
        "levelling it and finding its lay",
    )?;
    // Before levelling, which turns whole steps into a plane's fractions.
    let height_step_m = quantization::height_step(&f);
    let mut levelled = f;
    levelling::level_in_place(&mut levelled, degree)?;
    let parameters = parameters::area_parameters(&levelled);
    let lay = lay::lay(&levelled);
    let lay_uncertainty = lay.and_then(|l| lay_uncertainty::lay_uncertainty(&levelled, l.angle));
    let correlation = correlation::correlation(&levelled, lay.map_or(0.0, |l| l.angle));
    Ok(Characterisation {
        levelled,
        degree,
        parameters,
        lay,
        lay_uncertainty,
        correlation,
        height_step_m,
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The Sec. 3 wall (Δξ, Δζ) = (2.5°, 7.5°) with h = 1 µm (c_L = √2 h/Δ, Eq. 15) on
    /// `nodes`² nodes, 8 per c_Lz: a surface of `nodes/8` c_Lz by `nodes/24` c_Lx.
    pub(crate) fn sec3_wall(nodes: usize, seed: u64) -> crate::surface::HeightField {
        let c = |deg: f64| 2f64.sqrt() * 1e-6 / deg.to_radians();
        let spec = crate::surface::SurfaceSpec {
            length_m: nodes as f64 * c(7.5) / 8.0,
            nodes,
            rms_height_m: 1e-6,
            corr_length_x_m: Some(c(2.5)),
            corr_length_z_m: Some(c(7.5)),
        };
        crate::surface::generate(&spec, seed)
    }

    /// A plane `a + b x + c z` plus a sinusoid, with one missing point.
    pub(crate) fn tilted(nx: usize, ny: usize) -> ScanField {
        let (dx, dy) = (1e-6, 2e-6);
        let mut h = Vec::with_capacity(nx * ny);
        for iy in 0..ny {
            for ix in 0..nx {
                let (x, z) = (ix as f64 * dx, iy as f64 * dy);
                h.push(3e-6 + 0.01 * x - 0.02 * z + 1e-7 * (x / 7e-6).sin());
            }
        }
        h[nx + 1] = f64::NAN;
        ScanField::new(nx, ny, dx, dy, h).unwrap()
    }

    /// A tilted sinusoid along x: the tilt goes, the texture stays, and its grooves (along
    /// y) are the lay.
    #[test]
    fn characterise_levels_then_measures() {
        let c = characterise(tilted(200, 50), 1).unwrap();
        let p = c.parameters;
        assert!(p.mean_m.abs() < 1e-18);
        // Sinusoid of amplitude 1e-7 m less its best plane: Sq close to 1e-7/√2.
        assert!((p.sq_m / (1e-7 / 2f64.sqrt()) - 1.0).abs() < 0.05, "{p:?}");
        let lay = c.lay.unwrap();
        assert!(
            (lay.angle.abs() - std::f64::consts::FRAC_PI_2).abs() < 1e-6,
            "{lay:?}"
        );
        assert!(lay.delta_zeta > 1e3 * lay.delta_xi.max(1e-300), "{lay:?}");
    }

    /// Levelling, parameters, lay and autocorrelation of a scan with missing points give the
    /// same bits in pools of 1, 2 and 3 threads, at every levelling degree.
    #[test]
    fn characterise_gives_the_same_bits_for_any_thread_count() {
        let g = sec3_wall(160, 4);
        let mut h = g.heights.clone();
        for k in (0..h.len()).step_by(97) {
            h[k] = f64::NAN;
        }
        let f = ScanField::new(g.nx, g.nz, g.dx, g.dz, h).unwrap();
        for degree in 1..=3 {
            // Debug prints every f64 so that it reads back to the same bits.
            let run = |threads: usize| {
                let c = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap()
                    .install(|| characterise(f.clone(), degree).unwrap());
                assert!(c.lay.is_some() && c.correlation.length_across_m.is_some());
                format!("{c:?}")
            };
            let one = run(1);
            for threads in [2, 3] {
                assert!(run(threads) == one, "degree {degree}, {threads} threads");
            }
        }
    }

    #[test]
    fn bad_grids_are_refused_in_one_line() {
        let e = |r: Result<ScanField>| r.unwrap_err().to_string();
        assert!(e(ScanField::new(1, 1, 1.0, 1.0, vec![0.0])).contains("1 × 1"));
        assert!(e(ScanField::new(1 << 20, 1 << 20, 1.0, 1.0, vec![])).contains("up to"));
        assert!(e(ScanField::new(2, 2, 0.0, 1.0, vec![0.0; 4])).contains("spacing along x"));
        assert!(e(ScanField::new(2, 2, 1.0, 1.0, vec![f64::NAN; 4])).contains("0 valid"));
        assert!(e(ScanField::new(2, 2, 1.0, 1.0, vec![0.0; 3])).contains("holds 3"));
        let inf = vec![0.0, 1.0, f64::INFINITY, 0.0];
        assert!(e(ScanField::new(2, 2, 1.0, 1.0, inf)).contains("infinite"));
        // Magnitudes no wall has (issue 42): refused before they overflow the arithmetic.
        let huge = vec![0.0, 1e-6, 3e300, f64::NAN];
        assert!(e(ScanField::new(2, 2, 1e-6, 1e-6, huge)).contains("3e300 m"));
        let offset = vec![1.5e3, 1.5e3, 1.5e3, 1.5e3];
        assert!(e(ScanField::new(2, 2, 1e-6, 1e-6, offset)).contains("≤ 1000 m"));
        assert!(e(ScanField::new(2, 2, 1e-6, 5e302, vec![0.0; 4])).contains("along y"));
        assert!(e(ScanField::new(2, 2, 1e-300, 1e-6, vec![0.0; 4])).contains("along x"));
        assert!(ScanField::new(2, 2, 1.0, 1e-12, vec![0.0, 1.0, -1.0, 0.5]).is_ok());
        assert_eq!(tilted(8, 5).valid_count(), 39);
    }
}
