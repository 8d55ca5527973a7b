//! The erosion study's section of `REPORT.md` (issue 12): erosion per unit particle mass
//! against the nominal impact angle, on the walls `scripts/erosion.sh` runs, from both
//! models. Writes `erosion/erosion.csv`, `erosion/erosion.svg` and
//! `erosion/erosion_ratios.svg`; every number is read from the runs' `summary.csv`.

use crate::paths::{erosion_wall_name, DETERMINISTIC, EROSION, EROSION_WALLS, STOCHASTIC};
use outputs::csv::{num, run_toml, Rows};
use outputs::CsvTable;
use outputs::{plot_grid_svg, Kind, Plot, Series};
use roughwall::format::{fmt_num, fmt_sci};
use roughwall::Result;
use std::fmt::Write;
use std::path::Path;

/// The walls of the study, in the order the script runs them.
fn wall_names() -> [&'static str; 5] {
    EROSION_WALLS.map(erosion_wall_name)
}
/// The incident directions β⁻ (degrees): `paths::EROSION_BETAS_DEG`, which the script
/// reads (a test keeps the two equal).
const BETAS: [f64; 3] = [0.0, 45.0, 90.0];
const MODELS: [&str; 2] = [DETERMINISTIC, STOCHASTIC];
/// mm³ in m³: the figures' unit.
const MM3: f64 = 1e-9;

/// One condition of one run.
#[derive(Clone, Copy, Debug)]
struct Point {
    /// Nominal impact angle `|α⁻|` (degrees).
    alpha: f64,
    beta: f64,
    e: f64,
    se: f64,
    /// Stochastic: the rejected candidates' share.
    rejected: Option<f64>,
    se_rejected: Option<f64>,
    impacts: Option<f64>,
}

/// A wall's runs.
struct WallRuns {
    name: &'static str,
    delta_xi: f64,
    delta_zeta: f64,
    /// Deterministic, stochastic.
    points: [Vec<Point>; 2],
}

impl WallRuns {
    fn label(&self) -> String {
        match self.name {
            "smooth" => "smooth".into(),
            "iso" => format!("isotropic ({}°, {}°)", self.delta_xi, self.delta_zeta),
            "2d" => format!("2-D ({}°, {}°)", self.delta_xi, self.delta_zeta),
            _ => format!("({}°, {}°)", self.delta_xi, self.delta_zeta),
        }
    }

    fn at(&self, model: usize, alpha: f64, beta: f64) -> Option<&Point> {
        self.points[model]
            .iter()
            .find(|p| p.alpha == alpha && p.beta == beta)
    }

    /// The largest erosion over the nominal angles at `beta`: (angle, value, se).
    fn peak(&self, model: usize, beta: f64) -> Option<(f64, f64, f64)> {
        self.points[model]
            .iter()
            .filter(|p| p.beta == beta)
            .max_by(|a, b| a.e.total_cmp(&b.e))
            .map(|p| (p.alpha, p.e, p.se))
    }
}

fn read_points(dir: &Path) -> Result<Option<(f64, f64, Vec<Point>)>> {
    let Some(rows) = Rows::read(&dir.join("summary.csv"))? else {
        return Ok(None);
    };
    let mut dev = (0.0, 0.0);
    let mut v = Vec::new();
    for r in &rows.rows {
        let (Some(a), Some(b), Some(e), Some(se)) = (
            num(r, "alpha_in_deg"),
            num(r, "beta_in_deg"),
            num(r, "erosion_per_mass"),
            num(r, "se_erosion_per_mass"),
        ) else {
            continue;
        };
        dev = (
            num(r, "delta_xi_deg").unwrap_or(0.0),
            num(r, "delta_zeta_deg").unwrap_or(0.0),
        );
        v.push(Point {
            alpha: -a,
            beta: b,
            e,
            se,
            rejected: num(r, "erosion_per_mass_rejected"),
            se_rejected: num(r, "se_erosion_per_mass_rejected"),
            impacts: num(r, "mean_impacts"),
        });
    }
    v.sort_by(|a, b| a.beta.total_cmp(&b.beta).then(a.alpha.total_cmp(&b.alpha)));
    Ok((!v.is_empty()).then_some((dev.0, dev.1, v)))
}

