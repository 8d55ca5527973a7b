//! The calibrated escape law of the `calibrated` wall model: the probability that a
//! particle leaves the wall after a collision, tabulated from a deterministic run
//! (`rebound calibrate`) instead of Radenkovic & Simonin 2021, Eq. (34).
//!
//! Eq. (34) gives the single-collision probability as `tanh(ψ α⁺/Δγ(β⁺))` whatever the
//! incidence. The deterministic simulation says otherwise (`results/REPORT.md`, "A model
//! within the deterministic noise"): at grazing incidence a particle hits near the asperity
//! tops and escapes more easily, and after a first collision it starts low, in a valley.
//! So the table is indexed by the collision's stage (first, by the roughness of its
//! incident plane: [`Stage::first`]; or a later one of the same history, remembering the
//! element the particle has just left: [`Stage::later`]), by the
//! incident direction and by the rebound direction, both in units of the wall's roughness
//! in their own plane.
//!
//! The table works in the wall's *slopes* ([`super::slope_space`], table format v9): where
//! this module says `γ`, `α` and `Δγ(β)` it means the element's slope along the path, `tan α`
//! and the wall's slope spread `σ(β)` along the direction `β` (Eq. 35 with slopes for
//! angles), because in those units a point particle's first element has one law for every
//! wall. So `x_in = tan α/σ(β)` of the velocity before the collision (negative: descending;
//! positive: a rebound that was trapped and meets the wall again while rising), and
//! `x_out = tan α⁺/σ(β⁺)` of the rebound.
//!
//! The grid is fixed (so tables are comparable and a file cannot disagree with the code
//! about it): `x_in ∈ [−6, 6]` in 34 bins ([`X_IN_EDGES`], 0.125 wide at grazing incidence),
//! `x_out ∈ [0, 4]` in 40 bins, ten stages (three first, seven later).
//! The probability is read bilinearly (along `x_in` between the rows' mean `x_in`, along
//! `x_out` between bin centres, clamped at the edges); beyond `x_out = 4` it is 1 (the
//! deterministic runs measure `P ≥ 0.9999` from `x_out ≈ 2.6`).

use super::slope_space::reduced_slope;
use super::transverse_memory::{
    plausible, TransverseCounts, TransverseMemory, LATER_STAGES, MAX_TERM, Z_MAX,
};
use crate::error::{Error, Result};
use crate::wall::Deviations;
use nalgebra::Vector3;
use std::sync::{Mutex, OnceLock};

/// Edges of the `x_in` axis: 0.125 wide in `[−1, 0]`, where the laws change fastest (a
/// first element at `α⁻/Δγ = −0.34` and at `−0.64` differ by 0.1° in mean α⁺ on the Sec. 3
/// wall), 0.25 in `[−2, −1]` and `[0, 1]`, 0.5 beyond.
pub const X_IN_EDGES: [f64; 35] = [
    -6.0, -5.5, -5.0, -4.5, -4.0, -3.5, -3.0, -2.5, -2.0, -1.75, -1.5, -1.25, -1.0, -0.875, -0.75,
    -0.625, -0.5, -0.375, -0.25, -0.125, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0,
    4.5, 5.0, 5.5, 6.0,
];
/// Lower edge of the `x_in` axis.
pub const X_IN_MIN: f64 = X_IN_EDGES[0];
/// Upper edge of the `x_in` axis.
pub const X_IN_MAX: f64 = X_IN_EDGES[X_IN_BINS];
/// Bins along `x_in`.
pub const X_IN_BINS: usize = X_IN_EDGES.len() - 1;
/// Upper edge of the `x_out` axis (the lower one is 0).
pub const X_OUT_MAX: f64 = 4.0;
/// Bins along `x_out`.
pub const X_OUT_BINS: usize = 40;
/// Slices: the first collision of a history by `Δγ(β)` ([`FIRST_DG_EDGES_DEG`]), and the
/// later ones by the memory `q` ([`Q_EDGES`]).
pub const SLICES: usize = FIRST_STAGES + 1 + Q_EDGES.len();
/// Edges (the slope spread `σ(β)` × 180/π, written like degrees) of the first
/// collision's axis: the roughness of the incident plane (Eq. 35 in slopes). In slopes the
/// first *element*'s correction is the same on all three stages within the noise (table v9:
/// stage means of `s` within 0.002 at every `x_in`; in angles, table v8, up to 0.006 apart);
/// the *escape* law after it still differs between them at grazing incidence (χ²/cell 2–5
/// between the stages at `x_in` in [−0.75, −0.25]), presumably through the rebound's
/// deflection across the path. The edges split the calibration sweep's directions (2.5° and
/// 3.6°; 5.1–5.8°; 6.9° and 7.3°, as angles) into three stages, and a first collision reads
/// one of the two stages around its `σ(β)` ([`EscapeTable::first_stage`]).
pub const FIRST_DG_EDGES_DEG: [f64; 2] = [4.5, 6.5];
/// First-collision stages (by [`FIRST_DG_EDGES_DEG`]).
pub const FIRST_STAGES: usize = 1 + FIRST_DG_EDGES_DEG.len();
/// Cells of a table.
pub const CELLS: usize = SLICES * X_IN_BINS * X_OUT_BINS;
/// Collisions a cell needs to stand on its own (one standard error of `p` is then at most
/// `√(0.25/50) ≈ 0.07`); sparser cells take their neighbour's value.
pub const MIN_COUNT: u64 = 50;
/// Shadow-law draws a first-element cell needs for its weight (the weight's relative
/// noise is about `√(2/n)`: 4.5 % here); sparser cells pool neighbours (`window_ratio`).
pub const ELEMENT_MIN_COUNT: u64 = 1000;
/// Lower edge of the element's reduced local impact angle `s = (γ − α)/Δγ(β)` (`α` clamped
/// to the `x_in` range): an element the particle can reach has `s > 0`, and the shadow law
/// of Eq. (31) vanishes like `sin(α + γ)` there. Reading the correction in `s` rather than in
/// `γ` lines up that cut-off for the directions a cell mixes. Outside the range the weight
/// is 1 (the Gaussian factor leaves less than 4·10⁻⁵ of its mass beyond it).
pub const G_MIN: f64 = 0.0;
/// Upper edge of `s`.
pub const G_MAX: f64 = 10.0;
/// Bins along `s`.
pub const G_BINS: usize = 125;
/// Edges of the memory axis of the later collisions: `q = γ_prev/Δγ(β)`, the inclination
/// of the element the particle has just left, seen from its new direction `β` (negative:
/// it left down a slope). A trapped particle meets a valley's other side: on the
/// deterministic surface its next element is 0.3–0.6 Δγ steeper after a steep downslope
/// than after a flat one, and a rising particle escapes less often after an upslope.
/// The lower edges are 0.5 apart because a history trapped at steep incidence (α⁻ = −32.5° on
/// the Sec. 3 wall along its rougher direction) leaves its first element at `q ≈ −2` to `−3`,
/// where the next element's mean `γ/Δγ` rises from 1.1 to 2.0.
pub const Q_EDGES: [f64; 6] = [-2.75, -2.25, -1.75, -1.25, -0.5, 0.25];
/// Half-width (in `s` cells, 0.08 each) of the window a sparse later-stage element cell may
/// pool within its own stage (`same_stage_ratio`). With [`SAME_STAGE_ROWS`]: between the
/// windows measured at α⁻ = −32.5°, β⁻ = 90° on the Sec. 3 wall (±3 cells and ±3 rows: mean
/// α⁺ −0.038° off; ±3 and ±6: +0.008°; ±5 and ±4: +0.014°; docs/models.md), not tuned
/// further.
pub const SAME_STAGE_S_CELLS: usize = 4;
/// How many `x_in` bins each side a sparse later-stage element cell may pool within its own
/// stage (`same_stage_ratio`; the choice: [`SAME_STAGE_S_CELLS`]).
pub const SAME_STAGE_ROWS: usize = 6;
/// Cells of the element correction.
pub const ELEMENT_CELLS: usize = SLICES * X_IN_BINS * G_BINS;
/// First line of a table file (names the format and its version).
pub const MAGIC: &str = "# roughwall escape table v9";
/// What every version's first line starts with.
const MAGIC_STEM: &str = "# roughwall escape table v";
const HEADER: &str = "stage,x_in,x_out,collisions,escaped,p_escape";
const ELEMENT_HEADER: &str = "element_stage,x_in,s,deterministic,model,weight";
const ROW_HEADER: &str =
    "row_stage,x_in,escape_x_in_sum,escape_position,element_x_in_sum,element_position";
const FIRST_HEADER: &str = "first_stage,collisions,delta_gamma_sum,delta_gamma_position";
const TRANSVERSE_HEADER: &str = "transverse_stage,pairs,z_prev_sq_sum,cross_sum,slope,fresh";
const DG: f64 = (G_MAX - G_MIN) / G_BINS as f64;

const DX_OUT: f64 = X_OUT_MAX / X_OUT_BINS as f64;

/// Which collision of a history: the first (its `Δγ(β)` bin, [`FIRST_DG_EDGES_DEG`]), or a
/// later one with the memory of the element the particle has just left (its `q` bin,
/// [`Q_EDGES`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stage(usize);

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
    /// angle `delta_gamma` (radians; a NaN counts as 0): its [`FIRST_DG_EDGES_DEG`] bin.
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
    fn name(self) -> String {
        match self.0 {
            k if k < FIRST_STAGES => format!("first-d{k}"),
            k => format!("later-q{}", k - FIRST_STAGES),
        }
    }
}

/// Where one collision reads the element table ([`EscapeTable::element_read`]): the first
/// cells of its two rows along `x_in` and the upper row's weight, its `x_in` clamped to the
/// axis, and the rejection bound over both rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElementRead {
    lo: usize,
    hi: usize,
    ti: f64,
    x_in: f64,
    /// An upper bound of the weight over every `g` (at least 1).
    pub bound: f64,
}

fn cell(stage: Stage, i_in: usize, i_out: usize) -> usize {
    (stage.0 * X_IN_BINS + i_in) * X_OUT_BINS + i_out
}

fn bin_in(x_in: f64) -> usize {
    // Inner edges at or below `x_in` (a NaN counts none).
    X_IN_EDGES[1..X_IN_BINS].partition_point(|&e| e <= x_in)
}

/// Rows of the `x_in` axis (every slice's bins).
pub const ROWS: usize = SLICES * X_IN_BINS;

/// Units of the `x_in` sums (integers, so that sums are exact in any order).
const X_SUM_UNIT: f64 = 1e-6;

