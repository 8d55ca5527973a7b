//! The pipe-flow section of `REPORT.md` (`scripts/pipe-flow.sh`, issue 30): how much the
//! lay direction changes pneumatic conveying in a pipe, against isotropic roughness of the
//! same Δγ and against a smooth wall, and how the study's trends compare with the published
//! ones. Every number is read from `pipe-flow/summary.csv`, `comparisons.csv` and
//! `run.toml` (written by `rebound pipe-stats`).

use crate::paths::{PIPE_FLOW, PIPE_FLOW_QUICK};
use outputs::csv::{num, run_toml, Rows};
use roughwall::Result;
use std::collections::HashMap;
use std::fmt::Write;
use std::path::Path;

/// The quantities the section tabulates: column, heading, decimals.
const SHOWN: [(&str, &str, usize); 7] = [
    ("collisions_per_m", "collisions per m", 3),
    ("mean_ux_m_s", "mean u_x (m/s)", 3),
    ("rms_ur_m_s", "rms u_r (m/s)", 3),
    ("mean_height_over_r", "mean height / R", 3),
    ("bottom_half_fraction", "lower half", 3),
    ("mean_alpha_in_deg", "mean α⁻ (°)", 2),
    ("erosion_um_per_t", "erosion (µm/t)", 1),
];

const WALL_NAMES: [(&str, &str); 4] = [
    ("smooth", "smooth"),
    ("iso", "isotropic (5.95°, 5.95°)"),
    ("axial", "(3.8°, 7.5°), lay along the axis"),
    ("circ", "(3.8°, 7.5°), lay around the circumference"),
];

fn pm(v: Option<f64>, se: Option<f64>, digits: usize) -> String {
    match (v, se) {
        (Some(v), Some(se)) if v.is_finite() && se.is_finite() => {
            format!("{v:.digits$} ± {se:.digits$}")
        }
        _ => "–".into(),
    }
}

