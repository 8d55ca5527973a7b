//! What a calibration counts on a deterministic run ([`super::escape_counts`]): collisions
//! and escapes per cell, the first wall elements beside the proposal's draws, where each
//! row's counts sit along `x_in` and each first stage's along `Δγ`, and the transverse
//! residuals of successive elements. Every sum is an integer, so the counts do not depend
//! on the order or the thread that added them.

use super::constants::*;
use super::grid::*;
use super::slope_space::reduced_slope;
use super::transverse_memory::TransverseCounts;
use crate::wall::Deviations;
use nalgebra::Vector3;

/// Integer counts of collisions and escapes per cell: what a calibration run accumulates.
/// Sums are exact, so the counts do not depend on the order or the thread that added them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EscapeCounts {
    /// Collisions per cell `(stage, x_in bin, x_out bin)` of the escape table (`CELLS`
    /// cells), `x_in` and `x_out` the reduced slopes of the incident and rebound velocities
    /// (`super::slope_space::reduced_slope`). Counted for the histories that escaped (lost
    /// ones are not), and only rebounds away from the mean wall (`α⁺ > 0`) with `x_out`
    /// below `X_OUT_MAX`.
    pub collisions: Vec<u64>,
    /// Of the [`collisions`](Self::collisions) of each cell, those after which the particle
    /// left the wall (the last collision of its history), same cells: `escaped / collisions`
    /// is the cell's escape probability.
    pub escaped: Vec<u64>,
    /// First wall elements by `(x_in, g)`: seen by the deterministic particles, i.e. the
    /// element each collision hits (the first one met along the particle's path), per cell
    /// `(stage, x_in bin, s bin)` (`ELEMENT_CELLS` cells), with `g = γ/Δγ(β)` the element's
    /// reduced inclination (`β` of the velocity before the collision) and `s = g − x_in`; an
    /// `s` off the axis is not counted.
    pub element_deterministic: Vec<u64>,
    /// First wall elements by `(x_in, g)`: drawn from the paper's shadow law (Radenkovic &
    /// Simonin 2021, Eqs. 31–33, in slopes) for the same incident directions as
    /// [`element_deterministic`](Self::element_deterministic), one draw per collision, in
    /// the same cells; a draw with `s` off the axis is not counted.
    pub element_model: Vec<u64>,
    /// Sums of `x_in` (clamped to the axis, in `X_SUM_UNIT`s of 10⁻⁶) per
    /// `(slice, x_in bin)` row (`ROWS` rows) of the collisions counted in the escape table
    /// ([`collisions`](Self::collisions)). A row's mean `x_in` is where its values belong:
    /// the calibration's directions fill a bin unevenly, and the laws change fast with
    /// `x_in` at grazing incidence.
    pub escape_x_sum: Vec<i64>,
    /// Sums of `x_in` (clamped to the axis, in 10⁻⁶) per `(slice, x_in bin)` row of the
    /// shadow-law draws counted in the element table
    /// ([`element_model`](Self::element_model)): where the element table's rows belong
    /// along `x_in`, as for [`escape_x_sum`](Self::escape_x_sum).
    pub element_x_sum: Vec<i64>,
    /// First collisions per first stage ([`FIRST_STAGES`] stages, by `Δγ(β)` of the
    /// incident plane); a plane without roughness (`Δγ = 0` or NaN) is not counted. With
    /// [`first_dg_sum`](Self::first_dg_sum): where each first stage's values belong along
    /// `Δγ`.
    pub first_count: Vec<u64>,
    /// Sum of `Δγ(β)` of the first collisions counted in [`first_count`](Self::first_count),
    /// per first stage, in `DG_SUM_UNIT`s of degrees (10⁻⁶°): the stage's mean `Δγ` is
    /// `first_dg_sum · DG_SUM_UNIT / first_count` degrees.
    pub first_dg_sum: Vec<i64>,
    /// Successive elements' transverse residuals per later stage
    /// (`super::transverse_memory`).
    pub transverse: TransverseCounts,
}

impl Default for EscapeCounts {
    fn default() -> Self {
        EscapeCounts {
            collisions: vec![0; CELLS],
            escaped: vec![0; CELLS],
            element_deterministic: vec![0; ELEMENT_CELLS],
            element_model: vec![0; ELEMENT_CELLS],
            escape_x_sum: vec![0; ROWS],
            element_x_sum: vec![0; ROWS],
            first_count: vec![0; FIRST_STAGES],
            first_dg_sum: vec![0; FIRST_STAGES],
            transverse: TransverseCounts::default(),
        }
    }
}

