//! `rebound scan`: a measured wall (or, without a file, the case's wall generated and read as
//! a scan) levelled and characterised in the terms of the rough-wall models (issue 29).
//!
//! Outputs in `--out` (default `results/<case name>/scan/`):
//! - `scan_summary.csv` — one row: the grid, Sq, Ssk, Sku, Sdq, the lay and the deviations
//!   along and across it (columns `crate::writers::scan::SUMMARY_HEADER`);
//! - `wall_card.toml` — `[wall]` ready to paste into a case, `[lay]`, `[scan]`, notes and, with
//!   diameters (`[scan] diameters_um`, `--diameter-um`), a `[[diameter]]` per sphere;
//! - `wall_card_diameters.csv` (with a lay) — the point and each sphere: the deviations of
//!   its centre surface and where the scan is too small or too coarse for it
//!   (`crate::writers::scan_diameters`);
//! - `height_map.svg` (the levelled scan), `slope_angle_pdfs.svg` (`ξ'`, `ζ'` against the
//!   normal law), `autocorrelation.svg` (along and across the lay, with the `1/e` level) and
//!   `autocorrelation_map.svg` (over the lags along x and y, the `1/e` contour, the lay);
//! - `run.toml`.
//!
//! The scan is read (every problem a one-line input error) before `--out` is begun; `--out`
//! is written as a whole (`crate::output::out_dir`).

use crate::case::builtin;
use crate::case::scan::{generated_bytes, generated_scan, ReadScan, ScanSource};
use crate::cli::ScanArgs;
use crate::commands::{begin_out, context, warn, Summary};
use crate::figures;
use crate::measured_wall::build_tables;
use crate::output::fmt_num;
use crate::writers::measured_wall::manifest_entries;
use crate::writers::scan::{manifest_table, summary_table, wall_card, Source};
use crate::writers::scan_diameters::{diameters_table, manifest_rows};
use crate::writers::surface::round_ms;
use roughwall::deterministic::SurfacePlan;
use roughwall::scan::angle_histograms;
use roughwall::scan::centre_surface_bytes;
use roughwall::scan::seen_by;
use roughwall::scan::{characterise, Characterisation};
use roughwall::scan::{correlation_map, map_bytes};
use roughwall::scan::{labelled, notes};
use roughwall::surface::HistogramSpec;
use roughwall::Result;
use roughwall::Warning;
use std::path::Path;
use std::time::Instant;

/// Bins of the slope-angle histograms, over `±4` times the larger deviation.
pub const HIST_BINS: usize = 100;

/// Lags drawn at least on each side of the map's origin.
const MAP_MIN_LAGS: f64 = 16.0;

/// The half-widths (m) of `autocorrelation_map.svg` along the scan's x and y: three times the
/// longer correlation length (a quarter of the scan where there is none), at least
/// [`MAP_MIN_LAGS`] pixels, at most a quarter of the scan.
fn map_half_width(c: &Characterisation) -> [f64; 2] {
    let f = &c.levelled;
    let (lx, ly) = (f.nx as f64 * f.dx, f.ny as f64 * f.dy);
    let quarter = 0.25 * lx.min(ly);
    let longest = [c.correlation.length_along_m, c.correlation.length_across_m]
        .iter()
        .map(|l| l.unwrap_or(quarter))
        .fold(0.0, f64::max);
    let w = (3.0 * longest).max(MAP_MIN_LAGS * f.dx.max(f.dy));
    [w.min(0.25 * lx), w.min(0.25 * ly)]
}

/// The case of `rebound scan --scan FILE` without `--case`: named after the file (the default
/// output `results/<file stem>/scan/`), or `scan` when the stem cannot name a directory.
fn named_after(file: &Path) -> String {
    let stem = file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .filter(|s| crate::run_context::check_name(s).is_ok())
        .unwrap_or_else(|| "scan".into());
    format!("name = {}\n", toml::Value::String(stem))
}

/// The heights to characterise: a scan read, or a wall to generate.
enum Input<'a> {
    Read(ReadScan),
    Generate(&'a SurfacePlan),
}

