//! `rebound deterministic`: particle-centre bouncing on a generated (or saved)
//! rough surface for every incident condition of the case
//! (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5, 4).

use crate::case::{warn, Case, IncidentCondition, Scene, WallSource};
use crate::cli::DeterministicArgs;
use crate::commands::Context;
use crate::deterministic::scene::{choose_surface, SceneOptions, SurfaceChoice};
use crate::deterministic::{
    fill_block, tally_spec, LostCounts, ModelSetup, Tracker, DEFAULT_MAX_COLLISIONS,
};
use crate::erosion::ErosionSetup;
use crate::error::{Error, Result};
use crate::output::out_dir::{check_distinct, check_out};
use crate::output::schema::write_tables;
use crate::output::{prepare_out_dir, Manifest, OutputDir};
use crate::runner::{self, TallyOverrides};
use crate::surface::generate;
use crate::surface::heights_io::read_heights;
use crate::surface::HeightField;
use crate::tally::engine::ConditionStats;
use crate::tally::{ConditionResult, ConditionTally, TallySpec, BLOCK_SIZE};
use std::path::Path;

/// The built-in case: the first wall of Sec. 3, (Δξ, Δζ) = (2.5°, 7.5°).
pub const DEFAULT_CASE: &str = include_str!("../../configs/cases/aniso.toml");

/// Flattest incident angle the tracker is asked to follow (degrees): a descent from the top
/// of a shipped surface to its bottom at this angle takes some 2 · 10⁵ cells, well within
/// the step budget (`deterministic::trace::MAX_STEPS`).
pub const MIN_ABS_ALPHA_DEG: f64 = 1e-3;

/// Largest accepted `[deterministic] max_collisions`.
const MAX_COLLISIONS_LIMIT: i64 = 1_000_000;

/// The `[deterministic]` section, validated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeterministicOptions {
    pub max_collisions: u32,
    pub scene: SceneOptions,
    /// A sphere of this diameter (m) bounces (its centre on the dilated surface);
    /// `None`: the particle centre bounces on the surface (the paper's).
    pub sphere_diameter_m: Option<f64>,
}

/// Validates `[deterministic]` (keys named in one-line errors).
pub fn deterministic_options(case: &Case) -> Result<DeterministicOptions> {
    let d = case.deterministic.clone().unwrap_or_default();
    let mc = d.max_collisions.unwrap_or(DEFAULT_MAX_COLLISIONS as i64);
    if !(1..=MAX_COLLISIONS_LIMIT).contains(&mc) {
        return Err(Error::invalid(
            "deterministic.max_collisions",
            mc,
            "an integer from 1 to 1000000",
        ));
    }
    let def = SceneOptions::default();
    let spc = d
        .spacing_per_corr_length
        .unwrap_or(def.spacing_per_corr_length);
    if !(1.0..=64.0).contains(&spc) {
        return Err(Error::invalid(
            "deterministic.spacing_per_corr_length",
            spc,
            "a number from 1 to 64",
        ));
    }
    let side = d.side_per_corr_length.unwrap_or(def.side_per_corr_length);
    if !(1.0..=10_000.0).contains(&side) {
        return Err(Error::invalid(
            "deterministic.side_per_corr_length",
            side,
            "a number from 1 to 10000",
        ));
    }
    let h_um = d.rms_height_um.unwrap_or(def.rms_height_m * 1e6);
    // A picometre to a metre: the scale of a sphere's contact (and far from overflow in
    // the squared heights of the statistics).
    if !(1e-6..=1e6).contains(&h_um) {
        return Err(Error::invalid(
            "deterministic.rms_height_um",
            h_um,
            "1e-6 to 1000000 µm (a picometre to a metre)",
        ));
    }
    let sphere = match d.contact.as_deref() {
        None | Some("centre") => false,
        Some("sphere") => true,
        Some(other) => {
            return Err(Error::invalid(
                "deterministic.contact",
                format!("\"{other}\""),
                "\"centre\" (the particle centre bounces) or \"sphere\" (a sphere of [particles] diameter_um)",
            ))
        }
    };
    // A sphere needs the roughness's absolute scale: the automatic surface's height from
    // `[deterministic] rms_height_um` or the wall's `rms_height_um` (or a [surface], or a
    // height file: then the grid is given).
    let wall_h = case.wall.as_ref().and_then(|w| w.rms_height_um);
    let h_um = if sphere && d.rms_height_um.is_none() {
        match wall_h {
            Some(h) => h,
            None if case.surface.is_some() => h_um,
            None => {
                return Err(Error::Input(
                    "[deterministic] contact = \"sphere\" needs the roughness's absolute scale: set `deterministic.rms_height_um` (or `wall.rms_height_um` with correlation lengths, or give a [surface] or --surface)".into(),
                ))
            }
        }
    } else {
        h_um
    };
    let sphere_diameter_m = if sphere {
        let p = case.particles.clone().unwrap_or_default();
        let d_um = p.diameter_um.ok_or_else(|| {
            Error::Input(
                "[deterministic] contact = \"sphere\" needs `particles.diameter_um`, the sphere's diameter".into(),
            )
        })?;
        Some(d_um * 1e-6)
    } else {
        None
    };
    Ok(DeterministicOptions {
        max_collisions: mc as u32,
        scene: SceneOptions {
            spacing_per_corr_length: spc,
            side_per_corr_length: side,
            rms_height_m: h_um * 1e-6,
        },
        sphere_diameter_m,
    })
}

