//! One rebound from whichever rough-wall model a [`Variant`] names ([`rebound`] is the
//! paper's, the entry point a CFD code calls once per wall collision): the paper's
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

/// One rebound of a particle from the statistical anisotropic rough wall
/// (Radenkovic & Simonin 2021, Sec. 3.6, Fig. 13; docs/physics.md §3 steps 1–7).
///
/// 1. `α⁻, β⁻` of `u_in`, then `Δγ, Δγ*, Cov(γ, γ*)` (Eq. 26).
/// 2. `γ` from the shadow-effect law `P_eff(γ | α⁻)` (Eqs. 31–33), sampled exactly
///    ([`super::shadow_effect::ShadowSampler`]).
/// 3. `γ*` from the conditional normal law given `γ` (Eqs. 29–30).
/// 4. The unit normal `n` (Eq. 23, exact unit vector); if `U⁻·n ≥ 0`, back to 2.
/// 5. The collision law in the frame of `n` ([`CollisionLaw::collide`], Eqs. 36–42).
/// 6. `α⁺`; reject if `α⁺ ≤ 0` or with probability `1 − tanh(ψ α⁺/Δγ(β⁺))`
///    (Eqs. 34–35) and go back to 2 with the same incident state.
/// 7. Return `U⁺, ω⁺`.
///
/// `psi` is ψ of Eq. (34) (2 in the paper); `diameter_m` the particle diameter (m).
/// A smooth wall (`Δξ = Δζ = 0`) is one collision with the mean wall, exactly. A
/// non-positive or non-finite `psi` cannot accept any candidate: the smooth-wall
/// collision is returned with `tries = MAX_TRIES` (callers validate `psi`).
///
/// Precondition: the particle moves towards the wall, `u_in.y < 0`; otherwise the
/// input is returned unchanged with `tries = 0`.
///
/// ```
/// use nalgebra::Vector3;
/// use rand::SeedableRng;
/// use roughwall::collision::{CollisionLaw, ShParams};
/// use roughwall::stochastic::rebound;
/// use roughwall::wall::Deviations;
///
/// // Glass bead (D = 500 µm) hitting a steel wall at α⁻ = −15°, β⁻ = 60°.
/// let wall = Deviations { delta_xi: 3.8_f64.to_radians(), delta_zeta: 7.5_f64.to_radians() };
/// let law = CollisionLaw::SommerfeldHuber(ShParams::glass_steel());
/// let u_in = roughwall::angles::velocity_from_angles(6.0, (-15f64).to_radians(), 60f64.to_radians());
/// let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(42);
/// let out = rebound(u_in, Vector3::zeros(), &wall, &law, 2.0, 500e-6, &mut rng);
/// assert!(out.velocity.y > 0.0);                      // leaves the wall
/// assert!(out.velocity.norm() <= u_in.norm() + 1e-12); // no energy gain
/// assert!(out.tries >= 1);
/// ```
pub fn rebound<R: Rng + ?Sized>(
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    rng: &mut R,
) -> Rebound {
    rebound_variant(
        u_in,
        omega_in,
        wall,
        law,
        psi,
        diameter_m,
        Variant::PAPER,
        rng,
    )
}

/// [`rebound`] with the virtual walls drawn by `variant` ([`super::variants`]); the paper's
/// variant is [`rebound`].
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
/// or rejected as a multiple collision (Radenkovic & Simonin 2021, Eq. 34; docs/physics.md §3
/// step 6). The
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
