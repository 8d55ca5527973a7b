//! Distances between two binned probability densities (the Kolmogorov–Smirnov and L1
//! distances `rebound compare` reports between two runs' PDFs, and the tests use to compare
//! a run with a reference).

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

/// Two-sample Kolmogorov–Smirnov distance `sup |F_a − F_b|` of two samples (sorted in place;
/// 0 when either is empty).
pub fn ks_samples(a: &mut [f64], b: &mut [f64]) -> f64 {
    if a.is_empty() || b.is_empty() {
        return 0.0;
    }
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (mut i, mut j, mut d) = (0, 0, 0.0f64);
    while i < a.len() && j < b.len() {
        let x = a[i].min(b[j]);
        while i < a.len() && a[i] <= x {
            i += 1;
        }
        while j < b.len() && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / a.len() as f64 - j as f64 / b.len() as f64).abs());
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sample_ks_is_the_largest_gap_of_the_two_step_functions() {
        let (mut a, mut b) = (vec![3.0, 1.0, 2.0, 4.0], vec![2.5, 0.5]);
        // After 0.5: 0 vs 1/2; after 2: 1/2 vs 1/2; after 2.5: 1/2 vs 1.
        assert!((ks_samples(&mut a, &mut b) - 0.5).abs() < 1e-15);
        assert_eq!(ks_samples(&mut a.clone(), &mut a), 0.0);
        assert_eq!(ks_samples(&mut [], &mut b), 0.0);
    }

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
