//! `rebound force-sweep` end to end: outputs, shipped cases, bad input.
use crate::common::headers;
use std::ffi::OsString;
use std::path::{Path, PathBuf};

use crate::common::{rebound, rebound_case, Csv, Run};

/// The arguments of `rebound force-sweep --out OUT [--case CASE]`.
fn args(case: Option<PathBuf>, out: &Path) -> Vec<OsString> {
    let mut a: Vec<OsString> = vec!["force-sweep".into(), "--out".into(), out.into()];
    if let Some(c) = case {
        a.extend(["--case".into(), c.into()]);
    }
    a
}

/// Runs the binary: `Ok` on success, else the failed run.
fn run(args: &[OsString]) -> Result<(), Run> {
    let r = rebound(args);
    if r.code == 0 {
        Ok(())
    } else {
        Err(r)
    }
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Without `--case`: Hu et al. 2021, Fig. 6, for hu2021, hertz-rigid and hertz-dynamic.
#[test]
fn default_run_is_fig6() {
    let dir = tempfile::tempdir().unwrap();
    run(&args(None, dir.path())).unwrap();
    let csv = read(&dir.path().join("force_sweep.csv"));
    let csv = Csv::parse(&csv);
    assert_eq!(csv.header.join(","), headers::FORCE_SWEEP);
    assert_eq!(csv.rows.len(), 3 * 3 * 91);
    for r in csv.records() {
        assert_eq!(r.cells().len(), 11);
        assert_eq!(
            (
                &r["u_n_m_s"],
                &r["diameter_um"],
                &r["density_kg_m3"],
                &r["youngs_pa"],
                &r["poisson"]
            ),
            ("0.0457", "2.45", "2500", "64000000000", "0.24")
        );
        assert!(r.num("f_max_n") > 0.0 && r.num("xi") > 0.0);
        // Contact time: empty for hu2021 only.
        assert_eq!(
            r["contact_time_s"].is_empty(),
            &r["model"] == "hu2021",
            "{r:?}"
        );
    }
    // ξ of hu2021 at λ = 2, β = 0 is Eq. (8)'s constant term.
    assert!(csv
        .records()
        .any(|r| (&r["model"], &r["lambda"], &r["beta_deg"], &r["xi"])
            == ("hu2021", "2", "0", "0.82837")));
    let acc = Csv::read(&dir.path().join("accuracy.csv"));
    assert_eq!(acc.rows.len(), 6);
    let first = acc.row(0);
    for (column, value) in [
        ("model", "hertz-rigid"),
        ("lambda", "1.5"),
        ("diameter_um", "2.45"),
        ("u_n_m_s", "0.0457"),
        ("points", "91"),
        ("beta_min_deg", "0"),
        ("beta_max_deg", "90"),
    ] {
        assert_eq!(&first[column], value, "{column}");
    }
    assert!(
        read(&dir.path().join("dynamic_convergence.csv"))
            .lines()
            .count()
            > 3
    );
    for f in [
        "fmax_vs_beta.svg",
        "xi_vs_beta.svg",
        "sphere_check.svg",
        "run.toml",
    ] {
        assert!(dir.path().join(f).exists(), "{f}");
    }
    for f in ["force_sweep.csv", "accuracy.csv", "dynamic_convergence.csv"] {
        let s = read(&dir.path().join(f)).to_lowercase();
        assert!(!s.contains("nan") && !s.contains("inf"), "{f}");
    }
    assert!(read(&dir.path().join("run.toml")).contains("[[dynamic_convergence]]"));
}

/// Fig. 12's shipped case runs end to end (every shipped case resolves: a unit test of
/// `src/case/force.rs`).
#[test]
fn shipped_fig12_runs() {
    let dir = tempfile::tempdir().unwrap();
    run(&args(Some("cases/hu-fig12.toml".into()), dir.path())).unwrap();
    let csv = read(&dir.path().join("force_sweep.csv"));
    assert_eq!(csv.lines().count(), 1 + 3 * 12);
    assert!(dir.path().join("fmax_vs_un.svg").exists());
}

fn case_err(body: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("c.toml");
    std::fs::write(&case, format!("name = \"bad\"\n{body}")).unwrap();
    let out = dir.path().join("out");
    let e = run(&args(Some(case), &out)).unwrap_err();
    // Exit status 2: an input error.
    assert_eq!(e.code, 2, "{e:?}");
    let s = e.stderr.strip_suffix('\n').unwrap_or(&e.stderr).to_string();
    assert!(!s.contains('\n'), "{s}");
    assert!(!out.join("force_sweep.csv").exists());
    s
}

#[test]
fn bad_input_is_one_line_input_error() {
    assert!(case_err("[sweep]\nbeta_deg = [95.0]\n").contains("beta_deg"));
    assert!(case_err("[sweep]\nbeta_deg = [-5.0]\n").contains("beta_deg"));
    assert!(case_err("[sweep]\nlambda = [0.5]\n").contains("oblate"));
    assert!(case_err("[sweep]\nu_n_m_s = [-1.0]\n").contains("u_n_m_s"));
    assert!(case_err("[sweep]\nmodels = [\"dem\"]\n").contains("dem"));
    assert!(case_err("[particle]\npreset = \"steel\"\n").contains("steel"));
    assert!(case_err("[sweep]\nlambda = [2.5]\nmodels = [\"hu2021\"]\n").contains("hertz-rigid"));
    assert!(
        case_err("[sweep]\nlambda = [2.0]\nmodels = [\"hertz-sphere\"]\n").contains("hertz-rigid")
    );
    assert!(
        case_err("[particle]\ndiameter_um = 2.0\n[sweep]\ndiameter_um = [1.0]\n")
            .contains("diameter_um")
    );
    assert!(case_err("[particle]\npoisson = 0.6\n").contains("poisson"));
}

/// U_N = 0: zero force, empty contact time, no NaN.
#[test]
fn zero_speed_rows() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("c.toml");
    std::fs::write(
        &case,
        "name = \"zero\"\n[sweep]\nlambda = [1.0, 2.0]\nbeta_deg = [0.0, 90.0]\nu_n_m_s = [0.0]\nmodels = [\"hu2021\", \"hertz-rigid\", \"hertz-dynamic\"]\n",
    )
    .unwrap();
    let out = dir.path().join("out");
    run(&args(Some(case), &out)).unwrap();
    let csv = read(&out.join("force_sweep.csv"));
    assert_eq!(csv.lines().count(), 1 + 12);
    let table = Csv::parse(&csv);
    assert_eq!(table.header.join(","), headers::FORCE_SWEEP);
    for r in table.records() {
        assert_eq!((&r["f_max_n"], &r["contact_time_s"]), ("0", ""), "{r:?}");
        assert!(r.num("xi") > 0.0);
    }
    assert!(!csv.to_lowercase().contains("nan"));
}

