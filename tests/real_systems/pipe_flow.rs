//! The pipe-flow study in code_saturne (issue 30), coarse: `examples/code_saturne/pipe/
//! run_checks.sh` runs a periodic pipe section (gmsh mesh, k-ε RANS, frozen) with 300 glass
//! beads of 150 µm on four elastic walls, then on 2 ranks and without dispersion, and
//! `rebound pipe-stats` reduces the runs. This test checks the physics, not that it ran:
//! * a smooth elastic wall conserves the particle's kinetic energy at every hit (and
//!   reflects it specularly: α⁺ = α⁻);
//! * rough walls raise the rebound angle over the impact angle, and the lay decides by how
//!   much as the models predict: particles move mostly along the axis, so the roughness in
//!   their incident plane is Δξ = 3.8° with the lay along the axis and Δζ = 7.5° with the lay
//!   around the circumference, which rebounds them more steeply, more often, with faster
//!   wall-normal fluctuations;
//! * rough walls keep the particles suspended (higher, faster across the pipe) where the
//!   smooth wall lets them settle;
//! * without code_saturne's dispersion, 1 and 2 MPI ranks give the same wall hits for the
//!   same keys (particle id, collision index), with the same spins (carried between hits in
//!   a table the ranks exchange, with both lifts on), and the same per-particle statistics,
//!   to round-off; with dispersion, the same statistics within their standard errors.
//!
//! `pipe_forces.rs` checks the spin and the lifts on the same study.

use crate::common::*;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;
use std::process::Command;

pub(crate) fn rows(path: &Path) -> Vec<HashMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records()
        .map(|rec| {
            let rec = rec.unwrap();
            header
                .iter()
                .cloned()
                .zip(rec.iter().map(String::from))
                .collect()
        })
        .collect()
}

pub(crate) fn num(row: &HashMap<String, String>, key: &str) -> f64 {
    row[key]
        .parse()
        .unwrap_or_else(|_| panic!("{key} = {:?}", row[key]))
}

/// Every hit of a run, keyed by (particle id, collision index).
pub(crate) fn hits(run: &Path) -> BTreeMap<(u64, u64), HashMap<String, String>> {
    let mut out = BTreeMap::new();
    for e in std::fs::read_dir(run).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if name.starts_with("hits_rank") {
            for r in rows(&p) {
                let key = (
                    num(&r, "particle_id") as u64,
                    num(&r, "collision_index") as u64,
                );
                assert!(out.insert(key, r).is_none(), "key {key:?} twice");
            }
        }
    }
    out
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

/// The coarse study of `run_checks.sh`, run once for the tests of this file and of
/// `pipe_forces.rs` (in target/, replaced on the next run).
pub(crate) fn checks_study() -> &'static Path {
    static STUDY: std::sync::OnceLock<std::path::PathBuf> = std::sync::OnceLock::new();
    STUDY.get_or_init(|| {
        crate::require(&["code_saturne", "gmsh", "gfortran", "mpiexec"]);
        let root = repo_root();
        let work = root.join("target/real-systems/pipe-checks");
        crate::run_example_checks(
            &root.join("examples/code_saturne/pipe/run_checks.sh"),
            &work,
            &[("REBOUND_BIN", rebound_bin())],
        );
        work
    })
}

