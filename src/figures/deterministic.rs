//! The deterministic run's figures: analogues of Radenkovic & Simonin 2021,
//! Figs. 6, 7 (first and final rebound), 8, 9, 12 and, for β⁻ sweeps, Fig. 16.
//! Panels are laid out with one row per `α⁻` and one column per `β⁻`.

use super::{bins_to_points, condition_title, dbeta_sweeps, plot_grid_svg, Kind, Plot, Series};
use roughwall::tally::{ConditionResult, Quantity};
use roughwall::Result;
use std::path::Path;

/// Number of distinct `β⁻` (the grid's column count).
fn columns(results: &[ConditionResult]) -> usize {
    let mut betas: Vec<f64> = Vec::new();
    for r in results {
        if !betas.contains(&r.condition().beta_in) {
            betas.push(r.condition().beta_in);
        }
    }
    betas.len().max(1)
}

fn grid(
    path: &Path,
    results: &[ConditionResult],
    x_label: &str,
    y_label: &str,
    series: &[(Quantity, &str, Kind)],
) -> Result<()> {
    let plots: Vec<Plot> = results
        .iter()
        .map(|r| Plot {
            title: condition_title(&r.condition()),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: series
                .iter()
                .filter_map(|(q, label, kind)| {
                    r.pdf(*q).map(|b| {
                        let s = Series::new(*label, bins_to_points(b), *kind);
                        // Fractions carry ±2 standard errors (Fig. 12).
                        if *kind == Kind::Markers {
                            s.with_err(b.iter().map(|b| 2.0 * b.se.unwrap_or(0.0)).collect())
                        } else {
                            s
                        }
                    })
                })
                .collect(),
            ..Default::default()
        })
        .collect();
    plot_grid_svg(path, &plots, columns(results))
}

/// One figure: file name, axis labels and the `(quantity, legend, kind)` series of each panel.
type Panel<'a> = (&'a str, &'a str, &'a str, Vec<(Quantity, &'a str, Kind)>);

/// Writes every figure into `dir`; returns the file names.
pub fn write(dir: &Path, results: &[ConditionResult], label: &str) -> Result<Vec<String>> {
    const PDF: &str = "PDF (1/deg)";
    let panels: [Panel; 5] = [
        (
            "fig06_alpha_out.svg",
            "α⁺ (deg)",
            PDF,
            vec![(Quantity::AlphaOut, label, Kind::Step)],
        ),
        (
            "fig07_dbeta.svg",
            "β⁺ − β⁻ (deg)",
            PDF,
            vec![
                (Quantity::DbetaFirst, "first rebound (1C)", Kind::Dashed),
                (Quantity::Dbeta, "final rebound (MC)", Kind::Step),
            ],
        ),
        (
            "fig08_xi_first.svg",
            "ξ − 90° (deg)",
            PDF,
            vec![(Quantity::XiFirst, label, Kind::Step)],
        ),
        (
            "fig09_zeta_first.svg",
            "ζ − 90° (deg)",
            PDF,
            vec![(Quantity::ZetaFirst, label, Kind::Step)],
        ),
        (
            "fig12_p_single.svg",
            "α⁺ (deg)",
            "P(n = 1 | α⁺)",
            vec![
                (Quantity::PSingleGivenAlphaFirst, label, Kind::Markers),
                (
                    Quantity::PSingleModel,
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
    // Figs. 16–17: mean and std of β⁺ − β⁻ against β⁻ (one line per α⁻) or |α⁻| (one per β⁻);
    // a sweep needs at least three points to be worth a figure.
    names.extend(dbeta_sweeps(
        dir,
        results,
        label,
        3,
        ["fig16_dbeta_vs_beta.svg", "fig17_dbeta_vs_alpha.svg"],
    )?);
    Ok(names)
}
