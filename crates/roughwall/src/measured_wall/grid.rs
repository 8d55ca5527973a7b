//! The grid of incident directions a measured-wall table is built on, and its resolution.
//!
//! Rows are the incident angle `|α⁻|`, 0.5° apart at grazing incidence, where the shadow
//! effect changes the law fastest, and 2–5° apart above 24°, where a striated wall's law still
//! bends between rows 6–20° apart (docs/design-notes.md); a table adds rows of its own between
//! them where its wall's law bends ([`super::refine`]); columns are `β⁻` from the lay over
//! the whole circle, because a real wall need not be its own mirror image (`β⁻ ↔ −β⁻`) nor
//! unchanged by a half turn (`β⁻ ↔ β⁻ + 180°`). Between grid points the law is a mixture of
//! the neighbours' ([`super::MeasuredWallTable::incidence`]); the spacings were chosen by
//! measuring the interpolation error at grid midpoints (`tests/measured_wall.rs` and
//! docs/design-notes.md).

/// The base rows every table has: incident angles `|α⁻|` (degrees), increasing. A table adds
/// up to [`super::refine::MAX_REFINED_ROWS`] rows of its own between them, where its wall's
/// law bends ([`super::refine`]).
pub const ALPHA_ROWS_DEG: [f64; 43] = [
    1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0, 6.5, 7.0, 7.5, 8.0, 9.0, 10.0, 11.5,
    13.0, 15.0, 17.5, 20.5, 24.0, 26.0, 28.0, 30.0, 32.0, 34.0, 36.0, 38.0, 40.0, 43.0, 46.0, 50.0,
    54.0, 58.0, 62.0, 66.0, 70.0, 75.0, 80.0, 85.0, 90.0,
];

/// The columns: `β⁻ = −180° + j · 360°/BETA_COLUMNS`, `j = 0 … BETA_COLUMNS − 1` (15° apart).
pub const BETA_COLUMNS: usize = 24;

/// Knots of each cell's quantile function of `ξ'` ([`super::QuantileFunction`]).
pub const XI_KNOTS: usize = 129;

/// Rank bins of `ξ'` within which the law of `ζ'` is kept (their dependence). 8 bins left a
/// bias of up to 0.07° in mean `α⁺` at grazing incidence oblique to the lay, 16 halve it; a
/// narrow specular peak of the law (a sphere on a striated metal wall) needs more: its `ξ'`
/// paired with `ζ'` of other histories spreads it (docs/design-notes.md). 32 bins of 33
/// knots keep a table with every row a build may add under 16 MiB of text before the knots
/// a law with atoms adds ([`XI_ADDED_BUDGET`]); with every one of those, about 24 MiB, and
/// with every joint atom a cell may hold ([`super::MAX_ATOMS`]), about 38 MiB.
pub const RANK_BINS: usize = 32;

/// Knots of each rank bin's quantile function of `ζ'`.
pub const ZETA_KNOTS: usize = 33;

/// Knots a cell's quantile function of `ξ'` adds where the fixed ones put more than
/// [`XI_ADDED_TOLERANCE`] of probability where the sample has none (a gap between atoms of
/// a comb-like law: quantized heights), and
/// that tolerance. A smooth law's order statistics stray from the chord between two fixed
/// knots too: by at most 0.0016 over 20 normal samples of 17 711, and 0.0148 over 20 of 553
/// (a bin of `ζ'`), so the tolerances sit just above a smooth law's own excursions and it
/// gets few added knots (opd-1's point table: one `ξ'` function of 1 032, 4 % of the bins of
/// `ζ'`). The budgets were measured: 128/16 and 256/32 move no study row by more than 0.0004
/// of KS and grow the tables to 17 and 20 MB (docs/design-notes.md, "Knots where a law has
/// atoms").
pub const XI_ADDED_BUDGET: usize = 64;
/// See [`XI_ADDED_BUDGET`].
pub const XI_ADDED_TOLERANCE: f64 = 0.002;

