//! `rebound deterministic`.

use crate::cli::DeterministicArgs;
use crate::commands::Context;
use crate::error::{Error, Result};

/// Runs the subcommand. Not implemented yet: checks the case, then refuses with exit
/// status 2 rather than writing fake output.
pub fn run(args: &DeterministicArgs) -> Result<()> {
    Context::new(&args.common, "deterministic", "name = \"default\"\n")?;
    Err(Error::NotImplemented(
        "`rebound deterministic` (issue #3)".into(),
    ))
}
