//! `rebound force-sweep` end to end: outputs, shipped cases, bad input.
use roughwall::case::force::resolve;
use roughwall::force::tables::HEADER;
use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The arguments of `rebound force-sweep --case CASE --out OUT`.
fn args(case: Option<PathBuf>, out: &Path) -> Vec<OsString> {
    let mut a: Vec<OsString> = vec!["force-sweep".into(), "--out".into(), out.into()];
    if let Some(c) = case {
        a.extend(["--case".into(), c.into()]);
    }
    a
}

/// A failed run: its exit status and its stderr (one line for an input error).
#[derive(Debug)]
struct Failure {
    status: Option<i32>,
    stderr: String,
}

/// Runs the `rebound` binary.
fn run(args: &[OsString]) -> Result<(), Failure> {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rebound"))
        .args(args)
        .output()
        .expect("run rebound");
    if out.status.success() {
        return Ok(());
    }
    Err(Failure {
        status: out.status.code(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    })
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
    let mut lines = csv.lines();
    assert_eq!(lines.next().unwrap(), HEADER.join(","));
    assert_eq!(HEADER.join(","), "model,lambda,beta_deg,u_n_m_s,diameter_um,density_kg_m3,youngs_pa,poisson,f_max_n,xi,contact_time_s");
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3 * 3 * 91);
    for r in &rows {
        assert_eq!(r.len(), 11);
        assert_eq!(
            (r[3], r[4], r[5], r[6], r[7]),
            ("0.0457", "2.45", "2500", "64000000000", "0.24")
        );
        assert!(r[8].parse::<f64>().unwrap() > 0.0 && r[9].parse::<f64>().unwrap() > 0.0);
        // Contact time: empty for hu2021 only.
        assert_eq!(r[10].is_empty(), r[0] == "hu2021", "{r:?}");
    }
    // ξ of hu2021 at λ = 2, β = 0 is Eq. (8)'s constant term.
    assert!(rows
        .iter()
        .any(|r| r[0] == "hu2021" && r[1] == "2" && r[2] == "0" && r[9] == "0.82837"));
    let acc = read(&dir.path().join("accuracy.csv"));
    assert_eq!(acc.lines().count(), 1 + 6);
    assert!(acc
        .lines()
        .nth(1)
        .unwrap()
        .starts_with("hertz-rigid,1.5,2.45,0.0457,91,0,90,"));
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

/// Every shipped Hu et al. case resolves; Fig. 12's runs end to end.
#[test]
fn shipped_cases() {
    for name in [
        "hu-fig4",
        "hu-fig6",
        "hu-fig8",
        "hu-fig9",
        "hu-fig10",
        "hu-fig10b",
        "hu-fig11",
        "hu-fig11b",
        "hu-fig12",
    ] {
        let case =
            roughwall::case::load(Some(Path::new(&format!("cases/{name}.toml"))), "").unwrap();
        let (p, s) = resolve(&case).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(p.validate().is_ok() && !s.is_empty(), "{name}");
    }
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
    assert_eq!(e.status, Some(2), "{e:?}");
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
    for l in csv.lines().skip(1) {
        let r: Vec<&str> = l.split(',').collect();
        assert_eq!((r[8], r[10]), ("0", ""), "{l}");
        assert!(r[9].parse::<f64>().unwrap() > 0.0);
    }
    assert!(!csv.to_lowercase().contains("nan"));
}