/// `[surface_choice]` of `run.toml` for a generated wall: where the grid comes from, the grid
/// and the roughness.
fn surface_choice(plan: &SurfacePlan) -> toml::Value {
    let spec = plan.spec();
    let mut t = toml::Table::new();
    t.insert("source".into(), plan.source().into());
    t.insert("nodes".into(), (spec.nodes as i64).into());
    t.insert("length_um".into(), (spec.length_m * 1e6).into());
    t.insert("spacing_um".into(), (spec.spacing_m() * 1e6).into());
    t.insert("rms_height_um".into(), (spec.rms_height_m * 1e6).into());
    for (k, c) in [
        ("corr_length_x_um", spec.corr_length_x_m),
        ("corr_length_z_um", spec.corr_length_z_m),
    ] {
        if let Some(c) = c {
            t.insert(k.into(), (c * 1e6).into());
        }
    }
    toml::Value::Table(t)
}

/// Runs the subcommand.
pub fn run(args: &ScanArgs) -> Result<Summary> {
    let default = match (&args.common.case, &args.scan) {
        (None, Some(file)) => named_after(file),
        _ => builtin::SCAN.to_string(),
    };
    let mut ctx = context(&args.common, "scan", &default)?;
    // A relative `scan.file` is read from the case file's directory.
    let case_dir = match &args.common.case {
        Some(p) => crate::case::load::resolve_path(p)?
            .parent()
            .map(Path::to_path_buf),
        None => None,
    };
    let mut warnings = Vec::new();
    let setup = ctx.case.scan_setup(
        case_dir.as_deref(),
        args.scan.as_deref(),
        &args.diameter_um,
        (args.measured_wall, args.measured_wall_histories),
        &mut warnings,
    )?;
    warn(warnings);

    let t0 = Instant::now();
    // A file is read (and refused) before `--out` is begun; a wall is generated after.
    let (input, file) = match &setup.source {
        ScanSource::File(f) => {
            let read = f.read()?;
            // What the reader read despite a flaw (an X3P whose main.xml alone fails its
            // checksum) is the user's to know.
            warn(
                read.info
                    .iter()
                    .filter(|(k, _)| k == "warning")
                    .map(|(_, v)| Warning(format!("`{}` {}: {v}", f.key, f.shown))),
            );
            (Input::Read(read), f.shown.clone())
        }
        ScanSource::Generated(plan) => {
            let nodes = plan.spec().nodes;
            let key = match ctx.case.surface.is_some() {
                true => "surface.nodes",
                false => "wall (the automatic grid's nodes)",
            };
            roughwall::memory::require(
                key,
                nodes,
                generated_bytes(plan),
                &format!("generating a {nodes} × {nodes} wall and levelling it"),
            )?;
            (Input::Generate(plan), String::new())
        }
    };
    // What the centre surfaces and the map add to the levelled scan, checked before `--out`.
    let (nx, ny) = match &input {
        Input::Read(r) => (r.field.nx, r.field.ny),
        Input::Generate(plan) => (plan.spec().nodes, plan.spec().nodes),
    };
    if !setup.diameters_m.is_empty() {
        let key = match args.diameter_um.is_empty() {
            true => "scan.diameters_um",
            false => "--diameter-um",
        };
        let um: Vec<String> = setup.diameters_m.iter().map(|d| fmt_num(d * 1e6)).collect();
        roughwall::memory::require(
            key,
            format!("[{}]", um.join(", ")),
            centre_surface_bytes(nx, ny),
            &format!("the centre surface of a sphere over the {nx} × {ny} scan {file}"),
        )?;
    }
    let size_key = match &setup.source {
        ScanSource::File(f) => f.key,
        ScanSource::Generated(_) if ctx.case.surface.is_some() => "surface.nodes",
        ScanSource::Generated(_) => "wall (the automatic grid's nodes)",
    };
    let size_value = match &setup.source {
        ScanSource::File(_) => format!("{file} ({nx} × {ny} points)"),
        ScanSource::Generated(_) => format!("{nx} × {ny} points"),
    };
    roughwall::memory::require(
        size_key,
        size_value,
        map_bytes(nx, ny),
        "the autocorrelation map",
    )?;
    let out = begin_out(&ctx.out_dir)?;
    let ReadScan {
        field,
        format,
        info,
    } = match input {
        Input::Read(r) => r,
        Input::Generate(plan) => {
            ctx.manifest.set("surface_choice", surface_choice(plan));
            generated_scan(plan, ctx.seed)?
        }
    };
    let t_read = t0.elapsed().as_secs_f64();
    let points = (field.nx * field.ny) as u64;
    // The library's refusals (levelling, memory) name the scan, not the file: add it.
    let c = characterise(field, setup.level_degree).map_err(|e| match e {
        roughwall::Error::Input(m) if !file.is_empty() => {
            roughwall::Error::Input(format!("{file}: {m}"))
        }
        other => other,
    })?;
    let t_char = t0.elapsed().as_secs_f64() - t_read;

    // The point particle costs no dilation; each sphere one over the whole scan.
    let seen = seen_by(&c, &setup.diameters_m).unwrap_or_default();
    let t_centre = t0.elapsed().as_secs_f64() - t_read - t_char;

    let src = Source {
        file: &file,
        format: &format,
    };
    let t_cost = Instant::now();
    let triangulation = crate::case::deterministic::triangulation(&ctx.case)?;
    let cost = roughwall::gaussian_cost::of_scan(&c, triangulation)?;
    ctx.manifest.set_run(
        "gaussian_cost_s",
        toml::Value::Float(round_ms(t_cost.elapsed().as_secs_f64())),
    );
    if let Some(cost) = &cost {
        ctx.manifest.set("gaussian_cost", gaussian_cost_table(cost));
    }
    let mut notes = notes(&c, cost.as_ref().map(|c| c.effect()).as_ref());
    // The point particle's criteria are [wall]'s notes; a sphere's are its row's (and warnings).
    let (point, spheres) = seen
        .split_first()
        .map_or((None, &[][..]), |(p, s)| (Some(p), s));
    notes.extend(point.map(|p| labelled(p, &c.levelled)).unwrap_or_default());
    let sphere_notes: Vec<String> = spheres
        .iter()
        .flat_map(|s| labelled(s, &c.levelled))
        .collect();
    let dir = out.path().to_path_buf();
    // The wall's own model: a table per particle, beside the card that names them.
    let tables = match setup.measured_wall {
        true => {
            let t1 = Instant::now();
            let name = if file.is_empty() {
                "the generated wall"
            } else {
                &file
            };
            let tables = build_tables(
                &c,
                name,
                &setup.diameters_m,
                triangulation,
                (setup.measured_wall_histories, ctx.seed),
                &dir,
            )?;
            ctx.manifest.set("measured_wall", manifest_entries(&tables));
            ctx.manifest.set_run(
                "measured_wall_s",
                toml::Value::Float(round_ms(t1.elapsed().as_secs_f64())),
            );
            tables
        }
        false => Vec::new(),
    };
    summary_table(&src, &c).write(&dir.join("scan_summary.csv"))?;
    crate::output::write_atomic(
        &dir.join("wall_card.toml"),
        wall_card(&src, &c, &notes, &seen, &tables).as_bytes(),
    )?;
    // The point particle's row always: it is [wall]'s resolution check, which the card's
    // header points to.
    if !seen.is_empty() {
        diameters_table(&seen, &c.levelled).write(&dir.join("wall_card_diameters.csv"))?;
    }
    if !spheres.is_empty() {
        ctx.manifest
            .set("diameter", manifest_rows(&seen, &c.levelled));
        ctx.manifest
            .set_run("centre_surfaces_s", toml::Value::Float(round_ms(t_centre)));
    }
    figures::scan::height_map(&dir.join("height_map.svg"), &c.levelled, &ctx.case.name)?;
    let mut figures = vec!["height_map.svg"];
    if let Some(lay) = &c.lay {
        let half = (4.0 * lay.delta_xi.max(lay.delta_zeta)).max(1f64.to_radians());
        let hists = angle_histograms(
            &c.levelled,
            lay.angle,
            HistogramSpec {
                half_range: half,
                bins: HIST_BINS,
            },
        );
        figures::scan::angle_pdfs(&dir.join("slope_angle_pdfs.svg"), &hists, lay)?;
        figures.push("slope_angle_pdfs.svg");
    }
    if c.correlation.lags_m.len() > 1 {
        figures::scan::autocorrelation(&dir.join("autocorrelation.svg"), &c.correlation)?;
        figures.push("autocorrelation.svg");
    }
    let t_map = Instant::now();
    let map = correlation_map(&c.levelled, map_half_width(&c));
    ctx.manifest.set_run(
        "correlation_map_s",
        toml::Value::Float(round_ms(t_map.elapsed().as_secs_f64())),
    );
    figures::scan::autocorrelation_map(
        &dir.join("autocorrelation_map.svg"),
        &map,
        c.lay.map(|l| l.angle),
    )?;
    figures.push("autocorrelation_map.svg");
    ctx.manifest.set(
        "scan",
        manifest_table(&src, &c, &info, c.lay.map(|l| l.triangles)),
    );
    ctx.manifest.set(
        "notes",
        toml::Value::Array(notes.iter().map(|n| n.clone().into()).collect()),
    );
    ctx.manifest.set(
        "figures",
        toml::Value::Array(figures.iter().map(|&f| f.into()).collect()),
    );
    let read_key = if file.is_empty() {
        "generate_s"
    } else {
        "read_s"
    };
    ctx.manifest
        .set_run(read_key, toml::Value::Float(round_ms(t_read)));
    ctx.manifest
        .set_run("characterise_s", toml::Value::Float(round_ms(t_char)));
    ctx.manifest.write(&dir)?;
    let dir = out.commit()?;
    warn(notes.into_iter().chain(sphere_notes).map(Warning));

    let mut work = format!(
        "{} × {} {}",
        c.levelled.nx,
        c.levelled.ny,
        if file.is_empty() {
            "generated wall".to_string()
        } else {
            format!("scan ({format})")
        }
    );
    if let Some(l) = &c.lay {
        work += &format!(
            ", lay {}°, (Δξ, Δζ) = ({}°, {}°)",
            fmt_num(round_to(l.angle.to_degrees(), 2)),
            fmt_num(round_to(l.delta_xi.to_degrees(), 3)),
            fmt_num(round_to(l.delta_zeta.to_degrees(), 3))
        );
    }
    Ok(Summary {
        work,
        rate: Some((points, "points")),
        wrote: dir,
    })
}

