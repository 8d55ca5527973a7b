//! `rebound compare --a DIR --b DIR --out DIR`: KS and L1 distances, means and stds of
//! the PDFs of two runs (see `crate::compare`).

use crate::cli::CompareArgs;
use crate::commands::{Summary, Wrote};
use roughwall::error::Result;

/// Runs the subcommand.
pub fn run(args: &CompareArgs) -> Result<Summary> {
    let (rows, unmatched) =
        roughwall::compare::run_compare(&args.a, &args.b, &args.out, &args.label_a, &args.label_b)?;
    let unmatched = match unmatched {
        0 => String::new(),
        n => format!(", {n} unmatched"),
    };
    Ok(Summary {
        work: format!("{rows} rows compared{unmatched}"),
        rate: None,
        wrote: Wrote::Dir(args.out.clone()),
    })
}