#[test]
fn pipe_flow_physics_and_rank_independence() {
    let work = checks_study();
    let runs = work.join("runs");

    // Energy at every hit of the smooth elastic wall.
    let smooth = hits(&runs.join("150um-smooth-paper"));
    assert!(
        smooth.len() > 50,
        "only {} hits on the smooth wall",
        smooth.len()
    );
    for (key, h) in &smooth {
        let (a, b) = (num(h, "speed_in"), num(h, "speed_out"));
        assert!((a - b).abs() <= 1e-12 * a, "{key:?}: |u| {a} -> {b}");
        let (ai, ao) = (num(h, "alpha_in_deg"), num(h, "alpha_out_deg"));
        assert!((ai - ao).abs() < 1e-6, "{key:?}: alpha {ai} -> {ao}");
        // On a smooth wall the element struck is the wall.
        let ae = num(h, "alpha_element_deg");
        assert!((ae - ai).abs() < 1e-9, "{key:?}: element {ae} vs {ai}");
    }
    // On the rough elastic walls the element struck mirrors the velocity, so its impact
    // angle is half the turn of the velocity: sin α_e = |u⁺ − u⁻|/(2|u|), from the logged
    // α⁻, α⁺ and the deflection δ out of the incident plane.
    for w in ["iso", "axial", "circ"] {
        let rough = hits(&runs.join(format!("150um-{w}-paper")));
        let mut tilted = 0;
        for (key, h) in &rough {
            if num(h, "status") != 0.0 {
                continue;
            }
            let r = |k: &str| num(h, k).to_radians();
            let (ai, ao, dl) = (r("alpha_in_deg"), r("alpha_out_deg"), r("deflection_deg"));
            let turn = ((ao.cos() * dl.cos() - ai.cos()).powi(2)
                + (ao.sin() + ai.sin()).powi(2)
                + (ao.cos() * dl.sin()).powi(2))
            .sqrt();
            let expect = (0.5 * turn).asin().to_degrees();
            let ae = num(h, "alpha_element_deg");
            assert!(
                (ae - expect).abs() < 1e-5,
                "{w} {key:?}: element {ae} vs {expect}"
            );
            tilted += usize::from((ae - num(h, "alpha_in_deg")).abs() > 0.01);
        }
        assert!(
            2 * tilted > rough.len(),
            "{w}: {tilted} of {} hits on a tilted element",
            rough.len()
        );
    }

    let summary: HashMap<String, HashMap<String, String>> = rows(&work.join("stats/summary.csv"))
        .into_iter()
        .map(|r| (r["run"].clone(), r))
        .collect();
    let q = |run: &str, k: &str| {
        let r = &summary[run];
        (num(r, k), num(r, &format!("{k}_se")))
    };
    // Rough walls steepen the rebound; the smooth one does not.
    let (d, _) = q("150um-smooth-paper", "mean_alpha_change_deg");
    assert!(d.abs() < 1e-6, "smooth wall: mean alpha change {d}");
    for w in ["iso", "axial", "circ"] {
        let (v, se) = q(&format!("150um-{w}-paper"), "mean_alpha_change_deg");
        assert!(v > 5.0 * se && v > 0.5, "{w}: mean alpha change {v} ± {se}");
    }

    let comparisons = rows(&work.join("stats/comparisons.csv"));
    let diff = |a: &str, b: &str, quantity: &str| {
        let r = comparisons
            .iter()
            .find(|r| r["a"] == a && r["b"] == b && r["quantity"] == quantity)
            .unwrap_or_else(|| panic!("no comparison {a} - {b} of {quantity}"));
        (num(r, "difference"), num(r, "se"))
    };
    // The lay decides, as the models predict.
    for quantity in ["mean_alpha_change_deg", "collisions_per_m", "rms_ur_m_s"] {
        let (v, se) = diff("150um-circ-paper", "150um-axial-paper", quantity);
        assert!(v > 3.0 * se, "circ - axial {quantity}: {v} ± {se}");
    }
    // Rough walls keep particles suspended.
    for quantity in ["mean_height_over_r", "rms_ur_m_s"] {
        let (v, se) = diff("150um-iso-paper", "150um-smooth-paper", quantity);
        assert!(v > 3.0 * se, "iso - smooth {quantity}: {v} ± {se}");
    }

    // Ranks, dispersion off: the same hits for the same keys, the same tallies.
    let h1 = hits(&runs.join("150um-iso-paper-nodisp-1"));
    let h2 = hits(&runs.join("150um-iso-paper-nodisp-2"));
    assert!(h1.len() > 50, "only {} hits", h1.len());
    assert_eq!(
        h1.keys().collect::<Vec<_>>(),
        h2.keys().collect::<Vec<_>>(),
        "1 and 2 ranks hit the wall with different keys"
    );
    for (key, a) in &h1 {
        let b = &h2[key];
        for col in [
            "y",
            "z",
            "alpha_in_deg",
            "speed_in",
            "speed_out",
            "alpha_out_deg",
            "deflection_deg",
            "wx_in",
            "wy_in",
            "wz_in",
            "wx_out",
            "wy_out",
            "wz_out",
        ] {
            assert!(
                close(num(a, col), num(b, col)),
                "{key:?} {col}: {} (1 rank) vs {} (2 ranks)",
                a[col],
                b[col]
            );
        }
    }
    let p1 = rows(&runs.join("150um-iso-paper-nodisp-1/particles.csv"));
    let p2 = rows(&runs.join("150um-iso-paper-nodisp-2/particles.csv"));
    assert_eq!(p1.len(), 300);
    assert_eq!(p1.len(), p2.len());
    for (a, b) in p1.iter().zip(&p2) {
        for (k, v) in a {
            assert!(
                close(v.parse().unwrap(), num(b, k)),
                "particle {}: {k} {v} vs {}",
                a["particle_id"],
                b[k]
            );
        }
    }
    // Ranks, dispersion on: the same statistics within their standard errors.
    let ranked: Vec<_> = comparisons
        .iter()
        .filter(|r| r["a"] == "150um-iso-paper-2ranks" && r["b"] == "150um-iso-paper")
        .collect();
    assert!(
        ranked.len() >= 10,
        "{} comparisons of 2 ranks with 1",
        ranked.len()
    );
    for r in ranked {
        let (v, se) = (num(r, "difference"), num(r, "se"));
        assert!(
            v.abs() <= 4.5 * se,
            "2 ranks - 1 rank {}: {v} ± {se}",
            r["quantity"]
        );
    }
}

