//! `rebound stochastic`.

use crate::cli::StochasticArgs;
use crate::commands::Context;
use crate::error::{Error, Result};

/// Runs the subcommand. Not implemented yet: checks the case, then refuses with exit
/// status 2 rather than writing fake output.
pub fn run(args: &StochasticArgs) -> Result<()> {
    Context::new(&args.common, "stochastic", "name = \"default\"\n")?;
    Err(Error::NotImplemented(
        "`rebound stochastic` (issue #4)".into(),
    ))
}
