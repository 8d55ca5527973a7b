//! `rebound surface`: generate the Garcia–Stoll surface of the case and measure the
//! statistics of Radenkovic & Simonin 2021, Table 1 (Eqs. 7–9, 14–15).
//!
//! Outputs in `--out` ([`OUTPUT_FILES`]): `surface_summary.csv`, `normal_angles.csv`,
//! `height_map.svg`, `normal_angle_pdfs.svg`, `run.toml` (timings only there), and with
//! `--heights FILE` the height field in the format of [`crate::surface::heights_io`].
//! `--out` is written as a whole ([`crate::output::out_dir`]); a `--heights` file inside it
//! moves with the swap, one outside it is written on its own (atomically).

use crate::cli::SurfaceArgs;
use crate::commands::Context;
use crate::error::Result;
use crate::figures;
use crate::output::out_dir::{place_file, OutputDir};
use crate::output::{fmt_num, CsvTable};
use crate::surface::dilation::{effective_roughness, EffectiveRoughness};
use crate::surface::heights_io::write_heights;
use crate::surface::stats::{surface_stats, HistogramSpec, SurfaceStats};
use crate::surface::{generate, HeightField};
use crate::wall::{self, rotated_moments, Deviations};
use std::time::Instant;

/// The built-in case: the surface of Table 1 (L = 5 mm, N = 5001, h = 0.37 µm,
/// c_Lx = 12 µm, c_Lz = 4 µm).
pub const TABLE1_TOML: &str = include_str!("../../configs/cases/table1.toml");

/// Columns of `surface_summary.csv` (issue #2).
pub const SUMMARY_HEADER: [&str; 14] = [
    "nodes",
    "length_um",
    "spacing_um",
    "rms_height_um",
    "target_rms_height_um",
    "rms_slope_x",
    "target_rms_slope_x",
    "rms_slope_z",
    "target_rms_slope_z",
    "delta_xi_deg",
    "target_delta_xi_deg",
    "delta_zeta_deg",
    "target_delta_zeta_deg",
    "max_height_um",
];

/// Columns of `normal_angles.csv` (issue #2).
pub const ANGLES_HEADER: [&str; 9] = [
    "beta_star_deg",
    "delta_xi_star_deg",
    "delta_zeta_star_deg",
    "rho_xi_zeta",
    "rho_xi_eta",
    "rho_eta_zeta",
    "model_delta_xi_star_deg",
    "model_delta_zeta_star_deg",
    "model_rho_xi_zeta",
];

/// The files the command writes into `--out`.
pub const OUTPUT_FILES: [&str; 7] = [
    "surface_summary.csv",
    "normal_angles.csv",
    "height_map.svg",
    "normal_angle_pdfs.svg",
    "run.toml",
    "effective_roughness.csv",
    "effective_roughness.svg",
];

/// Columns of `effective_roughness.csv`.
/// The last three: the large-sphere asymptote `√(h/D)` (rad, shown in degrees; `h` the
/// measured rms height) and each effective deviation over it.
pub const EFFECTIVE_HEADER: [&str; 11] = [
    "diameter_um",
    "d_over_cl_x",
    "d_over_cl_z",
    "delta_xi_eff_deg",
    "delta_zeta_eff_deg",
    "delta_xi_ratio",
    "delta_zeta_ratio",
    "contact_fraction",
    "sqrt_h_over_d_deg",
    "delta_xi_eff_over_sqrt_h_over_d",
    "delta_zeta_eff_over_sqrt_h_over_d",
];

/// The large-sphere law `Δ_eff ≈ √(h/D)` (rad): a sphere much larger than `h/Δ²` rests on
/// asperity tops, and its centre surface is made of caps whose slopes scale as `√(h/R)`,
/// whatever the correlation lengths. Measured, not assumed: `effective_roughness.csv` gives
/// the ratio of each effective deviation to it.
pub fn large_sphere_deviation(rms_height_m: f64, diameter_m: f64) -> f64 {
    if diameter_m > 0.0 {
        (rms_height_m / diameter_m).sqrt()
    } else {
        f64::INFINITY
    }
}

/// Bins of the `ξ*`, `ζ*` histograms.
const HIST_BINS: usize = 100;

