//! What each command writes: tables, figures and `run.toml` of a finished run, from the
//! resolved case, the tallies and the physics. High in the module picture: it may use every
//! library module below it (`case`, `figures`, the physics, `tally`, `output`); none of
//! those uses it.
//!
//! * [`deterministic`], [`stochastic`]: `finish` of a Monte Carlo run (and of `merge`).
//! * [`surface`]: the tables of `rebound surface`.
//! * [`scan`]: the summary, wall card and notes of `rebound scan`;
//!   [`scan_diameters`]: its per-diameter deviations and notes; [`measured_wall`]: the
//!   measured-wall tables the card names.

pub mod deterministic;
pub mod force_sweep;
pub mod measured_wall;
pub mod scan;
pub mod scan_diameters;
pub mod stochastic;
pub mod surface;

use crate::case::{Scene, Warning};
use crate::output::{fmt_num, Manifest};
use roughwall::erosion::AngleDependency;
use roughwall::tally::ConditionStats;
use roughwall::tally::{ConditionTally, BLOCK_SIZE};
use roughwall::{ErosionModel, ErosionSetup};

fn f(x: f64) -> toml::Value {
    toml::Value::Float(x)
}

/// The standard errors of the mean `α⁺` and `β⁺ − β⁻` of a condition's manifest row, when
/// they are defined (two values or more).
fn insert_standard_errors(row: &mut toml::Table, s: &roughwall::tally::Summary) {
    let se = |e: Option<roughwall::tally::Estimate>| e.and_then(|e| e.se);
    if let (Some(a), Some(d)) = (se(s.alpha_out), se(s.dbeta)) {
        row.insert("se_mean_alpha_out_deg".into(), f(a));
        row.insert("se_mean_dbeta_deg".into(), f(d));
    }
}

fn round(x: f64, digits: i32) -> f64 {
    let p = 10f64.powi(digits);
    (x * p).round() / p
}

/// The `run.toml` entries both Monte Carlo models write from their shared scene: particles per
/// condition, the target standard error, the block size, the erosion law, the speed reference.
fn scene_entries(manifest: &mut Manifest, scene: &Scene, erosion: Option<&ErosionSetup>) {
    manifest.set_run(
        "particles_per_condition",
        toml::Value::Integer(scene.count as i64),
    );
    if let Some(t) = scene.target_se_deg {
        manifest.set_run("target_se_deg", f(t));
    }
    manifest.set_run("block_size", toml::Value::Integer(BLOCK_SIZE as i64));
    if let Some(e) = erosion {
        manifest.set("erosion", erosion_manifest(e));
    }
    if scene.speed.reference != roughwall::incidence::SpeedReference::Horizontal {
        manifest.set_run(
            "speed_reference",
            toml::Value::String(scene.speed.reference.name().into()),
        );
    }
}

/// The resolved law for `run.toml`: the model, every parameter (defaults filled in, SI
/// units) and the particle mass.
pub fn erosion_manifest(e: &ErosionSetup) -> toml::Value {
    let mut t = toml::Table::new();
    let mut put = |k: &str, v: f64| {
        t.insert(k.into(), toml::Value::Float(v));
    };
    match &e.model {
        ErosionModel::Finnie(f) => {
            put("flow_stress_pa", f.flow_stress_pa);
            put("psi", f.psi);
            put("k", f.k);
        }
        ErosionModel::Dnv(d) => {
            put("k", d.k);
            put("n", d.n);
            put("target_density_kg_m3", d.target_density_kg_m3);
        }
        ErosionModel::Oka(o) => {
            put("hardness_gpa", o.hardness_gpa);
            put("k", o.k);
            put("k1", o.k1);
            put("k2", o.k2);
            put("k3", o.k3);
            put("n1", o.n1);
            put("n2", o.n2);
            put("reference_speed_m_s", o.reference_speed_m_s);
            put("reference_diameter_m", o.reference_diameter_m);
        }
    }
    put("particle_mass_kg", e.particle_mass_kg);
    if let ErosionModel::Dnv(d) = &e.model {
        let a = match d.angle_dependency {
            AngleDependency::Ductile => "ductile",
            AngleDependency::Brittle => "brittle",
        };
        t.insert("angle_dependency".into(), toml::Value::String(a.into()));
    }
    t.insert("model".into(), toml::Value::String(e.model.name().into()));
    toml::Value::Table(t)
}

/// A warning per condition that ran to its particle count without reaching the target
/// standard error (`--target-se`, `[particles] target_se_deg`): the count it stopped at and
/// the standard errors it reached.
pub fn target_warnings(
    tallies: &[ConditionTally],
    stats: Option<&[ConditionStats]>,
    target_se_deg: Option<f64>,
) -> Vec<Warning> {
    let (Some(stats), Some(target)) = (stats, target_se_deg) else {
        return Vec::new();
    };
    tallies
        .iter()
        .zip(stats)
        .filter(|(_, s)| s.target_reached == Some(false))
        .map(|(t, _)| {
            let c = t.spec.condition;
            let se = t
                .running_se()
                .map(|(a, b)| format!("{}° and {}°", fmt_num(a), fmt_num(b)))
                .unwrap_or_else(|| "undefined".into());
            // Over several surfaces the error has a floor that particles cannot lower.
            let surfaces = match t.spec.realisations {
                n if n > 1 => format!(
                    "; over {n} surfaces (or a scan's {n} sub-patches) the error includes their spread, which only more `[deterministic] surfaces` (or a larger scan) lowers"
                ),
                _ => String::new(),
            };
            Warning(format!(
                "α⁻ = {}°, β⁻ = {}°: the target standard error {target}° was not reached in {} particles (the count caps a target: `--particles`, `[particles] count`); standard errors of mean α⁺ and mean β⁺ − β⁻ {se}{surfaces}",
                fmt_num(c.alpha_in_deg()),
                fmt_num(c.beta_in_deg()),
                t.counters.particles,
            ))
        })
        .collect()
}
