//! `rebound surface`: generate the Garcia–Stoll surface of the case and measure the
//! statistics of Radenkovic & Simonin 2021, Table 1 (Eqs. 7–9, 14–15).
//!
//! Outputs in `--out` (`roughwall::output::surface::OUTPUT_FILES`): `surface_summary.csv`, `normal_angles.csv`,
//! `height_map.svg`, `normal_angle_pdfs.svg`, `run.toml` (timings only there), and with
//! `--heights FILE` the height field in the format of `roughwall::surface::heights_io`.
//! `--out` is written as a whole (`roughwall::output::out_dir`); a `--heights` file inside it
//! moves with the swap, one outside it is written on its own (atomically).

use crate::cli::SurfaceArgs;
use crate::commands::{context, warn};
use roughwall::case::builtin;
use roughwall::error::Result;
use roughwall::figures::{plot_grid_svg, Kind, Plot, Series};
use roughwall::output::fmt_num;
use roughwall::output::out_dir::{place_file, OutputDir};
use roughwall::output::surface::{
    angles_table, effective_table, grid_table, model_row, round_ms, summary_table, HIST_BINS,
    OUTPUT_FILES,
};
use roughwall::surface::dilation::{effective_roughness, EffectiveRoughness};
use roughwall::surface::figure::height_map_svg;
use roughwall::surface::heights_io::write_heights;
use roughwall::surface::stats::{surface_stats, HistogramSpec, RotatedStats, SurfaceStats};
use roughwall::surface::{generate, SurfaceSpec};
use roughwall::wall::Deviations;
use std::path::Path;
use std::time::Instant;

/// Runs the subcommand: validate everything first (nothing is written on bad input),
/// then generate, measure, and write.
pub fn run(args: &SurfaceArgs) -> Result<()> {
    let mut ctx = context(&args.common, "surface", builtin::SURFACE)?;
    let mut warnings = Vec::new();
    let spec = ctx.case.surface_spec(&mut warnings)?;
    warn(warnings);
    let betas = ctx.case.beta_star()?;
    let diameters = ctx.case.effective_diameters(spec.length_m)?;
    if !diameters.is_empty() {
        let nodes = (spec.nodes as u64).saturating_mul(spec.nodes as u64);
        roughwall::memory::require(
            "stats.diameter_um",
            format!("{} diameters", diameters.len()),
            nodes.saturating_mul(roughwall::surface::dilation::BYTES_PER_NODE),
            "the centre surface of a sphere",
        )?;
    }
    let target = spec.deviations();
    let heights = args
        .heights
        .as_deref()
        .map(|h| place_file(h, "--heights", &ctx.out_dir, &OUTPUT_FILES))
        .transpose()?;
    let out = OutputDir::begin(&ctx.out_dir, "--out")?;

    let t0 = Instant::now();
    let field = generate(&spec, ctx.seed);
    let t_gen = t0.elapsed().as_secs_f64();
    let half_range = (4.0 * target.delta_xi.max(target.delta_zeta)).max(1f64.to_radians());
    let hist = HistogramSpec {
        half_range,
        bins: HIST_BINS,
    };
    let stats = surface_stats(&field, &betas, Some(hist));
    let t_stats = t0.elapsed().as_secs_f64() - t_gen;

    let dir = out.path().to_path_buf();
    summary_table(&spec, &target, &stats).write(&dir.join("surface_summary.csv"))?;
    angles_table(&target, &stats).write(&dir.join("normal_angles.csv"))?;
    height_map_svg(
        &dir.join("height_map.svg"),
        &field,
        &format!(
            "{}: heights, window of {} × {} nodes",
            ctx.case.name,
            field.nx.min(256),
            field.nx.max(field.nz).min(256)
        ),
    )?;
    pdf_figure(&dir.join("normal_angle_pdfs.svg"), &target, &stats)?;
    if !diameters.is_empty() {
        let t1 = Instant::now();
        let eff = effective_roughness(&field, &diameters);
        effective_table(&spec, &stats, &eff).write(&dir.join("effective_roughness.csv"))?;
        effective_figure(&dir.join("effective_roughness.svg"), &spec, &stats, &eff)?;
        ctx.manifest.set_run(
            "effective_roughness_s",
            toml::Value::Float(round_ms(t1.elapsed().as_secs_f64())),
        );
    }
    if let (Some(path), Some(place)) = (&args.heights, &heights) {
        write_heights(&place.path_in(&out), &field)?;
        ctx.manifest
            .set_run("heights_file", path.display().to_string().into());
    }
    ctx.manifest.set("grid", grid_table(&field));
    ctx.manifest
        .set_run("generate_s", toml::Value::Float(round_ms(t_gen)));
    ctx.manifest
        .set_run("stats_s", toml::Value::Float(round_ms(t_stats)));
    ctx.manifest.write(&dir)?;
    out.commit()?;
    Ok(())
}

