//! `gaussian-angle`: the rough-wall patch interaction of OpenFOAM forks, the impact angle
//! perturbed as `alpha1 = max(alpha + gamma*N(0,1), 0)` (as the issue quotes it; no public
//! source was found to read, so the formula is implemented as quoted): a tilt of the wall in
//! the incident plane, no transverse roughness, no shadow effect; a rebound into the wall
//! hits again.

use super::isotropic::{Isotropic, IsotropicDraw, IsotropicIncidence};
use crate::stochastic::SeenWall;
use rand::Rng;
use rand_distr::StandardNormal;

/// OpenFOAM forks: the impact angle perturbed in the incident plane.
pub type GaussianAngle = Isotropic<GaussianAngleWall>;

/// The wall element of [`GaussianAngle`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GaussianAngleWall;

impl IsotropicDraw for GaussianAngleWall {
    const NAME: &'static str = "gaussian-angle";

    /// `α₁ = max(α + Δγ N(0,1), 0)`: the element tilted in the incident plane by `α₁ − α`,
    /// never beyond the incident direction.
    fn draw<R: Rng + ?Sized>(inc: &IsotropicIncidence, rng: &mut R) -> SeenWall {
        let z: f64 = rng.sample(StandardNormal);
        inc.wall_of_gammas((inc.delta_gamma * z).max(inc.alpha), 0.0)
    }
}
