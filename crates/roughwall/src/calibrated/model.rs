//! The `calibrated` wall model: the virtual walls of Radenkovic & Simonin 2021 (Eqs. 26,
//! 29–33) drawn in the wall's slopes ([`super::slope_space`]) and corrected by the
//! calibrated element weight, the collision law, then the calibrated escape probability —
//! or the particle is trapped and meets the wall again with its rebound velocity, its next
//! element remembering the one it has just left ([`super::Stage::later`],
//! [`super::transverse_memory`]).

use super::constants::{MAX_PROPOSALS, PROPOSAL_EPS};
use super::grid::Stage;
use super::slope_space::{
    normal_from_slopes, proposal, reduced_slope, slope_deviations, slopes_from_normal,
};
use super::table::{ElementRead, EscapeTable};
use crate::stochastic::shadow_effect::ShadowSampler;
use crate::stochastic::virtual_wall::{Contact, Hits, Rebound, SeenWall};
use crate::wall::{conditional_gamma_star, draw_gamma_star, rotated_moments, Deviations, Moments};
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::StandardNormal;

/// The residual of the transverse slope of the wall element of unit normal `n` seen from
/// direction `β` on the wall of slope spreads `slopes` ([`slope_deviations`]): `s_t` less
/// its conditional mean given `s_l` (Eq. 30 in slopes), over its conditional spread — the
/// standard normal the `calibrated` model draws it from. The calibrated model's later
/// collisions remember it (`super::transverse_memory`); `rebound calibrate` counts it the
/// same way. 0 where Eq. (30) leaves `s_t` no spread.
pub fn transverse_residual(n: &Vector3<f64>, beta: f64, slopes: &Deviations) -> f64 {
    let moments = rotated_moments(slopes, beta);
    let (s_l, s_t) = slopes_from_normal(n, beta);
    residual_of_slopes(&moments, s_l, s_t)
}

/// What a later collision remembers of the element of unit normal `n_left` it has just
/// left, seen from its own direction `β` on the wall of slope spreads `slopes`: the
/// reduced slope `q = s_l/σ(β)` that sets its stage (the valley's memory,
/// [`Stage::later`]) and the transverse residual `z_prev` ([`transverse_residual`]). The
/// model and `rebound calibrate` both read the memory here.
pub fn left_element_memory(n_left: &Vector3<f64>, beta: f64, slopes: &Deviations) -> (f64, f64) {
    memory_of(&rotated_moments(slopes, beta), n_left, beta)
}

/// [`left_element_memory`] with the direction's slope moments given.
#[inline]
fn memory_of(moments: &Moments, n_left: &Vector3<f64>, beta: f64) -> (f64, f64) {
    let (s_l, s_t) = slopes_from_normal(n_left, beta);
    (
        s_l / moments.delta_gamma(),
        residual_of_slopes(moments, s_l, s_t),
    )
}

#[inline]
fn residual_of_slopes(moments: &Moments, s_l: f64, s_t: f64) -> f64 {
    let (mean, var) = conditional_gamma_star(moments, s_l);
    if var > 0.0 {
        (s_t - mean) / var.sqrt()
    } else {
        0.0
    }
}

/// What the calibrated model precomputes for an incident direction `(α, β)` on a wall: the
/// wall's slope spreads, their moments along `β` (Eq. 26 in slopes), the reduced incidence
/// `x_in = tan α/σ(β)` of the tables, and the proposal law at `x_in`.
#[derive(Clone, Copy, Debug)]
pub struct CalibratedIncidence {
    /// `α` (rad; positive for a trapped particle that meets the wall while rising).
    pub alpha: f64,
    /// `β` (rad).
    pub beta: f64,
    sin_cos_beta: (f64, f64),
    /// The slopes' `σ_l², σ_t², Cov` along and across `β`.
    moments: Moments,
    /// The proposal law ([`proposal`]) at `x_in`.
    sampler: ShadowSampler,
    /// `tan α/σ(β)` ([`reduced_slope`]), once per direction rather than once per particle.
    x_in: f64,
    /// The wall's slope spreads ([`slope_deviations`]).
    slopes: Deviations,
}

impl CalibratedIncidence {
    /// The direction `(α, β)` (rad) on the wall of normal-angle deviations `wall`.
    pub fn new(alpha: f64, beta: f64, wall: &Deviations) -> CalibratedIncidence {
        let slopes = slope_deviations(wall);
        let moments = rotated_moments(&slopes, beta);
        let x_in = alpha.tan() / moments.delta_gamma();
        CalibratedIncidence {
            alpha,
            beta,
            sin_cos_beta: beta.sin_cos(),
            moments,
            sampler: proposal(x_in),
            x_in,
            slopes,
        }
    }

    /// The reduced incidence `tan α/σ(β)` of the tables.
    pub fn x_in(&self) -> f64 {
        self.x_in
    }

