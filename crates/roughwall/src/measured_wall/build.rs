//! A measured-wall table from a deterministic reference: every grid cell's histories shot on
//! the wall, their effective elements' law kept.

use super::effective_normal::effective_normal;
use super::grid::{beta_column_deg, ALPHA_ROWS_DEG, BETA_COLUMNS, CELLS, RANK_BINS};
use super::grid::{HISTORIES_PER_CELL, SERVED_LEFT_BOUND};
use super::quantiles::CellLaw;
use super::table::MeasuredWallTable;
use crate::angles::xi_zeta_of_normal;
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
/// element ([`super::effective_normal`]) and kept as its `(ξ', ζ')`. `deviations` are the wall's own (for the table's
/// record), `source` says what it is. `progress(histories)` is called with each finished
/// cell's histories (from worker threads). The table is the same for any thread count.
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
    let cells: Vec<Result<CellLaw>> = (0..CELLS)
        .into_par_iter()
        .map(|k| {
            let (row, column) = (k / BETA_COLUMNS, k % BETA_COLUMNS);
            let cond =
                IncidentCondition::from_degrees(-ALPHA_ROWS_DEG[row], beta_column_deg(column));
            let law = cell_law(tracker, &setup, &cond, k as u64, opts);
            progress(opts.histories_per_cell);
            law
        })
        .collect();
    let cells = cells.into_iter().collect::<Result<Vec<_>>>()?;
    let served = |row: usize| {
        (0..BETA_COLUMNS).all(|c| cells[row * BETA_COLUMNS + c].left_share() <= SERVED_LEFT_BOUND)
    };
    let rows = ALPHA_ROWS_DEG.len();
    let mut first_row = rows;
    while first_row > 0 && served(first_row - 1) {
        first_row -= 1;
    }
    if first_row == rows {
        let worst = cells[(rows - 1) * BETA_COLUMNS..]
            .iter()
            .map(CellLaw::left_share)
            .fold(0.0, f64::max);
        return Err(Error::Input(format!(
            "{source}: too small for the measured-wall model: even at normal incidence {:.1} % of the histories leave it (at most {} allowed)",
            worst * 100.0,
            SERVED_LEFT_BOUND
        )));
    }
    Ok(MeasuredWallTable {
        source: source.to_string(),
        first_row,
        deviations,
        seed: opts.seed,
        cells,
    })
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
) -> Result<CellLaw> {
    let mut r = rng::stream(opts.seed, &[rng::domain::MEASURED_WALL, k]);
    let shift: (f64, f64) = (r.gen(), r.gen());
    let n = opts.histories_per_cell;
    let g = ((n as f64) / GOLDEN).round().max(1.0) as u64;
    let mut pairs = Vec::with_capacity(n as usize);
    let (mut left, mut lost) = (0u64, 0u64);
    for i in 0..n {
        let a = (i as f64 / n as f64 + shift.0).fract();
        let b = (((i * g) % n) as f64 / n as f64 + shift.1).fract();
        let h = history_entered(tracker, setup, cond, (a, b), &mut r, |_| {});
        match h.fate {
            Fate::Escaped => match effective_normal(&h.incident, &h.velocity) {
                Some(n) => pairs.push(xi_zeta_of_normal(&n)),
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
            return Ok(CellLaw::unserved(n, left, lost));
        }
        return Err(Error::Input(format!(
            "the measured-wall table's cell at α⁻ = {}°, β⁻ = {}°: only {} of {n} histories left the wall ({left} left the scan, {lost} lost otherwise)",
            cond.alpha_in_deg(),
            cond.beta_in_deg(),
            pairs.len()
        )));
    }
    Ok(CellLaw::of_pairs(pairs, n, left, lost))
}
