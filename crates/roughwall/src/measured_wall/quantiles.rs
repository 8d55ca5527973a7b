//! A cell's law of the effective element's `(ξ', ζ')` as quantile functions: the marginal law
//! of `ξ'`, and the law of `ζ'` within each rank bin of `ξ'` (so that their dependence is
//! kept).

use super::grid::{BETA_COLUMNS, RANK_BINS, SERVED_LEFT_BOUND, XI_KNOTS, ZETA_KNOTS};

/// A quantile function on `K` knots at the probabilities `p(t_k) = (1 − cos π t_k)/2`,
/// `t_k = k/(K − 1)`, linear in `t` between them: the knots are the sample's order statistics
/// interpolated at those probabilities (the sample minimum and maximum at the ends).
///
/// The knots crowd towards both tails (the first interval holds `≈ (π/2(K−1))²` of the
/// probability rather than `1/(K−1)`): with equally spaced probabilities the last interval
/// spreads its share uniformly out to the sample's extreme, which inflated the variance of
/// the wall's heavy-tailed `ζ'` by up to 15 % (docs/design-notes.md, "The measured-wall model").
#[derive(Clone, Debug, PartialEq)]
pub struct QuantileFunction {
    /// Non-decreasing values at probabilities `k/(K − 1)`.
    pub knots: Vec<f64>,
}

impl QuantileFunction {
    /// The quantile function of `sorted` (non-decreasing, not empty) on `k ≥ 2` knots.
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
        QuantileFunction { knots }
    }

    /// The value at probability `u` in `[0, 1]`.
    #[inline]
    pub fn at(&self, u: f64) -> f64 {
        at(&self.knots, knot_coordinate(u))
    }
}

/// Resolution of a knot (rad): 0.1 µrad, far below any wall's angles and a table's noise.
pub const KNOT_UNIT_RAD: f64 = 1e-7;

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
    /// Quantile function of `ξ'` ([`XI_KNOTS`] knots).
    pub xi: QuantileFunction,
    /// Quantile functions of `ζ'` in each of [`RANK_BINS`] equal-count rank bins of `ξ'`
    /// ([`ZETA_KNOTS`] knots each).
    pub zeta: Vec<QuantileFunction>,
}

impl CellLaw {
    /// The law of the pairs `(ξ', ζ')` (at least `2 · RANK_BINS` of them).
    pub fn of_pairs(
        mut pairs: Vec<(f64, f64)>,
        histories: u64,
        left_patch: u64,
        lost_other: u64,
    ) -> CellLaw {
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let xis: Vec<f64> = pairs.iter().map(|p| p.0).collect();
        let n = pairs.len();
        let zeta = (0..RANK_BINS)
            .map(|b| {
                let (lo, hi) = (b * n / RANK_BINS, (b + 1) * n / RANK_BINS);
                let mut s: Vec<f64> = pairs[lo..hi].iter().map(|p| p.1).collect();
                s.sort_by(f64::total_cmp);
                QuantileFunction::of_sorted(&s, ZETA_KNOTS)
            })
            .collect();
        CellLaw {
            histories,
            left_patch,
            lost_other,
            xi: QuantileFunction::of_sorted(&xis, XI_KNOTS),
            zeta,
        }
    }

    /// A cell with too few histories on the scan to be served: the mean wall's element
    /// (`ξ' = ζ' = 0`), with its counts.
    pub fn unserved(histories: u64, left_patch: u64, lost_other: u64) -> CellLaw {
        CellLaw {
            histories,
            left_patch,
            lost_other,
            xi: QuantileFunction {
                knots: vec![0.0; XI_KNOTS],
            },
            zeta: vec![
                QuantileFunction {
                    knots: vec![0.0; ZETA_KNOTS]
                };
                RANK_BINS
            ],
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