/// The section.
pub fn pipe_flow(results: &Path, md: &mut String) -> Result<()> {
    md.push_str("## Pneumatic conveying in a pipe with anisotropic rough walls (code_saturne)\n\n");
    let full = results.join(PIPE_FLOW);
    let quick = results.join(PIPE_FLOW_QUICK);
    let dir = if full.join("summary.csv").is_file() || !quick.join("summary.csv").is_file() {
        full
    } else {
        quick
    };
    let Some(summary) = Rows::read(&dir.join("summary.csv"))? else {
        // Not a failed stage: the study needs code_saturne, and a reproduction may leave it
        // out on purpose (REBOUND_WITHOUT_CFD=1).
        let _ = writeln!(
            md,
            "*The study is not in these results (`{}` is missing): `scripts/pipe-flow.sh` writes it; \
             it needs code_saturne and gmsh (`scripts/install-deps.sh`), and `reproduce-all.sh` runs \
             its quick mode unless `REBOUND_WITHOUT_CFD=1`.*\n",
            dir.join("summary.csv").display()
        );
        return Ok(());
    };
    if dir.ends_with(PIPE_FLOW_QUICK) {
        md.push_str(
            "**Quick mode only** (`scripts/pipe-flow.sh --quick`: 400 particles, 0.1 s before a 0.1 s \
             window, no checks): the full study (`scripts/pipe-flow.sh`) has not been run into these results.\n\n",
        );
    }
    let comparisons = Rows::read(&dir.join("comparisons.csv"))?.unwrap_or_default();
    let run = run_toml(&dir);
    md.push_str(
        "The question Radenkovic & Simonin leave open: how does the anisotropy of a rough wall act \
         in a particle-laden pipe flow? `scripts/pipe-flow.sh` answers it in code_saturne 6.0.2 \
         (docs/pipe-flow.md): air at 20 m/s in a horizontal 50 mm pipe (k-ε RANS, a periodic section \
         4 D long, meshed by gmsh), glass beads of 100 and 200 µm (2500 kg/m³, one-way coupled, gravity, \
         code_saturne's Langevin dispersion), every wall hit through roughwall with the Sec. 4 \
         glass–steel law. All walls start from the same particles, sampled after they travelled \
         about 170 D. Values are means over the sampling window ± one standard error (jackknife over \
         20 batches of particles); differences are paired.\n\n",
    );
    if let Some(t) = &run {
        for key in ["fluid", "mesh_coarse", "mesh_fine"] {
            if let Some(v) = t.get(key).and_then(|v| v.as_str()) {
                let _ = writeln!(md, "- {key}: `{}`", v.replace('\n', "; "));
            }
        }
        md.push('\n');
    }
    let by_name: HashMap<&str, &HashMap<String, String>> = summary
        .rows
        .iter()
        .filter_map(|r| Some((r.get("run")?.as_str(), r)))
        .collect();
    let mut diameters: Vec<String> = summary
        .rows
        .iter()
        .filter_map(|r| r.get("diameter_um").cloned())
        .collect();
    diameters.sort_by(|a, b| {
        a.parse::<f64>()
            .unwrap_or(0.0)
            .total_cmp(&b.parse::<f64>().unwrap_or(0.0))
    });
    diameters.dedup();
    for d in &diameters {
        let _ = writeln!(md, "### {d} µm beads\n");
        md.push_str("| wall | model |");
        for (_, h, _) in SHOWN {
            let _ = write!(md, " {h} |");
        }
        md.push_str("\n|---|---|");
        for _ in SHOWN {
            md.push_str("---|");
        }
        md.push('\n');
        for (wall, wall_name) in WALL_NAMES {
            for model in ["paper", "calibrated", "sh1999"] {
                let name = format!("{d}um-{wall}-{model}");
                let Some(r) = by_name.get(name.as_str()) else {
                    continue;
                };
                let model_name = match (wall, model) {
                    ("smooth", _) => "–",
                    (_, "paper") => "Radenkovic–Simonin",
                    (_, "calibrated") => "calibrated",
                    _ => "Sommerfeld–Huber 1999",
                };
                let _ = write!(md, "| {wall_name} | {model_name} |");
                for (q, _, digits) in SHOWN {
                    let _ = write!(
                        md,
                        " {} |",
                        pm(num(r, q), num(r, &format!("{q}_se")), digits)
                    );
                }
                md.push('\n');
            }
        }
        md.push('\n');
        // The differences the issue asks for.
        md.push_str("Differences (a − b, paired):\n\n| a − b |");
        for (_, h, _) in SHOWN {
            let _ = write!(md, " {h} |");
        }
        md.push_str("\n|---|");
        for _ in SHOWN {
            md.push_str("---|");
        }
        md.push('\n');
        let pairs = [
            ("axial", "iso", "paper"),
            ("circ", "iso", "paper"),
            ("circ", "axial", "paper"),
            ("axial", "iso", "calibrated"),
            ("circ", "iso", "calibrated"),
            ("iso", "smooth", "paper"),
            ("axial", "smooth", "paper"),
            ("circ", "smooth", "paper"),
        ];
        for (a, b, m) in pairs {
            let an = format!("{d}um-{a}-{m}");
            let bn = format!("{d}um-{b}-{}", if b == "smooth" { "paper" } else { m });
            let rows: Vec<&HashMap<String, String>> = comparisons
                .rows
                .iter()
                .filter(|r| r.get("a") == Some(&an) && r.get("b") == Some(&bn))
                .collect();
            if rows.is_empty() {
                continue;
            }
            let _ = write!(md, "| {a} − {b} ({m}) |");
            for (q, _, digits) in SHOWN {
                let cell = rows
                    .iter()
                    .find(|r| r.get("quantity").map(String::as_str) == Some(q))
                    .map_or("–".into(), |r| {
                        pm(num(r, "difference"), num(r, "se"), digits)
                    });
                let _ = write!(md, " {cell} |");
            }
            md.push('\n');
        }
        md.push('\n');
        answer(md, d, &comparisons);
        trends(md, d, &comparisons);
        settled(md, d, &by_name);
    }
    checks(md, &comparisons);
    if dir.join("concentration_100um.svg").is_file() {
        let rel = if dir.ends_with(PIPE_FLOW_QUICK) {
            PIPE_FLOW_QUICK
        } else {
            PIPE_FLOW
        };
        let _ = writeln!(
            md,
            "![Concentration profiles of the 100 µm beads]({rel}/concentration_100um.svg)\n"
        );
    }
    md.push_str(
        "Figures: `concentration_<d>um.svg`, `velocity_<d>um.svg`, `wall_hits_<d>um.svg`; \
         tables: `summary.csv`, `profiles.csv`, `distributions.csv`, `comparisons.csv` (all under \
         `pipe-flow/`). \
         Erosion is Finnie's ideal micro-cutting (flow stress 1 GPa, ψ = K = 2): compare walls by it, \
         not absolute wear rates.\n\n",
    );
    Ok(())
}

