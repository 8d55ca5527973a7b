//! Particle-centre tracking on the triangulated periodic height field
//! (Radenkovic & Simonin 2021, Sec. 3.1; docs/physics.md §5).
//!
//! The centre flies in straight lines (no gravity, no drag). The ray is walked
//! cell by cell under its horizontal projection (a 2-D DDA with periodic wrap);
//! inside a cell it is split at the triangle diagonal, so along the ray the
//! surface is piecewise linear between *breakpoints* (cell-edge and diagonal
//! crossings). The clearance `g = y_ray − y_surface` is evaluated once at every
//! breakpoint from the edge's own two nodes, so neighbouring pieces share the
//! same value and the walk is watertight: a ray can only pass below the surface
//! through a piece where `g` falls to `≤ 0`, and that piece is the hit. A coarse
//! map of tile maxima lets the walk jump over tiles the ray passes above.

use super::patch::Patch;
use crate::error::{Error, Result};
use crate::surface::HeightField;
use nalgebra::Vector3;

/// Why a particle could not be followed to its final rebound.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LostReason {
    /// It hit the cap on collisions per particle.
    CollisionCap,
    /// Its centre was found below the lowest node (a leak through the surface).
    BelowSurface,
    /// The cell walk of one history exceeded its step budget (a near-horizontal ray).
    StepBudget,
    /// The collision law returned a zero or non-finite velocity.
    Stopped,
    /// Its flight left a measured patch (the in-place reference on a scan,
    /// [`super::in_place`]) below the entry height: no measured wall to meet there.
    LeftPatch,
}

impl LostReason {
    /// A short human-readable reason for warnings.
    pub fn describe(self) -> &'static str {
        match self {
            LostReason::CollisionCap => "hit the cap on collisions per particle",
            LostReason::BelowSurface => "centre found below the surface",
            LostReason::StepBudget => "cell-walk step budget exhausted (near-horizontal flight)",
            LostReason::Stopped => "collision law returned a zero or non-finite velocity",
            LostReason::LeftPatch => "left the scan before escaping above it",
        }
    }
}

/// What became of one particle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fate {
    /// It left above the highest asperity after `History::collisions` collisions.
    Escaped,
    /// It could not be followed.
    Lost(LostReason),
}

/// The record of one particle history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct History {
    /// Whether the particle escaped above the highest asperity or was lost, and why.
    pub fate: Fate,
    /// Incident velocity.
    pub incident: Vector3<f64>,
    /// Number of collisions with the surface.
    pub collisions: u32,
    /// Unit normal of the first triangle hit (`j` if there was no collision).
    pub first_normal: Vector3<f64>,
    /// Velocity right after the first collision (the incident one if none).
    pub first_velocity: Vector3<f64>,
    /// Final velocity (after the last collision).
    pub velocity: Vector3<f64>,
    /// Final angular velocity.
    pub omega: Vector3<f64>,
}

/// One collision, as reported to an observer (tests, diagnostics).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitInfo {
    /// Hit point, wrapped into the base period of the surface.
    pub point: Vector3<f64>,
    /// Unit normal of the triangle hit.
    pub normal: Vector3<f64>,
    /// Velocity before the collision (m/s, surface frame).
    pub u_in: Vector3<f64>,
    /// Velocity after the collision (m/s, surface frame), from the collision law in the frame
    /// of [`normal`](Self::normal).
    pub u_out: Vector3<f64>,
    /// Cell hit, `(ix, iz)` wrapped into the grid (`0..nx`, `0..nz`).
    pub cell: (usize, usize),
    /// Triangle of the cell hit, 0 or 1, as numbered by
    /// [`HeightField::cell_normals`](crate::surface::HeightField::cell_normals).
    pub triangle: u8,
}

impl History {
    /// This history, traced in a patch's axes, in the models' frame
    /// ([`Patch::to_models`]).
    pub fn to_models(self, patch: &Patch) -> History {
        History {
            incident: patch.to_models(&self.incident),
            first_normal: patch.to_models(&self.first_normal),
            first_velocity: patch.to_models(&self.first_velocity),
            velocity: patch.to_models(&self.velocity),
            omega: patch.to_models(&self.omega),
            ..self
        }
    }
}

impl HitInfo {
    /// This collision, reported in a patch's axes, with its vectors in the models' frame
    /// (the point and cell stay the patch's).
    pub fn to_models(&self, patch: &Patch) -> HitInfo {
        HitInfo {
            normal: patch.to_models(&self.normal),
            u_in: patch.to_models(&self.u_in),
            u_out: patch.to_models(&self.u_out),
            ..*self
        }
    }
}

/// Default cap on collisions per particle.
pub const DEFAULT_MAX_COLLISIONS: u32 = 1000;

/// The step budget of one history: cells and tiles crossed in all. Enough for a ray
/// descending from the top of a shipped surface to its bottom at 0.001° (about 2 · 10⁵ cells,
/// 3 · 10⁴ tiles) many times over; ≈ 0.04 s of one core. A history that exhausts it is lost
/// (`LostReason::StepBudget`) and counted.
pub const MAX_STEPS: u64 = 4_000_000;

/// Side of a tile of the coarse max-height map, in cells.
const TILE: usize = 8;

/// Walk position: cell indices unwrapped (`ix`, `iz`) and wrapped (`wx`, `wz`).
#[derive(Clone, Copy, Debug)]
struct Cell {
    ix: i64,
    iz: i64,
    wx: usize,
    wz: usize,
}

/// Outcome of walking one straight segment.
enum Walk {
    Hit { t: f64, cell: Cell, tri: u8 },
    Escape,
    Lost(LostReason),
}

/// Coarse map of tile maxima (`twx × twz` cells, nodes on the tile border included).
struct Tiles {
    twx: usize,
    twz: usize,
    /// `log2` of the tile widths (widths are powers of two): floor division by a shift.
    shx: u32,
    shz: u32,
    ntx: usize,
    ntz: usize,
    /// Blocks of [`MAXIMA_BLOCK`]² tiles along `x`.
    blocks_x: usize,
    /// Each tile's highest node, in blocks of [`MAXIMA_BLOCK`]² tiles ([`Tiles::at`]).
    max: Vec<f64>,
}

/// Side of the square blocks of tiles whose maxima are stored together: a flight crosses
/// neighbouring tiles along `x` and `z` alike, and row-major maxima put the next tile along
/// `z` a row (`8 · ntx` bytes) away, a cache line and often a page of its own; an 8 × 8 block
/// is 512 contiguous bytes. Only the layout changes, not a value read.
const MAXIMA_BLOCK: usize = 8;

