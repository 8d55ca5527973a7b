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
const SHOWN: [(&str, &str, usize); 8] = [
    ("collisions_per_m", "collisions per m", 3),
    ("mean_ux_m_s", "mean u_x (m/s)", 3),
    ("rms_ur_m_s", "rms u_r (m/s)", 3),
    ("mean_height_over_r", "mean height / R", 3),
    ("bottom_half_fraction", "lower half", 3),
    ("mean_alpha_in_deg", "mean α⁻ (°)", 2),
    ("mean_alpha_element_deg", "mean α on the facet (°)", 2),
    (
        "erosion_finnie_um_per_t",
        "Finnie erosion at the facet (µm/t)",
        1,
    ),
];

/// The walls in table order: the smooth limit, the technically smooth walls, the rough ones.
const WALLS: [&str; 7] = ["smooth", "ts0.5", "ts1", "ts2", "iso", "axial", "circ"];

/// The reference walls the published trends are tested against: the technically smooth ones,
/// and the smooth limit.
const SMOOTH_REFERENCES: [&str; 4] = ["ts0.5", "ts1", "ts2", "smooth"];

/// A wall's name in the tables, with the deviations its run used (`summary.csv`).
fn wall_label(wall: &str, row: &HashMap<String, String>) -> String {
    let (xi, ze) = (
        num(row, "delta_xi_deg").unwrap_or(f64::NAN),
        num(row, "delta_zeta_deg").unwrap_or(f64::NAN),
    );
    match wall {
        "smooth" => "smooth (Δγ = 0)".into(),
        w if w.starts_with("ts") => format!("technically smooth, Δγ = {xi}°"),
        "iso" => format!("isotropic ({xi:.2}°, {ze:.2}°)"),
        "axial" => format!("({xi:.2}°, {ze:.2}°), lay along the axis"),
        "circ" => format!("({xi:.2}°, {ze:.2}°), lay around the circumference"),
        other => other.into(),
    }
}

