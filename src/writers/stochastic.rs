//! The outputs of `rebound stochastic` (one run or merged shards): `summary.csv`,
//! `pdfs.csv`, `moments.csv`, the figures and `run.toml`.

use crate::case::stochastic::Prepared;
use crate::case::Warning;
use crate::figures;
use crate::output::{prepare_out_dir, Manifest};
use crate::schema::write_tables;
use roughwall::models::gamma_model_curve;
use roughwall::tally::ConditionStats;
use roughwall::tally::ConditionTally;
use roughwall::Result;
use roughwall::RoughWallModel;
use std::path::Path;

use super::{f, insert_standard_errors, round};

/// Writes the outputs of a run (or of merged shards) into `dir` (the staging directory of
/// the run's [`OutputDir`](crate::output::OutputDir)): `summary.csv`, `pdfs.csv`, `moments.csv`, the figures and
/// `run.toml`. `stats` are the per-condition run statistics of a one-process run (`None`
/// after a merge). Returns the warnings about the run (e.g. lost particles).
pub fn finish(
    dir: &Path,
    mut manifest: Manifest,
    p: &Prepared,
    tallies: &[ConditionTally],
    stats: Option<&[ConditionStats]>,
    seconds: f64,
) -> Result<Vec<Warning>> {
    let mut warnings = Vec::new();
    let wall = p.setup.wall;
    let mut results = Vec::with_capacity(tallies.len());
    let mut rows = Vec::with_capacity(tallies.len());
    for (k, t) in tallies.iter().enumerate() {
        let cond = t.spec.condition;
        let c = &t.counters;
        if c.capped > 0 {
            warnings.push(Warning(format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} rebounds hit the guard of {} candidate walls and were taken off the mean wall",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                c.capped,
                c.particles,
                roughwall::stochastic::MAX_TRIES
            )));
        }
        let mut r = t.result();
        r.push_curve(gamma_model_curve(&wall, &cond, p.scene.bin_width_deg));
        let mut row = toml::Table::new();
        row.insert("alpha_in_deg".into(), f(cond.alpha_in_deg()));
        row.insert("beta_in_deg".into(), f(cond.beta_in_deg()));
        row.insert("rebounds".into(), toml::Value::Integer(c.particles as i64));
        row.insert(
            "blocks".into(),
            toml::Value::Integer(t.blocks().len() as i64),
        );
        if let Some(s) = stats.and_then(|s| s.get(k)) {
            row.insert("worker_seconds".into(), f(round(s.worker_seconds, 4)));
            row.insert(
                "rebounds_per_worker_s".into(),
                f(if s.worker_seconds > 0.0 {
                    (c.particles as f64 / s.worker_seconds).round()
                } else {
                    0.0
                }),
            );
            if let Some(reached) = s.target_reached {
                row.insert("target_reached".into(), toml::Value::Boolean(reached));
            }
        }
        row.insert(
            "candidate_walls_per_rebound".into(),
            f(round(c.tries as f64 / c.particles.max(1) as f64, 4)),
        );
        if let Some(ps) = r.summary.p_single {
            row.insert("p_single".into(), f(round(ps.value, 6)));
        }
        insert_standard_errors(&mut row, &r.summary);
        row.insert("capped".into(), toml::Value::Integer(c.capped as i64));
        rows.push(toml::Value::Table(row));
        results.push(r);
    }
    prepare_out_dir(dir)?;
    write_tables(dir, &results)?;
    let figs = figures::stochastic::write(dir, &results, &wall, "SM")?;
    for (k, v) in &p.notes {
        manifest.set(k, v.clone());
    }
    manifest.set("conditions", toml::Value::Array(rows));
    manifest.set(
        "figures",
        toml::Value::Array(figs.into_iter().map(toml::Value::String).collect()),
    );
    manifest.set_run("psi", f(p.scene.psi));
    if !p.setup.model.is_paper() {
        manifest.set_run("model", toml::Value::String(p.setup.model.name().into()));
        manifest.set_run(
            "delta_gamma_deg",
            f(p.setup.model.roughness_angle(&p.setup.wall).to_degrees()),
        );
    }
    super::scene_entries(&mut manifest, &p.scene, p.setup.erosion.as_ref());
    manifest.set_run("delta_xi_deg", f(round(wall.delta_xi.to_degrees(), 6)));
    manifest.set_run("delta_zeta_deg", f(round(wall.delta_zeta.to_degrees(), 6)));
    let total: u64 = tallies.iter().map(|t| t.counters.particles).sum();
    manifest.set_run("compute_s", f(round(seconds, 4)));
    if stats.is_some() && seconds > 0.0 {
        manifest.set_run("rebounds_per_s", f((total as f64 / seconds).round()));
    }
    manifest.write(dir)?;
    warnings.extend(super::target_warnings(
        tallies,
        stats,
        p.scene.target_se_deg,
    ));
    Ok(warnings)
}