/// `x_in` clamped to the axis, in [`X_SUM_UNIT`]s.
fn x_units(x_in: f64) -> i64 {
    (x_in.clamp(X_IN_MIN, X_IN_MAX) / X_SUM_UNIT).round() as i64
}

/// The centre of `x_in` bin `i`.
fn centre_in(i: usize) -> f64 {
    0.5 * (X_IN_EDGES[i] + X_IN_EDGES[i + 1])
}

/// Integer counts of collisions and escapes per cell: what a calibration run accumulates.
/// Sums are exact, so the counts do not depend on the order or the thread that added them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EscapeCounts {
    pub collisions: Vec<u64>,
    pub escaped: Vec<u64>,
    /// First wall elements by `(x_in, g)`: seen by the deterministic particles, and drawn
    /// from the paper's shadow law (Eqs. 31–33) for the same incident directions.
    pub element_deterministic: Vec<u64>,
    pub element_model: Vec<u64>,
    /// Sums of `x_in` (clamped to the axis, in 10⁻⁶) per `(slice, x_in bin)` row: of the
    /// collisions counted in the escape table, and of the shadow-law draws counted in the
    /// element table. A row's mean `x_in` is where its values belong: the calibration's
    /// directions fill a bin unevenly, and the laws change fast with `x_in` at grazing
    /// incidence.
    pub escape_x_sum: Vec<i64>,
    pub element_x_sum: Vec<i64>,
    /// First collisions per first stage and the sum of their `Δγ(β)` (in
    /// `DG_SUM_UNIT`s): where each first stage's values belong along `Δγ`.
    pub first_count: Vec<u64>,
    pub first_dg_sum: Vec<i64>,
    /// Successive elements' transverse residuals per later stage
    /// ([`super::transverse_memory`]).
    pub transverse: TransverseCounts,
}

/// Units of the `Δγ` sums (degrees; integers, so that sums are exact in any order).
const DG_SUM_UNIT: f64 = 1e-6;

impl Default for EscapeCounts {
    fn default() -> Self {
        EscapeCounts {
            collisions: vec![0; CELLS],
            escaped: vec![0; CELLS],
            element_deterministic: vec![0; ELEMENT_CELLS],
            element_model: vec![0; ELEMENT_CELLS],
            escape_x_sum: vec![0; ROWS],
            element_x_sum: vec![0; ROWS],
            first_count: vec![0; FIRST_STAGES],
            first_dg_sum: vec![0; FIRST_STAGES],
            transverse: TransverseCounts::default(),
        }
    }
}

/// The cell of `(slice, x_in, g)` in the element tables, `g = γ/Δγ(β)` (`None` outside
/// the `s` range).
fn element_cell(stage: Stage, x_in: f64, g: f64) -> Option<usize> {
    let s = g - x_in.clamp(X_IN_MIN, X_IN_MAX);
    if !(G_MIN..G_MAX).contains(&s) || x_in.is_nan() {
        return None;
    }
    let i_s = (((s - G_MIN) / DG) as usize).min(G_BINS - 1);
    Some((stage.0 * X_IN_BINS + bin_in(x_in)) * G_BINS + i_s)
}

impl EscapeCounts {
    /// Counts the wall element of one collision: `g_deterministic = γ/Δγ(β)` of the
    /// element the deterministic particle hit (`β` of its velocity before the collision),
    /// `g_model` of one draw of the shadow law for the same direction (reduced angle `x_in`).
    pub fn push_element(&mut self, stage: Stage, x_in: f64, g_deterministic: f64, g_model: f64) {
        if let Some(c) = element_cell(stage, x_in, g_deterministic) {
            self.element_deterministic[c] += 1;
        }
        if let Some(c) = element_cell(stage, x_in, g_model) {
            self.element_model[c] += 1;
            self.element_x_sum[c / G_BINS] += x_units(x_in);
        }
    }

    /// Counts one collision with incident velocity `u_in` and rebound `u_out`, and whether
    /// the particle then left the wall, on the wall of slope spreads `slopes`
    /// ([`super::slope_space::slope_deviations`]). Rebounds into the mean wall (`α⁺ ≤ 0`)
    /// are not counted: they cannot escape and the model never asks.
    pub fn push(
        &mut self,
        stage: Stage,
        u_in: &Vector3<f64>,
        u_out: &Vector3<f64>,
        slopes: &Deviations,
        escaped: bool,
    ) {
        if u_out.y <= 0.0 {
            return;
        }
        let x_out = reduced_slope(u_out, slopes);
        if x_out.is_nan() || x_out >= X_OUT_MAX {
            return;
        }
        let x_in = reduced_slope(u_in, slopes);
        if x_in.is_nan() {
            return;
        }
        let i_out = ((x_out / DX_OUT) as usize).min(X_OUT_BINS - 1);
        let c = cell(stage, bin_in(x_in), i_out);
        self.collisions[c] += 1;
        self.escaped[c] += escaped as u64;
        self.escape_x_sum[c / X_OUT_BINS] += x_units(x_in);
    }

    /// Counts a later collision's transverse residual `z` beside `z_prev` of the element the
    /// particle has just left ([`super::transverse_memory`]); a first collision has none.
    pub fn push_transverse(&mut self, stage: Stage, z_prev: f64, z: f64) {
        if let Some(k) = stage.later_index() {
            self.transverse.push(k, z_prev, z);
        }
    }

    /// Counts a first collision in an incident plane of roughness angle `delta_gamma`
    /// (radians) and returns its stage ([`Stage::first`]; a plane without roughness is not
    /// counted along `Δγ`).
    pub fn push_first(&mut self, delta_gamma: f64) -> Stage {
        let stage = Stage::first(delta_gamma);
        if delta_gamma.is_finite() && delta_gamma > 0.0 {
            self.first_count[stage.0] += 1;
            self.first_dg_sum[stage.0] += (delta_gamma.to_degrees() / DG_SUM_UNIT).round() as i64;
        }
        stage
    }

    /// Adds `other` (exact integer sums).
    pub fn add(&mut self, other: &EscapeCounts) {
        for (a, b) in self.collisions.iter_mut().zip(&other.collisions) {
            *a += b;
        }
        for (a, b) in self.escaped.iter_mut().zip(&other.escaped) {
            *a += b;
        }
        for (a, b) in self
            .element_deterministic
            .iter_mut()
            .zip(&other.element_deterministic)
        {
            *a += b;
        }
        for (a, b) in self.element_model.iter_mut().zip(&other.element_model) {
            *a += b;
        }
        for (a, b) in self.escape_x_sum.iter_mut().zip(&other.escape_x_sum) {
            *a += b;
        }
        for (a, b) in self.element_x_sum.iter_mut().zip(&other.element_x_sum) {
            *a += b;
        }
        for (a, b) in self.first_count.iter_mut().zip(&other.first_count) {
            *a += b;
        }
        for (a, b) in self.first_dg_sum.iter_mut().zip(&other.first_dg_sum) {
            *a += b;
        }
        self.transverse.add(&other.transverse);
    }

    /// Sets every row's `x_in` sums as if its counts sat at the bin's centre (tables built
    /// by hand in tests).
    #[cfg(test)]
    pub(crate) fn at_centres(mut self) -> EscapeCounts {
        for r in 0..ROWS {
            let x = x_units(centre_in(r % X_IN_BINS));
            let n: u64 = self.collisions[r * X_OUT_BINS..(r + 1) * X_OUT_BINS]
                .iter()
                .sum();
            self.escape_x_sum[r] = x * n as i64;
            let n: u64 = self.element_model[r * G_BINS..(r + 1) * G_BINS]
                .iter()
                .sum();
            self.element_x_sum[r] = x * n as i64;
        }
        self
    }

    /// Total collisions counted.
    pub fn total(&self) -> u64 {
        self.collisions.iter().sum()
    }
}

/// A calibrated escape law: the counts it came from and the probability of every cell
/// (sparse cells filled, see [`EscapeTable::from_counts`]).
#[derive(Clone, Debug, PartialEq)]
pub struct EscapeTable {
    counts: EscapeCounts,
    p: Vec<f64>,
    /// Element correction: the ratio of the deterministic elements' law to the shadow law
    /// per `(stage, x_in, s)` cell (sparse cells: see [`EscapeTable::from_counts`]), and its
    /// largest value per `x_in` row (the rejection bound).
    weight: Vec<f64>,
    row_max: Vec<f64>,
    /// Where each `(slice, x_in bin)` row's values belong along `x_in`: the row's mean
    /// `x_in` ([`row_positions`]), for the escape and the element table.
    escape_pos: Vec<f64>,
    element_pos: Vec<f64>,
    /// Where each first stage's values belong along `Δγ` (degrees, increasing).
    first_pos: Vec<f64>,
    /// The later stages' transverse memory.
    memory: TransverseMemory,
    /// Where the table came from (the `# source:` line of its file).
    pub source: String,
}

/// The ratio `d/m` of a row's counts at cell `j`, pooled over the narrowest window
/// `j−k..=j+k` (clipped to the row) that holds [`ELEMENT_MIN_COUNT`] model draws; `None`
/// when the whole row holds fewer.
fn window_ratio(d: &[u64], m: &[u64], j: usize) -> Option<f64> {
    window_ratio_within(d, m, j, usize::MAX)
}

/// `window_ratio` with the window's half-width at most `max_k` cells.
fn window_ratio_within(d: &[u64], m: &[u64], j: usize, max_k: usize) -> Option<f64> {
    let (mut sd, mut sm) = (d[j], m[j]);
    let mut k = 0;
    while sm < ELEMENT_MIN_COUNT {
        k += 1;
        if k > max_k || (k > j && j + k >= m.len()) {
            return None;
        }
        for i in [j.checked_sub(k), Some(j + k).filter(|&i| i < m.len())]
            .into_iter()
            .flatten()
        {
            sd += d[i];
            sm += m[i];
        }
    }
    Some(sd as f64 / sm as f64)
}

