//! The figures of `rebound force-sweep` (Hu et al. 2021):
//!
//! * `fmax_vs_beta.svg` (Fig. 6) and `xi_vs_beta.svg` (Fig. 9) when β varies: one line per
//!   model and λ at the sweep's first positive U_N and first D;
//! * `fmax_vs_un.svg` (Figs. 8, 10–12; log–log) when U_N varies: one panel per (λ, β), at most
//!   12, every model in each;
//! * always `sphere_check.svg` (Fig. 4): the ODE of Eq. (1) against Eq. (3) for a sphere.

use super::{plot_grid_svg, plot_svg, Kind, Plot, Series};
use crate::output::fmt_num;
use roughwall::force::{hertz_dynamic, hertz_sphere, Impact, Model, Particle};
use roughwall::force::{Row, Sweep};
use roughwall::Result;
use std::path::Path;

/// A force unit for axis labels so that `max` reads between 1 and 1000: (factor from N, name).
fn force_unit(max: f64) -> (f64, &'static str) {
    const UNITS: [(f64, &str); 6] = [
        (1.0, "N"),
        (1e3, "mN"),
        (1e6, "µN"),
        (1e9, "nN"),
        (1e12, "pN"),
        (1e15, "fN"),
    ];
    UNITS
        .iter()
        .copied()
        .find(|&(f, _)| max * f >= 1.0)
        .unwrap_or(UNITS[5])
}

/// The largest peak force of `rows` (N).
fn max_force<'a>(rows: impl Iterator<Item = &'a Row>) -> f64 {
    rows.map(|r| r.result.f_max).fold(0.0, f64::max)
}

/// How a model's curve is drawn: Hu et al.'s fit as markers, the ODE dashed, Hertz as lines.
fn style(m: Model) -> Kind {
    match m {
        Model::Hu2021 => Kind::Markers,
        Model::HertzDynamic => Kind::Dashed,
        Model::HertzRigid | Model::HertzSphere => Kind::Line,
    }
}

/// The values in first-seen order, each once (`==`: 0 and −0 are one value; the sweep's
/// values are finite). A set, not a scan of the output: a sweep may list 10⁵ speeds.
fn distinct(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut seen = std::collections::HashSet::new();
    values
        .filter(|v| seen.insert((v + 0.0).to_bits()))
        .collect()
}

/// Most speeds the sphere check simulates: it is a figure, and each point is an ODE
/// integration (~25 µs); a longer sweep is thinned to this many, evenly through its sorted
/// speeds.
const SPHERE_CHECK_POINTS: usize = 400;

/// `us` if it has at most `SPHERE_CHECK_POINTS` values, else that many of them, evenly
/// through their sorted order, the smallest and the largest included.
fn thinned(mut us: Vec<f64>) -> Vec<f64> {
    if us.len() <= SPHERE_CHECK_POINTS {
        return us;
    }
    us.sort_by(f64::total_cmp);
    let last = us.len() - 1;
    (0..SPHERE_CHECK_POINTS)
        .map(|k| us[k * last / (SPHERE_CHECK_POINTS - 1)])
        .collect()
}

/// Writes the figures of a sweep into `dir` (see the module documentation); `name` (the
/// case's) heads every title, `material` is the particle of `sphere_check`.
pub fn write(
    dir: &Path,
    name: &str,
    rows: &[Row],
    sweep: &Sweep,
    material: &Particle,
) -> Result<()> {
    let d0 = sweep.diameters[0];
    let u_fig = sweep
        .u_ns
        .iter()
        .copied()
        .find(|&u| u > 0.0)
        .unwrap_or(sweep.u_ns[0]);
    let betas = distinct(sweep.betas_deg.iter().copied());
    let us = distinct(sweep.u_ns.iter().copied());
    let lambdas = distinct(sweep.lambdas.iter().copied());
    let mut model_list: Vec<Model> = Vec::new();
    for &m in &sweep.models {
        if !model_list.contains(&m) {
            model_list.push(m);
        }
    }

    if betas.len() > 1 {
        let (fu, unit) = force_unit(max_force(
            rows.iter()
                .filter(|r| r.u_n == u_fig && r.particle.diameter == d0),
        ));
        let f_label = format!("F_max ({unit})");
        for (file, ylabel, pick) in [
            ("fmax_vs_beta.svg", f_label.as_str(), 0),
            ("xi_vs_beta.svg", "ξ = F_max / (ρ^0.6 U_N^1.2 D² E*^0.4)", 1),
        ] {
            let mut series = Vec::new();
            for &m in &model_list {
                for &l in &lambdas {
                    let pts: Vec<(f64, f64)> = rows
                        .iter()
                        .filter(|r| {
                            r.model == m
                                && r.lambda == l
                                && r.u_n == u_fig
                                && r.particle.diameter == d0
                        })
                        .map(|r| {
                            (
                                r.beta_deg,
                                if pick == 0 {
                                    r.result.f_max * fu
                                } else {
                                    r.result.xi
                                },
                            )
                        })
                        .collect();
                    series.push(Series::new(format!("{} λ={}", m.name(), l), pts, style(m)));
                }
            }
            let what = if pick == 0 { "Fig. 6" } else { "Fig. 9" };
            plot_svg(
                &dir.join(file),
                &Plot {
                    title: format!(
                        "{name}: {what} analogue (U_N = {} m/s, D = {} µm)",
                        fmt_num(u_fig),
                        fmt_num(d0 * 1e6)
                    ),
                    x_label: "β (deg)".into(),
                    y_label: ylabel.into(),
                    series,
                    x_range: Some((0.0, 90.0)),
                    ..Plot::default()
                },
            )?;
        }
    }

    if us.iter().filter(|&&u| u > 0.0).count() > 1 {
        // One panel per (λ, β) (at most 12), every model in each: Figs. 8, 10–12.
        let (fu, unit) = force_unit(max_force(rows.iter().filter(|r| r.particle.diameter == d0)));
        let mut panels = Vec::new();
        for &l in &lambdas {
            for &b in &betas {
                if panels.len() == 12 {
                    break;
                }
                let series = model_list
                    .iter()
                    .map(|&m| {
                        let pts: Vec<(f64, f64)> = rows
                            .iter()
                            .filter(|r| {
                                r.model == m
                                    && r.lambda == l
                                    && r.beta_deg == b
                                    && r.particle.diameter == d0
                                    && r.u_n > 0.0
                            })
                            .map(|r| (r.u_n, r.result.f_max * fu))
                            .collect();
                        Series::new(m.name(), pts, style(m))
                    })
                    .collect();
                panels.push(Plot {
                    title: format!("{name}: λ = {l}, β = {b}°, D = {} µm", fmt_num(d0 * 1e6)),
                    x_label: "U_N (m/s)".into(),
                    y_label: format!("F_max ({unit})"),
                    series,
                    log_x: true,
                    log_y: true,
                    ..Plot::default()
                });
            }
        }
        let cols = panels.len().min(3);
        plot_grid_svg(&dir.join("fmax_vs_un.svg"), &panels, cols)?;
    }

    sphere_check(dir, name, sweep, material)
}

