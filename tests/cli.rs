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
    for sub in [
        "surface",
        "deterministic",
        "stochastic",
        "force-sweep",
        "scan",
    ] {
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

/// Issue 14, part 8: a successful run ends with one summary line on stderr (what, how many,
/// how fast, what was written where); stdout stays empty; `--quiet` silences it.
#[test]
fn success_prints_a_summary_on_stderr_and_quiet_silences_it() {
    let dir = Dir::new();
    let case = dir.write_case(
        "c.toml",
        "name = \"s\"\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n[incidence]\nalpha_deg = [-10.0, -20.0]\n[particles]\ncount = 3000\n",
    );
    let out = dir.join("o");
    let r = rebound_case("stochastic", &case, &out, &[]).ok();
    assert!(r.stdout.is_empty(), "{}", r.stdout);
    let lines: Vec<&str> = r.stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{}", r.stderr);
    let line = lines[0];
    for part in [
        "stochastic: 2 conditions, 6 000 rebounds in ",
        " rebounds/s); wrote ",
        out.to_str().unwrap(),
        "moments.csv, pdfs.csv, run.toml, summary.csv",
        "SVG figures",
    ] {
        assert!(line.contains(part), "{part:?} not in {line:?}");
    }
    for quiet in ["--quiet", "-q"] {
        let out = dir.join(format!("q{quiet}"));
        let r = rebound(&[
            quiet,
            "stochastic",
            "--case",
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .ok();
        assert_eq!((r.stdout.as_str(), r.stderr.as_str()), ("", ""), "{quiet}");
        assert!(out.join("summary.csv").is_file());
    }
    // After the subcommand too (a global option), and warnings still print under it.
    let warned = dir.write_case(
        "w.toml",
        "name = \"w\"\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 9.0\n[incidence]\nalpha_deg = [-10.0]\n[particles]\ncount = 1000\n",
    );
    let r = rebound_case("stochastic", &warned, &dir.join("w"), &["--quiet"]).ok();
    let lines: Vec<&str> = r.stderr.lines().collect();
    assert!(!lines.is_empty(), "the warning must print under --quiet");
    assert!(
        lines.iter().all(|l| l.starts_with("warning: ")),
        "{}",
        r.stderr
    );
}

/// The summary of a shard run says which shard it was and that it wrote a partial tally.
#[test]
fn a_shard_run_summary_names_the_shard() {
    let dir = Dir::new();
    let out = dir.join("sh");
    let r = rebound(&[
        "stochastic",
        "--particles",
        "2000",
        "--shard",
        "2/3",
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    assert!(
        r.stderr.starts_with("stochastic: shard 2/3: ") && r.stderr.contains("(partial.toml)"),
        "{}",
        r.stderr
    );
}

/// Issue 14, part 10: `rebound <command> --help` shows an example of that command.
#[test]
fn every_command_help_shows_an_example() {
    for sub in [
        "surface",
        "deterministic",
        "stochastic",
        "force-sweep",
        "compare",
        "report",
        "merge",
        "calibrate",
        "scan",
    ] {
        let r = rebound(&[sub, "--help"]);
        assert_eq!(r.code, 0);
        assert!(
            r.stdout.contains(&format!("Example: rebound {sub} ")),
            "{sub} --help has no example:\n{}",
            r.stdout
        );
    }
}

/// Messages that named no key, called a value by the wrong type, said "not found" for a file
/// that exists, or printed a value as hundreds of digits.
#[test]
fn messages_name_what_is_wrong() {
    let tmp = Dir::new();
    let refused = |args: &[&str], needle: &str| {
        let out = tmp.join("never");
        let mut a: Vec<&str> = args.to_vec();
        a.extend(["--out", out.to_str().unwrap()]);
        rebound(&a).refused(needle);
        assert!(!out.exists());
    };
    let case = |name: &str, body: &str| write_case(tmp.path(), name, body).display().to_string();
    let array = case("a.toml", "name = \"x\"\n[[wall]]\ndelta_xi_deg = 1.0\n");
    refused(
        &["stochastic", "--case", &array],
        "a.toml:2: section `[[wall]]` is an array of tables: allowed one table `[wall]`",
    );
    let date = case(
        "d.toml",
        "name = \"x\"\n[wall]\ndelta_xi_deg = 1979-05-27T07:32:00Z\ndelta_zeta_deg = 1.0\n",
    );
    refused(
        &["stochastic", "--case", &date],
        "key `delta_xi_deg`: invalid type: a datetime, expected f64",
    );
    let tiny = case(
        "t.toml",
        "name = \"x\"\n[wall]\ndelta_xi_deg = 1.0\ndelta_zeta_deg = -1e-300\n",
    );
    refused(
        &["stochastic", "--case", &tiny],
        "invalid `wall.delta_zeta_deg` = -1e-300: allowed 0 to 20 degrees",
    );
    let fifo = tmp.join("fifo");
    assert!(std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let fifo = fifo.to_str().unwrap();
    let dir = tmp.path().to_str().unwrap();
    refused(
        &["stochastic", "--case", "/dev/null"],
        "is a character device, not a file",
    );
    refused(&["stochastic", "--case", fifo], "is a FIFO, not a file");
    refused(&["stochastic", "--case", dir], "is a directory, not a file");
    refused(
        &["deterministic", "--surface", fifo],
        "is a FIFO, not a file",
    );
    let table = case(
        "e.toml",
        &format!(
            "name = \"x\"\n[wall]\ndelta_xi_deg = 1.0\ndelta_zeta_deg = 1.0\n[incidence]\nalpha_deg = [-5.0]\n[stochastic]\nmodel = \"calibrated\"\nescape_table = \"{dir}\"\n"
        ),
    );
    refused(
        &["stochastic", "--case", &table],
        "`stochastic.escape_table` = ",
    );
    refused(
        &["stochastic", "--case", &table],
        ": a directory, not a file",
    );
}

/// On a non-terminal stderr (a batch job's log) a long run gives an estimate once it has run
/// for a second and then a line every `--log-every` seconds; `--quiet` silences them, and a
/// bad interval is refused.
#[test]
fn a_long_run_logs_its_progress_when_stderr_is_not_a_terminal() {
    let tmp = Dir::new();
    let run = |extra: &[&str]| {
        let out = tmp.join(format!("o{}", extra.len()));
        let mut args = vec![
            "stochastic",
            "--particles",
            "1500000",
            "--threads",
            "1",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        rebound(&args).ok().stderr
    };
    let log = run(&["--log-every", "0.2"]);
    let estimate = log
        .lines()
        .find(|l| l.starts_with("stochastic: 9000000 particles planned"))
        .unwrap_or_else(|| panic!("no estimate in {log}"));
    assert!(estimate.contains(" in all"), "{estimate}");
    assert!(
        log.lines()
            .any(|l| l.contains("particles (") && l.contains(" left")),
        "no progress line in {log}"
    );
    let quiet = run(&["--log-every", "0.2", "--quiet", "--seed", "3"]);
    assert!(quiet.is_empty(), "{quiet}");
    rebound(&["stochastic", "--log-every=-1"]).refused("invalid `--log-every` = -1");
}

/// Issue 41, part 5: the report lives in its own binary, `rebound-report`; `rebound report`
/// runs it (found beside `rebound`), so the command works as before.
#[test]
fn report_runs_the_report_binary_beside_rebound() {
    let dir = Dir::new();
    let results = dir.join("results");
    std::fs::create_dir(&results).unwrap();
    let r = rebound(&["report", "--results", results.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{}", r.stderr);
    assert!(r.stderr.starts_with("report: read "), "{}", r.stderr);
    let md = std::fs::read_to_string(results.join("REPORT.md")).unwrap();
    assert!(md.starts_with("# rebound: reproduction report\n") && md.contains("*Not run: `"));
    // `--quiet` reaches it.
    let r = rebound(&["--quiet", "report", "--results", results.to_str().unwrap()]);
    assert_eq!((r.code, r.stderr.as_str()), (0, ""));
    // A missing tree is refused before anything runs.
    rebound(&["report", "--results", dir.join("nope").to_str().unwrap()]).refused("--results");
}