/// The weight of a sparse later-stage element cell `c` from its own stage: the ratio over the
/// narrowest window of at most [`SAME_STAGE_S_CELLS`] cells each side along `s`, first in
/// its own row, then in the rows within 1, 2, … [`SAME_STAGE_ROWS`] bins along `x_in` pooled;
/// `None` when none holds [`ELEMENT_MIN_COUNT`] draws. Pooling along `x_in` within the stage
/// keeps the memory that pooling the stages loses: at α⁻ = −32.5°, β⁻ = 90° on the Sec. 3
/// wall the deterministic next element has a mean `γ/Δγ` of 1.07, 1.50 and 2.00 after `q` in
/// `[−3, −2.5)`, `[−2.5, −2)` and `[−2, −1.5)` (docs/models.md, "The valley's memory").
fn same_stage_ratio(deterministic: &[u64], model: &[u64], c: usize) -> Option<f64> {
    const K: usize = SAME_STAGE_S_CELLS;
    let plane = X_IN_BINS * G_BINS;
    let (slice, i_in, j) = (c / plane, (c % plane) / G_BINS, c % G_BINS);
    // Only the cells within K of j can enter the window: pool those alone.
    let (lo, hi) = (j.saturating_sub(K), (j + K).min(G_BINS - 1));
    let (mut d, mut m) = ([0u64; 2 * K + 1], [0u64; 2 * K + 1]);
    let n = hi - lo + 1;
    for r in 0..=SAME_STAGE_ROWS {
        // Row i_in itself, then the two rows r bins away.
        let rows = match r {
            0 => [Some(i_in), None],
            _ => [
                i_in.checked_sub(r),
                Some(i_in + r).filter(|&i| i < X_IN_BINS),
            ],
        };
        for i in rows.into_iter().flatten() {
            let b = slice * plane + i * G_BINS;
            for g in lo..=hi {
                d[g - lo] += deterministic[b + g];
                m[g - lo] += model[b + g];
            }
        }
        if let Some(w) = window_ratio_within(&d[..n], &m[..n], j - lo, K) {
            return Some(w);
        }
    }
    None
}

/// The position of every `(slice, x_in bin)` row: its counts' mean `x_in` (`sums` in
/// [`X_SUM_UNIT`]s over `counts` values) when it has at least `min` of them, else the bin's
/// centre. A mean lies in its bin, so positions increase along a slice.
fn row_positions(sums: &[i64], counts: &[u64], min: u64) -> Vec<f64> {
    let per_row = counts.len() / ROWS;
    (0..ROWS)
        .map(|r| {
            let n: u64 = counts[r * per_row..(r + 1) * per_row].iter().sum();
            if n >= min.max(1) {
                sums[r] as f64 * X_SUM_UNIT / n as f64
            } else {
                centre_in(r % X_IN_BINS)
            }
        })
        .collect()
}

/// The edges `[lo, hi)` (degrees) of first stage `k`.
fn first_edges(k: usize) -> (f64, f64) {
    let lo = if k == 0 {
        0.0
    } else {
        FIRST_DG_EDGES_DEG[k - 1]
    };
    let hi = FIRST_DG_EDGES_DEG.get(k).copied().unwrap_or(f64::INFINITY);
    (lo, hi)
}

/// The position of every first stage along `Δγ` (degrees): its first collisions' mean
/// `Δγ(β)`, or for a stage without any a point inside its bin (its values are then the
/// first stages' pooled ones).
fn first_positions(sums: &[i64], counts: &[u64]) -> Vec<f64> {
    (0..FIRST_STAGES)
        .map(|k| {
            if counts[k] > 0 {
                // Inside its bin even if every sum was rounded up onto the upper edge, so
                // that the positions increase.
                let (lo, hi) = first_edges(k);
                let mean = sums[k] as f64 * DG_SUM_UNIT / counts[k] as f64;
                mean.max(lo).min(hi - DG_SUM_UNIT)
            } else {
                match first_edges(k) {
                    (lo, hi) if hi.is_finite() => 0.5 * (lo + hi),
                    (lo, _) => lo + 1.0,
                }
            }
        })
        .collect()
}

/// Rows `(lo, hi)` of a slice and the weight of `hi` for a linear read at `x_in` between the
/// rows' positions `pos` (the slice's [`X_IN_BINS`] positions; clamped at the ends).
#[inline]
fn rows_at(x_in: f64, pos: &[f64]) -> (usize, usize, f64) {
    let i = bin_in(x_in);
    let (lo, hi) = if x_in >= pos[i] {
        (i, (i + 1).min(X_IN_BINS - 1))
    } else {
        (i.saturating_sub(1), i)
    };
    let span = pos[hi] - pos[lo];
    if span > 0.0 {
        (lo, hi, ((x_in - pos[lo]) / span).clamp(0.0, 1.0))
    } else {
        (lo, hi, 0.0)
    }
}

/// The counts `v` of `stages` added cell by cell: one stage's plane of `plane` cells.
fn pooled_stages(v: &[u64], plane: usize, stages: std::ops::Range<usize>) -> Vec<u64> {
    (0..plane)
        .map(|c| stages.clone().map(|k| v[k * plane + c]).sum())
        .collect()
}

/// Two tables of counts `(a, b)` pooled over each kind of stage: `[first, later]`, each the
/// pair of pooled planes (the fallback of a sparse cell).
fn pooled_by_kind(a: &[u64], b: &[u64], plane: usize) -> [(Vec<u64>, Vec<u64>); 2] {
    [0..FIRST_STAGES, FIRST_STAGES..SLICES].map(|stages| {
        (
            pooled_stages(a, plane, stages.clone()),
            pooled_stages(b, plane, stages),
        )
    })
}

/// The escape probabilities of every cell. A cell with fewer than [`MIN_COUNT`] collisions
/// takes the value of the nearest cell along `x_in` (same stage and `x_out`) that has enough;
/// a column with none takes the pooled counts of its kind of stage, first or later (nearest
/// along `x_in`; a later column then the first stages' pooled value); a column no run saw
/// trapped is 1 (the rebound is steep enough).
fn escape_probabilities(collisions: &[u64], escaped: &[u64]) -> Vec<f64> {
    let plane = X_IN_BINS * X_OUT_BINS;
    let mut p = vec![f64::NAN; SLICES * plane];
    let [(first_c, first_e), (pooled_c, pooled_e)] = pooled_by_kind(collisions, escaped, plane);
    for stage in 0..SLICES {
        for i_out in 0..X_OUT_BINS {
            // Nearest populated bin along x_in, the lower one first on a tie.
            let nearest = |c: &[u64], e: &[u64], i_in: usize, k: usize| {
                let own = |i: usize| {
                    let j = k + i * X_OUT_BINS + i_out;
                    (c[j] >= MIN_COUNT).then(|| e[j] as f64 / c[j] as f64)
                };
                (0..X_IN_BINS).find_map(|d| {
                    let lo = i_in.checked_sub(d).and_then(own);
                    let hi = (i_in + d < X_IN_BINS).then(|| own(i_in + d)).flatten();
                    lo.or(hi)
                })
            };
            for i_in in 0..X_IN_BINS {
                let at = i_in * X_OUT_BINS + i_out;
                p[stage * plane + at] = match nearest(collisions, escaped, i_in, stage * plane) {
                    Some(v) => v,
                    None if stage < FIRST_STAGES => {
                        nearest(&first_c, &first_e, i_in, 0).unwrap_or(f64::NAN)
                    }
                    None => nearest(&pooled_c, &pooled_e, i_in, 0)
                        .or_else(|| nearest(&first_c, &first_e, i_in, 0))
                        .unwrap_or(f64::NAN),
                };
            }
        }
    }
    p.into_iter()
        .map(|v| if v.is_nan() { 1.0 } else { v })
        .collect()
}

/// The element weights of every cell. An element cell with fewer than [`ELEMENT_MIN_COUNT`]
/// draws takes, for a later stage, the ratio pooled nearby in its own stage
/// (`same_stage_ratio`); else the ratio over the narrowest window that has enough
/// (`window_ratio`) in the pooled row of its kind of stage (first or later); a row without
/// enough draws keeps the shadow law (1).
fn element_weights(deterministic: &[u64], model: &[u64]) -> Vec<f64> {
    // The shadow law's tails are where cells are sparse, and there the deterministic
    // surface has fewer steep elements than the shadow law (the ratio falls to ~0.3 five Δγ
    // out): a sparse cell must not fall back to 1.
    let plane = X_IN_BINS * G_BINS;
    let [(first_d, first_m), (later_d, later_m)] = pooled_by_kind(deterministic, model, plane);
    (0..SLICES * plane)
        .map(|c| {
            let (d, m, base) = if model[c] >= ELEMENT_MIN_COUNT {
                (deterministic, model, c - c % G_BINS)
            } else if c < FIRST_STAGES * plane {
                (&first_d[..], &first_m[..], c % plane - c % G_BINS)
            } else if let Some(w) = same_stage_ratio(deterministic, model, c) {
                return w;
            } else {
                (&later_d[..], &later_m[..], c % plane - c % G_BINS)
            };
            window_ratio(&d[base..base + G_BINS], &m[base..base + G_BINS], c % G_BINS)
                .unwrap_or(1.0)
        })
        .collect()
}

impl EscapeTable {
    /// The table of `counts` (`escape_probabilities`, `element_weights`).
    pub fn from_counts(counts: EscapeCounts, source: &str) -> EscapeTable {
        let p = escape_probabilities(&counts.collisions, &counts.escaped);
        let weight = element_weights(&counts.element_deterministic, &counts.element_model);
        let row_max = weight
            .chunks(G_BINS)
            .map(|r| r.iter().copied().fold(0.0, f64::max))
            .collect();
        let escape_pos = row_positions(&counts.escape_x_sum, &counts.collisions, MIN_COUNT);
        let element_pos = row_positions(
            &counts.element_x_sum,
            &counts.element_model,
            ELEMENT_MIN_COUNT,
        );
        let first_pos = first_positions(&counts.first_dg_sum, &counts.first_count);
        let memory = TransverseMemory::from_counts(&counts.transverse);
        EscapeTable {
            counts,
            p,
            weight,
            row_max,
            escape_pos,
            element_pos,
            first_pos,
            memory,
            source: source.to_string(),
        }
    }

    /// The element weight `w(stage, x_in, s)` of an element of reduced inclination
    /// `g = γ/Δγ(β)`, read at `s = g − x_in` (bilinear between the rows' positions along
    /// `x_in` and the cell centres along `s`, 1 outside the `s` range): the calibrated model
    /// accepts a shadow-law draw with `w / bound(x_in)`.
    #[inline]
    pub fn element_weight(&self, stage: Stage, x_in: f64, g: f64) -> f64 {
        self.weight_at(&self.element_read(stage, x_in), g)
    }

    /// An upper bound of [`Self::element_weight`] at `x_in` (over every `g`; at least 1,
    /// the weight outside the range).
    #[inline]
    pub fn element_bound(&self, stage: Stage, x_in: f64) -> f64 {
        self.element_read(stage, x_in).bound
    }

