//! A measured-wall table from a deterministic reference: every grid cell's histories shot on
//! the wall, their effective elements' law kept.

use super::effective_normal::effective_normal;
use super::grid::{beta_column_deg, cell, ALPHA_ROWS_DEG, BETA_COLUMNS, RANK_BINS};
use super::grid::{HISTORIES_PER_CELL, SERVED_LEFT_BOUND};
use super::quantiles::{first_served_row, row_served, CellLaw};
use super::refine::{refined_rows, Turn, MAX_REFINED_ROWS};
use super::table::MeasuredWallTable;
use crate::angles::{gamma_rotated, incident_angles, xi_zeta_of_normal};
use crate::collision::CollisionLaw;
use crate::deterministic::{history_entered, Fate, LostReason, ModelSetup, Tracker};
use crate::error::{Error, Result};
use crate::incidence::{IncidentCondition, SpeedLaw, SpeedReference};
use crate::rng;
use crate::wall::Deviations;
use rand::Rng;
use rayon::prelude::*;

/// How a table is built.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuildOptions {
    /// Histories shot per grid cell ([`HISTORIES_PER_CELL`] by default).
    pub histories_per_cell: u64,
    /// Seed of the histories' streams: history `i` of cell `k` draws from
    /// `rng::stream(seed, [MEASURED_WALL, k, i])`.
    pub seed: u64,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            histories_per_cell: HISTORIES_PER_CELL,
            seed: 2021,
        }
    }
}

/// The cells a build shoots at most (the base grid and every row it may add): what a
/// progress display plans for, in cells of `histories_per_cell` histories.
pub const BUILD_CELLS: usize = (ALPHA_ROWS_DEG.len() + MAX_REFINED_ROWS) * BETA_COLUMNS;

/// The golden ratio, whose continued fraction makes the best two-dimensional lattices.
const GOLDEN: f64 = 1.618_033_988_749_895;

/// The least histories per cell a table is built with.
const MIN_HISTORIES: u64 = 1024;

/// The least histories of a cell that leave the wall for its law: each rank bin of `ξ'` needs
/// a few for its `ζ'` law.
const MIN_PAIRS: u64 = 8 * RANK_BINS as u64;

