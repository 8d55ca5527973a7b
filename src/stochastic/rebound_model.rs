//! One rebound from the statistical anisotropic rough wall: the stochastic procedure of
//! Radenkovic & Simonin 2021, Sec. 3.6 and Fig. 13 (written out in the physics notes §3).
//!
//! This is the library entry point a CFD (Euler–Lagrange) code calls once per wall
//! collision: it needs only the incident state, the wall's two deviations, the
//! collision law and a random generator — no surface, no tables.

use super::escape_table::{ElementRead, EscapeTable, Stage};
use super::shadow_effect::ShadowSampler;
use super::slope_space::{
    normal_from_slopes, proposal, reduced_slope, slope_deviations, slopes_from_normal, PROPOSAL_EPS,
};
use super::variants::{Variant, VariantKind};
use crate::angles::{
    gamma_from_normal, incident_angles, normal_from_xi_zeta, xi_zeta_of_normal, xi_zeta_rotated,
};
use crate::collision::CollisionLaw;
use crate::wall::{
    conditional_gamma_star, delta_gamma_sq_of_direction, draw_gamma_star, rotated_moments,
    Deviations, Moments,
};
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::StandardNormal;

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
    /// Fluctuations `ξ' = ξ − π/2`, `ζ' = ζ − π/2` of the normal's angles (rad, Eq. 23).
    pub xi: f64,
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
}

/// The residual of the transverse slope of the wall element of unit normal `n` seen from
/// direction `β` on the wall of slope spreads `slopes` ([`slope_deviations`]): `s_t` less
/// its conditional mean given `s_l` (Eq. 30 in slopes), over its conditional spread — the
/// standard normal the `calibrated` model draws it from. The calibrated model's later
/// collisions remember it ([`super::transverse_memory`]); `rebound calibrate` counts it the
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

/// Step 1 of the procedure and the shadow-effect sampler: everything that depends only on
/// the incident *direction* `(α⁻, β⁻)` and the wall, not on the speed or the random draws.
/// A run of many particles with one direction builds it once ([`rebound_from`]).
#[derive(Clone, Copy, Debug)]
pub struct Incidence {
    /// `α⁻`, `β⁻` (rad).
    pub alpha: f64,
    pub beta: f64,
    /// `(sin β⁻, cos β⁻)`, for Eq. (23).
    sin_cos_beta: (f64, f64),
    /// `Δγ², Δγ*², Cov(γ, γ*)` at `β⁻` (Eq. 26); for `calibrated`, the same moments of the
    /// slopes ([`super::slope_space`]).
    moments: Moments,
    /// `P_eff(γ | α⁻)` (Eqs. 31–33) with `Δγ(β⁻)` of Eq. (26) — or, for the isotropic
    /// variants, with their one roughness angle; for `calibrated`, the law at a vanishing
    /// roughness ([`super::slope_space::PROPOSAL_EPS`]) at the reduced incidence.
    sampler: ShadowSampler,
    /// The rough-wall model drawing the walls ([`super::variants`]).
    variant: Variant,
    /// The isotropic variants' roughness angle `Δγ` (rad).
    delta_gamma_iso: f64,
    /// The reduced incidence `tan α⁻/σ(β⁻)` of the calibrated model's tables
    /// ([`reduced_slope`]), once per direction rather than once per particle.
    x_in: f64,
    /// The calibrated model's slope spreads of the wall ([`slope_deviations`]; the wall's
    /// deviations for the other models).
    slopes: Deviations,
}

impl Incidence {
    /// The direction `(α⁻, β⁻)` (rad) on `wall`.
    pub fn new(alpha: f64, beta: f64, wall: &Deviations) -> Incidence {
        Incidence::with_variant(alpha, beta, wall, Variant::PAPER)
    }