impl Tiles {
    /// Index of tile `(tx, tz)` (wrapped) in [`Tiles::max`].
    #[inline]
    fn at(&self, tx: usize, tz: usize) -> usize {
        ((tz / MAXIMA_BLOCK) * self.blocks_x + tx / MAXIMA_BLOCK) * MAXIMA_BLOCK * MAXIMA_BLOCK
            + (tz % MAXIMA_BLOCK) * MAXIMA_BLOCK
            + tx % MAXIMA_BLOCK
    }
}

/// The particle-centre tracker on one height field.
pub struct Tracker<'a> {
    field: &'a HeightField,
    nx: usize,
    nz: usize,
    /// Effective spacings: an axis with a single node (surface constant along it)
    /// is stretched to one long cell, which changes no triangle.
    dx: f64,
    dz: f64,
    hmin: f64,
    hmax: f64,
    /// Depth below `hmin` at which a descending centre counts as leaked.
    tol: f64,
    max_collisions: u32,
    max_steps: u64,
    tiles: Option<Tiles>,
    /// The field's cells alternate their diagonal ([`crate::surface::Triangulation`]).
    alternating: bool,
    /// A measured patch rather than a periodic wall ([`Tracker::in_place`]).
    patch: Option<Patch>,
}

impl std::fmt::Debug for Tracker<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Tracker")
            .field("nx", &self.nx)
            .field("nz", &self.nz)
            .field("hmin", &self.hmin)
            .field("hmax", &self.hmax)
            .field("tiles", &self.tiles.is_some())
            .finish()
    }
}

#[inline]
fn lerp(a: f64, b: f64, s: f64) -> f64 {
    a * (1.0 - s) + b * s
}

impl<'a> Tracker<'a> {
    /// A tracker on `field` with a cap of `max_collisions` per particle.
    ///
    /// An input error ([`Error::Input`]) when the field is empty, has non-positive
    /// spacings or non-finite heights, or `max_collisions` is 0.
    pub fn new(field: &'a HeightField, max_collisions: u32) -> Result<Self> {
        let (nx, nz) = (field.nx, field.nz);
        if nx == 0 || nz == 0 || field.heights.len() != nx * nz {
            return Err(Error::Input(format!(
                "height field of {}×{} nodes holds {} heights",
                nx,
                nz,
                field.heights.len()
            )));
        }
        if !(field.dx.is_finite() && field.dx > 0.0 && field.dz.is_finite() && field.dz > 0.0) {
            return Err(Error::Input(
                "height field spacings must be positive and finite".into(),
            ));
        }
        if field.heights.iter().any(|h| !h.is_finite()) {
            return Err(Error::Input("height field holds non-finite heights".into()));
        }
        if max_collisions == 0 {
            return Err(Error::Input("max_collisions must be at least 1".into()));
        }
        let mut dx = field.dx;
        let mut dz = field.dz;
        if nz == 1 {
            dz = dz.max(nx as f64 * dx);
        }
        if nx == 1 {
            dx = dx.max(nz as f64 * dz);
        }
        let hmax = field.max_height();
        let hmin = field.heights.iter().copied().fold(f64::INFINITY, f64::min);
        let tol = 1e-9 * ((hmax - hmin) + dx + dz);
        // Tile width per axis: TILE cells, or the whole axis when it has one node
        // (a surface constant along it); no map if an axis does not divide evenly.
        let width = |n: usize| {
            if n == 1 {
                Some(1)
            } else if n.is_multiple_of(TILE) && n >= 2 * TILE {
                Some(TILE)
            } else {
                None
            }
        };
        let tiles = match (width(nx), width(nz)) {
            (Some(twx), Some(twz)) if nx * nz >= 2 * TILE => {
                let (ntx, ntz) = (nx / twx, nz / twz);
                let mut tiles = Tiles {
                    twx,
                    twz,
                    shx: twx.trailing_zeros(),
                    shz: twz.trailing_zeros(),
                    ntx,
                    ntz,
                    blocks_x: ntx.div_ceil(MAXIMA_BLOCK),
                    max: vec![
                        f64::NEG_INFINITY;
                        ntx.div_ceil(MAXIMA_BLOCK)
                            * ntz.div_ceil(MAXIMA_BLOCK)
                            * MAXIMA_BLOCK
                            * MAXIMA_BLOCK
                    ],
                };
                for tz in 0..ntz {
                    for tx in 0..ntx {
                        let mut m = f64::NEG_INFINITY;
                        for iz in tz * twz..=(tz + 1) * twz {
                            for ix in tx * twx..=(tx + 1) * twx {
                                m = m.max(field.at(ix, iz));
                            }
                        }
                        let k = tiles.at(tx, tz);
                        tiles.max[k] = m;
                    }
                }
                Some(tiles)
            }
            _ => None,
        };
        let max_steps = MAX_STEPS;
        Ok(Tracker {
            field,
            nx,
            nz,
            dx,
            dz,
            hmin,
            hmax,
            tol,
            max_collisions,
            max_steps,
            tiles,
            alternating: field.triangulation == crate::surface::Triangulation::Alternating,
            patch: None,
        })
    }

    /// A tracker on `field` taken as a measured, non-periodic patch (the in-place reference,
    /// [`super::in_place`]): whose lay is at `lay_angle` (rad) from its `x` towards its `−z`
    /// (the scan's `y`). Histories are then shot over an inner region and counted as
    /// [`LostReason::LeftPatch`] when a flight leaves the patch; the periodic wrap only
    /// carries the walk until that is seen. At least 3 × 3 nodes.
    pub fn in_place(field: &'a HeightField, max_collisions: u32, lay_angle: f64) -> Result<Self> {
        if field.nx < 3 || field.nz < 3 {
            return Err(Error::Input(format!(
                "a patch of {} × {} nodes: the in-place reference needs at least 3 × 3",
                field.nx, field.nz
            )));
        }
        if !lay_angle.is_finite() {
            return Err(Error::Input(format!(
                "lay angle {lay_angle}: must be finite"
            )));
        }
        let mut t = Tracker::new(field, max_collisions)?;
        t.patch = Some(Patch::new(
            field.nx,
            field.nz,
            field.dx,
            field.dz,
            t.hmax - t.hmin,
            lay_angle,
        ));
        Ok(t)
    }

    /// The same tracker with one entry region for every incident direction on its patch
    /// ([`Patch::with_entry_alpha`]; nothing changes on a periodic wall).
    pub fn with_entry_alpha(mut self, entry_alpha: Option<f64>) -> Self {
        self.patch = self.patch.map(|p| p.with_entry_alpha(entry_alpha));
        self
    }

    /// The measured patch this tracker walks, if it is one ([`Tracker::in_place`]).
    pub fn patch(&self) -> Option<&Patch> {
        self.patch.as_ref()
    }

    /// The same tracker without the coarse max-height map (for tests and benches).
    pub fn without_tiles(mut self) -> Self {
        self.tiles = None;
        self
    }

