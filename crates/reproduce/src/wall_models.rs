//! The rough-wall model benchmark's section of `REPORT.md`: every stochastic variant
//! against `deterministic` on every Sec. 3 and Sec. 4 scene (`scripts/wall-models.sh`).
//! Writes `wall-models/wall_models.csv` (byte-identical between runs: the cost per rebound,
//! a timing, is only in `REPORT.md`); every number is read from the runs' `compare` outputs
//! and manifests.

use crate::common::missing;
use crate::paths::{scene_name, COMPARE, STOCHASTIC, WALL_MODELS, WALL_MODELS_SCENES};
use outputs::csv::{num, run_toml, Rows};
use outputs::CsvTable;
use roughwall::format::fmt_num;
use roughwall::Result;
use roughwall::{AnyModel, RoughWallModel};
use std::fmt::Write;
use std::path::Path;

/// The scenes, by name (the directories under `wall-models/`).
fn scene_names() -> [&'static str; 9] {
    WALL_MODELS_SCENES.map(scene_name)
}

/// One variant on one scene against `deterministic`.
#[derive(Clone, Copy, Debug, Default)]
struct Score {
    ks_alpha: f64,
    ks_dbeta: f64,
    /// Largest |mean α⁺ (SM) − mean α⁺ (DS)| (deg) and its |z|.
    bias_alpha: f64,
    z_alpha: f64,
    bias_dbeta: f64,
    z_dbeta: f64,
    /// The same restricted to |α⁻| ≥ 2.5° (the goal's range).
    ks_alpha_25: f64,
    bias_alpha_25: f64,
    /// Wall-clock nanoseconds per rebound of the whole run (2 threads).
    ns_per_rebound: Option<f64>,
}

fn score(dir: &Path) -> Result<Option<Score>> {
    let Some(c) = Rows::read(&dir.join(COMPARE).join("comparison.csv"))? else {
        return Ok(None);
    };
    let mut s = Score::default();
    for r in &c.rows {
        let q = r.get("quantity").map_or("", String::as_str);
        let (Some(ks), Some(a), Some(b)) = (num(r, "ks"), num(r, "mean_a"), num(r, "mean_b"))
        else {
            continue;
        };
        let z = num(r, "z").unwrap_or(0.0).abs();
        let steep = num(r, "alpha_in_deg").is_some_and(|x| x.abs() >= 2.5);
        let bias = (b - a).abs();
        match q {
            "alpha_out" => {
                s.ks_alpha = s.ks_alpha.max(ks);
                if bias > s.bias_alpha {
                    s.bias_alpha = bias;
                }
                s.z_alpha = s.z_alpha.max(z);
                if steep {
                    s.ks_alpha_25 = s.ks_alpha_25.max(ks);
                    s.bias_alpha_25 = s.bias_alpha_25.max(bias);
                }
            }
            "dbeta" => {
                s.ks_dbeta = s.ks_dbeta.max(ks);
                s.bias_dbeta = s.bias_dbeta.max(bias);
                s.z_dbeta = s.z_dbeta.max(z);
            }
            _ => {}
        }
    }
    let sm = dir.join(STOCHASTIC);
    s.ns_per_rebound = run_toml(&sm).and_then(|t| {
        let run = t.get("run")?;
        let secs = run.get("compute_s")?.as_float()?;
        let per = run.get("particles_per_condition")?.as_integer()? as f64;
        let conditions = t.get("conditions")?.as_array()?.len() as f64;
        (per * conditions > 0.0).then(|| 1e9 * secs / (per * conditions))
    });
    Ok(Some(s))
}

