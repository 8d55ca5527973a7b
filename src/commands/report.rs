//! `rebound report`: the paper-reproduction report lives apart from the shipped binary, in
//! `crates/reproduce` (binary `rebound-report`); this command hands its arguments to that
//! binary, found beside `rebound` or else on `PATH`, the way `git` and `cargo` run their
//! external subcommands.

use crate::cli::ReportArgs;
use roughwall::Error;
use std::path::PathBuf;
use std::process::Command;

/// The report's binary.
const REPORT_BIN: &str = "rebound-report";

/// Replaces this process with `rebound-report --results <dir>` (and `--quiet` when `quiet`);
/// returns only when that failed, with the error.
pub fn run(args: &ReportArgs, quiet: bool) -> Error {
    if !args.results.is_dir() {
        return Error::invalid(
            "--results",
            args.results.display(),
            "an existing directory written by scripts/reproduce-all.sh",
        );
    }
    let bin = report_bin();
    let mut command = Command::new(&bin);
    command.arg("--results").arg(&args.results);
    if quiet {
        command.arg("--quiet");
    }
    let missing = |e: std::io::Error| {
        Error::Io(format!(
            "rebound report runs `{REPORT_BIN}`, which was not found beside rebound or on PATH ({e}): \
             build it with `cargo build --release` (the workspace builds both) or install it with \
             `cargo install --path crates/reproduce`"
        ))
    };
    #[cfg(unix)]
    {
        use std::os::unix::process::CommandExt;
        // `exec` returns only when it failed.
        missing(command.exec())
    }
    #[cfg(not(unix))]
    {
        match command.status() {
            Ok(status) => std::process::exit(status.code().unwrap_or(1)),
            Err(e) => missing(e),
        }
    }
}

/// `rebound-report` beside the running `rebound`, else the bare name (looked up on `PATH`).
fn report_bin() -> PathBuf {
    let name = format!("{REPORT_BIN}{}", std::env::consts::EXE_SUFFIX);
    std::env::current_exe()
        .ok()
        .map(|exe| exe.with_file_name(&name))
        .filter(|p| p.is_file())
        .unwrap_or_else(|| PathBuf::from(name))
}