    /// Whether the coarse max-height map is in use.
    pub fn has_tiles(&self) -> bool {
        self.tiles.is_some()
    }

    /// Highest node (m): the start and escape height.
    pub fn top(&self) -> f64 {
        self.hmax
    }

    /// Lowest node (m).
    pub fn bottom(&self) -> f64 {
        self.hmin
    }

    /// Nodes of the height field along `x` and `z`.
    pub fn grid(&self) -> (usize, usize) {
        (self.nx, self.nz)
    }

    /// Periods of the surface along `x` and `z` (m).
    pub fn periods(&self) -> (f64, f64) {
        (self.field.length_x(), self.field.length_z())
    }

    #[inline]
    fn h(&self, wx: usize, wz: usize) -> f64 {
        self.field.heights[wz * self.nx + wx]
    }

    #[inline]
    fn next_wx(&self, wx: usize) -> usize {
        if wx + 1 == self.nx {
            0
        } else {
            wx + 1
        }
    }

    #[inline]
    fn next_wz(&self, wz: usize) -> usize {
        if wz + 1 == self.nz {
            0
        } else {
            wz + 1
        }
    }

    /// Heights `(h00, h10, h01, h11)` of a cell.
    #[inline]
    fn corners(&self, c: &Cell) -> (f64, f64, f64, f64) {
        let x1 = self.next_wx(c.wx);
        let z1 = self.next_wz(c.wz);
        (
            self.h(c.wx, c.wz),
            self.h(x1, c.wz),
            self.h(c.wx, z1),
            self.h(x1, z1),
        )
    }

    /// Whether the cell is split along the other diagonal, `(ix+1, iz)`–`(ix, iz+1)`
    /// ([`HeightField::flipped`]). Such a cell is walked in its mirror image `u = 1 − s_x`
    /// (corners `(h10, h00, h11, h01)`, `dq` of the mirrored direction), where its
    /// diagonal is `u = s_z` like every other cell's; the cell edges are not mirrored.
    #[inline]
    fn flipped(&self, c: &Cell) -> bool {
        self.alternating && (c.wx + c.wz) & 1 == 1
    }

    /// Slopes `(∂y/∂x, ∂y/∂z)` of triangle `tri` of a cell with corners `hc`
    /// (the triangulation of [`HeightField::cell_normals`]).
    #[inline]
    fn slopes(&self, hc: (f64, f64, f64, f64), tri: u8, flip: bool) -> (f64, f64) {
        let (h00, h10, h01, h11) = hc;
        match (tri, flip) {
            (0, false) => ((h10 - h00) / self.dx, (h11 - h10) / self.dz),
            (_, false) => ((h11 - h01) / self.dx, (h01 - h00) / self.dz),
            (0, true) => ((h10 - h00) / self.dx, (h01 - h00) / self.dz),
            (_, true) => ((h11 - h01) / self.dx, (h11 - h10) / self.dz),
        }
    }

    /// Height of triangle `tri` at local coordinates `(sx, sz) ∈ [0, 1]²` of the cell
    /// *as walked*: for a flipped cell `hc` are the mirrored corners and `sx` is `u`.
    #[inline]
    fn plane(hc: (f64, f64, f64, f64), tri: u8, sx: f64, sz: f64) -> f64 {
        let (h00, h10, h01, h11) = hc;
        if tri == 0 {
            h00 + (h10 - h00) * sx + (h11 - h10) * sz
        } else {
            h00 + (h11 - h01) * sx + (h01 - h00) * sz
        }
    }

    /// The corners `(h00, h10, h01, h11)` of a cell as walked (mirrored in `x` if `flip`).
    #[inline]
    fn walked_corners(hc: (f64, f64, f64, f64), flip: bool) -> (f64, f64, f64, f64) {
        if flip {
            (hc.1, hc.0, hc.3, hc.2)
        } else {
            hc
        }
    }

    /// The local `x` coordinate as walked: `u = 1 − s_x` in a flipped cell.
    #[inline]
    fn walked_x(sx: f64, flip: bool) -> f64 {
        if flip {
            1.0 - sx
        } else {
            sx
        }
    }

    /// [`Self::tri_at`] in a cell that may be flipped; `dqf` is `dq` of the mirrored
    /// direction, `d(u − s_z)/dt`.
    #[inline]
    fn tri_in(flip: bool, sx: f64, sz: f64, dq: f64, dqf: f64) -> u8 {
        Self::tri_at(Self::walked_x(sx, flip), sz, if flip { dqf } else { dq })
    }

    /// The cell holding the point `(x, z)` (any real coordinates).
    fn cell_of(&self, x: f64, z: f64) -> Cell {
        let ix = (x / self.dx).floor() as i64;
        let iz = (z / self.dz).floor() as i64;
        Cell {
            ix,
            iz,
            wx: ix.rem_euclid(self.nx as i64) as usize,
            wz: iz.rem_euclid(self.nz as i64) as usize,
        }
    }

    /// Triangle of a point with local coordinates `(sx, sz)` moving with
    /// `dq = d(sx − sz)/dt` (ties on the diagonal go to the side it moves into).
    #[inline]
    fn tri_at(sx: f64, sz: f64, dq: f64) -> u8 {
        let q = sx - sz;
        if q > 0.0 || (q == 0.0 && dq >= 0.0) {
            0
        } else {
            1
        }
    }

    /// Surface height at `(x, z)` (m), periodic, with the tracker's triangulation.
    pub fn surface_height(&self, x: f64, z: f64) -> f64 {
        let c = self.cell_of(x, z);
        let sx = (x / self.dx - c.ix as f64).clamp(0.0, 1.0);
        let sz = (z / self.dz - c.iz as f64).clamp(0.0, 1.0);
        let flip = self.flipped(&c);
        let sv = Self::walked_x(sx, flip);
        Self::plane(
            Self::walked_corners(self.corners(&c), flip),
            Self::tri_at(sv, sz, 0.0),
            sv,
            sz,
        )
    }

    /// Follows one particle whose centre starts at `(x0, top, z0)` with velocity
    /// `u` and spin `omega`; `collide(u, omega, n)` is the collision law in the
    /// frame of the unit normal `n` (precondition `u·n < 0`).
    pub fn trace<C>(
        &self,
        x0: f64,
        z0: f64,
        u: Vector3<f64>,
        omega: Vector3<f64>,
        collide: C,
    ) -> History
    where
        C: FnMut(Vector3<f64>, Vector3<f64>, Vector3<f64>) -> (Vector3<f64>, Vector3<f64>),
    {
        self.trace_observed(x0, z0, u, omega, collide, |_| {})
    }

