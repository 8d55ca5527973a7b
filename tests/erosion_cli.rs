//! Erosion through the binary (issue 12): nothing changes without `[erosion]`; with it, the
//! appended columns, the local impact-angle PDFs, the hard cases (normal and grazing
//! incidence), the refusals, and byte-identical outputs for any thread count and shard split.

use crate::common::*;
use std::path::{Path, PathBuf};

const BASE: &str = r#"name = "erosion"
seed = 5
[wall]
delta_xi_deg = 2.5
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-5.0, -30.0]
beta_deg = [0.0, 45.0]
speed_mean_m_s = 20
speed_reference = "magnitude"
[particles]
count = 3000
diameter_um = 100
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
[deterministic]
side_per_corr_length = 16.0
"#;

const FINNIE: &str = "[erosion]\nmodel = \"finnie\"\nflow_stress_pa = 1e9\n";

fn run(dir: &Path, command: &str, case: &Path, name: &str, extra: &[&str]) -> PathBuf {
    run_case(command, case, &dir.join(name), extra)
}

#[test]
fn without_erosion_nothing_is_computed_and_the_outputs_do_not_change() {
    let tmp = Dir::new();
    let plain = write_case(tmp.path(), "plain.toml", BASE);
    let eroding = write_case(tmp.path(), "eroding.toml", &format!("{BASE}{FINNIE}"));
    for command in ["stochastic", "deterministic"] {
        let a = run(
            tmp.path(),
            command,
            &plain,
            &format!("{command}-plain"),
            &[],
        );
        let b = run(
            tmp.path(),
            command,
            &eroding,
            &format!("{command}-eroding"),
            &[],
        );
        let sa = Csv::read(&a.join("summary.csv"));
        let sb = Csv::read(&b.join("summary.csv"));
        assert_eq!(sa.header.len(), 28, "{command}");
        assert!(!sa.header.iter().any(|h| h.contains("erosion")));
        // The erosion columns are appended; the others keep their bytes.
        assert_eq!(sb.header[..28], sa.header[..]);
        assert_eq!(sb.header.len(), 36);
        for (ra, rb) in sa.rows.iter().zip(&sb.rows) {
            assert_eq!(rb[..28], ra[..], "{command}");
        }
        let pa = std::fs::read_to_string(a.join("pdfs.csv")).unwrap();
        let pb = std::fs::read_to_string(b.join("pdfs.csv")).unwrap();
        assert!(!pa.contains("impact_angle") && !pa.contains("erosion"));
        assert!(pb.contains(",impact_angle_local,"));
        // Every line of the run without erosion is in the run with it, in order.
        let extra: Vec<&str> = pb.lines().filter(|l| !pa.contains(l)).collect();
        assert!(extra.iter().all(|l| l.contains("impact_angle_local")));
        let ma = std::fs::read_to_string(a.join("moments.csv")).unwrap();
        let mb = std::fs::read_to_string(b.join("moments.csv")).unwrap();
        assert!(!ma.contains("erosion"));
        let kept: Vec<&str> = mb.lines().filter(|l| !l.contains("erosion")).collect();
        assert_eq!(kept, ma.lines().collect::<Vec<_>>());
        let manifest = std::fs::read_to_string(b.join("run.toml")).unwrap();
        assert!(manifest.contains("[erosion]") && manifest.contains("particle_mass_kg"));
    }
}

#[test]
fn erosion_columns_pdfs_and_their_meaning() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", &format!("{BASE}{FINNIE}"));
    let d = run(tmp.path(), "deterministic", &case, "d", &[]);
    let s = run(tmp.path(), "stochastic", &case, "s", &[]);
    let sd = Csv::read(&d.join("summary.csv"));
    let ss = Csv::read(&s.join("summary.csv"));
    for (c, model) in [(&sd, "deterministic"), (&ss, "stochastic")] {
        for row in &c.rows {
            let e = c.num(row, "erosion_per_mass");
            let se = c.num(row, "se_erosion_per_mass");
            assert!(e > 0.0 && se > 0.0 && se < 0.1 * e, "{model}: {e} ± {se}");
            // Volume per particle = per unit mass × the sphere's mass (glass, 100 µm).
            let m = 2500.0 * std::f64::consts::PI / 6.0 * 1e-12;
            let v = c.num(row, "erosion_per_particle_m3");
            assert!((v / (e * m) - 1.0).abs() < 1e-6, "{model}");
            assert!(c.num(row, "mean_impacts") >= 1.0);
        }
    }
    // Deterministic: impacts are collisions; no rejected candidates.
    for row in &sd.rows {
        assert_eq!(
            sd.num(row, "mean_impacts"),
            sd.num(row, "mean_collisions"),
            "{row:?}"
        );
        assert_eq!(sd.cell(row, "erosion_per_mass_rejected"), "");
    }
    // Stochastic: impacts are candidates, 1/p_single of them per rebound.
    for row in &ss.rows {
        let k = ss.num(row, "mean_impacts");
        let p = ss.num(row, "p_single");
        assert!((k * p - 1.0).abs() < 1e-5, "{k} × {p}");
        let rej = ss.num(row, "erosion_per_mass_rejected");
        assert!(rej >= 0.0 && (k > 1.0) == (rej > 0.0));
    }
    // Steep impacts erode glass on steel more than grazing ones (Finnie peaks near 17° at
    // K = 2; the local angles spread around the nominal one).
    let by = |c: &Csv, a: f64| {
        c.rows
            .iter()
            .find(|r| c.num(r, "alpha_in_deg") == a && c.num(r, "beta_in_deg") == 0.0)
            .map(|r| c.num(r, "erosion_per_mass"))
            .unwrap()
    };
    assert!(by(&sd, -30.0) > by(&sd, -5.0));
    // The local impact-angle PDF is a density over [0°, 90°], centred near |α⁻|.
    let pdfs = Csv::read(&d.join("pdfs.csv"));
    let rows: Vec<&Vec<String>> = pdfs
        .rows
        .iter()
        .filter(|r| {
            pdfs.cell(r, "quantity") == "impact_angle_local"
                && pdfs.num(r, "alpha_in_deg") == -30.0
                && pdfs.num(r, "beta_in_deg") == 0.0
        })
        .collect();
    let integral: f64 = rows
        .iter()
        .map(|r| pdfs.num(r, "value") * (pdfs.num(r, "bin_hi") - pdfs.num(r, "bin_lo")))
        .sum();
    assert!((integral - 1.0).abs() < 1e-5, "{integral}");
    let mean: f64 = rows
        .iter()
        .map(|r| {
            let (lo, hi) = (pdfs.num(r, "bin_lo"), pdfs.num(r, "bin_hi"));
            pdfs.num(r, "value") * (hi - lo) * 0.5 * (lo + hi)
        })
        .sum();
    assert!((mean - 30.0).abs() < 3.0, "{mean}");
    assert!(rows.iter().all(|r| pdfs.num(r, "bin_lo") >= 0.0));
}