/// A wall's short name in the differences.
fn short(wall: &str) -> String {
    match wall {
        w if w.starts_with("ts") => format!("tech. smooth {}°", &w[2..]),
        other => other.into(),
    }
}

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
    let sensitivity = Rows::read(&dir.join("sensitivity.csv"))?.unwrap_or_default();
    let run = run_toml(&dir);
    let _ = write!(
        md,
        "The question Radenkovic & Simonin leave open: how does the anisotropy of a rough wall act \
         in a particle-laden pipe flow? `scripts/pipe-flow.sh` answers it in code_saturne 6.0.2 \
         (docs/pipe-flow.md): air at 20 m/s in a horizontal 50 mm pipe (k-ε RANS, a periodic section \
         4 D long, meshed by gmsh), glass beads of 100 and 200 µm (2500 kg/m³, one-way coupled, gravity, \
         code_saturne's {} Langevin dispersion model, the Saffman–Mei and the Magnus lift, each bead's spin \
         carried between hits), every wall hit through roughwall with the Sec. 4 \
         glass–steel law. All walls start from the same particles, sampled after they travelled \
         about 170 D. Values are means over the sampling window ± one standard error (jackknife over \
         20 batches of particles); differences are paired.\n\n",
        langevin_model(&sensitivity)
    );
    if let Some(t) = &run {
        for key in ["fluid", "mesh_coarse", "mesh_fine", "mesh_nearwall"] {
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
        for wall in WALLS {
            for model in ["paper", "calibrated", "sh1999"] {
                let name = format!("{d}um-{wall}-{model}");
                let Some(r) = by_name.get(name.as_str()) else {
                    continue;
                };
                let wall_name = wall_label(wall, r);
                let model_name = match (wall, model) {
                    ("smooth", _) => "–",
                    (w, _) if w.starts_with("ts") => "Radenkovic–Simonin",
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
            ("iso", "ts1", "paper"),
            ("axial", "ts1", "paper"),
            ("circ", "ts1", "paper"),
            ("ts0.5", "smooth", "paper"),
            ("ts1", "smooth", "paper"),
            ("ts2", "smooth", "paper"),
            ("iso", "smooth", "paper"),
            ("axial", "smooth", "paper"),
            ("circ", "smooth", "paper"),
        ];
        for (a, b, m) in pairs {
            let an = format!("{d}um-{a}-{m}");
            let smooth_limit = b == "smooth" || b.starts_with("ts");
            let bn = format!("{d}um-{b}-{}", if smooth_limit { "paper" } else { m });
            let rows: Vec<&HashMap<String, String>> = comparisons
                .rows
                .iter()
                .filter(|r| r.get("a") == Some(&an) && r.get("b") == Some(&bn))
                .collect();
            if rows.is_empty() {
                continue;
            }
            let _ = write!(md, "| {} − {} ({m}) |", short(a), short(b));
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
        answer(md, d, &comparisons, &by_name);
        against_earlier_versions(md, d, &comparisons);
        erosion(md, d, &comparisons);
        trends(md, d, &comparisons);
        settled(md, d, &by_name);
    }
    switches(md, &sensitivity);
    costs(md, &Rows::read(&dir.join("costs.csv"))?.unwrap_or_default());
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
         Erosion is each law's volume at the impact angle on the facet struck (Finnie's ideal \
         micro-cutting with flow stress 1 GPa, ψ = K = 2; Oka with Hv 1.8 GPa and SiO₂ constants; \
         DNV RP-O501 for carbon steel): compare walls and laws by it, not absolute wear rates.\n\n",
    );
    Ok(())
}

/// The lay's effect in a sentence: the anisotropic walls against each other and against the
/// isotropic wall of the same mean Δγ (the paper's model).
fn answer(md: &mut String, d: &str, c: &Rows, by_name: &HashMap<&str, &HashMap<String, String>>) {
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
        ("erosion_finnie_um_per_t", "Finnie's erosion at the facet"),
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
    let deviations = by_name
        .get(axial.as_str())
        .and_then(|r| Some((num(r, "delta_xi_deg")?, num(r, "delta_zeta_deg")?)));
    if let (false, Some((xi, ze))) = (parts.is_empty(), deviations) {
        let _ = writeln!(
            md,
            "**The lay's effect ({d} µm, paper's model).** Turning the same ({xi:.2}°, {ze:.2}°) \
             wall's lay (what a {d} µm bead sees of the Sec. 4 wall) from the axis to the \
             circumference multiplies {}. Particles move mostly along the axis, so their incident \
             plane sees Δξ = {xi:.2}° when the lay is along the axis and Δζ = {ze:.2}° when it goes \
             around: the isotropic wall of the same mean Δγ lies between. The calibrated model's \
             differences are in the table above.\n",
            parts.join("; ")
        );
    }
}

/// What the first version of this study found (results/REPORT.md at commit fecd09f9,
/// 2026-11-27: the smooth wall Δγ = 0 as the baseline, the 500 µm bead's (3.8°, 7.5°) for
/// every size, Finnie at the mean wall's impact angle): per diameter (µm), the lay ratio
/// circumferential/axial of the collision frequency, of the wall-normal fluctuations and of
/// Finnie's erosion. Quoted so that the report says which conclusions held (issue 40, part 7).
const FIRST_VERSION: [(&str, f64, f64, f64); 2] =
    [("100", 1.91, 1.82, 2.45), ("200", 1.63, 1.54, 1.52)];

/// The second version (results/REPORT.md at commit 61a9939a, 2026-11-29: technically smooth
/// walls, each size's own deviations, erosion at the facet; no spin, no lift): per diameter
/// (µm), the same lay ratios, Finnie's erosion at the mean wall and at the facet.
const SECOND_VERSION: [(&str, f64, f64, f64, f64); 2] = [
    ("100", 2.07, 1.97, 2.62, 2.20),
    ("200", 1.74, 1.62, 1.54, 1.43),
];

/// The third version (results/REPORT.md at commit 8a03f822, 2026-11-29: the second with spin
/// and both lifts, code_saturne's simplified Langevin model): the same lay ratios.
const THIRD_VERSION: [(&str, f64, f64, f64, f64); 2] = [
    ("100", 2.09, 1.93, 2.37, 2.08),
    ("200", 1.62, 1.51, 1.30, 1.22),
];

/// The lay ratios now against the earlier versions'.
fn against_earlier_versions(md: &mut String, d: &str, c: &Rows) {
    let Some(&(_, collisions, rms, erosion)) = FIRST_VERSION.iter().find(|f| f.0 == d) else {
        return;
    };
    let Some(&(_, c2, r2, e2_wall, e2_facet)) = SECOND_VERSION.iter().find(|f| f.0 == d) else {
        return;
    };
    let Some(&(_, c3, r3, e3_wall, e3_facet)) = THIRD_VERSION.iter().find(|f| f.0 == d) else {
        return;
    };
    let (circ, axial) = (format!("{d}um-circ-paper"), format!("{d}um-axial-paper"));
    let ratio = |q: &str| {
        c.rows
            .iter()
            .find(|r| {
                r.get("a") == Some(&circ)
                    && r.get("b") == Some(&axial)
                    && r.get("quantity").map(String::as_str) == Some(q)
            })
            .and_then(|r| num(r, "ratio"))
    };
    let (Some(c_now), Some(r_now), Some(e_wall), Some(e_facet)) = (
        ratio("collisions_per_m"),
        ratio("rms_ur_m_s"),
        ratio("erosion_finnie_mean_wall_um_per_t"),
        ratio("erosion_finnie_um_per_t"),
    ) else {
        return;
    };
    let held = [c_now, r_now, e_wall, e_facet].iter().all(|&r| r > 1.0);
    let _ = writeln!(
        md,
        "**Against the earlier versions of this study** ({d} µm, lay ratio circumferential over \
         axial; first, commit fecd09f9: smooth baseline, (3.8°, 7.5°) for every size, Finnie at \
         the mean wall; second, commit 61a9939a: technically smooth walls, each size's own \
         deviations, erosion at the facet, no spin and no lift; third, commit 8a03f822: with spin \
         and both lifts, code_saturne's simplified Langevin model; now: its complete model): \
         collision frequency {collisions:.2} → {c2:.2} → {c3:.2} → {c_now:.2}; wall-normal \
         fluctuations {rms:.2} → {r2:.2} → {r3:.2} → {r_now:.2}; Finnie's erosion at the mean \
         wall {erosion:.2} → {e2_wall:.2} → {e3_wall:.2} → {e_wall:.2}, at the facet struck \
         {e2_facet:.2} → {e3_facet:.2} → {e_facet:.2}. {} The \
         sensitivity table below says what each switch moves.\n",
        if held {
            "The direction of every effect held: the lay around the circumference still raises \
             each of them."
        } else {
            "**Not every direction held**: a ratio at or below 1 above is an effect the lay no \
             longer has."
        }
    );
}

/// A note on the walls whose beads settled into a bed on the bottom (more than 95 % of the
/// samples in the lower half): the smooth limit and any technically smooth wall.
fn settled(md: &mut String, d: &str, by_name: &HashMap<&str, &HashMap<String, String>>) {
    let mut beds = Vec::new();
    let mut airborne = Vec::new();
    for wall in SMOOTH_REFERENCES {
        let Some(r) = by_name.get(format!("{d}um-{wall}-paper").as_str()) else {
            continue;
        };
        let (Some(lower), Some(height), Some(alpha)) = (
            num(r, "bottom_half_fraction"),
            num(r, "mean_height_over_r"),
            num(r, "mean_alpha_in_deg"),
        ) else {
            continue;
        };
        let what = format!(
            "{} (lower half {lower:.3}, mean height {height:.2} R, mean α⁻ {alpha:.2}°)",
            short(wall)
        );
        if lower > 0.95 {
            beds.push(what);
        } else {
            airborne.push(what);
        }
    }
    if !beds.is_empty() {
        let _ = writeln!(
            md,
            "**Beds on the bottom ({d} µm):** on {} the beads settle into a layer on the bottom \
             that bounces along it, in the slow flow of the first cells (its velocity moves with the \
             mesh: see the checks below). Its grazing contacts count as collisions, so a rough wall \
             against such a wall compares a suspension with a sliding bed.{}\n",
            beds.join("; "),
            if airborne.is_empty() {
                String::new()
            } else {
                format!(" The beads stay suspended on {}.", airborne.join("; "))
            }
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

/// What Kussin & Sommerfeld (2002, Exp. Fluids 33, 143–159: a horizontal channel 35 mm high,
/// glass beads of 60 µm to 1 mm at 10–25 m/s, with exchangeable wall plates) state in their
/// abstract, the only part of the paper reachable here (no tabulated profile was found):
/// "It was shown that wall roughness decreases the particle mean velocity and enhances
/// fluctuating velocities due to irregular wall bouncing and an increase in wall collision
/// frequency, i.e. reduction in mean free path. Thereby, the larger particles are mainly more
/// uniformly distributed across the channel, and gravitational settling is reduced." Each
/// claim is tested as this study's isotropic rough wall minus each technically smooth wall and
/// the smooth limit, in a pipe, not their channel: a check of sign, not of value.
const CLAIMS: [(&str, &str, f64); 6] = [
    (
        "wall roughness decreases the particle mean velocity",
        "mean_ux_m_s",
        -1.0,
    ),
    (
        "[wall roughness] enhances fluctuating velocities (axial)",
        "rms_ux_m_s",
        1.0,
    ),
    (
        "[wall roughness] enhances fluctuating velocities (wall-normal)",
        "rms_ur_m_s",
        1.0,
    ),
    (
        "an increase in wall collision frequency",
        "collisions_per_m",
        1.0,
    ),
    (
        "gravitational settling is reduced (mean height)",
        "mean_height_over_r",
        1.0,
    ),
    (
        "more uniformly distributed (fewer beads in the lower half)",
        "bottom_half_fraction",
        -1.0,
    ),
];

/// The stated findings ([`CLAIMS`]) against this study.
fn trends(md: &mut String, d: &str, c: &Rows) {
    let a = format!("{d}um-iso-paper");
    let references: Vec<&str> = SMOOTH_REFERENCES
        .into_iter()
        .filter(|w| {
            c.rows
                .iter()
                .any(|r| r.get("b") == Some(&format!("{d}um-{w}-paper")))
        })
        .collect();
    if references.is_empty() {
        return;
    }
    let _ = write!(
        md,
        "What Kussin & Sommerfeld (2002) state in their abstract about wall roughness in horizontal \
         conveying (glass beads of 60 µm to 1 mm; no tabulated profile of theirs is reachable, so \
         these are checks of sign in this pipe, not of value in their channel), against this study \
         ({d} µm, the isotropic rough wall minus each smoother wall; **agrees** or **does not \
         agree** beyond 3 standard errors): \"It was shown that wall roughness decreases the \
         particle mean velocity and enhances fluctuating velocities due to irregular wall bouncing \
         and an increase in wall collision frequency, i.e. reduction in mean free path. Thereby, the \
         larger particles are mainly more uniformly distributed across the channel, and \
         gravitational settling is reduced.\"\n\n| stated finding |"
    );
    for w in &references {
        let _ = write!(md, " iso − {} |", short(w));
    }
    md.push_str("\n|---|");
    for _ in &references {
        md.push_str("---|");
    }
    md.push('\n');
    for (claim, q, sign) in CLAIMS {
        let _ = write!(md, "| {claim} |");
        for w in &references {
            let verdict = match diff(c, &a, &format!("{d}um-{w}-paper"), q) {
                Some((v, se)) if v * sign > 3.0 * se => format!("**agrees**: {v:+.3} ± {se:.3}"),
                Some((v, se)) if v * sign < -3.0 * se => {
                    format!("**does not agree**: {v:+.3} ± {se:.3}")
                }
                Some((v, se)) => format!("no significant difference: {v:+.3} ± {se:.3}"),
                None => "–".into(),
            };
            let _ = write!(md, " {verdict} |");
        }
        md.push('\n');
    }
    md.push('\n');
}

/// The lay's effect on erosion by each law, at the facet struck and on the mean wall: the
/// ratio circumferential / axial with its paired standard error (`comparisons.csv` `ratio`).
fn erosion(md: &mut String, d: &str, c: &Rows) {
    let (circ, axial) = (format!("{d}um-circ-paper"), format!("{d}um-axial-paper"));
    let ratio = |q: &str| -> Option<(f64, f64)> {
        let r = c.rows.iter().find(|r| {
            r.get("a") == Some(&circ)
                && r.get("b") == Some(&axial)
                && r.get("quantity").map(String::as_str) == Some(q)
        })?;
        Some((num(r, "ratio")?, num(r, "ratio_se")?))
    };
    let mut rows = Vec::new();
    for (law, name) in [("finnie", "Finnie"), ("oka", "Oka"), ("dnv", "DNV")] {
        let facet = ratio(&format!("erosion_{law}_um_per_t"));
        let wall = ratio(&format!("erosion_{law}_mean_wall_um_per_t"));
        let cell =
            |x: Option<(f64, f64)>| x.map_or("–".into(), |(v, se)| format!("{v:.2} ± {se:.2}"));
        if facet.is_some() || wall.is_some() {
            rows.push(format!("| {name} | {} | {} |", cell(facet), cell(wall)));
        }
    }
    if rows.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "Erosion, lay around the circumference over lay along the axis ({d} µm, paper's model; \
         paired jackknife error), with each law at the impact angle on the facet struck \
         (`rw_element_impact_angle`) and on the mean wall:\n\n| law | at the facet | at the mean wall |\n|---|---|---|\n{}\n",
        rows.join("\n")
    );
}

/// What the study does not model, so no switch: named, with no number.
const NOT_MODELLED: &str = "a near-wall dispersion treatment (the near-wall mesh is the \
    sensitivity to near-wall resolution instead), wall-corrected lift, two-way coupling, \
    particle–particle collisions";

/// Which of code_saturne's Langevin models the study ran, from its sensitivity switches
/// (`sensitivity.csv`): the Langevin switch runs the other one.
fn langevin_model(sensitivity: &Rows) -> &'static str {
    let switched_to_complete = sensitivity
        .rows
        .iter()
        .any(|r| r.get("switch").map(String::as_str) == Some("complete-langevin"));
    if switched_to_complete {
        "simplified"
    } else {
        "complete"
    }
}

/// The sensitivity table: each physics switch's change of the lay ratio (circumferential over
/// axial) of the collision frequency, the wall-normal fluctuations and the erosion
/// (`sensitivity.csv`).
fn switches(md: &mut String, s: &Rows) {
    if s.rows.is_empty() {
        return;
    }
    let name = |k: &str| match k {
        "no-spin" => "no spin (0 at every hit, as code_saturne has it)".to_string(),
        "no-saffman" => "no Saffman–Mei lift".to_string(),
        "no-magnus" => "no Magnus lift".to_string(),
        "complete-langevin" => "code_saturne's complete Langevin model".to_string(),
        "simplified-langevin" => {
            "code_saturne's simplified Langevin model instead of the complete one".to_string()
        }
        "near-wall" => {
            "near-wall mesh (first cell at y⁺ ≈ 10, not 33–42; own flow and particles)".to_string()
        }
        "no-dispersion" => "no Langevin dispersion (the fluid seen is the cell's mean)".to_string(),
        "sec4-deviations" => {
            "the 500 µm bead's deviations (3.8°, 7.5°) instead of this size's own".to_string()
        }
        other => other.to_string(),
    };
    md.push_str(
        "**Sensitivity** (paper's model): each switch's change of the lay ratio, circumferential \
         over axial, the study's ratio → the switched one (change ± paired jackknife SE; the four \
         runs share their particles):\n\n| beads | switch | collisions per m | rms u_r | Finnie erosion at the facet | Oka | DNV |\n|---|---|---|---|---|---|---|\n",
    );
    let mut keys: Vec<(String, String)> = s
        .rows
        .iter()
        .filter_map(|r| Some((r.get("diameter_um")?.clone(), r.get("switch")?.clone())))
        .collect();
    keys.dedup();
    for (d, k) in keys {
        let _ = write!(md, "| {d} µm | {} |", name(&k));
        for q in [
            "collisions_per_m",
            "rms_ur_m_s",
            "erosion_finnie_um_per_t",
            "erosion_oka_um_per_t",
            "erosion_dnv_um_per_t",
        ] {
            let cell = s
                .rows
                .iter()
                .find(|r| {
                    r.get("diameter_um") == Some(&d)
                        && r.get("switch") == Some(&k)
                        && r.get("quantity").map(String::as_str) == Some(q)
                })
                .and_then(|r| {
                    Some(format!(
                        "{:.2} → {:.2} ({:+.2} ± {:.2})",
                        num(r, "ratio_study")?,
                        num(r, "ratio_switch")?,
                        num(r, "change")?,
                        num(r, "change_se")?
                    ))
                })
                .unwrap_or_else(|| "–".into());
            let _ = write!(md, " {cell} |");
        }
        md.push('\n');
    }
    // The switches that move the answer (the collision ratio) beyond 3 standard errors: a
    // physics choice the study's numbers depend on.
    let beyond: Vec<String> = s
        .rows
        .iter()
        .filter(|r| r.get("quantity").map(String::as_str) == Some("collisions_per_m"))
        .filter_map(|r| {
            let (c, se) = (num(r, "change")?, num(r, "change_se")?);
            let (d, k) = (r.get("diameter_um")?, r.get("switch")?);
            (c.abs() > 3.0 * se).then(|| format!("{d} µm {k} ({c:+.2} ± {se:.2})"))
        })
        .collect();
    if !beyond.is_empty() {
        let ran = langevin_model(s);
        let other = if ran == "complete" {
            "simplified"
        } else {
            "complete"
        };
        let _ = writeln!(
            md,
            "\nSwitches that move the collision ratio by more than 3 standard errors: {}. The \
             answer depends on these physics choices beyond its statistical error. The study runs \
             the {ran} Langevin model, spin, both lifts and each size's own deviations; where the \
             {other} Langevin model is among the switches above, it would give an answer that \
             differs from the study's beyond its error.",
            beyond.join("; ")
        );
    }
    let _ = writeln!(
        md,
        "\nNot modelled, so not in this table: {NOT_MODELLED}.\n"
    );
}

/// What the lifts and the spin cost per particle step (`costs.csv`), over the study's own
/// runs (`main`, all three on): the mean, and the range over runs.
fn costs(md: &mut String, c: &Rows) {
    let main: Vec<&HashMap<String, String>> = c
        .rows
        .iter()
        .filter(|r| r.get("kind").map(String::as_str) == Some("main"))
        .collect();
    if main.is_empty() {
        return;
    }
    let stat = |k: &str| {
        let v: Vec<f64> = main.iter().filter_map(|r| num(r, k)).collect();
        let mean = v.iter().sum::<f64>() / v.len().max(1) as f64;
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (mean, lo, hi)
    };
    let (lift, l0, l1) = stat("lift_ns_per_particle_step");
    let (spin, s0, s1) = stat("spin_ns_per_particle_step");
    let (step, t0, t1) = stat("step_ns_per_particle_step");
    let (share, f0, f1) = stat("forces_share");
    let _ = writeln!(
        md,
        "**What spin and lift cost** ({} runs of the study, one MPI rank each, two at a time on \
         two cores; `costs.csv`): the two lifts {lift:.0} ns per particle step ({l0:.0}–{l1:.0}), the \
         spin's relaxation {spin:.0} ns ({s0:.0}–{s1:.0}), against {:.1} µs for the whole particle \
         step ({:.1}–{:.1}: tracking, wall hits, dispersion and these): {:.1} % of it \
         ({:.1}–{:.1} %).\n",
        main.len(),
        step / 1e3,
        t0 / 1e3,
        t1 / 1e3,
        100.0 * share,
        100.0 * f0,
        100.0 * f1
    );
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
