//! Tallies shared by `deterministic` and `stochastic`: per incident condition, the
//! summary statistics and the PDFs, in one output schema so the two models compare
//! column for column (`summary.csv`, `pdfs.csv`).
//!
//! Outcomes are tallied in particle order after the parallel run, so the sums (and
//! hence the files) are the same for any thread count.

use crate::angles::alpha_xy;
use crate::case::IncidentCondition;
use crate::error::Result;
use crate::output::{fmt_num, fmt_opt, CsvTable};
use crate::wall::Deviations;
use std::path::Path;

/// Columns of `summary.csv`, exactly as the issues specify.
pub const SUMMARY_HEADER: [&str; 20] = [
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
];

/// Columns of `pdfs.csv` (long format).
pub const PDFS_HEADER: [&str; 6] = [
    "alpha_in_deg",
    "beta_in_deg",
    "quantity",
    "bin_lo",
    "bin_hi",
    "value",
];

/// What one particle history (or one accepted stochastic rebound) produced. Radians.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outcome {
    /// Final rebound angle `α⁺`.
    pub alpha_out: f64,
    /// Final transverse angle `β⁺`.
    pub beta_out: f64,
    /// Final transverse deviation `β⁺ − β⁻`, wrapped into (−π, π].
    pub dbeta: f64,
    /// Transverse deviation after the first collision (deterministic only).
    pub dbeta_first: Option<f64>,
    /// Fluctuation `ξ − π/2` of the first normal seen.
    pub xi_first: f64,
    /// Fluctuation `ζ − π/2` of the first normal seen.
    pub zeta_first: f64,
    /// `γ` of the first normal seen (Eq. 20).
    pub gamma_first: f64,
    /// `γ*` of the first normal seen (Eq. 21).
    pub gamma_star_first: f64,
    /// Number of wall collisions (deterministic only).
    pub collisions: Option<u32>,
    /// `|U⁺| / |U⁻|`.
    pub speed_ratio: f64,
}

/// One histogram bin of a PDF or curve, in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bin {
    pub lo: f64,
    pub hi: f64,
    pub value: f64,
}

/// A named curve to add to `pdfs.csv` (e.g. the model density `gamma_model`).
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    pub quantity: String,
    pub bins: Vec<Bin>,
}

/// Histogram ranges (degrees) of the PDF quantities.
const QUANTITIES: [(&str, f64, f64); 9] = [
    ("alpha_out", -90.0, 90.0),
    ("alpha_out_xy", -90.0, 90.0),
    ("beta_out", -180.0, 180.0),
    ("dbeta", -180.0, 180.0),
    ("dbeta_first", -180.0, 180.0),
    ("xi_first", -90.0, 90.0),
    ("zeta_first", -90.0, 90.0),
    ("gamma_first", -90.0, 90.0),
    ("gamma_star_first", -90.0, 90.0),
];

/// Extra facts a model supplies about a condition.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConditionExtras {
    /// Histories that could not be followed (deterministic); `None` leaves the column empty.
    pub lost: Option<u64>,
    /// Overrides `p_single` (stochastic: accepted fraction of candidate rebounds).
    pub p_single: Option<f64>,
    /// Extra curves for `pdfs.csv`.
    pub curves: Vec<Curve>,
}

