//! One rebound from whichever rough-wall model a [`Variant`] names: the paper's
//! ([`super::rebound_model`]), one of the models CFD codes ship ([`super::cfd_models`]) or
//! the calibrated one ([`crate::calibrated`]). Each model keeps its own view of an incident
//! direction ([`ModelIncidence`]); this module only chooses.

use super::cfd_models::{rebound_repeated, CfdIncidence};
use super::rebound_model::Incidence;
use super::variants::{Variant, VariantKind};
use super::virtual_wall::{trivial, Rebound};
use crate::angles::incident_angles;
use crate::calibrated::{CalibratedIncidence, EscapeTable};
use crate::collision::CollisionLaw;
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// What the model a variant names precomputes for one incident direction `(α, β)` on a wall:
/// built once for the many particles of a direction.
#[derive(Clone, Copy, Debug)]
pub enum ModelIncidence {
    /// Radenkovic & Simonin 2021.
    Paper(Incidence),
    /// A model CFD codes ship.
    Cfd(CfdIncidence),
    /// The calibrated model and its table.
    Calibrated(CalibratedIncidence, &'static EscapeTable),
}

impl ModelIncidence {
    /// The direction `(α, β)` (rad) on `wall`, walls drawn by `variant`.
    pub fn new(alpha: f64, beta: f64, wall: &Deviations, variant: Variant) -> ModelIncidence {
        match variant.kind.cfd_model() {
            Some(model) => ModelIncidence::Cfd(CfdIncidence::new(
                model,
                alpha,
                beta,
                variant.delta_gamma_on(wall),
            )),
            None if variant.kind == VariantKind::Calibrated => ModelIncidence::Calibrated(
                CalibratedIncidence::new(alpha, beta, wall),
                variant.escape_table(),
            ),
            None => ModelIncidence::Paper(Incidence::new(alpha, beta, wall)),
        }
    }
}

/// [`super::rebound`] with the virtual walls drawn by `variant` ([`super::variants`]); the
/// paper's variant is [`super::rebound`] exactly.
#[allow(clippy::too_many_arguments)]
pub fn rebound_variant<R: Rng + ?Sized>(
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    variant: Variant,
    rng: &mut R,
) -> Rebound {
    let smooth_wall = wall.delta_xi == 0.0 && wall.delta_zeta == 0.0;
    if let Some(done) = trivial(u_in, omega_in, smooth_wall, law, psi, diameter_m) {
        return done;
    }
    // The trivial cases are ruled out once, here: they also keep a direction from being
    // built for a particle that does not move towards the wall.
    let (alpha, beta) = incident_angles(&u_in);
    let inc = ModelIncidence::new(alpha, beta, wall, variant);
    rebound_drawn(
        &inc,
        u_in,
        omega_in,
        wall,
        law,
        psi,
        diameter_m,
        rng,
        |_, _, _| {},
    )
}

/// The rebound of a particle of velocity `u_in` whose direction's [`ModelIncidence`] is
/// given (built once for many particles of one direction; it must be the direction of
/// `u_in` on `wall`).
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn rebound_from<R: Rng + ?Sized>(
    inc: &ModelIncidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    rng: &mut R,
) -> Rebound {
    rebound_from_observed(
        inc,
        u_in,
        omega_in,
        wall,
        law,
        psi,
        diameter_m,
        rng,
        |_, _, _| {},
    )
}

/// [`rebound_from`] reporting every candidate rebound to `observe`: the incident velocity,
/// the normal of the virtual wall hit and whether the rebound was accepted (the last call)
/// or rejected as a multiple collision (Radenkovic & Simonin 2021, Fig. 13, step 6). The
/// smooth-wall fallback and the trivial cases with a collision report the mean wall `j` as
/// accepted; the models that follow a trapped particle report every hit as accepted.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn rebound_from_observed<R: Rng + ?Sized>(
    inc: &ModelIncidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    rng: &mut R,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    let smooth_wall = wall.delta_xi == 0.0 && wall.delta_zeta == 0.0;
    if let Some(done) = trivial(u_in, omega_in, smooth_wall, law, psi, diameter_m) {
        if done.candidates > 0 {
            observe(&u_in, &done.normal, true);
        }
        return done;
    }
    rebound_drawn(
        inc, u_in, omega_in, wall, law, psi, diameter_m, rng, observe,
    )
}

/// [`rebound_from_observed`] once the trivial cases are ruled out.
#[allow(clippy::too_many_arguments)]
#[inline]
fn rebound_drawn<R: Rng + ?Sized>(
    inc: &ModelIncidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    rng: &mut R,
    observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    match inc {
        ModelIncidence::Paper(inc) => {
            inc.rebound_observed(u_in, omega_in, wall, law, psi, diameter_m, rng, observe)
        }
        ModelIncidence::Cfd(inc) => {
            rebound_repeated(inc, u_in, omega_in, law, diameter_m, rng, observe)
        }
        ModelIncidence::Calibrated(inc, table) => crate::calibrated::rebound(
            inc, table, u_in, omega_in, wall, law, diameter_m, rng, observe,
        ),
    }
}
