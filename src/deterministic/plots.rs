//! The deterministic run's figures: analogues of Radenkovic & Simonin 2021,
//! Figs. 6, 7 (first and final rebound), 8, 9, 12 and, for β⁻ sweeps, Fig. 16.
//! Panels are laid out with one row per `α⁻` and one column per `β⁻`.

use crate::error::Result;
use crate::figures::{plot_grid_svg, Kind, Plot, Series};
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

/// Writes every figure into `dir`; returns the file names.
pub fn write_figures(dir: &Path, results: &[ConditionResult], label: &str) -> Result<Vec<String>> {
    let mut names = Vec::new();
    let mut put = |name: &str, r: Result<()>| -> Result<()> {
        r?;
        names.push(name.to_string());
        Ok(())
    };
    put(
        "fig06_alpha_out.svg",
        grid(
            &dir.join("fig06_alpha_out.svg"),
            results,
            "α⁺ (deg)",
            "PDF (1/deg)",
            &[("alpha_out", label, Kind::Step)],
        ),
    )?;
    put(
        "fig07_dbeta.svg",
        grid(
            &dir.join("fig07_dbeta.svg"),
            results,
            "β⁺ − β⁻ (deg)",
            "PDF (1/deg)",
            &[
                ("dbeta_first", "first rebound (1C)", Kind::Dashed),
                ("dbeta", "final rebound (MC)", Kind::Step),
            ],
        ),
    )?;
    put(
        "fig08_xi_first.svg",
        grid(
            &dir.join("fig08_xi_first.svg"),
            results,
            "ξ − 90° (deg)",
            "PDF (1/deg)",
            &[("xi_first", label, Kind::Step)],
        ),
    )?;
    put(
        "fig09_zeta_first.svg",
        grid(
            &dir.join("fig09_zeta_first.svg"),
            results,
            "ζ − 90° (deg)",
            "PDF (1/deg)",
            &[("zeta_first", label, Kind::Step)],
        ),
    )?;
    put(
        "fig12_p_single.svg",
        grid(
            &dir.join("fig12_p_single.svg"),
            results,
            "α⁺ (deg)",
            "P(n = 1 | α⁺)",
            &[
                ("p_single_given_alpha_out", label, Kind::Markers),
                (
                    "p_single_model",
                    "tanh(2 α⁺/Δγ(β⁺)), Eqs. 34–35",
                    Kind::Line,
                ),
            ],
        ),
    )?;
    // Fig. 16: mean and std of β⁺ − β⁻ against β⁻, one series per α⁻.
    if columns(results) >= 3 {
        let mut alphas: Vec<f64> = Vec::new();
        for r in results {
            if !alphas.contains(&r.condition.alpha_in) {
                alphas.push(r.condition.alpha_in);
            }
        }
        let series = |k: usize| -> Vec<Series> {
            alphas
                .iter()
                .map(|&a| {
                    let pts = results
                        .iter()
                        .filter(|r| r.condition.alpha_in == a)
                        .filter_map(|r| {
                            r.stat("dbeta").map(|(m, s)| {
                                (r.condition.beta_in_deg(), if k == 0 { m } else { s })
                            })
                        })
                        .collect();
                    Series::new(
                        format!("α⁻ = {}°", crate::output::fmt_num(a.to_degrees())),
                        pts,
                        Kind::Line,
                    )
                })
                .collect()
        };
        let plots = vec![
            Plot {
                title: "mean transverse deviation".into(),
                x_label: "β⁻ (deg)".into(),
                y_label: "E(β⁺ − β⁻) (deg)".into(),
                series: series(0),
                ..Default::default()
            },
            Plot {
                title: "std of the transverse deviation".into(),
                x_label: "β⁻ (deg)".into(),
                y_label: "Δβ⁺ (deg)".into(),
                series: series(1),
                ..Default::default()
            },
        ];
        put(
            "fig16_dbeta_vs_beta.svg",
            plot_grid_svg(&dir.join("fig16_dbeta_vs_beta.svg"), &plots, 2),
        )?;
    }
    // Fig. 17: mean and std of β⁺ − β⁻ against |α⁻|, one series per β⁻.
    let mut betas: Vec<f64> = Vec::new();
    for r in results {
        if !betas.contains(&r.condition.beta_in) {
            betas.push(r.condition.beta_in);
        }
    }
    if results.len() >= 5 * betas.len() {
        let series = |k: usize| -> Vec<Series> {
            betas
                .iter()
                .map(|&b| {
                    let pts = results
                        .iter()
                        .filter(|r| r.condition.beta_in == b)
                        .filter_map(|r| {
                            r.stat("dbeta").map(|(m, s)| {
                                (-r.condition.alpha_in_deg(), if k == 0 { m } else { s })
                            })
                        })
                        .collect();
                    Series::new(
                        format!("β⁻ = {}°", crate::output::fmt_num(b.to_degrees())),
                        pts,
                        Kind::Line,
                    )
                })
                .collect()
        };
        let plots = vec![
            Plot {
                title: "mean transverse deviation".into(),
                x_label: "|α⁻| (deg)".into(),
                y_label: "E(β⁺ − β⁻) (deg)".into(),
                series: series(0),
                ..Default::default()
            },
            Plot {
                title: "std of the transverse deviation".into(),
                x_label: "|α⁻| (deg)".into(),
                y_label: "Δβ⁺ (deg)".into(),
                series: series(1),
                ..Default::default()
            },
        ];
        put(
            "fig17_dbeta_vs_alpha.svg",
            plot_grid_svg(&dir.join("fig17_dbeta_vs_alpha.svg"), &plots, 2),
        )?;
    }
    Ok(names)
}
