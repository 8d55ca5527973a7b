//! A cell's law of the effective element's `(ξ', ζ')` as quantile functions: the marginal law
//! of `ξ'`, and the law of `ζ'` within each rank bin of `ξ'` (so that their dependence is
//! kept).

use super::atoms::Atoms;
use super::grid::{
    ADDED_NOISE, BETA_COLUMNS, KNOT_UNIT_RAD, RANK_BINS, SERVED_LEFT_BOUND, XI_ADDED_BUDGET,
    XI_ADDED_TOLERANCE, XI_KNOTS, ZETA_ADDED_BUDGET, ZETA_ADDED_TOLERANCE, ZETA_KNOTS,
};

/// A quantile function on `K` knots at the probabilities `p(t_k) = (1 − cos π t_k)/2`,
/// `t_k = k/(K − 1)`, linear in `t` between them: the knots are the sample's order statistics
/// interpolated at those probabilities (the sample minimum and maximum at the ends); and,
/// where the sample has an atom or a gap those knots smear, knots added at its own order
/// statistics ([`QuantileFunction::of_sorted_keeping`]).
///
/// The knots crowd towards both tails (the first interval holds `≈ (π/2(K−1))²` of the
/// probability rather than `1/(K−1)`): with equally spaced probabilities the last interval
/// spreads its share uniformly out to the sample's extreme, which inflated the variance of
/// the wall's heavy-tailed `ζ'` by up to 15 % (docs/design-notes.md, "The measured-wall model").
///
/// Why added knots: a wall whose heights an instrument wrote in whole steps (plu-1: 3.906 nm)
/// has facets whose slopes take a few values: the effective element's law is then a comb of
/// atoms (opd-1's spheres have one too). A piecewise-linear quantile function on fixed
/// probabilities puts the mass of each knot interval that spans a gap between atoms uniformly
/// inside the gap (1–2 % of the law on plu-1: with fixed knots alone a KS distance of α⁺ of
/// 0.012–0.015 against the reference, 0.011–0.012 with the added ones; docs/design-notes.md).
/// The added knots sit at both ends of each such gap, so the function is flat on each atom
/// and steep across each gap, as the sample is.
#[derive(Clone, Debug, PartialEq)]
pub struct QuantileFunction {
    /// Non-decreasing values at the fixed knot coordinates `t_k = k/(K − 1)`.
    pub knots: Vec<f64>,
    /// Knots added between them, `(t, value)`, `t` strictly increasing in `(0, 1)`, on the
    /// grid of [`ADDED_T_UNIT`] and at no fixed knot's `t`. Empty for most laws.
    added: Vec<(f64, f64)>,
    /// Every knot's `t` and value, in order, when `added` is not empty (what a draw reads).
    merged_t: Vec<f64>,
    merged_x: Vec<f64>,
}

/// Resolution of an added knot's coordinate `t`: `t` is a whole number of `10⁻⁹`, so that a
/// table's text holds it exactly.
pub const ADDED_T_UNIT: f64 = 1e-9;

impl QuantileFunction {
    /// The quantile function of `sorted` (non-decreasing, not empty) on `k ≥ 2` fixed knots.
    pub fn of_sorted(sorted: &[f64], k: usize) -> QuantileFunction {
        let n = sorted.len();
        let knots = (0..k)
            .map(|i| {
                let pos = level(i, k) * (n - 1) as f64;
                let lo = (pos.floor() as usize).min(n - 1);
                let hi = (lo + 1).min(n - 1);
                let t = pos - lo as f64;
                knot(sorted[lo] + t * (sorted[hi] - sorted[lo]))
            })
            .collect();
        QuantileFunction::fixed(knots)
    }

