//! `rebound stochastic`: the stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.6, Fig. 13; notes §3) for every incident condition of the case. No surface
//! is ever built: a case with surface parameters is converted to deviations (Eq. 15).

use crate::case::{warn, WallSource};
use crate::cli::StochasticArgs;
use crate::commands::Context;
use crate::error::Result;
use crate::output::prepare_out_dir;
use crate::stochastic::plots::write_figures;
use crate::stochastic::simulate::{gamma_model_curve, run_condition, ConditionRun, ModelSetup};
use crate::tally::{write_summary_and_pdfs, ConditionExtras, ConditionResult};

/// The built-in case: the Sec. 4 scene (glass beads, D = 500 µm, on steel with the
/// `glass-steel` Sommerfeld–Huber preset, Δξ = 3.8°, Δζ = 7.5°, horizontal speed
/// `N(5.91, 1.16)` m/s, α⁻ ∈ {−5°, −15°, −25°}, β⁻ ∈ {0°, 60°}).
pub const DEFAULT_CASE: &str = r#"# Radenkovic & Simonin 2021, Sec. 4 (Figs. 14-15, high roughness anisotropy).
name = "glass-steel-sec4"
seed = 2021

[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5

[incidence]
alpha_deg = [-5.0, -15.0, -25.0]
beta_deg = [0.0, 60.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16

[particles]
count = 100000
diameter_um = 500.0

[collision]
model = "sommerfeld-huber"
preset = "glass-steel"

[output]
bin_width_deg = 1.0

[stochastic]
psi = 2.0
"#;

fn f(x: f64) -> toml::Value {
    toml::Value::Float(x)
}

fn round(x: f64, digits: i32) -> f64 {
    let p = 10f64.powi(digits);
    (x * p).round() / p
}

/// Runs the subcommand.
pub fn run(args: &StochasticArgs) -> Result<()> {
    let mut ctx = Context::new(&args.common, "stochastic", DEFAULT_CASE)?;
    let mut scene = ctx.case.scene()?;
    scene.set_count(args.particles)?;
    let wall = scene.wall.deviations();
    if let WallSource::Surface(_) = scene.wall {
        let note = format!(
            "the case gives a surface; the stochastic model uses its deviations from Eq. (15): Δξ = {:.4}°, Δζ = {:.4}°",
            wall.delta_xi.to_degrees(),
            wall.delta_zeta.to_degrees()
        );
        warn(&note);
        ctx.manifest
            .set("wall_from_surface", toml::Value::String(note));
    }
    if scene.conditions.iter().any(|c| c.alpha_in_deg() == -90.0) {
        ctx.manifest.set(
            "notes",
            toml::Value::String(
                "normal incidence (α⁻ = −90°) has no incident plane: β⁻ is taken as 0° (physics notes §1)"
                    .into(),
            ),
        );
    }
    let setup = ModelSetup {
        wall,
        law: scene.law,
        psi: scene.psi,
        diameter_m: scene.diameter_m,
        speed: scene.speed,
    };

    let mut results = Vec::with_capacity(scene.conditions.len());
    let mut runs: Vec<ConditionRun> = Vec::with_capacity(scene.conditions.len());
    let mut rows = Vec::new();
    let bar = crate::progress::bar(scene.conditions.len() as u64, "stochastic");
    for (k, cond) in scene.conditions.iter().enumerate() {
        let t = std::time::Instant::now();
        let run = run_condition(&setup, *cond, k as u64, scene.count, ctx.seed);
        let secs = t.elapsed().as_secs_f64();
        if run.capped > 0 {
            warn(&format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} rebounds hit the guard of {} candidate walls and were taken off the mean wall",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                run.capped,
                scene.count,
                crate::stochastic::MAX_TRIES
            ));
        }
        let extras = ConditionExtras {
            lost: None,
            p_single: Some(run.p_single()),
            curves: vec![gamma_model_curve(&wall, cond, scene.bin_width_deg)],
        };
        results.push(ConditionResult::from_outcomes(
            *cond,
            wall,
            &run.outcomes,
            scene.bin_width_deg,
            extras,
        ));
        let mut row = toml::Table::new();
        row.insert("alpha_in_deg".into(), f(cond.alpha_in_deg()));
        row.insert("beta_in_deg".into(), f(cond.beta_in_deg()));
        row.insert("seconds".into(), f(round(secs, 4)));
        row.insert(
            "rebounds_per_s".into(),
            f(if secs > 0.0 {
                (scene.count as f64 / secs).round()
            } else {
                0.0
            }),
        );
        row.insert(
            "candidate_walls_per_rebound".into(),
            f(round(run.tries as f64 / scene.count as f64, 4)),
        );
        row.insert("p_single".into(), f(round(run.p_single(), 6)));
        row.insert("capped".into(), toml::Value::Integer(run.capped as i64));
        rows.push(toml::Value::Table(row));
        runs.push(run);
        bar.inc(1);
    }
    bar.finish_and_clear();

    prepare_out_dir(&ctx.out_dir)?;
    write_summary_and_pdfs(&ctx.out_dir, &results)?;
    let figs = write_figures(&ctx.out_dir, &results, &runs, &wall, "SM")?;
    ctx.manifest.set("conditions", toml::Value::Array(rows));
    ctx.manifest.set(
        "figures",
        toml::Value::Array(figs.into_iter().map(toml::Value::String).collect()),
    );
    ctx.manifest.set_run("psi", f(scene.psi));
    ctx.manifest.set_run(
        "particles_per_condition",
        toml::Value::Integer(scene.count as i64),
    );
    ctx.manifest
        .set_run("delta_xi_deg", f(round(wall.delta_xi.to_degrees(), 6)));
    ctx.manifest
        .set_run("delta_zeta_deg", f(round(wall.delta_zeta.to_degrees(), 6)));
    ctx.manifest.write(&ctx.out_dir)?;
    Ok(())
}
