//! The figures of `rebound pipe-stats`, one set per particle diameter: concentration
//! profiles along the two diameters and in slabs (`concentration_<d>um.svg`), velocity profiles (`velocity_<d>um.svg`) and the
//! wall hits (`wall_hits_<d>um.svg`: impact-angle and lay-angle PDFs, erosion around the
//! circumference). Every point carries its standard error as an error bar.

use super::plot::{plot_grid_svg, Kind, Plot, Series};
use crate::pipe_flow::read::is_smooth_limit;
use crate::pipe_flow::stats::{angle_pdf, erosion_profile, profile, Profile, ProfilePoint};
use crate::pipe_flow::tables::Analysed;
use roughwall::Result;
use std::path::Path;

/// The walls in drawing order, with their colours and labels.
const WALLS: [(&str, usize, &str); 5] = [
    ("smooth", 0, "smooth"),
    ("ts1", 5, "technically smooth, Δγ = 1°"),
    ("iso", 1, "isotropic"),
    ("axial", 2, "lay along the axis"),
    ("circ", 3, "lay around the circumference"),
];

/// The study's main runs of diameter `d` and model `model` (the smooth and technically smooth
/// walls whatever the model), in [`WALLS`] order, with colour and label; with `model` "paper" also the
/// isotropic wall under Sommerfeld–Huber 1999.
fn runs_of<'a>(
    runs: &'a [Analysed<'a>],
    d: f64,
    model: &str,
) -> Vec<(&'a Analysed<'a>, usize, String)> {
    let mut out = Vec::new();
    for (wall, colour, label) in WALLS {
        let m = if is_smooth_limit(wall) {
            "paper"
        } else {
            model
        };
        if let Some(a) = runs.iter().find(|a| {
            let i = &a.run.info;
            i.kind == "main" && i.diameter_um == d && i.wall == wall && i.model == m
        }) {
            out.push((a, colour, label.to_string()));
        }
    }
    if model == "paper" {
        if let Some(a) = runs.iter().find(|a| {
            let i = &a.run.info;
            i.kind == "main" && i.diameter_um == d && i.wall == "iso" && i.model == "sh1999"
        }) {
            out.push((a, 4, "isotropic, Sommerfeld–Huber 1999".into()));
        }
    }
    out
}

fn model_title(model: &str) -> &'static str {
    match model {
        "paper" => "Radenkovic–Simonin model",
        _ => "calibrated model",
    }
}

/// A series of profile points: `pick` gives the estimate of a point, if any.
fn profile_series(
    label: &str,
    colour: usize,
    points: &[ProfilePoint],
    pick: impl Fn(&ProfilePoint) -> Option<crate::pipe_flow::jackknife::Estimate>,
) -> Series {
    let (pts, err): (Vec<(f64, f64)>, Vec<f64>) = points
        .iter()
        .filter_map(|p| {
            pick(p)
                .filter(|e| e.value.is_finite())
                .map(|e| ((p.position_over_r, e.value), e.se))
        })
        .unzip();
    Series::new(label, pts, Kind::Line)
        .with_color(colour)
        .with_err(err)
}

