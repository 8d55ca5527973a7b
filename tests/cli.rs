//! Command-line behaviour shared by every subcommand: exit codes and one-line errors.

use std::process::Command;

fn rebound(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rebound"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn missing_case_file_is_a_one_line_error_with_status_2() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("o");
    let (code, _, err) = rebound(&[
        "stochastic",
        "--case",
        "no/such/case.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("no/such/case.toml"));
    assert!(!out.exists(), "nothing may be written on bad input");
}

#[test]
fn zero_threads_is_rejected() {
    let (code, _, err) = rebound(&["force-sweep", "--threads", "0"]);
    assert_eq!(code, 2);
    assert!(err.contains("--threads"));
}

#[test]
fn help_explains_every_common_option() {
    for sub in ["surface", "deterministic", "stochastic", "force-sweep"] {
        let (code, out, _) = rebound(&[sub, "--help"]);
        assert_eq!(code, 0);
        for opt in ["--case", "--out", "--seed", "--threads"] {
            assert!(out.contains(opt), "{sub} --help lacks {opt}");
        }
    }
}

#[test]
fn unknown_case_key_names_the_key() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("bad.toml");
    std::fs::write(
        &case,
        "name = 'x'\n[incidence]\nalpha_deg = [-10.0]\nspeed_mean = 3.0\n",
    )
    .unwrap();
    let (code, _, err) = rebound(&["stochastic", "--case", case.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("speed_mean"), "{err}");
}
