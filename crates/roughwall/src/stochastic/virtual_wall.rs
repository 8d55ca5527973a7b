//! What every stochastic wall model shares: the virtual wall element a particle meets
//! ([`SeenWall`]), the outcome of one rebound ([`Rebound`]), the rebounds that need no random
//! draw, the guard on the number of candidate walls, and the loop of the models that follow a
//! particle from hit to hit until it leaves the wall (`Hits`).

use crate::angles::incident_angles;
use crate::angles::{gamma_from_normal, normal_from_xi_zeta, xi_zeta_of_normal, xi_zeta_rotated};
use crate::collision::CollisionLaw;
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// What stays the same over the rebounds of a run: the wall's deviations, the collision law,
/// ψ of Eq. (34) and the particle's diameter (the lever arm of its spin). Every rough-wall
/// model reads its rebound's surroundings from it.
#[derive(Clone, Copy, Debug)]
pub struct Contact<'a> {
    /// Normal-angle deviations `(Δξ, Δζ)` of the statistical wall (rad).
    pub wall: &'a Deviations,
    /// The collision law applied in the frame of each virtual wall element.
    pub law: &'a CollisionLaw,
    /// ψ of the single-collision probability (Radenkovic & Simonin 2021, Eq. 34).
    pub psi: f64,
    /// Particle diameter `D` (m).
    pub diameter_m: f64,
}

/// Upper bound on the candidate walls drawn for one rebound (a guard: the expected
/// number is ~1–3 for every admissible input).
pub const MAX_TRIES: u32 = 100_000;

/// A virtual wall element: its inclinations and unit normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeenWall {
    /// Inclination `γ` in the incident plane (rad, Eq. 20).
    pub gamma: f64,
    /// Inclination `γ*` normal to the incident plane (rad, Eq. 21).
    pub gamma_star: f64,
    /// Fluctuation `ξ' = ξ − π/2` of the normal's angle with `x` (rad, Eq. 4; from `γ, γ*`
    /// by Eq. 23).
    pub xi: f64,
    /// Fluctuation `ζ' = ζ − π/2` of the normal's angle with `z` (rad, Eq. 4; from `γ, γ*`
    /// by Eq. 23).
    pub zeta: f64,
    /// Unit normal (Eqs. 10, 23, exact unit vector).
    pub normal: Vector3<f64>,
}

impl SeenWall {
    /// The mean (smooth) wall: `γ = γ* = 0`, `n = j`.
    pub const FLAT: SeenWall = SeenWall {
        gamma: 0.0,
        gamma_star: 0.0,
        xi: 0.0,
        zeta: 0.0,
        normal: Vector3::new(0.0, 1.0, 0.0),
    };

    /// The element of inclinations `(γ, γ*)` in the incident frame of direction `β`
    /// (`(sin β, cos β)` given): Radenkovic & Simonin 2021, Eq. (23), and its exact unit
    /// normal (Eq. 10; docs/physics.md §2).
    #[inline]
    pub fn of_gammas(gamma: f64, gamma_star: f64, sin_cos_beta: (f64, f64)) -> SeenWall {
        let (xi, zeta) = xi_zeta_rotated(gamma, gamma_star, sin_cos_beta);
        SeenWall {
            gamma,
            gamma_star,
            xi,
            zeta,
            normal: normal_from_xi_zeta(xi, zeta),
        }
    }

    /// The element of normal-angle fluctuations `(ξ', ζ')` in the wall's frame (Eq. 4), seen
    /// from the direction `β` (`(sin β, cos β)` given): its exact unit normal (Eq. 10) and
    /// its inclinations in the incident frame (Eqs. 20–21).
    #[inline]
    pub fn of_xi_zeta(xi: f64, zeta: f64, (s, c): (f64, f64)) -> SeenWall {
        SeenWall {
            gamma: c * xi - s * zeta,
            gamma_star: s * xi + c * zeta,
            xi,
            zeta,
            normal: normal_from_xi_zeta(xi, zeta),
        }
    }

