//! Closer rows where a wall's law bends: the rows a table adds to the base grid.
//!
//! Between two rows a rebound's element is drawn from a mixture of theirs with weights linear
//! in `cot α⁻` ([`super::grid::row_weights`]) and the incident direction is mirrored on it, so
//! what the mixture interpolates is how far the elements turn a rebound: each cell's *turn*
//! `2 γ̄`, twice its elements' mean inclination towards the incident direction, which is what
//! mirroring adds to `α⁺` for small slopes (zero on a flat wall). Not `mean α⁺ − |α⁻|`
//! itself: near normal incidence `α⁺` folds at 90°, which the mirroring does exactly,
//! whatever the element. Where the wall's law bends (a
//! striated metal wall near the incidence at which its flanks start to shadow each other),
//! the linear interpolant of the turn misses it by about `f[x₀, x₁, x₂] · h²/4` at the
//! interval's midpoint, with `f[…]` the second divided difference of the turn over three
//! neighbouring rows and `h` the interval, both in `x = cot α⁻`. The build measures that on
//! its base rows and adds the midpoint row of every interval where it exceeds
//! [`REFINE_ABOVE_DEG`] in some column, the worst first, up to [`MAX_REFINED_ROWS`].
//!
//! For equal spacing the estimate is `(f₀ − 2f₁ + f₂)/8`: its noise is about a third of one
//! cell's, whatever the spacing, so the base rows' own histories suffice, with no pilot run.
//! That noise is still comparable with the bound on a rough wall (σ(α⁺) ≈ 10°), so an
//! interval is refined only where the estimate exceeds the bound by [`REFINE_SIGMAS`] of its
//! standard errors: a row added in vain costs build time, a row missed costs accuracy.

use super::grid::{cot_deg, ALPHA_ROWS_DEG, BETA_COLUMNS, LINEAR_BELOW_DEG};

/// The predicted error of the turn, so of mean `α⁺` (degrees), at an interval's midpoint
/// above which the build adds the midpoint row: half the goal the model is held to (issue 39: 0.05°), so
/// that interpolation takes at most half of it.
pub const REFINE_ABOVE_DEG: f64 = 0.025;

/// The most rows a table adds: they cost a base row's build time each (about 0.15 s on a
/// 4096² scan on 2 cores: 14 base rows cost 2.14 s, docs/performance.md row 25's history in
/// docs/design-notes.md, "Rows"), and the widest table keeps within the 16 MiB a reader
/// takes (about 15 MiB; `src/case/stochastic.rs` tests it).
pub const MAX_REFINED_ROWS: usize = 12;

/// A cell's turn `2 γ̄` and its standard error (degrees; NaN for a cell without a law).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turn {
    /// Twice the mean inclination `γ` of the cell's elements towards the incident direction.
    pub deg: f64,
    /// Its standard error, as for independent histories. The lattice the histories enter on
    /// makes the true one smaller (two seeds' tables of sample-land differ by at most 0.046°
    /// in mean α⁺ where `σ(α⁺)/√n` is about 0.075°), so this errs towards adding fewer rows.
    pub se_deg: f64,
}

/// How sure the predicted error must be: an interval is refined where the error's lower
/// bound, the estimate less this many standard errors, exceeds [`REFINE_ABOVE_DEG`]. Each
/// interval is tested in 24 columns at its two ends, so a looser margin lets noise through:
/// without it every sample-land table took all 12 rows. With it, the 13 tables of the four
/// smooth shipped scans (x3p-2, opd-1, plu-1, metropro-1) and the generated 4096² bench wall
/// get none (docs/design-notes.md, "Rows per wall").
pub const REFINE_SIGMAS: f64 = 3.0;