/// Summary and PDFs of one incident condition.
#[derive(Clone, Debug, PartialEq)]
pub struct ConditionResult {
    pub condition: IncidentCondition,
    pub deviations: Deviations,
    pub particles: usize,
    pub summary: Vec<String>,
    /// `(quantity, bins)` in output order.
    pub pdfs: Vec<(String, Vec<Bin>)>,
    /// Mean and standard deviation (degrees) per summary quantity, for tests and figures.
    pub stats: Vec<(&'static str, f64, f64)>,
}

fn mean_std(xs: impl Iterator<Item = f64> + Clone) -> (f64, f64, usize) {
    let (mut n, mut s) = (0usize, 0.0);
    for x in xs.clone() {
        n += 1;
        s += x;
    }
    if n == 0 {
        return (f64::NAN, f64::NAN, 0);
    }
    let m = s / n as f64;
    let ss: f64 = xs.map(|x| (x - m) * (x - m)).sum();
    let sd = if n > 1 {
        (ss / (n - 1) as f64).sqrt()
    } else {
        0.0
    };
    (m, sd, n)
}

/// Below this magnitude (degrees) a value is rounding noise around an exact zero (e.g. `ζ'` on a
/// 2-D wall computed through Eq. 23): it is binned as 0, so that ±1e-15 does not straddle a bin edge.
const ZERO_SNAP_DEG: f64 = 1e-9;

/// Density histogram (per degree) of `values` (degrees) on `[lo, hi]` with bins aligned on
/// multiples of `width` from `lo`; only the span from the first to the last occupied bin is kept.
pub fn density(values: &[f64], lo: f64, hi: f64, width: f64) -> Vec<Bin> {
    let nbins = ((hi - lo) / width).ceil().max(1.0) as usize;
    let mut counts = vec![0u64; nbins];
    let mut n = 0u64;
    for &v in values {
        if !v.is_finite() {
            continue;
        }
        let v = if v.abs() < ZERO_SNAP_DEG { 0.0 } else { v };
        let i = (((v - lo) / width).floor().max(0.0) as usize).min(nbins - 1);
        counts[i] += 1;
        n += 1;
    }
    let (Some(first), Some(last)) = (
        counts.iter().position(|&c| c > 0),
        counts.iter().rposition(|&c| c > 0),
    ) else {
        return Vec::new();
    };
    (first..=last)
        .map(|i| Bin {
            lo: lo + i as f64 * width,
            hi: lo + (i + 1) as f64 * width,
            value: counts[i] as f64 / (n as f64 * width),
        })
        .collect()
}

impl ConditionResult {
    /// Tallies the outcomes of one condition (in particle order).
    pub fn from_outcomes(
        condition: IncidentCondition,
        deviations: Deviations,
        outcomes: &[Outcome],
        bin_width_deg: f64,
        extras: ConditionExtras,
    ) -> ConditionResult {
        let d = f64::to_degrees;
        let get = |f: fn(&Outcome) -> Option<f64>| {
            outcomes.iter().filter_map(f).map(d).collect::<Vec<f64>>()
        };
        let columns: Vec<(&str, Vec<f64>)> = vec![
            ("alpha_out", get(|o| Some(o.alpha_out))),
            (
                "alpha_out_xy",
                get(|o| Some(alpha_xy(o.alpha_out, o.beta_out))),
            ),
            ("beta_out", get(|o| Some(o.beta_out))),
            ("dbeta", get(|o| Some(o.dbeta))),
            ("dbeta_first", get(|o| o.dbeta_first)),
            ("xi_first", get(|o| Some(o.xi_first))),
            ("zeta_first", get(|o| Some(o.zeta_first))),
            ("gamma_first", get(|o| Some(o.gamma_first))),
            ("gamma_star_first", get(|o| Some(o.gamma_star_first))),
        ];
        let mut pdfs = Vec::new();
        let mut stats = Vec::new();
        for ((name, lo, hi), (_, vals)) in QUANTITIES.iter().zip(&columns) {
            if !vals.is_empty() {
                pdfs.push((name.to_string(), density(vals, *lo, *hi, bin_width_deg)));
                let (m, s, _) = mean_std(vals.iter().copied());
                stats.push((*name, m, s));
            }
        }
        // Fig. 12: fraction of single-collision histories per α⁺ bin.
        let with_counts: Vec<(f64, u32)> = outcomes
            .iter()
            .filter_map(|o| o.collisions.map(|c| (d(o.alpha_out), c)))
            .collect();
        if !with_counts.is_empty() {
            let nb = (90.0 / bin_width_deg).ceil() as usize;
            let mut tot = vec![0u64; nb];
            let mut single = vec![0u64; nb];
            for &(a, c) in &with_counts {
                if a >= 0.0 {
                    let i = ((a / bin_width_deg).floor() as usize).min(nb - 1);
                    tot[i] += 1;
                    single[i] += (c == 1) as u64;
                }
            }
            let bins = (0..nb)
                .filter(|&i| tot[i] > 0)
                .map(|i| Bin {
                    lo: i as f64 * bin_width_deg,
                    hi: (i + 1) as f64 * bin_width_deg,
                    value: single[i] as f64 / tot[i] as f64,
                })
                .collect();
            pdfs.push(("p_single_given_alpha_out".into(), bins));
        }
        for c in &extras.curves {
            pdfs.push((c.quantity.clone(), c.bins.clone()));
        }

        let stat = |name: &str| stats.iter().find(|s| s.0 == name).map(|s| (s.1, s.2));
        let ms = |name: &str| {
            stat(name).map_or((String::new(), String::new()), |(m, s)| {
                (fmt_num(m), fmt_num(s))
            })
        };
        let (ma, sa) = ms("alpha_out");
        let (mdb, sdb) = ms("dbeta");
        let (mdf, sdf) = ms("dbeta_first");
        let (mg, sg) = ms("gamma_first");
        let (mgs, sgs) = ms("gamma_star_first");
        let counts: Vec<u32> = outcomes.iter().filter_map(|o| o.collisions).collect();
        let p_single = extras.p_single.or_else(|| {
            (!counts.is_empty())
                .then(|| counts.iter().filter(|&&c| c == 1).count() as f64 / counts.len() as f64)
        });
        let mean_coll = (!counts.is_empty())
            .then(|| counts.iter().map(|&c| c as f64).sum::<f64>() / counts.len() as f64);
        let max_coll = counts
            .iter()
            .max()
            .map(|m| m.to_string())
            .unwrap_or_default();
        let speed = mean_std(outcomes.iter().map(|o| o.speed_ratio));
        let summary = vec![
            fmt_num(condition.alpha_in_deg()),
            fmt_num(condition.beta_in_deg()),
            fmt_num(deviations.delta_xi.to_degrees()),
            fmt_num(deviations.delta_zeta.to_degrees()),
            outcomes.len().to_string(),
            ma,
            sa,
            mdb,
            sdb,
            mdf,
            sdf,
            mg,
            sg,
            mgs,
            sgs,
            fmt_opt(p_single),
            fmt_opt(mean_coll),
            max_coll,
            if speed.2 > 0 {
                fmt_num(speed.0)
            } else {
                String::new()
            },
            extras.lost.map(|l| l.to_string()).unwrap_or_default(),
        ];
        ConditionResult {
            condition,
            deviations,
            particles: outcomes.len(),
            summary,
            pdfs,
            stats,
        }
    }

