//! What each command writes: tables, figures and `run.toml` of a finished run, from the
//! resolved case, the tallies and the physics. High in the module picture: it may use every
//! library module below it (`case`, `figures`, the physics, `tally`, `output`); none of
//! those uses it.
//!
//! * [`deterministic`], [`stochastic`]: `finish` of a Monte Carlo run (and of `merge`).
//! * [`surface`]: the tables of `rebound surface`.

pub mod deterministic;
pub mod stochastic;
pub mod surface;

use crate::case::Scene;
use crate::erosion::ErosionSetup;
use crate::output::Manifest;
use crate::tally::BLOCK_SIZE;

fn f(x: f64) -> toml::Value {
    toml::Value::Float(x)
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
        manifest.set("erosion", e.manifest());
    }
    if scene.speed.reference != crate::incidence::SpeedReference::Horizontal {
        manifest.set_run(
            "speed_reference",
            toml::Value::String(scene.speed.reference.name().into()),
        );
    }
}