/// Conditions of the rough walls where the deterministic erosion lies between the
/// stochastic accepted-only and accepted-plus-rejected values (each within 2 standard
/// errors), and all conditions compared.
fn bracketed(walls: &[WallRuns]) -> (usize, usize) {
    let (mut between, mut total) = (0, 0);
    for w in walls.iter().filter(|w| w.name != "smooth") {
        for d in &w.points[0] {
            let Some(s) = w.at(1, d.alpha, d.beta) else {
                continue;
            };
            total += 1;
            let all = s.e + s.rejected.unwrap_or(0.0);
            let tol = 2.0 * (d.se + s.se + s.se_rejected.unwrap_or(0.0));
            if s.e - tol <= d.e && d.e <= all + tol {
                between += 1;
            }
        }
    }
    (between, total)
}

fn sci(x: f64) -> String {
    fmt_sci(x)
}

/// `x/y` with two decimals, "–" when undefined.
fn ratio(x: f64, y: f64) -> String {
    if y > 0.0 && x.is_finite() {
        format!("{:.2}", x / y)
    } else {
        "–".into()
    }
}

pub fn erosion(results: &Path, md: &mut String) -> Result<()> {
    md.push_str("## Erosion on rough walls (beyond the papers)\n\n");
    let dir = results.join(EROSION);
    let mut walls = Vec::new();
    for name in wall_names() {
        let mut points: [Vec<Point>; 2] = [Vec::new(), Vec::new()];
        let mut dev = None;
        for (k, model) in MODELS.iter().enumerate() {
            if let Some((dx, dz, p)) = read_points(&dir.join(name).join(model))? {
                dev = Some((dx, dz));
                points[k] = p;
            }
        }
        if let Some((delta_xi, delta_zeta)) = dev {
            walls.push(WallRuns {
                name,
                delta_xi,
                delta_zeta,
                points,
            });
        }
    }
    let Some(smooth) = walls.iter().find(|w| w.name == "smooth") else {
        let _ = writeln!(
            md,
            "*Not run: `{}` has no smooth-wall run (`scripts/erosion.sh`).*\n",
            dir.display()
        );
        return Ok(());
    };
    // The law and the particles, from a run's manifest.
    let manifest = run_toml(&dir.join("smooth").join(DETERMINISTIC));
    let law = manifest
        .as_ref()
        .and_then(|t| t.get("erosion")?.as_table().cloned());
    let get = |k: &str| law.as_ref().and_then(|t| t.get(k)?.as_float());
    let particles = smooth.points[0]
        .first()
        .and(manifest.as_ref())
        .and_then(|t| t.get("run")?.get("particles_per_condition")?.as_integer());
    let _ = writeln!(
        md,
        "Glass spheres (500 µm, 2500 kg/m³) hit a steel wall at |U| = 20 m/s with Sommerfeld–Huber \
         glass–steel collisions; Finnie's law in OpenFOAM's convention (p = {} Pa, ψ = {}, K = {}) \
         removes volume at the *local* impact angle of every impact (`deterministic`: every collision \
         of a history on the generated surface; `stochastic`: the accepted virtual wall, and apart \
         the rejected candidates). {} particles per condition; nominal angle α = |α⁻|. Run by \
         `scripts/erosion.sh` (base case `configs/cases/erosion-glass-steel.toml`); the table is \
         `erosion/erosion.csv`.\n",
        get("flow_stress_pa").map_or("–".into(), fmt_num),
        get("psi").map_or("–".into(), fmt_num),
        get("k").map_or("–".into(), fmt_num),
        particles.map_or("–".into(), |n| n.to_string()),
    );
    md.push_str(
        "Checks against tools no one here wrote (run by the test suite, `tests/erosion_references.rs`): \
         on a smooth wall both models' Finnie volumes equal OpenFOAM v1912's `particleErosion` \
         (`scripts/openfoam-erosion/`, 96 impacts, two parameter sets) to the CSV's 7 digits, and the \
         law itself to 1e-12; `model = \"dnv\"` equals Equinor's pysand 2.0.0 (`scripts/pysand/`, \
         384 values) to 1e-9.\n\n",
    );

    // The aggregated table.
    let mut table = CsvTable::new(&[
        "wall",
        "delta_xi_deg",
        "delta_zeta_deg",
        "model",
        "beta_in_deg",
        "alpha_nominal_deg",
        "erosion_per_mass",
        "se_erosion_per_mass",
        "erosion_per_mass_rejected",
        "se_erosion_per_mass_rejected",
        "mean_impacts",
        "ratio_to_smooth",
    ]);
    for w in &walls {
        for (k, model) in MODELS.iter().enumerate() {
            for p in &w.points[k] {
                let s = smooth.at(k, p.alpha, p.beta).map(|s| s.e);
                table.push(vec![
                    w.name.to_string(),
                    fmt_num(w.delta_xi),
                    fmt_num(w.delta_zeta),
                    model.to_string(),
                    fmt_num(p.beta),
                    fmt_num(p.alpha),
                    sci(p.e),
                    sci(p.se),
                    p.rejected.map(sci).unwrap_or_default(),
                    p.se_rejected.map(sci).unwrap_or_default(),
                    p.impacts.map(fmt_num).unwrap_or_default(),
                    s.filter(|s| *s > 1e-6 * p.e.max(1e-300))
                        .map(|s| fmt_num(p.e / s))
                        .unwrap_or_default(),
                ]);
            }
        }
    }
    table.write(&dir.join("erosion.csv"))?;

    // Peaks and grazing erosion, deterministic (the reference) beside stochastic.
    md.push_str(
        "Peak erosion (largest over the nominal angles run; m³ per kg of particles) and erosion at \
         grazing (1°, 5°) and normal (90°) incidence, as multiples of the smooth wall's at the same \
         angle (normal incidence: absolute, Finnie's smooth-wall value is 0). DS = `deterministic`, \
         SM = `stochastic` (accepted walls).\n\n\
         | wall | β⁻ | DS peak (at α) | SM peak (at α) | DS 1° / smooth | SM 1° / smooth | DS 5° / smooth | SM 5° / smooth | DS 90° | SM 90° |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    let cell = |w: &WallRuns, k: usize, a: f64, b: f64| -> String {
        match (w.at(k, a, b), smooth.at(k, a, b)) {
            (Some(p), Some(s)) => ratio(p.e, s.e),
            _ => "–".into(),
        }
    };
    for w in &walls {
        for &b in &BETAS {
            if w.peak(0, b).is_none() {
                continue;
            }
            let peak = |k: usize| {
                w.peak(k, b).map_or("–".into(), |(a, e, se)| {
                    format!("{} ± {} ({a}°)", sci(e), sci(se))
                })
            };
            let normal = |k: usize| w.at(k, 90.0, 0.0).map_or("–".into(), |p| sci(p.e));
            let (n0, n1) = if b == 0.0 {
                (normal(0), normal(1))
            } else {
                ("".into(), "".into())
            };
            let _ = writeln!(
                md,
                "| {} | {b}° | {} | {} | {} | {} | {} | {} | {n0} | {n1} |",
                w.label(),
                peak(0),
                peak(1),
                cell(w, 0, 1.0, b),
                cell(w, 1, 1.0, b),
                cell(w, 0, 5.0, b),
                cell(w, 1, 5.0, b),
            );
        }
    }
    md.push('\n');

    // The stochastic model against the deterministic sum, with and without the rejected
    // candidates.
    md.push_str(
        "Stochastic against deterministic erosion, over all nominal angles and β⁻ of a wall: mean \
         and range of SM/DS, and the largest |z| (difference over the combined standard error), \
         for the accepted walls only and with the rejected candidates added.\n\n\
         | wall | SM/DS accepted: mean (min – max) | max \\|z\\| | SM/DS accepted + rejected: mean (min – max) | max \\|z\\| |\n\
         |---|---|---|---|---|\n",
    );
    let mut verdict: Vec<(String, f64, f64)> = Vec::new();
    for w in walls.iter().filter(|w| w.name != "smooth") {
        let mut acc = Vec::new();
        let mut all = Vec::new();
        for d in &w.points[0] {
            let Some(s) = w.at(1, d.alpha, d.beta) else {
                continue;
            };
            if d.e <= 0.0 {
                continue;
            }
            let z = |x: f64, se: f64| (x - d.e) / (se * se + d.se * d.se).sqrt().max(1e-300);
            acc.push((s.e / d.e, z(s.e, s.se)));
            let r = s.rejected.unwrap_or(0.0);
            // The two parts come from the same rebounds; their errors are added as if
            // independent (an upper bound for positively correlated parts).
            let se_all = s.se + s.se_rejected.unwrap_or(0.0);
            all.push(((s.e + r) / d.e, z(s.e + r, se_all)));
        }
        let stats = |v: &[(f64, f64)]| -> (String, String, f64) {
            if v.is_empty() {
                return ("–".into(), "–".into(), f64::NAN);
            }
            let mean = v.iter().map(|x| x.0).sum::<f64>() / v.len() as f64;
            let lo = v.iter().map(|x| x.0).fold(f64::INFINITY, f64::min);
            let hi = v.iter().map(|x| x.0).fold(f64::NEG_INFINITY, f64::max);
            let zmax = v.iter().map(|x| x.1.abs()).fold(0.0, f64::max);
            (
                format!("{mean:.3} ({lo:.3} – {hi:.3})"),
                format!("{zmax:.1}"),
                mean,
            )
        };
        let (a, za, da) = stats(&acc);
        let (b, zb, db) = stats(&all);
        verdict.push((w.label(), da, db));
        let _ = writeln!(md, "| {} | {a} | {za} | {b} | {zb} |", w.label());
    }
    md.push('\n');

    // Findings in words, from the numbers above.
    md.push_str("What roughness does, in numbers:\n\n");
    if let Some((a0, e0, _)) = smooth.peak(0, 0.0) {
        let _ = writeln!(
            md,
            "- On the smooth wall the erosion peaks at α = {a0}° with {} m³/kg (Finnie's \
             maximum for K = 2 is at tan α = 1/3, 18.4°) and vanishes at normal incidence.",
            sci(e0)
        );
    }
    for w in walls.iter().filter(|w| w.name != "smooth") {
        let peaks: Vec<(f64, f64, f64)> = BETAS.iter().filter_map(|&b| w.peak(0, b)).collect();
        let (Some((_, e_s, _)), false) = (smooth.peak(0, 0.0), peaks.is_empty()) else {
            continue;
        };
        let lo = peaks.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let hi = peaks.iter().map(|p| p.1).fold(0.0, f64::max);
        let angles: Vec<String> = peaks.iter().map(|p| format!("{}°", p.0)).collect();
        let graze: Vec<String> = BETAS
            .iter()
            .map(|&b| cell(w, 0, 1.0, b))
            .filter(|c| c != "–")
            .collect();
        let normal = w.at(0, 90.0, 0.0).map(|p| p.e);
        let _ = writeln!(
            md,
            "- {}: the peak is {}–{} of the smooth wall's (at α = {} for β⁻ = 0°, 45°, 90°); \
             erosion at α = 1° is {} times the smooth wall's (β⁻ = 0°, 45°, 90°); at normal \
             incidence it is {} m³/kg ({} of the smooth peak).",
            w.label(),
            ratio(lo, e_s),
            ratio(hi, e_s),
            angles.join(", "),
            graze.join(", "),
            normal.map_or("–".into(), sci),
            normal.map_or("–".into(), |n| format!("{:.1} %", 100.0 * n / e_s)),
        );
    }
    if !verdict.is_empty() {
        let n = verdict.len() as f64;
        let mean_acc = verdict.iter().map(|v| v.1).sum::<f64>() / n;
        let mean_all = verdict.iter().map(|v| v.2).sum::<f64>() / n;
        let (between, total) = bracketed(&walls);
        let _ = writeln!(
            md,
            "- Stochastic model against the deterministic sum over every collision: the accepted \
             walls alone give SM/DS = {:.3} on average over the rough walls' conditions, the \
             accepted walls plus the rejected candidates {:.3}; the deterministic value lies \
             between the two on {between} of {total} conditions. The rejected candidates are \
             charged the *incident* speed and a fresh wall, while a real second hit comes after \
             the first has slowed the particle and turned it towards grazing: the truth lies \
             between the two, nearer the accepted-only value at steep incidence.",
            mean_acc, mean_all,
        );
    }
    md.push('\n');

    // Figures: erosion against the nominal angle per β⁻, and the ratio to the smooth wall.
    let mut panels = Vec::new();
    let mut ratio_panels = Vec::new();
    for &b in &BETAS {
        let mut series = Vec::new();
        let mut rseries = Vec::new();
        for (c, w) in walls.iter().enumerate() {
            for k in [0, 1] {
                let pts: Vec<&Point> = w.points[k].iter().filter(|p| p.beta == b).collect();
                if pts.is_empty() {
                    continue;
                }
                // One colour per wall: deterministic line (labelled), stochastic markers.
                let (kind, label) = if k == 0 {
                    (Kind::Line, w.label())
                } else {
                    (Kind::Markers, String::new())
                };
                series.push(
                    Series::new(
                        label.clone(),
                        pts.iter().map(|p| (p.alpha, p.e / MM3)).collect(),
                        kind,
                    )
                    .with_err(pts.iter().map(|p| 2.0 * p.se / MM3).collect())
                    .with_color(c),
                );
                if w.name != "smooth" {
                    let r: Vec<(f64, f64)> = pts
                        .iter()
                        .filter_map(|p| {
                            let s = smooth.at(k, p.alpha, b)?.e;
                            (s > 1e-6 * p.e).then(|| (p.alpha, p.e / s))
                        })
                        .collect();
                    rseries.push(Series::new(label, r, kind).with_color(c));
                }
            }
        }
        panels.push(Plot {
            title: format!("Erosion, β⁻ = {b}°: DS lines, SM dots (±2 SE)"),
            x_label: "nominal impact angle |α⁻| (deg)".into(),
            y_label: "erosion per unit mass (mm³/kg)".into(),
            series,
            x_range: Some((0.0, 90.0)),
            ..Default::default()
        });
        ratio_panels.push(Plot {
            title: format!("Rough over smooth wall, β⁻ = {b}°: DS lines, SM dots"),
            x_label: "nominal impact angle |α⁻| (deg)".into(),
            y_label: "erosion / smooth-wall erosion".into(),
            series: rseries,
            x_range: Some((0.0, 90.0)),
            ..Default::default()
        });
    }
    plot_grid_svg(&dir.join("erosion.svg"), &panels, 3)?;
    plot_grid_svg(&dir.join("erosion_ratios.svg"), &ratio_panels, 3)?;
    md.push_str(
        "![erosion](erosion/erosion.svg)\n\n![erosion over smooth](erosion/erosion_ratios.svg)\n\n",
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_study_reads_the_walls_and_directions_the_script_runs() {
        let script: Vec<f64> = crate::paths::EROSION_BETAS_DEG
            .iter()
            .map(|b| b.parse().unwrap())
            .collect();
        assert_eq!(script, BETAS);
        assert_eq!(wall_names(), ["smooth", "iso", "2d", "aniso", "aniso-rev"]);
        for w in EROSION_WALLS {
            let f: Vec<&str> = w.split(':').collect();
            assert_eq!(f.len(), 3, "{w}");
            assert!(
                f[1].parse::<f64>().is_ok() && f[2].parse::<f64>().is_ok(),
                "{w}"
            );
        }
    }
}
