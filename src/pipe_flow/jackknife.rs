//! A statistic of one or several runs' batch sums ([`super::sums`]) and its standard error,
//! by the delete-one-batch jackknife: `θ` from all batches, `θ₋g` without batch `g`, and
//! `SE² = (G − 1)/G Σ_g (θ₋g − mean θ₋g)²` (Efron & Tibshirani, *An Introduction to the
//! Bootstrap*, 1993, Eq. 11.5). It fits ratios (a mean velocity is a sum over a count) without
//! a formula for each; across runs, batch `g` holds the same particle ids, so a difference
//! of two walls started from the same particles gets the error of the difference, paired.

use super::sums::{RunSums, BATCHES};

/// A value and its standard error; both NaN when the statistic is undefined (no sample).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    pub value: f64,
    pub se: f64,
}

impl Estimate {
    /// `(value − other)/√(se² + other.se²)`-free: the z of a difference whose SE is `se`.
    pub fn z(&self) -> f64 {
        self.value / self.se
    }
}

/// `f` of the runs' total sums, with its jackknife standard error. `f` gets one sum vector
/// per run, in the order of `runs`.
pub fn estimate(runs: &[&RunSums], f: impl Fn(&[&[f64]]) -> f64) -> Estimate {
    let totals: Vec<Vec<f64>> = runs
        .iter()
        .map(|r| {
            let mut t = vec![0.0; r.layout.len()];
            for b in &r.batches {
                for (ti, bi) in t.iter_mut().zip(b) {
                    *ti += bi;
                }
            }
            t
        })
        .collect();
    let refs: Vec<&[f64]> = totals.iter().map(|t| t.as_slice()).collect();
    let value = f(&refs);
    let mut loo = Vec::with_capacity(BATCHES);
    for g in 0..BATCHES {
        let without: Vec<Vec<f64>> = runs
            .iter()
            .zip(&totals)
            .map(|(r, t)| t.iter().zip(&r.batches[g]).map(|(a, b)| a - b).collect())
            .collect();
        let refs: Vec<&[f64]> = without.iter().map(|t| t.as_slice()).collect();
        loo.push(f(&refs));
    }
    let n = BATCHES as f64;
    let mean = loo.iter().sum::<f64>() / n;
    let se = ((n - 1.0) / n * loo.iter().map(|x| (x - mean).powi(2)).sum::<f64>()).sqrt();
    if value.is_finite() && se.is_finite() {
        Estimate { value, se }
    } else {
        Estimate {
            value: f64::NAN,
            se: f64::NAN,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipe_flow::sums::Layout;

    fn run_of(values: &[f64]) -> RunSums {
        // one sample per batch in the SAMPLES slot, the value in DIST
        let layout = Layout { nb: 2 };
        let batches = (0..BATCHES)
            .map(|g| {
                let mut v = vec![0.0; layout.len()];
                v[Layout::SAMPLES] = 1.0;
                v[Layout::DIST] = values[g];
                v
            })
            .collect();
        RunSums { layout, batches }
    }

    #[test]
    fn the_jackknife_of_a_mean_is_the_standard_error_of_the_mean() {
        let x: Vec<f64> = (0..BATCHES)
            .map(|i| (i as f64 * 0.37).sin() * 3.0 + 1.0)
            .collect();
        let r = run_of(&x);
        let e = estimate(&[&r], |s| s[0][Layout::DIST] / s[0][Layout::SAMPLES]);
        let n = BATCHES as f64;
        let mean = x.iter().sum::<f64>() / n;
        let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        assert!((e.value - mean).abs() < 1e-12);
        assert!(
            (e.se - sd / n.sqrt()).abs() < 1e-12,
            "{} {}",
            e.se,
            sd / n.sqrt()
        );
    }

    #[test]
    fn a_paired_difference_of_identical_runs_has_no_error() {
        let x: Vec<f64> = (0..BATCHES).map(|i| i as f64).collect();
        let (a, b) = (run_of(&x), run_of(&x));
        let e = estimate(&[&a, &b], |s| s[0][Layout::DIST] - s[1][Layout::DIST]);
        assert_eq!((e.value, e.se), (0.0, 0.0));
    }

    #[test]
    fn an_undefined_statistic_is_nan_not_a_number_with_an_error() {
        let r = run_of(&[0.0; BATCHES]);
        let e = estimate(&[&r], |s| s[0][Layout::HITS] / s[0][Layout::HITS]);
        assert!(e.value.is_nan() && e.se.is_nan());
    }
}
