//! The deterministic run's figures: analogues of Radenkovic & Simonin 2021,
//! Figs. 6, 7 (first and final rebound), 8, 9, 12 and, for β⁻ sweeps, Fig. 16.
//! Panels are laid out with one row per `α⁻` and one column per `β⁻`.

use crate::error::Result;
use crate::figures::{plot_grid_svg, sweep_plots, sweep_series, Kind, Plot, Series};
use crate::tally::{Bin, ConditionResult};
use std::path::Path;

fn centres(bins: &[Bin]) -> Vec<(f64, f64)> {
    bins.iter()
        .map(|b| (0.5 * (b.lo + b.hi), b.value))
        .collect()
}

fn title(r: &ConditionResult) -> String {
    format!(
        "α⁻ = {}°, β⁻ = {}°",
        crate::output::fmt_num(r.condition.alpha_in_deg()),
        crate::output::fmt_num(r.condition.beta_in_deg())
    )
}

/// Number of distinct `β⁻` (the grid's column count).
fn columns(results: &[ConditionResult]) -> usize {
    let mut betas: Vec<f64> = Vec::new();
    for r in results {
        if !betas.contains(&r.condition.beta_in) {
            betas.push(r.condition.beta_in);
        }
    }
    betas.len().max(1)
}

fn grid(
    path: &Path,
    results: &[ConditionResult],
    x_label: &str,
    y_label: &str,
    series: &[(&str, &str, Kind)],
) -> Result<()> {
    let plots: Vec<Plot> = results
        .iter()
        .map(|r| Plot {
            title: title(r),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: series
                .iter()
                .filter_map(|(q, label, kind)| {
                    r.pdf(q).map(|b| Series::new(*label, centres(b), *kind))
                })
                .collect(),
            ..Default::default()
        })
        .collect();
    plot_grid_svg(path, &plots, columns(results))
}

/// One figure: file name, axis labels and the `(quantity, legend, kind)` series of each panel.
type Panel<'a> = (&'a str, &'a str, &'a str, Vec<(&'a str, &'a str, Kind)>);

/// Writes every figure into `dir`; returns the file names.
pub fn write_figures(dir: &Path, results: &[ConditionResult], label: &str) -> Result<Vec<String>> {
    const PDF: &str = "PDF (1/deg)";
    let panels: [Panel; 5] = [
        (
            "fig06_alpha_out.svg",
            "α⁺ (deg)",
            PDF,
            vec![("alpha_out", label, Kind::Step)],
        ),
        (
            "fig07_dbeta.svg",
            "β⁺ − β⁻ (deg)",
            PDF,
            vec![
                ("dbeta_first", "first rebound (1C)", Kind::Dashed),
                ("dbeta", "final rebound (MC)", Kind::Step),
            ],
        ),
        (
            "fig08_xi_first.svg",
            "ξ − 90° (deg)",
            PDF,
            vec![("xi_first", label, Kind::Step)],
        ),
        (
            "fig09_zeta_first.svg",
            "ζ − 90° (deg)",
            PDF,
            vec![("zeta_first", label, Kind::Step)],
        ),
        (
            "fig12_p_single.svg",
            "α⁺ (deg)",
            "P(n = 1 | α⁺)",
            vec![
                ("p_single_given_alpha_first", label, Kind::Markers),
                (
                    "p_single_model",
                    "tanh(2 α⁺/Δγ(β⁺)), Eqs. 34–35",
                    Kind::Line,
                ),
            ],
        ),
    ];
    let mut names = Vec::new();
    for (name, x_label, y_label, quantities) in &panels {
        grid(&dir.join(name), results, x_label, y_label, quantities)?;
        names.push(name.to_string());
    }
    // Figs. 16–17: mean and std of β⁺ − β⁻ against β⁻ (one line per α⁻) or |α⁻| (one per β⁻).
    let mut alphas: Vec<f64> = results.iter().map(|r| r.condition.alpha_in_deg()).collect();
    let mut betas: Vec<f64> = results.iter().map(|r| r.condition.beta_in_deg()).collect();
    for v in [&mut alphas, &mut betas] {
        v.sort_by(|a, b| a.total_cmp(b));
        v.dedup();
    }
    for (along_beta, keys, name, x_label) in [
        (true, &alphas, "fig16_dbeta_vs_beta.svg", "β⁻ (deg)"),
        (false, &betas, "fig17_dbeta_vs_alpha.svg", "|α⁻| (deg)"),
    ] {
        let (mut mean, mut std) = (Vec::new(), Vec::new());
        for &k in keys.iter() {
            let pts = results
                .iter()
                .filter(|r| if along_beta { r.condition.alpha_in_deg() } else { r.condition.beta_in_deg() } == k)
                .filter_map(|r| {
                    let x = if along_beta { r.condition.beta_in_deg() } else { -r.condition.alpha_in_deg() };
                    r.stat("dbeta").map(|(m, s)| (x, m, s))
                })
                .collect::<Vec<_>>();
            // A sweep needs at least three points to be worth a figure.
            if pts.len() < 3 {
                continue;
            }
            let key = if along_beta { "α⁻" } else { "β⁻" };
            if let Some((m, sd)) = sweep_series(label, key, k, pts, Kind::Line) {
                mean.push(m);
                std.push(sd);
            }
        }
        if !mean.is_empty() {
            plot_grid_svg(&dir.join(name), &sweep_plots(mean, std, x_label), 2)?;
            names.push(name.to_string());
        }
    }
    Ok(names)
}