/// The measured-wall table of the wall `tracker` walks (the in-place reference on a scan,
/// [`crate::Tracker::in_place`]; or, for tests, a periodic wall), for a particle centre
/// bouncing ideally elastically: every grid cell's histories, each turned into its effective
/// element ([`super::effective_normal`]) and kept as its `(ξ', ζ')`. First the base rows;
/// then the rows [`super::refine`] adds where the law the base rows measured bends.
/// `deviations` are the wall's own (for the table's record), `source` says what it is.
/// `progress(histories)` is called with each finished cell's histories (from worker
/// threads); they sum to at most [`BUILD_CELLS`] cells' worth. The table is the same for any
/// thread count.
pub fn build_table(
    tracker: &Tracker<'_>,
    deviations: Deviations,
    source: &str,
    opts: &BuildOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<MeasuredWallTable> {
    if opts.histories_per_cell < MIN_HISTORIES {
        return Err(Error::invalid(
            "histories_per_cell",
            opts.histories_per_cell.to_string(),
            &format!("at least {MIN_HISTORIES}"),
        ));
    }
    let setup = ModelSetup {
        law: CollisionLaw::Elastic,
        diameter_m: 0.0,
        speed: SpeedLaw {
            mean_m_s: 1.0,
            std_m_s: 0.0,
            reference: SpeedReference::Magnitude,
        },
        wall: deviations,
        psi: crate::stochastic::PSI_PAPER,
        erosion: None,
        spin: Default::default(),
    };
    // Cell `(row, column)` of `rows`, with its stream's key.
    let row_cells = |rows: &[(f64, u64)]| -> Result<Vec<MeasuredCell>> {
        let cells: Vec<Result<MeasuredCell>> = (0..rows.len() * BETA_COLUMNS)
            .into_par_iter()
            .map(|k| {
                let ((alpha, key), column) = (rows[k / BETA_COLUMNS], k % BETA_COLUMNS);
                let cond = IncidentCondition::from_degrees(-alpha, beta_column_deg(column));
                let law = cell_law(tracker, &setup, &cond, key + column as u64, opts);
                progress(opts.histories_per_cell);
                law
            })
            .collect();
        cells.into_iter().collect()
    };
    // The base rows' streams are keyed by cell index, as they always were.
    let base: Vec<(f64, u64)> = ALPHA_ROWS_DEG
        .iter()
        .enumerate()
        .map(|(r, &a)| (a, (r * BETA_COLUMNS) as u64))
        .collect();
    let (laws, turn): (Vec<CellLaw>, Vec<Turn>) = row_cells(&base)?
        .into_iter()
        .map(|c| (c.law, c.turn))
        .unzip();
    let rows = ALPHA_ROWS_DEG.len();
    let first_row = first_served_row(&laws);
    if first_row == rows {
        let worst = laws[cell(rows - 1, 0)..]
            .iter()
            .map(CellLaw::left_share)
            .fold(0.0, f64::max);
        return Err(Error::Input(format!(
            "{source}: too small for the measured-wall model: even at normal incidence {:.1} % of the histories leave it (at most {} allowed)",
            worst * 100.0,
            SERVED_LEFT_BOUND
        )));
    }
    let added: Vec<(f64, u64)> = refined_rows(&turn, first_row)
        .into_iter()
        .map(|a| (a, refined_key(a)))
        .collect();
    let extra: Vec<CellLaw> = row_cells(&added)?.into_iter().map(|c| c.law).collect();
    // Every row, base and added, with its cells; an added row that is not served stays out
    // (a row between two served ones is served in practice), so that every row from
    // `first_row` up is served. Added rows lie above `first_row`, so it keeps its index.
    let mut by_row: Vec<(f64, &[CellLaw])> = ALPHA_ROWS_DEG
        .iter()
        .copied()
        .zip(laws.chunks(BETA_COLUMNS))
        .chain(
            added
                .iter()
                .map(|&(a, _)| a)
                .zip(extra.chunks(BETA_COLUMNS))
                .filter(|(_, c)| row_served(c)),
        )
        .collect();
    by_row.sort_by(|x, y| x.0.total_cmp(&y.0));
    Ok(MeasuredWallTable {
        source: source.to_string(),
        alpha_rows_deg: by_row.iter().map(|&(a, _)| a).collect(),
        first_row,
        deviations,
        seed: opts.seed,
        cells: by_row.iter().flat_map(|(_, c)| c.iter().cloned()).collect(),
    })
}

/// The stream key of the first cell of a row the build added at `alpha_deg` (its cells add
/// their column): far above the base cells' indices, and one per hundredth of a degree.
fn refined_key(alpha_deg: f64) -> u64 {
    (1 << 40) + (alpha_deg * 100.0).round() as u64 * BETA_COLUMNS as u64
}

/// A cell's law and, for [`super::refine`], how far its elements turn a rebound: twice their
/// mean inclination `γ` towards the incident direction (degrees; Radenkovic & Simonin 2021,
/// Eq. 20), what mirroring on them adds to `α⁺` for small slopes (NaN without a law).
#[derive(Clone)]
struct MeasuredCell {
    law: CellLaw,
    turn: Turn,
}

/// The measured-wall table of a levelled scan whose lay is `lay`, for a particle centre
/// (`diameter_m = None`) or a sphere of that diameter: the in-place reference's wall
/// ([`crate::deterministic::in_place_wall`], for a sphere its centre surface), walked in place
/// with its incident directions turned by the lay, and [`build_table`] with that wall's own
/// deviations (the scan's, `lay`'s, where the block has none). What `rebound scan
/// --measured-wall` and Python's `measured_wall_table` build.
pub fn scan_table(
    levelled: &crate::ScanField,
    lay: &crate::scan::Lay,
    diameter_m: Option<f64>,
    triangulation: crate::Triangulation,
    source: &str,
    opts: &BuildOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<MeasuredWallTable> {
    let wall = crate::deterministic::in_place_wall(levelled, lay.angle, diameter_m, triangulation)?;
    build_table(
        &wall.tracker()?,
        wall.met_deviations(lay),
        source,
        opts,
        progress,
    )
}

/// How far the elements `pairs` `(ξ', ζ')` turn a rebound of incident direction `beta`: twice
/// their mean inclination `γ` towards it (Radenkovic & Simonin 2021, Eq. 20,
/// [`gamma_rotated`]), with its standard error, in degrees.
fn turn_of(pairs: &[(f64, f64)], beta: f64) -> Turn {
    let sin_cos = beta.sin_cos();
    let m = pairs.len() as f64;
    let gamma = |&(xi, zeta): &(f64, f64)| gamma_rotated(xi, zeta, sin_cos).0;
    let mean = pairs.iter().map(gamma).sum::<f64>() / m;
    let variance = pairs.iter().map(|p| (gamma(p) - mean).powi(2)).sum::<f64>() / (m - 1.0);
    Turn {
        deg: (2.0 * mean).to_degrees(),
        se_deg: (2.0 * (variance / m).sqrt()).to_degrees(),
    }
}

/// One cell's law: its histories in order (a cell is one task, so the thread count does not
/// enter), the escaped ones' effective elements in the wall's frame `(ξ', ζ')`.
///
/// The histories enter on a rank-1 lattice over the entry region (generator `round(n/φ)`,
/// the Fibonacci lattice when `n` is a Fibonacci number), shifted by a uniform draw of the
/// cell's stream (Cranley & Patterson 1976), rather than at independent uniform points: the
/// law of a wall is an average over where particles land, and a lattice spreads them evenly,
/// so the table's sampling error falls faster than `1/√n` (measured: docs/design-notes.md).
fn cell_law(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cond: &IncidentCondition,
    k: u64,
    opts: &BuildOptions,
) -> Result<MeasuredCell> {
    let mut r = rng::stream(opts.seed, &[rng::domain::MEASURED_WALL, k]);
    let shift: (f64, f64) = (r.gen(), r.gen());
    let n = opts.histories_per_cell;
    let g = ((n as f64) / GOLDEN).round().max(1.0) as u64;
    let mut pairs = Vec::with_capacity(n as usize);
    let (mut left, mut lost) = (0u64, 0u64);
    // The incident direction's β in the walk's axes (the same for every history of the cell).
    let mut beta_walked = None;
    for i in 0..n {
        let a = (i as f64 / n as f64 + shift.0).fract();
        let b = (((i * g) % n) as f64 / n as f64 + shift.1).fract();
        let h = history_entered(tracker, setup, cond, (a, b), &mut r, |_| {});
        match h.fate {
            Fate::Escaped => match effective_normal(&h.incident, &h.velocity) {
                Some(n) => {
                    pairs.push(xi_zeta_of_normal(&n));
                    beta_walked.get_or_insert_with(|| incident_angles(&h.incident).1);
                }
                None => lost += 1,
            },
            Fate::Lost(LostReason::LeftPatch) => left += 1,
            Fate::Lost(_) => lost += 1,
        }
    }
    if (pairs.len() as u64) < MIN_PAIRS {
        // Too few histories stayed on the scan (a grazing row of a small scan): the cell
        // cannot be served, which its counts say; its law is the mean wall's.
        if left > 0 && (left as f64) / (n as f64) > SERVED_LEFT_BOUND {
            return Ok(MeasuredCell {
                law: CellLaw::unserved(n, left, lost),
                turn: Turn {
                    deg: f64::NAN,
                    se_deg: f64::NAN,
                },
            });
        }
        return Err(Error::Input(format!(
            "the measured-wall table's cell at α⁻ = {}°, β⁻ = {}°: only {} of {n} histories left the wall ({left} left the scan, {lost} lost otherwise)",
            cond.alpha_in_deg(),
            cond.beta_in_deg(),
            pairs.len()
        )));
    }
    let turn = turn_of(&pairs, beta_walked.unwrap_or(0.0));
    Ok(MeasuredCell {
        law: CellLaw::of_pairs(pairs, n, left, lost),
        turn,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_turn_is_twice_the_elements_inclination_towards_the_incidence() {
        // Elements tilted by ξ' = 0.01 rad: seen along x (β = 0) they turn a rebound by
        // 0.02 rad; seen across (β = 90°) by nothing.
        let pairs = vec![(0.01, 0.0); 100];
        let t = turn_of(&pairs, 0.0);
        assert!((t.deg - 0.02f64.to_degrees()).abs() < 1e-12 && t.se_deg.abs() < 1e-12);
        assert!(turn_of(&pairs, std::f64::consts::FRAC_PI_2).deg.abs() < 1e-12);
        // Spread ±0.01 rad: mean 0, standard error 2 · 0.01/√(n−1)… of the mean.
        let spread: Vec<(f64, f64)> = (0..100)
            .map(|i| (if i % 2 == 0 { 0.01 } else { -0.01 }, 0.0))
            .collect();
        let t = turn_of(&spread, 0.0);
        let sd = (100.0 * 0.01f64.powi(2) / 99.0).sqrt();
        assert!(t.deg.abs() < 1e-12);
        assert!((t.se_deg - (2.0 * sd / 10.0).to_degrees()).abs() < 1e-12);
    }
}
