//! Typed results of a condition: numbers stay numbers until `tally::schema` writes them.

use super::histogram::Bin;
use super::moments::Moments;
use super::quantity::Quantity;
use crate::incidence::IncidentCondition;
use crate::wall::Deviations;

/// Mean, standard deviation and standard error of the mean of `n ≥ 1` values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// Number of values.
    pub n: u64,
    /// Mean of the values, in their unit (degrees for angles).
    pub mean: f64,
    /// Sample standard deviation (divisor `n − 1`), same unit; `None` for a single value
    /// (undefined, written as an empty cell).
    pub std: Option<f64>,
    /// Standard error of the mean, same unit; `None` for a single value. `std/√n`, but
    /// for histories spread over several surface realisations, where it includes the
    /// spread between them (`moments::ensemble_se`).
    pub se: Option<f64>,
    /// `std/√n`, the standard error if the values were independent: equal to `se` but
    /// over several surface realisations, where `(se/se_histories)²` is the design effect
    /// of sharing surfaces.
    pub se_histories: Option<f64>,
}

impl Estimate {
    /// From moments; `None` when there are no values.
    pub fn of(m: &Moments) -> Option<Estimate> {
        Some(Estimate {
            n: m.n,
            mean: m.mean()?,
            std: m.std(),
            se: m.se(),
            se_histories: m.se(),
        })
    }

    /// The same estimate with standard error `se` (`se_histories` kept).
    pub fn with_se(self, se: Option<f64>) -> Estimate {
        Estimate { se, ..self }
    }

    /// The estimate of `c x` for a constant `c > 0`.
    pub fn scaled(&self, c: f64) -> Estimate {
        Estimate {
            n: self.n,
            mean: self.mean * c,
            std: self.std.map(|s| s * c),
            se: self.se.map(|s| s * c),
            se_histories: self.se_histories.map(|s| s * c),
        }
    }

    /// From exact integer sums `Σx`, `Σx²` of `n` integer values: the variance
    /// `(nΣx² − (Σx)²) / (n(n − 1))` is formed in integers, so it is exact before the
    /// final division.
    pub fn of_counts(n: u64, sum: u128, sum_sq: u128) -> Option<Estimate> {
        if n == 0 {
            return None;
        }
        let nn = n as u128;
        let mean = sum as f64 / n as f64;
        let var = (n > 1).then(|| {
            let num = nn
                .checked_mul(sum_sq)
                .and_then(|a| a.checked_sub(sum.checked_mul(sum)?));
            match num {
                Some(num) => num as f64 / (nn * (nn - 1)) as f64,
                // Beyond u128 (not reachable within the schema's limits): floating point.
                None => ((sum_sq as f64 - sum as f64 * mean) / (n - 1) as f64).max(0.0),
            }
        });
        let std = var.map(f64::sqrt);
        let se = std.map(|s| s / (n as f64).sqrt());
        Some(Estimate {
            n,
            mean,
            std,
            se,
            se_histories: se,
        })
    }
}

/// A probability and its standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Proportion {
    /// The probability, in `[0, 1]`.
    pub value: f64,
    /// Its standard error; `None` from a single trial (no spread to estimate it from).
    pub se: Option<f64>,
}

impl Proportion {
    /// `k` successes in `n` independent trials: `k/n`, `√(p(1 − p)/n)` (`None` for
    /// `n < 2`).
    pub fn binomial(k: u64, n: u64) -> Proportion {
        let p = k as f64 / n as f64;
        Proportion {
            value: p,
            se: (n > 1).then(|| (p * (1.0 - p) / n as f64).sqrt()),
        }
    }

    /// `n` accepted particles over `Σc` candidates, `c` the candidates of each particle
    /// (`Σc²` given): `p = n/Σc = 1/mean(c)`, with the delta-method error
    /// `p² · sd(c)/√n`.
    pub fn per_trials(n: u64, sum: u128, sum_sq: u128) -> Proportion {
        let c = Estimate::of_counts(n, sum, sum_sq);
        let p = if sum > 0 { n as f64 / sum as f64 } else { 1.0 };
        Proportion {
            value: p,
            se: c.and_then(|c| c.se).map(|se| p * p * se),
        }
    }
}

