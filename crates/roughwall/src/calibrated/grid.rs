//! The fixed grid of the calibrated tables, derived from the chosen axes of
//! [`super::constants`]: bins, cells, rows, and the stages of a collision. Fixed, so that
//! tables are comparable and a file cannot disagree with the code about it.

use super::constants::*;

/// Lower edge of the `x_in` axis.
pub const X_IN_MIN: f64 = X_IN_EDGES[0];

/// Upper edge of the `x_in` axis.
pub const X_IN_MAX: f64 = X_IN_EDGES[X_IN_BINS];

/// Bins along `x_in`.
pub const X_IN_BINS: usize = X_IN_EDGES.len() - 1;

/// Slices: the first collision of a history by `Δγ(β)` ([`FIRST_DG_EDGES_DEG`]), and the
/// later ones by the memory `q` ([`Q_EDGES`]).
pub const SLICES: usize = FIRST_STAGES + 1 + Q_EDGES.len();

/// First-collision stages (by `FIRST_DG_EDGES_DEG`).
pub const FIRST_STAGES: usize = 1 + FIRST_DG_EDGES_DEG.len();

/// Later stages (the transverse memory is per later stage: the valley's depth `q` sets the
/// hop).
pub const LATER_STAGES: usize = SLICES - FIRST_STAGES;

/// Cells of a table.
pub const CELLS: usize = SLICES * X_IN_BINS * X_OUT_BINS;

/// Cells of the element correction.
pub const ELEMENT_CELLS: usize = SLICES * X_IN_BINS * G_BINS;

/// Rows of the `x_in` axis (every slice's bins).
pub const ROWS: usize = SLICES * X_IN_BINS;

pub(super) const DG: f64 = (G_MAX - G_MIN) / G_BINS as f64;

pub(super) const DX_OUT: f64 = X_OUT_MAX / X_OUT_BINS as f64;

/// Which collision of a history: the first (its `Δγ(β)` bin, `FIRST_DG_EDGES_DEG`), or a
/// later one with the memory of the element the particle has just left (its `q` bin,
/// `Q_EDGES`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stage(pub(super) usize);

impl Stage {
    /// The first collision (the particle comes from the flow) in the least rough planes.
    pub const FIRST: Stage = Stage(0);

    /// A later collision (the particle was trapped by the roughness) of a particle that has
    /// just left an element of reduced inclination `q = γ_prev/Δγ(β)`, seen from its new
    /// direction `β` (a NaN counts as 0).
    #[inline]
    pub fn later(q: f64) -> Stage {
        let q = if q.is_nan() { 0.0 } else { q };
        Stage(FIRST_STAGES + Q_EDGES.iter().filter(|&&e| q >= e).count())
    }

    /// The first-collision stage that counts a particle whose incident plane has roughness
    /// angle `delta_gamma` (radians; a NaN counts as 0): its `FIRST_DG_EDGES_DEG` bin.
    #[inline]
    pub fn first(delta_gamma: f64) -> Stage {
        let d = delta_gamma.to_degrees();
        Stage(FIRST_DG_EDGES_DEG.iter().filter(|&&e| d >= e).count())
    }

    /// Every stage, in table order.
    pub fn all() -> impl Iterator<Item = Stage> {
        (0..SLICES).map(Stage)
    }

    /// Whether this is the first collision.
    pub fn is_first(self) -> bool {
        self.0 < FIRST_STAGES
    }

    /// A later stage's index among the later stages (`None` for a first one).
    #[inline]
    pub fn later_index(self) -> Option<usize> {
        self.0.checked_sub(FIRST_STAGES)
    }

    /// The stage's name in a table file: `first-d0`, `first-d1`, `first-d2`, `later-q0`, ….
    pub fn name(self) -> String {
        match self.0 {
            k if k < FIRST_STAGES => format!("first-d{k}"),
            k => format!("later-q{}", k - FIRST_STAGES),
        }
    }
}

pub(super) fn cell(stage: Stage, i_in: usize, i_out: usize) -> usize {
    (stage.0 * X_IN_BINS + i_in) * X_OUT_BINS + i_out
}

pub(super) fn bin_in(x_in: f64) -> usize {
    // Inner edges at or below `x_in` (a NaN counts none).
    X_IN_EDGES[1..X_IN_BINS].partition_point(|&e| e <= x_in)
}

/// `x_in` clamped to the axis, in [`X_SUM_UNIT`]s.
pub(super) fn x_units(x_in: f64) -> i64 {
    (x_in.clamp(X_IN_MIN, X_IN_MAX) / X_SUM_UNIT).round() as i64
}

/// The centre of `x_in` bin `i`.
pub(super) fn centre_in(i: usize) -> f64 {
    0.5 * (X_IN_EDGES[i] + X_IN_EDGES[i + 1])
}

/// The cell of `(slice, x_in, g)` in the element tables, `g = γ/Δγ(β)` (`None` outside
/// the `s` range).
pub(super) fn element_cell(stage: Stage, x_in: f64, g: f64) -> Option<usize> {
    let s = g - x_in.clamp(X_IN_MIN, X_IN_MAX);
    if !(G_MIN..G_MAX).contains(&s) || x_in.is_nan() {
        return None;
    }
    let i_s = (((s - G_MIN) / DG) as usize).min(G_BINS - 1);
    Some((stage.0 * X_IN_BINS + bin_in(x_in)) * G_BINS + i_s)
}

/// The edges `[lo, hi)` (degrees) of first stage `k`.
pub(super) fn first_edges(k: usize) -> (f64, f64) {
    let lo = if k == 0 {
        0.0
    } else {
        FIRST_DG_EDGES_DEG[k - 1]
    };
    let hi = FIRST_DG_EDGES_DEG.get(k).copied().unwrap_or(f64::INFINITY);
    (lo, hi)
}

/// Bins `(lo, hi)` and the weight of `hi` for a bilinear read at `x` (centres at
/// `min + (i + ½) dx`, clamped).
#[inline]
pub(super) fn axis(x: f64, min: f64, dx: f64, bins: usize) -> (usize, usize, f64) {
    let t = ((x - min) / dx - 0.5).clamp(0.0, (bins - 1) as f64);
    // `t ≥ 0`: truncation is its floor, without a libm call on the hot path.
    let i = (t as usize).min(bins - 2);
    (i, i + 1, t - i as f64)
}
