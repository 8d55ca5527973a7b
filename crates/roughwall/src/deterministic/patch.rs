//! A measured scan as a patch of a wall (issue 39, part 1): its extent, the frame turned by
//! its lay, and the margins of the region particles enter over ([`super::in_place`] says
//! why; Radenkovic & Simonin 2021, Sec. 3.1, on a non-periodic wall).

use nalgebra::{Rotation3, Vector3};

/// The margins in flights of the incident descent, `Δh cot α⁻` (at least `Δh`, a flight at
/// 45°), on every side and again downstream ([`Patch::margins`]). Measured on a generated
/// (5°, 5°) Gaussian wall of 1292 × 1292 height units and `Δh` = 7.8 (40 000 histories a
/// condition, β⁻ = 30°): with 1 (one flight), up to 1.3 · 10⁻³ of the histories left the patch
/// (α⁻ = −10°); with 3, at most 2.5 · 10⁻⁴ (α⁻ = −5° … −80°), inside [`LEFT_PATCH_BOUND`].
pub const MARGIN_FLIGHTS: f64 = 3.0;

/// Largest share of a side the margins may take together: the inner region keeps at least
/// 20 % of each side, and what the margins then miss shows as histories that left the patch.
pub const MAX_MARGIN_SHARE: f64 = 0.8;

/// Share of histories leaving the patch above which a run warns: the reference then
/// excludes flights long enough to reach an edge (grazing rebounds) more than it should.
pub const LEFT_PATCH_BOUND: f64 = 1e-3;

/// A scan as a non-periodic patch of a wall, in the models' frame turned by its lay.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Patch {
    /// Extent of the scan's cells along the tracker's `x` and `z` (m): `(n − 1)` spacings.
    pub extent: (f64, f64),
    /// Height range `Δh` of the patch (m): the deepest descent from the entry height.
    pub height_range: f64,
    /// Lay angle `φ` (rad): the models' `x` is the scan's `x` turned by `φ` towards its `y`.
    pub lay_angle: f64,
    /// `Some(α_e)`: one entry region for every direction, the margins of `|α⁻| = α_e` on
    /// every side ([`Patch::with_entry_alpha`]); `None`: margins that follow each direction.
    pub entry_alpha: Option<f64>,
    rotation: Rotation3<f64>,
}

/// The entry region's margins for one incident direction (m, in the tracker's axes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Margins {
    /// Margins at low `x`, high `x`, low `z`, high `z`.
    pub sides: [f64; 4],
    /// Whether [`MAX_MARGIN_SHARE`] cut them.
    pub clamped: bool,
}

impl Patch {
    /// The patch of a field of `nx × nz` nodes of spacings `dx`, `dz` with height range
    /// `height_range`, whose lay is at `lay_angle`.
    pub fn new(nx: usize, nz: usize, dx: f64, dz: f64, height_range: f64, lay_angle: f64) -> Self {
        Patch {
            extent: ((nx.max(1) - 1) as f64 * dx, (nz.max(1) - 1) as f64 * dz),
            height_range,
            lay_angle,
            entry_alpha: None,
            rotation: Rotation3::from_axis_angle(&Vector3::y_axis(), lay_angle),
        }
    }

    /// The same patch with one entry region for every incident direction (`Some(α_e)`, rad):
    /// every side keeps the largest margin any direction at `|α⁻| = α_e` asks of it (its own
    /// and the downstream share, [`Patch::margins`]), cut to [`MAX_MARGIN_SHARE`] of the side
    /// in equal parts. Why: where the region follows the direction it slides across the scan
    /// as `β⁻` turns and grows as `α⁻` steepens, so on a scan whose parts differ the law at
    /// neighbouring directions differs by the part it was sampled on as well as by the physics
    /// (0.6–0.9° in mean `α⁺` on a 3.9 mm metal scan at `α⁻ = −9°`; docs/design-notes.md). With
    /// one region, two directions sample the same part of the wall; directions flatter than
    /// `α_e` may then lose more histories off the scan, which are counted as always.
    pub fn with_entry_alpha(mut self, entry_alpha: Option<f64>) -> Self {
        self.entry_alpha = entry_alpha;
        self
    }

    /// A vector of the models' frame (`x` along the lay) in the tracker's axes: `R_y(φ)`,
    /// which takes the models' `x` to the lay `(cos φ, 0, −sin φ)`, the direction of
    /// `β = φ` (`β = atan2(−w, u)`, Radenkovic & Simonin 2021, Sec. 3.1).
    #[inline]
    pub fn to_field(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.rotation * v
    }