/// Writes the figures into `dir`; returns their file names.
pub fn write(dir: &Path, runs: &[Analysed]) -> Result<Vec<String>> {
    let mut diameters: Vec<f64> = runs.iter().map(|a| a.run.info.diameter_um).collect();
    diameters.sort_by(f64::total_cmp);
    diameters.dedup();
    let mut names = Vec::new();
    for d in diameters {
        let tag = format!("{}um", roughwall::format::fmt_num(d));
        // Concentration along the vertical and horizontal diameters and in slabs across the
        // section, both models.
        let mut plots = Vec::new();
        for kind in [
            Profile::VerticalDiameter,
            Profile::HorizontalDiameter,
            Profile::VerticalSlabs,
        ] {
            // The smooth wall's bed on the bottom is 50–80 times the mean: the vertical
            // profiles need a log axis to show the others, which leaves out the bins known to
            // less than a third of their value (empty, or a few samples).
            let log = kind != Profile::HorizontalDiameter;
            for model in ["paper", "calibrated"] {
                let series = runs_of(runs, d, model)
                    .into_iter()
                    .map(|(a, c, label)| {
                        profile_series(&label, c, &profile(&a.sums, &a.section(), kind), |p| {
                            Some(p.concentration).filter(|e| !log || e.value > 3.0 * e.se)
                        })
                    })
                    .collect();
                let (what, x_label) = match kind {
                    Profile::VerticalDiameter => ("along the vertical diameter", "y/R (up)"),
                    Profile::HorizontalDiameter => ("along the horizontal diameter", "z/R"),
                    _ => ("in horizontal slabs", "y/R (up)"),
                };
                plots.push(Plot {
                    title: format!("{d} µm, {}, {what}", model_title(model)),
                    x_label: x_label.into(),
                    y_label: "concentration / mean".into(),
                    series,
                    log_y: log,
                    ..Default::default()
                });
            }
        }
        let name = format!("concentration_{tag}.svg");
        plot_grid_svg(&dir.join(&name), &plots, 2)?;
        names.push(name);

        // Velocity profiles (vertical), the paper's model.
        type Pick = fn(&ProfilePoint) -> Option<crate::pipe_flow::jackknife::Estimate>;
        let panels: [(&str, &str, Pick); 3] = [
            ("mean axial velocity", "u_x (m/s)", |p| p.ux_mean),
            ("rms axial velocity", "u_x rms (m/s)", |p| p.ux_rms),
            ("rms wall-normal velocity", "u_r rms (m/s)", |p| p.ur_rms),
        ];
        let chosen = runs_of(runs, d, "paper");
        let profiles: Vec<Vec<ProfilePoint>> = chosen
            .iter()
            .map(|(a, _, _)| profile(&a.sums, &a.section(), Profile::VerticalSlabs))
            .collect();
        let plots: Vec<Plot> = panels
            .iter()
            .map(|(title, y_label, pick)| Plot {
                title: format!("{d} µm, {title}"),
                x_label: "y/R (up)".into(),
                y_label: (*y_label).into(),
                series: chosen
                    .iter()
                    .zip(&profiles)
                    .map(|((_, c, label), pts)| profile_series(label, *c, pts, pick))
                    .collect(),
                ..Default::default()
            })
            .collect();
        let name = format!("velocity_{tag}.svg");
        plot_grid_svg(&dir.join(&name), &plots, 3)?;
        names.push(name);

        // Wall hits: impact angle, lay angle, erosion (the paper's model).
        let dist = |bins: Vec<crate::pipe_flow::stats::DistBin>| {
            bins.into_iter()
                .filter(|b| b.value.value.is_finite())
                .map(|b| ((0.5 * (b.lo + b.hi), b.value.value), b.value.se))
                .unzip::<_, _, Vec<_>, Vec<_>>()
        };
        let mut hit_plots = vec![
            Plot {
                title: format!("{d} µm, impact angle"),
                x_label: "α⁻ (deg)".into(),
                y_label: "PDF (1/deg)".into(),
                x_range: Some((0.0, 30.0)),
                ..Default::default()
            },
            Plot {
                title: format!("{d} µm, angle of the incident plane to the lay"),
                x_label: "angle (deg)".into(),
                y_label: "PDF (1/deg)".into(),
                ..Default::default()
            },
            Plot {
                title: format!("{d} µm, Finnie erosion around the wall (at the facet struck)"),
                x_label: "angle from the bottom (deg)".into(),
                y_label: "µm per tonne conveyed".into(),
                ..Default::default()
            },
        ];
        for (a, c, label) in &chosen {
            let sets = [
                angle_pdf(&a.sums, false),
                angle_pdf(&a.sums, true),
                erosion_profile(&a.sums, 0.5 * a.run.params.pipe_diameter_m, 0),
            ];
            for (plot, bins) in hit_plots.iter_mut().zip(sets) {
                let (pts, err) = dist(bins);
                plot.series.push(
                    Series::new(label.clone(), pts, Kind::Step)
                        .with_color(*c)
                        .with_err(err),
                );
            }
        }
        let name = format!("wall_hits_{tag}.svg");
        plot_grid_svg(&dir.join(&name), &hit_plots, 3)?;
        names.push(name);
    }
    Ok(names)
}
