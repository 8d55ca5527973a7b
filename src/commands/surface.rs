//! `rebound surface`.

use crate::cli::SurfaceArgs;
use crate::commands::Context;
use crate::error::{Error, Result};

/// Runs the subcommand. Not implemented yet: checks the case, then refuses with exit
/// status 2 rather than writing fake output.
pub fn run(args: &SurfaceArgs) -> Result<()> {
    Context::new(&args.common, "surface", "name = \"default\"\n")?;
    Err(Error::NotImplemented("`rebound surface` (issue #2)".into()))
}
