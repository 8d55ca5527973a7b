//! The calibrated model's chosen numbers, in one place, each with how it was chosen: the
//! table's grid (axes and their edges), how many counts a cell needs before it stands on
//! its own, the proposal law's roughness, the slope inversion's quadrature, the transverse
//! memory's guards, and the units that keep every sum an exact integer. Everything the
//! table holds is measured by `rebound calibrate`; these numbers are not fitted to a
//! result. The grid derived from them (bins, cells, stages) is in [`super::grid`].

// ---- The table's axes --------------------------------------------------------------------

/// Edges of the `x_in` axis: 0.125 wide in `[−1, 0]`, where the laws change fastest (a
/// first element at `α⁻/Δγ = −0.34` and at `−0.64` differ by 0.1° in mean α⁺ on the Sec. 3
/// wall), 0.25 in `[−2, −1]` and `[0, 1]`, 0.5 beyond.
pub const X_IN_EDGES: [f64; 35] = [
    -6.0, -5.5, -5.0, -4.5, -4.0, -3.5, -3.0, -2.5, -2.0, -1.75, -1.5, -1.25, -1.0, -0.875, -0.75,
    -0.625, -0.5, -0.375, -0.25, -0.125, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0,
    4.5, 5.0, 5.5, 6.0,
];

/// Upper edge of the `x_out` axis (the lower one is 0); beyond it a particle always leaves.
/// Measured on the built-in table (pooled over stages and `x_in`): the escape probability is
/// 0.99947 at `x_out` = 2.65, above 0.9999 from 3.15 and 0.999998 in the last bin
/// (3.9–4.0), so taking 1 beyond 4 errs by about 2·10⁻⁶.
pub const X_OUT_MAX: f64 = 4.0;

/// Bins along `x_out`.
pub const X_OUT_BINS: usize = 40;

/// Edges (the slope spread `σ(β)` × 180/π, written like degrees) of the first
/// collision's axis: the roughness of the incident plane (Eq. 35 in slopes). In slopes the
/// first *element*'s correction is the same on all three stages within the noise (stage
/// means of `s` within 0.002 at every `x_in`); the *escape* law after it still differs
/// between them at grazing incidence (χ²/cell 2–5
/// between the stages at `x_in` in [−0.75, −0.25]), presumably through the rebound's
/// deflection across the path. The edges split the calibration sweep's directions (2.5° and
/// 3.6°; 5.1–5.8°; 6.9° and 7.3°, as angles) into three stages, and a first collision reads
/// one of the two stages around its `σ(β)` ([`super::EscapeTable::first_stage`]).
pub const FIRST_DG_EDGES_DEG: [f64; 2] = [4.5, 6.5];

/// Collisions a cell needs to stand on its own (one standard error of `p` is then at most
/// `√(0.25/50) ≈ 0.07`); sparser cells take their neighbour's value.
pub const MIN_COUNT: u64 = 50;

/// Shadow-law draws a first-element cell needs for its weight (the weight's relative
/// noise is about `√(2/n)`: 4.5 % here); sparser cells pool neighbours (the narrowest window along `s` that has enough).
pub const ELEMENT_MIN_COUNT: u64 = 1000;

/// Lower edge of the element's reduced local impact angle `s = (γ − α)/Δγ(β)` (`α` clamped
/// to the `x_in` range): an element the particle can reach has `s > 0`, and the shadow law
/// of Eqs. (31)–(32) vanishes like `sin(γ − α)` there (`α < 0` descending; docs/physics.md
/// §3). Reading the correction in `s` rather than in
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
/// pool within its own stage. With [`SAME_STAGE_ROWS`]: between the
/// windows measured at α⁻ = −32.5°, β⁻ = 90° on the Sec. 3 wall (±3 cells and ±3 rows: mean
/// α⁺ −0.038° off; ±3 and ±6: +0.008°; ±5 and ±4: +0.014°; docs/design-notes.md), not tuned
/// further.
pub const SAME_STAGE_S_CELLS: usize = 4;

