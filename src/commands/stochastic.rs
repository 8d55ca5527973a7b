//! `rebound stochastic`: the stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.6, Fig. 13; notes §3) for every incident condition of the case. No surface
//! is ever built: a case with surface parameters is converted to deviations (Eq. 15).

use crate::case::{warn, Case, Scene, WallSource};
use crate::cli::StochasticArgs;
use crate::commands::Context;
use crate::erosion::ErosionSetup;
use crate::error::{Error, Result};
use crate::output::schema::write_tables;
use crate::output::{prepare_out_dir, Manifest, OutputDir};
use crate::runner::{self, TallyOverrides};
use crate::stochastic::simulate::{fill_block, gamma_model_curve, tally_spec, ModelSetup};
use crate::tally::engine::ConditionStats;
use crate::tally::{ConditionTally, TallySpec, BLOCK_SIZE};
use crate::wall::Deviations;
use std::path::Path;

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

/// What a stochastic run resolves from its case before any rebound is drawn.
pub struct Prepared {
    pub scene: Scene,
    pub setup: ModelSetup,
    pub specs: Vec<TallySpec>,
    /// Manifest entries that follow from the case alone (notes).
    pub notes: toml::Table,
}

/// Resolves the scene, the model and what to tally (warnings on stderr).
pub fn prepare(case: &Case, o: &TallyOverrides, seed: u64) -> Result<Prepared> {
    let mut scene = case.scene()?;
    // One case file drives both models: its `[deterministic]` section is checked here too.
    crate::commands::deterministic::deterministic_options(case)?;
    scene.set_count(o.particles)?;
    scene.set_target_se(o.target_se)?;
    let mut notes = toml::Table::new();
    let wall = match effective_wall(case, seed)? {
        Some((dev, table)) => {
            notes.insert("effective_for_diameter".into(), toml::Value::Table(table));
            dev
        }
        None => scene.wall.deviations(),
    };
    if let WallSource::Surface(_) = scene.wall {
        let note = format!(
            "the case gives a surface; the stochastic model uses its deviations from Eq. (15): Δξ = {:.4}°, Δζ = {:.4}°",
            wall.delta_xi.to_degrees(),
            wall.delta_zeta.to_degrees()
        );
        warn(&note);
        notes.insert("wall_from_surface".into(), toml::Value::String(note));
    }
    if scene.conditions.iter().any(|c| c.alpha_in_deg() == -90.0) {
        notes.insert(
            "notes".into(),
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
        spin: scene.spin,
        variant: scene.variant,
        erosion: scene.erosion.map(|model| ErosionSetup {
            model,
            particle_mass_kg: scene.particle_mass_kg(),
            diameter_m: scene.diameter_m,
        }),
    };
    let specs = scene
        .conditions
        .iter()
        .map(|c| tally_spec(&wall, *c, scene.bin_width_deg, setup.erosion.as_ref()))
        .collect();
    Ok(Prepared {
        scene,
        setup,
        specs,
        notes,
    })
}

/// `[stochastic] effective_for_diameter = true`: the deviations a sphere of the case's
/// diameter sees — those of its centre surface (paraboloid dilation, `surface::dilation`) on
/// the surface `deterministic` generates for the case and seed — with the manifest entries.
/// `None` without the key.
fn effective_wall(case: &Case, seed: u64) -> Result<Option<(Deviations, toml::Table)>> {
    let on = case
        .stochastic
        .as_ref()
        .and_then(|s| s.effective_for_diameter)
        .unwrap_or(false);
    if !on {
        return Ok(None);
    }
    let key = "stochastic.effective_for_diameter";
    if case
        .particles
        .as_ref()
        .and_then(|p| p.diameter_um)
        .is_none()
    {
        return Err(Error::Input(format!(
            "`{key}` needs `particles.diameter_um`, the sphere's diameter"
        )));
    }
    let scale = case.surface.is_some()
        || case.wall.as_ref().and_then(|w| w.rms_height_um).is_some()
        || case
            .deterministic
            .as_ref()
            .and_then(|d| d.rms_height_um)
            .is_some();
    if !scale {
        return Err(Error::Input(format!(
            "`{key}` needs the roughness's absolute scale: set `deterministic.rms_height_um` (or `wall.rms_height_um` with correlation lengths, or give a [surface])"
        )));
    }
    // The surface and the sphere of `deterministic` with `contact = "sphere"`.
    let mut sphere_case = case.clone();
    let mut d = sphere_case.deterministic.clone().unwrap_or_default();
    d.contact = Some("sphere".into());
    sphere_case.deterministic = Some(d);
    let det =
        crate::commands::deterministic::prepare(&sphere_case, &TallyOverrides::default(), None)?;
    let (Some(plan), Some(diameter)) = (&det.surface, det.options.sphere_diameter_m) else {
        return Err(Error::Internal("no surface plan for the sphere".into()));
    };
    let field = crate::commands::deterministic::generate_surface(plan, seed)?;
    let nominal = crate::surface::stats::measured_deviations(&field);
    let dil =
        crate::surface::dilation::sphere_centre_surface(&field, diameter, &format!("`{key}`"))?;
    let eff = crate::surface::stats::measured_deviations(&dil.field);
    if !(eff.delta_xi.is_finite() && eff.delta_zeta.is_finite()) {
        return Err(Error::Model(format!(
            "`{key}`: the deviations of the sphere's centre surface are not finite numbers"
        )));
    }
    let mut t = toml::Table::new();
    let deg = |r: f64| toml::Value::Float((r.to_degrees() * 1e4).round() / 1e4);
    t.insert(
        "diameter_um".into(),
        toml::Value::Float((diameter * 1e15).round() / 1e9),
    );
    t.insert("surface_delta_xi_deg".into(), deg(nominal.delta_xi));
    t.insert("surface_delta_zeta_deg".into(), deg(nominal.delta_zeta));
    t.insert("effective_delta_xi_deg".into(), deg(eff.delta_xi));
    t.insert("effective_delta_zeta_deg".into(), deg(eff.delta_zeta));
    t.insert(
        "contact_fraction".into(),
        toml::Value::Float((dil.contact_fraction * 1e6).round() / 1e6),
    );
    t.insert(
        "how".into(),
        "deviations of the sphere's centre surface (paraboloid dilation) on the surface deterministic generates for this case and seed".into(),
    );
    Ok(Some((eff, t)))
}

/// Runs the subcommand.
pub fn run(args: &StochasticArgs) -> Result<()> {
    let ctx = Context::new(&args.common, "stochastic", DEFAULT_CASE)?;
    let o = args.tally.overrides();
    let p = prepare(&ctx.case, &o, ctx.seed)?;
    let plan = runner::plan(
        p.specs.clone(),
        p.scene.count as u64,
        p.scene.target_se_deg,
        o.shard,
    )?;
    // What shards must agree on (a shard's partial tally records it).
    let identity = plan
        .shard
        .map(|_| {
            runner::identity(
                "stochastic",
                &ctx.case_text,
                &ctx.case_origin,
                ctx.seed,
                &o,
                None,
            )
        })
        .transpose()?;
    // Every input is checked: lock and stage the output directory (a shard's own directory
    // for a shard run), then compute.
    let target = match plan.shard {
        Some(shard) => ctx.shard_dir(&args.common, shard),
        None => ctx.out_dir.clone(),
    };
    let out = OutputDir::begin(&target, "--out")?;
    let t0 = std::time::Instant::now();
    let seed = ctx.seed;
    let done = runner::execute(&plan, "stochastic", |k, start, end, block| {
        fill_block(
            &p.setup,
            &p.scene.conditions[k],
            k as u64,
            seed,
            (start, end),
            block,
        )
    });
    let seconds = t0.elapsed().as_secs_f64();
    let (tallies, stats): (Vec<ConditionTally>, Vec<ConditionStats>) = done.into_iter().unzip();
    if let Some(identity) = &identity {
        runner::write_partial(out.path(), identity, &plan, p.notes, tallies, seconds)?;
    } else {
        finish(
            out.path(),
            ctx.manifest,
            &p,
            &tallies,
            Some(&stats),
            seconds,
        )?;
    }
    out.commit()?;
    Ok(())
}

/// Writes the outputs of a run (or of merged shards) into `dir` (the staging directory of
/// the run's [`OutputDir`]): `summary.csv`, `pdfs.csv`, `moments.csv`, the figures and
/// `run.toml`. `stats` are the per-condition run statistics of a one-process run (`None`
/// after a merge).
pub fn finish(
    dir: &Path,
    mut manifest: Manifest,
    p: &Prepared,
    tallies: &[ConditionTally],
    stats: Option<&[ConditionStats]>,
    seconds: f64,
) -> Result<()> {
    let wall = p.setup.wall;
    let mut results = Vec::with_capacity(tallies.len());
    let mut rows = Vec::with_capacity(tallies.len());
    for (k, t) in tallies.iter().enumerate() {
        let cond = t.spec.condition;
        let c = &t.counters;
        if c.capped > 0 {
            warn(&format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} rebounds hit the guard of {} candidate walls and were taken off the mean wall",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                c.capped,
                c.particles,
                crate::stochastic::MAX_TRIES
            ));
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
        if let (Some(a), Some(d)) = (r.summary.alpha_out, r.summary.dbeta) {
            row.insert("se_mean_alpha_out_deg".into(), f(a.se));
            row.insert("se_mean_dbeta_deg".into(), f(d.se));
        }
        row.insert("capped".into(), toml::Value::Integer(c.capped as i64));
        rows.push(toml::Value::Table(row));
        results.push(r);
    }
    prepare_out_dir(dir)?;
    write_tables(dir, &results)?;
    let figs = crate::figures::stochastic::write(dir, &results, &wall, "SM")?;
    for (k, v) in &p.notes {
        manifest.set(k, v.clone());
    }
    manifest.set("conditions", toml::Value::Array(rows));
    manifest.set(
        "figures",
        toml::Value::Array(figs.into_iter().map(toml::Value::String).collect()),
    );
    manifest.set_run("psi", f(p.scene.psi));
    if !p.setup.variant.is_paper() {
        manifest.set_run(
            "model",
            toml::Value::String(p.setup.variant.kind.name().into()),
        );
        manifest.set_run(
            "delta_gamma_deg",
            f(p.setup.variant.delta_gamma_on(&p.setup.wall).to_degrees()),
        );
    }
    manifest.set_run(
        "particles_per_condition",
        toml::Value::Integer(p.scene.count as i64),
    );
    if let Some(t) = p.scene.target_se_deg {
        manifest.set_run("target_se_deg", f(t));
    }
    manifest.set_run("block_size", toml::Value::Integer(BLOCK_SIZE as i64));
    if let Some(e) = &p.setup.erosion {
        manifest.set("erosion", e.manifest());
    }
    if p.scene.speed.reference != crate::incidence::SpeedReference::Horizontal {
        manifest.set_run(
            "speed_reference",
            toml::Value::String(p.scene.speed.reference.name().into()),
        );
    }
    manifest.set_run("delta_xi_deg", f(round(wall.delta_xi.to_degrees(), 6)));
    manifest.set_run("delta_zeta_deg", f(round(wall.delta_zeta.to_degrees(), 6)));
    let total: u64 = tallies.iter().map(|t| t.counters.particles).sum();
    manifest.set_run("compute_s", f(round(seconds, 4)));
    if stats.is_some() && seconds > 0.0 {
        manifest.set_run("rebounds_per_s", f((total as f64 / seconds).round()));
    }
    manifest.write(dir)?;
    Ok(())
}