    /// The bins of one quantity, if present.
    pub fn pdf(&self, quantity: &str) -> Option<&[Bin]> {
        self.pdfs
            .iter()
            .find(|p| p.0 == quantity)
            .map(|p| p.1.as_slice())
    }

    /// Mean and std (degrees) of a quantity, if present.
    pub fn stat(&self, quantity: &str) -> Option<(f64, f64)> {
        self.stats
            .iter()
            .find(|s| s.0 == quantity)
            .map(|s| (s.1, s.2))
    }
}

/// `summary.csv` and `pdfs.csv` tables of a run.
pub fn tables(results: &[ConditionResult]) -> (CsvTable, CsvTable) {
    let mut summary = CsvTable::new(&SUMMARY_HEADER);
    let mut pdfs = CsvTable::new(&PDFS_HEADER);
    for r in results {
        summary.push(r.summary.clone());
        let (a, b) = (
            fmt_num(r.condition.alpha_in_deg()),
            fmt_num(r.condition.beta_in_deg()),
        );
        for (q, bins) in &r.pdfs {
            for bin in bins {
                pdfs.push(vec![
                    a.clone(),
                    b.clone(),
                    q.clone(),
                    fmt_num(bin.lo),
                    fmt_num(bin.hi),
                    fmt_num(bin.value),
                ]);
            }
        }
    }
    (summary, pdfs)
}

/// Writes `dir/summary.csv` and `dir/pdfs.csv`.
pub fn write_summary_and_pdfs(dir: &Path, results: &[ConditionResult]) -> Result<()> {
    let (s, p) = tables(results);
    s.write(&dir.join("summary.csv"))?;
    p.write(&dir.join("pdfs.csv"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn densities_integrate_to_one_and_summary_has_the_schema() {
        let outcomes: Vec<Outcome> = (0..1000)
            .map(|i| {
                let a = 0.01 + 0.5 * (i as f64 / 1000.0);
                Outcome {
                    alpha_out: a,
                    beta_out: 0.1,
                    dbeta: 0.1 - 0.2 * (i % 3) as f64,
                    collisions: Some(1 + (i % 2) as u32),
                    speed_ratio: 1.0,
                    ..Default::default()
                }
            })
            .collect();
        let cond = IncidentCondition {
            alpha_in: -0.2,
            beta_in: 0.0,
        };
        let r = ConditionResult::from_outcomes(
            cond,
            Deviations {
                delta_xi: 0.04,
                delta_zeta: 0.13,
            },
            &outcomes,
            1.0,
            ConditionExtras::default(),
        );
        assert_eq!(r.summary.len(), SUMMARY_HEADER.len());
        for (q, bins) in &r.pdfs {
            if q != "p_single_given_alpha_out" {
                let integral: f64 = bins.iter().map(|b| b.value * (b.hi - b.lo)).sum();
                assert!((integral - 1.0).abs() < 1e-12, "{q}");
            }
        }
        assert_eq!(r.summary[15], "0.5");
        assert_eq!(r.summary[17], "2");
        assert_eq!(r.summary[19], "");
    }

    #[test]
    fn rounding_noise_around_zero_lands_in_one_bin() {
        let bins = density(&[1e-15, -1e-15, 0.0, -0.0], -90.0, 90.0, 1.0);
        assert_eq!(bins.len(), 1);
        assert_eq!((bins[0].lo, bins[0].hi), (0.0, 1.0));
    }
}
