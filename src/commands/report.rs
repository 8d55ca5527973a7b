//! `rebound report`.

use crate::cli::ReportArgs;
use crate::error::{Error, Result};

/// Writes `REPORT.md` and the aggregated tables under `--results`.
pub fn run(args: &ReportArgs) -> Result<()> {
    if !args.results.is_dir() {
        return Err(Error::invalid(
            "--results",
            args.results.display(),
            "an existing directory written by scripts/reproduce-all.sh",
        ));
    }
    crate::report::write_report(&args.results)?;
    eprintln!("wrote {}", args.results.join("REPORT.md").display());
    Ok(())
}
