//! The deterministic reference on a measured scan itself (issue 39, part 1): the particle
//! centre bounces on the scan's own triangles, at its own pixel, with no resampling and no
//! mirroring (Radenkovic & Simonin 2021, Sec. 3.1, on a measured wall; docs/models.md,
//! "Measured walls").
//!
//! A scan is a patch: not periodic, and in general not aligned with its lay. Instead of
//! turning the wall to its lay (which resamples it), the incident direction is turned: the
//! models' frame (`x` along the lay, `β⁻` measured from it) is the scan's frame turned by the
//! lay angle `φ` about the wall normal, `R_y(φ)` ([`super::Patch::to_field`]). Particles enter at
//! the highest node over an inner region of the patch whose margins follow from the height
//! range `Δh` and `α⁻` ([`super::Patch::margins`]); a history whose flight leaves the patch below
//! the highest node has no measured wall to meet and is counted as
//! [`LostReason::LeftPatch`](super::LostReason::LeftPatch).
//!
//! The tracker walks the patch as if it were periodic (so it keeps its coarse tile map), and
//! [`super::Patch`] decides what is off it: a hit in a cell outside the scan's `(nx − 1) × (nz − 1)`
//! cells (the seam cells that close the period are not the scan's), or an escape point
//! outside the patch. A flight is a straight segment and the patch is convex, so a segment
//! between two points on it stays on it.

use crate::error::{Error, Result};
use crate::scan::{centre_surface, ScanField};
use crate::surface::{HeightField, Triangulation};

/// What a measured scan becomes for `deterministic` (`[deterministic] scan_wall`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ScanReference {
    /// The scan itself, in place ([`in_place_wall`], [`crate::Tracker::in_place`]): the
    /// reference.
    #[default]
    InPlace,
    /// Turned to its lay, resampled, cropped and mirror-tiled into a periodic wall
    /// ([`crate::scan::mirrored_wall`]): the earlier reference, kept to measure what it cost.
    Mirrored,
}

impl ScanReference {
    /// The names the case key accepts, in the order of the variants.
    pub const NAMES: [&'static str; 2] = ["in-place", "mirrored"];

    /// The case-file name.
    pub fn name(self) -> &'static str {
        match self {
            ScanReference::InPlace => Self::NAMES[0],
            ScanReference::Mirrored => Self::NAMES[1],
        }
    }

    /// The variant of a case-file name.
    pub fn from_name(name: &str) -> Option<Self> {
        [ScanReference::InPlace, ScanReference::Mirrored]
            .into_iter()
            .find(|r| r.name() == name)
    }
}

/// A measured scan made ready for the in-place reference ([`in_place_wall`]).
#[derive(Clone, Debug)]
pub struct InPlaceWall {
    /// The scan (or, for a sphere, its centre surface) on its own grid, in the tracker's axes:
    /// `x` the scan's `x`, `z` its `−y` (rows reversed), cropped as [`Self::crop`] says.
    pub field: HeightField,
    /// The lay angle the incident directions are turned by (rad).
    pub lay_angle: f64,
    /// The scan's points used: first column and row, and counts along `x` and `y`.
    pub crop: [usize; 4],
    /// For a sphere: the diameter (m) whose centre surface this is.
    pub diameter_m: Option<f64>,
    /// Share of the scan's points the wall keeps.
    pub area_fraction: f64,
    /// For a sphere: the share of the scan's points a resting sphere touches (among those
    /// the wall keeps).
    pub contact_fraction: Option<f64>,
    /// The deviations of this wall's own triangles along and across the lay (for a sphere,
    /// those of its centre surface): what the particles met.
    pub deviations: Option<crate::scan::Lay>,
    /// `Some(α_e)` (rad): one entry region for every direction, that of `|α⁻| = α_e`
    /// ([`crate::deterministic::Patch::with_entry_alpha`]); `None` (what [`in_place_wall`]
    /// gives): margins that follow each direction.
    pub entry_alpha: Option<f64>,
}

impl InPlaceWall {
    /// The tracker that walks this wall in place, its incident directions turned by the lay.
    pub fn tracker(&self) -> Result<super::Tracker<'_>> {
        Ok(
            super::Tracker::in_place(&self.field, super::DEFAULT_MAX_COLLISIONS, self.lay_angle)?
                .with_entry_alpha(self.entry_alpha),
        )
    }

    /// The deviations the particles meet: this wall's own, or `lay`'s (the whole scan's)
    /// where it has none.
    pub fn met_deviations(&self, lay: &crate::scan::Lay) -> crate::wall::Deviations {
        let own = self.deviations.as_ref().unwrap_or(lay);
        crate::wall::Deviations {
            delta_xi: own.delta_xi,
            delta_zeta: own.delta_zeta,
        }
    }
}

/// Side of the coarse tile map of the tracker, in cells: a crop to a multiple of it keeps
/// the map (`deterministic::trace`).
const TILE_MULTIPLE: usize = 8;

