//! The stochastic rebound model of Radenkovic & Simonin 2021 (Sec. 3.6, Fig. 13; the
//! procedure written out in docs/physics.md §3): one rebound of a particle from the
//! statistical anisotropic rough wall.
//!
//! Its entry point, [`rebound`], is what a CFD (Euler–Lagrange) code calls once per wall
//! collision: it needs only the incident state, the wall's two deviations, the collision law
//! and a random generator — no surface, no tables.

use super::shadow_effect::ShadowSampler;
use super::virtual_wall::{guard_rebound, trivial, Contact, Rebound, SeenWall, MAX_TRIES};
use crate::angles::incident_angles;
use crate::check::within;
use crate::collision::CollisionLaw;
use crate::error::Result;
use crate::wall::{
    delta_gamma_sq_of_direction, draw_gamma_star, rotated_moments, Deviations, Moments,
};
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::StandardNormal;

/// ψ of Eq. (34): the paper uses 2 (Konan et al. 1.5); below 0.01 almost every candidate
/// rebound is rejected (hundreds of redraws per rebound), above 100 none is.
pub const PSI_RANGE: (f64, f64) = (0.01, 100.0);

/// ψ of Eq. (34) when none is given: Radenkovic & Simonin 2021's 2 (Sec. 3.5, Fig. 12;
/// docs/physics.md §3 step 6).
pub const PSI_PAPER: f64 = 2.0;

/// ψ of Eq. (34) under the key `stochastic.psi`, checked against [`PSI_RANGE`].
pub fn checked_psi(psi: f64) -> Result<f64> {
    let (lo, hi) = PSI_RANGE;
    within(
        "stochastic.psi",
        psi,
        lo,
        hi,
        "",
        "below, almost every candidate rebound is redrawn; above, none is; the paper uses 2",
    )
}

/// One rebound of a particle from the statistical anisotropic rough wall
/// (Radenkovic & Simonin 2021, Sec. 3.6, Fig. 13; docs/physics.md §3 steps 1–7).
///
/// 1. `α⁻, β⁻` of `u_in`, then `Δγ, Δγ*, Cov(γ, γ*)` (Eq. 26).
/// 2. `γ` from the shadow-effect law `P_eff(γ | α⁻)` (Eqs. 31–33), sampled exactly
///    ([`ShadowSampler`]).
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
/// input is returned unchanged with `tries = 0`. The other rough-wall models are
/// [`crate::models`].
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
    let contact = Contact {
        wall,
        law,
        psi,
        diameter_m,
    };
    if let Some(done) = trivial(u_in, omega_in, &contact) {
        return done;
    }
    Incidence::of_velocity(&u_in, wall).rebound_observed(
        u_in,
        omega_in,
        &contact,
        rng,
        |_, _, _| {},
    )
}

/// Step 1 of the procedure and the shadow-effect sampler: everything that depends only on
/// the incident *direction* `(α⁻, β⁻)` and the wall, not on the speed or the random draws.
/// A run of many particles with one direction builds it once.
#[derive(Clone, Copy, Debug)]
pub struct Incidence {
    /// `α⁻` (rad).
    pub alpha: f64,
    /// `β⁻` (rad).
    pub beta: f64,
    /// `(sin β⁻, cos β⁻)`, for Eq. (23).
    sin_cos_beta: (f64, f64),
    /// `Δγ², Δγ*², Cov(γ, γ*)` at `β⁻` (Eq. 26).
    moments: Moments,
    /// `P_eff(γ | α⁻)` (Eqs. 31–33) with `Δγ(β⁻)` of Eq. (26).
    sampler: ShadowSampler,
}

impl Incidence {
    /// The direction `(α⁻, β⁻)` (rad) on `wall` (Eq. 26 at `β⁻`; the shadow law of Eqs.
    /// 31–33, continued to `α > 0` for a direction that rises: [`ShadowSampler::rising`]).
    pub fn new(alpha: f64, beta: f64, wall: &Deviations) -> Incidence {
        let moments = rotated_moments(wall, beta);
        let delta_gamma = moments.delta_gamma();
        let sampler = ShadowSampler::for_trajectory(alpha, delta_gamma);
        Incidence {
            alpha,
            beta,
            sin_cos_beta: beta.sin_cos(),
            moments,
            sampler,
        }
    }

    /// The direction of the velocity `u_in` (docs/physics.md §1) on `wall`.
    pub fn of_velocity(u_in: &Vector3<f64>, wall: &Deviations) -> Incidence {
        let (alpha, beta) = incident_angles(u_in);
        Incidence::new(alpha, beta, wall)
    }

    /// Steps 2–4 up to the normal: a wall element seen by this direction, `γ` from
    /// `P_eff(γ | α⁻)`, `γ*` given `γ` from Eq. (30), the unit normal of Eq. (23).
    #[inline]
    pub(crate) fn draw_wall<R: Rng + ?Sized>(&self, rng: &mut R) -> SeenWall {
        let gamma = self.sampler.sample(rng);
        let gamma_star = draw_gamma_star(&self.moments, gamma, || rng.sample(StandardNormal));
        SeenWall::of_gammas(gamma, gamma_star, self.sin_cos_beta)
    }

