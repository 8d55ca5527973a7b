//! Integer histograms: exact under any merge order, so they add across blocks, threads
//! and shards without a trace of how the work was split.

/// Below this magnitude (degrees) a value is rounding noise around an exact zero (e.g. `ζ'` on a
/// 2-D wall computed through Eq. 23): it is binned as 0, so that ±1e-15 does not straddle a bin edge.
const ZERO_SNAP_DEG: f64 = 1e-9;

/// Most bins one histogram may have (`[output] bin_width_deg` is validated against it).
pub const MAX_BINS: usize = 100_000;

/// One output bin of a PDF or curve (degrees for `lo`, `hi`). `se` is its standard error
/// (`None` where it does not apply, e.g. a model curve).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bin {
    /// Lower edge of the bin (degrees).
    pub lo: f64,
    /// Upper edge of the bin (degrees).
    pub hi: f64,
    /// The bin's value: a probability density (1/degree) for a PDF or a model density
    /// (`gamma_model`), a fraction for a [`RatioCurve`], a mean probability for the model
    /// `P(n = 1)` curve.
    pub value: f64,
    /// Standard error of `value` in its unit (`None` where it does not apply, e.g. a model
    /// curve).
    pub se: Option<f64>,
}

/// Number of bins of width `width` covering `[lo, hi]`, at least 1 and at most [`MAX_BINS`].
pub fn bin_count(lo: f64, hi: f64, width: f64) -> usize {
    let n = ((hi - lo) / width).ceil();
    if n.is_finite() && n >= 1.0 {
        (n as usize).min(MAX_BINS)
    } else {
        1
    }
}

/// Index of `v` among `nbins` bins of `width` from `lo`; values beyond either end land in
/// the end bins. (`as usize` truncates towards zero and saturates negatives at 0, which
/// for a non-negative quotient is `floor` without the library call.)
#[inline]
fn index(v: f64, lo: f64, width: f64, nbins: usize) -> usize {
    (((v - lo) / width) as usize).min(nbins - 1)
}

/// Counts of values (degrees) in bins of `width` from `lo`.
#[derive(Clone, Debug, PartialEq)]
pub struct Histogram {
    lo: f64,
    width: f64,
    counts: Vec<u64>,
    total: u64,
}

impl Histogram {
    /// An empty histogram over `[lo, hi]`.
    pub fn new(lo: f64, hi: f64, width: f64) -> Histogram {
        Histogram {
            lo,
            width,
            counts: vec![0; bin_count(lo, hi, width)],
            total: 0,
        }
    }

    /// Adds one value (degrees); non-finite values are skipped.
    #[inline]
    pub fn push(&mut self, v: f64) {
        if !v.is_finite() {
            return;
        }
        let v = if v.abs() < ZERO_SNAP_DEG { 0.0 } else { v };
        let i = index(v, self.lo, self.width, self.counts.len());
        self.counts[i] += 1;
        self.total += 1;
    }

    /// Values counted.
    pub fn total(&self) -> u64 {
        self.total
    }

    /// Adds another histogram of the same layout.
    pub fn add(&mut self, other: &Histogram) {
        debug_assert_eq!(self.counts.len(), other.counts.len());
        for (a, b) in self.counts.iter_mut().zip(&other.counts) {
            *a += b;
        }
        self.total += other.total;
    }

    /// The counts, for serialising a partial tally: `(first occupied bin, counts from there
    /// to the last occupied bin)`.
    pub fn occupied(&self) -> (usize, &[u64]) {
        match (
            self.counts.iter().position(|&c| c > 0),
            self.counts.iter().rposition(|&c| c > 0),
        ) {
            (Some(a), Some(b)) => (a, &self.counts[a..=b]),
            _ => (0, &[]),
        }
    }

    /// Restores counts written by [`Histogram::occupied`]; `false` if they do not fit.
    pub fn restore(&mut self, first: usize, counts: &[u64]) -> bool {
        if first + counts.len() > self.counts.len() {
            return false;
        }
        self.counts.iter_mut().for_each(|c| *c = 0);
        self.counts[first..first + counts.len()].copy_from_slice(counts);
        self.total = counts.iter().sum();
        true
    }