#[test]
fn normal_and_grazing_incidence_give_finite_erosion() {
    let tmp = Dir::new();
    let body = BASE
        .replace("alpha_deg = [-5.0, -30.0]", "alpha_deg = [-90.0, -0.01]")
        .replace("count = 3000", "count = 400");
    for model in [
        FINNIE.to_string(),
        "[erosion]\nmodel = \"dnv\"\n".into(),
        "[erosion]\nmodel = \"oka\"\nhardness_gpa = 1.8\n".into(),
    ] {
        let case = write_case(tmp.path(), "c.toml", &format!("{body}{model}"));
        for command in ["stochastic", "deterministic"] {
            let out = run(tmp.path(), command, &case, command, &[]);
            let s = Csv::read(&out.join("summary.csv"));
            for row in &s.rows {
                let a = s.num(row, "alpha_in_deg");
                let e = s.num(row, "erosion_per_mass");
                assert!(e.is_finite() && e >= 0.0, "{command} {a}: {e}");
                if a == -90.0 {
                    // Normal incidence: every law removes material.
                    assert!(e > 0.0, "{command} {model}");
                }
            }
            for file in ["summary.csv", "pdfs.csv", "moments.csv"] {
                let t = std::fs::read_to_string(out.join(file)).unwrap();
                assert!(!t.to_lowercase().contains("nan") && !t.contains("inf"));
            }
        }
    }
}

#[test]
fn bad_erosion_input_is_refused_in_one_line() {
    let tmp = Dir::new();
    for (section, key) in [
        (
            "model = \"finnie\"\nflow_stress_pa = 0",
            "erosion.flow_stress_pa",
        ),
        (
            "model = \"finnie\"\nflow_stress_pa = -1e9",
            "erosion.flow_stress_pa",
        ),
        (
            "model = \"finnie\"\nflow_stress_pa = 1e9\nk = 0",
            "erosion.k",
        ),
        (
            "model = \"finnie\"\nflow_stress_pa = 1e9\nk = -1",
            "erosion.k",
        ),
        ("model = \"finnie\"", "flow_stress_pa"),
        (
            "model = \"finnie\"\nflow_stress_pa = 1e9\nhardness_gpa = 2",
            "erosion.hardness_gpa",
        ),
        ("model = \"sand\"", "erosion.model"),
        ("flow_stress_pa = 1e9", "model"),
        ("model = \"dnv\"\nbogus = 1", "bogus"),
    ] {
        let case = write_case(
            tmp.path(),
            "bad.toml",
            &format!("{BASE}[erosion]\n{section}\n"),
        );
        for command in ["stochastic", "deterministic"] {
            refuse_case(command, &case, tmp.path(), key);
        }
    }
    let case = write_case(
        tmp.path(),
        "bad.toml",
        &BASE.replace("\"magnitude\"", "\"vertical\""),
    );
    rebound(&["stochastic", "--case", case.to_str().unwrap()]).refused("incidence.speed_reference");
}

#[test]
fn erosion_outputs_are_byte_identical_across_threads_and_shards() {
    let tmp = Dir::new();
    let body = BASE
        .replace("count = 3000", "count = 70000")
        .replace("alpha_deg = [-5.0, -30.0]", "alpha_deg = [-5.0]")
        .replace("beta_deg = [0.0, 45.0]", "beta_deg = [45.0]");
    let case = write_case(tmp.path(), "c.toml", &format!("{body}{FINNIE}"));
    for command in ["stochastic", "deterministic"] {
        let one = run(
            tmp.path(),
            command,
            &case,
            &format!("{command}-1"),
            &["--threads", "1"],
        );
        let two = run(
            tmp.path(),
            command,
            &case,
            &format!("{command}-2"),
            &["--threads", "2"],
        );
        assert_eq!(csv_files(&one), csv_files(&two), "{command}");
        let mut shards = Vec::new();
        for k in [2, 1] {
            shards.push(run(
                tmp.path(),
                command,
                &case,
                &format!("{command}-shard{k}"),
                &["--shard", &format!("{k}/2")],
            ));
        }
        let merged = tmp.path().join(format!("{command}-merged"));
        merge_shards(&merged, &shards);
        assert_eq!(csv_files(&one), csv_files(&merged), "{command}");
        assert!(std::fs::read_to_string(merged.join("summary.csv"))
            .unwrap()
            .contains("erosion_per_mass"));
    }
}