    /// Steps 2–7 for a particle moving towards the wall (`u_in.y < 0`, finite; the trivial
    /// cases ruled out by the caller) whose direction this is: candidate walls drawn until
    /// one is accepted, every candidate rebound reported to `observe` (the incident
    /// velocity, the virtual wall's normal, whether it was accepted).
    #[inline]
    pub(crate) fn rebound_observed<R: Rng + ?Sized>(
        &self,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        c: &Contact,
        rng: &mut R,
        mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    ) -> Rebound {
        let (wall, law, psi, diameter_m) = (c.wall, c.law, c.psi, c.diameter_m);
        let mut candidates = 0u32;
        let mut first = SeenWall::FLAT;
        for tries in 1..=MAX_TRIES {
            // Steps 2–4.
            let seen = self.draw_wall(rng);
            if u_in.dot(&seen.normal) >= 0.0 {
                continue;
            }
            // Step 5.
            candidates += 1;
            if candidates == 1 {
                first = seen;
            }
            let (u, w) = law.collide(u_in, omega_in, seen.normal, diameter_m);
            // Step 6.
            if !accept_single_collision(&u, wall, psi, rng) {
                observe(&u_in, &seen.normal, false);
                continue;
            }
            observe(&u_in, &seen.normal, true);
            // Step 7.
            return Rebound::off(&seen, u, w, tries, candidates, first);
        }
        guard_rebound(u_in, omega_in, law, diameter_m, candidates, first, observe)
    }
}

/// Radenkovic & Simonin 2021, Eq. (34): `P(n = 1 | α⁺) = tanh(ψ α⁺ / Δγ(β⁺))` for
/// `α⁺ > 0`, with `Δγ(β⁺)` of Eq. (35); `Δγ(β⁺) = 0` (smooth wall in that plane) gives 1.
///
/// `cos²β⁺ = u⁺²/(u⁺² + w⁺²)` is taken from the velocity directly (no trigonometry).
#[inline]
pub fn single_collision_probability(
    u_out: &Vector3<f64>,
    alpha_out: f64,
    wall: &Deviations,
    psi: f64,
) -> f64 {
    if alpha_out <= 0.0 {
        return 0.0;
    }
    let var = delta_gamma_sq_of_direction(u_out.x, u_out.z, wall);
    if var <= 0.0 {
        1.0
    } else {
        (psi * alpha_out / var.sqrt()).tanh()
    }
}

/// Accepts a candidate rebound with the probability [`single_collision_probability`]
/// (Eqs. 34–35), from the velocity alone and mostly without `asin`/`tanh`:
/// with `y = v⁺/|U⁺|` and `t₀ = ψ y / Δγ(β⁺) ≤ ψ α⁺/Δγ(β⁺)` (`asin y ≥ y`),
/// `tanh(t₀) ≥ (t₀ + t₀²)/(1 + t₀ + t₀²)` (from `e^{2t} ≥ 1 + 2t + 2t²`) is a squeeze, and
/// `tanh(t) = 1` exactly in `f64` for `t ≥ 20` (no uniform is drawn then).
#[inline]
fn accept_single_collision<R: Rng + ?Sized>(
    u_out: &Vector3<f64>,
    wall: &Deviations,
    psi: f64,
    rng: &mut R,
) -> bool {
    let s = u_out.norm();
    if s.is_nan() || s <= 0.0 || u_out.y <= 0.0 {
        return false;
    }
    let y = (u_out.y / s).min(1.0);
    let var = delta_gamma_sq_of_direction(u_out.x, u_out.z, wall);
    if var <= 0.0 {
        return true;
    }
    let sd = var.sqrt();
    let t0 = psi * y / sd;
    if t0 >= 20.0 {
        return true;
    }
    let u: f64 = rng.gen();
    let q = t0 + t0 * t0;
    u * (1.0 + q) < q || u < (psi * y.asin() / sd).tanh()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn squeezed_acceptance_has_the_probability_of_eq34() {
        let wall = Deviations {
            delta_xi: 0.04,
            delta_zeta: 0.13,
        };
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(3);
        for (a_deg, b) in [
            (0.5, 0.3),
            (2.0, 1.0),
            (5.0, -2.0),
            (20.0, 0.0),
            (0.01, 1.5),
        ] {
            let u = crate::angles::velocity_from_angles(2.0, f64::to_radians(a_deg), b);
            let (ao, _) = crate::angles::incident_angles(&u);
            let p = single_collision_probability(&u, ao, &wall, 2.0);
            let n = 200_000;
            let k = (0..n)
                .filter(|_| accept_single_collision(&u, &wall, 2.0, &mut rng))
                .count();
            let f = k as f64 / n as f64;
            let se = (p * (1.0 - p) / n as f64).sqrt().max(1e-9);
            assert!((f - p).abs() < 5.0 * se + 1e-12, "α⁺={a_deg}: {f} vs {p}");
        }
    }
}