/// `x` rounded to `digits` decimals.
fn round_to(x: f64, digits: i32) -> f64 {
    let p = 10f64.powi(digits);
    (x * p).round() / p
}

/// `run.toml`'s `[gaussian_cost]`: the scan check's numbers (docs/models.md, "What a
/// non-Gaussian wall does to rebounds"), written whether or not a note quotes them.
fn gaussian_cost_table(cost: &roughwall::gaussian_cost::GaussianCost) -> toml::Value {
    let pair = |(a, b): (f64, f64)| toml::Value::Array(vec![a.into(), b.into()]);
    let mut t = toml::Table::new();
    t.insert("ks".into(), cost.ks.into());
    t.insert("ks_at_deg".into(), pair(cost.ks_at));
    t.insert("bias_deg".into(), cost.bias_deg.into());
    t.insert("bias_at_deg".into(), pair(cost.bias_at));
    t.insert(
        "unserved_deg".into(),
        toml::Value::Array(cost.unserved.iter().map(|&d| pair(d)).collect()),
    );
    if let Some((ks, bias)) = cost.control {
        t.insert("control_ks".into(), ks.into());
        t.insert("control_bias_deg".into(), bias.into());
    }
    t.insert(
        "ks_noise".into(),
        roughwall::gaussian_cost::ks_noise().into(),
    );
    t.insert(
        "histories_per_direction".into(),
        (roughwall::gaussian_cost::HISTORIES as i64).into(),
    );
    t.insert("significant".into(), cost.significant().into());
    toml::Value::Table(t)
}