    /// [`QuantileFunction::of_sorted`], then knots added where the law it gives is farther
    /// than `tolerance` (and than the sample's noise, [`ADDED_NOISE`]`/√n`) in probability
    /// from the sample's own (its order statistic `i` at
    /// probability `i/(n − 1)`): each at the sample's worst order statistic, worst interval
    /// first, at most `budget` of them. A sample with neither atoms nor gaps wider than
    /// `tolerance` gets none, and is then [`QuantileFunction::of_sorted`]'s exactly.
    pub fn of_sorted_keeping(
        sorted: &[f64],
        k: usize,
        tolerance: f64,
        budget: usize,
    ) -> QuantileFunction {
        let base = QuantileFunction::of_sorted(sorted, k);
        let tolerance = tolerance.max(ADDED_NOISE / (sorted.len() as f64).sqrt());
        let added = added_knots(sorted, &base.knots, tolerance, budget);
        QuantileFunction::with_added(base.knots, added)
            .expect("added knots lie between the fixed ones on the sample's order statistics")
    }

    /// A quantile function on the fixed knots `knots` alone.
    pub fn fixed(knots: Vec<f64>) -> QuantileFunction {
        QuantileFunction {
            knots,
            added: Vec::new(),
            merged_t: Vec::new(),
            merged_x: Vec::new(),
        }
    }

    /// The fixed knots with `added` ones: a message when the merged knots do not increase
    /// in `t` (an added knot on or beyond a fixed one, or out of `(0, 1)`) or decrease in
    /// value.
    pub fn with_added(
        knots: Vec<f64>,
        added: Vec<(f64, f64)>,
    ) -> std::result::Result<QuantileFunction, String> {
        if knots.windows(2).any(|w| w[1] < w[0]) {
            return Err("a quantile function that decreases".into());
        }
        if added.is_empty() {
            return Ok(QuantileFunction::fixed(knots));
        }
        let k = knots.len();
        let mut merged: Vec<(f64, f64)> = (0..k)
            .map(|i| (fixed_t(i, k), knots[i]))
            .chain(added.iter().copied())
            .collect();
        merged.sort_by(|a, b| a.0.total_cmp(&b.0));
        if added.iter().any(|&(t, _)| !(t > 0.0 && t < 1.0))
            || merged
                .windows(2)
                .any(|w| w[0].0.partial_cmp(&w[1].0) != Some(std::cmp::Ordering::Less))
        {
            return Err("an added knot not strictly between the fixed ones".into());
        }
        if merged.windows(2).any(|w| w[1].1 < w[0].1) {
            return Err("a quantile function that decreases".into());
        }
        Ok(QuantileFunction {
            knots,
            added,
            merged_t: merged.iter().map(|m| m.0).collect(),
            merged_x: merged.iter().map(|m| m.1).collect(),
        })
    }

    /// The knots added to the fixed ones, `(t, value)`.
    pub fn added(&self) -> &[(f64, f64)] {
        &self.added
    }

    /// The value at probability `u` in `[0, 1]`.
    #[inline]
    pub fn at(&self, u: f64) -> f64 {
        self.at_t(knot_coordinate(u))
    }

    /// The value at knot coordinate `t` in `[0, 1]` ([`knot_coordinate`]), linear in `t`
    /// between knots.
    #[inline]
    pub fn at_t(&self, t: f64) -> f64 {
        if self.merged_t.is_empty() {
            return at(&self.knots, t);
        }
        let (ts, xs) = (&self.merged_t, &self.merged_x);
        let j = ts.partition_point(|&tk| tk <= t).clamp(1, ts.len() - 1) - 1;
        let f = ((t - ts[j]) / (ts[j + 1] - ts[j])).clamp(0.0, 1.0);
        xs[j] + f * (xs[j + 1] - xs[j])
    }
}

