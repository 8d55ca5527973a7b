//! The mean and std of `β⁺ − β⁻` against the incident angles (Radenkovic & Simonin 2021,
//! Figs. 16–17), shared by the figures of `deterministic`, `stochastic` and `compare`.

use super::{plot_grid_svg, Kind, Plot, Series};
use roughwall::Result;
use std::path::Path;

/// One point of a sweep curve: the swept angle, the mean and std of `β⁺ − β⁻` there, and the
/// standard error of the mean when known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepPoint {
    pub x: f64,
    pub mean: f64,
    pub std: Option<f64>,
    pub se: Option<f64>,
}

/// The mean and std curves of one line of a sweep (Radenkovic & Simonin 2021, Figs. 16–17):
/// `pts` for the conditions where the swept key (`α⁻` or `β⁻`, named by `key`) equals `k`.
/// The mean carries ±2 standard errors as error bars. `None` when fewer than two points make
/// no curve.
pub fn sweep_series(
    label: &str,
    key: &str,
    k: f64,
    mut pts: Vec<SweepPoint>,
    kind: Kind,
) -> Option<(Series, Series)> {
    if pts.len() < 2 {
        return None;
    }
    pts.sort_by(|a, b| a.x.total_cmp(&b.x));
    let name = format!("{label}, {key} = {k}°");
    let err: Vec<f64> = pts.iter().map(|p| 2.0 * p.se.unwrap_or(f64::NAN)).collect();
    let mean = Series::new(
        name.clone(),
        pts.iter().map(|p| (p.x, p.mean)).collect(),
        kind,
    );
    Some((
        if err.iter().any(|e| e.is_finite()) {
            mean.with_err(err)
        } else {
            mean
        },
        Series::new(
            name,
            pts.iter().filter_map(|p| Some((p.x, p.std?))).collect(),
            kind,
        ),
    ))
}

/// The two panels of Figs. 16–17: mean and std of `β⁺ − β⁻` against the swept angle.
pub fn sweep_plots(mean: Vec<Series>, std: Vec<Series>, x_label: &str) -> [Plot; 2] {
    [
        Plot {
            title: "mean transverse deviation".into(),
            x_label: x_label.into(),
            y_label: "E(β⁺ − β⁻) ± 2 SE (deg)".into(),
            series: mean,
            ..Default::default()
        },
        Plot {
            title: "std of the transverse deviation".into(),
            x_label: x_label.into(),
            y_label: "Δβ⁺ (deg)".into(),
            series: std,
            ..Default::default()
        },
    ]
}

/// Figs. 16–17 of a run (Radenkovic & Simonin 2021): mean (± 2 SE) and std of `β⁺ − β⁻`
/// against `β⁻`, one line per `α⁻` (file `names[0]`), and against `|α⁻|`, one line per `β⁻`
/// (file `names[1]`), written when some line has at least `min_points` conditions.
/// Returns the file names written.
pub fn dbeta_sweeps(
    dir: &Path,
    results: &[roughwall::tally::ConditionResult],
    label: &str,
    min_points: usize,
    names: [&str; 2],
) -> Result<Vec<String>> {
    let mut alphas: Vec<f64> = results
        .iter()
        .map(|r| r.condition().alpha_in_deg())
        .collect();
    let mut betas: Vec<f64> = results
        .iter()
        .map(|r| r.condition().beta_in_deg())
        .collect();
    for v in [&mut alphas, &mut betas] {
        v.sort_by(|a, b| a.total_cmp(b));
        v.dedup();
    }
    let mut written = Vec::new();
    for (along_beta, keys, name, x_label) in [
        (true, &alphas, names[0], "β⁻ (deg)"),
        (false, &betas, names[1], "|α⁻| (deg)"),
    ] {
        let (mut mean, mut std) = (Vec::new(), Vec::new());
        for &k in keys.iter() {
            let pts: Vec<SweepPoint> = results
                .iter()
                .filter(|r| {
                    let c = r.condition();
                    (if along_beta {
                        c.alpha_in_deg()
                    } else {
                        c.beta_in_deg()
                    }) == k
                })
                .filter_map(|r| {
                    let c = r.condition();
                    let e = r.estimate(roughwall::tally::Quantity::Dbeta)?;
                    Some(SweepPoint {
                        x: if along_beta {
                            c.beta_in_deg()
                        } else {
                            -c.alpha_in_deg()
                        },
                        mean: e.mean,
                        std: e.std,
                        se: e.se,
                    })
                })
                .collect();
            if pts.len() < min_points {
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
            written.push(name.to_string());
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_series_sorts_and_needs_two_points() {
        let p = |x, mean, std, se| SweepPoint { x, mean, std, se };
        assert!(sweep_series(
            "DS",
            "α⁻",
            -15.0,
            vec![p(10.0, 1.0, Some(2.0), None)],
            Kind::Line
        )
        .is_none());
        let (m, s) = sweep_series(
            "DS",
            "α⁻",
            -15.0,
            vec![
                p(20.0, 1.0, Some(3.0), Some(0.1)),
                p(10.0, 0.5, Some(2.0), Some(0.2)),
                p(30.0, 0.7, None, None),
            ],
            Kind::Line,
        )
        .unwrap();
        assert_eq!(m.points, vec![(10.0, 0.5), (20.0, 1.0), (30.0, 0.7)]);
        assert_eq!(m.err[..2], [0.4, 0.2]);
        assert!(m.err[2].is_nan(), "no error bar without a standard error");
        // A single particle's spread is undefined: no point on the std curve.
        assert_eq!(s.points, vec![(10.0, 2.0), (20.0, 3.0)]);
        assert_eq!(m.label, "DS, α⁻ = -15°");
    }
}
