//! The overlay figures of `rebound compare`: the PDFs of two runs in one panel per matched
//! condition (Radenkovic & Simonin 2021, Figs. 10–11, 14–15 with "DS" against "SM"), and the
//! mean/std of `β⁺ − β⁻` of both against the incident angles (Figs. 16–17).

use super::{
    bin_centres, plot_grid_svg, sweep_plots, sweep_series, title, Kind, Plot, Series, SweepPoint,
};
use crate::compare::RunOutputs;
use roughwall::Result;
use std::path::Path;

/// Quantities drawn as overlay figures (when present in both runs).
const OVERLAYS: [(&str, &str); 7] = [
    ("alpha_out", "α⁺ (deg)"),
    ("alpha_out_xy", "α⁺_xy (deg)"),
    ("dbeta", "β⁺ − β⁻ (deg)"),
    ("gamma_first", "γ (deg)"),
    ("gamma_star_first", "γ* (deg)"),
    ("xi_first", "ξ − 90° (deg)"),
    ("zeta_first", "ζ − 90° (deg)"),
];

/// Overlay figures (labels `label_a`, `label_b`, e.g. "DS" and "SM"): one file per
/// quantity with a panel per matched condition, and the mean/std of β⁺ − β⁻ against β⁻
/// and |α⁻| (Figs. 16–17) when the runs sweep them. Returns the file names.
pub fn write(
    dir: &Path,
    a: &RunOutputs,
    b: &RunOutputs,
    label_a: &str,
    label_b: &str,
) -> Result<Vec<String>> {
    let mut names = Vec::new();
    let matched: Vec<&(String, String, f64, f64)> = a
        .conditions
        .iter()
        .filter(|c| b.conditions.iter().any(|d| d.0 == c.0 && d.1 == c.1))
        .collect();
    for (q, xl) in OVERLAYS {
        let mut plots = Vec::new();
        for c in &matched {
            let key = (c.0.clone(), c.1.clone());
            let find = |r: &RunOutputs| {
                r.pdfs
                    .get(&key)
                    .and_then(|l| l.iter().find(|e| e.0 == q).map(|e| e.1.clone()))
            };
            if let (Some(pa), Some(pb)) = (find(a), find(b)) {
                plots.push(Plot {
                    title: title(&c.0, &c.1),
                    x_label: xl.into(),
                    y_label: "PDF (1/deg)".into(),
                    series: vec![
                        Series::new(label_a, bin_centres(pa.bins.iter().copied()), Kind::Step),
                        Series::new(label_b, bin_centres(pb.bins.iter().copied()), Kind::Dashed),
                    ],
                    ..Default::default()
                });
            }
        }
        if !plots.is_empty() {
            let name = format!("overlay_{q}.svg");
            let cols = plots.len().clamp(1, 3);
            plot_grid_svg(&dir.join(&name), &plots, cols)?;
            names.push(name);
        }
    }
    // Figs. 16–17: E(β⁺ − β⁻) and Δβ⁺ of both runs.
    for (along_beta, name) in [
        (true, "overlay_fig16_dbeta_vs_beta_in.svg"),
        (false, "overlay_fig17_dbeta_vs_alpha_in.svg"),
    ] {
        let mut keys: Vec<f64> = matched
            .iter()
            .map(|c| if along_beta { c.2 } else { c.3 })
            .collect();
        keys.sort_by(|x, y| x.total_cmp(y));
        keys.dedup();
        let mut mean = Vec::new();
        let mut std = Vec::new();
        for k in keys {
            for (r, label, kind) in [(a, label_a, Kind::Line), (b, label_b, Kind::Dashed)] {
                let pts: Vec<SweepPoint> = matched
                    .iter()
                    .filter(|c| (if along_beta { c.2 } else { c.3 }) == k)
                    .filter_map(|c| {
                        r.dbeta(&(c.0.clone(), c.1.clone()))
                            .map(|(mean, std, se)| SweepPoint {
                                x: if along_beta { c.3 } else { -c.2 },
                                mean,
                                std,
                                se,
                            })
                    })
                    .collect();
                let key = if along_beta { "α⁻" } else { "β⁻" };
                if let Some((m, sd)) = sweep_series(label, key, k, pts, kind) {
                    mean.push(m);
                    std.push(sd);
                }
            }
        }
        if mean.is_empty() {
            continue;
        }
        let xl = if along_beta {
            "β⁻ (deg)"
        } else {
            "|α⁻| (deg)"
        };
        plot_grid_svg(&dir.join(name), &sweep_plots(mean, std, xl), 2)?;
        names.push(name.to_string());
    }
    Ok(names)
}
