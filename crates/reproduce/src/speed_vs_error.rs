//! Speed against error: each run of `scripts/speed-vs-error.sh` against the reference run
//! (`speed_vs_error.csv`, `speed_vs_error.svg` and the section of `REPORT.md`).

use crate::common::{f, missing, subdirs, summary};
use crate::paths::{SPEED_DETERMINISTIC, SPEED_STOCHASTIC, SPEED_VS_ERROR, VS_REFERENCE};
use outputs::csv::{num, wall_time_s, Rows};
use outputs::CsvTable;
use outputs::{plot_svg, Kind, Plot, Series};
use roughwall::format::fmt_num;
use roughwall::Result;
use std::fmt::Write;
use std::path::Path;

/// Writes `speed_vs_error.csv` and its figure and the section of `REPORT.md`.
pub fn speed_vs_error(results: &Path, md: &mut String) -> Result<()> {
    md.push_str("## Speed against error\n\n");
    let dir = results.join(SPEED_VS_ERROR);
    let mut table = CsvTable::new(&[
        "model",
        "particles",
        "spacing_per_corr_length",
        "wall_time_s",
        "us_per_particle",
        "max_ks_alpha_out",
        "max_ks_dbeta",
        "max_abs_mean_alpha_out_err_deg",
        "target_se_deg",
        "max_se_mean_alpha_out_deg",
        "max_abs_z_alpha_out",
    ]);
    let mut pts_ds = Vec::new();
    let mut pts_sm = Vec::new();
    for run in subdirs(&dir, SPEED_DETERMINISTIC)
        .into_iter()
        .chain(subdirs(&dir, SPEED_STOCHASTIC))
    {
        let name = run
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let Some(c) = Rows::read(&run.join(VS_REFERENCE).join("comparison.csv"))? else {
            continue;
        };
        let Some(summ) = summary(&run)? else { continue };
        let model = if name.starts_with(SPEED_DETERMINISTIC) {
            "deterministic"
        } else {
            "stochastic"
        };
        let parse = |tag: char| {
            name.split('-')
                .find_map(|p| p.strip_prefix(tag).and_then(|v| v.parse::<f64>().ok()))
        };
        let spacing = if model == "deterministic" {
            parse('s')
        } else {
            None
        };
        let target = parse('t');
        // Particles per condition (the most any condition used) and in total.
        let per_condition: Vec<f64> = summ
            .rows
            .iter()
            .filter_map(|r| num(r, "particles"))
            .collect();
        let n = per_condition
            .iter()
            .copied()
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
        let total: f64 = per_condition.iter().sum();
        let wall = wall_time_s(&run);
        let per = wall.filter(|_| total > 0.0).map(|w| 1e6 * w / total);
        let maxq = |q: &str, k: &str| {
            c.with("quantity", q)
                .iter()
                .filter_map(|r| num(r, k))
                .fold(None, |m: Option<f64>, v| {
                    Some(m.map_or(v.abs(), |m| m.max(v.abs())))
                })
        };
        let ks_a = maxq("alpha_out", "ks");
        let ks_d = maxq("dbeta", "ks");
        let z_a = maxq("alpha_out", "z");
        let mean_err = c
            .with("quantity", "alpha_out")
            .iter()
            .filter_map(|r| Some((num(r, "mean_b")? - num(r, "mean_a")?).abs()))
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
        let se_a = summ
            .rows
            .iter()
            .filter_map(|r| num(r, "se_mean_alpha_out_deg"))
            .fold(None, |m: Option<f64>, v| Some(m.map_or(v, |m| m.max(v))));
        let cell = |x: Option<f64>| x.map(fmt_num).unwrap_or_default();
        table.push(vec![
            model.into(),
            cell(n),
            cell(spacing),
            cell(wall),
            cell(per),
            cell(ks_a),
            cell(ks_d),
            cell(mean_err),
            cell(target),
            cell(se_a),
            cell(z_a),
        ]);
        if let (Some(w), Some(k)) = (wall, ks_a) {
            if model == "deterministic" {
                pts_ds.push((w, k));
            } else {
                pts_sm.push((w, k));
            }
        }
    }
    if table.rows.is_empty() {
        missing(md, "scripts/speed-vs-error.sh", &dir);
        return Ok(());
    }
    table.write(&results.join("speed_vs_error.csv"))?;
    plot_svg(
        &results.join("speed_vs_error.svg"),
        &Plot {
            title: "KS distance of α⁺ to the reference vs wall time (aniso wall, α⁻ = −12.5°)"
                .into(),
            x_label: "wall time per run (s)".into(),
            y_label: "max KS distance, alpha_out".into(),
            series: vec![
                Series::new("deterministic", pts_ds, Kind::Markers),
                Series::new("stochastic", pts_sm, Kind::Markers),
            ],
            log_x: true,
            log_y: true,
            ..Default::default()
        },
    )?;
    md.push_str("Reference: deterministic run with the finest grid and the most particles (`speed-vs-error/reference`). Runs either at a fixed particle count or with `--target-se` (whole blocks of 65 536 particles until the standard errors of mean α⁺ and mean β⁺ − β⁻ are at most the target). Wall times from each run's `run.toml` (2-core machine, surface generation included for the deterministic runs). z: the difference of mean α⁺ from the reference in units of the combined standard error. Table: `speed_vs_error.csv`.\n\n| model | particles per condition | target SE (°) | c_L/δ | wall time (s) | µs per particle | max SE of mean α⁺ (°) | max KS α⁺ | max KS β⁺ − β⁻ | max \\|mean α⁺ error\\| (°) | max \\|z\\| α⁺ |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    for r in &table.rows {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r[0], r[1], r[8], r[2], r[3], r[4], r[9], r[5], r[6], r[7], r[10]
        );
    }
    // Cost per rebound, stochastic against deterministic, at equal particle counts.
    let per = |model: &str, n: &str| {
        table
            .rows
            .iter()
            .find(|r| {
                r[0] == model
                    && r[1] == n
                    && r[8].is_empty()
                    && (model == "stochastic" || r[2] == "8")
            })
            .and_then(|r| r[4].parse::<f64>().ok())
    };
    md.push_str("\nCost per rebound on the same scene (wall time per particle, surface generation included for the deterministic runs at c_L/δ = 8):\n\n| particles | deterministic (µs) | stochastic (µs) | deterministic / stochastic |\n|---|---|---|---|\n");
    let mut counts: Vec<&String> = table
        .rows
        .iter()
        .filter(|r| r[0] == "stochastic" && r[8].is_empty())
        .map(|r| &r[1])
        .collect();
    counts.sort_by(|a, b| {
        a.parse::<f64>()
            .unwrap_or(0.0)
            .total_cmp(&b.parse::<f64>().unwrap_or(0.0))
    });
    counts.dedup();
    for n in counts {
        let (d, sm) = (per("deterministic", n), per("stochastic", n));
        let _ = writeln!(
            md,
            "| {n} | {} | {} | {} |",
            f(d, 3),
            f(sm, 3),
            f(d.zip(sm).map(|(d, s)| d / s), 1)
        );
    }
    md.push_str("\n![speed vs error](speed_vs_error.svg)\n\n");
    Ok(())
}