pub fn wall_models(results: &Path, md: &mut String) -> Result<()> {
    md.push_str(
        "## Which rough-wall model to trust: the models CFD codes ship against `deterministic`\n\n",
    );
    let dir = results.join(WALL_MODELS);
    let mut table = CsvTable::new(&[
        "scene",
        "model",
        "max_ks_alpha_out",
        "max_ks_dbeta",
        "max_abs_bias_mean_alpha_out_deg",
        "max_abs_z_alpha_out",
        "max_abs_bias_mean_dbeta_deg",
        "max_abs_z_dbeta",
        "max_ks_alpha_out_steep",
        "max_abs_bias_mean_alpha_out_steep_deg",
    ]);
    let mut all: Vec<(&str, AnyModel, Score)> = Vec::new();
    for scene in scene_names() {
        for v in all_models() {
            if let Some(s) = score(&dir.join(scene).join(v.name()))? {
                table.push(vec![
                    scene.into(),
                    v.name().into(),
                    fmt_num(s.ks_alpha),
                    fmt_num(s.ks_dbeta),
                    fmt_num(s.bias_alpha),
                    fmt_num(s.z_alpha),
                    fmt_num(s.bias_dbeta),
                    fmt_num(s.z_dbeta),
                    fmt_num(s.ks_alpha_25),
                    fmt_num(s.bias_alpha_25),
                ]);
                all.push((scene, v, s));
            }
        }
    }
    if all.is_empty() {
        missing(md, "`scripts/wall-models.sh`", &dir);
        return Ok(());
    }
    table.write(&dir.join("wall_models.csv"))?;
    md.push_str(
        "Each variant of `[stochastic] model` runs every scene of Secs. 3–4 with the particles per \
         condition of the deterministic run it is compared with (`scripts/wall-models.sh`; table \
         `wall-models/wall_models.csv`). Per scene: the largest KS distance over the conditions of \
         α⁺ and of β⁺ − β⁻, the largest bias of the mean (SM − DS, degrees) with the largest |z| \
         (bias over the combined standard error), and the run's wall-clock time per rebound on 2 \
         threads. The isotropic variants use Δγ = (Δξ + Δζ)/2. Definitions and sources: \
         `crates/roughwall/src/stochastic/variants.rs`, [models.md](../docs/models.md).\n\n\
         | scene | model | max KS α⁺ | max KS β⁺−β⁻ | max \\|bias\\| mean α⁺ (°) | max \\|z\\| | max \\|bias\\| mean β⁺−β⁻ (°) | max \\|z\\| | ns/rebound |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for (scene, v, s) in &all {
        let _ = writeln!(
            md,
            "| {scene} | {} | {:.4} | {:.4} | {:.3} | {:.1} | {:.3} | {:.1} | {} |",
            v.name(),
            s.ks_alpha,
            s.ks_dbeta,
            s.bias_alpha,
            s.z_alpha,
            s.bias_dbeta,
            s.z_dbeta,
            s.ns_per_rebound.map_or("–".into(), |x| format!("{x:.0}")),
        );
    }
    md.push('\n');

    // Which model when: per variant, the mean over scenes and how often it is best.
    md.push_str("Over the scenes (mean of the per-scene maxima, and on how many scenes the variant has the smallest max KS of α⁺ and of β⁺ − β⁻):\n\n\
                 | model | mean max KS α⁺ | mean max KS β⁺−β⁻ | mean max \\|bias\\| α⁺ (°) | best KS α⁺ | best KS β⁺−β⁻ | mean ns/rebound |\n\
                 |---|---|---|---|---|---|---|\n");
    let scenes: Vec<&str> = scene_names()
        .iter()
        .copied()
        .filter(|s| all.iter().any(|a| a.0 == *s))
        .collect();
    let best = |pick: &dyn Fn(&Score) -> f64, v: AnyModel| -> usize {
        scenes
            .iter()
            .filter(|sc| {
                let rows: Vec<&(&str, AnyModel, Score)> =
                    all.iter().filter(|a| a.0 == **sc).collect();
                let min = rows
                    .iter()
                    .map(|a| pick(&a.2))
                    .fold(f64::INFINITY, f64::min);
                rows.iter().any(|a| a.1 == v && pick(&a.2) == min)
            })
            .count()
    };
    let mut summary: Vec<(AnyModel, f64, f64, f64)> = Vec::new();
    for v in all_models() {
        let rows: Vec<&Score> = all.iter().filter(|a| a.1 == v).map(|a| &a.2).collect();
        if rows.is_empty() {
            continue;
        }
        let n = rows.len() as f64;
        let mean = |f: &dyn Fn(&Score) -> f64| rows.iter().map(|s| f(s)).sum::<f64>() / n;
        let ka = mean(&|s| s.ks_alpha);
        let kb = mean(&|s| s.ks_dbeta);
        let ba = mean(&|s| s.bias_alpha);
        let costs: Vec<f64> = rows.iter().filter_map(|s| s.ns_per_rebound).collect();
        let cost = (!costs.is_empty()).then(|| costs.iter().sum::<f64>() / costs.len() as f64);
        let _ = writeln!(
            md,
            "| {} | {ka:.4} | {kb:.4} | {ba:.3} | {} of {} | {} of {} | {} |",
            v.name(),
            best(&|s| s.ks_alpha, v),
            scenes.len(),
            best(&|s| s.ks_dbeta, v),
            scenes.len(),
            cost.map_or("–".into(), |c| format!("{c:.0}")),
        );
        summary.push((v, ka, kb, ba));
    }
    md.push('\n');
    if let (Some(paper), Some(best_other)) = (
        summary.iter().find(|s| s.0.is_paper()),
        summary
            .iter()
            .filter(|s| !s.0.anisotropic())
            .min_by(|a, b| (a.1 + a.2).total_cmp(&(b.1 + b.2))),
    ) {
        let _ = writeln!(
            md,
            "Which model when, from these numbers: `radenkovic-simonin-2021` has a mean max KS of \
             {:.4} (α⁺) and {:.4} (β⁺ − β⁻); the best of the simpler models, `{}`, {:.4} and {:.4}, \
             {:.1}× and {:.1}× the paper model's. The simpler models ignore the wall's anisotropy \
             (one Δγ for every direction) and, but for Sommerfeld & Huber and ELEXI, the shadow \
             effect; they are defensible only on isotropic walls at steep incidence, where the \
             shadow effect and repeated hits vanish. On anisotropic walls, at grazing incidence, \
             or whenever the transverse deviation β⁺ − β⁻ matters (wall-normal dispersion in \
             pipes and channels), use `radenkovic-simonin-2021`. ELEXI's second rotation, by a \
             shadow-weighted and therefore biased angle, gives an isotropic wall a handedness \
             (mean β⁺ − β⁻ ≠ 0 at β⁻ = 0; `tests/stochastic_variants.rs`).\n",
            paper.1,
            paper.2,
            best_other.0.name(),
            best_other.1,
            best_other.2,
            best_other.1 / paper.1.max(1e-12),
            best_other.2 / paper.2.max(1e-12),
        );
        if let Some(cal) = summary.iter().find(|s| s.0.name() == "calibrated") {
            let _ = writeln!(
                md,
                "`calibrated` (the paper's walls with laws measured on a deterministic run; next \
                 section) runs here, like every row, with the wall's *nominal* deviations: mean max \
                 KS {:.4} (α⁺) and {:.4} (β⁺ − β⁻), {:.1}× and {:.1}× the paper model's. With nominal \
                 deviations the generated surfaces' few per cent less slope than nominal adds to \
                 both models' error; the next section compares them without it.\n",
                cal.1,
                cal.2,
                cal.1 / paper.1.max(1e-12),
                cal.2 / paper.2.max(1e-12),
            );
        }
    }
    Ok(())
}

/// Every registered rough-wall model with its default parameters, in the list's order.
fn all_models() -> Vec<AnyModel> {
    AnyModel::NAMES
        .iter()
        .filter_map(|name| AnyModel::with_defaults(name).ok())
        .collect()
}
