//! SVG figures of a stochastic run: analogues of Radenkovic & Simonin 2021, Figs. 10, 11,
//! the α⁺ and β⁺ − β⁻ panels of Figs. 14–15, and the mean/std of β⁺ − β⁻ against the
//! incident angles (Figs. 16–17).

use super::{bins_to_points, condition_title, dbeta_sweeps, plot_grid_svg, Kind, Plot, Series};
use roughwall::tally::{ConditionResult, Quantity};
use roughwall::wall::{conditional_gamma_star, rotated_moments};
use roughwall::Deviations;
use roughwall::Result;
use std::path::Path;

fn cols(n: usize) -> usize {
    n.clamp(1, 3)
}

/// Fewest particles in a Fig. 11 slice worth a histogram.
const MIN_SLICE: f64 = 50.0;

/// Writes the figures into `dir`; returns their file names.
pub fn write(
    dir: &Path,
    results: &[ConditionResult],
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
            if let Some(b) = r.pdf(Quantity::GammaFirst) {
                series.push(Series::new(label, bins_to_points(b), Kind::Step));
            }
            if let Some(b) = r.pdf(Quantity::GammaModel) {
                series.push(Series::new(
                    "ES, Eqs. (31)–(33)",
                    bins_to_points(b),
                    Kind::Line,
                ));
            }
            Plot {
                title: condition_title(&r.condition()),
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
        .map(|r| {
            let m = rotated_moments(wall, r.condition().beta_in);
            let dg = m.delta_gamma();
            let mut series = Vec::new();
            for (q, g0, name) in [
                (Quantity::GammaStarGivenGamma0, 0.0, "γ ≈ 0"),
                (Quantity::GammaStarGivenGammaDg, dg, "γ ≈ Δγ"),
            ] {
                let n = r.estimate(q).map_or(0.0, |e| e.n as f64);
                let Some(bins) = r.pdf(q).filter(|_| n >= MIN_SLICE) else {
                    continue;
                };
                series.push(Series::new(
                    format!("{label}, {name}"),
                    bins_to_points(bins),
                    Kind::Step,
                ));
                let (mean, var) = conditional_gamma_star(&m, g0);
                let sd = var.max(0.0).sqrt().to_degrees();
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
                title: condition_title(&r.condition()),
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
        let (q, xl) = if r.condition().beta_in == 0.0 {
            (Quantity::AlphaOutXy, "α⁺_xy (deg)")
        } else {
            (Quantity::AlphaOut, "α⁺ (deg)")
        };
        for (q, xl) in [(q, xl), (Quantity::Dbeta, "β⁺ − β⁻ (deg)")] {
            let series = r
                .pdf(q)
                .map(|b| vec![Series::new(label, bins_to_points(b), Kind::Step)])
                .unwrap_or_default();
            plots.push(Plot {
                title: condition_title(&r.condition()),
                x_label: xl.into(),
                y_label: "PDF (1/deg)".into(),
                series,
                ..Default::default()
            });
        }
    }
    plot_grid_svg(&dir.join("fig14_15_rebound_angles.svg"), &plots, 2)?;
    names.push("fig14_15_rebound_angles.svg".to_string());

    // Figs. 16–17, when the case sweeps β⁻ or α⁻.
    names.extend(dbeta_sweeps(
        dir,
        results,
        label,
        2,
        ["fig16_dbeta_vs_beta_in.svg", "fig17_dbeta_vs_alpha_in.svg"],
    )?);
    Ok(names)
}
