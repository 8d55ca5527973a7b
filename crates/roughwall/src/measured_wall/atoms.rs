//! The joint atoms of a cell's law: effective elements `(ξ', ζ')` that many of its histories
//! share exactly, kept as pairs with their counts.
//!
//! Why: a history that bounces once leaves with its facet's own normal as its effective
//! element, so every single-bounce history on one facet has the same `(ξ', ζ')`. On a scan
//! whose facets take few slopes (heights written in whole steps, plu-1) or on a sphere's centre
//! surface (the sphere resting on the same tips over wide areas) a cell's law is then largely
//! a set of atoms in `ξ'` and `ζ'` jointly. Quantile functions keep each angle's atoms
//! ([`super::QuantileFunction::of_sorted_keeping`]), but a rank bin of `ξ'` that spans several
//! atoms draws `ζ'` from all of them, which spreads the mass of `α⁺` into the gaps between its
//! spikes (docs/design-notes.md, "Knots where a law has atoms"). Kept as pairs, the atoms are
//! drawn exactly; the rest of the law stays in the quantile functions.

use super::grid::KNOT_UNIT_RAD;

/// Fewest histories of a cell sharing one element for it to be kept as an atom: two can be a
/// coincidence of a large facet, three of 17 711 (1.7 · 10⁻⁴ of the law) already mark a facet
/// family.
pub const ATOM_MIN_HISTORIES: u64 = 3;

/// Most atoms a cell keeps from its histories, the largest first (at most [`MAX_ATOMS`] in
/// all: when fewer than [`super::RANK_BINS`] · 2 histories would be left to the quantile
/// functions, the rest are kept as atoms too). plu-1's point particle holds a cell in 89–189
/// distinct elements; its 500 µm sphere in 1 303–1 426, whose 100 largest hold 78 % and 500
/// largest 94 % (docs/design-notes.md, "Knots where a law has atoms").
pub const ATOM_BUDGET: usize = 256;

/// Most atoms a cell may hold: the budget and the histories too few for quantile functions.
pub const MAX_ATOMS: usize = ATOM_BUDGET + 2 * super::RANK_BINS;

/// A cell's joint atoms: each `(ξ', ζ')` (rad, on the knot grid of 0.1 µrad, so that a table
/// read back is the table written) and its count of histories, in increasing `(ξ', ζ')`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Atoms {
    at: Vec<(f64, f64)>,
    counts: Vec<u64>,
    /// `cumulative[k]`: the share of the cell's escaped histories in atoms `0 … k`.
    cumulative: Vec<f64>,
}

/// An element on the knot grid, as whole units (exact keys to group and sort by).
fn units(x: f64) -> i64 {
    (x / KNOT_UNIT_RAD).round() as i64
}

impl Atoms {
    /// The atoms `(units of ξ', units of ζ', count)` of a cell of `escaped` histories, in
    /// increasing order; `None` when they are not (the counts then exceed the histories, or
    /// a count is zero, or two atoms coincide).
    pub fn from_units(list: Vec<(i64, i64, u64)>, escaped: u64) -> Option<Atoms> {
        let increasing = list.windows(2).all(|w| (w[0].0, w[0].1) < (w[1].0, w[1].1));
        let total = list.iter().try_fold(0u64, |s, a| s.checked_add(a.2))?;
        if !increasing || total > escaped || list.iter().any(|a| a.2 == 0) || list.len() > MAX_ATOMS
        {
            return None;
        }
        let mut sum = 0u64;
        let cumulative = list
            .iter()
            .map(|a| {
                sum += a.2;
                sum as f64 / escaped as f64
            })
            .collect();
        Some(Atoms {
            at: list
                .iter()
                .map(|a| (a.0 as f64 * KNOT_UNIT_RAD, a.1 as f64 * KNOT_UNIT_RAD))
                .collect(),
            counts: list.iter().map(|a| a.2).collect(),
            cumulative,
        })
    }