    /// Where a collision of `stage` at `x_in` reads the element table: found once per
    /// collision, read once per shadow-law proposal ([`Self::weight_at`]).
    #[inline]
    pub fn element_read(&self, stage: Stage, x_in: f64) -> ElementRead {
        let x_in = if x_in.is_nan() { 0.0 } else { x_in };
        let row = stage.0 * X_IN_BINS;
        let (i0, i1, ti) = rows_at(x_in, &self.element_pos[row..row + X_IN_BINS]);
        ElementRead {
            lo: (row + i0) * G_BINS,
            hi: (row + i1) * G_BINS,
            ti,
            x_in: x_in.clamp(X_IN_MIN, X_IN_MAX),
            bound: self.row_max[row + i0].max(self.row_max[row + i1]).max(1.0),
        }
    }

    /// [`Self::element_weight`] of an element of reduced inclination `g` where `read` says.
    #[inline]
    pub fn weight_at(&self, read: &ElementRead, g: f64) -> f64 {
        let s = g - read.x_in;
        if s.is_nan() || !(G_MIN..G_MAX).contains(&s) {
            return 1.0;
        }
        let (g0, g1, tg) = axis(s, G_MIN, DG, G_BINS);
        let w = &self.weight;
        let lo = w[read.lo + g0] + (w[read.lo + g1] - w[read.lo + g0]) * tg;
        let hi = w[read.hi + g0] + (w[read.hi + g1] - w[read.hi + g0]) * tg;
        lo + (hi - lo) * read.ti
    }

    /// The counts the table came from.
    pub fn counts(&self) -> &EscapeCounts {
        &self.counts
    }

    /// The first stage of a collision in an incident plane of roughness angle `delta_gamma`
    /// (radians), given a uniform draw `u` in `[0, 1)`: of the two first stages whose
    /// positions along `Δγ` bracket it, the upper one with probability `t` (the linear
    /// weight between them; clamped at the ends). The particle's first collision then
    /// follows the mixture `(1 − t)·law(lo) + t·law(hi)` exactly, at the cost of one table
    /// read: on the deterministic surface the law at one reduced angle still depends on the
    /// roughness angle itself (docs/models.md).
    #[inline]
    pub fn first_stage(&self, delta_gamma: f64, u: f64) -> Stage {
        let d = delta_gamma.to_degrees();
        let pos = &self.first_pos;
        let k = pos[1..FIRST_STAGES - 1].partition_point(|&p| p <= d);
        let t = (d - pos[k]) / (pos[k + 1] - pos[k]);
        // (A NaN `t` compares false: the lower stage.)
        Stage(if u < t { k + 1 } else { k })
    }

    /// The residual of the transverse inclination of a later collision's element after an
    /// element of residual `z_prev`, from a standard normal draw `n`
    /// ([`super::transverse_memory`]); a first collision has no memory: `n`.
    #[inline]
    pub fn transverse_residual(&self, stage: Stage, z_prev: f64, n: f64) -> f64 {
        match stage.later_index() {
            Some(k) => self.memory.residual(k, z_prev, n),
            None => n,
        }
    }

    /// The transverse memory's slope of a later stage (0 for a first one).
    pub fn transverse_slope(&self, stage: Stage) -> f64 {
        stage.later_index().map_or(0.0, |k| self.memory.slope(k))
    }

    /// The probability of cell `(stage, i_in, i_out)`.
    pub fn cell_p(&self, stage: Stage, i_in: usize, i_out: usize) -> f64 {
        self.p[cell(stage, i_in, i_out)]
    }

    /// The probability that a particle leaves the wall after a collision of `stage` from
    /// reduced incident angle `x_in` with reduced rebound angle `x_out` (bilinear between
    /// the rows' positions along `x_in` and the bin centres along `x_out`, clamped at the
    /// edges; 1 beyond `x_out = 4`, 0 for `x_out ≤ 0`).
    #[inline]
    pub fn p_escape(&self, stage: Stage, x_in: f64, x_out: f64) -> f64 {
        if x_out.is_nan() || x_out <= 0.0 {
            return 0.0;
        }
        if x_out >= X_OUT_MAX {
            return 1.0;
        }
        // A direction with no roughness in its plane has no reduced angle (0/0).
        let x_in = if x_in.is_nan() { 0.0 } else { x_in };
        let row = stage.0 * X_IN_BINS;
        let (i0, i1, ti) = rows_at(x_in, &self.escape_pos[row..row + X_IN_BINS]);
        let (o0, o1, to) = axis(x_out, 0.0, DX_OUT, X_OUT_BINS);
        let at = |i, o| self.p[cell(stage, i, o)];
        let lo = at(i0, o0) + (at(i0, o1) - at(i0, o0)) * to;
        let hi = at(i1, o0) + (at(i1, o1) - at(i1, o0)) * to;
        lo + (hi - lo) * ti
    }