/// One line of `summary.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// The incident condition `(α⁻, β⁻)`.
    pub condition: IncidentCondition,
    /// Normal-angle deviations `(Δξ, Δζ)` of the wall (radians).
    pub deviations: Deviations,
    /// Histories followed (deterministic: lost ones excluded; stochastic: rebounds).
    pub particles: u64,
    /// Final rebound angle `α⁺` (degrees).
    pub alpha_out: Option<Estimate>,
    /// Final `β⁺ − β⁻` (degrees).
    pub dbeta: Option<Estimate>,
    /// `β⁺ − β⁻` after the first collision (degrees; deterministic).
    pub dbeta_first: Option<Estimate>,
    /// `γ` of the first normal seen (degrees; Radenkovic & Simonin 2021, Eq. 20).
    pub gamma: Option<Estimate>,
    /// `γ*` of the first normal seen (degrees; Radenkovic & Simonin 2021, Eq. 21).
    pub gamma_star: Option<Estimate>,
    /// Deterministic: fraction of single-collision histories; stochastic: accepted
    /// fraction of candidate rebounds.
    pub p_single: Option<Proportion>,
    /// Collisions per history (deterministic).
    pub collisions: Option<Estimate>,
    /// Most collisions of one followed history (deterministic; `None` when no history was
    /// followed, and for the stochastic model).
    pub max_collisions: Option<u32>,
    /// `|U⁺|/|U⁻|`.
    pub speed_ratio: Option<Estimate>,
    /// Histories that could not be followed (deterministic).
    pub lost: Option<u64>,
    /// Wall erosion (with `[erosion]`).
    pub erosion: Option<ErosionSummary>,
}

/// The erosion columns of `summary.csv`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErosionSummary {
    /// Wall volume removed per unit mass of particles (m³/kg): the mean over histories of
    /// the volume each removes per unit of its mass.
    pub per_mass: Option<Estimate>,
    /// The same per particle (m³): `per_mass` times the particle mass.
    pub per_particle: Option<Estimate>,
    /// Impacts per history: deterministic collisions; stochastic candidate rebounds
    /// (the accepted one and the rejected ones).
    pub impacts: Option<Estimate>,
    /// Stochastic: what the rejected candidates would remove, per unit mass (m³/kg).
    pub rejected_per_mass: Option<Estimate>,
}

/// A PDF or per-bin curve of one quantity.
#[derive(Clone, Debug, PartialEq)]
pub struct Pdf {
    /// The quantity whose PDF or curve this is.
    pub quantity: Quantity,
    /// The bins in increasing angle, edges in degrees (densities in 1/degree; fractions or
    /// mean model probabilities for the per-bin curves of Fig. 12).
    pub bins: Vec<Bin>,
}

impl Pdf {
    /// The PDF or curve of `quantity` with these bins.
    pub fn new(quantity: Quantity, bins: Vec<Bin>) -> Pdf {
        Pdf { quantity, bins }
    }
}

/// Everything one incident condition produced.
#[derive(Clone, Debug, PartialEq)]
pub struct ConditionResult {
    /// The condition's line of `summary.csv`.
    pub summary: Summary,
    /// PDFs and curves, in `pdfs.csv` order.
    pub pdfs: Vec<Pdf>,
    /// Mean, std and standard error of every quantity with values (`moments.csv`).
    pub estimates: Vec<(Quantity, Estimate)>,
}

impl ConditionResult {
    /// The incident condition.
    pub fn condition(&self) -> IncidentCondition {
        self.summary.condition
    }

    /// The bins of one quantity, if present.
    pub fn pdf(&self, q: Quantity) -> Option<&[Bin]> {
        self.pdfs
            .iter()
            .find(|p| p.quantity == q)
            .map(|p| p.bins.as_slice())
    }

    /// The estimate of one quantity, if present.
    pub fn estimate(&self, q: Quantity) -> Option<&Estimate> {
        self.estimates.iter().find(|e| e.0 == q).map(|e| &e.1)
    }

    /// Appends a model curve (e.g. `gamma_model`).
    pub fn push_curve(&mut self, pdf: Pdf) {
        self.pdfs.push(pdf);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_estimates_are_exact() {
        // 1, 2, 3, 4: mean 2.5, variance 5/3.
        let e = Estimate::of_counts(4, 10, 30).unwrap();
        assert_eq!(e.mean, 2.5);
        assert!((e.std.unwrap() - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        // One value: a mean, no spread (undefined, not 0).
        let one = Estimate::of_counts(1, 7, 49).unwrap();
        assert_eq!((one.mean, one.std, one.se), (7.0, None, None));
        assert_eq!(Estimate::of_counts(0, 0, 0), None);
        // Constant values: exactly zero spread.
        assert_eq!(
            Estimate::of_counts(1000, 3000, 9000).unwrap().std,
            Some(0.0)
        );
    }

    #[test]
    fn proportions() {
        let p = Proportion::binomial(1, 4);
        assert_eq!(p.value, 0.25);
        assert!((p.se.unwrap() - (0.1875f64 / 4.0).sqrt()).abs() < 1e-15);
        // Every particle accepted at its first candidate: p = 1 exactly, no error.
        let q = Proportion::per_trials(10, 10, 10);
        assert_eq!((q.value, q.se), (1.0, Some(0.0)));
        // A single trial: a value, no error.
        assert_eq!(Proportion::binomial(1, 1).se, None);
        assert_eq!(Proportion::per_trials(1, 2, 4).se, None);
    }
}
