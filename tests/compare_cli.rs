//! `rebound compare` through the binary: schema, identity, unmatched conditions, errors.
use std::path::Path;
use std::process::Command;

fn rebound(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rebound"))
        .args(args)
        .output()
        .expect("run rebound")
}

fn run_case(dir: &Path, name: &str, alphas: &str, seed: u64) -> String {
    let case = dir.join(format!("{name}.toml"));
    std::fs::write(
        &case,
        format!(
            "name = \"{name}\"\nseed = {seed}\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n\
             [incidence]\nalpha_deg = {alphas}\nbeta_deg = [0.0, 60.0]\n[particles]\ncount = 4000\n"
        ),
    )
    .unwrap();
    let out = dir.join(name);
    let o = rebound(&[
        "stochastic",
        "--case",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out.display().to_string()
}

#[test]
fn compare_writes_the_schema_and_lists_unmatched_conditions() {
    let tmp = tempfile::tempdir().unwrap();
    let a = run_case(tmp.path(), "a", "[-12.5, -32.5]", 1);
    let b = run_case(tmp.path(), "b", "[-12.5, -2.5]", 2);
    let out = tmp.path().join("cmp");
    let o = rebound(&[
        "compare",
        "--a",
        &a,
        "--b",
        &b,
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    let csv = std::fs::read_to_string(out.join("comparison.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "alpha_in_deg,beta_in_deg,quantity,ks,l1,mean_a,mean_b,std_a,std_b,se_mean_a,se_mean_b,z"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert!(rows.iter().all(|r| r[0] == "-12.5"));
    // Two independent samples of the same law: small distances.
    for r in &rows {
        let ks: f64 = r[3].parse().unwrap();
        let l1: f64 = r[4].parse().unwrap();
        // (The Fig. 11 slices hold a few hundred particles: wider KS.)
        let bound = if r[2].starts_with("gamma_star_given") {
            0.2
        } else {
            0.06
        };
        assert!((0.0..bound).contains(&ks), "{r:?}");
        assert!((0.0..=2.0).contains(&l1), "{r:?}");
        // Exact moments with their standard errors: z of two samples of one law is small.
        // (A model curve has no sampling error.)
        if r[2] == "gamma_model" {
            assert_eq!((r[9], r[10], r[11]), ("", "", ""), "{r:?}");
            continue;
        }
        let (se_a, se_b, z): (f64, f64, f64) = (
            r[9].parse().unwrap(),
            r[10].parse().unwrap(),
            r[11].parse().unwrap(),
        );
        assert!(se_a > 0.0 && se_b > 0.0 && z.abs() < 5.0, "{r:?}");
        let mean_a: f64 = r[5].parse().unwrap();
        let mean_b: f64 = r[6].parse().unwrap();
        let expect = (mean_b - mean_a) / (se_a * se_a + se_b * se_b).sqrt();
        assert!((z - expect).abs() < 1e-4 * expect.abs().max(1.0), "{r:?}");
    }
    assert!(rows.iter().any(|r| r[2] == "dbeta") && rows.iter().any(|r| r[2] == "alpha_out"));
    let un = std::fs::read_to_string(out.join("unmatched.csv")).unwrap();
    assert!(
        un.contains("-32.5,0,,a") && un.contains("-2.5,60,,b"),
        "{un}"
    );
    assert!(err.contains("-32.5") && err.contains("-2.5"), "{err}");
    assert!(out.join("overlay_dbeta.svg").is_file());
    let svg = std::fs::read_to_string(out.join("overlay_dbeta.svg")).unwrap();
    assert!(svg.contains("DS") && svg.contains("SM"));

    // A run against itself: every distance is exactly 0 and the moments agree.
    let out2 = tmp.path().join("self");
    let o = rebound(&[
        "compare",
        "--a",
        &a,
        "--b",
        &a,
        "--out",
        out2.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let csv = std::fs::read_to_string(out2.join("comparison.csv")).unwrap();
    for l in csv.lines().skip(1) {
        let f: Vec<&str> = l.split(',').collect();
        assert_eq!((f[3], f[4]), ("0", "0"), "{l}");
        assert_eq!((f[5], f[7]), (f[6], f[8]), "{l}");
        assert!(f[11] == "0" || f[2] == "gamma_model", "{l}");
    }
}

#[test]
fn compare_rejects_directories_that_are_not_rebound_outputs() {
    let tmp = tempfile::tempdir().unwrap();
    let good = run_case(tmp.path(), "g", "[-12.5]", 3);
    let empty = tmp.path().join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let wrong = tmp.path().join("wrong");
    std::fs::create_dir_all(&wrong).unwrap();
    std::fs::write(wrong.join("summary.csv"), "a,b\n1,2\n").unwrap();
    std::fs::write(wrong.join("pdfs.csv"), "a,b\n1,2\n").unwrap();
    let missing = tmp.path().join("missing");
    for (bad, what) in [
        (&empty, "no summary.csv"),
        (&wrong, "not a rebound output"),
        (&missing, "not a directory"),
    ] {
        let out = tmp.path().join("out");
        let o = rebound(&[
            "compare",
            "--a",
            &good,
            "--b",
            bad.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(what) && err.contains("--b"), "{err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(!out.exists());
    }
}