    /// The element of unit normal `normal` seen from direction `β`, with its angles
    /// (Radenkovic & Simonin 2021, Eqs. 20–21).
    #[inline]
    pub fn of_normal(normal: Vector3<f64>, beta: f64) -> SeenWall {
        let (xi, zeta) = xi_zeta_of_normal(&normal);
        let (gamma, gamma_star) = gamma_from_normal(&normal, beta);
        SeenWall {
            gamma,
            gamma_star,
            xi,
            zeta,
            normal,
        }
    }
}

/// The outcome of a rebound from a statistical wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rebound {
    /// Rebound velocity `U⁺` (m/s).
    pub velocity: Vector3<f64>,
    /// Rebound angular velocity `ω⁺` (rad/s).
    pub spin: Vector3<f64>,
    /// Inclination `γ` of the accepted virtual wall in the incident plane (rad, Eq. 20).
    pub gamma: f64,
    /// Inclination `γ*` of the accepted virtual wall normal to the incident plane (rad, Eq. 21).
    pub gamma_star: f64,
    /// Unit normal of the accepted virtual wall (Eq. 23, exact unit vector).
    pub normal: Vector3<f64>,
    /// Candidate walls drawn (≥ 1): steps 2–6 of the procedure were run this many times.
    /// `0` means the particle was not moving towards the wall (`u_in.y ≥ 0` or a
    /// non-finite input) and was returned unchanged; [`MAX_TRIES`] means the guard was hit
    /// and the rebound is the one off the mean (smooth) wall.
    pub tries: u32,
    /// Candidate rebounds computed (steps 5–6 reached, i.e. `U⁻·n < 0`): `1/candidates`
    /// estimates the single-collision probability (a run's `p_single` is
    /// `Σ accepted / Σ candidates`).
    pub candidates: u32,
    /// The first wall element the particle *sees* (first candidate with `U⁻·n < 0`,
    /// before any single-collision rejection): `γ` follows `P_eff(γ | α⁻)` and `γ*` given
    /// `γ` Eq. (30) exactly — the analogue of the deterministic model's first normal
    /// (Radenkovic & Simonin 2021, Figs. 10–11). The accepted wall (`gamma`,
    /// `gamma_star`, `normal`) is biased towards walls that give single collisions.
    pub first: SeenWall,
}

impl Rebound {
    /// The rebound `(velocity, spin)` off the wall element `seen`.
    pub(crate) fn off(
        seen: &SeenWall,
        velocity: Vector3<f64>,
        spin: Vector3<f64>,
        tries: u32,
        candidates: u32,
        first: SeenWall,
    ) -> Rebound {
        Rebound {
            velocity,
            spin,
            gamma: seen.gamma,
            gamma_star: seen.gamma_star,
            normal: seen.normal,
            tries,
            candidates,
            first,
        }
    }

    /// Whether every candidate was rejected until the [`MAX_TRIES`] guard.
    pub fn capped(&self) -> bool {
        self.tries >= MAX_TRIES
    }
}

/// The rebounds that need no random draw: a particle not moving towards the wall (or a
/// non-finite input) is returned unchanged with `tries = 0`; a smooth wall (or a `psi` that
/// can accept nothing) gives the collision with the mean wall. These are this project's
/// rules for the hard cases of docs/physics.md §9, not the paper's (its procedure, §3,
/// assumes a rough wall and a particle that reaches it).
pub(crate) fn trivial(u_in: Vector3<f64>, omega_in: Vector3<f64>, c: &Contact) -> Option<Rebound> {
    let (smooth_wall, law, psi, diameter_m) = (c.wall.is_smooth(), c.law, c.psi, c.diameter_m);
    let j = Vector3::new(0.0, 1.0, 0.0);
    let finite = u_in.iter().chain(omega_in.iter()).all(|c| c.is_finite());
    if !finite || u_in.y >= 0.0 {
        return Some(Rebound {
            velocity: u_in,
            spin: omega_in,
            gamma: 0.0,
            gamma_star: 0.0,
            normal: j,
            tries: 0,
            candidates: 0,
            first: SeenWall::FLAT,
        });
    }
    let bad_psi = !(psi > 0.0 && psi.is_finite());
    if smooth_wall || bad_psi {
        let (u, w) = law.collide(u_in, omega_in, j, diameter_m);
        let n = if bad_psi { MAX_TRIES } else { 1 };
        return Some(Rebound {
            velocity: u,
            spin: w,
            gamma: 0.0,
            gamma_star: 0.0,
            normal: j,
            tries: n,
            candidates: n,
            first: SeenWall::FLAT,
        });
    }
    None
}

