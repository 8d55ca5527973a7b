//! One module per subcommand: read the case, run the library, write outputs.

pub mod calibrate;
pub mod compare;
pub mod deterministic;
pub mod force_sweep;
pub mod merge;
pub mod report;
pub mod stochastic;
pub mod surface;

use crate::case::{self, Case, DEFAULT_SEED};
use crate::cli::CommonArgs;
use crate::error::{Error, Result};
use crate::output::Manifest;
use std::path::PathBuf;

/// What every simulation subcommand resolves first: case, seed, threads, output folder.
pub struct Context {
    pub case: Case,
    /// The case file's text and where it came from (a shard's partial tally carries them).
    pub case_text: String,
    pub case_origin: String,
    pub seed: u64,
    pub threads: usize,
    pub out_dir: PathBuf,
    pub manifest: Manifest,
}

impl Context {
    /// Loads the case (or the built-in `default_toml`) and resolves seed, threads and `--out`
    /// (default `results/<case name>/<command>/`, for a case `name` that is one plain path
    /// component). Creates nothing on disk: commands write through an
    /// [`OutputDir`](crate::output::OutputDir) begun on `out_dir`.
    pub fn new(common: &CommonArgs, command: &str, default_toml: &str) -> Result<Context> {
        let (case_text, case_origin) = case::load_text(common.case.as_deref(), default_toml)?;
        Context::from_text(
            case_text,
            case_origin,
            common.seed,
            common.out.clone(),
            command,
        )
    }

    /// The context of a case given as text (e.g. carried by a partial tally).
    pub fn from_text(
        case_text: String,
        case_origin: String,
        seed: Option<u64>,
        out: Option<PathBuf>,
        command: &str,
    ) -> Result<Context> {
        let case = case::parse(&case_text, &case_origin)?;
        let seed = seed.or(case.seed).unwrap_or(DEFAULT_SEED);
        let threads = rayon::current_num_threads();
        let out_dir = match out {
            Some(d) => d,
            None => {
                check_name(&case.name)?;
                PathBuf::from("results").join(&case.name).join(command)
            }
        };
        let manifest = Manifest::new(command, &case, seed, threads);
        Ok(Context {
            case,
            case_text,
            case_origin,
            seed,
            threads,
            out_dir,
            manifest,
        })
    }

    /// Where a shard writes its partial tally: `--out`, else
    /// `results/<name>/<command>/shard-K-of-N`.
    pub fn shard_dir(&self, common: &CommonArgs, shard: crate::tally::Shard) -> PathBuf {
        match &common.out {
            Some(d) => d.clone(),
            None => self
                .out_dir
                .join(format!("shard-{}-of-{}", shard.index, shard.count)),
        }
    }
}

/// A case `name` names the default output directory `results/<name>/<command>/`: it must be
/// one plain path component, so that the outputs stay under `results/`.
pub fn check_name(name: &str) -> Result<()> {
    let plain = !name.is_empty()
        && name.len() <= 255
        && name != "."
        && name != ".."
        && !name.contains(['/', '\\', '\0']);
    if plain {
        return Ok(());
    }
    Err(Error::invalid(
        "name",
        format!("{name:?}"),
        "one plain path component (not empty, no `/`, `\\` or NUL, not `.` or `..`, at most 255 bytes): the default output directory is results/<name>/<command>/",
    ))
}
