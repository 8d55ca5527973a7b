//! `rebound compare`: distances between the PDFs of two runs with the `summary.csv` /
//! `pdfs.csv` schema of `roughwall::tally` (e.g. `deterministic` "DS" against `stochastic`
//! "SM", as in Radenkovic & Simonin 2021, Figs. 10–11, 14–17).
//!
//! For every incident condition and PDF quantity present in both runs: the
//! Kolmogorov–Smirnov distance of the binned CDFs, the L1 distance of the densities,
//! and the mean and standard deviation of each binned PDF.
//!
//! A binned PDF is piecewise constant: density `p_i` on `[lo_i, hi_i)`. Two PDFs may
//! have different bins; both are refined onto the union of their edges, where they are
//! still piecewise constant, so L1 is exact and the (piecewise-linear) CDFs differ most
//! at an edge, where KS is evaluated.

use crate::output::{fmt_num, fmt_opt, CsvTable};
use crate::schema::{read_run as read_tables, ConditionKey, RunTables};
use roughwall::tally::Quantity;
use roughwall::tally::{distances, BinnedPdf};
use roughwall::Result;
use std::collections::BTreeMap;
use std::path::Path;

/// Columns of `comparison.csv`: those of issue 4, then the standard errors of the two
/// means and their difference in units of the combined error, `z = (mean_b − mean_a) /
/// √(se_a² + se_b²)`.
pub const COMPARISON_HEADER: [&str; 12] = [
    "alpha_in_deg",
    "beta_in_deg",
    "quantity",
    "ks",
    "l1",
    "mean_a",
    "mean_b",
    "std_a",
    "std_b",
    "se_mean_a",
    "se_mean_b",
    "z",
];

/// Columns of `unmatched.csv`: what only one of the runs has (an empty `quantity` means
/// the whole condition).
pub const UNMATCHED_HEADER: [&str; 4] = ["alpha_in_deg", "beta_in_deg", "quantity", "only_in"];

/// Rows of `pdfs.csv` that are not probability densities are not compared: the
/// single-collision probability curves (`p_single_given_alpha_out`, …).
fn is_pdf(quantity: &str) -> bool {
    Quantity::from_name(quantity).is_none_or(|q| q.is_density())
}

/// One run's outputs: per condition (the CSV strings of α⁻, β⁻), per quantity, a PDF, and
/// the exact moments of `moments.csv`.
#[derive(Clone, Debug, Default)]
pub struct RunOutputs {
    /// Conditions in file order, with their parsed angles.
    pub conditions: Vec<(String, String, f64, f64)>,
    /// `(α⁻, β⁻) → quantity → PDF`, quantities in file order.
    pub pdfs: BTreeMap<ConditionKey, Vec<(String, BinnedPdf)>>,
    tables: RunTables,
}

impl RunOutputs {
    /// Mean, std and standard error of a quantity: exact from `moments.csv` when the run
    /// wrote it, else the binned PDF's (bin centres; no standard error).
    pub fn moments(
        &self,
        key: &ConditionKey,
        quantity: &str,
        pdf: &BinnedPdf,
    ) -> (f64, Option<f64>, Option<f64>) {
        match Quantity::from_name(quantity).and_then(|q| self.tables.estimate(key, q)) {
            Some(e) => (e.mean, e.std, e.se),
            None => {
                let (m, s) = pdf.mean_std();
                (m, Some(s), None)
            }
        }
    }

    /// `(mean, std, se)` of `β⁺ − β⁻` at a condition (Figs. 16–17).
    pub fn dbeta(&self, key: &ConditionKey) -> Option<(f64, Option<f64>, Option<f64>)> {
        let pdf = &self.pdfs.get(key)?.iter().find(|e| e.0 == "dbeta")?.1;
        Some(self.moments(key, "dbeta", pdf))
    }
}

/// Reads `summary.csv`, `pdfs.csv` and `moments.csv` of a run directory
/// (`tally::schema::read_run`); `flag` (e.g. `--a`) names it in errors.
pub fn read_run(dir: &Path, flag: &str) -> Result<RunOutputs> {
    let tables = read_tables(dir, flag)?;
    let pdfs = tables
        .pdfs
        .iter()
        .map(|(k, list)| {
            (
                k.clone(),
                list.iter()
                    .filter(|(q, _)| is_pdf(q))
                    .map(|(q, b)| (q.clone(), BinnedPdf::new(b.clone())))
                    .collect(),
            )
        })
        .collect();
    Ok(RunOutputs {
        conditions: tables.conditions.clone(),
        pdfs,
        tables,
    })
}