impl EscapeCounts {
    /// Counts the wall element of one collision: `g_deterministic = γ/Δγ(β)` of the
    /// element the deterministic particle hit (`β` of its velocity before the collision),
    /// `g_model` of one draw of the shadow law for the same direction (reduced angle `x_in`).
    pub fn push_element(&mut self, stage: Stage, x_in: f64, g_deterministic: f64, g_model: f64) {
        if let Some(c) = element_cell(stage, x_in, g_deterministic) {
            self.element_deterministic[c] += 1;
        }
        if let Some(c) = element_cell(stage, x_in, g_model) {
            self.element_model[c] += 1;
            self.element_x_sum[c / G_BINS] += x_units(x_in);
        }
    }

    /// Counts one collision with incident velocity `u_in` and rebound `u_out`, and whether
    /// the particle then left the wall, on the wall of slope spreads `slopes`
    /// ([`super::slope_deviations`]). Rebounds into the mean wall (`α⁺ ≤ 0`)
    /// are not counted: they cannot escape and the model never asks.
    pub fn push(
        &mut self,
        stage: Stage,
        u_in: &Vector3<f64>,
        u_out: &Vector3<f64>,
        slopes: &Deviations,
        escaped: bool,
    ) {
        if u_out.y <= 0.0 {
            return;
        }
        let x_out = reduced_slope(u_out, slopes);
        if x_out.is_nan() || x_out >= X_OUT_MAX {
            return;
        }
        let x_in = reduced_slope(u_in, slopes);
        if x_in.is_nan() {
            return;
        }
        let i_out = ((x_out / DX_OUT) as usize).min(X_OUT_BINS - 1);
        let c = cell(stage, bin_in(x_in), i_out);
        self.collisions[c] += 1;
        self.escaped[c] += escaped as u64;
        self.escape_x_sum[c / X_OUT_BINS] += x_units(x_in);
    }

    /// Counts a later collision's transverse residual `z` beside `z_prev` of the element the
    /// particle has just left (`super::transverse_memory`); a first collision has none.
    pub fn push_transverse(&mut self, stage: Stage, z_prev: f64, z: f64) {
        if let Some(k) = stage.later_index() {
            self.transverse.push(k, z_prev, z);
        }
    }

    /// Counts a first collision in an incident plane of roughness angle `delta_gamma`
    /// (radians) and returns its stage ([`Stage::first`]; a plane without roughness is not
    /// counted along `Δγ`).
    pub fn push_first(&mut self, delta_gamma: f64) -> Stage {
        let stage = Stage::first(delta_gamma);
        if delta_gamma.is_finite() && delta_gamma > 0.0 {
            self.first_count[stage.0] += 1;
            self.first_dg_sum[stage.0] += (delta_gamma.to_degrees() / DG_SUM_UNIT).round() as i64;
        }
        stage
    }

    /// Adds `other` (exact integer sums).
    pub fn add(&mut self, other: &EscapeCounts) {
        for (a, b) in self.collisions.iter_mut().zip(&other.collisions) {
            *a += b;
        }
        for (a, b) in self.escaped.iter_mut().zip(&other.escaped) {
            *a += b;
        }
        for (a, b) in self
            .element_deterministic
            .iter_mut()
            .zip(&other.element_deterministic)
        {
            *a += b;
        }
        for (a, b) in self.element_model.iter_mut().zip(&other.element_model) {
            *a += b;
        }
        for (a, b) in self.escape_x_sum.iter_mut().zip(&other.escape_x_sum) {
            *a += b;
        }
        for (a, b) in self.element_x_sum.iter_mut().zip(&other.element_x_sum) {
            *a += b;
        }
        for (a, b) in self.first_count.iter_mut().zip(&other.first_count) {
            *a += b;
        }
        for (a, b) in self.first_dg_sum.iter_mut().zip(&other.first_dg_sum) {
            *a += b;
        }
        self.transverse.add(&other.transverse);
    }

    /// Sets every row's `x_in` sums as if its counts sat at the bin's centre (tables built
    /// by hand in tests).
    #[cfg(test)]
    pub(super) fn at_centres(mut self) -> EscapeCounts {
        for r in 0..ROWS {
            let x = x_units(centre_in(r % X_IN_BINS));
            let n: u64 = self.collisions[r * X_OUT_BINS..(r + 1) * X_OUT_BINS]
                .iter()
                .sum();
            self.escape_x_sum[r] = x * n as i64;
            let n: u64 = self.element_model[r * G_BINS..(r + 1) * G_BINS]
                .iter()
                .sum();
            self.element_x_sum[r] = x * n as i64;
        }
        self
    }

    /// Total collisions counted.
    pub fn total(&self) -> u64 {
        self.collisions.iter().sum()
    }
}
