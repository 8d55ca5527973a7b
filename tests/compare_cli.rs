//! `rebound compare` through the binary: schema, identity, unmatched conditions, errors.
use crate::common::*;

/// Runs `stochastic` on the aniso wall at `alphas` × β⁻ ∈ {0°, 60°} into `dir/name`.
fn run_stochastic(dir: &Dir, name: &str, alphas: &str, seed: u64) -> String {
    let case = dir.write_case(
        &format!("{name}.toml"),
        &format!(
            "name = \"{name}\"\nseed = {seed}\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n\
             [incidence]\nalpha_deg = {alphas}\nbeta_deg = [0.0, 60.0]\n[particles]\ncount = 4000\n"
        ),
    );
    run_case("stochastic", &case, &dir.join(name), &[])
        .display()
        .to_string()
}

#[test]
fn compare_writes_the_schema_and_lists_unmatched_conditions() {
    let tmp = Dir::new();
    let a = run_stochastic(&tmp, "a", "[-12.5, -32.5]", 1);
    let b = run_stochastic(&tmp, "b", "[-12.5, -2.5]", 2);
    let out = tmp.join("cmp");
    let o = rebound(&[
        "compare",
        "--a",
        &a,
        "--b",
        &b,
        "--out",
        out.to_str().unwrap(),
    ]);
    let err = &o.stderr;
    assert_eq!(o.code, 0, "{err}");
    let csv = Csv::read(&out.join("comparison.csv"));
    assert_eq!(
        csv.header.join(","),
        "alpha_in_deg,beta_in_deg,quantity,ks,l1,mean_a,mean_b,std_a,std_b,se_mean_a,se_mean_b,z"
    );
    let rows: Vec<Row> = csv.records().collect();
    assert!(rows.iter().all(|r| &r["alpha_in_deg"] == "-12.5"));
    // Two independent samples of the same law: small distances.
    for r in &rows {
        let ks = r.num("ks");
        let l1 = r.num("l1");
        // (The Fig. 11 slices hold a few hundred particles: wider KS.)
        let bound = if r["quantity"].starts_with("gamma_star_given") {
            0.2
        } else {
            0.06
        };
        assert!((0.0..bound).contains(&ks), "{r:?}");
        assert!((0.0..=2.0).contains(&l1), "{r:?}");
        // Exact moments with their standard errors: z of two samples of one law is small.
        // (A model curve has no sampling error.)
        if &r["quantity"] == "gamma_model" {
            assert_eq!(
                (&r["se_mean_a"], &r["se_mean_b"], &r["z"]),
                ("", "", ""),
                "{r:?}"
            );
            continue;
        }
        let (se_a, se_b, z) = (r.num("se_mean_a"), r.num("se_mean_b"), r.num("z"));
        assert!(se_a > 0.0 && se_b > 0.0 && z.abs() < 5.0, "{r:?}");
        let mean_a = r.num("mean_a");
        let mean_b = r.num("mean_b");
        let expect = (mean_b - mean_a) / (se_a * se_a + se_b * se_b).sqrt();
        assert!((z - expect).abs() < 1e-4 * expect.abs().max(1.0), "{r:?}");
    }
    assert!(
        rows.iter().any(|r| &r["quantity"] == "dbeta")
            && rows.iter().any(|r| &r["quantity"] == "alpha_out")
    );
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
    let out2 = tmp.join("self");
    rebound(&[
        "compare",
        "--a",
        &a,
        "--b",
        &a,
        "--out",
        out2.to_str().unwrap(),
    ])
    .ok();
    let csv = Csv::read(&out2.join("comparison.csv"));
    for r in csv.records() {
        assert_eq!((&r["ks"], &r["l1"]), ("0", "0"), "{r:?}");
        assert_eq!(
            (&r["mean_a"], &r["std_a"]),
            (&r["mean_b"], &r["std_b"]),
            "{r:?}"
        );
        assert!(&r["z"] == "0" || &r["quantity"] == "gamma_model", "{r:?}");
    }
}

#[test]
fn compare_rejects_directories_that_are_not_rebound_outputs() {
    let tmp = Dir::new();
    let good = run_stochastic(&tmp, "g", "[-12.5]", 3);
    let empty = tmp.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let wrong = tmp.join("wrong");
    std::fs::create_dir_all(&wrong).unwrap();
    std::fs::write(wrong.join("summary.csv"), "a,b\n1,2\n").unwrap();
    std::fs::write(wrong.join("pdfs.csv"), "a,b\n1,2\n").unwrap();
    let missing = tmp.join("missing");
    for (bad, what) in [
        (&empty, "no summary.csv"),
        (&wrong, "not a rebound output"),
        (&missing, "not a directory"),
    ] {
        let out = tmp.join("out");
        let o = rebound(&[
            "compare",
            "--a",
            &good,
            "--b",
            bad.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        o.refused(what);
        assert!(o.stderr.contains("--b"), "{}", o.stderr);
        assert!(!out.exists());
    }
}
