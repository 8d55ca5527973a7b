//! Reading the tool's own CSV outputs back by column name, for the report.

use crate::error::{Error, Result};
use std::collections::HashMap;
use std::path::Path;

/// A CSV file as rows of `column → cell`.
#[derive(Clone, Debug, Default)]
pub struct Rows {
    pub rows: Vec<HashMap<String, String>>,
}

impl Rows {
    /// Reads `path`; `Ok(None)` if the file does not exist.
    pub fn read(path: &Path) -> Result<Option<Rows>> {
        if !path.is_file() {
            return Ok(None);
        }
        let mut r = csv::Reader::from_path(path)
            .map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
        let header: Vec<String> = r
            .headers()
            .map_err(|e| Error::Input(format!("{}: {e}", path.display())))?
            .iter()
            .map(String::from)
            .collect();
        let mut rows = Vec::new();
        for rec in r.records() {
            let rec = rec.map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
            rows.push(
                header
                    .iter()
                    .cloned()
                    .zip(rec.iter().map(String::from))
                    .collect(),
            );
        }
        Ok(Some(Rows { rows }))
    }

    /// Rows whose numeric columns equal the given values (within 1e-9).
    pub fn filter(&self, keys: &[(&str, f64)]) -> Vec<&HashMap<String, String>> {
        self.rows
            .iter()
            .filter(|r| {
                keys.iter()
                    .all(|(k, v)| num(r, k).is_some_and(|x| (x - v).abs() < 1e-9))
            })
            .collect()
    }

    /// Rows whose text column equals `value`.
    pub fn with<'a>(&'a self, key: &str, value: &str) -> Vec<&'a HashMap<String, String>> {
        self.rows
            .iter()
            .filter(|r| r.get(key).map(String::as_str) == Some(value))
            .collect()
    }
}

/// A numeric cell, `None` when absent or empty.
pub fn num(row: &HashMap<String, String>, key: &str) -> Option<f64> {
    row.get(key).and_then(|s| s.parse::<f64>().ok())
}

/// Wall time and other `[run]` entries of a `run.toml`.
pub fn run_toml(dir: &Path) -> Option<toml::Table> {
    let text = std::fs::read_to_string(dir.join("run.toml")).ok()?;
    toml::from_str(&text).ok()
}

/// `[run] wall_time_s` of a run directory.
pub fn wall_time_s(dir: &Path) -> Option<f64> {
    let t = run_toml(dir)?;
    t.get("run")?.get("wall_time_s")?.as_float()
}
