//! What every simulation command resolves first: the case, the seed and the output folder
//! (the thread count goes into the manifest). Plain values in (no command-line types), so that the library runs a case
//! the same way whatever drives it.

use crate::case::{self, Case, DEFAULT_SEED};
use crate::output::Manifest;
use roughwall::{Error, Result};
use std::path::{Path, PathBuf};

/// A run's case, seed and output folder.
pub struct Context {
    pub case: Case,
    /// The case file's text and where it came from (a shard's partial tally carries them).
    pub case_text: String,
    pub case_origin: String,
    pub seed: u64,
    pub out_dir: PathBuf,
    pub manifest: Manifest,
}

impl Context {
    /// Loads the case file `case_file` (or the built-in `default_toml`) and resolves the seed
    /// (`seed` overrides the case's) and `out` (default
    /// `results/<case name>/<command>/`, for a case `name` that is one plain path component).
    /// Creates nothing on disk: commands write through an
    /// [`OutputDir`](crate::output::OutputDir) begun on `out_dir`.
    pub fn new(
        case_file: Option<&Path>,
        seed: Option<u64>,
        out: Option<PathBuf>,
        command: &str,
        default_toml: &str,
    ) -> Result<Context> {
        let (case_text, case_origin) = case::load_text(case_file, default_toml)?;
        Context::from_text(case_text, case_origin, seed, out, command)
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
            out_dir,
            manifest,
        })
    }

    /// Runs `command` on `case` instead of the case read (e.g. with a wall card's wall): the
    /// manifest's `[case]` and the text a shard carries (which `merge` reads back) become
    /// that case, written out.
    pub fn set_case(&mut self, case: Case, command: &str) -> Result<()> {
        self.case_text = toml::to_string(&case)
            .map_err(|e| Error::Internal(format!("writing the case out: {e}")))?;
        self.manifest = Manifest::new(command, &case, self.seed, rayon::current_num_threads());
        self.case = case;
        Ok(())
    }

    /// Where a shard writes its partial tally: `out` (`--out`), else
    /// `results/<name>/<command>/shard-K-of-N`.
    pub fn shard_dir(&self, out: Option<&Path>, shard: roughwall::tally::Shard) -> PathBuf {
        match out {
            Some(d) => d.to_path_buf(),
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