    /// The table as a file: the magic line, `# source:`, then one row per cell.
    pub fn to_csv(&self) -> String {
        let mut s = format!("{MAGIC}\n# source: {}\n{HEADER}\n", self.source);
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_out in 0..X_OUT_BINS {
                    let c = cell(stage, i_in, i_out);
                    s.push_str(&format!(
                        "{},{:.4},{:.3},{},{},{:.6}\n",
                        stage.name(),
                        centre_in(i_in),
                        (i_out as f64 + 0.5) * DX_OUT,
                        self.counts.collisions[c],
                        self.counts.escaped[c],
                        self.p[c]
                    ));
                }
            }
        }
        s.push_str(ELEMENT_HEADER);
        s.push('\n');
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_g in 0..G_BINS {
                    let c = (stage.0 * X_IN_BINS + i_in) * G_BINS + i_g;
                    s.push_str(&format!(
                        "{},{:.4},{:.3},{},{},{:.6}\n",
                        stage.name(),
                        centre_in(i_in),
                        G_MIN + (i_g as f64 + 0.5) * DG,
                        self.counts.element_deterministic[c],
                        self.counts.element_model[c],
                        self.weight[c]
                    ));
                }
            }
        }
        s.push_str(ROW_HEADER);
        s.push('\n');
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                let r = stage.0 * X_IN_BINS + i_in;
                s.push_str(&format!(
                    "{},{:.4},{},{:.6},{},{:.6}\n",
                    stage.name(),
                    centre_in(i_in),
                    self.counts.escape_x_sum[r],
                    self.escape_pos[r],
                    self.counts.element_x_sum[r],
                    self.element_pos[r]
                ));
            }
        }
        s.push_str(FIRST_HEADER);
        s.push('\n');
        for k in 0..FIRST_STAGES {
            s.push_str(&format!(
                "{},{},{},{:.6}\n",
                Stage(k).name(),
                self.counts.first_count[k],
                self.counts.first_dg_sum[k],
                self.first_pos[k]
            ));
        }
        s.push_str(TRANSVERSE_HEADER);
        s.push('\n');
        let t = &self.counts.transverse;
        for k in 0..LATER_STAGES {
            s.push_str(&format!(
                "{},{},{},{},{:.6},{:.6}\n",
                Stage(FIRST_STAGES + k).name(),
                t.pairs[k],
                t.prev_sq_sum[k],
                t.cross_sum[k],
                self.memory.slope(k),
                self.memory.fresh(k)
            ));
        }
        s
    }

    /// Reads a table written by [`EscapeTable::to_csv`]; `what` names it in errors. The
    /// probabilities are recomputed from the counts, and every row is checked against the
    /// grid: a malformed or mismatched table is a one-line error.
    pub fn parse(text: &str, what: &str) -> Result<EscapeTable> {
        let bad = |line: usize, msg: &str| Error::Input(format!("{what}, line {line}: {msg}"));
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim_end()));
        match lines.next() {
            Some((_, l)) if l == MAGIC => {}
            // Another version of the format: say so, rather than "not a table".
            Some((_, l)) if l.starts_with(MAGIC_STEM) => {
                return Err(Error::Input(format!(
                    "{what}: an escape table of another format (`{l}`); this version reads `{MAGIC}`: run `rebound calibrate` again"
                )))
            }
            _ => {
                return Err(Error::Input(format!(
                    "{what}: not an escape table (the first line must be `{MAGIC}`; `rebound calibrate` writes one)"
                )))
            }
        }
        let source = match lines.next() {
            Some((_, l)) if l.starts_with("# source: ") => l["# source: ".len()..].to_string(),
            Some((n, _)) => return Err(bad(n, "expected `# source: …`")),
            None => return Err(bad(2, "expected `# source: …`")),
        };
        let header = |got: Option<(usize, &str)>, want: &str, after: &str| match got {
            Some((_, l)) if l == want => Ok(()),
            Some((n, _)) => Err(bad(n, &format!("expected the header `{want}`"))),
            None => Err(Error::Input(format!(
                "{what}: truncated {after} (expected the header `{want}`)"
            ))),
        };
        header(lines.next(), HEADER, "after the source line")?;
        let mut counts = EscapeCounts::default();
        let mut written_p = vec![0.0; CELLS];
        let mut rows = 0usize;
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_out in 0..X_OUT_BINS {
                    let cell_x = (i_out as f64 + 0.5) * DX_OUT;
                    let (n, l) = lines.next().ok_or_else(|| {
                        Error::Input(format!(
                            "{what}: truncated after {rows} of {CELLS} rows (the grid is {SLICES} stages × {X_IN_BINS} × {X_OUT_BINS})"
                        ))
                    })?;
                    let (c, e, p) =
                        parse_row(l, stage, i_in, ("x_out", cell_x)).map_err(|m| bad(n, &m))?;
                    if e > c {
                        return Err(bad(n, &format!("{e} escapes out of {c} collisions")));
                    }
                    if !(0.0..=1.0).contains(&p) {
                        return Err(bad(n, &format!("p_escape = {p} is not in [0, 1]")));
                    }
                    let k = cell(stage, i_in, i_out);
                    (counts.collisions[k], counts.escaped[k], written_p[k]) = (c, e, p);
                    rows += 1;
                }
            }
        }
        header(
            lines.next(),
            ELEMENT_HEADER,
            &format!("after the {CELLS} escape rows"),
        )?;
        let mut written_w = vec![0.0; ELEMENT_CELLS];
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_g in 0..G_BINS {
                    let k = (stage.0 * X_IN_BINS + i_in) * G_BINS + i_g;
                    let cell_g = G_MIN + (i_g as f64 + 0.5) * DG;
                    let (n, l) = lines.next().ok_or_else(|| {
                        Error::Input(format!(
                            "{what}: truncated after {k} of {ELEMENT_CELLS} element rows"
                        ))
                    })?;
                    let (d, m, w) =
                        parse_row(l, stage, i_in, ("s", cell_g)).map_err(|m| bad(n, &m))?;
                    if w < 0.0 {
                        return Err(bad(n, &format!("weight = {w} is negative")));
                    }
                    (
                        counts.element_deterministic[k],
                        counts.element_model[k],
                        written_w[k],
                    ) = (d, m, w);
                }
            }
        }
        header(
            lines.next(),
            ROW_HEADER,
            &format!("after the {ELEMENT_CELLS} element rows"),
        )?;
        let (mut written_escape_pos, mut written_element_pos) = (vec![0.0; ROWS], vec![0.0; ROWS]);
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                let r = stage.0 * X_IN_BINS + i_in;
                let (n, l) = lines.next().ok_or_else(|| {
                    Error::Input(format!("{what}: truncated after {r} of {ROWS} x_in rows"))
                })?;
                let f = parse_position_row(l, stage, i_in).map_err(|m| bad(n, &m))?;
                (
                    counts.escape_x_sum[r],
                    written_escape_pos[r],
                    counts.element_x_sum[r],
                    written_element_pos[r],
                ) = f;
            }
        }
        header(
            lines.next(),
            FIRST_HEADER,
            &format!("after the {ROWS} x_in rows"),
        )?;
        let mut written_first_pos = vec![0.0; FIRST_STAGES];
        for (k, pos) in written_first_pos.iter_mut().enumerate() {
            let (n, l) = lines.next().ok_or_else(|| {
                Error::Input(format!(
                    "{what}: truncated after {k} of {FIRST_STAGES} first-stage rows"
                ))
            })?;
            let f = parse_first_row(l, Stage(k)).map_err(|m| bad(n, &m))?;
            (counts.first_count[k], counts.first_dg_sum[k], *pos) = f;
        }
        header(
            lines.next(),
            TRANSVERSE_HEADER,
            &format!("after the {FIRST_STAGES} first-stage rows"),
        )?;
        let (mut written_slope, mut written_fresh) =
            (vec![0.0; LATER_STAGES], vec![0.0; LATER_STAGES]);
        for k in 0..LATER_STAGES {
            let (n, l) = lines.next().ok_or_else(|| {
                Error::Input(format!(
                    "{what}: truncated after {k} of {LATER_STAGES} transverse rows"
                ))
            })?;
            let t = &mut counts.transverse;
            let f = parse_transverse_row(l, Stage(FIRST_STAGES + k)).map_err(|m| bad(n, &m))?;
            (
                t.pairs[k],
                t.prev_sq_sum[k],
                t.cross_sum[k],
                written_slope[k],
                written_fresh[k],
            ) = f;
            if !plausible(t.pairs[k], t.prev_sq_sum[k], t.cross_sum[k]) {
                return Err(bad(
                    n,
                    &format!(
                        "sums {} and {} cannot come from {} pairs of residuals within ±{Z_MAX} (0 ≤ z_prev² sum ≤ {MAX_TERM} per pair, |cross sum| as large)",
                        t.prev_sq_sum[k], t.cross_sum[k], t.pairs[k]
                    ),
                ));
            }
        }
        if let Some((n, _)) = lines.find(|(_, l)| !l.is_empty()) {
            return Err(bad(n, "more rows than the grid has"));
        }
        let table = EscapeTable::from_counts(counts, &source);
        // The written values must be the ones the counts give (a hand-edited or corrupted
        // table is refused rather than silently recomputed).
        // Compared as written (six decimals): a value on a rounding boundary must not differ
        // by the last bit of a subtraction. A written value on the six-decimal grid within
        // 4.5·10⁻⁷ of its computed one is that value rounded (the next grid value is at least
        // 5.5·10⁻⁷ away), so only the others are formatted: this keeps a host's start-up
        // short. (A hand-written value with more decimals is off the grid: formatted.)
        let edited = |kind: &str, written: &[f64], computed: &[f64]| {
            (0..written.len())
                .find(|&k| {
                    let (w, c) = (written[k], computed[k]);
                    // (A NaN difference is not close: formatted.)
                    let micro = w * 1e6;
                    let close = (micro - micro.round()).abs() < 1e-3 && (w - c).abs() < 4.5e-7;
                    !close && format!("{w:.6}") != format!("{c:.6}")
                })
                .map(|k| {
                    Error::Input(format!(
                        "{what}: {kind} row {} gives {} but its counts give {:.6} (edited or corrupted)",
                        k + 1,
                        written[k],
                        computed[k]
                    ))
                })
        };
        if let Some(e) = edited("escape", &written_p, &table.p) {
            return Err(e);
        }
        if let Some(e) = edited("element", &written_w, &table.weight) {
            return Err(e);
        }
        if let Some(e) = edited("escape position", &written_escape_pos, &table.escape_pos) {
            return Err(e);
        }
        if let Some(e) = edited("element position", &written_element_pos, &table.element_pos) {
            return Err(e);
        }
        // A row's mean must lie in its bin (else the positions do not increase).
        for (kind, pos) in [
            ("escape", &table.escape_pos),
            ("element", &table.element_pos),
        ] {
            if let Some(r) = (0..ROWS).find(|&r| {
                let i = r % X_IN_BINS;
                !(X_IN_EDGES[i]..=X_IN_EDGES[i + 1]).contains(&pos[r])
            }) {
                return Err(Error::Input(format!(
                    "{what}: the {kind} x_in sum of row {} puts its mean at {} outside its bin (edited or corrupted)",
                    r + 1,
                    pos[r]
                )));
            }
        }
        if let Some(e) = edited("first-stage position", &written_first_pos, &table.first_pos) {
            return Err(e);
        }
        let slopes: Vec<f64> = (0..LATER_STAGES).map(|k| table.memory.slope(k)).collect();
        if let Some(e) = edited("transverse slope", &written_slope, &slopes) {
            return Err(e);
        }
        let fresh: Vec<f64> = (0..LATER_STAGES).map(|k| table.memory.fresh(k)).collect();
        if let Some(e) = edited("transverse fresh", &written_fresh, &fresh) {
            return Err(e);
        }
        if table.counts.total() == 0 {
            return Err(Error::Input(format!("{what}: no collisions counted")));
        }
        Ok(table)
    }

    /// The table shipped with the library: calibrated by `rebound calibrate --case
    /// calibration/aniso.toml` on the (Δξ, Δζ) = (2.5°, 7.5°) wall of Radenkovic & Simonin
    /// 2021, Sec. 3 (`scripts/calibrate.sh` regenerates it byte for byte).
    pub fn builtin() -> &'static EscapeTable {
        static T: OnceLock<EscapeTable> = OnceLock::new();
        T.get_or_init(|| {
            EscapeTable::parse(BUILTIN, "the built-in escape table")
                .expect("the built-in escape table is checked by a test")
        })
    }

    /// A `'static` copy of `self`, shared by every wall built with an equal table: wall
    /// models are `Copy` and hold a reference, and a host building many walls from one
    /// table keeps one copy. (Each distinct table is kept for the life of the process.)
    pub fn intern(self) -> &'static EscapeTable {
        static TABLES: Mutex<Vec<&'static EscapeTable>> = Mutex::new(Vec::new());
        if self == *EscapeTable::builtin() {
            return EscapeTable::builtin();
        }
        let mut v = TABLES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(t) = v.iter().find(|t| ***t == self) {
            return t;
        }
        let t: &'static EscapeTable = Box::leak(Box::new(self));
        v.push(t);
        t
    }
}

/// The built-in table's text.
pub const BUILTIN: &str = include_str!("../../configs/calibration/aniso-escape.csv");

/// A table row's fields (six for a cell or an `x_in` row, checked by [`Fields::of`]; four for
/// a first-stage row, checked by [`parse_first_row`]; six for a transverse row, checked by
/// [`parse_transverse_row`]).
struct Fields<'a>(Vec<&'a str>);

impl<'a> Fields<'a> {
    fn of(line: &'a str) -> std::result::Result<Self, String> {
        let f: Vec<&str> = line.split(',').collect();
        match f.len() {
            6 => Ok(Fields(f)),
            n => Err(format!("{n} fields, expected 6")),
        }
    }

    /// Field `j` as a finite number.
    fn num(&self, j: usize) -> std::result::Result<f64, String> {
        self.0[j]
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("`{}` is not a number", self.0[j]))
    }

    /// Field `j` as a count.
    fn count(&self, j: usize) -> std::result::Result<u64, String> {
        self.0[j]
            .parse::<u64>()
            .map_err(|_| format!("`{}` is not a non-negative integer", self.0[j]))
    }

    /// Field `j` as a signed integer.
    fn int(&self, j: usize) -> std::result::Result<i64, String> {
        self.0[j]
            .parse::<i64>()
            .map_err(|_| format!("`{}` is not an integer", self.0[j]))
    }

    /// Checks that the row is the one the fixed grid has here: its stage, its `x_in` bin
    /// centre and, for a cell, the centre along its second axis (field 2).
    fn at(
        &self,
        stage: Stage,
        i_in: usize,
        axis: Option<(&str, f64)>,
    ) -> std::result::Result<(), String> {
        let (stage, x_in) = (stage.name(), centre_in(i_in));
        let axis_ok = match axis {
            Some((_, v)) => (self.num(2)? - v).abs() <= 1e-9,
            None => true,
        };
        if self.0[0] == stage && (self.num(1)? - x_in).abs() <= 1e-9 && axis_ok {
            return Ok(());
        }
        let what = match axis {
            Some((name, v)) => format!("the cell ({stage}, x_in = {x_in}, {name} = {v})"),
            None => format!("the row ({stage}, x_in = {x_in})"),
        };
        Err(format!(
            "expected {what}: the table does not match this version's grid"
        ))
    }
}

/// One row `stage,x_in,<axis>,count,count,value` of a table: checked against the cell it
/// must be (the grid is fixed), the two counts and the value; the error without the line.
fn parse_row(
    line: &str,
    stage: Stage,
    i_in: usize,
    axis: (&str, f64),
) -> std::result::Result<(u64, u64, f64), String> {
    let f = Fields::of(line)?;
    f.at(stage, i_in, Some(axis))?;
    Ok((f.count(3)?, f.count(4)?, f.num(5)?))
}

