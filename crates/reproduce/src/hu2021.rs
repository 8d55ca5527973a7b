//! Hu et al. 2021: the peak elastic force of spheres and prolate spheroids (Figs. 4, 6, 9,
//! 11b), the physical models against the paper's fit, and the cost of `hertz-dynamic`.

use crate::common::{f, missing, pct, yes};
use crate::paths::{HU2021, HU_FIG11B, HU_FIG4, HU_FIG6, HU_FIG9};
use outputs::csv::{num, run_toml, Rows};
use roughwall::Result;
use std::fmt::Write;
use std::path::Path;

/// Hu et al., Sec. 3 (Fig. 4): FE against Eq. (3) for spheres, `φ ≤ 0.93 %` for `U_N ≤ 0.2 m/s`.
pub const HU_FIG4_PHI_MAX: f64 = 0.0093;

/// Hu et al., Sec. 4 (Fig. 11b): model against FE differs by 13.6 % at `U_N = 20 m/s`
/// (D = 10 µm, λ = 1.5, β = 45°).
pub const HU_FIG11B_DIFF: f64 = 0.136;

/// The section on Hu et al. 2021: Figs. 4, 6, 9 and 11b and the cost of `hertz-dynamic`.
pub fn hu(results: &Path, md: &mut String) -> Result<()> {
    md.push_str("## Hu et al.: peak elastic force of spheres and prolate spheroids\n\n");
    let root = results.join(HU2021);
    // Fig. 4 analogue: the time-integrated sphere against Eq. (3).
    if let Some(s) = Rows::read(&root.join(HU_FIG4).join("force_sweep.csv"))? {
        let sphere = s.with("model", "hertz-sphere");
        let mut worst = 0.0f64;
        let mut n = 0;
        for d in s.with("model", "hertz-dynamic") {
            let key = |r: &std::collections::HashMap<String, String>| {
                (
                    num(r, "u_n_m_s"),
                    num(r, "diameter_um"),
                    num(r, "density_kg_m3"),
                    num(r, "youngs_pa"),
                )
            };
            if let Some(h) = sphere.iter().find(|h| key(h) == key(d)) {
                if let (Some(a), Some(b)) = (num(d, "f_max_n"), num(h, "f_max_n")) {
                    if b > 0.0 {
                        worst = worst.max(((a - b) / b).abs());
                        n += 1;
                    }
                }
            }
        }
        let _ = writeln!(
            md,
            "**Fig. 4 (sphere check).** Paper: FE against Eq. (3), φ ≤ {:.2} % for U_N ≤ 0.2 m/s. Ours (time-integrated Hertz ODE, Eq. 1, against Eq. 3): largest relative difference {:.2e} over {n} points — an ODE, not FE, so it checks our integrator, not the continuum effects FE sees.\n",
            100.0 * HU_FIG4_PHI_MAX, worst
        );
    } else {
        missing(
            md,
            "scripts/hu2021.sh",
            &root.join(HU_FIG4).join("force_sweep.csv"),
        );
    }
    // Accuracy of the physical models against Eq. (8).
    if let Some(a) = Rows::read(&root.join(HU_FIG6).join("accuracy.csv"))? {
        md.push_str("**Fig. 6: physical models against Hu et al.'s fit (Eqs. 7–8), β = 0°…90°.** Goal of issue 5: mean deviation ≤ 5 % per λ.\n\n| model | λ | mean rel. dev. | max rel. dev. | at β | ≤ 5 % |\n|---|---|---|---|---|---|\n");
        for r in &a.rows {
            let mean = num(r, "mean_rel_dev");
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {}° | {} |",
                r.get("model").map_or("", |s| s.as_str()),
                f(num(r, "lambda"), 1),
                pct(mean),
                pct(num(r, "max_rel_dev")),
                f(num(r, "beta_at_max_deg"), 0),
                yes(mean.map(|m| m <= 0.05))
            );
        }
        md.push('\n');
    } else {
        missing(
            md,
            "scripts/hu2021.sh",
            &root.join(HU_FIG6).join("accuracy.csv"),
        );
    }
    if let Some(s) = Rows::read(&root.join(HU_FIG6).join("force_sweep.csv"))? {
        md.push_str("Orientation of the smallest F_max (paper, Fig. 6: near 45° for λ = 2 and 3):\n\n| model | λ | β at min F_max |\n|---|---|---|\n");
        for model in ["hu2021", "hertz-rigid", "hertz-dynamic"] {
            for lam in [1.5, 2.0, 3.0] {
                let rows: Vec<_> = s
                    .with("model", model)
                    .into_iter()
                    .filter(|r| num(r, "lambda") == Some(lam))
                    .collect();
                let min = rows
                    .iter()
                    .filter_map(|r| Some((num(r, "f_max_n")?, num(r, "beta_deg")?)))
                    .min_by(|a, b| a.0.total_cmp(&b.0));
                let _ = writeln!(md, "| {model} | {lam} | {}° |", f(min.map(|m| m.1), 0));
            }
        }
        md.push_str("\n![Fig. 6 analogue](hu2021/fig6/fmax_vs_beta.svg) ![Fig. 9 analogue](hu2021/fig6/xi_vs_beta.svg)\n\n");
    }
    if let Some(s) = Rows::read(&root.join(HU_FIG9).join("force_sweep.csv"))? {
        md.push_str("**Eq. (8): the coefficient ξ of Eq. (7)** (Hu et al.'s fit, `hu2021`) beside the first-principles `hertz-rigid` (Fig. 9 setup):\n\n| β | ξ λ = 1.5 (Eq. 8) | hertz-rigid | ξ λ = 2 (Eq. 8) | hertz-rigid | ξ λ = 3 (Eq. 8) | hertz-rigid |\n|---|---|---|---|---|---|---|\n");
        for beta in [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0] {
            let mut row = format!("| {beta}° |");
            for lam in [1.5, 2.0, 3.0] {
                for model in ["hu2021", "hertz-rigid"] {
                    let xi = s
                        .with("model", model)
                        .into_iter()
                        .find(|r| num(r, "lambda") == Some(lam) && num(r, "beta_deg") == Some(beta))
                        .and_then(|r| num(r, "xi"));
                    let _ = write!(row, " {} |", f(xi, 4));
                }
            }
            let _ = writeln!(md, "{row}");
        }
        md.push('\n');
    }
    if let Some(s) = Rows::read(&root.join(HU_FIG11B).join("force_sweep.csv"))? {
        let at = |model: &str| {
            s.with("model", model)
                .into_iter()
                .filter_map(|r| Some((num(r, "u_n_m_s")?, num(r, "f_max_n")?)))
                .min_by(|a, b| (a.0 - 20.0).abs().total_cmp(&(b.0 - 20.0).abs()))
        };
        if let Some((u, hu)) = at("hu2021") {
            let _ = writeln!(
                md,
                "**Fig. 11b (D = 10 µm, λ = 1.5, β = 45°) at U_N = {u:.1} m/s.** Paper: model against FE differs by {:.1} %. Ours against the paper's model: hertz-rigid {}, hertz-dynamic {} (no FE here, so this is model against model).\n",
                100.0 * HU_FIG11B_DIFF,
                pct(at("hertz-rigid").map(|r| (r.1 - hu) / hu)),
                pct(at("hertz-dynamic").map(|r| (r.1 - hu) / hu)),
            );
        }
    }
    if let Some(c) = Rows::read(&root.join(HU_FIG6).join("dynamic_convergence.csv"))? {
        md.push_str("**hertz-dynamic: speed against error** (relative error of the peak against a 20 000-step reference, `results/hu2021/fig6/dynamic_convergence.csv`; median time per impact from `run.toml`, this run's machine and load):\n\n| steps per contact | max rel. error F_max | max rel. error contact time | median time per impact |\n|---|---|---|---|\n");
        let mut by: std::collections::BTreeMap<i64, (f64, f64)> = Default::default();
        for r in &c.rows {
            if let (Some(s), Some(e), Some(t)) = (
                num(r, "steps_per_contact"),
                num(r, "rel_err_f_max"),
                num(r, "rel_err_contact_time"),
            ) {
                let v = by.entry(s as i64).or_insert((0.0, 0.0));
                v.0 = v.0.max(e.abs());
                v.1 = v.1.max(t.abs());
            }
        }
        let mut times: std::collections::BTreeMap<i64, Vec<f64>> = Default::default();
        if let Some(t) = run_toml(&root.join(HU_FIG6)) {
            for e in t
                .get("dynamic_convergence")
                .and_then(|v| v.as_array())
                .into_iter()
                .flatten()
            {
                let steps = e.get("steps_per_contact").and_then(|v| v.as_integer());
                let time = e.get("time_per_impact_s").and_then(|v| v.as_float());
                if let (Some(st), Some(ti)) = (steps, time) {
                    times.entry(st).or_default().push(ti);
                }
            }
        }
        for (s, (e, t)) in by {
            let median = times.get_mut(&s).and_then(|v| {
                v.sort_by(f64::total_cmp);
                v.get(v.len() / 2).copied()
            });
            let time = median.map_or("–".to_string(), |m| format!("{:.1} µs", m * 1e6));
            let _ = writeln!(md, "| {s} | {e:.2e} | {t:.2e} | {time} |");
        }
        md.push('\n');
    }
    md.push_str("Other figures: `hu2021/*/*.svg` (Figs. 8–12 analogues).\n\n");
    Ok(())
}