/// The same for each rank bin's quantile function of `ζ'` (about 550 histories a bin).
pub const ZETA_ADDED_BUDGET: usize = 8;
/// See [`ZETA_ADDED_BUDGET`].
pub const ZETA_ADDED_TOLERANCE: f64 = 0.015;

/// No quantile function of `n` samples adds a knot for less than `ADDED_NOISE/√n` of
/// probability: a smaller excursion is within the sample's own noise (the KS distance of `n`
/// draws from their own law is about `0.87/√n`), and a table of few histories a cell would
/// otherwise add knots nearly everywhere (1 024 histories: every `ξ'` function and 99 % of the
/// bins of `ζ'`; with it, 0 and 1 of 33 024, where normal samples of 1 024 and of 32 stray by
/// at most 0.006 and 0.031 over 20 seeds). 0.25 is the largest round value at which, at the
/// default [`HISTORIES_PER_CELL`], this stays below both tolerances (0.0019 for `ξ'`, 0.011
/// for a bin of `ζ'`), so a default table is what the tolerances alone give.
pub const ADDED_NOISE: f64 = 0.25;

/// Histories shot per cell by default (the Fibonacci number `F₂₂`, whose lattice is the
/// Fibonacci lattice): the table's sampling noise at a grid point is then a KS distance of
/// about `0.87/√n` ≈ 0.0065 and an error of mean `α⁺` of `σ(α⁺)/√n`: 0.001–0.12° on the
/// shipped scans, whose `σ(α⁺)` is 0.14–15° at the study's directions
/// (`results/measured-wall-model/`), less between grid points, where four cells are mixed. The build then takes
/// about 8 s on a 4096² scan on 2 cores (docs/performance.md, row 25).
pub const HISTORIES_PER_CELL: u64 = 17_711;

/// Resolution of a knot and of a joint atom (rad): 0.1 µrad, far below any wall's angles and
/// a table's noise.
pub const KNOT_UNIT_RAD: f64 = 1e-7;

/// The angle `|α⁻|` (degrees) whose margins fix the one entry region of every direction of a
/// table built on a scan ([`crate::deterministic::Patch::with_entry_alpha`]): the grid's
/// lowest row, so the region is that of the flattest direction the table could serve (on a scan
/// of fewer than about 860 height ranges a side, the inner fifth of each side of its block). Every cell then samples the
/// same part of the scan, and the in-place reference a table is judged against takes the same
/// region (`[deterministic] entry_alpha_deg`, which the wall card states).
pub const ENTRY_ALPHA_DEG: f64 = ALPHA_ROWS_DEG[0];

/// The largest share of a cell's histories that may leave the scan for the cell to be
/// served: a row with a cell above it (grazing incidence on a small scan) is not served, and
/// incident angles below the lowest served row take that row's law (the table says so).
/// Ten times the in-place reference's warning bound (`deterministic::LEFT_PATCH_BOUND`): the
/// table then follows the reference where the reference warns but still answers, and the
/// card states the largest share served.
pub const SERVED_LEFT_BOUND: f64 = 1e-2;

/// Cells of the base grid (a table with refined rows has [`BETA_COLUMNS`] more per row).
pub const CELLS: usize = ALPHA_ROWS_DEG.len() * BETA_COLUMNS;

/// The `β⁻` (degrees) of column `j`.
pub fn beta_column_deg(j: usize) -> f64 {
    -180.0 + j as f64 * 360.0 / BETA_COLUMNS as f64
}

/// The index of cell `(row, column)`.
#[inline]
pub fn cell(row: usize, column: usize) -> usize {
    row * BETA_COLUMNS + column
}