    /// The density per degree on the span from the first to the last occupied bin, with the
    /// binomial standard error of each bin, `√(p(1 − p)/n)/width` with `p = count/n`.
    pub fn density(&self) -> Vec<Bin> {
        let (first, counts) = self.occupied();
        let n = self.total as f64;
        counts
            .iter()
            .enumerate()
            .map(|(j, &c)| {
                let i = first + j;
                let p = c as f64 / n;
                Bin {
                    lo: self.lo + i as f64 * self.width,
                    hi: self.lo + (i + 1) as f64 * self.width,
                    value: c as f64 / (n * self.width),
                    se: Some((p * (1.0 - p) / n).sqrt() / self.width),
                }
            })
            .collect()
    }
}

/// Fixed-point scale of the model sums of a [`RatioCurve`]: values in `[0, 1]` are summed
/// as integers of `2⁻⁵³`, which is exact and associative (a float sum is neither).
const FIXED_ONE: f64 = 9_007_199_254_740_992.0; // 2^53

/// Per bin of an angle (degrees): how many particles, how many of them were "hits"
/// (e.g. single-collision histories), and optionally the sum of a model probability in
/// `[0, 1]` over the same particles (Fig. 12 of Radenkovic & Simonin 2021).
#[derive(Clone, Debug, PartialEq)]
pub struct RatioCurve {
    lo: f64,
    width: f64,
    /// Particles counted per bin.
    pub total: Vec<u64>,
    /// Of those, the hits per bin (e.g. single-collision histories).
    pub hits: Vec<u64>,
    /// Sum per bin of the model probability (clamped into `[0, 1]`) in fixed point, units
    /// of `2⁻⁵³` so that the sum is exact in any order; particles pushed without a model
    /// value add 0.
    pub model: Vec<u128>,
    /// Values below this (degrees) are not counted (e.g. rebounds into the wall).
    min: f64,
}

impl RatioCurve {
    /// An empty curve over `[lo, hi)`; values below `min` are ignored.
    pub fn new(lo: f64, hi: f64, width: f64, min: f64) -> RatioCurve {
        let n = bin_count(lo, hi, width);
        RatioCurve {
            lo,
            width,
            total: vec![0; n],
            hits: vec![0; n],
            model: vec![0; n],
            min,
        }
    }

    /// Adds one particle at angle `v` (degrees); `model` is clamped into `[0, 1]`.
    #[inline]
    pub fn push(&mut self, v: f64, hit: bool, model: Option<f64>) {
        if !v.is_finite() || v < self.min {
            return;
        }
        let i = index(v, self.lo, self.width, self.total.len());
        self.total[i] += 1;
        self.hits[i] += hit as u64;
        if let Some(m) = model {
            let m = if m.is_finite() {
                m.clamp(0.0, 1.0)
            } else {
                0.0
            };
            self.model[i] += (m * FIXED_ONE).round() as u128;
        }
    }

    /// Adds another curve of the same layout.
    pub fn add(&mut self, other: &RatioCurve) {
        for i in 0..self.total.len() {
            self.total[i] += other.total[i];
            self.hits[i] += other.hits[i];
            self.model[i] += other.model[i];
        }
    }

