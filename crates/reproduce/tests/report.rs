//! `rebound-report` as a user (or `rebound report`, which runs it) meets it.

use std::path::Path;
use std::process::{Command, Output};

fn report(results: &Path, extra: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rebound-report"))
        .arg("--results")
        .arg(results)
        .args(extra)
        .output()
        .unwrap()
}

/// On an empty results tree every section says which run is missing, and nothing fails.
#[test]
fn an_empty_results_tree_gives_a_report_of_missing_runs() {
    let dir = tempfile::tempdir().unwrap();
    let out = report(dir.path(), &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let md = std::fs::read_to_string(dir.path().join("REPORT.md")).unwrap();
    assert!(md.starts_with("# rebound: reproduction report\n"));
    assert!(md.contains("*Not run: `"), "{md}");
    assert!(md.contains("no byte-for-byte check was possible"));
    let summary = String::from_utf8_lossy(&out.stderr);
    assert!(summary.starts_with("report: read ") && summary.contains("REPORT.md"));
    // `--quiet` prints nothing on success.
    let quiet = report(dir.path(), &["--quiet"]);
    assert!(quiet.status.success() && quiet.stderr.is_empty() && quiet.stdout.is_empty());
}

/// A missing results directory is a one-line error naming `--results`, with status 2, and
/// nothing is written.
#[test]
fn a_missing_results_directory_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no-such-results");
    let out = report(&missing, &[]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        err.contains("--results") && err.contains("no-such-results"),
        "{err}"
    );
    assert!(!missing.exists());
    // An unknown flag too.
    let out = report(dir.path(), &["--no-such-flag"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&out.stderr)
            .trim_end()
            .lines()
            .count(),
        1
    );
}