/// Fig. 4 analogue: the ODE of Eq. (1) (`hertz-dynamic`, λ = 1) against Eq. (3), over the
/// sweep's U_N (or 0.01–20 m/s if it has fewer than two), for each D of the sweep.
fn sphere_check(dir: &Path, name: &str, sweep: &Sweep, material: &Particle) -> Result<()> {
    let mut us: Vec<f64> = thinned(distinct(sweep.u_ns.iter().copied().filter(|&u| u > 0.0)));
    if us.len() < 2 {
        us = (0..12)
            .map(|i| 10f64.powf(-2.0 + 3.30103 * i as f64 / 11.0))
            .collect();
    }
    let mut series = Vec::new();
    let mut worst: f64 = 0.0;
    for &d in &distinct(sweep.diameters.iter().copied()) {
        let p = Particle {
            diameter: d,
            ..*material
        };
        let mut eq3 = Vec::new();
        let mut ode = Vec::new();
        for &u in &us {
            let imp = Impact::from_deg(1.0, 0.0, u)?;
            let a = hertz_sphere::evaluate(&p, u).f_max;
            let b = hertz_dynamic::evaluate(&p, &imp, &hertz_dynamic::Options::default()).f_max;
            worst = worst.max((b / a - 1.0).abs());
            eq3.push((u, a));
            ode.push((u, b));
        }
        let dl = fmt_num(d * 1e6);
        series.push(Series::new(
            format!("Eq. (3), D = {dl} µm"),
            eq3,
            Kind::Line,
        ));
        series.push(Series::new(
            format!("ODE of Eq. (1), D = {dl} µm"),
            ode,
            Kind::Markers,
        ));
    }
    let max = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(0.0, f64::max);
    let (fu, unit) = force_unit(max);
    for s in &mut series {
        for p in &mut s.points {
            p.1 *= fu;
        }
    }
    plot_svg(
        &dir.join("sphere_check.svg"),
        &Plot {
            title: format!(
                "{name}: Fig. 4 analogue, sphere (max rel. diff {:.1e})",
                worst
            ),
            x_label: "U_N (m/s)".into(),
            y_label: format!("F_max ({unit})"),
            series,
            log_x: true,
            log_y: true,
            ..Plot::default()
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distinct_keeps_first_seen_order_and_merges_signed_zeros() {
        let v = distinct([3.0, 1.0, 3.0, -0.0, 0.0, 2.0, 1.0].into_iter());
        assert_eq!(v.len(), 4);
        assert_eq!(v[..2], [3.0, 1.0]);
        assert!(v[2] == 0.0 && v[2].is_sign_negative());
        assert_eq!(v[3], 2.0);
    }

    #[test]
    fn the_sphere_check_thins_long_sweeps_only() {
        let short: Vec<f64> = (1..=SPHERE_CHECK_POINTS).rev().map(|i| i as f64).collect();
        assert_eq!(thinned(short.clone()), short);
        let long: Vec<f64> = (0..100_000).rev().map(|i| 1e-3 * (i + 1) as f64).collect();
        let t = thinned(long);
        assert_eq!(t.len(), SPHERE_CHECK_POINTS);
        assert_eq!(t[0], 1e-3);
        assert_eq!(*t.last().unwrap(), 100.0);
        assert!(t.windows(2).all(|w| w[0] < w[1]));
    }
}
