//! Writing results, the primitives: output directories written as a whole (staging
//! directory, lock and swap: `out_dir`), atomic files (temporary file, then rename),
//! deterministic number formatting, CSV tables (`csv`) and the run manifest `run.toml`.
//! Low in the module picture: it depends on no physics, tally or case module. What each
//! command writes lives in `writers`; the schema of the tally outputs in `tally::schema`.

pub mod out_dir;

pub use self::out_dir::OutputDir;
pub use outputs::{csv, write_atomic, write_atomic_with, CsvTable};
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

use roughwall::{Error, Result};
use std::path::{Path, PathBuf};

/// Creates the output directory (and parents). Commands write into the staging directory of
/// an [`OutputDir`]; this only makes sure a directory exists.
pub fn prepare_out_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))
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

    /// Writes `dir/run.toml` with the wall time so far. A value that could not be computed
    /// (NaN or infinite) is left out, its key listed in `[run] not_computed` (issue 42: a
    /// scan offset by 1e300 m wrote `sq_um = inf`).
    pub fn write(mut self, dir: &Path) -> Result<PathBuf> {
        let wall = self.elapsed_s();
        self.set_run(
            "wall_time_s",
            toml::Value::Float((wall * 1e3).round() / 1e3),
        );
        let mut dropped = Vec::new();
        drop_non_finite(&mut self.root, "", &mut dropped);
        if !dropped.is_empty() {
            self.set_run(
                "not_computed",
                toml::Value::Array(dropped.into_iter().map(toml::Value::String).collect()),
            );
        }
        let text = toml::to_string_pretty(&self.root)
            .map_err(|e| Error::Internal(format!("run.toml: {e}")))?;
        let path = dir.join("run.toml");
        write_atomic(&path, text.as_bytes())?;
        Ok(path)
    }
}

/// Whether `v` holds a NaN or an infinity (in a float, or anywhere in an array).
fn non_finite(v: &toml::Value) -> bool {
    match v {
        toml::Value::Float(x) => !x.is_finite(),
        toml::Value::Array(a) => a.iter().any(non_finite),
        _ => false,
    }
}

/// Removes from `t` (and the tables inside it, also those in arrays of tables) every entry
/// holding a NaN or an infinity, pushing its dotted key (under `prefix`) to `dropped`.
fn drop_non_finite(t: &mut toml::Table, prefix: &str, dropped: &mut Vec<String>) {
    let path = |k: &str| {
        if prefix.is_empty() {
            k.to_string()
        } else {
            format!("{prefix}.{k}")
        }
    };
    t.retain(|k, v| {
        let keep = matches!(v, toml::Value::Array(a) if a.iter().all(toml::Value::is_table))
            || !non_finite(v);
        if !keep {
            dropped.push(path(k));
        }
        keep
    });
    for (k, v) in t.iter_mut() {
        match v {
            toml::Value::Table(inner) => drop_non_finite(inner, &path(k), dropped),
            toml::Value::Array(a) => {
                for (i, item) in a.iter_mut().enumerate() {
                    if let toml::Value::Table(inner) = item {
                        drop_non_finite(inner, &format!("{}[{i}]", path(k)), dropped);
                    }
                }
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A manifest never holds a NaN or an infinity: the entry is left out and named.
    #[test]
    fn non_finite_values_are_left_out_of_the_manifest_and_named() {
        let dir = tempfile::tempdir().unwrap();
        let mut m = Manifest::new("scan", &toml::Table::new(), 1, 1);
        let mut scan = toml::Table::new();
        scan.insert("sq_um".into(), toml::Value::Float(f64::INFINITY));
        scan.insert("lay_deg".into(), toml::Value::Float(3.0));
        scan.insert(
            "pixel_um".into(),
            toml::Value::Array(vec![1.0.into(), f64::NAN.into()]),
        );
        m.set("scan", toml::Value::Table(scan));
        let mut row = toml::Table::new();
        row.insert("fraction".into(), toml::Value::Float(f64::NAN));
        m.set(
            "diameter",
            toml::Value::Array(vec![toml::Value::Table(row)]),
        );
        let text = std::fs::read_to_string(m.write(dir.path()).unwrap()).unwrap();
        let back: toml::Table = text.parse().unwrap();
        assert!(
            !text.to_lowercase().contains("nan") && !text.contains("inf"),
            "{text}"
        );
        assert_eq!(back["scan"]["lay_deg"].as_float(), Some(3.0));
        let named: Vec<&str> = back["run"]["not_computed"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        assert_eq!(
            named,
            ["diameter[0].fraction", "scan.pixel_um", "scan.sq_um"]
        );
    }

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
