//! One module per subcommand: context → resolve → run → write, each step a library call.

pub mod calibrate;
pub mod compare;
pub mod deterministic;
pub mod force_sweep;
pub mod merge;
pub mod report;
pub mod stochastic;
pub mod surface;

use crate::cli::CommonArgs;
use roughwall::error::Result;
use roughwall::run_context::Context;

/// The run context of `--case`, `--seed` and `--out` (threads: the pool the command runs in).
pub fn context(common: &CommonArgs, command: &str, default_toml: &str) -> Result<Context> {
    Context::new(
        common.case.as_deref(),
        common.seed,
        common.out.clone(),
        command,
        default_toml,
    )
}
