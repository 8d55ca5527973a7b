//! The transverse memory of the `calibrated` model: a trapped particle's next wall element
//! leans across its path the way the element it has just left does.
//!
//! Radenkovic & Simonin 2021 draw every element's transverse inclination `γ*` afresh from
//! Eq. (30). On the deterministic surface two successive elements of one history are a
//! short hop apart, and the slope *across* the hop decorrelates slowly (for a Gaussian
//! autocorrelation of length `l`, the transverse slopes at lag `d` correlate as
//! `exp(−d²/l²)`, while the slopes *along* the hop change sign: the valley's memory of
//! [`super::Stage::later`]). Measured on the Sec. 4 glass–steel wall at
//! α⁻ = −5°, β⁻ = 0° (16 surfaces, 10⁶ histories): the residuals of successive elements'
//! `γ*` correlate by 0.45 (regression slope 0.43), where independent draws give 0; a trapped
//! history's transverse deflections then add up too little (`β⁺ − β⁻` of the two-collision
//! histories: std 1.41° against 1.55°).
//!
//! The memory is the regression of the next element's residual on the one just left, per
//! later stage (`rebound calibrate` counts it): with `z_prev` the residual of the element
//! just left and `N` a standard normal, the next residual is
//! `z = b z_prev + √(1 − b² E[z_prev²]) N` (its variance stays 1, as in Eq. 30, when the
//! model's `z_prev` has the calibration's spread). The residual is
//! [`super::transverse_residual`]: the transverse slope less its conditional
//! mean given the slope along the path, over its conditional spread (Eq. 30 in slopes,
//! [`super::slope_space`]), both seen from the new direction.

use super::constants::{B_MAX, MAX_TERM, MIN_PAIRS, TRANSVERSE_UNIT as UNIT, Z_MAX};
use super::grid::LATER_STAGES;

/// Pairs of successive elements' residuals per later stage: what a calibration counts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TransverseCounts {
    /// Pairs `(z_prev, z)` counted per later stage (`LATER_STAGES` entries): later
    /// collisions whose residuals are both not NaN.
    pub pairs: Vec<u64>,
    /// `Σ z_prev²` per later stage, of the residuals clamped to ±`Z_MAX`, in
    /// `TRANSVERSE_UNIT`s (integers, exact in any order).
    pub prev_sq_sum: Vec<i64>,
    /// `Σ z_prev z` per later stage, of the residuals clamped to ±`Z_MAX`, in
    /// `TRANSVERSE_UNIT`s: `cross_sum / prev_sq_sum` is
    /// the regression slope `b` of `z` on `z_prev`.
    pub cross_sum: Vec<i64>,
}

impl Default for TransverseCounts {
    fn default() -> Self {
        TransverseCounts {
            pairs: vec![0; LATER_STAGES],
            prev_sq_sum: vec![0; LATER_STAGES],
            cross_sum: vec![0; LATER_STAGES],
        }
    }
}

fn clamp_z(z: f64) -> f64 {
    z.clamp(-Z_MAX, Z_MAX)
}

impl TransverseCounts {
    /// Counts one later collision of later stage `k` (0-based among the later stages):
    /// the residual `z_prev` of the element just left and `z` of the element hit, both seen
    /// from the direction between them. A NaN is not counted; an infinite residual (a facet
    /// at γ = ±90°) counts at the clamp, as the model reads it.
    pub fn push(&mut self, k: usize, z_prev: f64, z: f64) {
        if z_prev.is_nan() || z.is_nan() {
            return;
        }
        let (p, z) = (clamp_z(z_prev), clamp_z(z));
        self.pairs[k] += 1;
        self.prev_sq_sum[k] += (p * p / UNIT).round() as i64;
        self.cross_sum[k] += (p * z / UNIT).round() as i64;
    }

    /// Adds `other` (exact integer sums).
    pub fn add(&mut self, other: &TransverseCounts) {
        for k in 0..LATER_STAGES {
            self.pairs[k] += other.pairs[k];
            self.prev_sq_sum[k] += other.prev_sq_sum[k];
            self.cross_sum[k] += other.cross_sum[k];
        }
    }
}

/// The memory read by the model: per later stage, the slope `b` and the spread of the
/// fresh part.
#[derive(Clone, Debug, PartialEq)]
pub struct TransverseMemory {
    slope: Vec<f64>,
    fresh: Vec<f64>,
}