/// The rows (degrees, increasing) to add to the base grid, given each base cell's turn
/// (`turn[row · BETA_COLUMNS + column]`), with rows from `first_row` served.
pub fn refined_rows(turn: &[Turn], first_row: usize) -> Vec<f64> {
    let rows = &ALPHA_ROWS_DEG;
    debug_assert_eq!(turn.len(), rows.len() * BETA_COLUMNS);
    let x: Vec<f64> = rows.iter().map(|&a| cot_deg(a)).collect();
    // The second divided difference at interior row `r` of column `c` and its standard
    // error, where its three rows are served and have laws.
    let divided = |r: usize, c: usize| -> Option<(f64, f64)> {
        if r < first_row + 1 || r + 1 >= rows.len() {
            return None;
        }
        let (x0, x1, x2) = (x[r - 1], x[r], x[r + 1]);
        let a = [
            1.0 / ((x0 - x1) * (x0 - x2)),
            1.0 / ((x1 - x0) * (x1 - x2)),
            1.0 / ((x2 - x0) * (x2 - x1)),
        ];
        let t = [0, 1, 2].map(|j| turn[(r - 1 + j) * BETA_COLUMNS + c]);
        let d: f64 = (0..3).map(|j| a[j] * t[j].deg).sum();
        let se = (0..3)
            .map(|j| (a[j] * t[j].se_deg).powi(2))
            .sum::<f64>()
            .sqrt();
        (d.is_finite() && se.is_finite()).then_some((d, se))
    };
    let mut scored: Vec<(f64, usize)> = Vec::new();
    for i in first_row..rows.len() - 1 {
        if rows[i] < LINEAR_BELOW_DEG {
            continue;
        }
        let q = (x[i] - x[i + 1]).powi(2) / 4.0;
        let worst = (0..BETA_COLUMNS)
            .flat_map(|c| [divided(i, c), divided(i + 1, c)])
            .flatten()
            .map(|(d, se)| q * (d.abs() - REFINE_SIGMAS * se))
            .fold(f64::NEG_INFINITY, f64::max);
        if worst > REFINE_ABOVE_DEG {
            scored.push((worst, i));
        }
    }
    // The worst intervals first; ties (never in practice) by angle, so the choice is
    // deterministic.
    scored.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    scored.truncate(MAX_REFINED_ROWS);
    let mut added: Vec<f64> = scored
        .iter()
        .map(|&(_, i)| 0.5 * (rows[i] + rows[i + 1]))
        .collect();
    added.sort_by(f64::total_cmp);
    added
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The turn of a law `g(α⁻)` in every column, known to `se` degrees.
    fn turn_se(g: impl Fn(f64) -> f64, se: f64) -> Vec<Turn> {
        ALPHA_ROWS_DEG
            .iter()
            .flat_map(|&a| {
                std::iter::repeat_n(
                    Turn {
                        deg: g(a),
                        se_deg: se,
                    },
                    BETA_COLUMNS,
                )
            })
            .collect()
    }

    /// The turn of a law `g(α⁻)` in every column, known to 0.005°.
    fn turn_known(g: impl Fn(f64) -> f64) -> Vec<Turn> {
        turn_se(g, 0.005)
    }

    /// A kink at 38.5° of 0.25°/deg within 3° of it, like the point particle's
    /// `mean α⁺ − |α⁻|` on x3ptools' sample-land (4.69, 4.06, 4.36, 4.73° at 36, 38, 40,
    /// 43°, β⁻ = 97.5°).
    fn kink(a: f64) -> f64 {
        4.0 + 0.25 * (a - 38.5).abs().min(3.0)
    }

    #[test]
    fn a_law_linear_in_cot_alpha_gets_no_rows() {
        // What the mixture reproduces exactly (a flat wall turns nothing): nothing to add.
        assert!(refined_rows(&turn_known(|a| 3.0 + 2.0 * cot_deg(a)), 0).is_empty());
        assert!(refined_rows(&turn_known(|_| 0.0), 0).is_empty());
        // A turn linear in α⁻ is curved in cot α⁻, but too little to matter.
        assert!(refined_rows(&turn_known(|a| 0.05 * a), 0).is_empty());
    }

    #[test]
    fn a_kink_gets_the_midpoints_around_it_and_no_more() {
        let added = refined_rows(&turn_known(kink), 0);
        assert!(added.contains(&39.0), "{added:?}");
        assert!(
            added.iter().all(|&a| (30.0..=46.0).contains(&a)),
            "{added:?}"
        );
        // The same kink in one column only is found too (the worst column counts).
        let mut one = turn_known(|_| 4.0);
        for (r, &a) in ALPHA_ROWS_DEG.iter().enumerate() {
            one[r * BETA_COLUMNS + 5].deg = kink(a);
        }
        assert_eq!(refined_rows(&one, 0), added);
        // Known too poorly (the bend within three standard errors of the bound): no rows.
        assert!(refined_rows(&turn_se(kink, 1.0), 0).is_empty());
    }

    #[test]
    fn unserved_rows_and_cells_without_a_law_are_left_alone_and_the_count_is_capped() {
        let served_from_40 = ALPHA_ROWS_DEG.iter().position(|&a| a == 40.0).unwrap();
        assert!(refined_rows(&turn_known(kink), served_from_40)
            .iter()
            .all(|&a| a > 40.0));
        assert!(refined_rows(&turn_known(|_| f64::NAN), 0).is_empty());
        // Rows alternating by 2° (known far better): every interval qualifies, at most the
        // cap is added.
        let noisy: Vec<Turn> = (0..ALPHA_ROWS_DEG.len() * BETA_COLUMNS)
            .map(|k| Turn {
                deg: if (k / BETA_COLUMNS).is_multiple_of(2) {
                    1.0
                } else {
                    -1.0
                },
                se_deg: 0.005,
            })
            .collect();
        let added = refined_rows(&noisy, 0);
        assert_eq!(added.len(), MAX_REFINED_ROWS);
        assert!(added.windows(2).all(|w| w[0] < w[1]));
        // Midpoints: never a base row.
        assert!(added.iter().all(|a| !ALPHA_ROWS_DEG.contains(a)));
    }
}
