//! `rebound scan --measured-wall`: the wall's own stochastic model. For the point particle and
//! each diameter of the card, the in-place deterministic reference on the levelled scan (its
//! centre surface for a sphere) is run over the grid of incident directions and its rebound
//! law kept as a measured-wall table (`roughwall::measured_wall`), written beside the card as
//! `measured_wall_point.txt` or `measured_wall_<D>um.txt` and named by the card's `[wall]` or
//! row (`measured_wall_table`), for `[stochastic] model = "measured-wall"` (docs/models.md,
//! "The measured-wall model").
//!
//! A diameter the scan cannot serve (its centre surface too small, every cell's histories
//! leaving it) gets no table and a note saying why; the card is still written.

use crate::output::fmt_num;
use crate::progress::Progress;
use crate::writers::measured_wall::{MeasuredWallEntry, VersusPaper};
use crate::writers::measured_wall::{VERSUS_DIRECTIONS, VERSUS_REBOUNDS};
use roughwall::measured_wall::MeasuredWallTable;
use roughwall::measured_wall::{scan_table, BuildOptions, BUILD_CELLS};
use roughwall::scan::Characterisation;
use roughwall::{Result, Triangulation};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

/// The table's file name for a particle of `diameter_m` (0: the point).
pub fn table_file_name(diameter_m: f64) -> String {
    if diameter_m > 0.0 {
        format!("measured_wall_{}um.txt", fmt_num(diameter_m * 1e6))
    } else {
        "measured_wall_point.txt".to_string()
    }
}

/// Builds and writes (into `dir`) the tables of the point particle and of each of
/// `diameters_m`, on the levelled scan of `c` (which has a lay), with `histories_per_cell`
/// histories per grid cell drawn from `seed`; `file` names the scan.
/// A table that cannot be built is an entry with a note, not an error; an output that cannot
/// be written is.
pub fn build_tables(
    c: &Characterisation,
    file: &str,
    diameters_m: &[f64],
    triangulation: Triangulation,
    (histories_per_cell, seed): (u64, u64),
    dir: &Path,
) -> Result<Vec<MeasuredWallEntry>> {
    let Some(lay) = c.lay else {
        return Ok(Vec::new());
    };
    let particles: Vec<f64> = std::iter::once(0.0)
        .chain(diameters_m.iter().copied())
        .collect();
    // At most: the base rows and every row a build may add.
    let per_table = BUILD_CELLS as u64 * histories_per_cell;
    let progress = Progress::particles(per_table * particles.len() as u64, "measured-wall tables");
    let mut entries = Vec::with_capacity(particles.len());
    for &d in &particles {
        let t0 = Instant::now();
        let what = match d > 0.0 {
            true => format!("{file}, {} µm sphere", fmt_num(d * 1e6)),
            false => format!("{file}, point particle"),
        };
        let opts = BuildOptions {
            histories_per_cell,
            seed,
        };
        let shot = AtomicU64::new(0);
        let built = scan_table(
            &c.levelled,
            &lay,
            (d > 0.0).then_some(d),
            triangulation,
            &what,
            &opts,
            &|n| {
                shot.fetch_add(n, Ordering::Relaxed);
                progress.advance(n)
            },
        );
        // The plan held every row a build may add; what it did not shoot will not run.
        progress.skip(per_table.saturating_sub(shot.load(Ordering::Relaxed)));
        let entry = match built {
            Ok(table) => {
                let name = table_file_name(d);
                crate::output::write_atomic(&dir.join(&name), table.to_text().as_bytes())?;
                let lowest = table.lowest_served_alpha_deg();
                let note = match lowest > roughwall::measured_wall::ALPHA_ROWS_DEG[0] {
                    true => format!(
                        "measured from |α⁻| = {}° up: the scan is too small for grazing incidence below (more than {} % of the histories leave it); there the {}° law is taken",
                        fmt_num(lowest),
                        fmt_num(roughwall::measured_wall::SERVED_LEFT_BOUND * 100.0),
                        fmt_num(lowest)
                    ),
                    false => String::new(),
                };
                MeasuredWallEntry {
                    diameter_m: d,
                    file: Some(name),
                    lowest_alpha_deg: lowest,
                    max_left_share: table.max_served_left_share(),
                    note,
                    seconds: t0.elapsed().as_secs_f64(),
                    histories_per_cell,
                    refined_rows_deg: table.refined_rows_deg(),
                    versus_paper: Some(versus_paper(&table, seed)?),
                }
            }
            Err(e @ roughwall::Error::Input(_)) => MeasuredWallEntry {
                diameter_m: d,
                file: None,
                lowest_alpha_deg: f64::NAN,
                max_left_share: f64::NAN,
                note: format!("no measured-wall table: {e}"),
                seconds: t0.elapsed().as_secs_f64(),
                histories_per_cell,
                refined_rows_deg: Vec::new(),
                versus_paper: None,
            },
            Err(e) => return Err(e),
        };
        entries.push(entry);
    }
    progress.finish();
    Ok(entries)
}

/// The paper's model with the deviations of the wall `table` was measured on, against the
/// measured-wall model of `table`, ideally elastic, over [`VERSUS_DIRECTIONS`]: rebound `i` of
/// direction `k` draws from `rng::stream(seed, [MEASURED_WALL, u64::MAX − k, i])` for both
/// models (the table's histories key their cells from 0 up).
fn versus_paper(table: &MeasuredWallTable, seed: u64) -> Result<VersusPaper> {
    use roughwall::models::{rebound_off_table, rebound_with, AnyModel};
    use roughwall::stochastic::Contact;
    let law = roughwall::CollisionLaw::Elastic;
    let wall = table.deviations;
    let contact = Contact {
        wall: &wall,
        law: &law,
        psi: roughwall::stochastic::PSI_PAPER,
        diameter_m: 0.0,
    };
    let mut v = VersusPaper {
        ks: 0.0,
        ks_at: (0.0, 0.0),
        bias_deg: 0.0,
        bias_at: (0.0, 0.0),
    };
    for (k, &(a, b)) in VERSUS_DIRECTIONS.iter().enumerate() {
        let u = roughwall::angles::velocity_from_angles(1.0, a.to_radians(), b.to_radians());
        let prefix = roughwall::rng::StreamPrefix::new(
            seed,
            &[roughwall::rng::domain::MEASURED_WALL, u64::MAX - k as u64],
        );
        let inc = table.incidence(a.to_radians(), b.to_radians());
        let alphas = |own: bool| -> Vec<f64> {
            (0..VERSUS_REBOUNDS)
                .map(|i| {
                    let mut r = prefix.stream(i);
                    let zero = nalgebra::Vector3::zeros();
                    let out = match own {
                        true => {
                            rebound_off_table(table, &inc, u, zero, &contact, &mut r, |_, _, _| {})
                        }
                        false => rebound_with(&AnyModel::PAPER, u, zero, &contact, &mut r),
                    };
                    roughwall::angles::incident_angles(&out.velocity)
                        .0
                        .to_degrees()
                })
                .collect()
        };
        let (mut p, mut w) = (alphas(false), alphas(true));
        let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len() as f64;
        let bias = mean(&p) - mean(&w);
        let ks = roughwall::tally::ks_samples(&mut p, &mut w);
        if ks > v.ks {
            (v.ks, v.ks_at) = (ks, (a, b));
        }
        if bias.abs() > v.bias_deg.abs() {
            (v.bias_deg, v.bias_at) = (bias, (a, b));
        }
    }
    Ok(v)
}