/// Runs the subcommand: validate everything first (nothing is written on bad input),
/// then generate, measure, and write.
pub fn run(args: &SurfaceArgs) -> Result<()> {
    let mut ctx = Context::new(&args.common, "surface", TABLE1_TOML)?;
    let spec = ctx.case.surface_spec()?;
    let betas = ctx.case.beta_star()?;
    let diameters = ctx.case.effective_diameters(spec.length_m)?;
    if !diameters.is_empty() {
        let nodes = (spec.nodes as u64).saturating_mul(spec.nodes as u64);
        crate::memory::require(
            "stats.diameter_um",
            format!("{} diameters", diameters.len()),
            nodes.saturating_mul(crate::surface::dilation::BYTES_PER_NODE),
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

/// `D/c_L` along an axis (empty for `c_L = ∞`, 2-D roughness).
fn d_over_cl(d: f64, c: Option<f64>) -> Option<f64> {
    c.map(|c| d / c)
}

fn effective_table(
    spec: &crate::case::SurfaceSpec,
    s: &SurfaceStats,
    eff: &[EffectiveRoughness],
) -> CsvTable {
    let ratio = |x: f64, base: f64| {
        if base > 0.0 {
            fmt_num(x / base)
        } else {
            String::new()
        }
    };
    let mut t = CsvTable::new(&EFFECTIVE_HEADER);
    for e in eff {
        let a = large_sphere_deviation(s.rms_height_m, e.diameter_m);
        t.push(vec![
            fmt_num(e.diameter_m * 1e6),
            d_over_cl(e.diameter_m, spec.corr_length_x_m)
                .map(fmt_num)
                .unwrap_or_default(),
            d_over_cl(e.diameter_m, spec.corr_length_z_m)
                .map(fmt_num)
                .unwrap_or_default(),
            fmt_num(e.delta_xi.to_degrees()),
            fmt_num(e.delta_zeta.to_degrees()),
            ratio(e.delta_xi, s.delta_xi),
            ratio(e.delta_zeta, s.delta_zeta),
            fmt_num(e.contact_fraction),
            fmt_num(a.to_degrees()),
            ratio(e.delta_xi, a),
            ratio(e.delta_zeta, a),
        ]);
    }
    t
}

/// Refuses a grid whose generation would not fit in the available memory (Linux:
/// `MemAvailable` of /proc/meminfo) instead of letting the allocation abort the process.
fn round_ms(s: f64) -> f64 {
    (s * 1e3).round() / 1e3
}

/// How the field is stored (see `HeightField`): `nz = 1` for a surface constant along z.
fn grid_table(f: &HeightField) -> toml::Value {
    let mut t = toml::Table::new();
    t.insert("nx".into(), toml::Value::Integer(f.nx as i64));
    t.insert("nz".into(), toml::Value::Integer(f.nz as i64));
    t.insert("dx_m".into(), toml::Value::Float(f.dx));
    t.insert("dz_m".into(), toml::Value::Float(f.dz));
    t.insert(
        "statistics".into(),
        "every triangle of the grid (two per cell), equally weighted".into(),
    );
    toml::Value::Table(t)
}

/// Target rms slope `√2 h / c_L` (Radenkovic & Simonin 2021, Eq. 14); 0 for `c_L = ∞`.
fn target_slope(h: f64, c: Option<f64>) -> f64 {
    c.map_or(0.0, |c| wall::deviation_from_surface(h, c))
}

fn summary_table(
    spec: &crate::case::SurfaceSpec,
    target: &Deviations,
    s: &SurfaceStats,
) -> CsvTable {
    let um = |m: f64| fmt_num(m * 1e6);
    let deg = |r: f64| fmt_num(r.to_degrees());
    let mut t = CsvTable::new(&SUMMARY_HEADER);
    t.push(vec![
        spec.nodes.to_string(),
        um(spec.length_m),
        um(spec.spacing_m()),
        um(s.rms_height_m),
        um(spec.rms_height_m),
        fmt_num(s.rms_slope_x),
        fmt_num(target_slope(spec.rms_height_m, spec.corr_length_x_m)),
        fmt_num(s.rms_slope_z),
        fmt_num(target_slope(spec.rms_height_m, spec.corr_length_z_m)),
        deg(s.delta_xi),
        deg(target.delta_xi),
        deg(s.delta_zeta),
        deg(target.delta_zeta),
        um(s.max_height_m),
    ]);
    t
}

/// Model columns: Eq. (9) with the target deviations of Eq. (15), and Eq. (8). At
/// multiples of 90° the covariance is exactly 0 (not `cos(π/2) ≈ 6e-17` times something).
fn model_row(target: &Deviations, beta_star: f64) -> (f64, f64, f64) {
    let mut m = rotated_moments(target, beta_star);
    let q = beta_star / std::f64::consts::FRAC_PI_2;
    if (q - q.round()).abs() < 1e-12 {
        m.cov = 0.0;
    }
    (m.var_a.sqrt(), m.var_b.sqrt(), m.rho())
}

fn angles_table(target: &Deviations, s: &SurfaceStats) -> CsvTable {
    let deg = |r: f64| fmt_num(r.to_degrees());
    let mut t = CsvTable::new(&ANGLES_HEADER);
    for r in &s.rotated {
        let (mx, mz, mrho) = model_row(target, r.beta_star);
        t.push(vec![
            deg(r.beta_star),
            deg(r.delta_xi_star),
            deg(r.delta_zeta_star),
            fmt_num(r.rho_xi_zeta),
            fmt_num(r.rho_xi_eta),
            fmt_num(r.rho_eta_zeta),
            deg(mx),
            deg(mz),
            fmt_num(mrho),
        ]);
    }
    t
}