    /// The direction `(α⁻, β⁻)` (rad) on `wall`, walls drawn by `variant`.
    pub fn with_variant(alpha: f64, beta: f64, wall: &Deviations, variant: Variant) -> Incidence {
        let delta_gamma_iso = variant.delta_gamma_on(wall);
        // `calibrated` works in slopes ([`super::slope_space`]): its moments are the
        // slopes', its proposal the shadow law in `tan α/σ(β)`, and its reduced incidence that.
        let calibrated = variant.kind == VariantKind::Calibrated;
        let slopes = if calibrated {
            slope_deviations(wall)
        } else {
            *wall
        };
        let moments = rotated_moments(&slopes, beta);
        let x_in = if calibrated {
            alpha.tan() / moments.delta_gamma()
        } else {
            alpha / moments.delta_gamma()
        };
        // A rising particle meets the wall only in the calibrated model's later collisions.
        let sampler = if calibrated {
            proposal(x_in)
        } else {
            let delta_gamma = if variant.kind.anisotropic() {
                moments.delta_gamma()
            } else {
                delta_gamma_iso
            };
            if alpha > 0.0 {
                ShadowSampler::rising(alpha, delta_gamma)
            } else {
                ShadowSampler::new(alpha, delta_gamma)
            }
        };
        Incidence {
            alpha,
            beta,
            sin_cos_beta: beta.sin_cos(),
            x_in,
            slopes,
            moments,
            sampler,
            variant,
            delta_gamma_iso,
        }
    }

    /// The variant drawing the walls.
    pub fn variant(&self) -> Variant {
        self.variant
    }

    /// The direction of the velocity `u_in` (physics notes §1) on `wall`.
    pub fn of_velocity(u_in: &Vector3<f64>, wall: &Deviations) -> Incidence {
        let (alpha, beta) = incident_angles(u_in);
        Incidence::new(alpha, beta, wall)
    }

