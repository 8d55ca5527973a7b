//! `rebound deterministic`: particle-centre bouncing on a generated (or saved)
//! rough surface for every incident condition of the case
//! (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5, 4).

use crate::case::{warn, Case, IncidentCondition, Scene, WallSource};
use crate::cli::DeterministicArgs;
use crate::commands::Context;
use crate::deterministic::scene::{choose_surface, SceneOptions, SurfaceChoice};
use crate::deterministic::{plots, run_condition, Tracker, DEFAULT_MAX_COLLISIONS};
use crate::error::{Error, Result};
use crate::output::prepare_out_dir;
use crate::surface::generate;
use crate::surface::heights_io::read_heights;
use crate::surface::HeightField;
use crate::tally::{write_summary_and_pdfs, ConditionResult};
use crate::wall::Deviations;
use std::path::Path;

/// The built-in case: the first wall of Sec. 3, (Δξ, Δζ) = (2.5°, 7.5°).
pub const DEFAULT_CASE: &str = include_str!("../../configs/cases/aniso.toml");

/// Largest accepted `[deterministic] max_collisions`.
const MAX_COLLISIONS_LIMIT: i64 = 1_000_000;

/// The `[deterministic]` section, validated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeterministicOptions {
    pub max_collisions: u32,
    pub scene: SceneOptions,
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
    if !(h_um > 0.0 && h_um.is_finite()) {
        return Err(Error::invalid(
            "deterministic.rms_height_um",
            h_um,
            "a positive number",
        ));
    }
    Ok(DeterministicOptions {
        max_collisions: mc as u32,
        scene: SceneOptions {
            spacing_per_corr_length: spc,
            side_per_corr_length: side,
            rms_height_m: h_um * 1e-6,
        },
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

/// RMS of the triangle normals' angle fluctuations `(ξ − 90°, ζ − 90°)` (rad): the
/// deviations the surface really has (Radenkovic & Simonin 2021, Sec. 2.2).
pub fn measured_deviations(f: &HeightField) -> Deviations {
    let (mut sx, mut sz, mut n) = (0.0, 0.0, 0.0);
    for iz in 0..f.nz {
        for ix in 0..f.nx {
            for t in f.cell_normals(ix, iz) {
                let norm = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
                let xi = (t[0] / norm).clamp(-1.0, 1.0).asin();
                let ze = (t[2] / norm).clamp(-1.0, 1.0).asin();
                sx += xi * xi;
                sz += ze * ze;
                n += 1.0;
            }
        }
    }
    Deviations {
        delta_xi: (sx / n).sqrt(),
        delta_zeta: (sz / n).sqrt(),
    }
}

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
    gen_s: f64,
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
    let m = measured_deviations(field);
    t.insert(
        "measured_delta_xi_deg".into(),
        f(round(m.delta_xi.to_degrees(), 4)),
    );
    t.insert(
        "measured_delta_zeta_deg".into(),
        f(round(m.delta_zeta.to_degrees(), 4)),
    );
    t.insert("generation_s".into(), f(round(gen_s, 3)));
    toml::Value::Table(t)
}

/// Runs the subcommand.
pub fn run(args: &DeterministicArgs) -> Result<()> {
    let mut ctx = Context::new(&args.common, "deterministic", DEFAULT_CASE)?;
    let mut scene = ctx.case.scene()?;
    scene.set_count(args.particles)?;
    let opt = deterministic_options(&ctx.case)?;
    // A saved surface replaces the generated one; the case's wall then only labels the
    // deviations (summary columns, Δγ of the Fig. 12 model).
    let plan = match args.surface {
        Some(_) => None,
        None => Some(SurfacePlan::for_scene(&scene, &opt.scene)?),
    };
    let dev = scene.wall.deviations();
    for c in &scene.conditions {
        if c.alpha_in_deg() == -90.0 {
            ctx.manifest.set(
                "notes",
                toml::Value::String("normal incidence (α⁻ = −90°) has no incident plane: β⁻ is taken as 0° (physics notes §1)".into()),
            );
        }
    }
    // Everything the user gave is checked; now the surface (the only slow input step).
    let t0 = std::time::Instant::now();
    let (field, source) = match (&args.surface, &plan) {
        (Some(p), _) => (read_surface(p)?, "file"),
        (None, Some(plan)) => (
            generate_surface(plan, ctx.seed)?,
            match plan {
                SurfacePlan::Case(_) => "case",
                SurfacePlan::Auto(_) => "auto",
            },
        ),
        (None, None) => return Err(Error::Io("internal: no surface plan".into())),
    };
    let gen_s = t0.elapsed().as_secs_f64();
    let tracker = Tracker::new(&field, opt.max_collisions).map_err(|e| {
        Error::Input(match &args.surface {
            Some(p) => format!("--surface `{}`: {e}", p.display()),
            None => e,
        })
    })?;
    ctx.manifest.set(
        "surface_choice",
        surface_table(
            plan.as_ref(),
            args.surface.as_deref(),
            &field,
            source,
            &opt.scene,
            gen_s,
        ),
    );

    let mut results: Vec<ConditionResult> = Vec::new();
    let mut timings = Vec::new();
    let bar = crate::progress::bar(scene.conditions.len() as u64, "deterministic");
    for (k, cond) in scene.conditions.iter().enumerate() {
        let t = std::time::Instant::now();
        let run = run_condition(
            &tracker,
            &scene.law,
            scene.diameter_m,
            *cond,
            k as u64,
            scene.count,
            ctx.seed,
            &scene.speed,
        );
        let secs = t.elapsed().as_secs_f64();
        if run.lost.total() > 0 {
            warn(&format!(
                "α⁻ = {}°, β⁻ = {}°: {} of {} particles lost ({})",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                run.lost.total(),
                scene.count,
                run.lost.describe()
            ));
        }
        if run.outcomes.is_empty() {
            return Err(Error::Io(format!(
                "α⁻ = {}°, β⁻ = {}°: no particle could be followed ({})",
                cond.alpha_in_deg(),
                cond.beta_in_deg(),
                run.lost.describe()
            )));
        }
        timings.push(timing_row(cond, secs, scene.count, &run.lost));
        results.push(run.tally(&dev, scene.psi, scene.bin_width_deg));
        bar.inc(1);
    }
    bar.finish_and_clear();

    prepare_out_dir(&ctx.out_dir)?;
    write_summary_and_pdfs(&ctx.out_dir, &results)?;
    let figs = plots::write_figures(&ctx.out_dir, &results, "DS")?;
    ctx.manifest.set("conditions", toml::Value::Array(timings));
    ctx.manifest.set(
        "figures",
        toml::Value::Array(figs.into_iter().map(toml::Value::String).collect()),
    );
    ctx.manifest.set_run(
        "max_collisions",
        toml::Value::Integer(opt.max_collisions as i64),
    );
    ctx.manifest.set_run(
        "particles_per_condition",
        toml::Value::Integer(scene.count as i64),
    );
    ctx.manifest.write(&ctx.out_dir)?;
    Ok(())
}

fn timing_row(
    cond: &IncidentCondition,
    secs: f64,
    count: usize,
    lost: &crate::deterministic::LostCounts,
) -> toml::Value {
    let mut t = toml::Table::new();
    t.insert("alpha_in_deg".into(), f(round(cond.alpha_in_deg(), 9)));
    t.insert("beta_in_deg".into(), f(round(cond.beta_in_deg(), 9)));
    t.insert("seconds".into(), f(round(secs, 4)));
    t.insert(
        "particles_per_s".into(),
        f(if secs > 0.0 {
            (count as f64 / secs).round()
        } else {
            0.0
        }),
    );
    t.insert("lost".into(), toml::Value::Integer(lost.total() as i64));
    t.insert(
        "collision_cap_hits".into(),
        toml::Value::Integer(lost.collision_cap as i64),
    );
    toml::Value::Table(t)
}
