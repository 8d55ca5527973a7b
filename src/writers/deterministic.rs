//! The outputs of `rebound deterministic` (one run or merged shards): `summary.csv`,
//! `pdfs.csv`, `moments.csv`, the figures and `run.toml`.

use crate::case::deterministic::Prepared;
use crate::case::Warning;
use crate::figures;
use crate::output::{prepare_out_dir, Manifest};
use crate::schema::write_tables;
use roughwall::deterministic::SceneOptions;
use roughwall::deterministic::{LostCounts, ScanReference, LEFT_PATCH_BOUND};
use roughwall::deterministic::{SphereDilation, SurfacePlan};
use roughwall::surface::pooled_deviations;
use roughwall::tally::ConditionStats;
use roughwall::tally::{ConditionResult, ConditionTally};
use roughwall::HeightField;
use roughwall::IncidentCondition;
use roughwall::{Error, Result};
use std::path::Path;

use super::{f, insert_standard_errors, round};

/// `surface_choice` of `run.toml`: where the surface came from, its grid and (`measure`)
/// the deviations it has (over all its realisations).
pub fn surface_table(
    plan: Option<&SurfacePlan>,
    file: Option<&Path>,
    fields: &[&HeightField],
    source: &str,
    opt: &SceneOptions,
    measure: bool,
    met: Option<(f64, f64)>,
) -> toml::Value {
    let Some(&field) = fields.first() else {
        return toml::Value::Table(toml::Table::new());
    };
    let mut t = toml::Table::new();
    t.insert("source".into(), source.into());
    if let Some(p) = file {
        t.insert("file".into(), p.display().to_string().into());
        t.insert("spacing_x_um".into(), f(field.dx * 1e6));
        t.insert("spacing_z_um".into(), f(field.dz * 1e6));
    }
    if let Some(plan) = plan {
        let spec = plan.spec();
        let (l, n, h, cx, cz) = (
            spec.length_m,
            spec.nodes,
            spec.rms_height_m,
            spec.corr_length_x_m,
            spec.corr_length_z_m,
        );
        t.insert("length_um".into(), f(l * 1e6));
        t.insert("nodes".into(), toml::Value::Integer(n as i64));
        t.insert("spacing_um".into(), f(l / n as f64 * 1e6));
        t.insert("rms_height_um".into(), f(h * 1e6));
        if let Some(c) = cx {
            t.insert("corr_length_x_um".into(), f(c * 1e6));
        }
        if let Some(c) = cz {
            t.insert("corr_length_z_um".into(), f(c * 1e6));
        }
        if let SurfacePlan::Auto(_) = plan {
            t.insert(
                "spacing_per_corr_length".into(),
                f(opt.spacing_per_corr_length),
            );
            t.insert("side_per_corr_length".into(), f(opt.side_per_corr_length));
            t.insert("wall_deviations".into(), opt.deviations.name().into());
            // What the grid's triangles have on average (docs/physics.md §4): the
            // deviations asked for with "normal-angles", 0.3–2.1 % less with "eq15".
            let e = roughwall::surface::expected_deviations(h, [cx, cz], spec.spacing_m());
            t.insert(
                "expected_delta_xi_deg".into(),
                f(round(e.delta_xi.to_degrees(), 4)),
            );
            t.insert(
                "expected_delta_zeta_deg".into(),
                f(round(e.delta_zeta.to_degrees(), 4)),
            );
            t.insert(
                "rule".into(),
                "spacing = c_L,min / spacing_per_corr_length; side ≥ side_per_corr_length · c_L,max; nodes = 8 × 5-smooth".into(),
            );
        }
    }
    t.insert("grid_nx".into(), toml::Value::Integer(field.nx as i64));
    t.insert("grid_nz".into(), toml::Value::Integer(field.nz as i64));
    t.insert("triangulation".into(), field.triangulation.name().into());
    if fields.len() > 1 {
        // The realisations' seeds follow from the run's (`scene::realisation_seed`).
        t.insert("surfaces".into(), toml::Value::Integer(fields.len() as i64));
    }
    if let (true, Some((xi, zeta))) = (measure, met) {
        // A scan in place: its own triangles along and across its lay (the field's axes are
        // the scan's, and the seam cells that close its period are not the scan's).
        t.insert("measured_delta_xi_deg".into(), f(round(xi.to_degrees(), 4)));
        t.insert(
            "measured_delta_zeta_deg".into(),
            f(round(zeta.to_degrees(), 4)),
        );
    } else if measure {
        // Over all realisations: the deviations of the ensemble the histories saw.
        let m = pooled_deviations(fields);
        t.insert(
            "measured_delta_xi_deg".into(),
            f(round(m.delta_xi.to_degrees(), 4)),
        );
        t.insert(
            "measured_delta_zeta_deg".into(),
            f(round(m.delta_zeta.to_degrees(), 4)),
        );
    }
    toml::Value::Table(t)
}

