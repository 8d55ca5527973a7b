//! `normal-perturbation`: ELEXI (`flexi-framework/elexi`,
//! `src/particles/boundary/particle_boundary_condition.f90` l. 855–937,
//! `Part-Boundary[$]-RoughWall`): the normal rotated by `θ₁` about `n × t` and then by `θ₂`
//! about the original normal, each angle drawn by rejection from
//! `sin(α + θ)/sin α · N(θ; 0, σ)` (the shadow-weighted Gaussian). ELEXI's code uses `σ` as
//! the standard deviation in the exponent and as the variance in the prefactor, and accepts
//! against an unscaled uniform; here the intended law is sampled exactly. A rebound into the
//! wall hits again.

use super::isotropic::{Isotropic, IsotropicDraw, IsotropicIncidence};
use crate::stochastic::SeenWall;
use nalgebra::Vector3;
use rand::Rng;

/// ELEXI: the normal rotated by two shadow-weighted Gaussian angles.
pub type NormalPerturbation = Isotropic<NormalPerturbationWall>;

/// The wall element of [`NormalPerturbation`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormalPerturbationWall;

impl IsotropicDraw for NormalPerturbationWall {
    const NAME: &'static str = "normal-perturbation";

    /// Rotate `n` by `θ₁` about `n × t` (towards the particle), then by `θ₂` about the original
    /// `n`, both angles from the shadow-weighted Gaussian.
    fn draw<R: Rng + ?Sized>(inc: &IsotropicIncidence, rng: &mut R) -> SeenWall {
        let j = Vector3::new(0.0, 1.0, 0.0);
        let th1 = inc.sampler.sample(rng);
        let th2 = inc.sampler.sample(rng);
        let (s1, c1) = th1.sin_cos();
        let (s2, c2) = th2.sin_cos();
        // The horizontal part −sin θ₁ t, turned by θ₂ about y.
        let h = -inc.tangent() * s1;
        let h = Vector3::new(h.x * c2 + h.z * s2, 0.0, -h.x * s2 + h.z * c2);
        inc.wall_of_normal((j * c1 + h).normalize())
    }
}
