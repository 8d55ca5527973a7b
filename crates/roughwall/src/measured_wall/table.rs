//! The law a measured-wall rebound reads: the table of cells, and the draw of an effective
//! wall element for any incident direction between them.

use super::grid::{cell, column_weights, row_weights};
use super::quantiles::{knot_coordinate, rank_bin, CellLaw};
use crate::wall::Deviations;
use rand::Rng;

/// A measured-wall table: one [`CellLaw`] per grid cell (row-major: `|α⁻|` rows, `β⁻`
/// columns), built by [`super::build_table`] and read by [`super::super::models`]'s
/// `measured-wall` model.
#[derive(Clone, Debug, PartialEq)]
pub struct MeasuredWallTable {
    /// What the table was built on (scan file, diameter, block), for messages and files.
    pub source: String,
    /// Its rows `|α⁻|` (degrees, increasing): the base rows
    /// ([`super::ALPHA_ROWS_DEG`]) and those its build added where the wall's law bends
    /// ([`super::refine`]).
    pub alpha_rows_deg: Vec<f64>,
    /// The lowest row served: every row from it up has at most
    /// [`super::SERVED_LEFT_BOUND`] of each cell's histories leaving the scan. Incident
    /// angles below it take its law.
    pub first_row: usize,
    /// The deviations `(Δξ, Δζ)` of the wall the table was built on (rad): what a run with
    /// the table reports as its wall.
    pub deviations: Deviations,
    /// The seed of the histories.
    pub seed: u64,
    /// The cells, `cell(row, column)`.
    pub cells: Vec<CellLaw>,
}

/// Where a direction `(α⁻, β⁻)` falls in a table: its four cells and their weights, and
/// `(sin β⁻, cos β⁻)` to turn a drawn element into the wall's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeasuredWallIncidence {
    /// The four surrounding cells (repeated where a weight is zero).
    pub cells: [u32; 4],
    /// Their bilinear weights (summing to 1).
    pub weights: [f64; 4],
    /// `(sin β⁻, cos β⁻)`.
    pub sin_cos_beta: (f64, f64),
}

impl MeasuredWallTable {
    /// The incident angles `|α⁻|` (degrees) the table serves as measured; below, the lowest
    /// served row's law is taken.
    pub fn lowest_served_alpha_deg(&self) -> f64 {
        self.alpha_rows_deg[self.first_row]
    }

    /// The rows the build added to the base grid (degrees, increasing).
    pub fn refined_rows_deg(&self) -> Vec<f64> {
        self.alpha_rows_deg
            .iter()
            .filter(|a| !super::ALPHA_ROWS_DEG.contains(a))
            .copied()
            .collect()
    }

    /// The largest share of histories that left the scan in a served cell.
    pub fn max_served_left_share(&self) -> f64 {
        self.cells[cell(self.first_row, 0)..]
            .iter()
            .map(CellLaw::left_share)
            .fold(0.0, f64::max)
    }

    /// Histories shot per cell.
    pub fn histories_per_cell(&self) -> u64 {
        self.cells.first().map_or(0, |c| c.histories)
    }

    /// Where the incident direction `(α, β)` (rad, `α < 0` towards the wall) falls.
    pub fn incidence(&self, alpha: f64, beta: f64) -> MeasuredWallIncidence {
        let abs_alpha = alpha.abs().to_degrees().min(90.0);
        let (r0, r1, wr) = row_weights(abs_alpha, &self.alpha_rows_deg, self.first_row);
        let (c0, c1, wc) = column_weights(beta.to_degrees());
        let idx = |r, c| cell(r, c) as u32;
        MeasuredWallIncidence {
            cells: [idx(r0, c0), idx(r0, c1), idx(r1, c0), idx(r1, c1)],
            weights: [
                (1.0 - wr) * (1.0 - wc),
                (1.0 - wr) * wc,
                wr * (1.0 - wc),
                wr * wc,
            ],
            sin_cos_beta: beta.sin_cos(),
        }
    }