/// `scripts/pipe-flow.sh --quick` (what `reproduce-all.sh` runs) writes every table and
/// figure of the study, and `rebound report` turns them into its section.
#[test]
fn pipe_flow_script_quick_mode_writes_the_study() {
    crate::require(&["code_saturne", "gmsh", "gfortran", "mpiexec"]);
    let root = repo_root();
    let tmp = tempfile::Builder::new()
        .prefix("pipeq")
        .tempdir_in("/tmp")
        .unwrap();
    let results = tmp.path().join("results");
    let out = Command::new("bash")
        .arg(root.join("scripts/pipe-flow.sh"))
        .arg("--quick")
        .env("REBOUND_BIN", rebound_bin())
        .env("REBOUND_RESULTS", &results)
        .env("PIPE_WORK", tmp.path().join("work"))
        .env("ROUGHWALL_LIB", c_library_dir())
        .output()
        .expect("run scripts/pipe-flow.sh --quick");
    assert!(
        out.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let dir = results.join("pipe-flow-quick");
    let summary = rows(&dir.join("summary.csv"));
    assert_eq!(
        summary.len(),
        46,
        "2 diameters x (11 walls and models + 6 switches on 2 lays)"
    );
    // Each bead size rebounds off the rough wall as its own sphere sees it
    // (configs/cases/pipe-wall.toml): more across the lay than the 500 µm bead's 7.5°.
    for (d, zeta) in [(100.0, 8.387), (200.0, 8.352)] {
        let axial = summary
            .iter()
            .find(|r| r["run"] == format!("{d}um-axial-paper"))
            .unwrap();
        assert!(
            (num(axial, "delta_zeta_deg") - zeta).abs() < 0.01,
            "{axial:?}"
        );
        // The technically smooth walls are there, with their Δγ.
        for (w, dg) in [("ts0.5", 0.5), ("ts1", 1.0), ("ts2", 2.0)] {
            let t = summary
                .iter()
                .find(|r| r["run"] == format!("{d}um-{w}-paper"))
                .unwrap();
            assert_eq!(num(t, "delta_xi_deg"), dg);
        }
        // Erosion at the facet: rough walls strike steeper facets than the mean wall.
        assert!(num(axial, "mean_alpha_element_deg") > num(axial, "mean_alpha_in_deg"));
    }
    for r in &summary {
        assert!(num(r, "hits") > 0.0, "{}: no hit", r["run"]);
        for (k, v) in r {
            assert!(!v.eq_ignore_ascii_case("nan"), "{}: {k} = {v}", r["run"]);
        }
    }
    for f in [
        "profiles.csv",
        "distributions.csv",
        "comparisons.csv",
        "run.toml",
        "concentration_100um.svg",
        "velocity_200um.svg",
        "wall_hits_100um.svg",
    ] {
        assert!(dir.join(f).is_file(), "no {f}");
    }
    let report = Command::new(rebound_bin())
        .args(["report", "--results"])
        .arg(&results)
        .output()
        .unwrap();
    assert!(
        report.status.success(),
        "{}",
        String::from_utf8_lossy(&report.stderr)
    );
    let md = std::fs::read_to_string(results.join("REPORT.md")).unwrap();
    assert!(md.contains("Quick mode only") && md.contains("lay around the circumference"));
    assert!(md.contains("Kussin & Sommerfeld (2002)") && md.contains("at the facet"));
    // The sensitivity table: every switch of the quick mode, both sizes, with a change and
    // its error.
    let sens = rows(&dir.join("sensitivity.csv"));
    for d in ["100", "200"] {
        for switch in [
            "no-spin",
            "no-saffman",
            "no-magnus",
            "no-dispersion",
            "simplified-langevin",
            "sec4-deviations",
        ] {
            let r = sens
                .iter()
                .find(|r| {
                    r["diameter_um"] == d
                        && r["switch"] == switch
                        && r["quantity"] == "collisions_per_m"
                })
                .unwrap_or_else(|| panic!("{d} µm, {switch}: no row"));
            assert!(num(r, "change_se") > 0.0, "{r:?}");
        }
    }
    assert!(
        md.contains("**Sensitivity**") && md.contains("Against the earlier versions of this study")
    );
    // What the forces cost: every study run timed them, a run without spin spent nothing on it.
    let costs = rows(&dir.join("costs.csv"));
    for r in &costs {
        let (lift, spin, step) = (
            num(r, "lift_ns_per_particle_step"),
            num(r, "spin_ns_per_particle_step"),
            num(r, "step_ns_per_particle_step"),
        );
        assert!(step > 0.0 && lift < step && spin < step, "{r:?}");
        if r["kind"] == "main" {
            assert!(lift > 0.0 && spin > 0.0, "{r:?}");
        }
        if r["kind"] == "no-spin" {
            assert_eq!(spin, 0.0, "{r:?}");
        }
    }
    assert!(md.contains("What spin and lift cost"));
    // The switches reach code_saturne: its setup log names the complete model in the study's
    // runs and not in the `simplified-langevin` ones; the study mesh's first cells sit at y+
    // of about 30 or more.
    let setup = |run: &str| {
        std::fs::read_to_string(tmp.path().join(format!("work/runs/{run}/setup.log"))).unwrap()
    };
    let from = |log: &str| -> i64 {
        let line = log
            .lines()
            .find(|l| l.contains("apply complete model from time step"))
            .expect("the complete-model line of setup.log");
        line.split_whitespace().last().unwrap().parse().unwrap()
    };
    assert!(from(&setup("100um-axial-paper")) > 0);
    assert!(from(&setup("200um-circ-calibrated")) > 0);
    assert_eq!(from(&setup("100um-axial-paper-simplified-langevin")), 0);
    let fluid = std::fs::read_to_string(tmp.path().join("work/fluid.txt")).unwrap();
    let y_plus_min: f64 = fluid
        .split("first-cell y+ min ")
        .nth(1)
        .and_then(|t| t.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no first-cell y+ in {fluid}"));
    assert!(y_plus_min >= 30.0, "study mesh: first-cell y+ {y_plus_min}");
}

/// The `near-wall` switch's mesh (`NEARWALL` of scripts/pipe-flow.sh) puts every wall cell's
/// centre in the buffer layer, y⁺ ≤ 15, where the study mesh has 30 or more (the quick-mode
/// test above). 40 fluid steps, not the study's 600: y⁺ then takes the friction velocity of
/// the driving gradient at step 40, which gave 9.45–11.9 against the converged flow's
/// 9.55–12.0 in the study (2026-11-29): 1 % apart, far inside the bound.
#[test]
fn pipe_flow_near_wall_mesh_puts_the_first_cells_below_y_plus_15() {
    crate::require(&["code_saturne", "gmsh", "gfortran", "mpiexec"]);
    let root = repo_root();
    let script = std::fs::read_to_string(root.join("scripts/pipe-flow.sh")).unwrap();
    let mesh = script
        .split("NEARWALL=\"")
        .nth(1)
        .and_then(|t| t.split('"').next())
        .expect("NEARWALL=\"...\" in scripts/pipe-flow.sh");
    let tmp = tempfile::Builder::new()
        .prefix("pipenw")
        .tempdir_in("/tmp")
        .unwrap();
    let ex = root.join("examples/code_saturne/pipe");
    let out = Command::new("bash")
        .arg("-c")
        .arg(format!(
            "set -euo pipefail; PIPE_EX={ex}; source $PIPE_EX/study_lib.sh; \
             D=0.05 L=0.2 UB=20 WORK={work}; study_init; \
             $PIPE_EX/setup_pipe.sh $WORK/nearwall {mesh} > /dev/null; \
             params $WORK/fluid.params 0 40 dt 0.001; \
             $PIPE_EX/run_phase.sh $WORK/nearwall/build $WORK/nearwall/fluid - 1 \
               $WORK/fluid.params 'fluid nearwall'; \
             grep -h 'pipe: first-cell y+' $WORK/nearwall/fluid/run_solver.log",
            ex = ex.display(),
            work = tmp.path().join("study").display()
        ))
        .env("ROUGHWALL_INCLUDE", root.join("include"))
        .env("ROUGHWALL_LIB", c_library_dir())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = stdout
        .lines()
        .find(|l| l.contains("first-cell y+"))
        .unwrap_or_else(|| panic!("no first-cell y+ in {stdout}"));
    let value = |key: &str| -> f64 {
        line.split(key)
            .nth(1)
            .and_then(|t| t.split_whitespace().next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("no {key:?} in {line}"))
    };
    let (lo, hi) = (value("first-cell y+ min "), value(" max "));
    eprintln!("near-wall mesh {mesh}: first-cell y+ {lo} to {hi}");
    assert!(hi <= 15.0 && lo >= 5.0, "first-cell y+ {lo} to {hi}");
}