/// `(b, E[z_prev²])` of the sums (wide integers: a pooled sum of hand-edited values cannot
/// overflow), `None` without [`MIN_PAIRS`] pairs or a spread.
fn regression(pairs: u128, prev_sq: i128, cross: i128) -> Option<(f64, f64)> {
    (pairs >= MIN_PAIRS as u128 && prev_sq > 0).then(|| {
        let b = (cross as f64 / prev_sq as f64).clamp(-B_MAX, B_MAX);
        (b, prev_sq as f64 * UNIT / pairs as f64)
    })
}

/// Whether the sums of one stage can come from `pairs` clamped residuals (a check of a table
/// read back: its `pairs` enter the fresh part).
pub fn plausible(pairs: u64, prev_sq: i64, cross: i64) -> bool {
    let bound = MAX_TERM as i128 * pairs as i128;
    (0..=bound).contains(&(prev_sq as i128)) && (cross as i128).abs() <= bound
}

impl TransverseMemory {
    /// The memory of `counts`: each later stage's own regression, or for a sparse stage the
    /// later stages' pooled one, or none (slope 0: Eq. 30's independent draws).
    pub fn from_counts(counts: &TransverseCounts) -> TransverseMemory {
        let pooled = regression(
            counts.pairs.iter().map(|&v| v as u128).sum(),
            counts.prev_sq_sum.iter().map(|&v| v as i128).sum(),
            counts.cross_sum.iter().map(|&v| v as i128).sum(),
        );
        let (slope, fresh) = (0..LATER_STAGES)
            .map(|k| {
                let own = regression(
                    counts.pairs[k] as u128,
                    counts.prev_sq_sum[k] as i128,
                    counts.cross_sum[k] as i128,
                );
                own.or(pooled).map_or((0.0, 1.0), |(b, m2)| {
                    (b, (1.0 - b * b * m2).max(1.0 - B_MAX * B_MAX).sqrt())
                })
            })
            .unzip();
        TransverseMemory { slope, fresh }
    }

    /// The slope of later stage `k`.
    pub fn slope(&self, k: usize) -> f64 {
        self.slope[k]
    }

    /// The spread of later stage `k`'s fresh part.
    pub fn fresh(&self, k: usize) -> f64 {
        self.fresh[k]
    }