    /// Steps 2–4 up to the normal: a wall element seen by this direction, `γ` from
    /// `P_eff(γ | α⁻)`, `γ*` given `γ` from Eq. (30), the unit normal of Eq. (23).
    #[inline]
    fn draw_wall<R: Rng + ?Sized>(&self, rng: &mut R) -> SeenWall {
        let gamma = self.sampler.sample(rng);
        self.wall_given_gamma(gamma, rng)
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
    fn draw_wall_corrected<R: Rng + ?Sized>(
        &self,
        table: &EscapeTable,
        &(stage, read, z_prev): &(Stage, ElementRead, f64),
        rng: &mut R,
    ) -> SeenWall {
        let mut g = self.sampler.sample(rng) / PROPOSAL_EPS;
        // The bound makes ~1–2 proposals typical; the cap only guards a degenerate table.
        for _ in 0..1000 {
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

    /// Steps 3–4 for a drawn `γ`: `γ*` from Eq. (30) as published, the normal of Eq. (23)
    /// (`calibrated` draws its own γ*: [`Self::draw_wall_corrected`]).
    #[inline]
    fn wall_given_gamma<R: Rng + ?Sized>(&self, gamma: f64, rng: &mut R) -> SeenWall {
        let gamma_star = draw_gamma_star(&self.moments, gamma, || rng.sample(StandardNormal));
        self.wall_of_gammas(gamma, gamma_star)
    }

    /// A wall element of inclinations `(γ, γ*)` in the incident frame (Eq. 23).
    #[inline]
    fn wall_of_gammas(&self, gamma: f64, gamma_star: f64) -> SeenWall {
        let (xi, zeta) = xi_zeta_rotated(gamma, gamma_star, self.sin_cos_beta);
        SeenWall {
            gamma,
            gamma_star,
            xi,
            zeta,
            normal: normal_from_xi_zeta(xi, zeta),
        }
    }

    /// A wall element of unit normal `n`, with its angles.
    #[inline]
    fn wall_of_normal(&self, normal: Vector3<f64>) -> SeenWall {
        let (xi, zeta) = xi_zeta_of_normal(&normal);
        let (gamma, gamma_star) = gamma_from_normal(&normal, self.beta);
        SeenWall {
            gamma,
            gamma_star,
            xi,
            zeta,
            normal,
        }
    }

    /// A wall element drawn by one of the simpler variants ([`super::variants`]).
    /// `t` is the horizontal incident direction `(cos β⁻, 0, −sin β⁻)` and `γ > 0` tilts
    /// the element towards the particle (local impact angle `|α⁻| + γ`).
    fn draw_variant<R: Rng + ?Sized>(&self, rng: &mut R) -> SeenWall {
        let dg = self.delta_gamma_iso;
        let (sb, cb) = self.sin_cos_beta;
        let t = Vector3::new(cb, 0.0, -sb);
        let j = Vector3::new(0.0, 1.0, 0.0);
        match self.variant.kind {
            VariantKind::RadenkovicSimonin2021 => self.draw_wall(rng),
            // `calibrated`'s proposal, without its table's correction (the model itself
            // reads the table: `draw_wall_corrected`).
            VariantKind::Calibrated => {
                let g = self.sampler.sample(rng) / PROPOSAL_EPS;
                let s_l = g * self.moments.delta_gamma();
                let s_t = draw_gamma_star(&self.moments, s_l, || rng.sample(StandardNormal));
                self.wall_of_slopes(s_l, s_t)
            }
            // Sommerfeld & Huber 1999: the shadow law in the incident plane, an independent
            // normal law across it, one Δγ for both (isotropic).
            VariantKind::SommerfeldHuber1999 => {
                let gamma = self.sampler.sample(rng);
                let z: f64 = rng.sample(StandardNormal);
                self.wall_of_gammas(gamma, dg * z)
            }
            // `α₁ = max(α + Δγ N(0,1), 0)`: the element tilted in the incident plane by
            // `α₁ − α`, never beyond the incident direction.
            VariantKind::GaussianAngle => {
                let z: f64 = rng.sample(StandardNormal);
                self.wall_of_gammas((dg * z).max(self.alpha), 0.0)
            }
            // LIGGGHTS-PFM: a half-normal tilt δ about an azimuth ψ ∈ [0, π) measured from
            // n₂ = n × n₁, n₁ opposite the tangential velocity: the element always leans
            // towards the particle.
            VariantKind::GaussianTilt => {
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
            VariantKind::NormalPerturbation => {
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

/// The outcome of [`rebound`].
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
    fn off(
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

/// One rebound of a particle from the statistical anisotropic rough wall
/// (Radenkovic & Simonin 2021, Sec. 3.6, Fig. 13; physics notes §3 steps 1–7).
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

/// [`rebound`] with the virtual walls drawn by `variant` ([`super::variants`]); the
/// paper's variant is [`rebound`] exactly.
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
    if let Some(done) = trivial(u_in, omega_in, wall, law, psi, diameter_m) {
        return done;
    }
    // The trivial cases are ruled out once, here: they also keep an incidence from being
    // built for a particle that does not move towards the wall.
    let (alpha, beta) = incident_angles(&u_in);
    let inc = Incidence::with_variant(alpha, beta, wall, variant);
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

/// The rebounds that need no random draw: a particle not moving towards the wall (or a
/// non-finite input) is returned unchanged with `tries = 0`; a smooth wall (or a `psi` that
/// can accept nothing) gives the collision with the mean wall.
fn trivial(
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
) -> Option<Rebound> {
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
    let smooth_wall = wall.delta_xi == 0.0 && wall.delta_zeta == 0.0;
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

/// [`rebound`] for an incident velocity whose direction's [`Incidence`] is given (built
/// once for many particles of one direction); steps 2–7 of the procedure. `inc` must be
/// the incidence of `u_in`'s direction on `wall`.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn rebound_from<R: Rng + ?Sized>(
    inc: &Incidence,
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

/// The simpler variants ([`super::variants`]): a wall element is drawn for the incident
/// velocity (redrawn while the particle cannot reach it, `U·n ≥ 0`), the collision law is
/// applied, and a rebound that does not leave the mean wall (`v⁺ ≤ 0`) hits the wall again:
/// a new element is drawn for the new velocity. `candidates` counts the collisions. Every
/// collision is reported to `observe` as accepted (each is a real impact).
#[allow(clippy::too_many_arguments)]
fn rebound_repeated<R: Rng + ?Sized>(
    inc: &Incidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    diameter_m: f64,
    rng: &mut R,
    observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    // A rising particle never meets the wall again in these models.
    Hits::new(inc, wall, law, diameter_m, false).follow(
        u_in,
        omega_in,
        rng,
        observe,
        |_, _, _| (),
        |cur, _, rng| cur.draw_variant(rng),
        |_, _, u_out, _| u_out.y > 0.0,
    )
}

/// The `calibrated` model: the paper's virtual walls (Eqs. 26, 29–33, for the current
/// direction, in the wall's slopes: [`super::slope_space`]; the element's law corrected by the
/// calibrated weight), the collision law, and then the particle leaves with the calibrated
/// probability `P(escape | stage, tan α/σ(β), tan α⁺/σ(β⁺))` of [`super::escape_table`] — or
/// it is trapped and meets the wall again *with
/// its rebound velocity* (rising or not: the shadow law continued to `α > 0`,
/// [`ShadowSampler::rising`]). A later collision's stage remembers the element just left
/// ([`Stage::later`]: its slope seen from the new direction), because a trapped
/// particle meets the other side of the valley it is in. Radenkovic & Simonin 2021 instead
/// reject the trapped rebound and redraw for the same incident particle (Eq. 34, Fig. 13),
/// which makes every multiple-collision history end like a single collision. Every collision is reported to
/// `observe` as accepted (each is an impact).
#[allow(clippy::too_many_arguments)]
fn rebound_calibrated<R: Rng + ?Sized>(
    inc: &Incidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    diameter_m: f64,
    rng: &mut R,
    observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    let table = inc.variant.escape_table();
    Hits::new(inc, wall, law, diameter_m, true).follow(
        u_in,
        omega_in,
        rng,
        observe,
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

/// The models that follow a particle from hit to hit until it leaves the wall.
struct Hits<'a> {
    inc: &'a Incidence,
    wall: &'a Deviations,
    law: &'a CollisionLaw,
    diameter_m: f64,
    /// Whether a trapped particle may meet the wall while rising (`α > 0`).
    rising: bool,
}

impl<'a> Hits<'a> {
    fn new(
        inc: &'a Incidence,
        wall: &'a Deviations,
        law: &'a CollisionLaw,
        diameter_m: f64,
        rising: bool,
    ) -> Self {
        Hits {
            inc,
            wall,
            law,
            diameter_m,
            rising,
        }
    }

    /// Hit `k = 0, 1, …` with velocity `u` and its incidence: `at_hit(incidence, the normal
    /// of the element just left (None for the first hit), rng)` once,
    /// then `draw(incidence, state, rng)` an element the particle can reach (redrawn while
    /// `U·n ≥ 0`), the collision law, then `leaves(incidence, state, u⁺, rng)` or the next
    /// hit with `u⁺` from its own incidence; the mean wall after [`MAX_TRIES`].
    #[allow(clippy::too_many_arguments)]
    fn follow<R: Rng + ?Sized, S>(
        &self,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        rng: &mut R,
        mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
        mut at_hit: impl FnMut(&Incidence, Option<&Vector3<f64>>, &mut R) -> S,
        mut draw: impl FnMut(&Incidence, &S, &mut R) -> SeenWall,
        mut leaves: impl FnMut(&Incidence, &S, &Vector3<f64>, &mut R) -> bool,
    ) -> Rebound {
        let (mut u, mut w) = (u_in, omega_in);
        let mut cur = *self.inc;
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
            // hair so that the incidence is defined.
            let alpha = if self.rising {
                alpha
            } else {
                alpha.min(-1e-12)
            };
            cur = Incidence::with_variant(alpha, beta, self.wall, self.inc.variant);
            state = at_hit(&cur, Some(&seen.normal), rng);
        }
        guard_rebound(u, w, self.law, self.diameter_m, candidates, first, observe)
    }
}

/// After [`MAX_TRIES`] candidate walls: the collision with the mean (smooth) wall `j`.
fn guard_rebound(
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

/// [`rebound_from`] reporting every candidate rebound to `observe`: the normal of the
/// virtual wall hit and whether the rebound was accepted (the last call) or rejected as a
/// multiple collision (Fig. 13, step 6). The smooth-wall fallback and the trivial cases
/// with a collision report the mean wall `j` as accepted.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn rebound_from_observed<R: Rng + ?Sized>(
    inc: &Incidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    rng: &mut R,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    if let Some(done) = trivial(u_in, omega_in, wall, law, psi, diameter_m) {
        if done.candidates > 0 {
            observe(&u_in, &done.normal, true);
        }
        return done;
    }
    rebound_drawn(
        inc, u_in, omega_in, wall, law, psi, diameter_m, rng, observe,
    )
}

/// [`rebound_from_observed`] once the trivial cases are ruled out: candidate walls drawn
/// until one is accepted (steps 2–7), or the simpler variants' repeated hits.
#[allow(clippy::too_many_arguments)]
#[inline]
fn rebound_drawn<R: Rng + ?Sized>(
    inc: &Incidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    psi: f64,
    diameter_m: f64,
    rng: &mut R,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    match inc.variant.kind {
        VariantKind::RadenkovicSimonin2021 => {}
        VariantKind::Calibrated => {
            return rebound_calibrated(inc, u_in, omega_in, wall, law, diameter_m, rng, observe)
        }
        _ => return rebound_repeated(inc, u_in, omega_in, wall, law, diameter_m, rng, observe),
    }
    let mut candidates = 0u32;
    let mut first = SeenWall::FLAT;
    for tries in 1..=MAX_TRIES {
        // Steps 2–4.
        let seen = inc.draw_wall(rng);
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

    #[test]
    fn the_element_correction_samples_the_weighted_law() {
        // A table whose weight is 3 above γ = 0 and 1 below, at the direction's x_in: the
        // corrected draws must follow 3·P_eff above 0 and P_eff below (renormalised).
        use crate::stochastic::escape_table::{EscapeCounts, EscapeTable, ELEMENT_MIN_COUNT};
        let wall = Deviations {
            delta_xi: 0.05,
            delta_zeta: 0.05,
        };
        // x_in = tan α/σ = −1.125, a row's centre (where `at_centres` puts the row's values).
        let beta = 0.0;
        let sigma = crate::stochastic::slope_space::slope_deviations(&wall).delta_xi;
        let alpha = (-1.125 * sigma).atan();
        let inc = Incidence::with_variant(alpha, beta, &wall, Variant::calibrated(None));
        let x_in = -1.125;
        assert!((inc.x_in - x_in).abs() < 1e-12, "{}", inc.x_in);
        let mut c = EscapeCounts::default();
        let mut probe = EscapeCounts::default();
        for k in 0..100 {
            // Cell centres in s = g − x_in (the reachable elements, s > 0).
            let g = x_in + 0.08 * k as f64 + 0.04;
            probe.push_element(Stage::FIRST, x_in, g, g);
            let Some(cell) = probe.element_model.iter().position(|&n| n > 0) else {
                continue;
            };
            probe.element_model[cell] = 0;
            c.element_model[cell] = ELEMENT_MIN_COUNT;
            c.element_deterministic[cell] = if g > 0.0 { 3 } else { 1 } * ELEMENT_MIN_COUNT;
        }
        let table = EscapeTable::from_counts(c.at_centres(), "w");
        let state = (
            Stage::FIRST,
            table.element_read(Stage::FIRST, inc.x_in),
            0.0,
        );
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(5);
        let n = 200_000;
        let plain = (0..n)
            .filter(|_| inc.draw_variant(&mut rng).gamma > 0.0)
            .count() as f64
            / n as f64;
        let corrected = (0..n)
            .filter(|_| inc.draw_wall_corrected(&table, &state, &mut rng).gamma > 0.0)
            .count() as f64
            / n as f64;
        // Bilinear reading smooths the step over one bin on either side of 0 (±0.08 Δγ).
        let want = 3.0 * plain / (3.0 * plain + (1.0 - plain));
        assert!(
            (corrected - want).abs() < 0.01,
            "{corrected} vs {want} (plain {plain})"
        );
    }

    #[test]
    fn the_calibrated_incidence_is_the_reduced_slope_of_its_velocity() {
        // x_in of an incidence (from its angles) and of a velocity (`reduced_slope`, what the
        // calibration and the escape decision read) agree in every quadrant, rising or not.
        let wall = Deviations {
            delta_xi: 0.04,
            delta_zeta: 0.12,
        };
        let slopes = slope_deviations(&wall);
        for a in [-80.0f64, -2.0, 3.0, 60.0] {
            for b in [-150.0f64, -30.0, 0.0, 40.0, 120.0] {
                let (alpha, beta) = (a.to_radians(), b.to_radians());
                let inc = Incidence::with_variant(alpha, beta, &wall, Variant::calibrated(None));
                let u = crate::angles::velocity_from_angles(1.5, alpha, beta);
                let x = reduced_slope(&u, &slopes);
                assert!((x - inc.x_in).abs() < 1e-12 * x.abs().max(1.0), "{a} {b}");
                assert_eq!(x > 0.0, a > 0.0);
            }
        }
    }

    #[test]
    fn calibrated_rebounds_off_a_wall_without_slope_along_the_path() {
        // 2-D roughness seen along its lay (σ(β) = 0, x_in infinite): finite rebounds, the
        // transverse roughness deflecting them, no NaN.
        let wall = Deviations {
            delta_xi: 0.0,
            delta_zeta: 0.1,
        };
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(9);
        let u = crate::angles::velocity_from_angles(1.0, -0.2, 0.0);
        let law = CollisionLaw::Elastic;
        let mut deflected = 0;
        for _ in 0..2000 {
            let r = rebound_variant(
                u,
                Vector3::zeros(),
                &wall,
                &law,
                2.0,
                1e-4,
                Variant::calibrated(None),
                &mut rng,
            );
            assert!(r.velocity.iter().all(|v| v.is_finite()) && r.velocity.y > 0.0);
            assert!((r.velocity.norm() - 1.0).abs() < 1e-12);
            deflected += (r.velocity.z.abs() > 1e-3) as u32;
        }
        assert!(deflected > 1000, "{deflected}");
    }

    #[test]
    fn a_trapped_particle_meets_steeper_elements_after_a_downslope() {
        // The built-in table's memory (escape_table::Q_EDGES): on the deterministic surface a
        // particle that has just left a steep downslope (q ≈ −2) meets the valley's other
        // side, steeper than after an upslope (q ≥ 0.25), at the same incidence.
        let wall = Deviations {
            delta_xi: 0.05,
            delta_zeta: 0.05,
        };
        let inc = Incidence::with_variant(-0.0125, 0.0, &wall, Variant::calibrated(None));
        let table = EscapeTable::builtin();
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(9);
        let mut mean = |stage: Stage| {
            let state = (stage, table.element_read(stage, inc.x_in), 0.0);
            let n = 100_000;
            (0..n)
                .map(|_| inc.draw_wall_corrected(table, &state, &mut rng).gamma / 0.05)
                .sum::<f64>()
                / n as f64
        };
        let (down, up) = (mean(Stage::later(-2.0)), mean(Stage::later(0.5)));
        assert!(
            down - up > 0.15,
            "after a downslope {down}, after an upslope {up}"
        );
    }
}
