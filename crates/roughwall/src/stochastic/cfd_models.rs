//! The rough-wall models CFD codes ship ([`super::variants`] names them and cites their
//! sources): a virtual wall element drawn from one isotropic roughness angle `Δγ`, the
//! collision law, and a rebound that does not leave the mean wall hits the wall again with a
//! new element for its new velocity.

use super::shadow_effect::ShadowSampler;
use super::virtual_wall::{Hits, Rebound, SeenWall};
use crate::collision::CollisionLaw;
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::StandardNormal;

/// The rough-wall models CFD codes ship (their sources: [`super::variants`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CfdModel {
    /// Sommerfeld & Huber 1999: the shadow law in the incident plane, an independent normal
    /// law across it.
    SommerfeldHuber1999,
    /// OpenFOAM forks: the impact angle perturbed in the incident plane.
    GaussianAngle,
    /// LIGGGHTS-PFM: a half-normal tilt about a uniform azimuth.
    GaussianTilt,
    /// ELEXI: the normal rotated by two shadow-weighted Gaussian angles.
    NormalPerturbation,
}

/// What one of these models precomputes for an incident direction `(α, β)`.
#[derive(Clone, Copy, Debug)]
pub struct CfdIncidence {
    model: CfdModel,
    alpha: f64,
    beta: f64,
    sin_cos_beta: (f64, f64),
    /// The model's one roughness angle `Δγ` (rad).
    delta_gamma: f64,
    /// The shadow law of Eqs. (31–33) with `Δγ` (Sommerfeld & Huber, ELEXI).
    sampler: ShadowSampler,
}

impl CfdIncidence {
    /// The direction `(α, β)` (rad) for `model` with the roughness angle `delta_gamma`
    /// (rad).
    pub fn new(model: CfdModel, alpha: f64, beta: f64, delta_gamma: f64) -> CfdIncidence {
        let sampler = ShadowSampler::for_trajectory(alpha, delta_gamma);
        CfdIncidence {
            model,
            alpha,
            beta,
            sin_cos_beta: beta.sin_cos(),
            delta_gamma,
            sampler,
        }
    }

    fn wall_of_gammas(&self, gamma: f64, gamma_star: f64) -> SeenWall {
        SeenWall::of_gammas(gamma, gamma_star, self.sin_cos_beta)
    }

    fn wall_of_normal(&self, normal: Vector3<f64>) -> SeenWall {
        SeenWall::of_normal(normal, self.beta)
    }

    /// A wall element drawn by this model, as each model's source gives it
    /// ([`super::variants`]: Sommerfeld & Huber 1999 by Radenkovic & Simonin 2021,
    /// Eqs. 31–33, isotropic; the quoted `gaussian-angle` formula; LIGGGHTS-PFM
    /// `surface_model_roughness.h` l. 144–213; ELEXI `particle_boundary_condition.f90`
    /// l. 855–937). `t` is the horizontal incident direction `(cos β⁻, 0, −sin β⁻)` and `γ > 0` tilts
    /// the element towards the particle (local impact angle `|α⁻| + γ`).
    pub(crate) fn draw<R: Rng + ?Sized>(&self, rng: &mut R) -> SeenWall {
        let dg = self.delta_gamma;
        let (sb, cb) = self.sin_cos_beta;
        let t = Vector3::new(cb, 0.0, -sb);
        let j = Vector3::new(0.0, 1.0, 0.0);
        match self.model {
            // Sommerfeld & Huber 1999: the shadow law in the incident plane, an independent
            // normal law across it, one Δγ for both (isotropic).
            CfdModel::SommerfeldHuber1999 => {
                let gamma = self.sampler.sample(rng);
                let z: f64 = rng.sample(StandardNormal);
                self.wall_of_gammas(gamma, dg * z)
            }
            // `α₁ = max(α + Δγ N(0,1), 0)`: the element tilted in the incident plane by
            // `α₁ − α`, never beyond the incident direction.
            CfdModel::GaussianAngle => {
                let z: f64 = rng.sample(StandardNormal);
                self.wall_of_gammas((dg * z).max(self.alpha), 0.0)
            }
            // LIGGGHTS-PFM: a half-normal tilt δ about an azimuth ψ ∈ [0, π) measured from
            // n₂ = n × n₁, n₁ opposite the tangential velocity: the element always leans
            // towards the particle.
            CfdModel::GaussianTilt => {
                let z: f64 = rng.sample(StandardNormal);
                let delta = (dg * z).abs().min(std::f64::consts::FRAC_PI_2);
                let psi = std::f64::consts::PI * rng.gen::<f64>();
                let n1 = -t;
                let n2 = j.cross(&n1);
                let (sd, cd) = delta.sin_cos();
                let (sp, cp) = psi.sin_cos();
                self.wall_of_normal((j * cd + (n1 * sp + n2 * cp) * sd).normalize())
            }
            // ELEXI: rotate n by θ₁ about n × t (towards the particle), then by θ₂ about the
            // original n, both angles from the shadow-weighted Gaussian.
            CfdModel::NormalPerturbation => {
                let th1 = self.sampler.sample(rng);
                let th2 = self.sampler.sample(rng);
                let (s1, c1) = th1.sin_cos();
                let (s2, c2) = th2.sin_cos();
                // The horizontal part −sin θ₁ t, turned by θ₂ about y.
                let h = -t * s1;
                let h = Vector3::new(h.x * c2 + h.z * s2, 0.0, -h.x * s2 + h.z * c2);
                self.wall_of_normal((j * c1 + h).normalize())
            }
        }
    }
}

/// A rebound off one of these models for a particle moving towards the wall (the trivial
/// cases ruled out by the caller) whose direction is `inc`: a wall element is drawn for the
/// incident velocity (redrawn while the particle cannot reach it, `U·n ≥ 0`), the collision
/// law is applied, and a rebound that does not leave the mean wall (`v⁺ ≤ 0`) hits the wall
/// again: a new element is drawn for the new velocity ([`super::virtual_wall::Hits`] gives the
/// source). `candidates` counts the collisions.
/// Every collision is reported to `observe` as accepted (each is a real impact).
#[allow(clippy::too_many_arguments)]
pub(crate) fn rebound_repeated<R: Rng + ?Sized>(
    inc: &CfdIncidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    law: &CollisionLaw,
    diameter_m: f64,
    rng: &mut R,
    observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    // A rising particle never meets the wall again in these models.
    let hits = Hits {
        law,
        diameter_m,
        rising: false,
    };
    let (model, delta_gamma) = (inc.model, inc.delta_gamma);
    hits.follow(
        *inc,
        u_in,
        omega_in,
        rng,
        observe,
        |alpha, beta| CfdIncidence::new(model, alpha, beta, delta_gamma),
        |_, _, _| (),
        |cur, _, rng| cur.draw(rng),
        |_, _, u_out, _| u_out.y > 0.0,
    )
}