/// The knots [`QuantileFunction::of_sorted_keeping`] adds to the fixed `knots` of `sorted`.
fn added_knots(sorted: &[f64], knots: &[f64], tolerance: f64, budget: usize) -> Vec<(f64, f64)> {
    let n = sorted.len();
    let k = knots.len();
    if n < 3 || budget == 0 {
        return Vec::new();
    }
    // The knots so far, (t, value), and each interval's worst order statistic.
    let mut ts: Vec<f64> = (0..k).map(|i| fixed_t(i, k)).collect();
    let mut xs: Vec<f64> = knots.to_vec();
    // The worst order statistic of the interval (t_j, t_j+1) and its distance in probability.
    let worst = |t0: f64, x0: f64, t1: f64, x1: f64| -> Option<(f64, usize)> {
        let scale = (n - 1) as f64;
        let (u0, u1) = (probability_at(t0), probability_at(t1));
        let lo = ((u0 * scale).floor() as usize + 1).min(n - 1);
        let hi = ((u1 * scale).ceil() as usize).min(n).max(lo);
        let mut best: Option<(f64, usize)> = None;
        for (i, &s) in sorted.iter().enumerate().take(hi).skip(lo) {
            let u = i as f64 / scale;
            if u <= u0 || u >= u1 {
                continue;
            }
            // The probabilities at which the function takes the value s: the whole interval
            // where it is flat at s (within a knot's rounding); else the point where its line
            // crosses s (an end of the interval when s lies beyond it).
            let d = if (x1 - x0).abs() <= KNOT_UNIT_RAD {
                if (s - x0).abs() <= KNOT_UNIT_RAD {
                    0.0
                } else if s > x0 {
                    u1 - u
                } else {
                    u - u0
                }
            } else {
                let f = ((s - x0) / (x1 - x0)).clamp(0.0, 1.0);
                (probability_at(t0 + f * (t1 - t0)) - u).abs()
            };
            if best.is_none_or(|b| d > b.0) {
                best = Some((d, i));
            }
        }
        best
    };
    let mut added = Vec::new();
    let mut gaps: Vec<Option<(f64, usize)>> = (0..k - 1)
        .map(|j| worst(ts[j], xs[j], ts[j + 1], xs[j + 1]))
        .collect();
    while added.len() < budget {
        // The interval with the largest distance (the first of equals, for determinism).
        let Some((j, (d, i))) = gaps
            .iter()
            .enumerate()
            .filter_map(|(j, g)| g.map(|g| (j, g)))
            .max_by(|a, b| a.1 .0.total_cmp(&b.1 .0).then(b.0.cmp(&a.0)))
        else {
            break;
        };
        if d <= tolerance {
            break;
        }
        let t = (knot_coordinate(i as f64 / (n - 1) as f64) / ADDED_T_UNIT).round() * ADDED_T_UNIT;
        let x = knot(sorted[i]);
        if !(t > ts[j] && t < ts[j + 1]) || x < xs[j] || x > xs[j + 1] {
            // Too close to a knot to split (or off it by rounding): leave the interval.
            gaps[j] = None;
            continue;
        }
        ts.insert(j + 1, t);
        xs.insert(j + 1, x);
        added.push((t, x));
        gaps[j] = worst(ts[j], xs[j], t, x);
        gaps.insert(j + 1, worst(t, x, ts[j + 2], xs[j + 2]));
    }
    added.sort_by(|a, b| a.0.total_cmp(&b.0));
    added
}

/// `x` (rad) on the knots' resolution, so that the table's text (whole multiples of
/// [`KNOT_UNIT_RAD`]) holds it exactly.
#[inline]
pub fn knot(x: f64) -> f64 {
    (x / KNOT_UNIT_RAD).round() * KNOT_UNIT_RAD
}

/// The probability of knot `i` of `k`: `(1 − cos(π i/(k − 1)))/2`.
#[inline]
pub(crate) fn level(i: usize, k: usize) -> f64 {
    0.5 * (1.0 - (std::f64::consts::PI * i as f64 / (k - 1) as f64).cos())
}

/// The knot coordinate `t_k = k/(K − 1)` of fixed knot `k` of `K`.
#[inline]
fn fixed_t(k: usize, count: usize) -> f64 {
    k as f64 / (count - 1) as f64
}

/// The probability `(1 − cos π t)/2` at knot coordinate `t` (the inverse of
/// [`knot_coordinate`]; [`level`] is the same at a fixed knot, computed as the fixed knots
/// always were).
#[inline]
fn probability_at(t: f64) -> f64 {
    0.5 * (1.0 - (std::f64::consts::PI * t).cos())
}

