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
use roughwall::case::Warning;
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

/// Hands the warnings of the library to the binary's stderr: `cli::run` prints them, in
/// order, once the command has succeeded (an error is always the one line a failed run prints).
pub fn warn(warnings: impl IntoIterator<Item = Warning>) {
    for w in warnings {
        roughwall::case::warn(&w.0);
    }
}