/// The lay's effect in a sentence: the anisotropic walls against each other and against the
/// isotropic wall of the same mean Δγ (the paper's model).
fn answer(md: &mut String, d: &str, c: &Rows) {
    let values = |a: &str, b: &str, q: &str| -> Option<(f64, f64, f64)> {
        let r = c.rows.iter().find(|r| {
            r.get("a").map(String::as_str) == Some(a)
                && r.get("b").map(String::as_str) == Some(b)
                && r.get("quantity").map(String::as_str) == Some(q)
        })?;
        Some((num(r, "value_a")?, num(r, "value_b")?, num(r, "se")?))
    };
    let (circ, axial, iso) = (
        format!("{d}um-circ-paper"),
        format!("{d}um-axial-paper"),
        format!("{d}um-iso-paper"),
    );
    let mut parts = Vec::new();
    for (q, what) in [
        ("collisions_per_m", "the collision frequency"),
        ("rms_ur_m_s", "the wall-normal fluctuations"),
        ("erosion_um_per_t", "the erosion"),
        ("mean_ux_m_s", "the mean axial velocity"),
    ] {
        let (Some((vc, va, _)), Some((_, vi, _))) =
            (values(&circ, &axial, q), values(&axial, &iso, q))
        else {
            continue;
        };
        let Some((d_ca, se_ca)) = diff(c, &circ, &axial, q) else {
            continue;
        };
        parts.push(format!(
            "{what} {:.2}× (circumferential − axial {d_ca:+.3} ± {se_ca:.3}; axial {:+.0} %, \
             circumferential {:+.0} % against isotropic)",
            vc / va,
            100.0 * (va / vi - 1.0),
            100.0 * (vc / vi - 1.0)
        ));
    }
    if !parts.is_empty() {
        let _ = writeln!(
            md,
            "**The lay's effect ({d} µm, paper's model).** Turning the same (3.8°, 7.5°) wall's lay \
             from the axis to the circumference multiplies {}. Particles move mostly along the axis, so \
             their incident plane sees Δξ = 3.8° when the lay is along the axis and Δζ = 7.5° when it \
             goes around: the isotropic wall of the same mean Δγ lies between. The calibrated model's \
             differences are in the table above.\n",
            parts.join("; ")
        );
    }
}

/// A note where the smooth wall's beads settled into a bed on the bottom.
fn settled(md: &mut String, d: &str, by_name: &HashMap<&str, &HashMap<String, String>>) {
    let Some(r) = by_name.get(format!("{d}um-smooth-paper").as_str()) else {
        return;
    };
    let (Some(lower), Some(height), Some(alpha)) = (
        num(r, "bottom_half_fraction"),
        num(r, "mean_height_over_r"),
        num(r, "mean_alpha_in_deg"),
    ) else {
        return;
    };
    if lower > 0.95 {
        let _ = writeln!(
            md,
            "**Caveat on these verdicts:** on the smooth wall the {d} µm beads settle into a layer \
             on the bottom (lower half {lower:.3}, mean height {height:.2} R) that bounces along it \
             at {alpha:.2}° on average, in the slow flow of the first cells (its velocity moves with \
             the mesh: see the checks below). Its grazing contacts count as collisions, and the \
             rough walls lift the beads into the faster core, so \"isotropic − smooth\" compares a \
             suspension with a sliding bed. The published trends compare suspensions that stay \
             airborne on both walls; with k-ε RANS, Langevin dispersion, no lift force and a \
             smooth wall, code_saturne does not keep these beads airborne.\n"
        );
    }
}

