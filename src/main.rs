//! The `rebound` binary: parse, dispatch, report errors. The physics lives in the library
//! crate `roughwall` (crates/roughwall); the modules here are what the tool adds over it.
//!
//! A run goes through them in this order: `cli` parses, `commands` dispatches; `case` reads
//! and checks the case file into the library's resolved values (returning warnings, never
//! printing them); `run_context` holds the case, seed, threads and output folder; `runner`
//! drives the library's tally engine with a `progress` bar, or writes and merges the shards'
//! `partial` tallies; `writers` write each command's tables (columns named in `schema`),
//! figures (`figures`, the one place that imports `plotters`) and `run.toml`, on the
//! primitives of `output`; `compare` reads two runs and computes their distances;
//! `pipe_flow` reduces a code_saturne pipe-flow study (`pipe-stats`). The paper-reproduction
//! report is not here: `rebound report` runs `rebound-report` (crates/reproduce). Files import each other without cycles (checked by the test
//! `tests/layering.rs`).

mod case;
mod cli;
mod commands;
mod compare;
mod figures;
mod measured_wall;
mod output;
mod partial;
mod pipe_flow;
mod progress;
mod run_context;
mod runner;
mod scan_wall;
mod schema;
mod writers;

/// This build's identity: the package version, `+src.`, and a 64-bit FNV-1a digest (16 hex
/// digits) of the sources of both crates, their manifests and `Cargo.lock` (`build.rs`), e.g.
/// `0.1.0+src.0123456789abcdef`. The package version alone is the same for every commit; this
/// changes whenever the code that produces results does. Partial tallies record it and
/// `rebound merge` refuses shards of another build; `run.toml` records it as `version`.
pub const BUILD_VERSION: &str = concat!(
    env!("CARGO_PKG_VERSION"),
    "+src.",
    env!("ROUGHWALL_SOURCE_DIGEST")
);

use clap::error::ErrorKind;
use clap::Parser;

fn main() {
    output::out_dir::remove_staging_on_signals();
    let cli = match cli::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e)
            if matches!(
                e.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) =>
        {
            e.exit()
        }
        Err(e) => {
            // One line, like every other input error: clap's message without its usage hints.
            eprintln!("{}", cli::one_line(&e.render().to_string()));
            std::process::exit(2);
        }
    };
    if let Err(e) = commands::run(cli) {
        eprintln!("error: {e}");
        std::process::exit(e.exit_code());
    }
}
