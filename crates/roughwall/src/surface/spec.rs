//! The grid and roughness of a generated surface, whether a case gives them (`[surface]`)
//! or `deterministic::scene` chooses them from the deviations.

use crate::wall::{self, Deviations};

/// A generated surface, SI units. A `None` correlation length means `Δ = 0` along that
/// axis: the surface is exactly constant along it (notes §4).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceSpec {
    pub length_m: f64,
    pub nodes: usize,
    pub rms_height_m: f64,
    pub corr_length_x_m: Option<f64>,
    pub corr_length_z_m: Option<f64>,
}

impl SurfaceSpec {
    /// Grid spacing `δ = L/N` (notes §4).
    pub fn spacing_m(&self) -> f64 {
        self.length_m / self.nodes as f64
    }

    /// Target deviations from Eq. (15).
    pub fn deviations(&self) -> Deviations {
        let d =
            |c: Option<f64>| c.map_or(0.0, |c| wall::deviation_from_surface(self.rms_height_m, c));
        Deviations {
            delta_xi: d(self.corr_length_x_m),
            delta_zeta: d(self.corr_length_z_m),
        }
    }
}
