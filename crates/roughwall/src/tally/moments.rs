//! Count, mean and spread of a quantity as mergeable accumulators.
//!
//! Within a block of particles the values are summed as deviations from the block's
//! first value ([`ShiftedSums`]: two additions and a multiply per value, no division, and
//! no catastrophic cancellation because the shift is a sample of the same law). Blocks
//! become [`Moments`] `(n, mean, M2)` and are merged with the pairwise update of Chan,
//! Golub & LeVeque (1979), *Updating formulae and a pairwise algorithm for computing
//! sample variances* — the form OpenMC's tallies and Welford's method share. Blocks are
//! always merged in block order, so the floating-point result does not depend on how the
//! blocks were spread over threads, shards or machines.

/// Count, mean and sum of squared deviations from the mean (`M2`) of a set of values.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Moments {
    /// Number of values.
    pub n: u64,
    /// Mean of the values (0 when `n = 0`), in their unit (degrees for the tallied angles).
    pub mean: f64,
    /// Sum of squared deviations from the mean, `Σ (x − mean)²` (`M2` of Chan et al. 1979),
    /// in the square of the values' unit: the sample variance is `m2/(n − 1)`.
    pub m2: f64,
}

impl Moments {
    /// Adds the values summarised by `other` (Chan et al. 1979, Eq. 2.1b).
    pub fn merge(&mut self, other: &Moments) {
        if other.n == 0 {
            return;
        }
        if self.n == 0 {
            *self = *other;
            return;
        }
        let n = self.n + other.n;
        let delta = other.mean - self.mean;
        let w = other.n as f64 / n as f64;
        self.mean += delta * w;
        self.m2 += other.m2 + delta * delta * self.n as f64 * w;
        self.n = n;
    }

    /// Sample standard deviation (divisor `n − 1`), `None` for fewer than two values (it is
    /// undefined, not 0).
    pub fn std(&self) -> Option<f64> {
        match self.n {
            0 | 1 => None,
            n => Some((self.m2.max(0.0) / (n - 1) as f64).sqrt()),
        }
    }

    /// Standard error of the mean, `std / √n` (independent values), `None` for fewer than
    /// two values.
    pub fn se(&self) -> Option<f64> {
        self.std().map(|s| s / (self.n as f64).sqrt())
    }

    /// Mean, `None` when empty.
    pub fn mean(&self) -> Option<f64> {
        (self.n > 0).then_some(self.mean)
    }

    /// The same moments for the values multiplied by `k` (e.g. radians → degrees).
    pub fn scaled(&self, k: f64) -> Moments {
        Moments {
            n: self.n,
            mean: self.mean * k,
            m2: self.m2 * k * k,
        }
    }
}

/// Standard error of a mean over histories that share surface realisations: `n` values
/// with mean `mean` and independent-value standard error `se_histories` (`std/√n`), spread
/// over clusters (realisations) whose `(n_r, mean_r)` are given.
///
/// Histories on one realisation share its quirks, so they are not independent; the
/// cluster-robust (sandwich) variance of a mean over `G` clusters (Cameron & Miller 2015,
/// *A practitioner's guide to cluster-robust inference*, J. Human Resources 50(2) 317–372:
/// their CRVE of an OLS regression on a constant alone, with the "CR1" finite-cluster factor
/// `G/(G − 1) · (N − 1)/(N − K)`, which is `G/(G − 1)` for `K = 1`; the same batch-means
/// idea as OpenMC's tally statistics, with a realisation as the batch) is
///
/// `V = G/(G − 1) · Σ_r (n_r/n)² (mean_r − mean)²`,
///
/// which holds the spread between realisations and the histories' own spread. The result
/// is `√max(se_histories², V)`: with realisations that are at least as alike within as
/// between (intra-cluster correlation ≥ 0, Kish's design effect ≥ 1), the true variance is
/// never below the independent-value one, and with few realisations `V` alone is noisy.
/// Fewer than two non-empty clusters: `se_histories` (one surface has no between-surface
/// spread to measure; the error is then conditional on that surface).
pub fn ensemble_se(
    n: u64,
    mean: f64,
    se_histories: Option<f64>,
    clusters: impl IntoIterator<Item = (u64, f64)>,
) -> Option<f64> {
    let se = se_histories?;
    let (mut g, mut v) = (0u64, 0.0f64);
    for (n_r, mean_r) in clusters {
        if n_r == 0 {
            continue;
        }
        let w = n_r as f64 / n as f64;
        v += w * w * (mean_r - mean) * (mean_r - mean);
        g += 1;
    }
    if g < 2 {
        return Some(se);
    }
    let v = v * g as f64 / (g - 1) as f64;
    Some(se.max(v.sqrt()))
}

/// Sums of `x − shift` and `(x − shift)²` with `shift` the first value pushed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShiftedSums {
    n: u64,
    shift: f64,
    s1: f64,
    s2: f64,
}

impl ShiftedSums {
    /// Adds a value; non-finite values are skipped (they never reach a tally from the
    /// models, and one must not turn every later mean into NaN).
    #[inline]
    pub fn push(&mut self, x: f64) {
        if !x.is_finite() {
            return;
        }
        if self.n == 0 {
            self.shift = x;
        }
        let d = x - self.shift;
        self.n += 1;
        self.s1 += d;
        self.s2 += d * d;
    }

    /// Values pushed.
    pub fn count(&self) -> u64 {
        self.n
    }