/// Where the surface of a run comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum SurfacePlan {
    /// Generated from the case's `[surface]` grid as given.
    Case(crate::case::SurfaceSpec),
    /// Chosen from the deviations (`[wall]`), see `deterministic::scene`.
    Auto(SurfaceChoice),
}

impl SurfacePlan {
    /// The plan for a scene.
    pub fn for_scene(scene: &Scene, opt: &SceneOptions) -> Result<SurfacePlan> {
        match &scene.wall {
            WallSource::Surface(spec) => Ok(SurfacePlan::Case(spec.clone())),
            WallSource::Deviations(d) => choose_surface(d.delta_xi, d.delta_zeta, opt)
                .map(SurfacePlan::Auto)
                .map_err(Error::Input),
        }
    }

    fn grid(&self) -> (f64, usize, f64, Option<f64>, Option<f64>) {
        match self {
            SurfacePlan::Case(s) => (
                s.length_m,
                s.nodes,
                s.rms_height_m,
                s.corr_length_x_m,
                s.corr_length_z_m,
            ),
            SurfacePlan::Auto(c) => (
                c.length_m,
                c.nodes,
                c.rms_height_m,
                c.corr_length_x_m,
                c.corr_length_z_m,
            ),
        }
    }
}

/// Generates the planned surface with the Garcia–Stoll generator of `crate::surface`
/// (Radenkovic & Simonin 2021, Eqs. 1–2).
pub fn generate_surface(plan: &SurfacePlan, seed: u64) -> Result<HeightField> {
    let (length_m, nodes, rms_height_m, corr_length_x_m, corr_length_z_m) = plan.grid();
    Ok(generate(
        &crate::case::SurfaceSpec {
            length_m,
            nodes,
            rms_height_m,
            corr_length_x_m,
            corr_length_z_m,
        },
        seed,
    ))
}

/// Reads a height field saved by `rebound surface --heights FILE`; every problem is a
/// one-line input error naming the file.
pub fn read_surface(path: &Path) -> Result<HeightField> {
    if !path.is_file() {
        return Err(Error::Input(format!(
            "--surface file `{}` not found",
            path.display()
        )));
    }
    read_heights(path).map_err(|e| match e {
        Error::Input(m) => Error::Input(format!("--surface {m}")),
        other => other,
    })
}

pub use crate::surface::stats::measured_deviations;

fn f(x: f64) -> toml::Value {
    toml::Value::Float(x)
}

fn round(x: f64, digits: i32) -> f64 {
    let p = 10f64.powi(digits);
    (x * p).round() / p
}