/// After [`MAX_TRIES`] candidate walls: the collision with the mean (smooth) wall `j` (a
/// guard of this project, docs/physics.md §9: never a hang; the paper's procedure, §3, has
/// no cap).
pub(crate) fn guard_rebound(
    u: Vector3<f64>,
    w: Vector3<f64>,
    law: &CollisionLaw,
    diameter_m: f64,
    candidates: u32,
    first: SeenWall,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    let j = Vector3::new(0.0, 1.0, 0.0);
    let (u_out, w_out) = law.collide(u, w, j, diameter_m);
    observe(&u, &j, true);
    Rebound {
        velocity: u_out,
        spin: w_out,
        gamma: 0.0,
        gamma_star: 0.0,
        normal: j,
        tries: MAX_TRIES,
        candidates,
        first,
    }
}

/// The models that follow a particle from hit to hit until it leaves the wall (the simpler
/// variants and the calibrated model): each hit draws an element for the particle's current
/// direction, applies the collision law, and either lets the particle leave or goes on with
/// the rebound velocity. A rebound that does not leave meets a new virtual wall (Sommerfeld
/// & Zivkovic 1992, as Radenkovic & Simonin 2021, Sec. 1, describe it; for `calibrated`,
/// docs/design-notes.md, "Multiple collisions followed"), unlike the paper's model, which
/// redraws the same incident particle (Eq. 34).
pub(crate) struct Hits<'a> {
    pub law: &'a CollisionLaw,
    pub diameter_m: f64,
    /// Whether a trapped particle may meet the wall while rising (`α > 0`).
    pub rising: bool,
}

impl Hits<'_> {
    /// Hit `k = 0, 1, …` with velocity `u` and its direction `cur` (`first`, then
    /// `direction(α, β)` of the rebound velocity): `at_hit(cur, the normal of the element just
    /// left (None for the first hit), rng)` once, then `draw(cur, state, rng)` an element the
    /// particle can reach (redrawn while `U·n ≥ 0`), the collision law, then
    /// `leaves(cur, state, u⁺, rng)` or the next hit; the mean wall after [`MAX_TRIES`].
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn follow<R: Rng + ?Sized, I, S>(
        &self,
        first_direction: I,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        rng: &mut R,
        mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
        direction: impl Fn(f64, f64) -> I,
        mut at_hit: impl FnMut(&I, Option<&Vector3<f64>>, &mut R) -> S,
        mut draw: impl FnMut(&I, &S, &mut R) -> SeenWall,
        mut leaves: impl FnMut(&I, &S, &Vector3<f64>, &mut R) -> bool,
    ) -> Rebound {
        let (mut u, mut w) = (u_in, omega_in);
        let mut cur = first_direction;
        let mut candidates = 0u32;
        let mut first = SeenWall::FLAT;
        let mut state = at_hit(&cur, None, rng);
        for tries in 1..=MAX_TRIES {
            let seen = draw(&cur, &state, rng);
            if u.dot(&seen.normal) >= 0.0 {
                continue;
            }
            candidates += 1;
            if candidates == 1 {
                first = seen;
            }
            observe(&u, &seen.normal, true);
            let (u_out, w_out) = self.law.collide(u, w, seen.normal, self.diameter_m);
            if leaves(&cur, &state, &u_out, rng) {
                return Rebound::off(&seen, u_out, w_out, tries, candidates, first);
            }
            (u, w) = (u_out, w_out);
            let (alpha, beta) = incident_angles(&u);
            // Without rising hits, an exactly tangential velocity is taken as grazing by a
            // hair so that the direction is defined.
            let alpha = if self.rising {
                alpha
            } else {
                alpha.min(-1e-12)
            };
            cur = direction(alpha, beta);
            state = at_hit(&cur, Some(&seen.normal), rng);
        }
        guard_rebound(u, w, self.law, self.diameter_m, candidates, first, observe)
    }
}