/// How many `x_in` bins each side a sparse later-stage element cell may pool within its own
/// stage (the choice: [`SAME_STAGE_S_CELLS`]).
pub const SAME_STAGE_ROWS: usize = 6;

// ---- Units of the exact sums ------------------------------------------------------------

/// Units of the `x_in` sums (integers, so that sums are exact in any order).
pub const X_SUM_UNIT: f64 = 1e-6;

/// Units of the `Δγ` sums (degrees; integers, so that sums are exact in any order).
pub const DG_SUM_UNIT: f64 = 1e-6;

// ---- The proposal law and the slope inversion ----------------------------------------

/// `Δγ` of the proposal law: the paper's shadow law (Eq. 32) at a vanishing roughness,
/// `sin(ε(g − x)) e^{−g²/2}`, is the slope-space law `(g − x) e^{−g²/2}` on `g > x` (the
/// rate at which a path of slope `x σ` crosses profile slopes `g σ`) to a relative
/// `(ε x)²/6`.
pub const PROPOSAL_EPS: f64 = 1e-4;

/// `|x|` beyond which the proposal reads `x` at this bound (its law is then the Gaussian
/// tilted by less than `1/5000` per unit `g`); keeps `ε x` at most 0.5 rad.
pub const PROPOSAL_X_MAX: f64 = 5000.0;

/// Nodes each side of 0 and step (in standard deviations) of the trapezoid rule behind
/// [`super::slope_deviations`]. For an analytic integrand under a Gaussian weight the rule's error
/// is of order `e^{−2π²/h²}` (1e−137 at `h` = 0.25), and ±7 standard deviations leave out
/// `e^{−24.5}` of the weight: round-off is all that remains. This is the number of nodes each
/// side of 0 (28 nodes of [`STEP`] reach ±7 standard deviations).
pub const NODES: i32 = 28;
/// The step `h` of that trapezoid rule, in standard deviations (see [`NODES`]).
pub const STEP: f64 = 0.25;

/// Fixed-point steps of [`super::slope_deviations`] at most: each shrinks the error by about
/// `2σ²`, and the steps stop once a step changes nothing beyond round-off.
pub const ITERATIONS: usize = 100;

/// Walls whose slope spreads [`super::slope_deviations`] keeps per thread (the oldest goes first): a
/// choice, not a measurement — a few wall types per CFD case, with room to spare; a lookup
/// scans them (16 comparisons at most).
pub const CACHED_WALLS: usize = 16;

/// Shadow-law proposals the corrected element draw makes at most before it takes the last
/// one: the rejection bound makes one or two proposals typical; the cap only guards a
/// degenerate table (a chosen guard, not a measurement).
pub const MAX_PROPOSALS: usize = 1000;

// ---- The transverse memory ---------------------------------------------------------------

/// Pairs a later stage needs for its own slope (the slope's standard error is then about
/// `1/√n`: 0.03); a sparser stage takes the later stages' pooled slope.
pub const MIN_PAIRS: u64 = 1000;

/// Residuals are clamped to `±Z_MAX` when counted and when read: a residual of a
/// near-degenerate conditional spread must not dominate the sums or a draw.
pub const Z_MAX: f64 = 4.0;

/// Units of the sums (integers, so that sums are exact in any order).
pub const TRANSVERSE_UNIT: f64 = 1e-6;

/// A guard, not a fitted value: the slope is kept within `±B_MAX`, and the fresh part's
/// spread at least `√(1 − B_MAX²)`: however degenerate a table, every later element keeps a fresh random part
/// (the built-in table's slopes are at most 0.78 with `E[z_prev²]` ≈ 1: fresh parts 0.63–0.94).
pub const B_MAX: f64 = 0.95;

/// The largest `Σ z_prev²` (or `|Σ z_prev z|`) per pair, in [`TRANSVERSE_UNIT`]s: a clamped residual's.
pub const MAX_TERM: i64 = 16_000_000;