    /// The block's `(n, mean, M2)`: `mean = shift + s1/n`, `M2 = s2 − s1²/n`.
    pub fn moments(&self) -> Moments {
        if self.n == 0 {
            return Moments::default();
        }
        let d = self.s1 / self.n as f64;
        Moments {
            n: self.n,
            mean: self.shift + d,
            m2: (self.s2 - self.s1 * d).max(0.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_pass(xs: &[f64]) -> (f64, f64) {
        let n = xs.len() as f64;
        let m = xs.iter().sum::<f64>() / n;
        let v = xs.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
        (m, v.sqrt())
    }

    #[test]
    fn blocks_merged_in_order_give_the_two_pass_mean_and_std() {
        // Values with a large offset and a small spread: the case that breaks Σx² − (Σx)²/n.
        let xs: Vec<f64> = (0..10_000)
            .map(|i| 1e6 + ((i * 7919) % 1000) as f64 * 1e-3)
            .collect();
        let mut total = Moments::default();
        for block in xs.chunks(777) {
            let mut s = ShiftedSums::default();
            block.iter().for_each(|&x| s.push(x));
            total.merge(&s.moments());
        }
        let (m, sd) = two_pass(&xs);
        assert_eq!(total.n, 10_000);
        assert!((total.mean - m).abs() < 1e-9, "{} vs {m}", total.mean);
        assert!((total.std().unwrap() / sd - 1.0).abs() < 1e-9);
        assert!((total.se().unwrap() - sd / 100.0).abs() < 1e-12);
    }

    #[test]
    fn empty_single_and_constant_sets() {
        assert_eq!(Moments::default().std(), None);
        let mut s = ShiftedSums::default();
        s.push(3.0);
        assert_eq!((s.moments().std(), s.moments().se()), (None, None));
        assert_eq!(s.moments().mean(), Some(3.0));
        for _ in 0..99 {
            s.push(3.0);
        }
        let m = s.moments();
        assert_eq!((m.n, m.mean, m.m2), (100, 3.0, 0.0));
        s.push(f64::NAN);
        assert_eq!(s.count(), 100);
        let mut e = Moments::default();
        e.merge(&m);
        e.merge(&Moments::default());
        assert_eq!(e, m);
    }

    /// Two clusters of constant values: all the spread is between them, and the clustered
    /// error is the spread of two cluster means, far above the independent-value one.
    #[test]
    fn ensemble_error_of_clusters() {
        // 500 values of 0 and 500 of 1: mean 0.5, std ≈ 0.5, se ≈ 0.0158.
        let se = 0.5 * (1000.0f64 / 999.0).sqrt() / 1000f64.sqrt();
        let e = ensemble_se(1000, 0.5, Some(se), [(500, 0.0), (500, 1.0)]).unwrap();
        // G/(G−1) Σ (1/2)² (±1/2)² = 2 · 2 · 1/16 = 1/4: se 0.5.
        assert!((e - 0.5).abs() < 1e-15, "{e}");
        // Clusters that agree: the independent-value error is the floor.
        let same = ensemble_se(1000, 0.5, Some(se), [(500, 0.5), (500, 0.5)]).unwrap();
        assert_eq!(same, se);
        // One cluster (or empty ones besides it): nothing between to measure.
        assert_eq!(
            ensemble_se(1000, 0.5, Some(se), [(1000, 0.5), (0, 9.0)]),
            Some(se)
        );
        assert_eq!(ensemble_se(1, 0.5, None, [(1, 0.5)]), None);
    }

    /// The clustered error matches the spread of means over many independent ensembles of
    /// a random-effects model (realisation effect of std 1, history noise of std 1).
    #[test]
    fn ensemble_error_matches_the_spread_between_ensembles() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(3);
        let normal = |r: &mut rand_xoshiro::Xoshiro256PlusPlus| -> f64 {
            r.sample(rand_distr::StandardNormal)
        };
        let (g, per) = (16usize, 200usize);
        let (mut means, mut ses, mut naive) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..400 {
            let mut total = Moments::default();
            let mut clusters = Vec::new();
            for _ in 0..g {
                let effect = normal(&mut rng);
                let mut s = ShiftedSums::default();
                for _ in 0..per {
                    s.push(effect + normal(&mut rng));
                }
                total.merge(&s.moments());
                clusters.push((s.moments().n, s.moments().mean));
            }
            means.push(total.mean);
            naive.push(total.se().unwrap());
            ses.push(ensemble_se(total.n, total.mean, total.se(), clusters).unwrap());
        }
        let m = means.iter().sum::<f64>() / means.len() as f64;
        let spread = (means.iter().map(|x| (x - m) * (x - m)).sum::<f64>()
            / (means.len() - 1) as f64)
            .sqrt();
        let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
        // True error √(1/16 + 1/3200) ≈ 0.251; the independent-value one ≈ 0.025.
        assert!(
            (rms(&ses) / spread - 1.0).abs() < 0.1,
            "{} vs {spread}",
            rms(&ses)
        );
        assert!(rms(&naive) < spread / 5.0);
    }

    #[test]
    fn scaling_scales_mean_and_std() {
        let mut s = ShiftedSums::default();
        [1.0, 2.0, 4.0].iter().for_each(|&x| s.push(x));
        let m = s.moments().scaled(10.0);
        let (mean, sd) = two_pass(&[10.0, 20.0, 40.0]);
        assert!((m.mean - mean).abs() < 1e-12 && (m.std().unwrap() - sd).abs() < 1e-12);
    }
}