/// `Δ_eff/Δ` against `D/c_L` for both axes, and the contact fraction.
fn effective_figure(
    path: &Path,
    spec: &SurfaceSpec,
    s: &SurfaceStats,
    eff: &[EffectiveRoughness],
) -> Result<()> {
    let mut series = Vec::new();
    for (label, c, base, pick) in [
        (
            "Δξ_eff/Δξ against D/c_Lx",
            spec.corr_length_x_m,
            s.delta_xi,
            (|e: &EffectiveRoughness| e.delta_xi) as fn(&EffectiveRoughness) -> f64,
        ),
        (
            "Δζ_eff/Δζ against D/c_Lz",
            spec.corr_length_z_m,
            s.delta_zeta,
            |e: &EffectiveRoughness| e.delta_zeta,
        ),
    ] {
        let (Some(c), true) = (c, base > 0.0) else {
            continue;
        };
        let pts: Vec<(f64, f64)> = eff
            .iter()
            .filter(|e| e.diameter_m > 0.0)
            .map(|e| (e.diameter_m / c, pick(e) / base))
            .collect();
        series.push(Series::new(label, pts, Kind::Line));
    }
    let contact = Plot {
        title: "nodes a resting sphere touches".into(),
        x_label: "D (µm)".into(),
        y_label: "fraction of nodes".into(),
        series: vec![Series::new(
            "",
            eff.iter()
                .filter(|e| e.diameter_m > 0.0)
                .map(|e| (e.diameter_m * 1e6, e.contact_fraction))
                .collect(),
            Kind::Line,
        )],
        log_x: true,
        log_y: true,
        ..Plot::default()
    };
    let ratio = Plot {
        title: "effective roughness of a sphere's centre surface".into(),
        x_label: "D / c_L".into(),
        y_label: "Δ_eff / Δ".into(),
        series,
        log_x: true,
        ..Plot::default()
    };
    plot_grid_svg(path, &[ratio, contact], 2)
}

/// Normal density of std `sd` (degrees) on `[-half, half]`, per degree (Eqs. 12–13 for
/// the fluctuations `ξ* − 90°`, `ζ* − 90°`). Empty for `sd = 0` (a Dirac peak).
fn normal_curve(sd: f64, half: f64) -> Vec<(f64, f64)> {
    if sd <= 0.0 {
        return Vec::new();
    }
    let n = 200;
    (0..=n)
        .map(|i| {
            let x = -half + 2.0 * half * i as f64 / n as f64;
            let y = (-0.5 * (x / sd).powi(2)).exp() / (sd * (2.0 * std::f64::consts::PI).sqrt());
            (x, y)
        })
        .collect()
}

fn pdf_panel(target: &Deviations, r: &RotatedStats) -> Plot {
    let (mx, mz, _) = model_row(target, r.beta_star);
    let per_deg = |h: &roughwall::surface::stats::Histogram| -> Vec<(f64, f64)> {
        h.density()
            .into_iter()
            .map(|(x, p)| (x.to_degrees(), p.to_radians()))
            .collect()
    };
    let mut series = Vec::new();
    let mut half = 1.0;
    if let Some(h) = &r.hist_xi {
        half = h.half_range.to_degrees();
        series.push(Series::new("ξ* − 90° (surface)", per_deg(h), Kind::Step));
    }
    if let Some(h) = &r.hist_zeta {
        series.push(Series::new("ζ* − 90° (surface)", per_deg(h), Kind::Step));
    }
    series.push(Series::new(
        "Eq. (12)",
        normal_curve(mx.to_degrees(), half),
        Kind::Dashed,
    ));
    series.push(Series::new(
        "Eq. (13)",
        normal_curve(mz.to_degrees(), half),
        Kind::Dashed,
    ));
    Plot {
        title: format!("β* = {}°", fmt_num(r.beta_star.to_degrees())),
        x_label: "angle − 90° (deg)".into(),
        y_label: "PDF (1/deg)".into(),
        series,
        x_range: Some((-half, half)),
        ..Plot::default()
    }
}

fn pdf_figure(path: &Path, target: &Deviations, s: &SurfaceStats) -> Result<()> {
    let plots: Vec<Plot> = s.rotated.iter().map(|r| pdf_panel(target, r)).collect();
    if plots.is_empty() {
        return Ok(());
    }
    plot_grid_svg(path, &plots, plots.len().min(2))
}
