//! `rebound force-sweep`.

use crate::cli::ForceSweepArgs;
use crate::commands::Context;
use crate::error::{Error, Result};

/// Runs the subcommand. Not implemented yet: checks the case, then refuses with exit
/// status 2 rather than writing fake output.
pub fn run(args: &ForceSweepArgs) -> Result<()> {
    Context::new(&args.common, "force-sweep", "name = \"default\"\n")?;
    Err(Error::NotImplemented(
        "`rebound force-sweep` (issue #5)".into(),
    ))
}