fn surface_table(
    plan: Option<&SurfacePlan>,
    file: Option<&Path>,
    field: &HeightField,
    source: &str,
    opt: &SceneOptions,
    measure: bool,
) -> toml::Value {
    let mut t = toml::Table::new();
    t.insert("source".into(), source.into());
    if let Some(p) = file {
        t.insert("file".into(), p.display().to_string().into());
        t.insert("spacing_x_um".into(), f(field.dx * 1e6));
        t.insert("spacing_z_um".into(), f(field.dz * 1e6));
    }
    if let Some(plan) = plan {
        let (l, n, h, cx, cz) = plan.grid();
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
            t.insert(
                "rule".into(),
                "spacing = c_L,min / spacing_per_corr_length; side ≥ side_per_corr_length · c_L,max; nodes = 8 × 5-smooth".into(),
            );
        }
    }
    t.insert("grid_nx".into(), toml::Value::Integer(field.nx as i64));
    t.insert("grid_nz".into(), toml::Value::Integer(field.nz as i64));
    if measure {
        let m = measured_deviations(field);
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

/// What a deterministic run resolves from its case before the surface is built.
pub struct Prepared {
    pub scene: Scene,
    pub options: DeterministicOptions,
    pub setup: ModelSetup,
    pub specs: Vec<TallySpec>,
    /// Where the surface comes from (`None`: a height file).
    pub surface: Option<SurfacePlan>,
    /// Manifest entries that follow from the case alone (notes).
    pub notes: toml::Table,
}

/// Resolves the scene, the tracker options, the surface plan and what to tally.
/// `surface_file`: a height file given with `--surface` (replaces the generated surface;
/// the case's wall then only labels the deviations).
pub fn prepare(case: &Case, o: &TallyOverrides, surface_file: Option<&Path>) -> Result<Prepared> {
    let mut scene = case.scene()?;
    scene.set_count(o.particles)?;
    scene.set_target_se(o.target_se)?;
    let options = deterministic_options(case)?;
    // Flatter than this, every history would exhaust the tracker's step budget.
    if let Some(c) = scene
        .conditions
        .iter()
        .find(|c| c.alpha_in_deg().abs() < MIN_ABS_ALPHA_DEG)
    {
        return Err(Error::invalid(
            "incidence.alpha_deg",
            c.alpha_in_deg(),
            &format!(
                "|α⁻| ≥ {MIN_ABS_ALPHA_DEG}° for the deterministic model (the grazing limit its step budget follows; the stochastic model takes any angle)"
            ),
        ));
    }
    let surface = match surface_file {
        Some(_) => None,
        None => Some(SurfacePlan::for_scene(&scene, &options.scene)?),
    };
    let dev = scene.wall.deviations();
    let mut notes = toml::Table::new();
    if scene.conditions.iter().any(|c| c.alpha_in_deg() == -90.0) {
        notes.insert(
            "notes".into(),
            toml::Value::String("normal incidence (α⁻ = −90°) has no incident plane: β⁻ is taken as 0° (physics notes §1)".into()),
        );
    }
    let setup = ModelSetup {
        law: scene.law,
        diameter_m: scene.diameter_m,
        speed: scene.speed,
        spin: scene.spin,
        erosion: scene.erosion.map(|model| ErosionSetup {
            model,
            particle_mass_kg: scene.particle_mass_kg(),
            diameter_m: scene.diameter_m,
        }),
        wall: dev,
        psi: scene.psi,
    };
    let specs = scene
        .conditions
        .iter()
        .map(|c| tally_spec(&dev, *c, scene.bin_width_deg, setup.erosion.as_ref()))
        .collect();
    Ok(Prepared {
        scene,
        options,
        setup,
        specs,
        surface,
        notes,
    })
}

/// Runs the subcommand.
pub fn run(args: &DeterministicArgs) -> Result<()> {
    let ctx = Context::new(&args.common, "deterministic", DEFAULT_CASE)?;
    let o = args.tally.overrides();
    let mut p = prepare(&ctx.case, &o, args.surface.as_deref())?;
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
                "deterministic",
                &ctx.case_text,
                &ctx.case_origin,
                ctx.seed,
                &o,
                args.surface.as_deref(),
            )
        })
        .transpose()?;
    let target = match plan.shard {
        Some(shard) => ctx.shard_dir(&args.common, shard),
        None => ctx.out_dir.clone(),
    };
    check_out(&target, "--out")?;
    if let Some(file) = &args.surface {
        // `--out` is replaced as a whole: it must not hold the height file the run reads.
        check_distinct(&target, "--out", &[("--surface", file.as_path())])?;
    }
    // Everything the user gave is checked; now the surface (the only slow input step).
    let t0 = std::time::Instant::now();
    let (field, source) = match (&args.surface, &p.surface) {
        (Some(path), _) => (read_surface(path)?, "file"),
        (None, Some(plan)) => (
            generate_surface(plan, ctx.seed)?,
            match plan {
                SurfacePlan::Case(_) => "case",
                SurfacePlan::Auto(_) => "auto",
            },
        ),
        (None, None) => return Err(Error::Internal("no surface plan".into())),
    };
    let gen_s = t0.elapsed().as_secs_f64();
    // A sphere: its centre rides on the dilated surface (paraboloid, surface::dilation).
    let mut sphere_entries = toml::Table::new();
    let field = match p.options.sphere_diameter_m {
        None => field,
        Some(d) => {
            let t = std::time::Instant::now();
            let dil =
                crate::surface::dilation::sphere_centre_surface(&field, d, "contact = \"sphere\"")?;
            sphere_entries.insert("contact".into(), "sphere".into());
            sphere_entries.insert("diameter_um".into(), f(d * 1e6));
            sphere_entries.insert(
                "approximation".into(),
                "paraboloid cap (sqrt(R^2 - r^2) - R ~ -r^2/2R), Felzenszwalb-Huttenlocher lower envelopes".into(),
            );
            sphere_entries.insert("contact_fraction".into(), f(round(dil.contact_fraction, 6)));
            sphere_entries.insert("dilation_s".into(), f(round(t.elapsed().as_secs_f64(), 3)));
            dil.field
        }
    };
    let tracker = Tracker::new(&field, p.options.max_collisions).map_err(|e| {
        match (e, &args.surface) {
            (Error::Input(m), Some(path)) => {
                Error::Input(format!("--surface `{}`: {m}", path.display()))
            }
            // A surface this tool generated and the tracker refuses: a bug, not the input.
            (Error::Input(m), None) => Error::Internal(format!("generated surface: {m}")),
            (e, _) => e,
        }
    })?;
    p.notes.insert(
        "surface_choice".into(),
        surface_table(
            p.surface.as_ref(),
            args.surface.as_deref(),
            &field,
            source,
            &p.options.scene,
            // Merged shards report shard 1's table: the others need not measure again.
            plan.shard.is_none_or(|s| s.index == 1),
        ),
    );
    if !sphere_entries.is_empty() {
        // `surface_choice` measured the surface the centre rides on: the dilated one.
        p.notes
            .insert("sphere_contact".into(), toml::Value::Table(sphere_entries));
    }
    // The surface is valid: lock and stage the output directory (a shard's own directory for
    // a shard run), then compute.
    let out = OutputDir::begin(&target, "--out")?;
    let t1 = std::time::Instant::now();
    let seed = ctx.seed;
    let done = runner::execute(&plan, "deterministic", |k, start, end, block| {
        fill_block(
            &tracker,
            &p.setup,
            &p.scene.conditions[k],
            k as u64,
            seed,
            (start, end),
            block,
        )
    });
    let seconds = t1.elapsed().as_secs_f64();
    let (tallies, stats): (Vec<ConditionTally>, Vec<ConditionStats>) = done.into_iter().unzip();
    if let Some(identity) = &identity {
        runner::write_partial(
            out.path(),
            identity,
            &plan,
            p.notes,
            tallies,
            seconds + gen_s,
        )?;
    } else {
        let mut manifest = ctx.manifest;
        manifest.set_run("surface_s", f(round(gen_s, 3)));
        finish(out.path(), manifest, &p, &tallies, Some(&stats), seconds)?;
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
    let mut results = Vec::with_capacity(tallies.len());
    let mut rows = Vec::with_capacity(tallies.len());
    for (k, t) in tallies.iter().enumerate() {
        let cond = t.spec.condition;
        let lost = LostCounts::from_tally(&t.counters.lost);
        if lost.total() > 0 {
            warn(&format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} particles lost ({})",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                lost.total(),
                t.counters.particles,
                lost.describe()
            ));
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
        ));
        results.push(r);
    }
    prepare_out_dir(dir)?;
    write_tables(dir, &results)?;
    let figs = crate::figures::deterministic::write(dir, &results, "DS")?;
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
    manifest.set_run("compute_s", f(round(seconds, 4)));
    let total: u64 = tallies.iter().map(|t| t.counters.particles).sum();
    if stats.is_some() && seconds > 0.0 {
        manifest.set_run("particles_per_s", f((total as f64 / seconds).round()));
    }
    manifest.write(dir)?;
    Ok(())
}

fn condition_row(
    cond: &IncidentCondition,
    t: &ConditionTally,
    lost: &LostCounts,
    stats: Option<&ConditionStats>,
    r: &ConditionResult,
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
    if let (Some(a), Some(d)) = (r.summary.alpha_out, r.summary.dbeta) {
        row.insert("se_mean_alpha_out_deg".into(), f(a.se));
        row.insert("se_mean_dbeta_deg".into(), f(d.se));
    }
    row.insert("lost".into(), toml::Value::Integer(lost.total() as i64));
    row.insert(
        "collision_cap_hits".into(),
        toml::Value::Integer(lost.collision_cap as i64),
    );
    toml::Value::Table(row)
}
