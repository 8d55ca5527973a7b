//! `rebound report`.

use crate::cli::ReportArgs;
use crate::commands::{Summary, Wrote};
use roughwall::{Error, Result};

/// Writes `REPORT.md` and the aggregated tables under `--results`.
///
/// Unlike the other commands, `report` does not replace a directory as a whole: it adds a
/// few files (`REPORT.md`, `fig4.csv`/`.svg`, `speed_vs_error.csv`/`.svg`) to an existing
/// results tree that the runs own, so each file is written on its own, atomically
/// (`output::write_atomic`: temporary file, then rename).
pub fn run(args: &ReportArgs) -> Result<Summary> {
    if !args.results.is_dir() {
        return Err(Error::invalid(
            "--results",
            args.results.display(),
            "an existing directory written by scripts/reproduce-all.sh",
        ));
    }
    crate::report::write_report(&args.results)?;
    Ok(Summary {
        work: format!("read {}", args.results.display()),
        rate: None,
        wrote: Wrote::Files(vec![args.results.join("REPORT.md")]),
    })
}