    /// A vector of the tracker's axes in the models' frame (the inverse of [`Self::to_field`]).
    #[inline]
    pub fn to_models(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.rotation.inverse_transform_vector(v)
    }

    /// The margins of the entry region for incident angle `alpha_in` (rad, either sign) and
    /// the incident velocity `u` in the tracker's axes. The incident flight descends at most
    /// `Δh` from the entry height, over `Δh cot α⁻` horizontally, downstream; a rebound
    /// escapes over `Δh_local cot α⁺`, a tail that falls only as `1/m` with the distance `m`
    /// (grazing rebounds). So every side keeps [`MARGIN_FLIGHTS`]` · Δh · max(1, cot α⁻)`,
    /// and the downstream sides as much again, shared by the components of the horizontal
    /// direction. Together they take at most [`MAX_MARGIN_SHARE`] of a side.
    /// With one entry region ([`Patch::with_entry_alpha`]) the margins are those of its
    /// angle on every side, whatever `alpha_in` and `u`.
    pub fn margins(&self, alpha_in: f64, u: &Vector3<f64>) -> Margins {
        // α⁻ < 0 for an incident particle (docs/physics.md §1): its size is what counts.
        let alpha_in = self.entry_alpha.unwrap_or(alpha_in);
        let tan = alpha_in.abs().tan();
        let cot = if tan > 0.0 { 1.0 / tan } else { f64::INFINITY };
        // A flat patch needs no margin (and Δh · ∞ would be NaN at α⁻ = 0).
        let flights = |c: f64| {
            if self.height_range > 0.0 {
                MARGIN_FLIGHTS * self.height_range * c
            } else {
                0.0
            }
        };
        let (base, extra) = (flights(cot.max(1.0)), flights(cot));
        let h = (u.x * u.x + u.z * u.z).sqrt();
        let (cx, cz) = if h > 0.0 {
            (u.x / h, u.z / h)
        } else {
            (0.0, 0.0)
        };
        let mut sides = match self.entry_alpha {
            // Downstream may be any side: each keeps the whole downstream share.
            Some(_) => [base + extra; 4],
            None => [
                base + extra * (-cx).max(0.0),
                base + extra * cx.max(0.0),
                base + extra * (-cz).max(0.0),
                base + extra * cz.max(0.0),
            ],
        };
        let mut clamped = false;
        for (k, extent) in [self.extent.0, self.extent.1].into_iter().enumerate() {
            let (lo, hi) = (sides[2 * k], sides[2 * k + 1]);
            let total = lo + hi;
            let cap = MAX_MARGIN_SHARE * extent;
            if total > cap {
                clamped = true;
                // Kept in proportion; an infinite margin (α⁻ = 0) takes the whole cap.
                let share = if lo.is_finite() && hi.is_finite() && total > 0.0 {
                    lo / total
                } else if lo.is_infinite() && hi.is_infinite() {
                    0.5
                } else if lo.is_infinite() {
                    1.0
                } else {
                    0.0
                };
                sides[2 * k] = cap * share;
                sides[2 * k + 1] = cap * (1.0 - share);
            }
        }
        Margins { sides, clamped }
    }

    /// The entry point `(x, z)` of the uniform numbers `a`, `b` in `[0, 1)` over the inner
    /// region for incident angle `alpha_in` and velocity `u` (tracker's axes).
    #[inline]
    pub fn start(&self, alpha_in: f64, u: &Vector3<f64>, a: f64, b: f64) -> (f64, f64) {
        self.start_in(&self.margins(alpha_in, u), a, b)
    }

    /// [`Self::start`] in the region of margins `margins`.
    #[inline]
    pub fn start_in(&self, margins: &Margins, a: f64, b: f64) -> (f64, f64) {
        let m = margins.sides;
        let x = m[0] + a * (self.extent.0 - m[0] - m[1]);
        let z = m[2] + b * (self.extent.1 - m[2] - m[3]);
        (x, z)
    }

    /// Whether the cell `(ix, iz)` (unwrapped) is one of the scan's.
    #[inline]
    pub(crate) fn holds_cell(&self, ix: i64, iz: i64, nx: usize, nz: usize) -> bool {
        ix >= 0 && iz >= 0 && ix < nx as i64 - 1 && iz < nz as i64 - 1
    }

    /// Whether the point `(x, z)` (tracker's axes) lies on the patch.
    #[inline]
    pub(crate) fn holds_point(&self, x: f64, z: f64) -> bool {
        (0.0..=self.extent.0).contains(&x) && (0.0..=self.extent.1).contains(&z)
    }
}
