//! `rebound stochastic` through the binary: outputs, reproducibility across thread
//! counts, Eq. (15) conversion, and the bad-input rules of issue 4.
use crate::common::*;
use std::path::Path;

/// Writes the case file `name` into `dir`; its path as a string.
fn case_in(dir: &Dir, name: &str, body: &str) -> String {
    dir.write_case(name, body).display().to_string()
}

const BASE: &str = r#"name = "t"
seed = 5
[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-0.01, -15.0, -90.0]
beta_deg = [0.0, 60.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16
[particles]
count = 3000
diameter_um = 500.0
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
[stochastic]
psi = 2.0
"#;

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

#[test]
fn outputs_are_byte_identical_for_one_and_two_threads() {
    let tmp = Dir::new();
    let case = case_in(&tmp, "c.toml", BASE);
    let mut files = Vec::new();
    for t in ["1", "2"] {
        let out = tmp.join(format!("t{t}"));
        rebound(&[
            "stochastic",
            "--case",
            &case,
            "--threads",
            t,
            "--out",
            out.to_str().unwrap(),
        ])
        .ok();
        files.push((read(&out.join("summary.csv")), read(&out.join("pdfs.csv"))));
    }
    assert_eq!(files[0], files[1]);
}

#[test]
fn default_run_has_the_shared_schema_model_curve_and_figures() {
    let tmp = Dir::new();
    let out = tmp.join("o");
    rebound(&[
        "stochastic",
        "--particles",
        "4000",
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    let summary = Csv::read(&out.join("summary.csv"));
    assert_eq!(summary.header.join(","), headers::SUMMARY);
    // Built-in default: Sec. 4 scene, α⁻ ∈ {−5, −15, −25}, β⁻ ∈ {0, 60}.
    assert_eq!(summary.rows.len(), 6);
    for r in summary.records() {
        for empty in [
            "mean_dbeta_first_deg",
            "std_dbeta_first_deg",
            "mean_collisions",
            "max_collisions",
            "lost",
        ] {
            assert_eq!(&r[empty], "", "{empty}");
        }
        let p = r.num("p_single");
        assert!(p > 0.5 && p <= 1.0, "{p}");
        assert_eq!(&r["delta_xi_deg"], "3.8");
        assert_eq!(&r["delta_zeta_deg"], "7.5");
        let speed = r.num("mean_speed_ratio");
        assert!(speed > 0.0 && speed < 1.0, "{speed}");
        assert!(!r
            .cells()
            .iter()
            .any(|c| c.contains("NaN") || c.contains("inf")));
    }
    let pdfs = read(&out.join("pdfs.csv"));
    assert!(pdfs.starts_with("alpha_in_deg,beta_in_deg,quantity,bin_lo,bin_hi,value,se\n"));
    // gamma_model integrates to ~1 (per degree, on 1° bins) for each condition.
    let pdfs = Csv::read(&out.join("pdfs.csv"));
    for (a, b) in [("-5", "0"), ("-25", "60")] {
        let total: f64 = pdfs
            .records()
            .filter(|r| {
                (&r["alpha_in_deg"], &r["beta_in_deg"], &r["quantity"]) == (a, b, "gamma_model")
            })
            .map(|r| r.num("value") * (r.num("bin_hi") - r.num("bin_lo")))
            .sum();
        assert!((total - 1.0).abs() < 0.02, "{a},{b}: {total}");
    }
    for f in [
        "fig10_gamma.svg",
        "fig11_gamma_star_given_gamma.svg",
        "fig14_15_rebound_angles.svg",
        "run.toml",
    ] {
        assert!(out.join(f).is_file(), "{f}");
    }
    assert!(read(&out.join("run.toml")).contains("psi = 2.0"));
}

#[test]
fn surface_parameters_are_converted_with_eq15_without_building_a_surface() {
    let tmp = Dir::new();
    // Table 1's surface: h = 0.37 µm, c_Lx = 12 µm, c_Lz = 4 µm → Δξ = 2.498°, Δζ = 7.495°.
    let case = case_in(
        &tmp,
        "s.toml",
        r#"name = "s"
[surface]
length_um = 5000.0
nodes = 5001
rms_height_um = 0.37
corr_length_x_um = 12.0
corr_length_z_um = 4.0
[incidence]
alpha_deg = [-12.5]
[particles]
count = 1000
"#,
    );
    let out = tmp.join("o");
    let t = std::time::Instant::now();
    rebound(&[
        "stochastic",
        "--case",
        &case,
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    // A 5001² surface would take seconds; the model needs none.
    assert!(t.elapsed().as_secs_f64() < 5.0);
    let s = Csv::read(&out.join("summary.csv"));
    let row = s.row(0);
    let (xi, zeta) = (row.num("delta_xi_deg"), row.num("delta_zeta_deg"));
    assert!((xi - 2.498).abs() < 0.001, "{xi}");
    assert!((zeta - 7.495).abs() < 0.001, "{zeta}");
    assert!(read(&out.join("run.toml")).contains("wall_from_surface"));
}

/// Runs a bad case: exit status 2, one stderr line naming `key`, no output directory.
fn bad(case_body: &str, key: &str, extra: &[&str]) {
    let tmp = Dir::new();
    let case = case_in(&tmp, "bad.toml", case_body);
    let out = tmp.join("never");
    let mut args = vec![
        "stochastic",
        "--case",
        &case,
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = rebound(&args);
    let err = &o.stderr;
    assert_eq!(o.code, 2, "{key}: {err}");
    let lines: Vec<&str> = err.lines().filter(|l| !l.starts_with("warning")).collect();
    assert_eq!(lines.len(), 1, "{key}: {err}");
    assert!(lines[0].contains(key), "{key}: {err}");
    assert!(!out.exists(), "{key}: output written");
}

#[test]
fn bad_input_is_one_line_naming_the_key_with_exit_2_and_nothing_written() {
    bad(
        &BASE.replace("psi = 2.0", "psi = 0.0"),
        "stochastic.psi",
        &[],
    );
    bad(
        &BASE.replace("psi = 2.0", "psi = -1.0"),
        "stochastic.psi",
        &[],
    );
    bad(
        &BASE.replace("delta_xi_deg = 3.8", "delta_xi_deg = -1.0"),
        "delta_xi_deg",
        &[],
    );
    bad(
        &BASE.replace("delta_zeta_deg = 7.5", "delta_zeta_deg = 25.0"),
        "delta_zeta_deg",
        &[],
    );
    bad(
        &BASE.replace("speed_std_m_s = 1.16", "speed_std_m_s = -0.5"),
        "speed_std_m_s",
        &[],
    );
    bad(
        &BASE.replace("alpha_deg = [-0.01, -15.0, -90.0]", "alpha_deg = []"),
        "alpha_deg",
        &[],
    );
    bad(
        &BASE.replace("beta_deg = [0.0, 60.0]", "beta_deg = []"),
        "beta_deg",
        &[],
    );
    bad(BASE, "--particles", &["--particles", "0"]);
    bad(
        &BASE.replace("psi = 2.0", "psi = 2.0\nkappa = 1.0"),
        "kappa",
        &[],
    );
}

#[test]
fn roughness_beyond_the_low_roughness_range_warns_but_runs() {
    let tmp = Dir::new();
    let case = case_in(
        &tmp,
        "w.toml",
        &BASE.replace("delta_zeta_deg = 7.5", "delta_zeta_deg = 12.0"),
    );
    let out = tmp.join("o");
    let err = rebound(&[
        "stochastic",
        "--case",
        &case,
        "--out",
        out.to_str().unwrap(),
    ])
    .ok()
    .stderr;
    assert!(
        err.contains("warning") && err.contains("delta_zeta_deg"),
        "{err}"
    );
    assert!(out.join("summary.csv").is_file());
}

/// A target standard error is one behaviour whether the case or the command line sets it:
/// without a count both run past the 10 000 particles of a run without a target (here
/// two blocks of 65 536), and a target the count stops short of is a warning naming it.
#[test]
fn a_target_runs_the_same_from_the_case_and_the_command_line() {
    let tmp = Dir::new();
    let scene = BASE
        .replace("alpha_deg = [-0.01, -15.0, -90.0]", "alpha_deg = [-15.0]")
        .replace("beta_deg = [0.0, 60.0]", "beta_deg = [60.0]")
        .replace("count = 3000\n", "");
    let in_case = case_in(
        &tmp,
        "in_case.toml",
        &scene.replace(
            "diameter_um = 500.0",
            "diameter_um = 500.0\ntarget_se_deg = 0.015",
        ),
    );
    let plain = case_in(&tmp, "plain.toml", &scene);
    let run = |case: &str, out: &str, extra: &[&str]| {
        let out = tmp.join(out);
        let mut args = vec!["stochastic", "--case", case, "--out", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let r = rebound(&args).ok();
        (
            std::fs::read(out.join("summary.csv")).unwrap(),
            r.stderr,
            out,
        )
    };
    let (a, a_err, a_dir) = run(&in_case, "a", &[]);
    let (b, b_err, _) = run(&plain, "b", &["--target-se", "0.015"]);
    assert_eq!(a, b, "the case's target and --target-se differ");
    assert!(!a_err.contains("not reached") && !b_err.contains("not reached"));
    let s = Csv::read(&a_dir.join("summary.csv"));
    let n = s.num(&s.rows[0], "particles");
    assert!(n > 10_000.0, "stopped at {n}");
    assert!(s.num(&s.rows[0], "se_mean_alpha_out_deg") <= 0.015);
    // A count that stops the run first: a warning, not silence.
    let (_, err, _) = run(
        &plain,
        "c",
        &["--target-se", "0.0001", "--particles", "20000"],
    );
    assert!(
        err.contains("the target standard error 0.0001° was not reached in 20000 particles"),
        "{err}"
    );
}

/// `[wall]` lengths have the ranges of a `[surface]`'s (10⁻⁶ … 10⁹ µm), for every command
/// that reads the wall.
#[test]
fn wall_lengths_below_their_minimum_are_refused() {
    let wall = "[wall]\ndelta_xi_deg = 3.8\ndelta_zeta_deg = 7.5";
    for (body, key) in [
        (
            "[wall]\nrms_height_um = 1e-300\ncorr_length_x_um = 12.0\ncorr_length_z_um = 4.0",
            "wall.rms_height_um",
        ),
        (
            "[wall]\nrms_height_um = 5e-324\ncorr_length_x_um = 12.0\ncorr_length_z_um = 4.0",
            "wall.rms_height_um",
        ),
        (
            "[wall]\nrms_height_um = 0.37\ncorr_length_x_um = 1e-9\ncorr_length_z_um = 4.0",
            "wall.corr_length_x_um",
        ),
        (
            "[wall]\ndelta_xi_deg = 3.8\ndelta_zeta_deg = 7.5\nrms_height_um = 1e-7",
            "wall.rms_height_um",
        ),
    ] {
        let case = BASE.replace(wall, body);
        assert_ne!(case, BASE);
        bad(&case, key, &[]);
        let tmp = Dir::new();
        let file = case_in(&tmp, "c.toml", &case);
        for cmd in ["deterministic", "calibrate"] {
            let out = tmp.join(cmd);
            rebound(&[cmd, "--case", &file, "--out", out.to_str().unwrap()]).refused(key);
        }
    }
}

/// One particle has a mean but no spread: every std and se cell is empty (not 0) in both
/// models' `summary.csv` and `moments.csv`, and `compare` reads such a run back (issue 33).
#[test]
fn one_particle_writes_no_spread() {
    let tmp = Dir::new();
    for model in ["stochastic", "deterministic"] {
        let out = tmp.join(model);
        rebound(&[model, "--particles", "1", "--out", out.to_str().unwrap()]).ok();
        let summary = Csv::read(&out.join("summary.csv"));
        let moments = Csv::read(&out.join("moments.csv"));
        for row in summary.records() {
            assert_eq!(&row["particles"], "1");
            assert!(!row["mean_alpha_out_deg"].is_empty(), "{model}: no mean");
            for (name, cell) in summary.header.iter().zip(row.cells()) {
                if name.starts_with("std_") || name.starts_with("se_") {
                    assert!(cell.is_empty(), "{model}: {name} = {cell}");
                }
            }
        }
        for row in moments.records() {
            assert_eq!(&row["n"], "1");
            assert_eq!((&row["std"], &row["se"]), ("", ""), "{model}");
        }
        let (r, c) = (out.to_str().unwrap(), tmp.join(format!("{model}-compare")));
        rebound(&["compare", "--a", r, "--b", r, "--out", c.to_str().unwrap()]).ok();
        let cmp = Csv::read(&c.join("comparison.csv"));
        for row in cmp
            .records()
            .filter(|r| ["alpha_out", "dbeta"].contains(&&r["quantity"]))
        {
            assert_eq!((&row["std_a"], &row["z"]), ("", ""), "{model}");
        }
    }
}