/// One row of `comparison.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct ComparisonRow {
    pub alpha_in: String,
    pub beta_in: String,
    pub quantity: String,
    pub ks: f64,
    pub l1: f64,
    pub mean_a: f64,
    pub mean_b: f64,
    pub std_a: Option<f64>,
    pub std_b: Option<f64>,
    pub se_a: Option<f64>,
    pub se_b: Option<f64>,
}

impl ComparisonRow {
    /// `(mean_b − mean_a) / √(se_a² + se_b²)`; `None` without both errors or when they vanish.
    pub fn z(&self) -> Option<f64> {
        let se = (self.se_a? * self.se_a? + self.se_b? * self.se_b?).sqrt();
        let z = (self.mean_b - self.mean_a) / se;
        (se > 0.0 && z.is_finite()).then_some(z)
    }
}

/// What only one run has: `(α⁻, β⁻, quantity or "", "a" | "b")`.
pub type Unmatched = (String, String, String, &'static str);

/// Compares two runs: rows for every condition and quantity in both (in the order of
/// run A), and the list of what only one of them has.
pub fn compare_runs(a: &RunOutputs, b: &RunOutputs) -> (Vec<ComparisonRow>, Vec<Unmatched>) {
    let mut rows = Vec::new();
    let mut unmatched = Vec::new();
    let empty = Vec::new();
    for (ka, kb, _, _) in &a.conditions {
        let key = (ka.clone(), kb.clone());
        if !b.conditions.iter().any(|c| c.0 == *ka && c.1 == *kb) {
            unmatched.push((ka.clone(), kb.clone(), String::new(), "a"));
            continue;
        }
        let qa = a.pdfs.get(&key).unwrap_or(&empty);
        let qb = b.pdfs.get(&key).unwrap_or(&empty);
        for (q, pa) in qa {
            match qb.iter().find(|e| e.0 == *q) {
                Some((_, pb)) => {
                    let (ks, l1) = distances(pa, pb);
                    let (mean_a, std_a, se_a) = a.moments(&key, q, pa);
                    let (mean_b, std_b, se_b) = b.moments(&key, q, pb);
                    rows.push(ComparisonRow {
                        alpha_in: ka.clone(),
                        beta_in: kb.clone(),
                        quantity: q.clone(),
                        ks,
                        l1,
                        mean_a,
                        mean_b,
                        std_a,
                        std_b,
                        se_a,
                        se_b,
                    });
                }
                None => unmatched.push((ka.clone(), kb.clone(), q.clone(), "a")),
            }
        }
        for (q, _) in qb {
            if !qa.iter().any(|e| e.0 == *q) {
                unmatched.push((ka.clone(), kb.clone(), q.clone(), "b"));
            }
        }
    }
    for (ka, kb, _, _) in &b.conditions {
        if !a.conditions.iter().any(|c| c.0 == *ka && c.1 == *kb) {
            unmatched.push((ka.clone(), kb.clone(), String::new(), "b"));
        }
    }
    (rows, unmatched)
}

/// `comparison.csv` of the rows.
pub fn comparison_table(rows: &[ComparisonRow]) -> CsvTable {
    let mut t = CsvTable::new(&COMPARISON_HEADER);
    for r in rows {
        t.push(vec![
            r.alpha_in.clone(),
            r.beta_in.clone(),
            r.quantity.clone(),
            fmt_num(r.ks),
            fmt_num(r.l1),
            fmt_num(r.mean_a),
            fmt_num(r.mean_b),
            fmt_opt(r.std_a),
            fmt_opt(r.std_b),
            fmt_opt(r.se_a),
            fmt_opt(r.se_b),
            fmt_opt(r.z()),
        ]);
    }
    t
}

/// `unmatched.csv` of what only one run has.
pub fn unmatched_table(list: &[Unmatched]) -> CsvTable {
    let mut t = CsvTable::new(&UNMATCHED_HEADER);
    for (a, b, q, w) in list {
        t.push(vec![a.clone(), b.clone(), q.clone(), w.to_string()]);
    }
    t
}
