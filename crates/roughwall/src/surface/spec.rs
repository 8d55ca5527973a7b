//! The grid and roughness of a generated surface, whether a case gives them (`[surface]`)
//! or `deterministic::scene` chooses them from the deviations.

use crate::wall::{self, Deviations};

/// A generated surface, SI units. A `None` correlation length means `Δ = 0` along that
/// axis: the surface is exactly constant along it (docs/physics.md §4).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceSpec {
    /// Side `L` of the square periodic surface (m).
    pub length_m: f64,
    /// Nodes `N` per side of the `N × N` grid (spacing `δ = L/N`; a surface constant along `z`
    /// is generated as one row of `N` nodes).
    pub nodes: usize,
    /// rms height `h` (m; Radenkovic & Simonin 2021, Eqs. 1–2).
    pub rms_height_m: f64,
    /// Correlation length `c_Lx` along `x` (m; Radenkovic & Simonin 2021, Eq. 2); `None`:
    /// `Δξ = 0`, the surface is constant along `x`.
    pub corr_length_x_m: Option<f64>,
    /// Correlation length `c_Lz` along `z` (m; Radenkovic & Simonin 2021, Eq. 2); `None`:
    /// `Δζ = 0`, the surface is constant along `z` (2-D roughness).
    pub corr_length_z_m: Option<f64>,
}

impl SurfaceSpec {
    /// Grid spacing `δ = L/N` (docs/physics.md §4).
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
