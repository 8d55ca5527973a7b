//! The output schema of `deterministic` and `stochastic` (and of `merge`): one place that
//! names the columns of `summary.csv`, `pdfs.csv` and `moments.csv`, turns typed results
//! into rows, and reads the files back for `compare` and `report`.
//!
//! Columns are only ever appended: a reader that looks columns up by name keeps working.
//! An empty cell means "not applicable to this model" (e.g. `mean_collisions` of the
//! stochastic model, or the standard error of a model curve).

use crate::output::csv::{CsvTable, Rows};
use crate::output::{fmt_num, fmt_sci};
use roughwall::incidence::fmt_key;
use roughwall::tally::{ConditionResult, Estimate, Quantity};
use roughwall::{Error, Result};
use std::collections::BTreeMap;
use std::path::Path;

/// Columns of `summary.csv`: the 20 of the first version, then the standard errors.
pub const SUMMARY_HEADER: [&str; 28] = [
    "alpha_in_deg",
    "beta_in_deg",
    "delta_xi_deg",
    "delta_zeta_deg",
    "particles",
    "mean_alpha_out_deg",
    "std_alpha_out_deg",
    "mean_dbeta_deg",
    "std_dbeta_deg",
    "mean_dbeta_first_deg",
    "std_dbeta_first_deg",
    "mean_gamma_deg",
    "std_gamma_deg",
    "mean_gamma_star_deg",
    "std_gamma_star_deg",
    "p_single",
    "mean_collisions",
    "max_collisions",
    "mean_speed_ratio",
    "lost",
    "se_mean_alpha_out_deg",
    "se_mean_dbeta_deg",
    "se_mean_dbeta_first_deg",
    "se_mean_gamma_deg",
    "se_mean_gamma_star_deg",
    "se_p_single",
    "se_mean_collisions",
    "se_mean_speed_ratio",
];

/// Columns appended to `summary.csv` when the case has `[erosion]`: wall volume per unit
/// particle mass (m³/kg), impacts per history, what rejected stochastic candidates would
/// remove (m³/kg), and the volume per particle (m³), each with its standard error.
pub const SUMMARY_EROSION_HEADER: [&str; 8] = [
    "erosion_per_mass",
    "se_erosion_per_mass",
    "mean_impacts",
    "se_mean_impacts",
    "erosion_per_mass_rejected",
    "se_erosion_per_mass_rejected",
    "erosion_per_particle_m3",
    "se_erosion_per_particle_m3",
];

/// Columns of `pdfs.csv` (long format); `se` is the standard error of `value`.
pub const PDFS_HEADER: [&str; 7] = [
    "alpha_in_deg",
    "beta_in_deg",
    "quantity",
    "bin_lo",
    "bin_hi",
    "value",
    "se",
];

/// Columns of `moments.csv`: exact (unbinned) count, mean, standard deviation and
/// standard error of the mean of every tallied quantity, then the standard error the values
/// would have if they were independent (`se_histories`: equal to `se` but over several
/// surface realisations, where `se` includes the spread between them).
pub const MOMENTS_HEADER: [&str; 8] = [
    "alpha_in_deg",
    "beta_in_deg",
    "quantity",
    "n",
    "mean",
    "std",
    "se",
    "se_histories",
];

/// The columns of `moments.csv` a reader needs (the first version's).
pub const MOMENTS_REQUIRED: usize = 7;

/// The columns a reader needs (the first version's; later ones are optional).
pub const SUMMARY_REQUIRED: usize = 20;
pub const PDFS_REQUIRED: usize = 6;

/// The output files of a tally run.
pub const SUMMARY_CSV: &str = "summary.csv";
pub const PDFS_CSV: &str = "pdfs.csv";
pub const MOMENTS_CSV: &str = "moments.csv";

fn opt(x: Option<f64>) -> String {
    x.map(fmt_num).unwrap_or_default()
}

/// The `summary.csv` row of a condition.
pub fn summary_row(r: &ConditionResult) -> Vec<String> {
    let s = &r.summary;
    let mean = |e: Option<Estimate>| opt(e.map(|e| e.mean));
    let std = |e: Option<Estimate>| opt(e.and_then(|e| e.std));
    let se = |e: Option<Estimate>| opt(e.and_then(|e| e.se));
    vec![
        fmt_key(s.condition.alpha_in_deg()),
        fmt_key(s.condition.beta_in_deg()),
        fmt_num(s.deviations.delta_xi.to_degrees()),
        fmt_num(s.deviations.delta_zeta.to_degrees()),
        s.particles.to_string(),
        mean(s.alpha_out),
        std(s.alpha_out),
        mean(s.dbeta),
        std(s.dbeta),
        mean(s.dbeta_first),
        std(s.dbeta_first),
        mean(s.gamma),
        std(s.gamma),
        mean(s.gamma_star),
        std(s.gamma_star),
        opt(s.p_single.map(|p| p.value)),
        mean(s.collisions),
        s.max_collisions.map(|m| m.to_string()).unwrap_or_default(),
        mean(s.speed_ratio),
        s.lost.map(|l| l.to_string()).unwrap_or_default(),
        se(s.alpha_out),
        se(s.dbeta),
        se(s.dbeta_first),
        se(s.gamma),
        se(s.gamma_star),
        opt(s.p_single.and_then(|p| p.se)),
        se(s.collisions),
        se(s.speed_ratio),
    ]
}

