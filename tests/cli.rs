//! Command-line behaviour shared by every subcommand: exit codes and one-line errors.

use crate::common::*;

#[test]
fn missing_case_file_is_a_one_line_error_with_status_2() {
    let dir = Dir::new();
    let out = dir.join("o");
    rebound(&[
        "stochastic",
        "--case",
        "no/such/case.toml",
        "--out",
        out.to_str().unwrap(),
    ])
    .refused("no/such/case.toml");
    assert!(!out.exists(), "nothing may be written on bad input");
}

#[test]
fn zero_threads_is_rejected() {
    let r = rebound(&["force-sweep", "--threads", "0"]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("--threads"));
}

#[test]
fn help_explains_every_common_option() {
    for sub in ["surface", "deterministic", "stochastic", "force-sweep"] {
        let r = rebound(&[sub, "--help"]);
        assert_eq!(r.code, 0);
        for opt in ["--case", "--out", "--seed", "--threads"] {
            assert!(r.stdout.contains(opt), "{sub} --help lacks {opt}");
        }
    }
}

#[test]
fn unknown_case_key_names_the_key() {
    let dir = Dir::new();
    let case = dir.write_case(
        "bad.toml",
        "name = 'x'\n[incidence]\nalpha_deg = [-10.0]\nspeed_mean = 3.0\n",
    );
    rebound(&["stochastic", "--case", case.to_str().unwrap()]).refused("speed_mean");
}