/// The knot coordinate `t` in `[0, 1]` of probability `u` in `[0, 1]` (the inverse of
/// [`level`]'s map): shared by every quantile function read at `u`.
#[inline]
pub(crate) fn knot_coordinate(u: f64) -> f64 {
    (1.0 - 2.0 * u).clamp(-1.0, 1.0).acos() / std::f64::consts::PI
}

/// The quantile function of `knots` at knot coordinate `t` in `[0, 1]`
/// ([`knot_coordinate`]), linear in `t` between knots.
#[inline]
pub(crate) fn at(knots: &[f64], t: f64) -> f64 {
    let x = t * (knots.len() - 1) as f64;
    let k = (x as usize).min(knots.len() - 2);
    let f = x - k as f64;
    knots[k] + f * (knots[k + 1] - knots[k])
}

/// One grid cell: the law of the effective element's normal-angle fluctuations `(ξ', ζ')`
/// (rad, in the wall's frame: Radenkovic & Simonin 2021, Eq. 4) its histories had, and what
/// became of them.
#[derive(Clone, Debug, PartialEq)]
pub struct CellLaw {
    /// Histories shot.
    pub histories: u64,
    /// Of those, histories whose flight left the scan (not in the law).
    pub left_patch: u64,
    /// Of those, histories lost otherwise (collision cap, step budget, …; not in the law).
    pub lost_other: u64,
    /// Quantile function of `ξ'` ([`XI_KNOTS`] knots, and up to [`XI_ADDED_BUDGET`] added).
    pub xi: QuantileFunction,
    /// Quantile functions of `ζ'` in each of [`RANK_BINS`] equal-count rank bins of `ξ'`
    /// ([`ZETA_KNOTS`] knots each, and up to [`ZETA_ADDED_BUDGET`] added).
    pub zeta: Vec<QuantileFunction>,
    /// The joint atoms, drawn with their share of the law; the quantile functions hold the
    /// rest of it (all zeros when the atoms hold all of it).
    pub atoms: Atoms,
}

impl CellLaw {
    /// The law of the pairs `(ξ', ζ')` (at least `2 · RANK_BINS` of them): its joint atoms,
    /// and the rest as quantile functions.
    pub fn of_pairs(
        pairs: Vec<(f64, f64)>,
        histories: u64,
        left_patch: u64,
        lost_other: u64,
    ) -> CellLaw {
        let (atoms, mut pairs) = Atoms::split(pairs, 2 * RANK_BINS);
        if pairs.is_empty() {
            let mut law = CellLaw::unserved(histories, left_patch, lost_other);
            law.atoms = atoms;
            return law;
        }
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let xis: Vec<f64> = pairs.iter().map(|p| p.0).collect();
        let n = pairs.len();
        let zeta = (0..RANK_BINS)
            .map(|b| {
                let (lo, hi) = (b * n / RANK_BINS, (b + 1) * n / RANK_BINS);
                let mut s: Vec<f64> = pairs[lo..hi].iter().map(|p| p.1).collect();
                s.sort_by(f64::total_cmp);
                QuantileFunction::of_sorted_keeping(
                    &s,
                    ZETA_KNOTS,
                    ZETA_ADDED_TOLERANCE,
                    ZETA_ADDED_BUDGET,
                )
            })
            .collect();
        CellLaw {
            histories,
            left_patch,
            lost_other,
            xi: QuantileFunction::of_sorted_keeping(
                &xis,
                XI_KNOTS,
                XI_ADDED_TOLERANCE,
                XI_ADDED_BUDGET,
            ),
            zeta,
            atoms,
        }
    }

    /// A cell with too few histories on the scan to be served: the mean wall's element
    /// (`ξ' = ζ' = 0`), with its counts.
    pub fn unserved(histories: u64, left_patch: u64, lost_other: u64) -> CellLaw {
        CellLaw {
            histories,
            left_patch,
            lost_other,
            xi: QuantileFunction::fixed(vec![0.0; XI_KNOTS]),
            zeta: vec![QuantileFunction::fixed(vec![0.0; ZETA_KNOTS]); RANK_BINS],
            atoms: Atoms::default(),
        }
    }

