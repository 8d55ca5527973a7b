//! `rebound compare`: distances between the PDFs of two runs with the `summary.csv` /
//! `pdfs.csv` schema of `crate::tally` (e.g. `deterministic` "DS" against `stochastic`
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

use crate::error::Result;
use crate::output::{fmt_num, fmt_opt, CsvTable};
use crate::tally::schema::{read_run as read_tables, ConditionKey, RunTables};
use crate::tally::Quantity;
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

/// A piecewise-constant density on contiguous or gapped bins (any unit of `x`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BinnedPdf {
    /// Bins `(lo, hi, density)`, sorted by `lo`, non-overlapping.
    pub bins: Vec<(f64, f64, f64)>,
}

impl BinnedPdf {
    /// From bins in any order; drops empty or non-finite bins.
    pub fn new(mut bins: Vec<(f64, f64, f64)>) -> Self {
        bins.retain(|&(l, h, p)| l.is_finite() && h.is_finite() && p.is_finite() && h > l);
        bins.sort_by(|a, b| a.0.total_cmp(&b.0));
        Self { bins }
    }

    /// Total probability `Σ p_i (hi_i − lo_i)`.
    pub fn mass(&self) -> f64 {
        self.bins
            .iter()
            .map(|&(l, h, p)| p.max(0.0) * (h - l))
            .sum()
    }

    /// Density at `x` (0 outside every bin), normalised to unit mass.
    fn density_at(&self, x: f64, mass: f64) -> f64 {
        if mass <= 0.0 {
            return 0.0;
        }
        // Bins are few (≤ a few hundred): a binary search on `lo`.
        let i = self.bins.partition_point(|b| b.0 <= x);
        if i == 0 {
            return 0.0;
        }
        let (l, h, p) = self.bins[i - 1];
        if x >= l && x < h {
            p.max(0.0) / mass
        } else {
            0.0
        }
    }

    /// Mean and standard deviation of the binned law (bin centres, weights `p_i w_i`).
    pub fn mean_std(&self) -> (f64, f64) {
        let mass = self.mass();
        if mass <= 0.0 {
            return (0.0, 0.0);
        }
        let mean = self
            .bins
            .iter()
            .map(|&(l, h, p)| 0.5 * (l + h) * p.max(0.0) * (h - l))
            .sum::<f64>()
            / mass;
        let var = self
            .bins
            .iter()
            .map(|&(l, h, p)| (0.5 * (l + h) - mean).powi(2) * p.max(0.0) * (h - l))
            .sum::<f64>()
            / mass;
        (mean, var.max(0.0).sqrt())
    }
}

/// Kolmogorov–Smirnov distance `sup |F_a − F_b|` and L1 distance `∫|p_a − p_b|` of two
/// binned PDFs, each normalised to unit mass (an empty PDF counts as all-zero).
pub fn distances(a: &BinnedPdf, b: &BinnedPdf) -> (f64, f64) {
    let (ma, mb) = (a.mass(), b.mass());
    let mut edges: Vec<f64> = a
        .bins
        .iter()
        .chain(b.bins.iter())
        .flat_map(|&(l, h, _)| [l, h])
        .collect();
    edges.sort_by(|x, y| x.total_cmp(y));
    edges.dedup();
    let (mut fa, mut fb, mut ks, mut l1) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for w in edges.windows(2) {
        let (l, h) = (w[0], w[1]);
        let mid = 0.5 * (l + h);
        let pa = a.density_at(mid, ma);
        let pb = b.density_at(mid, mb);
        l1 += (pa - pb).abs() * (h - l);
        fa += pa * (h - l);
        fb += pb * (h - l);
        ks = ks.max((fa - fb).abs());
    }
    (ks.min(1.0), l1.min(2.0))
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
    ) -> (f64, f64, Option<f64>) {
        match Quantity::from_name(quantity).and_then(|q| self.tables.estimate(key, q)) {
            Some(e) => (e.mean, e.std, Some(e.se)),
            None => {
                let (m, s) = pdf.mean_std();
                (m, s, None)
            }
        }
    }

    /// `(mean, std, se)` of `β⁺ − β⁻` at a condition (Figs. 16–17).
    pub fn dbeta(&self, key: &ConditionKey) -> Option<(f64, f64, Option<f64>)> {
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
    pub std_a: f64,
    pub std_b: f64,
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
            fmt_num(r.std_a),
            fmt_num(r.std_b),
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

#[cfg(test)]
mod tests {
    use super::*;

    fn uniform(lo: f64, hi: f64, n: usize) -> BinnedPdf {
        let w = (hi - lo) / n as f64;
        BinnedPdf::new(
            (0..n)
                .map(|i| (lo + i as f64 * w, lo + (i + 1) as f64 * w, 1.0 / (hi - lo)))
                .collect(),
        )
    }

    #[test]
    fn identical_pdfs_have_zero_distance() {
        let a = uniform(0.0, 10.0, 20);
        assert_eq!(distances(&a, &a), (0.0, 0.0));
        // Same law on different bins.
        let b = uniform(0.0, 10.0, 7);
        let (ks, l1) = distances(&a, &b);
        assert!(ks < 1e-12 && l1 < 1e-12);
    }

    #[test]
    fn disjoint_pdfs_have_maximal_distance() {
        let (ks, l1) = distances(&uniform(0.0, 1.0, 4), &uniform(2.0, 3.0, 4));
        assert!((ks - 1.0).abs() < 1e-12 && (l1 - 2.0).abs() < 1e-12);
    }

    #[test]
    fn shifted_uniform_ks_and_l1() {
        // U(0,1) vs U(0.5,1.5): KS = 0.5, L1 = 1.
        let (ks, l1) = distances(&uniform(0.0, 1.0, 10), &uniform(0.5, 1.5, 10));
        assert!((ks - 0.5).abs() < 1e-12 && (l1 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn mean_and_std_of_a_uniform_histogram() {
        let (m, s) = uniform(0.0, 10.0, 10).mean_std();
        assert!((m - 5.0).abs() < 1e-12);
        // Bin centres 0.5..9.5: variance (n² − 1)/12 = 99/12.
        assert!((s - (99.0f64 / 12.0).sqrt()).abs() < 1e-12);
    }
}