/// One row `stage,x_in,sum,position,sum,position` of the `x_in` rows' block:
/// checked against the row it must be; the two sums and the two positions.
fn parse_position_row(
    line: &str,
    stage: Stage,
    i_in: usize,
) -> std::result::Result<(i64, f64, i64, f64), String> {
    let f = Fields::of(line)?;
    f.at(stage, i_in, None)?;
    Ok((f.int(2)?, f.num(3)?, f.int(4)?, f.num(5)?))
}

/// One row `stage,count,sum,position` of the first stages' block: checked against the
/// stage it must be; the count, the `Δγ` sum and the position.
fn parse_first_row(line: &str, stage: Stage) -> std::result::Result<(u64, i64, f64), String> {
    let f = Fields(line.split(',').collect());
    if f.0.len() != 4 || f.0[0] != stage.name() {
        return Err(format!(
            "expected the first-stage row `{},<collisions>,<Δγ sum>,<position>`: the table does not match this version's grid",
            stage.name()
        ));
    }
    Ok((f.count(1)?, f.int(2)?, f.num(3)?))
}

/// One row `stage,pairs,sum,sum,slope,fresh` of the transverse block: checked against the
/// stage it must be; the count, the two sums, the slope and the fresh part's spread.
fn parse_transverse_row(
    line: &str,
    stage: Stage,
) -> std::result::Result<(u64, i64, i64, f64, f64), String> {
    let f = Fields(line.split(',').collect());
    if f.0.len() != 6 || f.0[0] != stage.name() {
        return Err(format!(
            "expected the transverse row `{},<pairs>,<z_prev² sum>,<cross sum>,<slope>,<fresh>`: the table does not match this version's grid",
            stage.name()
        ));
    }
    Ok((f.count(1)?, f.int(2)?, f.int(3)?, f.num(4)?, f.num(5)?))
}