    /// Share of the histories that left the scan.
    pub fn left_share(&self) -> f64 {
        if self.histories == 0 {
            0.0
        } else {
            self.left_patch as f64 / self.histories as f64
        }
    }

    /// Whether the cell serves its direction: at most [`SERVED_LEFT_BOUND`] of its histories
    /// left the scan. A row is served when every cell of it is.
    pub fn served(&self) -> bool {
        self.left_share() <= SERVED_LEFT_BOUND
    }
}

/// Whether a row of cells serves its directions: every one of its cells does.
pub fn row_served(row: &[CellLaw]) -> bool {
    row.iter().all(CellLaw::served)
}

/// The lowest row of the grid `cells` (rows of [`BETA_COLUMNS`] cells, increasing `|α⁻|`)
/// from which every row up is served: what a build measures and a table states as its
/// `first_row`. The row count when not even the top row is served.
pub fn first_served_row(cells: &[CellLaw]) -> usize {
    let rows: Vec<&[CellLaw]> = cells.chunks(BETA_COLUMNS).collect();
    let mut first = rows.len();
    while first > 0 && row_served(rows[first - 1]) {
        first -= 1;
    }
    first
}

/// The rank bin of probability `u` in `[0, 1)`.
#[inline]
pub(crate) fn rank_bin(u: f64) -> usize {
    ((u * RANK_BINS as f64) as usize).min(RANK_BINS - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_uniform_sample_gives_its_own_quantiles() {
        let s: Vec<f64> = (0..=1000).map(|i| i as f64 / 1000.0).collect();
        // (angles in radians: the knots keep 0.1 µrad)
        let q = QuantileFunction::of_sorted(&s, 129);
        // Exact at the knots, within the knots' spacing between them.
        for i in [0, 1, 17, 64, 100, 128] {
            let u = level(i, 129);
            assert!((q.at(u) - u).abs() < 1e-6, "{u}");
        }
        for u in [0.013, 0.5, 0.77] {
            assert!((q.at(u) - u).abs() < 1e-3, "{u}");
        }
        assert!(level(1, 129) < 2e-4 && (level(128, 129) - 1.0).abs() < 1e-15);
    }

    /// The largest distance in probability between the law of `q` and the sample's own
    /// (the KS distance), measured on a fine grid of values.
    fn ks_to_sample(q: &QuantileFunction, sorted: &[f64]) -> f64 {
        let draws: Vec<f64> = (0..200_000)
            .map(|i| q.at((i as f64 + 0.5) / 200_000.0))
            .collect();
        let (lo, hi) = (sorted[0], sorted[sorted.len() - 1]);
        (0..=4000)
            .map(|k| {
                let x = lo + (hi - lo) * k as f64 / 4000.0;
                let f = |s: &[f64]| s.partition_point(|&v| v <= x) as f64 / s.len() as f64;
                (f(&draws) - f(sorted)).abs()
            })
            .fold(0.0, f64::max)
    }

    #[test]
    fn a_comb_keeps_its_atoms_and_a_smooth_law_gets_no_added_knots() {
        // A comb: five atoms 2.4 mrad apart (plu-1's 0.135° steps), unequal masses.
        let masses = [0.05, 0.2, 0.4, 0.25, 0.1];
        let n = 17_711;
        let mut comb = Vec::with_capacity(n);
        for (a, m) in masses.iter().enumerate() {
            let count = (m * n as f64).round() as usize;
            comb.extend(std::iter::repeat_n((a as f64 - 2.0) * 2.4e-3, count));
        }
        let fixed = QuantileFunction::of_sorted(&comb, XI_KNOTS);
        let kept = QuantileFunction::of_sorted_keeping(&comb, XI_KNOTS, 0.002, XI_ADDED_BUDGET);
        let (ks_fixed, ks_kept) = (ks_to_sample(&fixed, &comb), ks_to_sample(&kept, &comb));
        // The fixed knots put up to half a knot interval's mass (1/256) in each of the four
        // gaps; the added ones leave at most the tolerance (plus the sample's own 1/n).
        assert!(ks_fixed > 0.003, "{ks_fixed}");
        assert!(
            ks_kept <= 0.002 + 2.0 / n as f64,
            "{ks_kept} ({} added)",
            kept.added().len()
        );
        assert!(kept.added().len() <= 8, "{}", kept.added().len());
        let between = |q: &QuantileFunction| {
            let m = 100_000;
            (0..m)
                .map(|i| q.at((i as f64 + 0.5) / m as f64))
                .filter(|x| ((x / 2.4e-3).round() * 2.4e-3 - x).abs() > 2.0 * KNOT_UNIT_RAD)
                .count() as f64
                / m as f64
        };
        let (fixed_between, kept_between) = (between(&fixed), between(&kept));
        assert!(
            kept_between <= 0.5 * fixed_between,
            "{kept_between} {fixed_between}"
        );
        assert!(kept_between <= 4.0 * 0.002, "{kept_between}");
        // A smooth law (normal order statistics from a fixed stream) gets none, and is then the
        // fixed knots' law bit for bit.
        use rand::SeedableRng;
        use rand_distr::{Distribution, StandardNormal};
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(7);
        // (and so do the few histories of a small table, whose noise exceeds the tolerances)
        for (size, k, tol) in [
            (17_711, XI_KNOTS, 0.002),
            (553, ZETA_KNOTS, 0.015),
            (1024, XI_KNOTS, 0.002),
            (32, ZETA_KNOTS, 0.015),
        ] {
            let mut smooth: Vec<f64> = (0..size)
                .map(|_| 0.01 * Distribution::<f64>::sample(&StandardNormal, &mut rng))
                .collect::<Vec<f64>>();
            smooth.sort_by(f64::total_cmp);
            let q = QuantileFunction::of_sorted_keeping(&smooth, k, tol, 48);
            assert!(q.added().is_empty(), "{size}: {:?}", q.added());
            assert_eq!(q, QuantileFunction::of_sorted(&smooth, k));
        }
    }

    #[test]
    fn added_knots_are_refused_out_of_order() {
        let k = vec![0.0, 1.0, 2.0];
        assert!(QuantileFunction::with_added(k.clone(), vec![(0.25, 0.5)]).is_ok());
        // On a fixed knot, outside (0, 1), or making the function decrease.
        assert!(QuantileFunction::with_added(k.clone(), vec![(0.5, 1.0)]).is_err());
        assert!(QuantileFunction::with_added(k.clone(), vec![(1.0, 2.0)]).is_err());
        assert!(QuantileFunction::with_added(k.clone(), vec![(0.25, 1.5)]).is_err());
        // Fixed knots that decrease, with or without added ones.
        assert!(QuantileFunction::with_added(vec![0.0, 2.0, 1.0], vec![]).is_err());
        let q = QuantileFunction::with_added(k, vec![(0.25, 0.0)]).unwrap();
        // Flat from t = 0 to 0.25, then steep to the knot at 0.5.
        assert_eq!(q.at_t(0.1), 0.0);
        assert!((q.at_t(0.375) - 0.5).abs() < 1e-12);
        assert_eq!(q.at_t(1.0), 2.0);
    }

    #[test]
    fn rank_bins_keep_the_dependence() {
        // ζ' = ξ' exactly: within each rank bin ζ' covers that bin's ξ'.
        let n = 1000 * RANK_BINS;
        let pairs: Vec<(f64, f64)> = (0..n).map(|i| (i as f64 * 1e-4, i as f64 * 1e-4)).collect();
        let c = CellLaw::of_pairs(pairs, n as u64, 0, 0);
        for b in 0..RANK_BINS {
            let q = &c.zeta[b];
            assert!((q.knots[0] - (b * 1000) as f64 * 1e-4).abs() < 1e-12);
            assert!((q.knots[ZETA_KNOTS - 1] - (b * 1000 + 999) as f64 * 1e-4).abs() < 1e-12);
        }
        assert_eq!(rank_bin(0.0), 0);
        assert_eq!(rank_bin(0.999_999), RANK_BINS - 1);
    }
}
