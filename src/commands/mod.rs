//! One module per subcommand: read the case, run the library, write outputs.

pub mod compare;
pub mod deterministic;
pub mod force_sweep;
pub mod report;
pub mod stochastic;
pub mod surface;

use crate::case::{self, Case, DEFAULT_SEED};
use crate::cli::CommonArgs;
use crate::error::Result;
use crate::output::Manifest;
use std::path::PathBuf;

/// What every simulation subcommand resolves first: case, seed, threads, output folder.
pub struct Context {
    pub case: Case,
    pub seed: u64,
    pub threads: usize,
    pub out_dir: PathBuf,
    pub manifest: Manifest,
}

impl Context {
    /// Loads the case (or the built-in `default_toml`) and resolves seed, threads and `--out`
    /// (default `results/<case name>/<command>/`). Creates nothing on disk.
    pub fn new(common: &CommonArgs, command: &str, default_toml: &str) -> Result<Context> {
        let case = case::load(common.case.as_deref(), default_toml)?;
        let seed = common.seed.or(case.seed).unwrap_or(DEFAULT_SEED);
        let threads = rayon::current_num_threads();
        let out_dir = common
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from("results").join(&case.name).join(command));
        let manifest = Manifest::new(command, &case, seed, threads);
        Ok(Context {
            case,
            seed,
            threads,
            out_dir,
            manifest,
        })
    }
}