    /// The next element's residual at later stage `k` after an element of residual
    /// `z_prev`, from a standard normal draw `n`.
    #[inline]
    pub fn residual(&self, k: usize, z_prev: f64, n: f64) -> f64 {
        // (An infinite residual reads at the clamp, as it was counted; a NaN as 0.)
        let z_prev = if z_prev.is_nan() {
            0.0
        } else {
            clamp_z(z_prev)
        };
        self.slope[k] * z_prev + self.fresh[k] * n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_slope_is_the_regression_of_the_counted_pairs() {
        let mut c = TransverseCounts::default();
        // z = 0.4 z_prev + e, with e alternating ±0.3 so that it is uncorrelated.
        for i in 0..2000 {
            let zp = ((i % 17) as f64 - 8.0) / 4.0;
            let e = if i % 2 == 0 { 0.3 } else { -0.3 };
            c.push(2, zp, 0.4 * zp + e);
        }
        let m = TransverseMemory::from_counts(&c);
        assert!((m.slope(2) - 0.4).abs() < 0.01, "{}", m.slope(2));
        // The sparse stages take the pooled slope (here the one populated stage).
        assert_eq!(m.slope(0), m.slope(2));
        // The fresh part keeps the residual's variance at 1 for z_prev of the counted spread.
        let m2 = c.prev_sq_sum[2] as f64 * UNIT / c.pairs[2] as f64;
        let f = m.fresh(2);
        assert!((m.slope(2).powi(2) * m2 + f * f - 1.0).abs() < 1e-12);
        assert_eq!(m.residual(2, 1.0, 0.0), m.slope(2));
        assert_eq!(m.residual(2, 0.0, 1.0), f);
    }

    #[test]
    fn no_pairs_is_no_memory_and_bad_values_are_harmless() {
        let mut c = TransverseCounts::default();
        c.push(0, f64::NAN, 1.0);
        c.push(0, 1.0, f64::NAN);
        assert_eq!(c, TransverseCounts::default());
        c.push(0, f64::INFINITY, 1.0);
        assert_eq!((c.pairs[0], c.prev_sq_sum[0]), (1, MAX_TERM));
        let m = TransverseMemory::from_counts(&c);
        for k in 0..LATER_STAGES {
            assert_eq!(m.residual(k, 2.0, 0.7), 0.7);
        }
        // Residuals are clamped when counted and read.
        let mut c = TransverseCounts::default();
        for _ in 0..MIN_PAIRS {
            c.push(1, 1e9, 1e9);
        }
        assert_eq!(
            c.prev_sq_sum[1],
            (Z_MAX * Z_MAX / UNIT) as i64 * MIN_PAIRS as i64
        );
        assert!(plausible(c.pairs[1], c.prev_sq_sum[1], c.cross_sum[1]));
        assert!(!plausible(c.pairs[1], c.prev_sq_sum[1] + 1, c.cross_sum[1]));
        assert!(!plausible(0, 1, 0) && !plausible(5, -1, 0) && !plausible(1, 0, 2 * MAX_TERM));
        // A degenerate table keeps a fresh part.
        let m = TransverseMemory::from_counts(&c);
        assert_eq!(m.slope(1), B_MAX);
        assert!((m.fresh(1) - (1.0 - B_MAX * B_MAX).sqrt()).abs() < 1e-15);
        assert!(m.residual(1, f64::NAN, 0.0) == 0.0);
        assert_eq!(m.residual(1, f64::INFINITY, 0.0), B_MAX * Z_MAX);
        assert!(m.residual(1, 1e300, 0.0) <= B_MAX * Z_MAX);
        // Sums far beyond any table's pool without overflow.
        let mut huge = TransverseCounts::default();
        for k in 0..LATER_STAGES {
            (huge.pairs[k], huge.prev_sq_sum[k], huge.cross_sum[k]) =
                (u64::MAX, i64::MAX, i64::MAX);
        }
        let m = TransverseMemory::from_counts(&huge);
        assert!(m.slope(0).is_finite() && m.fresh(0).is_finite());
    }

    /// The calibrated model's successive elements: their residuals regress on each other
    /// with the table's slope (0 without memory: Eq. 30's independent draws).
    #[test]
    fn the_model_remembers_the_transverse_inclination_with_the_table_slope() {
        use super::super::grid::{Stage, CELLS};
        use super::super::model::{rebound, transverse_residual, CalibratedIncidence};
        use super::super::{EscapeCounts, EscapeTable};
        use crate::angles::{incident_angles, velocity_from_angles};
        use crate::collision::CollisionLaw;
        use crate::wall::Deviations;
        use nalgebra::Vector3;
        use rand::SeedableRng;
        let deg = f64::to_radians;
        let wall = Deviations {
            delta_xi: deg(3.8),
            delta_zeta: deg(7.5),
        };
        let measured = |b: f64, beta: f64| {
            // Half the rebounds trapped: many later collisions.
            let mut c = EscapeCounts::default();
            for j in 0..CELLS {
                c.collisions[j] = 400;
                c.escaped[j] = 200;
            }
            for k in 0..LATER_STAGES {
                for i in 0..2000 {
                    let z = ((i % 21) as f64 - 10.0) / 5.0;
                    c.transverse.push(k, z, b * z);
                }
            }
            let table = EscapeTable::from_counts(c, "memory").intern().unwrap();
            assert!((table.transverse_slope(Stage::later(0.0)) - b).abs() < 1e-6);
            let inc = CalibratedIncidence::new(deg(-5.0), deg(beta), &wall);
            let u = velocity_from_angles(1.0, deg(-5.0), deg(beta));
            let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(11);
            let (mut pp, mut pz) = (0.0, 0.0);
            let mut hits: Vec<(Vector3<f64>, Vector3<f64>)> = Vec::new();
            for _ in 0..40_000 {
                hits.clear();
                let law = CollisionLaw::Elastic;
                let contact = crate::stochastic::Contact {
                    wall: &wall,
                    law: &law,
                    psi: 2.0,
                    diameter_m: 1e-4,
                };
                rebound(
                    &inc,
                    table,
                    u,
                    Vector3::zeros(),
                    &contact,
                    &mut rng,
                    |u, n, _| hits.push((*u, *n)),
                );
                // The residuals are the model's: in the wall's slopes.
                let slopes = super::super::slope_deviations(&wall);
                for k in 1..hits.len() {
                    let beta = incident_angles(&hits[k].0).1;
                    let zp = transverse_residual(&hits[k - 1].1, beta, &slopes);
                    let z = transverse_residual(&hits[k].1, beta, &slopes);
                    pp += zp * zp;
                    pz += zp * z;
                }
            }
            pz / pp
        };
        // Along a principal direction, and obliquely (γ and γ* correlated, β changing from
        // hit to hit): the residuals are seen from the direction between the two elements.
        for (b, beta) in [(0.0, 0.0), (0.6, 0.0), (0.6, 60.0)] {
            let got = measured(b, beta);
            assert!(
                (got - b).abs() < 0.03,
                "slope {b} at β⁻ = {beta}°: measured {got}"
            );
        }
    }
}