/// The scan `f` (levelled) as the in-place reference's wall for a particle centre
/// (`diameter_m = None`) or a sphere of that diameter, whose centre rides on the scan's
/// centre surface (the paraboloid dilation of [`crate::scan::centre_surface`]).
///
/// Nothing is resampled: the wall is the largest rectangle of the scan's own nodes on which
/// the surface is known everywhere (for a sphere, exact: the edges lose the dilation's reach;
/// a scan with missing points inside gives the largest complete rectangle between them), cut
/// to a multiple of 8 nodes along each axis (at most 7 rows and columns) so that the tracker
/// keeps its tile map.
pub fn in_place_wall(
    f: &ScanField,
    lay_angle: f64,
    diameter_m: Option<f64>,
    triangulation: Triangulation,
) -> Result<InPlaceWall> {
    crate::memory::require(
        "--surface",
        format!("{} × {} points", f.nx, f.ny),
        (f.nx as u64)
            .saturating_mul(f.ny as u64)
            .saturating_mul(8 * if diameter_m.is_some() { 4 } else { 1 }),
        "the in-place wall of the scan",
    )?;
    let (surface, contact_fraction) = match diameter_m {
        Some(d) => {
            let c = centre_surface::centre_surface(f, d);
            let touched = centre_surface::contact_fraction(f, &c);
            (c.field, Some(touched))
        }
        None => (f.clone(), None),
    };
    let [x0, y0, nx, ny] = known_block(&surface);
    let what = match diameter_m {
        Some(d) => format!(
            "the centre surface of a {} µm sphere",
            crate::format::fmt_num(d * 1e6)
        ),
        None => "the scan".to_string(),
    };
    if nx < 3 || ny < 3 {
        return Err(Error::Input(format!(
            "{what} is known on a block of {nx} × {ny} points of the {} × {} scan: the in-place reference needs at least 3 × 3",
            f.nx, f.ny
        )));
    }
    let cut = |n: usize| {
        if n >= 2 * TILE_MULTIPLE {
            n - n % TILE_MULTIPLE
        } else {
            n
        }
    };
    let (nx, ny) = (cut(nx), cut(ny));
    // The block in the scan's own axes, for its deviations along the lay.
    let mut block = Vec::with_capacity(nx * ny);
    for iy in y0..y0 + ny {
        block.extend_from_slice(&surface.heights[iy * surface.nx + x0..iy * surface.nx + x0 + nx]);
    }
    drop(surface);
    let missing = block.iter().filter(|h| !h.is_finite()).count();
    if missing > 0 {
        return Err(Error::Internal(format!(
            "{what}: {missing} missing points inside the complete block {nx} × {ny}"
        )));
    }
    let block = ScanField {
        nx,
        ny,
        dx: f.dx,
        dy: f.dy,
        heights: block,
    };
    let deviations = crate::scan::lay_at(&block, lay_angle);
    // The tracker's z is the scan's −y: its first row is the scan's last.
    let mut heights = block.heights;
    let mut rows = heights.chunks_exact_mut(nx);
    while let (Some(a), Some(b)) = (rows.next(), rows.next_back()) {
        a.swap_with_slice(b);
    }
    let field = HeightField {
        nx,
        nz: ny,
        dx: f.dx,
        dz: f.dy,
        heights,
        triangulation,
    };
    Ok(InPlaceWall {
        field,
        lay_angle,
        crop: [x0, y0, nx, ny],
        diameter_m,
        area_fraction: (nx * ny) as f64 / (f.nx * f.ny) as f64,
        contact_fraction,
        deviations,
        entry_alpha: None,
    })
}

/// The largest block `[x0, y0, nx, ny]` of `f` whose every point is known (for a centre
/// surface, outside the band the dilation cannot know): the largest rectangle under the
/// histogram of known runs, row by row (the classic stack method, `O(nx · ny)`). A scan whose
/// known points form one rectangle (missing rows and columns only at its edges) gives that
/// rectangle; a scan with holes inside, the largest complete rectangle between them (the first
/// in row order among equals).
fn known_block(f: &ScanField) -> [usize; 4] {
    let mut run = vec![0usize; f.nx];
    let mut best = ([0usize; 4], 0usize);
    let mut stack: Vec<(usize, usize)> = Vec::with_capacity(f.nx + 1);
    for iy in 0..f.ny {
        let row = &f.heights[iy * f.nx..(iy + 1) * f.nx];
        for (r, h) in run.iter_mut().zip(row) {
            *r = if h.is_finite() { *r + 1 } else { 0 };
        }
        // Largest rectangle under the histogram `run`, bottom edge on row `iy`.
        stack.clear();
        // A zero past the end closes every run still open.
        for (ix, height) in run.iter().copied().chain(std::iter::once(0)).enumerate() {
            let mut start = ix;
            while let Some(&(s0, h0)) = stack.last() {
                if h0 < height {
                    break;
                }
                stack.pop();
                let area = h0 * (ix - s0);
                if area > best.1 {
                    best = ([s0, iy + 1 - h0, ix - s0, h0], area);
                }
                start = s0;
            }
            stack.push((start, height));
        }
    }
    best.0
}
