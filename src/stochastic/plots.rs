//! SVG figures of a stochastic run: analogues of Radenkovic & Simonin 2021, Figs. 10, 11,
//! the α⁺ and β⁺ − β⁻ panels of Figs. 14–15, and the mean/std of β⁺ − β⁻ against the
//! incident angles (Figs. 16–17).

use super::simulate::ConditionRun;
use crate::error::Result;
use crate::figures::{
    bins_to_points, plot_grid_svg, sweep_plots, sweep_series, Kind, Plot, Series,
};
use crate::tally::{density, ConditionResult};
use crate::wall::{conditional_gamma_star, rotated_moments, Deviations};
use std::path::Path;

fn title(r: &ConditionResult) -> String {
    format!(
        "α⁻ = {}°, β⁻ = {}°",
        crate::output::fmt_num(r.condition.alpha_in_deg()),
        crate::output::fmt_num(r.condition.beta_in_deg())
    )
}

fn cols(n: usize) -> usize {
    n.clamp(1, 3)
}

/// Writes the figures into `dir`; returns their file names.
pub fn write_figures(
    dir: &Path,
    results: &[ConditionResult],
    runs: &[ConditionRun],
    wall: &Deviations,
    label: &str,
) -> Result<Vec<String>> {
    let mut names = Vec::new();
    if results.is_empty() {
        return Ok(names);
    }
    // Fig. 10: γ, samples and the model density.
    let plots: Vec<Plot> = results
        .iter()
        .map(|r| {
            let mut series = Vec::new();
            if let Some(b) = r.pdf("gamma_first") {
                series.push(Series::new(label, bins_to_points(b), Kind::Step));
            }
            if let Some(b) = r.pdf("gamma_model") {
                series.push(Series::new(
                    "ES, Eqs. (31)–(33)",
                    bins_to_points(b),
                    Kind::Line,
                ));
            }
            Plot {
                title: title(r),
                x_label: "γ (deg)".into(),
                y_label: "PDF (1/deg)".into(),
                series,
                ..Default::default()
            }
        })
        .collect();
    plot_grid_svg(&dir.join("fig10_gamma.svg"), &plots, cols(plots.len()))?;
    names.push("fig10_gamma.svg".to_string());

    // Fig. 11: γ* given γ in two slices of γ (around 0 and around +Δγ), samples and Eq. (29).
    let plots: Vec<Plot> = results
        .iter()
        .zip(runs)
        .map(|(r, run)| {
            let m = rotated_moments(wall, r.condition.beta_in);
            let dg = m.var_a.max(0.0).sqrt();
            let mut series = Vec::new();
            for (k, g0) in [(0, 0.0), (1, dg)] {
                let half = (0.1 * dg).max(1e-9);
                let sel: Vec<f64> = run
                    .outcomes
                    .iter()
                    .filter(|o| (o.gamma_first - g0).abs() <= half)
                    .map(|o| o.gamma_star_first.to_degrees())
                    .collect();
                if sel.len() < 50 {
                    continue;
                }
                let (mean, var) = conditional_gamma_star(&m, g0);
                let sd = var.max(0.0).sqrt().to_degrees();
                let w = (sd / 5.0).clamp(0.05, 1.0);
                let bins = density(&sel, -90.0, 90.0, w);
                let name = if k == 0 { "γ ≈ 0" } else { "γ ≈ Δγ" };
                series.push(Series::new(
                    format!("{label}, {name}"),
                    bins_to_points(&bins),
                    Kind::Step,
                ));
                if sd > 0.0 {
                    let mu = mean.to_degrees();
                    let pts = (0..=120)
                        .map(|i| {
                            let x = mu - 4.0 * sd + 8.0 * sd * i as f64 / 120.0;
                            let z = (x - mu) / sd;
                            (
                                x,
                                (-0.5 * z * z).exp() / (sd * (2.0 * std::f64::consts::PI).sqrt()),
                            )
                        })
                        .collect();
                    series.push(Series::new(format!("Eq. (29), {name}"), pts, Kind::Line));
                }
            }
            Plot {
                title: title(r),
                x_label: "γ* (deg)".into(),
                y_label: "PDF of γ* given γ (1/deg)".into(),
                series,
                ..Default::default()
            }
        })
        .collect();
    plot_grid_svg(
        &dir.join("fig11_gamma_star_given_gamma.svg"),
        &plots,
        cols(plots.len()),
    )?;
    names.push("fig11_gamma_star_given_gamma.svg".to_string());

    // Figs. 14–15: α⁺ (α⁺_xy of Eq. 43 at β⁻ = 0, as in Fig. 14) and β⁺ − β⁻.
    let mut plots = Vec::new();
    for r in results {
        let (q, xl) = if r.condition.beta_in == 0.0 {
            ("alpha_out_xy", "α⁺_xy (deg)")
        } else {
            ("alpha_out", "α⁺ (deg)")
        };
        for (q, xl) in [(q, xl), ("dbeta", "β⁺ − β⁻ (deg)")] {
            let series = r
                .pdf(q)
                .map(|b| vec![Series::new(label, bins_to_points(b), Kind::Step)])
                .unwrap_or_default();
            plots.push(Plot {
                title: title(r),
                x_label: xl.into(),
                y_label: "PDF (1/deg)".into(),
                series,
                ..Default::default()
            });
        }
    }
    plot_grid_svg(&dir.join("fig14_15_rebound_angles.svg"), &plots, 2)?;
    names.push("fig14_15_rebound_angles.svg".to_string());

    // Figs. 16–17: mean and std of β⁺ − β⁻ against β⁻ (one curve per α⁻) and against |α⁻|
    // (one curve per β⁻), when the case sweeps them.
    let mut alphas: Vec<f64> = results.iter().map(|r| r.condition.alpha_in_deg()).collect();
    let mut betas: Vec<f64> = results.iter().map(|r| r.condition.beta_in_deg()).collect();
    for v in [&mut alphas, &mut betas] {
        v.sort_by(|a, b| a.total_cmp(b));
        v.dedup();
    }
    let sweep = |along_beta: bool| -> Vec<Plot> {
        let (keys, xl) = if along_beta {
            (&alphas, "β⁻ (deg)")
        } else {
            (&betas, "|α⁻| (deg)")
        };
        let mut mean = Vec::new();
        let mut std = Vec::new();
        for &k in keys {
            let pts: Vec<(f64, f64, f64)> = results
                .iter()
                .filter(|r| {
                    if along_beta {
                        r.condition.alpha_in_deg() == k
                    } else {
                        r.condition.beta_in_deg() == k
                    }
                })
                .filter_map(|r| {
                    let x = if along_beta {
                        r.condition.beta_in_deg()
                    } else {
                        -r.condition.alpha_in_deg()
                    };
                    r.stat("dbeta").map(|(m, s)| (x, m, s))
                })
                .collect();
            let key = if along_beta { "α⁻" } else { "β⁻" };
            if let Some((m, sd)) = sweep_series(label, key, k, pts, Kind::Line) {
                mean.push(m);
                std.push(sd);
            }
        }
        if mean.is_empty() {
            return Vec::new();
        }
        sweep_plots(mean, std, xl).to_vec()
    };
    for (along_beta, name) in [
        (true, "fig16_dbeta_vs_beta_in.svg"),
        (false, "fig17_dbeta_vs_alpha_in.svg"),
    ] {
        let plots = sweep(along_beta);
        if !plots.is_empty() {
            plot_grid_svg(&dir.join(name), &plots, 2)?;
            names.push(name.to_string());
        }
    }
    Ok(names)
}
