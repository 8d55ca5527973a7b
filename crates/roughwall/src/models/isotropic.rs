//! What the rough-wall models CFD codes ship have in common (each model's file cites its
//! source): a virtual wall element drawn from one isotropic roughness angle `Δγ`, the
//! collision law, and a rebound that does not leave the mean wall hits the wall again, with a
//! new element for its new velocity. Each model's file draws its element
//! ([`IsotropicDraw`]); [`Isotropic`] makes the draw a rough-wall model.

use super::params;
use super::rough_wall_model::{ModelParams, NamedModel, RoughWallModel};
use crate::error::Result;
use crate::stochastic::virtual_wall::Hits;
use crate::stochastic::{Contact, Rebound, SeenWall, ShadowSampler};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;
use std::marker::PhantomData;

/// How one isotropic model draws its virtual wall element, and its name.
pub trait IsotropicDraw: Copy + std::fmt::Debug + PartialEq + Send + Sync {
    /// The model's name in case files.
    const NAME: &'static str;

    /// A wall element for the direction `inc`, `γ > 0` tilting it towards the particle.
    fn draw<R: Rng + ?Sized>(inc: &IsotropicIncidence, rng: &mut R) -> SeenWall;
}

/// The isotropic rough-wall model whose element `D` draws, with its roughness angle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Isotropic<D> {
    /// The roughness angle `Δγ` (rad); `None`: `(Δξ + Δζ)/2` of the wall.
    pub delta_gamma: Option<f64>,
    draw: PhantomData<D>,
}

impl<D> Isotropic<D> {
    /// The model with the roughness angle `delta_gamma` (rad; `None`: the wall's mean).
    pub fn new(delta_gamma: Option<f64>) -> Isotropic<D> {
        Isotropic {
            delta_gamma,
            draw: PhantomData,
        }
    }
}

impl<D: IsotropicDraw> RoughWallModel for Isotropic<D> {
    type Incidence = IsotropicIncidence;

    fn name(&self) -> &'static str {
        D::NAME
    }

    fn anisotropic(&self) -> bool {
        false
    }

    fn roughness_angle(&self, wall: &Deviations) -> f64 {
        self.delta_gamma
            .unwrap_or(0.5 * (wall.delta_xi + wall.delta_zeta))
    }

    fn incidence(&self, alpha: f64, beta: f64, wall: &Deviations) -> IsotropicIncidence {
        IsotropicIncidence::new(alpha, beta, self.roughness_angle(wall))
    }

    #[inline]
    fn rebound_drawn<R: Rng + ?Sized>(
        &self,
        inc: &IsotropicIncidence,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        contact: &Contact,
        rng: &mut R,
        observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    ) -> Rebound {
        rebound_repeated(inc, u_in, omega_in, contact, rng, observe, D::draw)
    }
}

impl<D: IsotropicDraw> NamedModel for Isotropic<D> {
    const NAME: &'static str = D::NAME;

    /// `stochastic.delta_gamma_deg` (checked), and no escape table.
    fn from_params(params: &ModelParams) -> Result<Self> {
        let delta_gamma = params::delta_gamma(params)?;
        params::refuse_escape_table(params, D::NAME)?;
        params::refuse_wall_table(params, D::NAME)?;
        Ok(Isotropic::new(delta_gamma))
    }
}

/// What these models precompute for an incident direction `(α, β)`.
#[derive(Clone, Copy, Debug)]
pub struct IsotropicIncidence {
    /// `α` (rad).
    pub alpha: f64,
    /// `β` (rad).
    pub beta: f64,
    /// `(sin β, cos β)`.
    pub sin_cos_beta: (f64, f64),
    /// The model's one roughness angle `Δγ` (rad).
    pub delta_gamma: f64,
    /// The shadow law of Eqs. (31–33) with `Δγ` (Sommerfeld & Huber, ELEXI).
    pub sampler: ShadowSampler,
}

impl IsotropicIncidence {
    /// The direction `(α, β)` (rad) with the roughness angle `delta_gamma` (rad).
    pub fn new(alpha: f64, beta: f64, delta_gamma: f64) -> IsotropicIncidence {
        let sampler = ShadowSampler::for_trajectory(alpha, delta_gamma);
        IsotropicIncidence {
            alpha,
            beta,
            sin_cos_beta: beta.sin_cos(),
            delta_gamma,
            sampler,
        }
    }

    /// The element of angles `γ` (in the incident plane, towards the particle) and `γ*`
    /// (across it).
    pub fn wall_of_gammas(&self, gamma: f64, gamma_star: f64) -> SeenWall {
        SeenWall::of_gammas(gamma, gamma_star, self.sin_cos_beta)
    }

    /// The element of unit normal `normal`.
    pub fn wall_of_normal(&self, normal: Vector3<f64>) -> SeenWall {
        SeenWall::of_normal(normal, self.beta)
    }

    /// The horizontal incident direction `t = (cos β, 0, −sin β)`.
    pub fn tangent(&self) -> Vector3<f64> {
        let (sb, cb) = self.sin_cos_beta;
        Vector3::new(cb, 0.0, -sb)
    }
}

/// A rebound off one of these models for a particle moving towards the wall (the trivial
/// cases ruled out by the caller) whose direction is `inc`: an element is drawn by `draw` for
/// the incident velocity (redrawn while the particle cannot reach it, `U·n ≥ 0`), the
/// collision law is applied, and a rebound that does not leave the mean wall (`v⁺ ≤ 0`) hits
/// the wall again: a new element is drawn for the new velocity ([`Hits`] gives the source).
/// `candidates` counts the collisions; every one is reported to `observe` as accepted (each
/// is a real impact).
fn rebound_repeated<R: Rng + ?Sized>(
    inc: &IsotropicIncidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    contact: &Contact,
    rng: &mut R,
    observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    draw: impl Fn(&IsotropicIncidence, &mut R) -> SeenWall,
) -> Rebound {
    // A rising particle never meets the wall again in these models.
    let hits = Hits {
        law: contact.law,
        diameter_m: contact.diameter_m,
        rising: false,
    };
    let delta_gamma = inc.delta_gamma;
    hits.follow(
        *inc,
        u_in,
        omega_in,
        rng,
        observe,
        |alpha, beta| IsotropicIncidence::new(alpha, beta, delta_gamma),
        |_, _, _| (),
        |cur, _, rng| draw(cur, rng),
        |_, _, u_out, _| u_out.y > 0.0,
    )
}