    /// [`Tracker::trace`] reporting every collision to `observe`.
    pub fn trace_observed<C, O>(
        &self,
        x0: f64,
        z0: f64,
        u: Vector3<f64>,
        omega: Vector3<f64>,
        mut collide: C,
        mut observe: O,
    ) -> History
    where
        C: FnMut(Vector3<f64>, Vector3<f64>, Vector3<f64>) -> (Vector3<f64>, Vector3<f64>),
        O: FnMut(&HitInfo),
    {
        let mut hist = History {
            fate: Fate::Escaped,
            incident: u,
            collisions: 0,
            first_normal: Vector3::y(),
            first_velocity: u,
            velocity: u,
            omega,
        };
        let (lx, lz) = (self.nx as f64 * self.dx, self.nz as f64 * self.dz);
        let mut o = Vector3::new(x0.rem_euclid(lx), self.hmax, z0.rem_euclid(lz));
        if !o.x.is_finite() || !o.z.is_finite() {
            o.x = 0.0;
            o.z = 0.0;
        }
        let mut d = u;
        let mut w = omega;
        let mut cell = self.cell_of(o.x, o.z);
        let mut exclude: Option<(i64, i64, u8)> = None;
        let mut steps: u64 = 0;
        loop {
            if !(d.x.is_finite() && d.y.is_finite() && d.z.is_finite()) || d == Vector3::zeros() {
                hist.fate = Fate::Lost(LostReason::Stopped);
                break;
            }
            // Local coordinates of the origin and its triangle.
            let sx = (o.x / self.dx - cell.ix as f64).clamp(0.0, 1.0);
            let sz = (o.z / self.dz - cell.iz as f64).clamp(0.0, 1.0);
            let dq = d.x / self.dx - d.z / self.dz;
            let dqf = -d.x / self.dx - d.z / self.dz;
            let tri = match exclude {
                Some((_, _, k)) => k,
                None => Self::tri_in(self.flipped(&cell), sx, sz, dq, dqf),
            };
            // On the surface after a hit; at the start the clearance is computed by
            // the walk only if the first tile is not skipped (saves a cache miss).
            let g0 = match exclude {
                Some(_) => 0.0,
                None => f64::NAN,
            };
            match self.walk(&o, &d, cell, tri, g0, exclude, &mut steps) {
                Walk::Escape => {
                    hist.fate = if hist.collisions == 0 {
                        Fate::Lost(LostReason::BelowSurface)
                    } else if self.escapes_off_patch(&o, &d) {
                        Fate::Lost(LostReason::LeftPatch)
                    } else {
                        Fate::Escaped
                    };
                    break;
                }
                Walk::Lost(r) => {
                    hist.fate = Fate::Lost(r);
                    break;
                }
                Walk::Hit {
                    t,
                    cell: hc,
                    tri: k,
                } => {
                    if let Some(patch) = &self.patch {
                        if !patch.holds_cell(hc.ix, hc.iz, self.nx, self.nz) {
                            hist.fate = Fate::Lost(LostReason::LeftPatch);
                            break;
                        }
                    }
                    if hist.collisions >= self.max_collisions {
                        hist.fate = Fate::Lost(LostReason::CollisionCap);
                        break;
                    }
                    let mut p = o + d * t;
                    let mut c = hc;
                    // Re-wrap into the base period to keep coordinates small.
                    let sxp = c.ix.div_euclid(self.nx as i64);
                    let szp = c.iz.div_euclid(self.nz as i64);
                    if sxp != 0 {
                        c.ix -= sxp * self.nx as i64;
                        p.x -= sxp as f64 * lx;
                    }
                    if szp != 0 {
                        c.iz -= szp * self.nz as i64;
                        p.z -= szp as f64 * lz;
                    }
                    let (a, b) = self.slopes(self.corners(&c), k, self.flipped(&c));
                    let n = Vector3::new(-a, 1.0, -b).normalize();
                    let (d_new, w_new) = collide(d, w, n);
                    observe(&HitInfo {
                        point: p,
                        normal: n,
                        u_in: d,
                        u_out: d_new,
                        cell: (c.wx, c.wz),
                        triangle: k,
                    });
                    hist.collisions += 1;
                    if hist.collisions == 1 {
                        hist.first_normal = n;
                        hist.first_velocity = d_new;
                    }
                    d = d_new;
                    w = w_new;
                    o = p;
                    cell = c;
                    exclude = Some((c.ix, c.iz, k));
                }
            }
        }
        hist.velocity = d;
        hist.omega = w;
        hist
    }

    /// On a patch: whether the flight from `o` (on the patch) along `d` (rising) reaches the
    /// entry height off the patch. The flight is straight and the patch convex, so it stayed
    /// on the patch if its end did.
    #[inline]
    fn escapes_off_patch(&self, o: &Vector3<f64>, d: &Vector3<f64>) -> bool {
        let Some(patch) = &self.patch else {
            return false;
        };
        if d.y <= 0.0 {
            return false;
        }
        let t = ((self.hmax - o.y) / d.y).max(0.0);
        !patch.holds_point(o.x + d.x * t, o.z + d.z * t)
    }

