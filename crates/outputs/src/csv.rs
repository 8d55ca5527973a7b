//! CSV tables: writing them with a fixed header, and the one reader of the tool's own
//! outputs (by column name), which `compare` and `report` share.

use roughwall::{Error, Result};
use std::collections::HashMap;
use std::path::Path;

/// A CSV table with a fixed header.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CsvTable {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl CsvTable {
    pub fn new(header: &[&str]) -> CsvTable {
        CsvTable {
            header: header.iter().map(|s| s.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    pub fn push(&mut self, row: Vec<String>) {
        debug_assert_eq!(row.len(), self.header.len());
        self.rows.push(row);
    }

    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
        // Writing into memory cannot fail.
        let _ = w.write_record(&self.header);
        for r in &self.rows {
            let _ = w.write_record(r);
        }
        w.into_inner().unwrap_or_default()
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        crate::write_atomic(path, &self.to_bytes())
    }
}

/// A CSV file as rows of `column → cell`: the one reader of the tool's outputs.
#[derive(Clone, Debug, Default)]
pub struct Rows {
    /// Column names in file order.
    pub header: Vec<String>,
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
            if rec.len() != header.len() {
                return Err(Error::Input(format!(
                    "{}: not a rebound output (a row has {} cells, the header {})",
                    path.display(),
                    rec.len(),
                    header.len()
                )));
            }
            rows.push(
                header
                    .iter()
                    .cloned()
                    .zip(rec.iter().map(String::from))
                    .collect(),
            );
        }
        Ok(Some(Rows { header, rows }))
    }

    /// Reads a table this tool wrote, whose header must start with `columns` (later
    /// versions append columns, never rename or reorder them). A missing file, another
    /// header or a ragged row is an input error naming the file.
    pub fn read_output(path: &Path, columns: &[&str]) -> Result<Rows> {
        let bad = |what: String| {
            Error::Input(format!("{}: not a rebound output ({what})", path.display()))
        };
        let rows = Rows::read(path)?.ok_or_else(|| {
            let name = path
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let dir = path.parent().unwrap_or(Path::new("."));
            Error::Input(format!(
                "{}: not a rebound output (no {name})",
                dir.display()
            ))
        })?;
        if rows.header.len() < columns.len() || rows.header[..columns.len()] != *columns {
            return Err(bad(format!(
                "header is `{}`, expected `{}…`",
                rows.header.join(","),
                columns.join(",")
            )));
        }
        Ok(rows)
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
