//! A measured-wall table from a deterministic reference: every grid cell's histories shot on
//! the wall, their effective elements' law kept.

use super::effective_normal::effective_normal;
use super::grid::{beta_column_deg, cell, ALPHA_ROWS_DEG, BETA_COLUMNS, RANK_BINS};
use super::grid::{ENTRY_ALPHA_DEG, HISTORIES_PER_CELL, SERVED_LEFT_BOUND};
use super::quantiles::{first_served_row, row_served, CellLaw};
use super::refine::{refined_rows, Turn, MAX_REFINED_ROWS};
use super::table::MeasuredWallTable;
use crate::angles::{gamma_rotated, incident_angles, xi_zeta_of_normal};
use crate::collision::CollisionLaw;
use crate::deterministic::{Entry, Fate, History, LostReason, ModelSetup, Tracker};
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

/// The most histories per cell a table is built with: a build numbers the histories it holds
/// at once (at most this many, or [`SHOTS_IN_FLIGHT`]) in 32 bits.
const MAX_HISTORIES: u64 = 1 << 24;

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
    if !(MIN_HISTORIES..=MAX_HISTORIES).contains(&opts.histories_per_cell) {
        return Err(Error::invalid(
            "histories_per_cell",
            opts.histories_per_cell.to_string(),
            &format!("{MIN_HISTORIES} to {MAX_HISTORIES}"),
        ));
    }
    let setup = build_setup(deviations);
    // The cells `(row, column)` of `rows`, each with its stream's key.
    let row_cells = |rows: &[(f64, u64)]| -> Result<Vec<MeasuredCell>> {
        let cells: Vec<CellShots> = (0..rows.len() * BETA_COLUMNS)
            .map(|k| {
                let ((alpha, key), column) = (rows[k / BETA_COLUMNS], k % BETA_COLUMNS);
                let cond = IncidentCondition::from_degrees(-alpha, beta_column_deg(column));
                CellShots::new(tracker, &setup, cond, key + column as u64, opts)
            })
            .collect();
        let n = opts.histories_per_cell;
        shoot_cells(tracker, &setup, &cells, n, SHOTS_IN_FLIGHT, progress)
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

/// What a build's histories are: particle centres bouncing ideally elastically at a fixed
/// speed, without spin (so that they draw nothing, [`CellShots`]).
fn build_setup(deviations: Deviations) -> ModelSetup {
    ModelSetup {
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
    }
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
/// deviations (the scan's, `lay`'s, where the block has none). Every direction enters over one
/// region, that of [`ENTRY_ALPHA_DEG`]. What `rebound scan --measured-wall` and Python's
/// `measured_wall_table` build.
pub fn scan_table(
    levelled: &crate::ScanField,
    lay: &crate::scan::Lay,
    diameter_m: Option<f64>,
    triangulation: crate::Triangulation,
    source: &str,
    opts: &BuildOptions,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<MeasuredWallTable> {
    let mut wall =
        crate::deterministic::in_place_wall(levelled, lay.angle, diameter_m, triangulation)?;
    wall.entry_alpha = Some(ENTRY_ALPHA_DEG.to_radians());
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

/// A cell to shoot: its incident direction and the lattice its histories enter on.
///
/// The histories enter on a rank-1 lattice over the entry region (generator `round(n/φ)`,
/// the Fibonacci lattice when `n` is a Fibonacci number), shifted by a uniform draw of the
/// cell's stream (Cranley & Patterson 1976), rather than at independent uniform points: the
/// law of a wall is an average over where particles land, and a lattice spreads them evenly,
/// so the table's sampling error falls faster than `1/√n` (measured: docs/design-notes.md).
struct CellShots {
    cond: IncidentCondition,
    /// What the cell's histories share. A build's speed and spin have no spread, so a
    /// history draws nothing from the cell's stream after its shift, and one entry drawn for
    /// the cell is each history's: a history is a function of its cell and index alone,
    /// whatever order the histories are shot in.
    entry: Entry,
    shift: (f64, f64),
    generator: u64,
    n: u64,
}

impl CellShots {
    fn new(
        tracker: &Tracker<'_>,
        setup: &ModelSetup,
        cond: IncidentCondition,
        k: u64,
        opts: &BuildOptions,
    ) -> Self {
        let mut stream = rng::stream(opts.seed, &[rng::domain::MEASURED_WALL, k]);
        let shift: (f64, f64) = (stream.gen(), stream.gen());
        let n = opts.histories_per_cell;
        CellShots {
            cond,
            entry: Entry::draw(tracker, setup, &cond, &mut stream),
            shift,
            generator: ((n as f64) / GOLDEN).round().max(1.0) as u64,
            n,
        }
    }

    /// The uniform entry numbers `(a, b)` of history `i`: its lattice point.
    #[inline]
    fn lattice_point(&self, i: u64) -> (f64, f64) {
        let n = self.n;
        let a = (i as f64 / n as f64 + self.shift.0).fract();
        let b = (((i * self.generator) % n) as f64 / n as f64 + self.shift.1).fract();
        (a, b)
    }
}

/// What one history leaves its cell's law.
#[derive(Clone, Copy)]
enum Shot {
    /// Left the wall: its effective element `(ξ', ζ')`.
    Escaped((f64, f64)),
    LeftPatch,
    Lost,
}

/// History `i` of `cell`.
fn history_of(tracker: &Tracker<'_>, setup: &ModelSetup, cell: &CellShots, i: u64) -> History {
    cell.entry
        .history(tracker, setup, cell.lattice_point(i), |_| {})
}

/// What history `i` of `cell` leaves its law.
fn shoot(tracker: &Tracker<'_>, setup: &ModelSetup, cell: &CellShots, i: u64) -> Shot {
    let h = history_of(tracker, setup, cell, i);
    match h.fate {
        Fate::Escaped => match effective_normal(&h.incident, &h.velocity) {
            Some(n) => Shot::Escaped(xi_zeta_of_normal(&n)),
            None => Shot::Lost,
        },
        Fate::Lost(LostReason::LeftPatch) => Shot::LeftPatch,
        Fate::Lost(_) => Shot::Lost,
    }
}

/// Histories a build holds at once (their order, where each is shot, their shots: 32 bytes
/// each, 64 MiB), whatever the histories per cell.
const SHOTS_IN_FLIGHT: u64 = 1 << 21;

/// Histories shot by one task: a thousand tasks in a group of [`SHOTS_IN_FLIGHT`], so that
/// two threads finish together, each a run of neighbours on the wall.
const SHOT_CHUNK: usize = 2048;

/// The laws of `cells`, `n` histories each. Histories are shot in the order of where they
/// are expected to meet the wall ([`LocalityKey`]), across as many cells at once as
/// `in_flight` histories allow ([`SHOTS_IN_FLIGHT`]), then each cell's are taken in their own
/// order: the heights and tile maxima a history reads are then mostly those its predecessor
/// read, where shooting cell by cell met a new part of a wall larger than the caches at every
/// history (a 4096² scan holds 128 MiB of heights). Only the order changes, not a history:
/// the table is the same for any order and thread count.
fn shoot_cells(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cells: &[CellShots],
    n: u64,
    in_flight: u64,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<Vec<MeasuredCell>> {
    let per_group = (in_flight / n).max(1) as usize;
    let mut laws = Vec::with_capacity(cells.len());
    for group in cells.chunks(per_group) {
        // Each history's block, then the histories block by block (a counting sort), each
        // block's in cell and index order.
        let mut blocks = vec![0u32; group.len() * n as usize];
        blocks
            .par_chunks_mut(n as usize)
            .zip(group)
            .for_each(|(out, cell)| {
                let at = LocalityKey::new(tracker, cell);
                for (i, block) in out.iter_mut().enumerate() {
                    *block = at.block(cell.lattice_point(i as u64));
                }
            });
        let mut starts = vec![0u32; LocalityKey::blocks(tracker) + 1];
        for &k in &blocks {
            starts[k as usize + 1] += 1;
        }
        for k in 1..starts.len() {
            starts[k] += starts[k - 1];
        }
        // `order[p]` is the history shot `p`-th, `shot_of[h]` where history `h` is shot.
        let mut order = vec![0u32; blocks.len()];
        let mut shot_of = blocks;
        for (h, k) in shot_of.iter_mut().enumerate() {
            let p = &mut starts[*k as usize];
            order[*p as usize] = h as u32;
            *k = *p;
            *p += 1;
        }
        let mut shots = vec![Shot::Lost; order.len()];
        shots
            .par_chunks_mut(SHOT_CHUNK)
            .zip(order.par_chunks(SHOT_CHUNK))
            .for_each(|(out, histories)| {
                for (shot, &h) in out.iter_mut().zip(histories) {
                    let (c, i) = (h as u64 / n, h as u64 % n);
                    *shot = shoot(tracker, setup, &group[c as usize], i);
                }
            });
        drop(order);
        let group_laws: Vec<Result<MeasuredCell>> = shot_of
            .par_chunks(n as usize)
            .zip(group)
            .map(|(at, cell)| {
                let law = cell_law(tracker, setup, cell, at.iter().map(|&p| shots[p as usize]));
                progress(n);
                law
            })
            .collect();
        for law in group_laws {
            laws.push(law?);
        }
    }
    Ok(laws)
}

/// Side, in cells, of the square blocks of the wall a build shoots its histories block by
/// block in: 64² cells' heights are 32 KiB, which the caches hold while the block's histories
/// are walked.
const LOCALITY_BLOCK: usize = 64;

/// Where a cell's histories are expected to meet the wall: the entry point moved downstream
/// by the descent from the entry height to the mid height, as the block of the wall there.
/// Only an order ([`shoot_cells`]): no result depends on it.
struct LocalityKey {
    /// The entry region's affine map from `(a, b)`: its origin and extents.
    origin: (f64, f64),
    extent: (f64, f64),
    /// The descent's horizontal run.
    run: (f64, f64),
    periods: (f64, f64),
    blocks: (usize, usize),
}

impl LocalityKey {
    fn new(tracker: &Tracker<'_>, cell: &CellShots) -> Self {
        let alpha = cell.cond.alpha_in;
        let u = cell.entry.velocity();
        let origin = cell.entry.start(tracker, (0.0, 0.0));
        let end = cell.entry.start(tracker, (1.0, 1.0));
        let extent = (end.0 - origin.0, end.1 - origin.1);
        let h = (u.x * u.x + u.z * u.z).sqrt();
        let tan = alpha.tan().abs();
        let reach = if h > 0.0 && tan > 0.0 {
            0.5 * (tracker.top() - tracker.bottom()) / tan
        } else {
            0.0
        };
        let run = if h > 0.0 {
            (reach * u.x / h, reach * u.z / h)
        } else {
            (0.0, 0.0)
        };
        LocalityKey {
            origin,
            extent,
            run,
            periods: tracker.periods(),
            blocks: Self::grid_blocks(tracker),
        }
    }

    /// The blocks along `x` and `z`.
    fn grid_blocks(tracker: &Tracker<'_>) -> (usize, usize) {
        let (nx, nz) = tracker.grid();
        (nx.div_ceil(LOCALITY_BLOCK), nz.div_ceil(LOCALITY_BLOCK))
    }

    /// How many blocks a wall has.
    fn blocks(tracker: &Tracker<'_>) -> usize {
        let (bx, bz) = Self::grid_blocks(tracker);
        bx * bz
    }

    /// The block of entry numbers `(a, b)`, row by row along `x`.
    #[inline]
    fn block(&self, (a, b): (f64, f64)) -> u32 {
        let x = self.origin.0 + a * self.extent.0 + self.run.0;
        let z = self.origin.1 + b * self.extent.1 + self.run.1;
        let index = |v: f64, period: f64, blocks: usize| -> usize {
            let s = ((v / period).rem_euclid(1.0) * blocks as f64) as usize;
            s.min(blocks - 1)
        };
        let (bx, bz) = (
            index(x, self.periods.0, self.blocks.0),
            index(z, self.periods.1, self.blocks.1),
        );
        (bz * self.blocks.0 + bx) as u32
    }
}

/// One cell's law from its histories' shots, in their order: the escaped ones' effective
/// elements in the wall's frame `(ξ', ζ')`.
fn cell_law(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cell: &CellShots,
    shots: impl ExactSizeIterator<Item = Shot>,
) -> Result<MeasuredCell> {
    let (cond, n) = (&cell.cond, shots.len() as u64);
    let mut pairs = Vec::with_capacity(shots.len());
    let (mut left, mut lost) = (0u64, 0u64);
    let mut first_escaped = None;
    for (i, shot) in shots.enumerate() {
        match shot {
            Shot::Escaped(pair) => {
                pairs.push(pair);
                first_escaped.get_or_insert(i as u64);
            }
            Shot::LeftPatch => left += 1,
            Shot::Lost => lost += 1,
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
    // The incident direction's β in the walk's axes (the same for every history of the
    // cell), as the first escaped history walked it.
    let beta_walked = first_escaped.map_or(0.0, |i| {
        incident_angles(&history_of(tracker, setup, cell, i).incident).1
    });
    let turn = turn_of(&pairs, beta_walked);
    Ok(MeasuredCell {
        law: CellLaw::of_pairs(pairs, n, left, lost),
        turn,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cell's law as a build took it before histories were shot in the order of the wall:
    /// each history in index order (at `cell`'s lattice points), drawing its own entry from
    /// the cell's stream as the previous one left it.
    fn cell_in_index_order(
        tracker: &Tracker<'_>,
        setup: &ModelSetup,
        cell: &CellShots,
        k: u64,
        opts: &BuildOptions,
    ) -> CellLaw {
        let mut r = rng::stream(opts.seed, &[rng::domain::MEASURED_WALL, k]);
        let _shift: (f64, f64) = (r.gen(), r.gen());
        let n = opts.histories_per_cell;
        let (mut pairs, mut left, mut lost) = (Vec::new(), 0, 0);
        for i in 0..n {
            let ab = cell.lattice_point(i);
            let h = crate::deterministic::history_entered(
                tracker,
                setup,
                &cell.cond,
                ab,
                &mut r,
                |_| {},
            );
            match (h.fate, effective_normal(&h.incident, &h.velocity)) {
                (Fate::Escaped, Some(n)) => pairs.push(xi_zeta_of_normal(&n)),
                (Fate::Lost(LostReason::LeftPatch), _) => left += 1,
                _ => lost += 1,
            }
        }
        CellLaw::of_pairs(pairs, n, left, lost)
    }

    #[test]
    fn shooting_in_the_order_of_the_wall_changes_no_law() {
        let field = super::super::test_wall(256, 5);
        let dev = crate::surface::measured_deviations(&field);
        let setup = build_setup(dev);
        let opts = BuildOptions {
            histories_per_cell: 1024,
            seed: 7,
        };
        let periodic = Tracker::new(&field, 1000).unwrap();
        let patch = Tracker::in_place(&field, 1000, 30f64.to_radians()).unwrap();
        for tracker in [&periodic, &patch] {
            // Grazing to normal, both senses of β, on a patch and periodic.
            let conds: Vec<(IncidentCondition, u64)> =
                [(-3.0, 15.0), (-10.0, -120.0), (-45.0, 90.0), (-90.0, 0.0)]
                    .iter()
                    .enumerate()
                    .map(|(k, &(a, b))| (IncidentCondition::from_degrees(a, b), 11 * k as u64))
                    .collect();
            let cells: Vec<CellShots> = conds
                .iter()
                .map(|&(c, k)| CellShots::new(tracker, &setup, c, k, &opts))
                .collect();
            // Groups of one cell and of all: the order differs, the laws must not.
            for in_flight in [1024, 1 << 21] {
                let laws = shoot_cells(tracker, &setup, &cells, 1024, in_flight, &|_| {}).unwrap();
                for (((cond, k), cell), law) in conds.iter().zip(&cells).zip(&laws) {
                    let reference = cell_in_index_order(tracker, &setup, cell, *k, &opts);
                    assert!(
                        reference.left_share() < 1.0 && law.law == reference,
                        "{cond:?}"
                    );
                }
            }
        }
    }

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