    /// Walks the straight segment `o + d t`, `t ≥ 0`, starting in `cell`,
    /// triangle `tri`, with clearance `g0` at `t = 0` (NaN: not known yet). Triangle `exclude` (the one
    /// just left) cannot be hit.
    #[allow(clippy::too_many_arguments)]
    fn walk(
        &self,
        o: &Vector3<f64>,
        d: &Vector3<f64>,
        mut cell: Cell,
        mut tri: u8,
        g0: f64,
        exclude: Option<(i64, i64, u8)>,
        steps: &mut u64,
    ) -> Walk {
        let (dx, dz) = (self.dx, self.dz);
        let inv_ux = 1.0 / d.x;
        let inv_uz = 1.0 / d.z;
        let sgx: i64 = if d.x > 0.0 { 1 } else { -1 };
        let sgz: i64 = if d.z > 0.0 { 1 } else { -1 };
        let dq = d.x / dx - d.z / dz;
        let dqf = -d.x / dx - d.z / dz;
        // Segment limit in height: escape above the top, leak below the bottom.
        let t_y = if d.y > 0.0 {
            ((self.hmax - o.y) / d.y).max(0.0)
        } else if d.y < 0.0 {
            ((self.hmin - self.tol - o.y) / d.y).max(0.0)
        } else {
            f64::INFINITY
        };
        let mut t_cur = 0.0_f64;
        let mut g_cur = g0;
        let (shx, shz) = match &self.tiles {
            Some(t) => (t.shx, t.shz),
            None => (0, 0),
        };
        let mut checked_tile = (i64::MIN, i64::MIN);
        loop {
            *steps += 1;
            if *steps > self.max_steps {
                return Walk::Lost(LostReason::StepBudget);
            }
            // Coarse skip: on entering a tile, jump over whole tiles the ray passes above.
            if let Some(tiles) = &self.tiles {
                let tile = (cell.ix >> shx, cell.iz >> shz);
                if tile == checked_tile {
                    // Already known to need the cell walk.
                } else if let Some((t_new, c_new, g_new)) =
                    match self.skip_tiles(tiles, o, d, &cell, t_cur, t_y, steps) {
                        Ok(skip) => skip,
                        Err(()) => return Walk::Lost(LostReason::StepBudget),
                    }
                {
                    t_cur = t_new;
                    cell = c_new;
                    g_cur = g_new;
                    let sx = ((o.x + d.x * t_cur) / dx - cell.ix as f64).clamp(0.0, 1.0);
                    let sz = ((o.z + d.z * t_cur) / dz - cell.iz as f64).clamp(0.0, 1.0);
                    tri = Self::tri_in(self.flipped(&cell), sx, sz, dq, dqf);
                    if t_cur >= t_y {
                        return if d.y > 0.0 {
                            Walk::Escape
                        } else {
                            Walk::Lost(LostReason::BelowSurface)
                        };
                    }
                    checked_tile = (cell.ix >> shx, cell.iz >> shz);
                } else {
                    checked_tile = tile;
                }
            }
            let hc = self.corners(&cell);
            let flip = self.flipped(&cell);
            let hv = Self::walked_corners(hc, flip);
            let dqv = if flip { dqf } else { dq };
            let x0 = cell.ix as f64 * dx;
            let z0 = cell.iz as f64 * dz;
            if g_cur.is_nan() {
                let sx = (((o.x + d.x * t_cur) - x0) / dx).clamp(0.0, 1.0);
                let sz = (((o.z + d.z * t_cur) - z0) / dz).clamp(0.0, 1.0);
                g_cur = o.y + d.y * t_cur - Self::plane(hv, tri, Self::walked_x(sx, flip), sz);
            }
            let t_x = if d.x > 0.0 {
                ((x0 + dx - o.x) * inv_ux).max(t_cur)
            } else if d.x < 0.0 {
                ((x0 - o.x) * inv_ux).max(t_cur)
            } else {
                f64::INFINITY
            };
            let t_z = if d.z > 0.0 {
                ((z0 + dz - o.z) * inv_uz).max(t_cur)
            } else if d.z < 0.0 {
                ((z0 - o.z) * inv_uz).max(t_cur)
            } else {
                f64::INFINITY
            };
            let t_exit = t_x.min(t_z).min(t_y);
            if !t_exit.is_finite() {
                return Walk::Lost(LostReason::StepBudget);
            }
            // Diagonal crossing inside the cell (as walked).
            let sx_c = ((o.x + d.x * t_cur) - x0) / dx;
            let sz_c = ((o.z + d.z * t_cur) - z0) / dz;
            let q = Self::walked_x(sx_c, flip) - sz_c;
            let t_d = if tri == 0 && dqv < 0.0 {
                t_cur + q.max(0.0) / (-dqv)
            } else if tri == 1 && dqv > 0.0 {
                t_cur + (-q).max(0.0) / dqv
            } else {
                f64::INFINITY
            };
            if t_d < t_exit {
                let sx = ((o.x + d.x * t_d) - x0) / dx;
                let sz = ((o.z + d.z * t_d) - z0) / dz;
                let s = (0.5 * (Self::walked_x(sx, flip) + sz)).clamp(0.0, 1.0);
                let g_d = o.y + d.y * t_d - lerp(hv.0, hv.3, s);
                if let Some(t) =
                    self.piece(hc, flip, &cell, tri, exclude, d, t_cur, g_cur, t_d, g_d)
                {
                    return Walk::Hit { t, cell, tri };
                }
                t_cur = t_d;
                g_cur = g_d;
                tri ^= 1;
            }
            // Clearance at the end of the piece.
            let y_exit = o.y + d.y * t_exit;
            let g_exit = if t_exit == t_y {
                let sx = (((o.x + d.x * t_exit) - x0) / dx).clamp(0.0, 1.0);
                let sz = ((o.z + d.z * t_exit) - z0) / dz;
                y_exit - Self::plane(hv, tri, Self::walked_x(sx, flip), sz.clamp(0.0, 1.0))
            } else if t_exit == t_x {
                let sz = (((o.z + d.z * t_exit) - z0) / dz).clamp(0.0, 1.0);
                if d.x > 0.0 {
                    y_exit - lerp(hc.1, hc.3, sz)
                } else {
                    y_exit - lerp(hc.0, hc.2, sz)
                }
            } else {
                let sx = (((o.x + d.x * t_exit) - x0) / dx).clamp(0.0, 1.0);
                if d.z > 0.0 {
                    y_exit - lerp(hc.2, hc.3, sx)
                } else {
                    y_exit - lerp(hc.0, hc.1, sx)
                }
            };
            if let Some(t) = self.piece(
                hc, flip, &cell, tri, exclude, d, t_cur, g_cur, t_exit, g_exit,
            ) {
                return Walk::Hit { t, cell, tri };
            }
            if t_exit == t_y {
                return if d.y > 0.0 {
                    Walk::Escape
                } else {
                    Walk::Lost(LostReason::BelowSurface)
                };
            }
            // Step into the next cell; the entry side fixes one local coordinate.
            if t_exit == t_x {
                let sz = (((o.z + d.z * t_exit) - z0) / dz).clamp(0.0, 1.0);
                self.step_x(&mut cell, sgx);
                let sx = if sgx > 0 { 0.0 } else { 1.0 };
                tri = Self::tri_in(self.flipped(&cell), sx, sz, dq, dqf);
            } else {
                let sx = (((o.x + d.x * t_exit) - x0) / dx).clamp(0.0, 1.0);
                self.step_z(&mut cell, sgz);
                let sz = if sgz > 0 { 0.0 } else { 1.0 };
                tri = Self::tri_in(self.flipped(&cell), sx, sz, dq, dqf);
            }
            t_cur = t_exit;
            g_cur = g_exit;
        }
    }