/// Bins `(lo, hi)` and the weight of `hi` for a bilinear read at `x` (centres at
/// `min + (i + ½) dx`, clamped).
#[inline]
fn axis(x: f64, min: f64, dx: f64, bins: usize) -> (usize, usize, f64) {
    let t = ((x - min) / dx - 0.5).clamp(0.0, (bins - 1) as f64);
    // `t ≥ 0`: truncation is its floor, without a libm call on the hot path.
    let i = (t as usize).min(bins - 2);
    (i, i + 1, t - i as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wall() -> Deviations {
        Deviations {
            delta_xi: 0.05,
            delta_zeta: 0.12,
        }
    }

    #[test]
    fn the_builtin_table_parses_and_is_a_probability() {
        let t = EscapeTable::builtin();
        assert!(t.counts().total() > 1_000_000);
        for stage in Stage::all() {
            for x_in in [-7.0, -3.3, -0.1, 0.0, 0.4, 2.0, 9.0] {
                let mut last = 0.0;
                for k in 0..=90 {
                    let x_out = k as f64 * 0.05;
                    let p = t.p_escape(stage, x_in, x_out);
                    assert!((0.0..=1.0).contains(&p), "{p}");
                    // (The later stage is sparse and noisier: range only.)
                    if stage.is_first() && k > 0 && x_out < 3.0 {
                        // Steeper rebounds escape more often (up to the counting noise).
                        assert!(
                            p > last - 0.08,
                            "{stage:?} {x_in} {x_out}: {p} after {last}"
                        );
                    }
                    last = p;
                }
            }
        }
        assert_eq!(t.p_escape(Stage::FIRST, -1.0, 0.0), 0.0);
        assert_eq!(t.p_escape(Stage::FIRST, -1.0, -0.3), 0.0);
        assert_eq!(t.p_escape(Stage::FIRST, -1.0, 4.0), 1.0);
        assert!(t.p_escape(Stage::FIRST, f64::NAN, 1.0).is_finite());
    }

    #[test]
    fn counts_round_trip_through_the_file_exactly() {
        let mut c = EscapeCounts::default();
        let w = wall();
        let u_in = Vector3::new(1.0, -0.1, 0.3);
        for k in 0..2000 {
            let a = 0.001 + 0.0004 * k as f64;
            let u_out = Vector3::new(a.cos(), a.sin(), 0.1);
            let stage = if k % 3 == 0 {
                Stage::later(-2.0 + 0.001 * k as f64)
            } else {
                Stage::FIRST
            };
            c.push(stage, &u_in, &u_out, &w, k % 5 != 0);
            let g = -1.0 + 0.004 * k as f64;
            c.push_element(stage, -1.2, g, g + 0.3);
            let z = (k as f64 * 0.01).sin();
            c.push_transverse(stage, z, 0.3 * z);
            c.push_transverse(Stage::later(-1.0), z, 0.3 * z);
        }
        assert_eq!(c.transverse.pairs.iter().sum::<u64>(), 2667);
        let t = EscapeTable::from_counts(c.clone(), "test");
        assert!(t.transverse_slope(Stage::later(-1.0)) > 0.29);
        assert_eq!(t.transverse_slope(Stage::FIRST), 0.0);
        assert_eq!(t.transverse_residual(Stage::FIRST, 2.0, 0.5), 0.5);
        let back = EscapeTable::parse(&t.to_csv(), "t").unwrap();
        assert_eq!(back, t);
        assert_eq!(back.counts(), &c);
        assert_eq!(back.to_csv(), t.to_csv());
    }

    #[test]
    fn bilinear_reading_hits_the_cell_centres() {
        let mut c = EscapeCounts::default();
        // One populated cell column: x_in bin 10, every x_out bin, p = i_out/40.
        for i_out in 0..X_OUT_BINS {
            let k = cell(Stage::FIRST, 10, i_out);
            c.collisions[k] = 400;
            c.escaped[k] = 10 * i_out as u64;
        }
        let t = EscapeTable::from_counts(c.at_centres(), "t");
        let x_in = centre_in(10);
        for i_out in 0..X_OUT_BINS {
            let x_out = (i_out as f64 + 0.5) * DX_OUT;
            let p = t.p_escape(Stage::FIRST, x_in, x_out);
            assert!((p - i_out as f64 / 40.0).abs() < 1e-12);
        }
        // Half way between two centres: the mean; sparse bins take the populated one's value,
        // and the later stages (empty) the first stage's.
        let p = t.p_escape(Stage::later(0.0), -5.9, 1.0);
        assert!((p - 0.5 * (9.0 + 10.0) / 40.0).abs() < 1e-12, "{p}");
        // A later stage without counts of its own takes the later stages' pooled ones.
        let mut c = EscapeCounts::default();
        for i_out in 0..X_OUT_BINS {
            c.collisions[cell(Stage::later(-2.0), 10, i_out)] = 400;
            c.escaped[cell(Stage::later(-2.0), 10, i_out)] = 100;
            c.collisions[cell(Stage::later(1.0), 10, i_out)] = 400;
            c.escaped[cell(Stage::later(1.0), 10, i_out)] = 300;
            c.collisions[cell(Stage::later(-1.0), 10, i_out)] = 20;
        }
        let t = EscapeTable::from_counts(c.at_centres(), "t");
        assert!((t.p_escape(Stage::later(-2.0), x_in, 1.0) - 0.25).abs() < 1e-12);
        assert!((t.p_escape(Stage::later(1.0), x_in, 1.0) - 0.75).abs() < 1e-12);
        let pooled = t.p_escape(Stage::later(-1.0), x_in, 1.0);
        assert!((pooled - 400.0 / 820.0).abs() < 1e-12, "{pooled}");
    }

    #[test]
    fn later_stages_are_binned_by_the_element_just_left() {
        assert_eq!(Stage::later(-1.7), Stage::later(-1.3));
        assert_ne!(Stage::later(-1.3), Stage::later(-1.2));
        assert_ne!(Stage::later(-1.8), Stage::later(-1.7));
        assert_eq!(Stage::later(-9.0), Stage::later(-2.8));
        assert_eq!(Stage::later(f64::NAN), Stage::later(0.0));
        assert_eq!(Stage::later(f64::INFINITY), Stage::later(9.0));
        let names: Vec<String> = Stage::all().map(|s| s.name()).collect();
        assert_eq!(
            names,
            [
                "first-d0", "first-d1", "first-d2", "later-q0", "later-q1", "later-q2", "later-q3",
                "later-q4", "later-q5", "later-q6"
            ]
        );
        assert!(Stage::all()
            .filter(|s| s.is_first())
            .eq([Stage(0), Stage(1), Stage(2)]));
        assert!(!Stage::later(-9.0).is_first());
    }

    /// The model reads a first collision's stage by its plane's `Δγ`: with a table whose
    /// roughest first stage never lets a particle leave after its first collision (but for
    /// rebounds beyond `x_out = 4`, which always leave), a wall rougher than that stage's
    /// position loses its single collisions, one below the middle position keeps them, and
    /// half way between the two upper positions half of them are lost.
    #[test]
    fn the_model_reads_the_first_stage_of_its_roughness_angle() {
        use crate::collision::CollisionLaw;
        use crate::stochastic::rebound_model::rebound_variant;
        use crate::stochastic::Variant;
        use rand::SeedableRng;
        let deg = f64::to_radians;
        let table = |trap_roughest: bool| -> &'static EscapeTable {
            let mut c = EscapeCounts::default();
            for k in 0..SLICES {
                for i in 0..X_IN_BINS {
                    for o in 0..X_OUT_BINS {
                        let j = cell(Stage(k), i, o);
                        c.collisions[j] = 400;
                        c.escaped[j] = if trap_roughest && k == 2 { 0 } else { 400 };
                    }
                }
            }
            for d in [3.0, 5.0, 7.0] {
                c.push_first(deg(d));
            }
            EscapeTable::from_counts(c.at_centres(), "stages").intern()
        };
        let single = |t: &'static EscapeTable, d: f64| {
            let wall = Deviations {
                delta_xi: deg(d),
                delta_zeta: deg(d),
            };
            // The same reduced incidence on every wall.
            let u = crate::angles::velocity_from_angles(1.0, -0.3 * deg(d), 0.0);
            let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(4);
            let n = 20_000;
            let v = Variant::calibrated(Some(t));
            (0..n)
                .filter(|_| {
                    let law = CollisionLaw::Elastic;
                    rebound_variant(u, Vector3::zeros(), &wall, &law, 2.0, 1e-4, v, &mut rng)
                        .candidates
                        == 1
                })
                .count() as f64
                / n as f64
        };
        let (trap, free) = (table(true), table(false));
        // (A first rebound into the mean wall is trapped whatever the table says.)
        assert!(single(free, 8.0) > 0.8, "{}", single(free, 8.0));
        let steep = single(trap, 8.0) / single(free, 8.0);
        assert!(steep < 0.25, "{steep}");
        assert_eq!(single(trap, 4.0), single(free, 4.0));
        // The stage is read at the slope spread along the path (`slope_space`), a little
        // above the angle's: t of the upper stage between the positions 5 and 7.
        let sigma = crate::stochastic::slope_space::slope_deviations(&Deviations {
            delta_xi: deg(6.0),
            delta_zeta: deg(6.0),
        })
        .delta_xi
        .to_degrees();
        let t = (sigma - 5.0) / 2.0;
        assert!(t > 0.5 && t < 0.6, "{sigma}");
        let half = single(trap, 6.0) / single(free, 6.0);
        assert!(
            (half - ((1.0 - t) + t * steep)).abs() < 0.03,
            "{half} ({steep}, {t})"
        );
    }

    #[test]
    fn first_collisions_are_binned_and_read_by_the_roughness_angle() {
        let deg = f64::to_radians;
        assert_eq!(Stage::first(deg(2.5)), Stage::FIRST);
        assert_eq!(Stage::first(deg(4.49)), Stage::FIRST);
        assert_eq!(Stage::first(deg(4.5)), Stage(1));
        assert_eq!(Stage::first(deg(7.5)), Stage(2));
        assert_eq!(Stage::first(f64::NAN), Stage::FIRST);
        // Three first stages with different escape probabilities in one cell column, their
        // collisions at mean Δγ 3°, 5° and 7°.
        let mut c = EscapeCounts::default();
        for (k, (d, escaped)) in [(3.0, 100), (5.0, 200), (7.0, 300)].into_iter().enumerate() {
            for i_out in 0..X_OUT_BINS {
                c.collisions[cell(Stage(k), 10, i_out)] = 400;
                c.escaped[cell(Stage(k), 10, i_out)] = escaped;
            }
            for _ in 0..4 {
                c.push_first(deg(d));
            }
        }
        let t = EscapeTable::from_counts(c.at_centres(), "t");
        let x_in = centre_in(10);
        // The mixture's escape probability over a uniform grid of draws.
        let n = 10_000;
        let p = |d: f64| {
            (0..n)
                .map(|i| {
                    t.p_escape(
                        t.first_stage(deg(d), (i as f64 + 0.5) / n as f64),
                        x_in,
                        1.0,
                    )
                })
                .sum::<f64>()
                / n as f64
        };
        // At a stage's position its own value, between two positions the linear blend,
        // beyond the ends the end stage's value.
        for (d, want) in [
            (3.0, 0.25),
            (5.0, 0.5),
            (7.0, 0.75),
            (4.0, 0.375),
            (6.5, 0.6875),
            (1.0, 0.25),
            (9.0, 0.75),
        ] {
            assert!((p(d) - want).abs() < 1e-4, "{d}: {} against {want}", p(d));
        }
        assert!(p(f64::NAN).is_finite());
        // Round trip; a position is kept inside its bin (so positions increase), and one
        // that is not what its sum gives is refused.
        let text = t.to_csv();
        assert_eq!(EscapeTable::parse(&text, "t").unwrap(), t);
        let mut c = EscapeCounts::default();
        c.first_count[0] = 1;
        c.first_dg_sum[0] = 9_000_000;
        c.collisions[0] = 1;
        assert_eq!(
            EscapeTable::from_counts(c, "edge").first_pos[0],
            FIRST_DG_EDGES_DEG[0] - DG_SUM_UNIT
        );
        let bad = text.replace(
            "first-d0,4,12000000,3.000000",
            "first-d0,4,12000000,3.500000",
        );
        assert_ne!(bad, text);
        let err = EscapeTable::parse(&bad, "t").unwrap_err().to_string();
        assert!(
            err.contains("first-stage position") && err.contains("edited or corrupted"),
            "{err}"
        );
    }

    #[test]
    fn malformed_or_mismatched_tables_are_one_line_errors() {
        let good = EscapeTable::builtin().to_csv();
        let lines: Vec<&str> = good.lines().collect();
        let edit = |k: usize, to: &str| {
            let mut l = lines.clone();
            l[k] = to;
            l.join("\n")
        };
        let row = lines[10];
        let fields: Vec<&str> = row.split(',').collect();
        // Row 10 with field `k` replaced.
        let field = |k: usize, v: &str| {
            let mut f = fields.clone();
            f[k] = v;
            edit(10, &f.join(","))
        };
        let cases: Vec<(String, &str)> = vec![
            (String::new(), "not an escape table"),
            (good.replacen("v9", "v8", 1), "another format"),
            (
                good.replacen("# roughwall", "# other", 1),
                "not an escape table",
            ),
            (edit(1, "source"), "# source"),
            (edit(2, "a,b"), "header"),
            (lines[..100].join("\n"), "truncated after 97"),
            (edit(10, "first,1,2"), "3 fields"),
            (field(0, "later-q0"), "does not match this version's grid"),
            (field(1, "-0.3125"), "does not match this version's grid"),
            (field(2, "9.999"), "does not match"),
            (field(3, "x"), "`x` is not a non-negative integer"),
            (
                edit(10, &format!("{},1,2,0.5", fields[..3].join(","))),
                "2 escapes out of 1",
            ),
            (field(5, "1.5"), "not in [0, 1]"),
            (field(5, "nan"), "`nan` is not a number"),
            (
                format!("{good}first,0,0,0,0,0\n"),
                "more rows than the grid",
            ),
        ];
        // Line `row` with field `k` replaced.
        let field_of = |row: usize, k: usize, v: &str| {
            let mut f: Vec<&str> = lines[row].split(',').collect();
            f[k] = v;
            edit(row, &f.join(","))
        };
        // The rows' block: its first row with field `k` replaced.
        let first_row = lines.iter().position(|l| *l == ROW_HEADER).unwrap() + 1;
        let row_field = |k: usize, v: &str| field_of(first_row, k, v);
        let truncated = format!("truncated after 3 of {ROWS} x_in rows");
        let cases: Vec<(String, &str)> = cases
            .into_iter()
            .chain([
                (edit(first_row, "first,1"), "2 fields"),
                (row_field(2, "1.5"), "`1.5` is not an integer"),
                (row_field(3, "x"), "`x` is not a number"),
                (
                    row_field(1, "-5.2500"),
                    "does not match this version's grid",
                ),
                (lines[..first_row + 3].join("\n"), &truncated),
            ])
            .collect();
        // The transverse block: its first row with field `k` replaced.
        let t_row = lines.iter().position(|l| *l == TRANSVERSE_HEADER).unwrap() + 1;
        let t_field = |k: usize, v: &str| field_of(t_row, k, v);
        let t_truncated = format!("truncated after 2 of {LATER_STAGES} transverse rows");
        let cases: Vec<(String, &str)> = cases
            .into_iter()
            .chain([
                (
                    edit(t_row, "later-q0,1,2,3,4"),
                    "expected the transverse row",
                ),
                (t_field(0, "later-q1"), "expected the transverse row"),
                (t_field(1, "-1"), "not a non-negative integer"),
                (t_field(2, "-5"), "cannot come from"),
                (t_field(1, "0"), "cannot come from"),
                (t_field(4, "0.123457"), "transverse slope row 1 gives"),
                (t_field(5, "0.123457"), "transverse fresh row 1 gives"),
                // More pairs for the same sums: the slope is the same, the fresh part not.
                (t_field(1, "98789"), "transverse fresh row 1 gives"),
                (lines[..t_row + 2].join("\n"), &t_truncated),
                (
                    lines[..t_row - 1].join("\n"),
                    "after the 3 first-stage rows",
                ),
            ])
            .collect();
        for (text, needle) in cases {
            let e = match EscapeTable::parse(&text, "`stochastic.escape_table` = \"t.csv\"") {
                Ok(_) => panic!("accepted a bad table (wanted {needle})"),
                Err(e) => e.to_string(),
            };
            assert!(e.contains(needle), "{e} (wanted {needle})");
            assert!(e.contains("t.csv"), "{e}");
            assert!(!e.contains('\n'), "{e}");
        }
        // A probability that disagrees with its counts (hand-edited): refused.
        let k = (3..3 + CELLS)
            .find(|&k| {
                let f: Vec<&str> = lines[k].split(',').collect();
                f[3].parse::<u64>().unwrap() >= MIN_COUNT && f[5] != "0.999999"
            })
            .unwrap();
        let f: Vec<&str> = lines[k].split(',').collect();
        let e = EscapeTable::parse(&edit(k, &format!("{},0.999999", f[..5].join(","))), "t");
        match e {
            Ok(_) => panic!("accepted an edited table"),
            Err(e) => assert!(e.to_string().contains("edited or corrupted"), "{e}"),
        }
    }

    #[test]
    fn element_weights_are_the_count_ratio_and_bounded() {
        let mut c = EscapeCounts::default();
        // Row x_in ∈ [−1.5, −1.25), centre −1.375: the deterministic run saw twice the shadow
        // law's count above s = γ/Δγ − x_in = 1.375 (g = 0 at the centre) and the same below.
        for k in 0..200 {
            let s = 0.02 * k as f64 + 0.01;
            let n = if s > 1.375 {
                2 * ELEMENT_MIN_COUNT
            } else {
                ELEMENT_MIN_COUNT
            };
            let cell = element_cell(Stage::FIRST, -1.375, s - 1.375).unwrap();
            c.element_deterministic[cell] = n;
            c.element_model[cell] = ELEMENT_MIN_COUNT;
        }
        // Out of reach (s < 0) and beyond the range: no cell.
        assert_eq!(element_cell(Stage::FIRST, -1.375, -1.45), None);
        assert_eq!(element_cell(Stage::FIRST, -1.375, 9.0), None);
        let t = EscapeTable::from_counts(c.at_centres(), "w");
        assert!((t.element_weight(Stage::FIRST, -1.375, 1.05) - 2.0).abs() < 1e-12);
        assert!((t.element_weight(Stage::FIRST, -1.375, -0.5) - 1.0).abs() < 1e-12);
        // Empty cells and the other stages keep the shadow law; outside the range too.
        assert_eq!(t.element_weight(Stage::later(0.0), -1.375, 1.05), 1.0);
        assert_eq!(t.element_weight(Stage::FIRST, -1.375, 9.0), 1.0);
        assert!(t.element_bound(Stage::FIRST, -1.375) >= 2.0);
        for k in 0..400 {
            let (x, g) = (-3.0 + 0.01 * k as f64, -4.0 + 0.025 * k as f64);
            assert!(
                t.element_weight(Stage::FIRST, x, g) <= t.element_bound(Stage::FIRST, x) + 1e-12
            );
        }
    }

    /// A sparse cell takes the ratio of the narrowest window around it that holds enough
    /// draws, so the shadow law's thin tail keeps the trend of its dense neighbours instead of
    /// jumping back to 1; a row with too few draws in all keeps the shadow law.
    #[test]
    fn sparse_element_cells_take_their_window_ratio() {
        let n = ELEMENT_MIN_COUNT;
        // A dense cell stands alone.
        assert_eq!(window_ratio(&[3 * n, 0, 0], &[2 * n, 0, 0], 0), Some(1.5));
        // The tail: cell 3 has 100 draws; the window 2..=4 (clipped at the row's end: 2..=3
        // and then 1..=3) first holds enough at 1..=3.
        let d = [0, n / 2, n / 4, 30];
        let m = [0, n, n / 2, 100];
        let r = window_ratio(&d, &m, 3).unwrap();
        let want = (n / 2 + n / 4 + 30) as f64 / (n + n / 2 + 100) as f64;
        assert_eq!(r, want);
        assert!(r < 0.6, "{r}");
        // Too few in the whole row: the shadow law.
        assert_eq!(window_ratio(&[5, 5, 5], &[10, 10, 10], 1), None);
        // Through the table: a thin tail beyond s = 4 keeps the dense cells' ratio 0.5.
        let mut c = EscapeCounts::default();
        for k in 0..125 {
            let s = (k as f64 + 0.5) * DG;
            let cell = element_cell(Stage::FIRST, -1.375, s - 1.375).unwrap();
            let m = if s < 4.0 { 4 * n } else { 10 };
            c.element_model[cell] = m;
            c.element_deterministic[cell] = m / 2;
        }
        let t = EscapeTable::from_counts(c.at_centres(), "tail");
        assert!((t.element_weight(Stage::FIRST, -1.375, 6.0 - 1.375) - 0.5).abs() < 1e-3);
    }

    /// A sparse later-stage cell takes its own stage's ratio from nearby rows before the
    /// later stages' pooled one: after a steep downslope the next element is steeper than
    /// after a flat one, and pooling the stages would wash that out.
    #[test]
    fn sparse_later_cells_pool_their_own_stage_first() {
        let n = ELEMENT_MIN_COUNT;
        let cell = |stage: Stage, i: usize, j: usize| (stage.0 * X_IN_BINS + i) * G_BINS + j;
        let (steep, flat) = (Stage::later(-2.5), Stage::later(0.5));
        let (i, j) = (12, 40);
        let mut d = vec![0; ELEMENT_CELLS];
        let mut m = vec![0; ELEMENT_CELLS];
        // The sparse cell, 3 rows away the same stage with ratio 2, and the flat stage dense
        // with ratio 0.5 at the same place.
        m[cell(steep, i, j)] = 10;
        d[cell(steep, i, j)] = 20;
        m[cell(steep, i + 3, j)] = n;
        d[cell(steep, i + 3, j)] = 2 * n;
        m[cell(flat, i, j)] = 100 * n;
        d[cell(flat, i, j)] = 50 * n;
        let w = element_weights(&d, &m);
        let want = (2 * n + 20) as f64 / (n + 10) as f64;
        assert_eq!(w[cell(steep, i, j)], want);
        // Beyond the window along s the same stage has nothing: the pooled stages' ratio.
        let far = j + SAME_STAGE_S_CELLS + 1;
        m[cell(steep, i, far)] = 10;
        d[cell(steep, i, far)] = 10;
        m[cell(flat, i, far)] = 100 * n;
        d[cell(flat, i, far)] = 50 * n;
        let w = element_weights(&d, &m);
        let pooled = (50 * n + 10) as f64 / (100 * n + 10) as f64;
        assert_eq!(w[cell(steep, i, far)], pooled);
        // Rows beyond SAME_STAGE_ROWS do not count.
        assert_eq!(
            same_stage_ratio(&d, &m, cell(steep, i + 3 + SAME_STAGE_ROWS + 1, j)),
            None
        );
    }

    /// A weight on a six-decimal rounding boundary (16965/16000 = 1.0603125) reads back: the
    /// check compares the values as written, not by a tolerance the rounding can exceed.
    #[test]
    fn a_weight_on_a_rounding_boundary_reads_back() {
        let mut c = EscapeCounts::default();
        let cell = element_cell(Stage::FIRST, -1.375, 1.0).unwrap();
        c.element_deterministic[cell] = 16965;
        c.element_model[cell] = 16000;
        c.collisions[0] = 1;
        let t = EscapeTable::from_counts(c.at_centres(), "boundary");
        let back = EscapeTable::parse(&t.to_csv(), "boundary").unwrap();
        assert_eq!(back.counts(), t.counts());
    }

    /// A row's values belong at its counts' mean `x_in`, not at the bin's centre: a read
    /// there gives the row's value, and between two rows' means the read is linear.
    #[test]
    fn rows_are_read_at_their_mean_incidence() {
        let w = wall();
        let at = |x_in: f64| {
            // The velocity of reduced slope x_in along x (σ(0) = Δξ of a slope wall).
            let a = (x_in * w.delta_xi).atan();
            Vector3::new(a.cos(), a.sin(), 0.0)
        };
        let mut c = EscapeCounts::default();
        // Bin [−0.375, −0.25): 400 collisions at x_in = −0.35, a quarter escaping; bin
        // [−0.5, −0.375): 400 at −0.45, three quarters escaping; both at x_out = 1.05 (a bin
        // centre).
        let u_out = at(-1.05).component_mul(&Vector3::new(1.0, -1.0, 1.0));
        for k in 0..400 {
            c.push(Stage::FIRST, &at(-0.35), &u_out, &w, k % 4 == 0);
            c.push(Stage::FIRST, &at(-0.45), &u_out, &w, k % 4 != 0);
        }
        let t = EscapeTable::from_counts(c.clone(), "positions");
        let x_out = reduced_slope(&u_out, &w);
        let p = |x: f64| t.p_escape(Stage::FIRST, x, x_out);
        assert!((p(-0.35) - 0.25).abs() < 1e-9, "{}", p(-0.35));
        assert!((p(-0.45) - 0.75).abs() < 1e-9, "{}", p(-0.45));
        assert!((p(-0.4) - 0.5).abs() < 1e-9, "{}", p(-0.4));
        // The bins' centres would have put the values at −0.3125 and −0.4375.
        assert!((p(-0.3125) - 0.25).abs() < 1e-9);
        // The positions travel with the table.
        let back = EscapeTable::parse(&t.to_csv(), "positions").unwrap();
        assert_eq!(back, t);
        // A sum whose mean leaves its bin is refused; so is an edited position.
        let text = t.to_csv();
        let block = text.lines().position(|l| l == ROW_HEADER).unwrap();
        let row = block
            + text
                .lines()
                .skip(block)
                .position(|l| l.starts_with("first-d0,-0.3125,"))
                .unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let f: Vec<&str> = lines[row].split(',').collect();
        let edit = |to: String| {
            let mut l = lines.clone();
            l[row] = &to;
            EscapeTable::parse(&l.join("\n"), "t")
                .unwrap_err()
                .to_string()
        };
        let moved = format!(
            "first-d0,-0.3125,{},-0.150000,{},{}",
            -60_000_000, f[4], f[5]
        );
        let e = edit(moved);
        assert!(e.contains("outside its bin"), "{e}");
        let e = edit(format!(
            "first-d0,-0.3125,{},-0.340000,{},{}",
            f[2], f[4], f[5]
        ));
        assert!(e.contains("escape position") && e.contains("edited"), "{e}");
    }

    /// The element table's rows are read at the mean `x_in` of their shadow-law draws too,
    /// and its rejection bound holds there.
    #[test]
    fn element_rows_are_read_at_their_mean_incidence() {
        let mut c = EscapeCounts::default();
        for _ in 0..2000 {
            // Row [−0.375, −0.25) at −0.35: the deterministic run saw twice the draws.
            c.push_element(Stage::FIRST, -0.35, 0.1, 0.1);
            c.push_element(Stage::FIRST, -0.35, 0.1, 100.0);
            // Row [−0.5, −0.375) at −0.45: half the draws.
            c.push_element(Stage::FIRST, -0.45, 0.1, 0.1);
            c.push_element(Stage::FIRST, -0.45, 100.0, 0.1);
        }
        // (A table must count at least one collision to be read back.)
        c.collisions[0] = 1;
        let t = EscapeTable::from_counts(c, "element positions");
        for g in [-0.2, 0.1, 1.0, 3.0] {
            let w = |x: f64| t.element_weight(Stage::FIRST, x, g);
            assert!((w(-0.35) - 2.0).abs() < 1e-9, "{}", w(-0.35));
            assert!((w(-0.45) - 0.5).abs() < 1e-9, "{}", w(-0.45));
            assert!((w(-0.4) - 1.25).abs() < 1e-9, "{}", w(-0.4));
            for x in [-0.45, -0.4, -0.35, -0.3] {
                assert!(w(x) <= t.element_bound(Stage::FIRST, x) + 1e-12);
            }
        }
        let back = EscapeTable::parse(&t.to_csv(), "element positions").unwrap();
        assert_eq!(back, t);
    }

    #[test]
    fn the_incidence_axis_is_finest_at_grazing_incidence() {
        assert_eq!(X_IN_BINS, 34);
        assert_eq!(bin_in(-100.0), 0);
        assert_eq!(bin_in(X_IN_MIN), 0);
        assert_eq!(
            bin_in(-0.125),
            X_IN_EDGES.iter().position(|&e| e == -0.125).unwrap()
        );
        assert_eq!(bin_in(-1e-12), bin_in(-0.125));
        assert_eq!(bin_in(0.0), bin_in(0.2));
        assert_eq!(bin_in(100.0), X_IN_BINS - 1);
        assert_eq!(bin_in(f64::NAN), 0);
        for w in X_IN_EDGES.windows(2) {
            assert!(w[1] > w[0]);
            let width = w[1] - w[0];
            assert!(if (-1.0..0.0).contains(&w[0]) {
                width == 0.125
            } else {
                width >= 0.25
            });
        }
    }

    #[test]
    fn interning_keeps_one_copy_per_table() {
        let a = EscapeTable::from_counts(EscapeCounts::default(), "x");
        let p = a.clone().intern();
        let q = a.intern();
        assert!(std::ptr::eq(p, q));
        assert!(std::ptr::eq(
            EscapeTable::builtin().clone().intern(),
            EscapeTable::builtin()
        ));
    }
}