/// The erosion cells of a condition's `summary.csv` row (empty without erosion).
fn erosion_cells(r: &ConditionResult) -> Vec<String> {
    let Some(e) = &r.summary.erosion else {
        return vec![String::new(); SUMMARY_EROSION_HEADER.len()];
    };
    let sci = |x: Option<f64>| x.map(fmt_sci).unwrap_or_default();
    let pair = |x: Option<Estimate>| [sci(x.map(|e| e.mean)), sci(x.and_then(|e| e.se))];
    let impacts = e.impacts;
    [
        pair(e.per_mass),
        [
            opt(impacts.map(|e| e.mean)),
            opt(impacts.and_then(|e| e.se)),
        ],
        pair(e.rejected_per_mass),
        pair(e.per_particle),
    ]
    .concat()
}

/// `summary.csv`, `pdfs.csv` and `moments.csv` of a run.
pub fn tables(results: &[ConditionResult]) -> [CsvTable; 3] {
    let erosion = results.iter().any(|r| r.summary.erosion.is_some());
    let mut header = SUMMARY_HEADER.to_vec();
    if erosion {
        header.extend(SUMMARY_EROSION_HEADER);
    }
    let mut summary = CsvTable::new(&header);
    let mut pdfs = CsvTable::new(&PDFS_HEADER);
    let mut moments = CsvTable::new(&MOMENTS_HEADER);
    for r in results {
        let mut row = summary_row(r);
        if erosion {
            row.extend(erosion_cells(r));
        }
        summary.push(row);
        let c = r.condition();
        let (a, b) = (fmt_key(c.alpha_in_deg()), fmt_key(c.beta_in_deg()));
        for pdf in &r.pdfs {
            for bin in &pdf.bins {
                pdfs.push(vec![
                    a.clone(),
                    b.clone(),
                    pdf.quantity.name().to_string(),
                    fmt_num(bin.lo),
                    fmt_num(bin.hi),
                    fmt_num(bin.value),
                    opt(bin.se),
                ]);
            }
        }
        for (q, e) in &r.estimates {
            // Erosion volumes (m³/kg) are far below 1: scientific notation.
            let f = if q.is_erosion() { fmt_sci } else { fmt_num };
            moments.push(vec![
                a.clone(),
                b.clone(),
                q.name().to_string(),
                e.n.to_string(),
                f(e.mean),
                e.std.map(f).unwrap_or_default(),
                e.se.map(f).unwrap_or_default(),
                e.se_histories.map(f).unwrap_or_default(),
            ]);
        }
    }
    [summary, pdfs, moments]
}

/// Writes `summary.csv`, `pdfs.csv` and `moments.csv` into `dir`.
pub fn write_tables(dir: &Path, results: &[ConditionResult]) -> Result<()> {
    let [s, p, m] = tables(results);
    s.write(&dir.join(SUMMARY_CSV))?;
    p.write(&dir.join(PDFS_CSV))?;
    m.write(&dir.join(MOMENTS_CSV))
}

/// An incident condition as written in the CSV files: `(alpha_in_deg, beta_in_deg)`.
pub type ConditionKey = (String, String);

/// A binned PDF read back: `(lo, hi, value)` per bin, in file order.
pub type BinsRead = Vec<(f64, f64, f64)>;

/// A run's tally outputs read back (`compare`, `report`).
#[derive(Clone, Debug, Default)]
pub struct RunTables {
    /// Conditions in file order, with their parsed angles.
    pub conditions: Vec<(String, String, f64, f64)>,
    /// `(α⁻, β⁻) → [(quantity, bins)]`, quantities in file order.
    pub pdfs: BTreeMap<ConditionKey, Vec<(String, BinsRead)>>,
    /// `(α⁻, β⁻, quantity) → estimate` from `moments.csv` (empty for runs written before
    /// it existed).
    pub estimates: BTreeMap<(String, String, String), Estimate>,
}

fn cell<'a>(row: &'a std::collections::HashMap<String, String>, key: &str) -> &'a str {
    row.get(key).map_or("", String::as_str)
}