/// `sphere_contact` of `run.toml`: the sphere whose centre rides on the dilated surface.
pub fn sphere_table(s: &SphereDilation) -> toml::Value {
    let mut t = toml::Table::new();
    t.insert("contact".into(), "sphere".into());
    t.insert("diameter_um".into(), f(s.diameter_m * 1e6));
    t.insert(
        "approximation".into(),
        "paraboloid cap (sqrt(R^2 - r^2) - R ~ -r^2/2R), Felzenszwalb-Huttenlocher lower envelopes"
            .into(),
    );
    t.insert("contact_fraction".into(), f(round(s.contact_fraction, 6)));
    t.insert("dilation_s".into(), f(round(s.dilation_s, 3)));
    toml::Value::Table(t)
}

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
    let in_place = p
        .notes
        .get("scan")
        .and_then(|s| s.get("reference"))
        .and_then(|r| r.as_str())
        == Some(ScanReference::InPlace.name());
    let mut results = Vec::with_capacity(tallies.len());
    let mut rows = Vec::with_capacity(tallies.len());
    for (k, t) in tallies.iter().enumerate() {
        let cond = t.spec.condition;
        let lost = LostCounts::from_tally(&t.counters.lost);
        // On a scan in place, histories leave the patch at a rate the margins keep small:
        // only a rate above the bound is worth a warning. Every other loss is.
        let others = LostCounts {
            left_patch: 0,
            ..lost
        };
        if others.total() > 0 {
            warnings.push(Warning(format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} particles lost ({})",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                others.total(),
                t.counters.particles,
                others.describe()
            )));
        }
        let left = lost.left_patch as f64 / t.counters.particles.max(1) as f64;
        if left > LEFT_PATCH_BOUND {
            warnings.push(Warning(format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} histories ({:.2} %, above the bound of {} %) left the scan before escaping above it; they are not tallied, so the reference lacks some of its longest (most grazing) flights: use a larger scan or a steeper α⁻",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                lost.left_patch,
                t.counters.particles,
                100.0 * left,
                100.0 * LEFT_PATCH_BOUND,
            )));
        }
        if t.followed() == 0 && lost.left_patch == lost.total() {
            // Every history flew off the scan: the scan is too small for this incidence.
            let scan = p.notes.get("scan");
            let file = scan
                .and_then(|s| s.get("file"))
                .and_then(|f| f.as_str())
                .unwrap_or("the scan");
            return Err(Error::Input(format!(
                "--surface `{file}`: at α⁻ = {}°, β⁻ = {}° every history left the scan before escaping above it: the scan is too small for this incidence (its margins follow from its height range and α⁻; docs/models.md, Measured walls); use a larger scan or a steeper α⁻",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
            )));
        }
        if t.followed() == 0 {
            return Err(Error::Model(format!(
                "α⁻ = {}°, β⁻ = {}°: no particle could be followed ({})",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                lost.describe()
            )));
        }
        let r = t.result();
        rows.push(condition_row(
            &cond,
            t,
            &lost,
            stats.and_then(|s| s.get(k)),
            &r,
            in_place,
        ));
        results.push(r);
    }
    prepare_out_dir(dir)?;
    write_tables(dir, &results)?;
    let figs = figures::deterministic::write(dir, &results, "DS")?;
    for (k, v) in &p.notes {
        manifest.set(k, v.clone());
    }
    manifest.set("conditions", toml::Value::Array(rows));
    manifest.set(
        "figures",
        toml::Value::Array(figs.into_iter().map(toml::Value::String).collect()),
    );
    manifest.set_run(
        "max_collisions",
        toml::Value::Integer(p.options.max_collisions as i64),
    );
    super::scene_entries(&mut manifest, &p.scene, p.setup.erosion.as_ref());
    manifest.set_run("compute_s", f(round(seconds, 4)));
    let total: u64 = tallies.iter().map(|t| t.counters.particles).sum();
    if stats.is_some() && seconds > 0.0 {
        manifest.set_run("particles_per_s", f((total as f64 / seconds).round()));
    }
    manifest.write(dir)?;
    warnings.extend(super::target_warnings(
        tallies,
        stats,
        p.scene.target_se_deg,
    ));
    Ok(warnings)
}

fn condition_row(
    cond: &IncidentCondition,
    t: &ConditionTally,
    lost: &LostCounts,
    stats: Option<&ConditionStats>,
    r: &ConditionResult,
    in_place: bool,
) -> toml::Value {
    let mut row = toml::Table::new();
    row.insert("alpha_in_deg".into(), f(cond.alpha_in_deg()));
    row.insert("beta_in_deg".into(), f(cond.beta_in_deg()));
    row.insert(
        "histories".into(),
        toml::Value::Integer(t.counters.particles as i64),
    );
    row.insert(
        "blocks".into(),
        toml::Value::Integer(t.blocks().len() as i64),
    );
    if let Some(s) = stats {
        row.insert("worker_seconds".into(), f(round(s.worker_seconds, 4)));
        row.insert(
            "particles_per_worker_s".into(),
            f(if s.worker_seconds > 0.0 {
                (t.counters.particles as f64 / s.worker_seconds).round()
            } else {
                0.0
            }),
        );
        if let Some(reached) = s.target_reached {
            row.insert("target_reached".into(), toml::Value::Boolean(reached));
        }
    }
    insert_standard_errors(&mut row, &r.summary);
    row.insert("lost".into(), toml::Value::Integer(lost.total() as i64));
    row.insert(
        "collision_cap_hits".into(),
        toml::Value::Integer(lost.collision_cap as i64),
    );
    if in_place {
        row.insert(
            "left_patch".into(),
            toml::Value::Integer(lost.left_patch as i64),
        );
    }
    toml::Value::Table(row)
}
