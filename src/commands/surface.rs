//! `rebound surface`: generate the Garcia–Stoll surface of the case and measure the
//! statistics of Radenkovic & Simonin 2021, Table 1 (Eqs. 7–9, 14–15).
//!
//! Outputs in `--out` (`crate::writers::surface::OUTPUT_FILES`): `surface_summary.csv`, `normal_angles.csv`,
//! `height_map.svg`, `normal_angle_pdfs.svg`, `run.toml` (timings only there), and with
//! `--heights FILE` the height field in the format of `roughwall::surface::heights_io`.
//! `--out` is written as a whole (`crate::output::out_dir`); a `--heights` file inside it
//! moves with the swap, one outside it is written on its own (atomically).

use crate::case::builtin;
use crate::cli::SurfaceArgs;
use crate::commands::{begin_out, context, counted, warn, Summary};
use crate::figures;
use crate::output::out_dir::place_file;
use crate::writers::surface::{
    angles_table, effective_table, grid_table, model_row, round_ms, summary_table, HIST_BINS,
    OUTPUT_FILES,
};
use roughwall::format::fmt_num;
use roughwall::surface::effective_roughness;
use roughwall::surface::generate;
use roughwall::surface::write_heights;
use roughwall::surface::{surface_stats, HistogramSpec};
use roughwall::{Error, Result};
use std::time::Instant;

/// Runs the subcommand: validate everything first (nothing is written on bad input),
/// then generate, measure, and write.
pub fn run(args: &SurfaceArgs) -> Result<Summary> {
    let mut ctx = context(&args.common, "surface", builtin::SURFACE)?;
    let mut warnings = Vec::new();
    let spec = ctx.case.surface_spec(&mut warnings)?;
    warn(warnings);
    let betas = ctx.case.beta_star()?;
    let triangulation = crate::case::deterministic::triangulation(&ctx.case)?;
    let diameters = ctx.case.effective_diameters(spec.length_m)?;
    if !diameters.is_empty() {
        let nodes = (spec.nodes as u64).saturating_mul(spec.nodes as u64);
        roughwall::memory::require(
            "stats.diameter_um",
            format!("{} diameters", diameters.len()),
            nodes.saturating_mul(roughwall::surface::BYTES_PER_NODE),
            "the centre surface of a sphere",
        )?;
    }
    let target = spec.deviations();
    let heights = args
        .heights
        .as_deref()
        .map(|h| place_file(h, "--heights", &ctx.out_dir, &OUTPUT_FILES))
        .transpose()?;
    let out = begin_out(&ctx.out_dir)?;

    let t0 = Instant::now();
    let mut field = generate(&spec, ctx.seed);
    field.triangulation = triangulation;
    warn(field.triangulation_seam());
    let t_gen = t0.elapsed().as_secs_f64();
    let half_range = (4.0 * target.delta_xi.max(target.delta_zeta)).max(1f64.to_radians());
    let hist = HistogramSpec {
        half_range,
        bins: HIST_BINS,
    };
    let stats = surface_stats(&field, &betas, Some(hist));
    let t_stats = t0.elapsed().as_secs_f64() - t_gen;
    // What a sphere sees of a flat surface is no roughness at all: its ratios to the surface's
    // own deviations, and to √(h/D), are 0/0. A surface comes out flat when its rms height is
    // 0, or when its correlation lengths are so much longer than the surface that only the
    // mean is left.
    let rough = stats.rms_height_m > 0.0;
    if !diameters.is_empty() && !rough {
        return Err(Error::invalid(
            "stats.diameter_um",
            format!(
                "{} µm on a flat surface (generated rms height {} µm)",
                fmt_num(diameters[0] * 1e6),
                fmt_num(stats.rms_height_m * 1e6)
            ),
            "a surface with roughness: [surface] rms_height_um > 0 and correlation lengths \
             shorter than length_um",
        ));
    }

    let dir = out.path().to_path_buf();
    summary_table(&spec, &target, &stats).write(&dir.join("surface_summary.csv"))?;
    angles_table(&target, &stats).write(&dir.join("normal_angles.csv"))?;
    figures::surface::height_map(
        &dir.join("height_map.svg"),
        &field,
        &format!(
            "{}: heights, window of {} × {} nodes",
            ctx.case.name,
            field.nx.min(256),
            field.nx.max(field.nz).min(256)
        ),
    )?;
    let model: Vec<(f64, f64)> = stats
        .rotated
        .iter()
        .map(|r| model_row(&target, r.beta_star))
        .map(|(x, z, _)| (x, z))
        .collect();
    figures::surface::normal_angle_pdfs(&dir.join("normal_angle_pdfs.svg"), &stats, &model)?;
    if !diameters.is_empty() {
        let t1 = Instant::now();
        let eff = effective_roughness(&field, &diameters);
        effective_table(&spec, &stats, &eff).write(&dir.join("effective_roughness.csv"))?;
        figures::surface::effective_roughness(
            &dir.join("effective_roughness.svg"),
            spec.corr_length_x_m,
            spec.corr_length_z_m,
            &stats,
            &eff,
        )?;
        ctx.manifest.set_run(
            "effective_roughness_s",
            toml::Value::Float(round_ms(t1.elapsed().as_secs_f64())),
        );
    }
    if let (Some(path), Some(place)) = (&args.heights, &heights) {
        crate::output::write_atomic_with(&place.path_in(&out), |w| write_heights(w, &field))?;
        ctx.manifest
            .set_run("heights_file", path.display().to_string().into());
    }
    ctx.manifest.set("grid", grid_table(&field));
    ctx.manifest
        .set_run("generate_s", toml::Value::Float(round_ms(t_gen)));
    ctx.manifest
        .set_run("stats_s", toml::Value::Float(round_ms(t_stats)));
    ctx.manifest.write(&dir)?;
    let dir = out.commit()?;
    // The grid the case asked for: a surface constant along z is stored with one row.
    let mut work = format!(
        "{n} × {n} surface, {}",
        counted(betas.len(), "rotated frame"),
        n = spec.nodes
    );
    if !diameters.is_empty() {
        work += &format!(
            ", effective roughness of {}",
            counted(diameters.len(), "diameter")
        );
    }
    let nodes = (spec.nodes as u64).saturating_mul(spec.nodes as u64);
    Ok(Summary {
        work,
        rate: Some((nodes, "nodes")),
        wrote: dir,
    })
}