fn number(s: &str, path: &Path, what: &str) -> Result<f64> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(Error::Input(format!(
            "{}: not a rebound output (`{what}` = \"{s}\" is not a finite number)",
            path.display()
        ))),
    }
}

/// [`number`], or `None` for an empty cell (a value undefined for the run, e.g. a standard
/// deviation of one value).
fn optional_number(s: &str, path: &Path, what: &str) -> Result<Option<f64>> {
    if s.is_empty() {
        return Ok(None);
    }
    number(s, path, what).map(Some)
}

/// Reads `summary.csv`, `pdfs.csv` and (when present) `moments.csv` of a run directory;
/// `flag` (e.g. `--a`) names it in errors. A directory without the first two, or with
/// other columns, is not a rebound output: a one-line input error.
pub fn read_run(dir: &Path, flag: &str) -> Result<RunTables> {
    if !dir.is_dir() {
        return Err(Error::Input(format!(
            "`{flag}` {}: not a directory",
            dir.display()
        )));
    }
    let named = |e: Error| match e {
        Error::Input(m) => Error::Input(format!("`{flag}` {m}")),
        other => other,
    };
    let (sp, pp, mp) = (
        dir.join(SUMMARY_CSV),
        dir.join(PDFS_CSV),
        dir.join(MOMENTS_CSV),
    );
    let summary = Rows::read_output(&sp, &SUMMARY_HEADER[..SUMMARY_REQUIRED]).map_err(named)?;
    let pdfs = Rows::read_output(&pp, &PDFS_HEADER[..PDFS_REQUIRED]).map_err(named)?;
    let moments = if mp.is_file() {
        Some(Rows::read_output(&mp, &MOMENTS_HEADER[..MOMENTS_REQUIRED]).map_err(named)?)
    } else {
        None
    };
    let mut out = RunTables::default();
    let mut add_condition = |a: &str, b: &str, path: &Path| -> Result<ConditionKey> {
        if !out.conditions.iter().any(|c| c.0 == a && c.1 == b) {
            let (af, bf) = (
                number(a, path, "alpha_in_deg")?,
                number(b, path, "beta_in_deg")?,
            );
            out.conditions.push((a.into(), b.into(), af, bf));
        }
        Ok((a.to_string(), b.to_string()))
    };
    for row in &summary.rows {
        add_condition(cell(row, "alpha_in_deg"), cell(row, "beta_in_deg"), &sp).map_err(named)?;
    }
    for row in &pdfs.rows {
        let key = add_condition(cell(row, "alpha_in_deg"), cell(row, "beta_in_deg"), &pp)
            .map_err(named)?;
        let q = cell(row, "quantity").to_string();
        let bin = (
            number(cell(row, "bin_lo"), &pp, "bin_lo").map_err(named)?,
            number(cell(row, "bin_hi"), &pp, "bin_hi").map_err(named)?,
            number(cell(row, "value"), &pp, "value").map_err(named)?,
        );
        let list = out.pdfs.entry(key).or_default();
        match list.iter_mut().find(|e| e.0 == q) {
            Some(e) => e.1.push(bin),
            None => list.push((q, vec![bin])),
        }
    }
    for row in moments.iter().flat_map(|m| &m.rows) {
        let n = number(cell(row, "n"), &mp, "n").map_err(named)?;
        let se = optional_number(cell(row, "se"), &mp, "se").map_err(named)?;
        let e = Estimate {
            n: n.max(0.0) as u64,
            mean: number(cell(row, "mean"), &mp, "mean").map_err(named)?,
            std: optional_number(cell(row, "std"), &mp, "std").map_err(named)?,
            se,
            // Written before the column existed: one surface, the same error.
            se_histories: match row.get("se_histories") {
                Some(s) => optional_number(s, &mp, "se_histories").map_err(named)?,
                None => se,
            },
        };
        out.estimates.insert(
            (
                cell(row, "alpha_in_deg").into(),
                cell(row, "beta_in_deg").into(),
                cell(row, "quantity").into(),
            ),
            e,
        );
    }
    Ok(out)
}

impl RunTables {
    /// The estimate of `quantity` at a condition, when the run wrote `moments.csv`.
    pub fn estimate(&self, key: &ConditionKey, quantity: Quantity) -> Option<&Estimate> {
        self.estimates
            .get(&(key.0.clone(), key.1.clone(), quantity.name().to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_columns_start_with_the_first_versions_and_add_errors_at_the_end() {
        assert_eq!(SUMMARY_HEADER[SUMMARY_REQUIRED - 1], "lost");
        assert!(SUMMARY_HEADER[SUMMARY_REQUIRED..]
            .iter()
            .all(|c| c.starts_with("se_")));
        assert_eq!(PDFS_HEADER[PDFS_REQUIRED - 1], "value");
    }
}