    /// The `calibrated` model's element, in slopes ([`super::slope_space`]): the reduced
    /// slope along the path `g = s_l/σ(β⁻)` from the shadow law in `x = tan α⁻/σ(β⁻)`
    /// (Eq. 32 at a vanishing roughness: `(g − x) e^{−g²/2}` on `g > x`) corrected by the
    /// calibrated weight `w(stage, x, g − x)` of [`EscapeTable::element_weight`] (a draw is
    /// accepted with `w / bound`: rejection sampling, exact for the corrected law); the
    /// transverse slope `s_t` given `s_l` from Eq. (30) in slopes, exact for a Gaussian
    /// surface, its standardised residual remembering the element just left (`z_prev`,
    /// [`super::transverse_memory`]; a first collision: a fresh draw); the normal of those
    /// slopes.
    #[inline]
    pub(crate) fn draw_wall_corrected<R: Rng + ?Sized>(
        &self,
        table: &EscapeTable,
        &(stage, read, z_prev): &(Stage, ElementRead, f64),
        rng: &mut R,
    ) -> SeenWall {
        let mut g = self.sampler.sample(rng) / PROPOSAL_EPS;
        // The bound makes ~1–2 proposals typical; the cap only guards a degenerate table.
        for _ in 0..MAX_PROPOSALS {
            if rng.gen::<f64>() * read.bound < table.weight_at(&read, g) {
                break;
            }
            g = self.sampler.sample(rng) / PROPOSAL_EPS;
        }
        let s_l = g * self.moments.delta_gamma();
        let s_t = draw_gamma_star(&self.moments, s_l, || {
            table.transverse_residual(stage, z_prev, rng.sample(StandardNormal))
        });
        self.wall_of_slopes(s_l, s_t)
    }

    /// The proposal's element without the table's correction: the slope along the path from
    /// the shadow law in slopes (Radenkovic & Simonin 2021, Eq. 32 at vanishing roughness,
    /// `(g − x)e^{−g²/2}`: `super::slope_space::proposal`), the transverse slope from
    /// Eq. (30) in slopes afresh.
    #[inline]
    pub fn draw_proposal<R: Rng + ?Sized>(&self, rng: &mut R) -> SeenWall {
        let g = self.sampler.sample(rng) / PROPOSAL_EPS;
        let s_l = g * self.moments.delta_gamma();
        let s_t = draw_gamma_star(&self.moments, s_l, || rng.sample(StandardNormal));
        self.wall_of_slopes(s_l, s_t)
    }

    /// A wall element of slopes `(s_l, s_t)` along and across the incident plane, with its
    /// angles (`ξ' = acos n_x − π/2 = −asin n_x`, Eqs. 20–21 for `(γ, γ*)`).
    #[inline]
    fn wall_of_slopes(&self, s_l: f64, s_t: f64) -> SeenWall {
        let normal = normal_from_slopes(s_l, s_t, self.sin_cos_beta);
        let (xi, zeta) = (-normal.x.asin(), -normal.z.asin());
        let (s, c) = self.sin_cos_beta;
        SeenWall {
            gamma: c * xi - s * zeta,
            gamma_star: s * xi + c * zeta,
            xi,
            zeta,
            normal,
        }
    }
}

/// A rebound off the `calibrated` model with the table `table`, for a particle moving
/// towards the wall `wall` (the trivial cases ruled out by the caller) whose direction is
/// `inc`: the paper's virtual walls (Eqs. 26, 29–33, for the current direction, in the wall's
/// slopes: `super::slope_space`; the element's law corrected by the calibrated weight), the
/// collision law, and then the particle leaves with the calibrated probability
/// `P(escape | stage, tan α/σ(β), tan α⁺/σ(β⁺))` of the table — or it is trapped and meets
/// the wall again *with its rebound velocity* (rising or not: the shadow law continued to
/// `α > 0`, [`ShadowSampler::rising`]). A later collision's stage remembers the element just
/// left ([`Stage::later`]: its slope seen from the new direction), because a trapped particle
/// meets the other side of the valley it is in. Radenkovic & Simonin 2021 instead reject the
/// trapped rebound and redraw for the same incident particle (Eq. 34, Fig. 13), which makes
/// every multiple-collision history end like a single collision. Every collision is reported
/// to `observe` as accepted (each is an impact).
pub fn rebound<R: Rng + ?Sized>(
    inc: &CalibratedIncidence,
    table: &EscapeTable,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    contact: &Contact,
    rng: &mut R,
    observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    let wall = contact.wall;
    let hits = Hits {
        law: contact.law,
        diameter_m: contact.diameter_m,
        rising: true,
    };
    hits.follow(
        *inc,
        u_in,
        omega_in,
        rng,
        observe,
        |alpha, beta| CalibratedIncidence::new(alpha, beta, wall),
        // Per hit, once: its stage (for a later hit, by the slope of the element just
        // left, seen from the new direction: the valley's memory), where the element
        // table is read at its reduced incidence (rows and bound, once per hit), and the
        // transverse residual of the element just left (0 for the first hit: unused).
        |cur, left, rng| {
            let (stage, z_prev) = match left {
                None => (table.first_stage(cur.moments.delta_gamma(), rng.gen()), 0.0),
                Some(n) => {
                    let (q, z_prev) = memory_of(&cur.moments, n, cur.beta);
                    (Stage::later(q), z_prev)
                }
            };
            (stage, table.element_read(stage, cur.x_in), z_prev)
        },
        |cur, state, rng| cur.draw_wall_corrected(table, state, rng),
        |cur, &(stage, _, _), u_out, rng| {
            u_out.y > 0.0 && {
                let p = table.p_escape(stage, cur.x_in, reduced_slope(u_out, &cur.slopes));
                p >= 1.0 || rng.gen::<f64>() < p
            }
        },
    )
}
