//! `gaussian-tilt`: LIGGGHTS-PFM (`ParticulateFlow/LIGGGHTS-PFM`, `src/fix_roughness.cpp`
//! l. 193–211, `src/surface_model_roughness.h` l. 144–213): `deltaGamma = σ N(0,1)` redrawn
//! while `γ/2 + deltaGamma < 0` with `γ` clamped to `≤ 0` (so a half-normal tilt for an
//! approaching particle), azimuth `ψ = π U[0,1)`, tilted normal
//! `n′ = cos δ n + sin δ (sin ψ n₁ + cos ψ n₂)`, `n₁` opposite the tangential velocity,
//! `n₂ = n × n₁`; no shadow effect; a rebound into the wall hits again.

use super::isotropic::{Isotropic, IsotropicDraw, IsotropicIncidence};
use crate::stochastic::SeenWall;
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::StandardNormal;

/// LIGGGHTS-PFM: a half-normal tilt about a uniform azimuth.
pub type GaussianTilt = Isotropic<GaussianTiltWall>;

/// The wall element of [`GaussianTilt`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GaussianTiltWall;

impl IsotropicDraw for GaussianTiltWall {
    const NAME: &'static str = "gaussian-tilt";

    /// A half-normal tilt `δ` about an azimuth `ψ ∈ [0, π)` measured from `n₂ = n × n₁`, `n₁`
    /// opposite the tangential velocity: the element always leans towards the particle.
    fn draw<R: Rng + ?Sized>(inc: &IsotropicIncidence, rng: &mut R) -> SeenWall {
        let j = Vector3::new(0.0, 1.0, 0.0);
        let z: f64 = rng.sample(StandardNormal);
        let delta = (inc.delta_gamma * z).abs().min(std::f64::consts::FRAC_PI_2);
        let psi = std::f64::consts::PI * rng.gen::<f64>();
        let n1 = -inc.tangent();
        let n2 = j.cross(&n1);
        let (sd, cd) = delta.sin_cos();
        let (sp, cp) = psi.sin_cos();
        inc.wall_of_normal((j * cd + (n1 * sp + n2 * cp) * sd).normalize())
    }
}