/// Issue 14, part 9: force-sweep's particle section is `[impactor]`; the old name `[particle]`
/// still works, with a warning, and gives the same table; both at once are refused.
#[test]
fn the_old_particle_section_still_works_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = "[sweep]\nmodels = [\"hu2021\"]\nbeta_deg = [0.0, 45.0]\n";
    let mut tables = Vec::new();
    for section in ["impactor", "particle"] {
        let case = dir.path().join(format!("{section}.toml"));
        std::fs::write(
            &case,
            format!("name = \"p\"\n[{section}]\npreset = \"copper\"\n{sweep}"),
        )
        .unwrap();
        let out = dir.path().join(section);
        let r = rebound_case("force-sweep", &case, &out, &[]).ok();
        let warned = r
            .stderr
            .contains("warning: section [particle] is the old name of [impactor]");
        assert_eq!(warned, section == "particle", "{}", r.stderr);
        tables.push(read(&out.join("force_sweep.csv")));
    }
    assert_eq!(tables[0], tables[1]);
    let both = case_err("[impactor]\npreset = \"copper\"\n[particle]\npreset = \"copper\"\n");
    assert!(both.contains("both [impactor] and [particle]"), "{both}");
}

/// A stochastic case with force-sweep's particle section warns instead of running silently
/// with the default diameter.
#[test]
fn a_section_of_another_command_is_a_warning_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("s.toml");
    std::fs::write(
        &case,
        "name = \"s\"\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n[incidence]\nalpha_deg = [-10.0]\n[particles]\ncount = 1000\n[particle]\ndiameter_um = 100.0\n",
    )
    .unwrap();
    let r = rebound_case("stochastic", &case, &dir.path().join("o"), &[]).ok();
    assert!(
        r.stderr.contains("warning: section [particle] is not read by `stochastic` (did you mean [particles]?): it is read by `force-sweep` only"),
        "{}",
        r.stderr
    );
}