    /// One effective element `(ξ', ζ')` (rad, the wall's frame) for `inc`: one of the four
    /// cells, drawn by its weight (a mixture); one of its joint atoms by its share, or its
    /// quantile functions read at two probabilities, the second in the rank bin of the first.
    ///
    /// A mixture, not a blend of the cells' quantile functions at the same probabilities:
    /// unshadowed, the law of the elements a particle meets has a density linear in
    /// `cot α⁻` (each element weighted by `1 + cot|α⁻| tan γ`, Radenkovic & Simonin 2021,
    /// Eq. 29), which the mixture of two rows with weights linear in `cot α⁻` is, exactly
    /// where the elements' mean slope vanishes (a levelled wall); and a narrow peak of the
    /// law (a wall's specular facets) sits at a different rank in each cell, which a blend
    /// smears (docs/design-notes.md, "The measured-wall model"). The wall's frame, not the
    /// incident one, because a law that only turns with `β⁻` (the elements of a wall seen
    /// from steep incidence) is then the same in every column.
    #[inline]
    pub fn draw<R: Rng + ?Sized>(&self, inc: &MeasuredWallIncidence, rng: &mut R) -> (f64, f64) {
        let (u0, u1, u2): (f64, f64, f64) = (rng.gen(), rng.gen(), rng.gen());
        let law = &self.cells[inc.cells[mixture_member(&inc.weights, u0)] as usize];
        // The cell's joint atoms first, then the rest of its law at the rest of `u1`'s range
        // (`u1` itself where there are no atoms).
        let share = law.atoms.share();
        if u1 < share {
            return law.atoms.pick(u1);
        }
        let u1 = if share > 0.0 {
            ((u1 - share) / (1.0 - share)).min(1.0 - f64::EPSILON)
        } else {
            u1
        };
        let (t1, t2) = (knot_coordinate(u1), knot_coordinate(u2));
        (law.xi.at_t(t1), law.zeta[rank_bin(u1)].at_t(t2))
    }
}

/// The member of a mixture of weights `w` (summing to 1) that the uniform `u` in `[0, 1)`
/// picks: the first whose cumulative weight exceeds `u`, never one of weight 0.
#[inline]
fn mixture_member(w: &[f64; 4], u: f64) -> usize {
    let mut cumulative = 0.0;
    for (i, &wi) in w.iter().enumerate() {
        cumulative += wi;
        if u < cumulative && wi > 0.0 {
            return i;
        }
    }
    // Rounding left `u` above the weights' sum: the last member of positive weight.
    w.iter().rposition(|&wi| wi > 0.0).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cell's joint atoms are drawn with their shares, exactly at their elements; the rest of
    /// its draws come from its quantile functions.
    #[test]
    fn a_cell_draws_its_atoms_by_their_share() {
        use crate::measured_wall::Atoms;
        use rand::SeedableRng;
        let mut table = super::super::small_table().clone();
        let k = super::super::grid::cell(30, 5);
        let law = &mut table.cells[k];
        let escaped = law.histories - law.left_patch - law.lost_other;
        // A quarter and an eighth of the law in two atoms.
        let (a, b) = (escaped / 4, escaped / 8);
        law.atoms = Atoms::from_units(vec![(-40_000, 7, a), (12_345, -2, b)], escaped).unwrap();
        let alpha = -table.alpha_rows_deg[30].to_radians();
        let beta = super::super::grid::beta_column_deg(5).to_radians();
        let inc = table.incidence(alpha, beta);
        // The grid point itself: its cell takes all the weight (up to rounding).
        let m = (0..4).find(|&i| inc.weights[i] > 1.0 - 1e-9).unwrap();
        assert_eq!(inc.cells[m] as usize, k);
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(1);
        let n = 200_000;
        let (mut first, mut second) = (0, 0);
        for _ in 0..n {
            let (x, z) = table.draw(&inc, &mut rng);
            let at = |u: (i64, i64)| x == u.0 as f64 * 1e-7 && z == u.1 as f64 * 1e-7;
            first += at((-40_000, 7)) as u64;
            second += at((12_345, -2)) as u64;
        }
        let (p1, p2) = (a as f64 / escaped as f64, b as f64 / escaped as f64);
        for (count, p) in [(first, p1), (second, p2)] {
            let sd = (p * (1.0 - p) / n as f64).sqrt();
            assert!(
                (count as f64 / n as f64 - p).abs() < 5.0 * sd,
                "{count} of {n}, p = {p}"
            );
        }
    }

    #[test]
    fn the_mixture_picks_members_by_their_weights_and_never_a_weightless_one() {
        let w = [0.0, 0.25, 0.0, 0.75];
        assert_eq!(mixture_member(&w, 0.0), 1);
        assert_eq!(mixture_member(&w, 0.2499), 1);
        assert_eq!(mixture_member(&w, 0.25), 3);
        assert_eq!(mixture_member(&w, 0.999_999), 3);
        assert_eq!(mixture_member(&[1.0, 0.0, 0.0, 0.0], 0.999_999_999), 0);
        // Weights whose sum rounds below 1.
        let w = [0.1, 0.2, 0.3, 0.399_999_999_999];
        assert_eq!(mixture_member(&w, 0.999_999_999_999_9), 3);
        let mut counts = [0usize; 4];
        let w = [0.1, 0.2, 0.3, 0.4];
        for i in 0..10_000 {
            counts[mixture_member(&w, (i as f64 + 0.5) / 10_000.0)] += 1;
        }
        assert_eq!(counts, [1000, 2000, 3000, 4000]);
    }
}