    /// Bins holding at least one particle.
    fn occupied(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.total.len()).filter(|&i| self.total[i] > 0)
    }

    fn bin(&self, i: usize, value: f64, se: Option<f64>) -> Bin {
        Bin {
            lo: self.lo + i as f64 * self.width,
            hi: self.lo + (i + 1) as f64 * self.width,
            value,
            se,
        }
    }

    /// The fraction of hits per occupied bin, with its binomial standard error.
    pub fn fraction(&self) -> Vec<Bin> {
        self.occupied()
            .map(|i| {
                let n = self.total[i] as f64;
                let p = self.hits[i] as f64 / n;
                self.bin(i, p, Some((p * (1.0 - p) / n).sqrt()))
            })
            .collect()
    }

    /// The mean model probability per occupied bin (no standard error: a model value).
    pub fn model_mean(&self) -> Vec<Bin> {
        self.occupied()
            .map(|i| {
                let mean = self.model[i] as f64 / FIXED_ONE / self.total[i] as f64;
                self.bin(i, mean, None)
            })
            .collect()
    }

    /// Raw arrays for a partial tally: `(total, hits, model)`.
    pub fn parts(&self) -> (&[u64], &[u64], &[u128]) {
        (&self.total, &self.hits, &self.model)
    }

    /// Restores arrays written by [`RatioCurve::parts`]; `false` if the layout differs.
    pub fn restore(&mut self, total: Vec<u64>, hits: Vec<u64>, model: Vec<u128>) -> bool {
        let n = self.total.len();
        if total.len() != n || hits.len() != n || model.len() != n {
            return false;
        }
        self.total = total;
        self.hits = hits;
        self.model = model;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn densities_integrate_to_one_and_errors_are_binomial() {
        let mut h = Histogram::new(-90.0, 90.0, 1.0);
        for i in 0..1000 {
            h.push(0.01 + 30.0 * (i as f64 / 1000.0));
        }
        let bins = h.density();
        let integral: f64 = bins.iter().map(|b| b.value * (b.hi - b.lo)).sum();
        assert!((integral - 1.0).abs() < 1e-12);
        assert_eq!(bins.len(), 30);
        // 33 or 34 values a bin of 1000: se = √(p(1−p)/n).
        let p = bins[0].value;
        assert!((bins[0].se.unwrap() - (p * (1.0 - p) / 1000.0).sqrt()).abs() < 1e-15);
    }

    #[test]
    fn rounding_noise_around_zero_lands_in_one_bin() {
        let mut h = Histogram::new(-90.0, 90.0, 1.0);
        [1e-15, -1e-15, 0.0, -0.0].iter().for_each(|&v| h.push(v));
        let bins = h.density();
        assert_eq!(bins.len(), 1);
        assert_eq!((bins[0].lo, bins[0].hi), (0.0, 1.0));
    }

    #[test]
    fn histograms_add_exactly_and_restore() {
        let mut a = Histogram::new(-180.0, 180.0, 0.5);
        let mut b = a.clone();
        let mut all = a.clone();
        for i in 0..500 {
            let v = (i as f64 * 0.731).sin() * 170.0;
            if i % 3 == 0 { &mut a } else { &mut b }.push(v);
            all.push(v);
        }
        a.add(&b);
        assert_eq!(a, all);
        let (first, counts) = all.occupied();
        let mut r = Histogram::new(-180.0, 180.0, 0.5);
        let counts = counts.to_vec();
        assert!(r.restore(first, &counts));
        assert_eq!(r, all);
        assert!(!r.restore(first, &vec![1; 10_000]));
    }

    #[test]
    fn bin_count_is_bounded() {
        assert_eq!(bin_count(-90.0, 90.0, 1.0), 180);
        assert_eq!(bin_count(-90.0, 90.0, 1e-300), MAX_BINS);
        assert_eq!(bin_count(0.0, 0.0, 1.0), 1);
    }

    #[test]
    fn ratio_curve_fraction_and_model_mean() {
        let mut c = RatioCurve::new(-90.0, 90.0, 1.0, f64::NEG_INFINITY);
        for i in 0..4 {
            c.push(10.5, i < 3, Some(0.25 * i as f64));
        }
        c.push(f64::NAN, true, Some(1.0));
        let f = c.fraction();
        assert_eq!(f.len(), 1);
        assert_eq!((f[0].lo, f[0].value), (10.0, 0.75));
        assert!((f[0].se.unwrap() - (0.75f64 * 0.25 / 4.0).sqrt()).abs() < 1e-15);
        let m = c.model_mean();
        assert_eq!(m[0].value, 0.375);
        assert_eq!(m[0].se, None);
        // Values below `min` are not counted.
        let mut pos = RatioCurve::new(0.0, 90.0, 1.0, 0.0);
        pos.push(-1.0, true, None);
        assert!(pos.fraction().is_empty());
    }
}
