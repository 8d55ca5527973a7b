//! `rebound deterministic`: particle-centre bouncing on a generated (or saved)
//! rough surface for every incident condition of the case
//! (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5, 4).

use crate::case::wall_card::CardWall;
use crate::case::{builtin, deterministic::prepare};
use crate::cli::DeterministicArgs;
use crate::commands::monte_carlo::{MonteCarlo, Scene};
use crate::commands::{apply_wall_card, context, warn, Summary};
use crate::output::out_dir::{check_distinct, check_out};
use crate::writers::deterministic::{finish, sphere_table, surface_table};
use roughwall::deterministic::fill_block;
use roughwall::deterministic::{build_surfaces, realisations, BuiltSurface, SphereDilation};
use roughwall::HeightField;
use roughwall::{Error, Result};

/// Runs the subcommand.
pub fn run(args: &DeterministicArgs) -> Result<Summary> {
    let mut ctx = context(&args.common, "deterministic", builtin::DETERMINISTIC)?;
    let card = apply_wall_card(
        &mut ctx,
        args.wall_card.as_deref(),
        "deterministic",
        CardWall::OfTheParticles,
    )?;
    let o = args.tally.overrides();
    let file = args.surface.as_deref();
    let mut p = prepare(&ctx.case, &o, file)?;
    warn(std::mem::take(&mut p.warnings));
    if let Some(card) = card {
        p.notes.insert("wall_card".into(), toml::Value::Table(card));
    }
    let scene = Scene {
        specs: p.specs.clone(),
        count: p.scene.count as u64,
        target_se_deg: p.scene.target_se_deg,
        surface_file: file,
    };
    let out = args.common.out.as_deref();
    let mc = MonteCarlo::plan(&ctx, out, "deterministic", "histories", scene, &o)?;
    let target = mc.target();
    check_out(target, "--out")?;
    // `--out` is replaced as a whole: it must not hold the height file or the card the run
    // reads.
    let inputs: Vec<(&str, &std::path::Path)> = [
        ("--surface", file),
        ("--wall-card", args.wall_card.as_deref()),
    ]
    .into_iter()
    .filter_map(|(k, p)| p.map(|p| (k, p)))
    .collect();
    check_distinct(target, "--out", &inputs)?;
    // Everything the user gave is checked; now the surfaces (the only slow input step).
    let sphere = p.options.sphere_diameter_m;
    let scan = match file {
        Some(path) => crate::scan_wall::scan_wall(path, &p.options)?,
        None => None,
    };
    if let (Some(a), None) = (p.options.entry_alpha, &scan) {
        return Err(Error::Input(format!(
            "deterministic.entry_alpha_deg = {}: only for a measured scan given as --surface and bounced on in place; a generated or periodic wall has no entry region",
            crate::output::fmt_num(a.to_degrees())
        )));
    }
    let mut met = None;
    let built = match scan {
        // A measured scan: in place, or turned to its lay and mirror-tiled.
        Some(s) => {
            warn(s.warnings);
            p.notes.insert("scan".into(), toml::Value::Table(s.table));
            met = s.met;
            vec![s.built]
        }
        None => build_surfaces(
            p.surface.as_ref(),
            file,
            sphere,
            ctx.seed,
            p.options.triangulation,
            p.options.surfaces,
        )?,
    };
    let fields: Vec<&HeightField> = built.iter().map(|b| &b.field).collect();
    // The realisations share the grid: one warning for all.
    warn(fields[0].triangulation_seam());
    let surfaces = realisations(&built, p.options.max_collisions, file)?;
    // Merged shards report shard 1's table: the others need not measure again.
    let measure = mc.shard().is_none_or(|s| s.index == 1);
    let source = built[0].source;
    let choice = surface_table(
        p.surface.as_ref(),
        file,
        &fields,
        source,
        &p.options.scene,
        measure,
        met,
    );
    p.notes.insert("surface_choice".into(), choice);
    if let Some(s) = pooled_sphere(&built) {
        // `surface_choice` measured the surface the centre rides on: the dilated one.
        p.notes.insert("sphere_contact".into(), sphere_table(&s));
    }
    // The surface is valid: lock and stage the output directory, then compute.
    let (setup, conditions, seed) = (&p.setup, &p.scene.conditions, ctx.seed);
    let gen_s: f64 = built.iter().map(|b| b.generate_s).sum();
    let mut manifest = ctx.manifest;
    mc.run(
        &p.notes,
        gen_s,
        |k, start, end, block| {
            let range = (start, end);
            fill_block(
                &surfaces,
                setup,
                &conditions[k],
                k as u64,
                seed,
                range,
                block,
            )
        },
        |dir, tallies, stats, seconds| {
            let gen_ms = toml::Value::Float((gen_s * 1e3).round() / 1e3);
            manifest.set_run("surface_s", gen_ms);
            finish(dir, manifest, &p, tallies, Some(stats), seconds)
        },
    )
}

/// The sphere's dilation over all realisations: the mean contact fraction, the total time
/// (for one realisation, its own).
fn pooled_sphere(built: &[BuiltSurface]) -> Option<SphereDilation> {
    let all: Vec<&SphereDilation> = built.iter().filter_map(|b| b.sphere.as_ref()).collect();
    let first = all.first()?;
    if all.len() == 1 {
        return Some(SphereDilation { ..**first });
    }
    let n = all.len() as f64;
    Some(SphereDilation {
        diameter_m: first.diameter_m,
        contact_fraction: all.iter().map(|s| s.contact_fraction).sum::<f64>() / n,
        dilation_s: all.iter().map(|s| s.dilation_s).sum(),
    })
}
