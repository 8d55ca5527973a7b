//! One rebound from any rough-wall model, with the cases that need no random draw ruled out
//! the same way for every model: a particle not moving towards the wall (or a non-finite
//! input) is returned unchanged, a smooth wall (or a ψ that can accept nothing) gives the
//! collision with the mean wall (docs/physics.md §9).

use super::rough_wall_model::RoughWallModel;
use crate::angles::incident_angles;
use crate::stochastic::virtual_wall::trivial;
use crate::stochastic::{Contact, Rebound};
use nalgebra::Vector3;
use rand::Rng;

/// One rebound of a particle of velocity `u_in` and spin `omega_in` off `model`: the entry
/// point for a single hit (a CFD code's). [`crate::stochastic::rebound`] is the paper's
/// model's.
pub fn rebound_with<M: RoughWallModel, R: Rng + ?Sized>(
    model: &M,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    contact: &Contact,
    rng: &mut R,
) -> Rebound {
    if let Some(done) = trivial(u_in, omega_in, contact) {
        return done;
    }
    // The trivial cases are ruled out once, here: they also keep a direction from being
    // built for a particle that does not move towards the wall.
    let (alpha, beta) = incident_angles(&u_in);
    let inc = model.incidence(alpha, beta, contact.wall);
    model.rebound_drawn(&inc, u_in, omega_in, contact, rng, |_, _, _| {})
}

/// The rebound of a particle of velocity `u_in` whose direction's incidence `inc` is given
/// (built once for the many particles of one direction by [`RoughWallModel::incidence`]; it
/// must be the direction of `u_in` on the contact's wall), reporting every candidate rebound
/// to `observe`: the incident velocity, the normal of the virtual wall hit and whether the
/// rebound was accepted (the last call) or rejected as a multiple collision (Radenkovic &
/// Simonin 2021, Eq. 34; docs/physics.md §3 step 6). The smooth-wall fallback and the trivial
/// cases with a collision report the mean wall `j` as accepted; the models that follow a
/// trapped particle report every hit as accepted.
#[inline]
pub fn rebound_from_observed<M: RoughWallModel, R: Rng + ?Sized>(
    model: &M,
    inc: &M::Incidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    contact: &Contact,
    rng: &mut R,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    if let Some(done) = trivial(u_in, omega_in, contact) {
        if done.candidates > 0 {
            observe(&u_in, &done.normal, true);
        }
        return done;
    }
    model.rebound_drawn(inc, u_in, omega_in, contact, rng, observe)
}
