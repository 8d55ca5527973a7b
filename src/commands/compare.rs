//! `rebound compare --a DIR --b DIR --out DIR`: KS and L1 distances, means and stds of
//! the PDFs of two runs (see `crate::compare`).

use crate::cli::CompareArgs;
use roughwall::error::Result;

/// Runs the subcommand.
pub fn run(args: &CompareArgs) -> Result<()> {
    roughwall::compare::run_compare(&args.a, &args.b, &args.out, &args.label_a, &args.label_b)?;
    Ok(())
}