/// The interval of `rows` (a table's, increasing) holding `|α⁻|` (degrees) and the weight of
/// its upper row, with rows below `first_row` not served: angles below it take it alone.
#[inline]
pub fn row_weights(abs_alpha_deg: f64, rows: &[f64], first_row: usize) -> (usize, usize, f64) {
    let last = rows.len() - 1;
    if abs_alpha_deg.is_nan() || abs_alpha_deg <= rows[first_row] {
        return (first_row, first_row, 0.0);
    }
    if abs_alpha_deg >= rows[last] {
        return (last, last, 0.0);
    }
    // The rows are few: a scan from the top is as fast as a bisection.
    let mut i = first_row;
    while rows[i + 1] <= abs_alpha_deg {
        i += 1;
    }
    // Above grazing incidence the law of the elements seen is linear in `cot α⁻` (their
    // weight `−U⁻·n ∝ 1 + cot|α⁻| tan γ`, Radenkovic & Simonin 2021, Eq. 29, unshadowed);
    // at grazing incidence the shadow effect makes it no simpler in `cot α⁻` than in `α⁻`,
    // and `α⁻` interpolates better there (measured at the rows' midpoints).
    let w = if rows[i + 1] <= LINEAR_BELOW_DEG {
        (abs_alpha_deg - rows[i]) / (rows[i + 1] - rows[i])
    } else {
        (cot_deg(abs_alpha_deg) - cot_deg(rows[i])) / (cot_deg(rows[i + 1]) - cot_deg(rows[i]))
    };
    (i, i + 1, w)
}

/// Rows up to this `|α⁻|` (degrees) are interpolated linearly in `α⁻`, the others in
/// `cot α⁻`.
pub const LINEAR_BELOW_DEG: f64 = 9.0;

/// `cot α` of `α` in degrees (0 at 90°).
#[inline]
pub(crate) fn cot_deg(a: f64) -> f64 {
    if a >= 90.0 {
        0.0
    } else {
        1.0 / a.to_radians().tan()
    }
}

/// The two columns around `β⁻` (degrees, any value) and the weight of the second.
#[inline]
pub fn column_weights(beta_deg: f64) -> (usize, usize, f64) {
    let step = 360.0 / BETA_COLUMNS as f64;
    let t = (beta_deg + 180.0).rem_euclid(360.0) / step;
    let j = (t.floor() as usize).min(BETA_COLUMNS - 1);
    let w = (t - j as f64).clamp(0.0, 1.0);
    (j, (j + 1) % BETA_COLUMNS, w)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_increase_and_end_at_normal_incidence() {
        assert!(ALPHA_ROWS_DEG.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(*ALPHA_ROWS_DEG.last().unwrap(), 90.0);
    }

    #[test]
    fn weights_hit_the_grid_and_interpolate_between() {
        assert_eq!(row_weights(4.0, &ALPHA_ROWS_DEG, 0), (6, 7, 0.0));
        let (i, k, w) = row_weights(4.25, &ALPHA_ROWS_DEG, 0);
        assert_eq!((i, k), (6, 7));
        assert!((w - 0.5).abs() < 1e-12);
        // Above 9° the weights are linear in cot α.
        let (i, k, w) = row_weights(48.0, &ALPHA_ROWS_DEG, 0);
        assert_eq!((i, k), (32, 33));
        assert_eq!((ALPHA_ROWS_DEG[i], ALPHA_ROWS_DEG[k]), (46.0, 50.0));
        let cot = |a: f64| 1.0 / a.to_radians().tan();
        assert!((w - (cot(48.0) - cot(46.0)) / (cot(50.0) - cot(46.0))).abs() < 1e-12);
        assert_eq!(row_weights(0.3, &ALPHA_ROWS_DEG, 0), (0, 0, 0.0));
        assert_eq!(row_weights(2.5, &ALPHA_ROWS_DEG, 4), (4, 4, 0.0));
        assert_eq!(row_weights(90.0, &ALPHA_ROWS_DEG, 0), (42, 42, 0.0));
        assert_eq!(column_weights(-180.0), (0, 1, 0.0));
        assert_eq!(column_weights(180.0), (0, 1, 0.0));
        let (j, k, w) = column_weights(172.5);
        assert_eq!((j, k), (23, 0));
        assert!((w - 0.5).abs() < 1e-12);
        for j in 0..BETA_COLUMNS {
            let (a, _, w) = column_weights(beta_column_deg(j));
            assert_eq!(a, j);
            assert!(w.abs() < 1e-12);
        }
    }
}