    /// Asks the processor to fetch the node rows of the tile holding `c`, which the walk is
    /// about to cross cell by cell. On a wall larger than the caches (a 4096² scan holds
    /// 128 MiB of heights) the walk waits on memory: each row of a tile is a different cache
    /// line, 8 · nx bytes from the next, and without this the walk loads them one at a time as
    /// it reaches them (docs/design-notes.md, "A faster cell walk"). Only a hint: nothing is
    /// read, so no result depends on it.
    #[inline]
    fn prefetch_tile(&self, tiles: &Tiles, c: &Cell) {
        #[cfg(target_arch = "x86_64")]
        {
            use core::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
            let x0 = (c.wx >> tiles.shx) << tiles.shx;
            let z0 = (c.wz >> tiles.shz) << tiles.shz;
            // The tile's nodes, its far border included (the last tile's wraps to the first
            // row and column: left to the walk).
            let x1 = (x0 + tiles.twx).min(self.nx - 1);
            let z1 = (z0 + tiles.twz).min(self.nz - 1);
            let h = self.field.heights.as_ptr();
            for z in z0..=z1 {
                // A row's nodes x0..=x1 (at most 9 values, 72 bytes) span one or two lines.
                for x in [x0, x1] {
                    // SAFETY: a prefetch reads nothing and cannot fault; the address lies
                    // inside `heights` (z < nz, x < nx).
                    unsafe { _mm_prefetch::<_MM_HINT_T0>(h.add(z * self.nx + x).cast()) };
                }
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (tiles, c);
    }

    #[inline]
    fn step_x(&self, c: &mut Cell, s: i64) {
        c.ix += s;
        if s > 0 {
            c.wx = self.next_wx(c.wx);
        } else {
            c.wx = if c.wx == 0 { self.nx - 1 } else { c.wx - 1 };
        }
    }

    #[inline]
    fn step_z(&self, c: &mut Cell, s: i64) {
        c.iz += s;
        if s > 0 {
            c.wz = self.next_wz(c.wz);
        } else {
            c.wz = if c.wz == 0 { self.nz - 1 } else { c.wz - 1 };
        }
    }

    /// Tests one linear piece `[t_a, t_b]` of triangle `tri`: a hit if the ray
    /// approaches the triangle's plane and its clearance falls to `≤ 0`.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn piece(
        &self,
        hc: (f64, f64, f64, f64),
        flip: bool,
        cell: &Cell,
        tri: u8,
        exclude: Option<(i64, i64, u8)>,
        d: &Vector3<f64>,
        t_a: f64,
        g_a: f64,
        t_b: f64,
        g_b: f64,
    ) -> Option<f64> {
        if g_b > 0.0 {
            return None;
        }
        if exclude == Some((cell.ix, cell.iz, tri)) {
            return None;
        }
        let (a, b) = self.slopes(hc, tri, flip);
        let dn = d.y - a * d.x - b * d.z;
        if dn >= 0.0 {
            return None;
        }
        let t = if g_a <= 0.0 {
            t_a
        } else {
            t_a + (t_b - t_a) * (g_a / (g_a - g_b))
        };
        Some(t.clamp(t_a, t_b))
    }

    /// If the ray at `t_cur` sits at the border of a tile (or anywhere inside one)
    /// and stays above that tile's maximum until it leaves it, returns the time,
    /// cell and clearance where it enters the next tile that may be hit; `None`
    /// if the current tile must be walked cell by cell. Every tile crossed counts against
    /// the history's step budget (`Err` when it is exhausted): a nearly horizontal ray may
    /// cross tiles for ever.
    #[allow(clippy::too_many_arguments)]
    fn skip_tiles(
        &self,
        tiles: &Tiles,
        o: &Vector3<f64>,
        d: &Vector3<f64>,
        cell: &Cell,
        t_cur: f64,
        t_y: f64,
        steps: &mut u64,
    ) -> std::result::Result<Option<(f64, Cell, f64)>, ()> {
        let (twx, twz) = (tiles.twx as i64, tiles.twz as i64);
        let mut c = *cell;
        let mut t = t_cur;
        let mut skipped = false;
        let mut last_axis_x = true;
        loop {
            *steps += 1;
            if *steps > self.max_steps {
                return Err(());
            }
            // Tile of the current cell (unwrapped) and its exit time.
            let tx = c.ix >> tiles.shx;
            let tz = c.iz >> tiles.shz;
            let wtx = c.wx >> tiles.shx;
            let wtz = c.wz >> tiles.shz;
            debug_assert!(wtx < tiles.ntx && wtz < tiles.ntz);
            let tmax = tiles.max[tiles.at(wtx, wtz)];
            let tx_exit = if d.x > 0.0 {
                (((tx + 1) * twx) as f64 * self.dx - o.x) / d.x
            } else if d.x < 0.0 {
                ((tx * twx) as f64 * self.dx - o.x) / d.x
            } else {
                f64::INFINITY
            };
            let tz_exit = if d.z > 0.0 {
                (((tz + 1) * twz) as f64 * self.dz - o.z) / d.z
            } else if d.z < 0.0 {
                ((tz * twz) as f64 * self.dz - o.z) / d.z
            } else {
                f64::INFINITY
            };
            let t_out = tx_exit.min(tz_exit).max(t);
            // Lowest height of the ray over [t, t_out] (clipped at the segment limit).
            let t_end = t_out.min(t_y);
            let y_low = if d.y < 0.0 {
                o.y + d.y * t_end
            } else {
                o.y + d.y * t
            };
            if y_low.is_nan() || y_low <= tmax || !t_out.is_finite() {
                break;
            }
            if t_out >= t_y {
                // Above this tile until the segment ends: nothing more to hit.
                return Ok(Some((t_y, c, 1.0)));
            }
            // Move to the first cell of the next tile.
            let px = o.x + d.x * t_out;
            let pz = o.z + d.z * t_out;
            if tx_exit <= tz_exit {
                let target = if d.x > 0.0 {
                    (tx + 1) * twx
                } else {
                    tx * twx - 1
                };
                let jz = ((pz / self.dz).floor() as i64).clamp(tz * twz, tz * twz + twz - 1);
                self.move_to(&mut c, target, jz);
                last_axis_x = true;
            } else {
                let target = if d.z > 0.0 {
                    (tz + 1) * twz
                } else {
                    tz * twz - 1
                };
                let jx = ((px / self.dx).floor() as i64).clamp(tx * twx, tx * twx + twx - 1);
                self.move_to(&mut c, jx, target);
                last_axis_x = false;
            }
            t = t_out;
            skipped = true;
        }
        // The walk goes on cell by cell in this tile.
        self.prefetch_tile(tiles, &c);
        if !skipped {
            return Ok(None);
        }
        // Clearance at the entry point on the edge just crossed.
        let y = o.y + d.y * t;
        let x0 = c.ix as f64 * self.dx;
        let z0 = c.iz as f64 * self.dz;
        let hc = self.corners(&c);
        let g = if last_axis_x {
            let sz = (((o.z + d.z * t) - z0) / self.dz).clamp(0.0, 1.0);
            if d.x > 0.0 {
                y - lerp(hc.0, hc.2, sz)
            } else {
                y - lerp(hc.1, hc.3, sz)
            }
        } else {
            let sx = (((o.x + d.x * t) - x0) / self.dx).clamp(0.0, 1.0);
            if d.z > 0.0 {
                y - lerp(hc.0, hc.1, sx)
            } else {
                y - lerp(hc.2, hc.3, sx)
            }
        };
        Ok(Some((t, c, g)))
    }

    #[inline]
    fn move_to(&self, c: &mut Cell, ix: i64, iz: i64) {
        c.ix = ix;
        c.iz = iz;
        c.wx = ix.rem_euclid(self.nx as i64) as usize;
        c.wz = iz.rem_euclid(self.nz as i64) as usize;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::Triangulation;
    use rand::{Rng, SeedableRng};
    use rand_xoshiro::Xoshiro256PlusPlus;

    fn reflect(u: Vector3<f64>, w: Vector3<f64>, n: Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (u - 2.0 * u.dot(&n) * n, w)
    }

    fn field(nx: usize, nz: usize, dx: f64, dz: f64, f: impl Fn(f64, f64) -> f64) -> HeightField {
        let mut heights = vec![0.0; nx * nz];
        for iz in 0..nz {
            for ix in 0..nx {
                heights[iz * nx + ix] = f(ix as f64 * dx, iz as f64 * dz);
            }
        }
        HeightField {
            nx,
            nz,
            dx,
            dz,
            heights,
            triangulation: Default::default(),
        }
    }

    /// Smooth random bumps: a sum of periodic sinusoids with random phases.
    fn bumps(n: usize, amp: f64, seed: u64) -> HeightField {
        let mut r = Xoshiro256PlusPlus::seed_from_u64(seed);
        let modes: Vec<(f64, f64, f64, f64)> = (0..12)
            .map(|_| {
                let kx = r.gen_range(1..6) as f64;
                let kz = r.gen_range(-5..6) as f64;
                (
                    kx,
                    kz,
                    r.gen::<f64>() * std::f64::consts::TAU,
                    amp / (kx * kx + kz * kz).sqrt(),
                )
            })
            .collect();
        let l = n as f64;
        field(n, n, 1.0, 1.0, |x, z| {
            modes
                .iter()
                .map(|&(kx, kz, ph, a)| {
                    a * (std::f64::consts::TAU * (kx * x + kz * z) / l + ph).sin()
                })
                .sum()
        })
    }

    fn incident(alpha_deg: f64, beta_deg: f64) -> Vector3<f64> {
        let (a, b) = (alpha_deg.to_radians(), beta_deg.to_radians());
        Vector3::new(a.cos() * b.cos(), a.sin(), -a.cos() * b.sin())
    }

    #[test]
    fn flat_wall_is_a_mirror() {
        let f = field(16, 16, 1.0, 1.0, |_, _| 0.0);
        let t = Tracker::new(&f, 100).unwrap();
        for (a, b) in [
            (-0.01, 0.0),
            (-12.5, 30.0),
            (-90.0, 0.0),
            (-45.0, 90.0),
            (-5.0, -180.0),
        ] {
            let u = incident(a, b);
            let h = t.trace(3.3, 7.1, u, Vector3::zeros(), reflect);
            assert_eq!(h.fate, Fate::Escaped);
            assert_eq!(h.collisions, 1);
            assert!((h.velocity - Vector3::new(u.x, -u.y, u.z)).norm() < 1e-15);
        }
    }

    #[test]
    fn v_grooves_reflect_analytically() {
        // Symmetric triangle wave along x with faces at ±20°: a vertical particle
        // leaves after one collision at 90° − 2·20° = 50° elevation.
        let slope = 20f64.to_radians().tan();
        for nz in [1, 8] {
            let f = field(32, nz, 1.0, 1.0, |x, _| slope * (x % 8.0 - 4.0).abs());
            let t = Tracker::new(&f, 100).unwrap();
            let mut r = Xoshiro256PlusPlus::seed_from_u64(1);
            for _ in 0..1000 {
                let (x, z) = (r.gen::<f64>() * 32.0, r.gen::<f64>() * 8.0);
                let h = t.trace(x, z, incident(-90.0, 0.0), Vector3::zeros(), reflect);
                assert_eq!(h.fate, Fate::Escaped);
                let elev = (h.velocity.y / h.velocity.norm()).asin().to_degrees();
                // Exactly on a ridge or in a valley, a node: measure zero.
                if h.collisions == 1 {
                    assert!((elev - 50.0).abs() < 1e-9, "elevation {elev}");
                    assert!(h.velocity.z.abs() < 1e-15);
                }
            }
        }
    }

    #[test]
    fn elastic_energy_is_conserved_and_the_centre_stays_above_the_surface() {
        for (tiles, triangulation) in [
            (true, Triangulation::Uniform),
            (false, Triangulation::Uniform),
            (true, Triangulation::Alternating),
            (false, Triangulation::Alternating),
        ] {
            let mut f = bumps(64, 3.0, 5);
            f.triangulation = triangulation;
            let mut t = Tracker::new(&f, 1000).unwrap();
            if !tiles {
                t = t.without_tiles();
            }
            assert_eq!(t.has_tiles(), tiles);
            let mut r = Xoshiro256PlusPlus::seed_from_u64(2);
            let mut multi = 0;
            for i in 0..3000 {
                let a = [-0.01, -2.5, -12.5, -32.5, -90.0][i % 5];
                let b = r.gen::<f64>() * 360.0 - 180.0;
                let u = incident(a, b) * 3.7;
                let (x, z) = (r.gen::<f64>() * 64.0, r.gen::<f64>() * 64.0);
                let mut hits: Vec<HitInfo> = Vec::new();
                let h = t.trace_observed(x, z, u, Vector3::zeros(), reflect, |hi| hits.push(*hi));
                assert_eq!(h.fate, Fate::Escaped, "a {a} b {b}");
                assert!(h.velocity.y > 0.0);
                assert!(((h.velocity.norm() - u.norm()) / u.norm()).abs() < 1e-12);
                if h.collisions > 1 {
                    multi += 1;
                }
                for (k, hi) in hits.iter().enumerate() {
                    // The normal is one of the cell's two (HeightField::cell_normals, the
                    // triangulation the statistics use), the one of the triangle reported.
                    let c = f.cell_normals(hi.cell.0, hi.cell.1)[hi.triangle as usize];
                    let c = Vector3::new(c[0], c[1], c[2]).normalize();
                    assert!((c - hi.normal).norm() < 1e-12, "{triangulation:?}");
                    let s = t.surface_height(hi.point.x, hi.point.z);
                    assert!(
                        (hi.point.y - s).abs() < 1e-9,
                        "hit off the surface by {}",
                        hi.point.y - s
                    );
                    // The flight after this hit stays above the surface.
                    let end = hits.get(k + 1).map(|n| n.point);
                    let dir = hi.u_out;
                    let tmax = match end {
                        Some(e) => {
                            let mut de = e - hi.point;
                            de.x -= (de.x / 64.0).round() * 64.0;
                            de.z -= (de.z / 64.0).round() * 64.0;
                            de.norm() / dir.norm()
                        }
                        None => (t.top() - hi.point.y) / dir.y,
                    };
                    for j in 1..20 {
                        let p = hi.point + dir * (tmax * j as f64 / 20.0);
                        let s = t.surface_height(p.x, p.z);
                        assert!(p.y >= s - 1e-9, "centre below the surface by {}", s - p.y);
                    }
                }
            }
            assert!(
                multi > 50,
                "too few multiple collisions to test anything: {multi}"
            );
        }
    }

    #[test]
    fn tiles_do_not_change_the_histories() {
        for triangulation in [Triangulation::Uniform, Triangulation::Alternating] {
            let mut f = bumps(64, 3.0, 9);
            f.triangulation = triangulation;
            tiles_do_not_change(&f);
        }
    }

    fn tiles_do_not_change(f: &HeightField) {
        let t1 = Tracker::new(f, 1000).unwrap();
        let t2 = Tracker::new(f, 1000).unwrap().without_tiles();
        let mut r = Xoshiro256PlusPlus::seed_from_u64(3);
        for i in 0..2000 {
            let a = [-0.01, -2.5, -12.5, -32.5][i % 4];
            let u = incident(a, r.gen::<f64>() * 360.0 - 180.0);
            let (x, z) = (r.gen::<f64>() * 64.0, r.gen::<f64>() * 64.0);
            let h1 = t1.trace(x, z, u, Vector3::zeros(), reflect);
            let h2 = t2.trace(x, z, u, Vector3::zeros(), reflect);
            assert_eq!(h1.collisions, h2.collisions);
            assert!((h1.velocity - h2.velocity).norm() < 1e-9);
        }
    }

    #[test]
    fn rays_along_grid_lines_and_diagonals() {
        for triangulation in [Triangulation::Uniform, Triangulation::Alternating] {
            let mut f = bumps(32, 2.0, 11);
            f.triangulation = triangulation;
            rays_along_grid_lines(&f);
        }
    }

    fn rays_along_grid_lines(f: &HeightField) {
        let t = Tracker::new(f, 1000).unwrap();
        for b in [0.0, 90.0, 180.0, -90.0, 45.0, -45.0, 135.0, -135.0] {
            for a in [-0.01, -5.0, -30.0, -90.0] {
                for (x, z) in [
                    (0.0, 0.0),
                    (3.0, 5.0),
                    (3.0, 5.5),
                    (7.5, 9.0),
                    (31.999999999, 0.0),
                ] {
                    let u = incident(a, b);
                    let h = t.trace(x, z, u, Vector3::zeros(), reflect);
                    assert_eq!(h.fate, Fate::Escaped, "a {a} b {b} at ({x}, {z})");
                    assert!((h.velocity.norm() - 1.0).abs() < 1e-12);
                }
            }
        }
    }

    /// Mirror symmetry `β → −β` (docs/physics.md §1): the mirror image `z → −z` of a
    /// particle on the mirror image of a surface has the mirror image of its history. On a
    /// grid with even node counts the alternating triangulation is mapped onto itself; the
    /// uniform one is mapped onto the other diagonal, so there the histories differ.
    #[test]
    fn alternating_triangulation_is_mirror_symmetric() {
        let n = 64;
        let mut f = bumps(n, 3.0, 13);
        let mut g = f.clone();
        for iz in 0..n {
            for ix in 0..n {
                g.heights[iz * n + ix] = f.heights[((n - iz) % n) * n + ix];
            }
        }
        let lz = n as f64 * f.dz;
        let mut differ = [0usize; 2];
        let mut multi = 0;
        for (k, triangulation) in [Triangulation::Uniform, Triangulation::Alternating]
            .into_iter()
            .enumerate()
        {
            f.triangulation = triangulation;
            g.triangulation = triangulation;
            let tf = Tracker::new(&f, 1000).unwrap();
            let tg = Tracker::new(&g, 1000).unwrap();
            let mut r = Xoshiro256PlusPlus::seed_from_u64(17);
            for i in 0..2000 {
                let a = [-2.5, -12.5, -32.5, -60.0][i % 4];
                let u = incident(a, r.gen::<f64>() * 360.0 - 180.0);
                let (x, z) = (r.gen::<f64>() * n as f64, r.gen::<f64>() * lz);
                let hf = tf.trace(x, z, u, Vector3::zeros(), reflect);
                let um = Vector3::new(u.x, u.y, -u.z);
                let hg = tg.trace(x, lz - z, um, Vector3::zeros(), reflect);
                assert_eq!(hf.fate, Fate::Escaped);
                let v = hf.velocity;
                let mirrored = Vector3::new(v.x, v.y, -v.z);
                if hf.collisions != hg.collisions || (mirrored - hg.velocity).norm() > 1e-9 {
                    differ[k] += 1;
                }
                multi += usize::from(k == 1 && hf.collisions > 1);
            }
        }
        assert_eq!(
            differ[1], 0,
            "alternating: {} of 2000 histories not mirrored",
            differ[1]
        );
        assert!(
            multi > 20,
            "too few multiple collisions to test anything: {multi}"
        );
        assert!(
            differ[0] > 1000,
            "uniform: only {} of 2000 differ",
            differ[0]
        );
    }

    #[test]
    fn two_d_surface_keeps_the_transverse_velocity() {
        // Constant along z: the normal has no z component, so w never changes.
        let f = field(64, 1, 1.0, 1.0, |x, _| {
            1.5 * (std::f64::consts::TAU * x / 16.0).sin()
        });
        let t = Tracker::new(&f, 1000).unwrap();
        let mut r = Xoshiro256PlusPlus::seed_from_u64(4);
        for b in [0.0, 60.0, 90.0] {
            for _ in 0..500 {
                let u = incident(-15.0, b);
                let h = t.trace(
                    r.gen::<f64>() * 64.0,
                    r.gen::<f64>(),
                    u,
                    Vector3::zeros(),
                    reflect,
                );
                assert_eq!(h.fate, Fate::Escaped);
                assert!((h.velocity.z - u.z).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn collision_cap_is_reported() {
        // A narrow V groove with faces at 80°: a vertical particle bounces about
        // 180°/20° ≈ 9 times between the faces before it gets out.
        let slope = 80f64.to_radians().tan();
        let f = field(16, 1, 1.0, 1.0, |x, _| slope * (x % 8.0 - 4.0).abs());
        let t = Tracker::new(&f, 3).unwrap();
        let h = t.trace(2.3, 0.0, incident(-90.0, 0.0), Vector3::zeros(), reflect);
        assert_eq!(h.fate, Fate::Lost(LostReason::CollisionCap));
        assert_eq!(h.collisions, 3);
        let t = Tracker::new(&f, 1000).unwrap();
        let h = t.trace(2.3, 0.0, incident(-90.0, 0.0), Vector3::zeros(), reflect);
        assert_eq!(h.fate, Fate::Escaped);
        assert!(h.collisions > 3 && h.collisions < 20, "{}", h.collisions);
    }
}