    /// Splits the escaped histories' elements `pairs` into atoms (elements shared by at least
    /// [`ATOM_MIN_HISTORIES`] of them on the knot grid, the [`ATOM_BUDGET`] largest; all the
    /// elements when fewer than `keep_at_least` would be left) and the rest, in their order.
    pub fn split(pairs: Vec<(f64, f64)>, keep_at_least: usize) -> (Atoms, Vec<(f64, f64)>) {
        let escaped = pairs.len() as u64;
        let mut keys: Vec<(i64, i64)> = pairs.iter().map(|p| (units(p.0), units(p.1))).collect();
        keys.sort_unstable();
        // Runs of equal elements, the largest first (ties in increasing order: deterministic).
        let mut runs: Vec<((i64, i64), u64)> = Vec::new();
        for k in keys {
            match runs.last_mut() {
                Some((last, c)) if *last == k => *c += 1,
                _ => runs.push((k, 1)),
            }
        }
        let distinct = runs.len();
        // Only the shared elements are ranked (a smooth law has none: no sort of its runs).
        let mut kept: Vec<((i64, i64), u64)> = runs
            .iter()
            .filter(|r| r.1 >= ATOM_MIN_HISTORIES)
            .copied()
            .collect();
        if kept.is_empty() {
            return (Atoms::default(), pairs);
        }
        kept.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        kept.truncate(ATOM_BUDGET);
        let in_atoms: u64 = kept.iter().map(|r| r.1).sum();
        let left = escaped - in_atoms;
        if (left as usize) < keep_at_least && distinct <= MAX_ATOMS {
            kept = runs;
        }
        kept.sort_by_key(|r| r.0);
        let is_atom = |p: &(f64, f64)| {
            kept.binary_search_by(|r| r.0.cmp(&(units(p.0), units(p.1))))
                .is_ok()
        };
        let rest: Vec<(f64, f64)> = pairs.iter().filter(|p| !is_atom(p)).copied().collect();
        let list = kept.iter().map(|r| (r.0 .0, r.0 .1, r.1)).collect();
        let atoms = Atoms::from_units(list, escaped).expect("atoms of the cell's own histories");
        (atoms, rest)
    }

    /// How many atoms.
    pub fn len(&self) -> usize {
        self.at.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.at.is_empty()
    }

    /// The atoms as `(units of ξ', units of ζ', count)`, for the table's text.
    pub fn units(&self) -> impl Iterator<Item = (i64, i64, u64)> + '_ {
        self.at
            .iter()
            .zip(&self.counts)
            .map(|(a, &c)| (units(a.0), units(a.1), c))
    }

    /// Histories in atoms.
    pub fn histories(&self) -> u64 {
        self.counts.iter().sum()
    }

    /// The share of the cell's law in its atoms.
    #[inline]
    pub fn share(&self) -> f64 {
        self.cumulative.last().copied().unwrap_or(0.0)
    }

    /// The atom that probability `u` (below [`Self::share`]) falls in: the first whose
    /// cumulative share exceeds `u`.
    #[inline]
    pub fn pick(&self, u: f64) -> (f64, f64) {
        let k = self.cumulative.partition_point(|&c| c <= u);
        self.at[k.min(self.at.len() - 1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shared_elements_become_atoms_and_the_rest_stays() {
        let u = KNOT_UNIT_RAD;
        let mut pairs = Vec::new();
        // Two facets, 5 and 3 histories; 100 distinct elements; one pair of twins (not kept).
        pairs.extend(std::iter::repeat_n((10.0 * u, -4.0 * u), 5));
        pairs.extend(std::iter::repeat_n((-7.0 * u, 2.0 * u), 3));
        pairs.extend((0..100).map(|i| ((1000 + i) as f64 * u, (i % 7) as f64 * u)));
        pairs.extend(std::iter::repeat_n((50.0 * u, 50.0 * u), 2));
        let (atoms, rest) = Atoms::split(pairs, 64);
        assert_eq!(atoms.len(), 2);
        assert_eq!(
            atoms.units().collect::<Vec<_>>(),
            vec![(-7, 2, 3), (10, -4, 5)]
        );
        assert_eq!(rest.len(), 102);
        assert!((atoms.share() - 8.0 / 110.0).abs() < 1e-15);
        assert_eq!(atoms.pick(0.0), (-7.0 * u, 2.0 * u));
        assert_eq!(atoms.pick(3.0 / 110.0 - 1e-12), (-7.0 * u, 2.0 * u));
        assert_eq!(atoms.pick(3.0 / 110.0), (10.0 * u, -4.0 * u));
        // Too few left for quantile functions: every element is an atom.
        let few: Vec<(f64, f64)> = std::iter::repeat_n((1.0 * u, 1.0 * u), 50)
            .chain((0..10).map(|i| (i as f64 * u, -u)))
            .collect();
        let (atoms, rest) = Atoms::split(few, 64);
        assert!(rest.is_empty());
        assert_eq!(atoms.len(), 11);
        assert_eq!(atoms.share(), 1.0);
        // A continuous law has none.
        let smooth: Vec<(f64, f64)> = (0..500).map(|i| (i as f64 * 0.37, -(i as f64))).collect();
        let (atoms, rest) = Atoms::split(smooth.clone(), 64);
        assert!(atoms.is_empty() && rest == smooth);
    }

    #[test]
    fn atoms_out_of_order_or_beyond_the_histories_are_refused() {
        assert!(Atoms::from_units(vec![(1, 0, 2), (0, 0, 2)], 10).is_none());
        assert!(Atoms::from_units(vec![(0, 0, 6), (1, 0, 5)], 10).is_none());
        assert!(Atoms::from_units(vec![(0, 0, 0)], 10).is_none());
        assert!(Atoms::from_units(vec![(0, 0, 1), (0, 0, 1)], 10).is_none());
        let a = Atoms::from_units(vec![(0, 0, 5), (1, 0, 5)], 10).unwrap();
        assert_eq!(a.share(), 1.0);
    }
}
