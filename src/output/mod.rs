//! Writing results, the primitives: output directories written as a whole (staging
//! directory, lock and swap: `out_dir`), atomic files (temporary file, then rename),
//! deterministic number formatting, CSV tables (`csv`) and the run manifest `run.toml`.
//! Low in the module picture: it depends on no physics, tally or case module. What each
//! command writes lives in `writers`; the schema of the tally outputs in `tally::schema`.

pub mod csv;
pub mod out_dir;

pub use self::csv::CsvTable;
pub use self::out_dir::OutputDir;
pub use roughwall::format::{fmt_num, fmt_opt, fmt_sci};

/// A TOML string (quoted and escaped), for outputs written as commented TOML text.
pub fn toml_str(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

/// A TOML float with at most 7 significant digits (always with a `.` or an exponent).
pub fn toml_float(x: f64) -> String {
    let s = fmt_num(x);
    if s.contains(['.', 'e', 'E']) {
        s
    } else {
        format!("{s}.0")
    }
}

use roughwall::error::{Error, Result};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Creates the output directory (and parents). Commands write into the staging directory of
/// an [`OutputDir`]; this only makes sure a directory exists.
pub fn prepare_out_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))
}

/// Writes `bytes` to `path` through a temporary file in the same directory and a rename,
/// so a reader never sees a half-written file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic_with(path, |w| w.write_all(bytes))
}

/// Like [`write_atomic`], for content streamed by `fill` (e.g. a large height field).
pub fn write_atomic_with(
    path: &Path,
    fill: impl FnOnce(&mut std::io::BufWriter<std::fs::File>) -> std::io::Result<()>,
) -> Result<()> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let result = (|| -> std::io::Result<()> {
        let mut w = std::io::BufWriter::with_capacity(1 << 20, std::fs::File::create(&tmp)?);
        fill(&mut w)?;
        w.flush()?;
        w.get_ref().sync_all()?;
        drop(w);
        std::fs::rename(&tmp, path)
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(Error::io(path, e));
    }
    Ok(())
}

/// SHA-256 of `bytes`, in lowercase hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::{Digest, Sha256};
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The run manifest `run.toml`: what ran, with which case, seed and threads, and how long
/// it took. Timings live only here so that the CSV outputs are byte-identical between runs.
pub struct Manifest {
    root: toml::Table,
    started: std::time::Instant,
}

impl Manifest {
    /// `case` is written as the `[case]` table (the binary passes its `case::Case`).
    pub fn new(command: &str, case: &impl serde::Serialize, seed: u64, threads: usize) -> Manifest {
        let mut run = toml::Table::new();
        run.insert("command".into(), command.into());
        run.insert("version".into(), crate::BUILD_VERSION.into());
        run.insert("seed".into(), toml::Value::Integer(seed as i64));
        run.insert("threads".into(), toml::Value::Integer(threads as i64));
        let mut root = toml::Table::new();
        root.insert("run".into(), toml::Value::Table(run));
        let case_value =
            toml::Value::try_from(case).unwrap_or(toml::Value::Table(toml::Table::new()));
        root.insert("case".into(), case_value);
        Manifest {
            root,
            started: std::time::Instant::now(),
        }
    }

    /// Adds or replaces a top-level entry (e.g. a `[surface_choice]` table).
    pub fn set(&mut self, key: &str, value: toml::Value) {
        self.root.insert(key.into(), value);
    }

    /// Adds an entry to the `[run]` table.
    pub fn set_run(&mut self, key: &str, value: toml::Value) {
        if let Some(toml::Value::Table(run)) = self.root.get_mut("run") {
            run.insert(key.into(), value);
        }
    }

    /// Seconds since the manifest was created.
    pub fn elapsed_s(&self) -> f64 {
        self.started.elapsed().as_secs_f64()
    }

    /// Writes `dir/run.toml` with the wall time so far.
    pub fn write(mut self, dir: &Path) -> Result<PathBuf> {
        let wall = self.elapsed_s();
        self.set_run(
            "wall_time_s",
            toml::Value::Float((wall * 1e3).round() / 1e3),
        );
        let text = toml::to_string_pretty(&self.root)
            .map_err(|e| Error::Internal(format!("run.toml: {e}")))?;
        let path = dir.join("run.toml");
        write_atomic(&path, text.as_bytes())?;
        Ok(path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_stable() {
        assert_eq!(fmt_num(0.123456789), "0.1234568");
        assert_eq!(fmt_num(32.5), "32.5");
        assert_eq!(fmt_num(-1e-9), "-0.000000001");
        assert_eq!(fmt_num(0.0), "0");
        assert_eq!(fmt_num(f64::NAN), "");
    }

    #[test]
    fn scientific_cells_keep_seven_digits() {
        assert_eq!(fmt_sci(1.8170774e-8), "1.817077e-8");
        assert_eq!(fmt_sci(-2.5e-17), "-2.5e-17");
        assert_eq!(fmt_sci(3.0), "3e0");
        assert_eq!(fmt_sci(0.0), "0");
        assert_eq!(fmt_sci(f64::INFINITY), "");
        for x in [1.8170774e-8, 3.787272e-43, 6.02214076e23] {
            let back: f64 = fmt_sci(x).parse().unwrap();
            assert!((back / x - 1.0).abs() < 5e-7, "{x}");
        }
    }

    #[test]
    fn atomic_write_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.csv");
        write_atomic(&p, b"x\n").unwrap();
        let names: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("a.csv")]);
    }
}
