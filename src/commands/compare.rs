//! `rebound compare`.

use crate::cli::CompareArgs;
use crate::error::{Error, Result};

/// Runs the subcommand. Not implemented yet: refuses with exit status 2 rather than fake output.
pub fn run(_args: &CompareArgs) -> Result<()> {
    Err(Error::NotImplemented("`rebound compare` (issue #4)".into()))
}