/// One comparison's difference and SE.
fn diff(c: &Rows, a: &str, b: &str, q: &str) -> Option<(f64, f64)> {
    let r = c.rows.iter().find(|r| {
        r.get("a").map(String::as_str) == Some(a)
            && r.get("b").map(String::as_str) == Some(b)
            && r.get("quantity").map(String::as_str) == Some(q)
    })?;
    Some((num(r, "difference")?, num(r, "se")?))
}

/// The published trends of horizontal pneumatic conveying over rough walls (Sommerfeld &
/// Huber 1999; Huber & Sommerfeld 1998; Kussin & Sommerfeld 2002), against this study's
/// isotropic wall minus the smooth one.
fn trends(md: &mut String, d: &str, c: &Rows) {
    let (a, b) = (format!("{d}um-iso-paper"), format!("{d}um-smooth-paper"));
    let claims = [
        (
            "roughness keeps particles suspended (higher mean height)",
            "mean_height_over_r",
            1.0,
        ),
        (
            "roughness lowers the mean particle velocity",
            "mean_ux_m_s",
            -1.0,
        ),
        (
            "roughness raises the wall-normal velocity fluctuations",
            "rms_ur_m_s",
            1.0,
        ),
        (
            "roughness raises the wall-collision frequency",
            "collisions_per_m",
            1.0,
        ),
    ];
    let _ = writeln!(
        md,
        "Published trends (the experiments behind the Sommerfeld–Huber model: Huber & \
         Sommerfeld 1998, Sommerfeld & Huber 1999) against this study ({d} µm, isotropic − \
         smooth):\n"
    );
    for (claim, q, sign) in claims {
        let verdict = match diff(c, &a, &b, q) {
            Some((v, se)) if v * sign > 3.0 * se => format!("**agrees**: {v:+.3} ± {se:.3}"),
            Some((v, se)) if v * sign < -3.0 * se => {
                format!("**does not agree**: {v:+.3} ± {se:.3}")
            }
            Some((v, se)) => format!("no significant difference: {v:+.3} ± {se:.3}"),
            None => "–".into(),
        };
        let _ = writeln!(md, "- {claim}: {verdict}");
    }
    md.push('\n');
}

/// The mesh and development checks (full mode only).
fn checks(md: &mut String, c: &Rows) {
    let rows: Vec<&HashMap<String, String>> = c
        .rows
        .iter()
        .filter(|r| {
            r.get("a")
                .is_some_and(|a| a.ends_with("-fine") || a.ends_with("-late"))
        })
        .collect();
    if rows.is_empty() {
        md.push_str("*The mesh and development checks run in the full mode only (`scripts/pipe-flow.sh`).*\n\n");
        return;
    }
    md.push_str("Checks (200 µm, paper's model): a finer mesh (12 cells per quarter and ring, 30 along the axis) for the isotropic and the smooth wall, and a sampling window 0.4 s later for the isotropic wall, each minus the study's run; |z| < 3 means no significant difference, and the relative difference is what the check moves a value by, to set beside the differences between walls above.\n\n| check | quantity | difference | relative | z |\n|---|---|---|---|---|\n");
    for r in rows {
        let check = match (r["a"].ends_with("-fine"), r["a"].contains("-smooth-")) {
            (true, true) => "finer mesh, smooth wall",
            (true, false) => "finer mesh, isotropic wall",
            _ => "later window, isotropic wall",
        };
        let q = r.get("quantity").map_or("", String::as_str);
        let relative = match (num(r, "difference"), num(r, "value_b")) {
            (Some(d), Some(b)) if b != 0.0 => format!("{:+.1} %", 100.0 * d / b.abs()),
            _ => "–".into(),
        };
        let _ = writeln!(
            md,
            "| {check} | {q} | {} | {relative} | {} |",
            pm(num(r, "difference"), num(r, "se"), 3),
            num(r, "z").map_or("–".into(), |z| format!("{z:.1}"))
        );
    }
    md.push('\n');
}
