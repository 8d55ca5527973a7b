//! The stochastic wall model as a CFD code calls it, once per particle–wall hit
//! (Radenkovic & Simonin 2021, Sec. 5: the model "can be used in Euler–Lagrange
//! simulations"): in the host's global axes and SI units, with a face normal of either
//! orientation, the wall's lay direction, a moving wall, and a random stream keyed by
//! `(seed, particle id, collision index)`, so that the same hit gives the same rebound on
//! any number of MPI ranks, threads or domain decompositions.
//!
//! The physics is [`crate::stochastic::rebound`] (the procedure of Fig. 13, docs/physics.md
//! §3) in the wall's own frame: `y` along the normal into the flow, `x` along the lay
//! direction (the principal roughness direction of `Δξ`), `z = x × y`. The C library
//! (`crate::ffi`) is a thin layer over [`WallModel::rebound`].

use crate::collision::{CollisionLaw, CollisionParams};
use crate::error::{Error, Result};
use crate::models::{rebound_with, AnyModel, ModelParams, RoughWallModel};
use crate::parameters::{ParameterKind, WALL_PARAMETERS};
use crate::rng;
use crate::stochastic::{checked_psi, Contact, PSI_PAPER};
use crate::wall::{checked_deviation, Deviations};
use nalgebra::Vector3;

/// What a wall handle is built from; the collision law uses the keys (and ranges) of a
/// case file's `[collision]` section.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WallParams {
    /// `Δξ` (degrees): standard deviation of the wall normal's angle along the lay direction
    /// (Radenkovic & Simonin 2021, Eq. 15; 0 … 20; beyond 7.5 a warning).
    pub delta_xi_deg: f64,
    /// `Δζ` (degrees): standard deviation of the wall normal's angle across the lay direction
    /// (Radenkovic & Simonin 2021, Eq. 15; 0 … 20, 0 for 2-D roughness; beyond 7.5 a warning).
    pub delta_zeta_deg: f64,
    /// `[collision]`: `model` (`"elastic"`, `"sommerfeld-huber"`), `preset`, parameters.
    pub collision: CollisionParams,
    /// ψ of Eq. (34) (in [0.01, 100],
    /// [`PSI_RANGE`](crate::stochastic::PSI_RANGE); the paper's 2 when `None`).
    pub psi: Option<f64>,
    /// Seed of every hit's random stream.
    pub seed: u64,
    /// The rough-wall model by its case-file name (`[stochastic] model`; the paper's when
    /// `None`).
    pub model: Option<String>,
    /// The isotropic variants' roughness angle `Δγ` (degrees; `(Δξ + Δζ)/2` when `None`).
    pub delta_gamma_deg: Option<f64>,
    /// The escape table of `model = "calibrated"`, as the text `rebound calibrate` writes
    /// (`None`: the built-in table). The handle keeps its own copy: no file is read at run
    /// time.
    pub escape_table: Option<String>,
    /// The table of `model = "measured-wall"`, as the text `rebound scan --measured-wall`
    /// writes. The handle keeps its own copy.
    pub wall_table: Option<String>,
}

impl WallParams {
    /// The value of the numeric parameter `case_key` of [`WALL_PARAMETERS`] (`Some(None)`:
    /// not given), `None` for a key that is not a number of this struct.
    fn number(&self, case_key: &str) -> Option<Option<f64>> {
        let c = &self.collision;
        Some(match case_key {
            "wall.delta_xi_deg" => Some(self.delta_xi_deg),
            "wall.delta_zeta_deg" => Some(self.delta_zeta_deg),
            "collision.e_h" => c.e_h,
            "collision.alpha_e_deg" => c.alpha_e_deg,
            "collision.mu_0" => c.mu_0,
            "collision.mu_h" => c.mu_h,
            "collision.alpha_mu_deg" => c.alpha_mu_deg,
            "stochastic.psi" => self.psi,
            "stochastic.delta_gamma_deg" => self.delta_gamma_deg,
            _ => return None,
        })
    }

    /// The numeric parameters of [`WALL_PARAMETERS`] with their values, in the order of their
    /// keys' names (the order a case file's are checked in).
    pub fn numbers(&self) -> Vec<(&'static str, Option<f64>)> {
        let mut numbers: Vec<(&'static str, Option<f64>)> = WALL_PARAMETERS
            .iter()
            .filter(|q| q.kind == ParameterKind::Number)
            .filter_map(|q| Some((q.case_key, self.number(q.case_key)?)))
            .collect();
        numbers.sort_by_key(|n| n.0);
        numbers
    }
}

/// A wall: immutable once built, so one handle serves every thread.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallModel {
    /// Normal-angle deviations `(Δξ, Δζ)` of the wall (radians), checked.
    pub wall: Deviations,
    /// The collision law applied in the frame of each virtual wall element.
    pub law: CollisionLaw,
    /// `ψ` of the single-collision probability `tanh(ψ α⁺/Δγ(β⁺))` (Radenkovic & Simonin
    /// 2021, Eq. 34), checked against [`PSI_RANGE`](crate::stochastic::PSI_RANGE).
    pub psi: f64,
    /// Seed of every hit's random stream, keyed further by the hit's particle id and
    /// collision index.
    pub seed: u64,
    /// The rough-wall model drawing the virtual walls.
    pub model: AnyModel,
}

impl WallModel {
    /// Validates the parameters with the case-file rules and one-line messages (keys named
    /// as in a case file: `wall.delta_xi_deg`, `collision.e_h`, `stochastic.psi`, …), through
    /// the same checks `rebound` applies to a case file, so the same bad value gives the same
    /// message: first every number must be finite (in the order of the keys' names, as a
    /// case file's are checked), then [`checked_deviation`], [`CollisionParams::law`],
    /// [`checked_psi`] and [`AnyModel::named`]. Returns the handle and the warnings (e.g. a
    /// deviation beyond the low-roughness range).
    pub fn new(p: &WallParams) -> Result<(WallModel, Vec<String>)> {
        let c = &p.collision;
        for (key, v) in p.numbers() {
            if let Some(v) = v.filter(|v| !v.is_finite()) {
                return Err(Error::invalid(key, v, "a finite number"));
            }
        }
        let mut warnings = Vec::new();
        let wall = Deviations {
            delta_xi: checked_deviation("wall.delta_xi_deg", p.delta_xi_deg, &mut warnings)?,
            delta_zeta: checked_deviation("wall.delta_zeta_deg", p.delta_zeta_deg, &mut warnings)?,
        };
        let law = c.law()?;
        let psi = checked_psi(p.psi.unwrap_or(PSI_PAPER))?;
        // The escape table is given as text: parsed only once the model has taken the key.
        let read_table = || {
            let text = p.escape_table.as_deref().unwrap_or_default();
            crate::calibrated::EscapeTable::parse(text, "`stochastic.escape_table`")?.intern()
        };
        let read_wall_table = || {
            let text = p.wall_table.as_deref().unwrap_or_default();
            crate::measured_wall::MeasuredWallTable::parse(text, "`stochastic.wall_table`")?
                .intern()
        };
        let params = ModelParams {
            delta_gamma_deg: p.delta_gamma_deg,
            escape_table: p
                .escape_table
                .as_ref()
                .map(|_| &read_table as &dyn Fn() -> Result<_>),
            wall_table: p
                .wall_table
                .as_ref()
                .map(|_| &read_wall_table as &dyn Fn() -> Result<_>),
        };
        let model = AnyModel::named(p.model.as_deref(), &params)?;
        let built = WallModel {
            // A model measured on a wall rebounds off that wall, whatever deviations are given.
            wall: model.wall(&wall),
            law,
            psi,
            seed: p.seed,
            model,
        };
        Ok((built, warnings.into_iter().map(|w| w.0).collect()))
    }

    /// The rebound of one hit (see [`Hit`]); never NaN: an input it cannot use is returned
    /// unchanged with [`HitStatus::InvalidInput`] (non-finite components as 0), a particle that
    /// does not move across the wall with [`HitStatus::NotApproaching`].
    pub fn rebound(&self, hit: &Hit) -> HitOutcome {
        let unchanged = |status| HitOutcome::unchanged(hit, status);
        let finite = [
            hit.velocity,
            hit.spin,
            hit.normal,
            hit.lay,
            hit.wall_velocity,
        ]
        .iter()
        .flatten()
        .chain(std::iter::once(&hit.diameter_m))
        .all(|x| x.is_finite());
        if !finite || hit.diameter_m < 0.0 {
            return unchanged(HitStatus::InvalidInput);
        }
        let Some(frame) = Frame::new(hit) else {
            return unchanged(HitStatus::InvalidInput);
        };
        // The rebound is homogeneous of degree one in (velocity, spin): a velocity whose
        // squares would over- or underflow is brought near 1 by a power of two (exact) and the
        // rebound scaled back. Within range nothing is scaled: the same bits as ever.
        let u_host = Vector3::from(hit.velocity) - Vector3::from(hit.wall_velocity);
        let k = taming_exponent(&u_host);
        let (u_rel, spin_in) = (
            scale_pow2(u_host, -k),
            scale_pow2(Vector3::from(hit.spin), -k),
        );
        let u = frame.to_local(&u_rel);
        if u.y == 0.0 {
            return unchanged(HitStatus::NotApproaching);
        }
        // The elastic law leaves the spin alone: it is returned as given, not rotated into
        // the wall's frame and back (which would change its last bits).
        let elastic = matches!(self.law, CollisionLaw::Elastic);
        let spin_back = |w: Vector3<f64>| {
            if elastic {
                Vector3::from(hit.spin)
            } else {
                scale_pow2(w, k)
            }
        };
        if self.wall.is_smooth() {
            // A smooth wall: the collision with the mean wall, as `stochastic::rebound` gives
            // it (no random draw, one candidate wall), but computed in the host's axes rather
            // than through the wall's frame and back. For the elastic law that is
            // `u − (2 (u·n)) n` with the dot product summed x, y, z: the operations, in the
            // same order, of a CFD code's own specular rebound (code_saturne's
            // CS_LAGR_REBOUND), so a smooth elastic roughwall wall gives its host's
            // trajectories bit for bit (examples/code_saturne, check (a)).
            let (v, w) = self.law.collide(u_rel, spin_in, frame.ey, hit.diameter_m);
            return Self::outcome(hit, scale_pow2(v, k), spin_back(w), 0.0, 0.0, 1);
        }
        let w = frame.to_local(&spin_in);
        let mut r = rng::stream(
            self.seed,
            &[rng::domain::WALL_HITS, hit.particle_id, hit.collision_index],
        );
        let contact = Contact {
            wall: &self.wall,
            law: &self.law,
            psi: self.psi,
            diameter_m: hit.diameter_m,
        };
        let out = rebound_with(&self.model, u, w, &contact, &mut r);
        Self::outcome(
            hit,
            scale_pow2(frame.to_global(&out.velocity), k),
            spin_back(frame.to_global(&out.spin)),
            out.gamma,
            out.gamma_star,
            out.tries,
        )
    }

    /// The outcome of a rebound computed relative to the wall (global axes): the wall's
    /// velocity added back, and no NaN or infinity to the host.
    fn outcome(
        hit: &Hit,
        velocity_rel: Vector3<f64>,
        spin: Vector3<f64>,
        gamma: f64,
        gamma_star: f64,
        candidate_walls: u32,
    ) -> HitOutcome {
        let velocity = velocity_rel + Vector3::from(hit.wall_velocity);
        if !velocity.iter().chain(spin.iter()).all(|x| x.is_finite()) {
            // Overflow of extreme inputs (e.g. |u| near f64::MAX): no NaN reaches the host.
            return HitOutcome::unchanged(hit, HitStatus::InvalidInput);
        }
        HitOutcome {
            velocity: velocity.into(),
            spin: spin.into(),
            status: HitStatus::Rebound,
            gamma,
            gamma_star,
            candidate_walls,
        }
    }
}

/// One particle–wall hit in the host's global axes, SI units.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Hit {
    /// Particle velocity before the hit (m/s, global axes; not relative to the wall).
    pub velocity: [f64; 3],
    /// Particle angular velocity before the hit (rad/s, global axes).
    pub spin: [f64; 3],
    /// Face normal, either orientation, any non-zero length: it is oriented against the
    /// particle's velocity relative to the wall.
    pub normal: [f64; 3],
    /// The wall's lay direction, its principal roughness direction `x` (that of `Δξ`):
    /// projected onto the wall plane; parallel to the normal is an invalid input.
    pub lay: [f64; 3],
    /// Velocity of the wall (m/s): the bounce is computed in the wall's frame.
    pub wall_velocity: [f64; 3],
    /// Particle diameter (m, ≥ 0; enters the Sommerfeld–Huber spin terms).
    pub diameter_m: f64,
    /// The key of the hit's random stream: the same key, the same rebound. This part is the
    /// particle's identifier (unique, and the same on every rank).
    pub particle_id: u64,
    /// The second part of the key: the index of this hit among the particle's wall hits, so
    /// that two hits of one particle draw different walls.
    pub collision_index: u64,
}

/// What became of a hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(i32)]
pub enum HitStatus {
    /// A rebound was computed.
    Rebound = 0,
    /// The particle does not move across the wall (velocity relative to the wall parallel
    /// to it, or zero): returned unchanged.
    NotApproaching = 1,
    /// A non-finite number, a zero normal, a lay direction parallel to the normal or a
    /// negative diameter: returned unchanged.
    InvalidInput = 2,
}

/// The rebound of a hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HitOutcome {
    /// Rebound velocity (m/s, global axes, wall velocity added back); for an unchanged
    /// particle its incident velocity, non-finite components as 0.
    pub velocity: [f64; 3],
    /// Rebound angular velocity (rad/s, global axes); for an unchanged particle its incident
    /// spin, non-finite components as 0.
    pub spin: [f64; 3],
    /// Whether a rebound was computed, or why the particle was returned unchanged.
    pub status: HitStatus,
    /// Inclination `γ` (rad) of the virtual wall element that produced the rebound, in the
    /// incident plane (Radenkovic & Simonin 2021, Eq. 20; 0 for a smooth wall or an unchanged
    /// particle).
    pub gamma: f64,
    /// Inclination `γ*` (rad) of that element normal to the incident plane (Radenkovic &
    /// Simonin 2021, Eq. 21; 0 for a smooth wall or an unchanged particle).
    pub gamma_star: f64,
    /// Candidate walls drawn (≥ 1 for a rebound; `stochastic::MAX_TRIES` when the guard
    /// was hit and the mean wall used).
    pub candidate_walls: u32,
}

impl HitOutcome {
    /// The impact angle (rad, in `[0, π/2]`) of `hit`'s velocity relative to the wall on the
    /// wall element that produced this rebound: the facet the particle struck, whose angle
    /// the erosion laws take, rather than the mean wall's. From [`HitOutcome::gamma`],
    /// [`HitOutcome::gamma_star`] and the incident direction in the wall's frame
    /// ([`crate::erosion::ImpactAngle::on_element`]; Radenkovic & Simonin 2021, Eqs. 10,
    /// 20–23); on a smooth wall (`γ = γ* = 0`) the angle to the wall. 0 unless a rebound
    /// was computed.
    pub fn element_impact_angle(&self, hit: &Hit) -> f64 {
        if self.status != HitStatus::Rebound {
            return 0.0;
        }
        element_impact_angle(hit, self.gamma, self.gamma_star)
    }

    /// A particle not rebounded: it leaves as it came, a non-finite component as 0, so that
    /// no NaN or infinity reaches the host.
    fn unchanged(hit: &Hit, status: HitStatus) -> HitOutcome {
        let clean = |v: [f64; 3]| v.map(|x| if x.is_finite() { x } else { 0.0 });
        HitOutcome {
            velocity: clean(hit.velocity),
            spin: clean(hit.spin),
            status,
            gamma: 0.0,
            gamma_star: 0.0,
            candidate_walls: 0,
        }
    }
}

/// [`HitOutcome::element_impact_angle`] of the element `(γ, γ*)` (rad); 0 for a hit whose
/// frame or velocity cannot be used (the statuses other than a rebound).
pub fn element_impact_angle(hit: &Hit, gamma: f64, gamma_star: f64) -> f64 {
    let Some(frame) = Frame::new(hit) else {
        return 0.0;
    };
    let u_host = Vector3::from(hit.velocity) - Vector3::from(hit.wall_velocity);
    let u = frame.to_local(&scale_pow2(u_host, -taming_exponent(&u_host)));
    let speed = u.norm();
    if !(speed.is_finite() && gamma.is_finite() && gamma_star.is_finite()) {
        return 0.0;
    }
    crate::erosion::ImpactAngle::on_element(&u, speed, gamma, gamma_star).alpha
}

/// Components within `[2^-SAFE_EXPONENT, 2^SAFE_EXPONENT]` have squares and sums of three
/// squares that neither overflow nor underflow (`f64` spans about `2^±1022`).
const SAFE_EXPONENT: i32 = 400;

/// The exponent `k` of a power of two that brings the largest component of `v` into
/// `[1, 2)` when it lies outside `[2^-SAFE_EXPONENT, 2^SAFE_EXPONENT]`, else 0 (also for a
/// zero or non-finite vector).
fn taming_exponent(v: &Vector3<f64>) -> i32 {
    let m = v.amax();
    if m == 0.0 || !m.is_finite() {
        return 0;
    }
    // The binary exponent of m, from its bits (a subnormal counts as 2^-1023 or below).
    let e = ((m.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    let e = if e == -1023 {
        -1023 - (m.to_bits() & ((1u64 << 52) - 1)).leading_zeros() as i32 + 12
    } else {
        e
    };
    if e.abs() > SAFE_EXPONENT {
        e
    } else {
        0
    }
}

/// `v · 2^k`, exactly (two steps, so that `2^k` itself stays representable).
fn scale_pow2(v: Vector3<f64>, k: i32) -> Vector3<f64> {
    if k == 0 {
        return v;
    }
    let half = k / 2;
    let step = |e: i32| f64::from_bits(((e + 1023) as u64) << 52);
    v * step(half) * step(k - half)
}

/// The wall's frame at a hit: `e_y` the normal into the flow, `e_x` the lay direction in the
/// wall plane, `e_z = e_x × e_y` (right-handed, as the paper's `x, y, z`).
struct Frame {
    ex: Vector3<f64>,
    ey: Vector3<f64>,
    ez: Vector3<f64>,
}

impl Frame {
    /// `None` for a zero normal or a lay direction (nearly) parallel to it. Both may have
    /// any finite non-zero length: one whose squares would over- or underflow is first
    /// scaled by a power of two (exact, and the same unit vector as without the scaling).
    fn new(hit: &Hit) -> Option<Frame> {
        let n = Vector3::from(hit.normal);
        let n = scale_pow2(n, -taming_exponent(&n));
        let n_len = n.norm();
        if n_len == 0.0 || !n_len.is_finite() {
            return None;
        }
        // A normal the host made unit (to round-off) is used as given: dividing it by its
        // computed length could change its last bits, and the host's own rebound uses it
        // as it is.
        let mut ey = if (n_len - 1.0).abs() <= 4.0 * f64::EPSILON {
            n
        } else {
            n / n_len
        };
        let u_rel = Vector3::from(hit.velocity) - Vector3::from(hit.wall_velocity);
        if u_rel.dot(&ey) > 0.0 {
            ey = -ey; // into the flow: the particle arrives against it
        }
        let lay = Vector3::from(hit.lay);
        let lay = scale_pow2(lay, -taming_exponent(&lay));
        let lay_len = lay.norm();
        let t = lay - lay.dot(&ey) * ey;
        let t_len = t.norm();
        if !(lay_len > 0.0 && t_len > 1e-9 * lay_len) {
            return None;
        }
        let ex = t / t_len;
        Some(Frame {
            ez: ex.cross(&ey),
            ex,
            ey,
        })
    }

    fn to_local(&self, v: &Vector3<f64>) -> Vector3<f64> {
        Vector3::new(v.dot(&self.ex), v.dot(&self.ey), v.dot(&self.ez))
    }

    fn to_global(&self, v: &Vector3<f64>) -> Vector3<f64> {
        self.ex * v.x + self.ey * v.y + self.ez * v.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::ShParams;
    use crate::stochastic::rebound;

    /// Every numeric parameter declared in `WALL_PARAMETERS` is a field here, and is checked
    /// for finiteness by `WallModel::new` with its key.
    #[test]
    fn every_declared_number_is_a_field_and_is_checked() {
        let p = WallParams::default();
        for q in WALL_PARAMETERS
            .iter()
            .filter(|q| q.kind == ParameterKind::Number)
        {
            assert!(p.number(q.case_key).is_some(), "{}", q.case_key);
        }
        let declared = WALL_PARAMETERS
            .iter()
            .filter(|q| q.kind == ParameterKind::Number)
            .count();
        assert_eq!(p.numbers().len(), declared);
        let bad = WallParams {
            psi: Some(f64::NAN),
            ..Default::default()
        };
        let err = WallModel::new(&bad).unwrap_err().to_string();
        assert_eq!(
            err,
            "invalid `stochastic.psi` = NaN: allowed a finite number"
        );
    }

    fn glass_steel() -> WallModel {
        WallModel::new(&WallParams {
            delta_xi_deg: 3.8,
            delta_zeta_deg: 7.5,
            collision: CollisionParams {
                model: Some("sommerfeld-huber".into()),
                preset: Some("glass-steel".into()),
                ..Default::default()
            },
            psi: None,
            seed: 5,
            ..Default::default()
        })
        .unwrap()
        .0
    }

    fn hit() -> Hit {
        Hit {
            velocity: [5.0, -1.3, -2.1],
            spin: [0.0, 0.0, 0.0],
            normal: [0.0, 1.0, 0.0],
            lay: [1.0, 0.0, 0.0],
            wall_velocity: [0.0; 3],
            diameter_m: 500e-6,
            particle_id: 12,
            collision_index: 3,
        }
    }

    #[test]
    fn in_the_papers_frame_it_is_the_stochastic_rebound_with_the_hits_stream() {
        let m = glass_steel();
        assert_eq!(
            m.law,
            crate::collision::CollisionLaw::SommerfeldHuber(ShParams::glass_steel())
        );
        let h = hit();
        let out = m.rebound(&h);
        let mut r = rng::stream(5, &[rng::domain::WALL_HITS, 12, 3]);
        let direct = rebound(
            Vector3::from(h.velocity),
            Vector3::zeros(),
            &m.wall,
            &m.law,
            2.0,
            500e-6,
            &mut r,
        );
        assert_eq!(out.status, HitStatus::Rebound);
        assert_eq!(out.velocity, <[f64; 3]>::from(direct.velocity));
        assert_eq!(out.candidate_walls, direct.tries);
        // Same key, same rebound; another collision index, another one.
        assert_eq!(m.rebound(&h), out);
        let other = m.rebound(&Hit {
            collision_index: 4,
            ..h
        });
        assert_ne!(other.velocity, out.velocity);
    }

    #[test]
    fn a_flipped_normal_a_tilted_lay_and_a_moving_wall_change_nothing_physical() {
        let m = glass_steel();
        let h = hit();
        let base = m.rebound(&h);
        // Normal given the other way round and not unit length; lay with a normal component.
        let flipped = m.rebound(&Hit {
            normal: [0.0, -3.0, 0.0],
            lay: [2.0, 0.7, 0.0],
            ..h
        });
        for i in 0..3 {
            assert!((flipped.velocity[i] - base.velocity[i]).abs() < 1e-12);
        }
        // A wall moving along itself: the rebound is computed relative to it.
        let v = [0.4, 0.0, -0.3];
        let moving = m.rebound(&Hit {
            velocity: [h.velocity[0] + v[0], h.velocity[1], h.velocity[2] + v[2]],
            wall_velocity: v,
            ..h
        });
        for ((m, v), b) in moving.velocity.iter().zip(v).zip(base.velocity) {
            assert!((m - v - b).abs() < 1e-12);
        }
    }

    #[test]
    fn a_rotated_scene_gives_the_rotated_rebounds_to_round_off() {
        use nalgebra::{Rotation3, Unit};
        let m = glass_steel();
        let base_hit = Hit {
            spin: [120.0, -40.0, 300.0],
            ..hit()
        };
        let base = m.rebound(&base_hit);
        let mut r = rng::stream(9, &[1]);
        use rand::Rng;
        for k in 0..50 {
            let axis = Unit::new_normalize(Vector3::new(
                r.gen::<f64>() - 0.5,
                r.gen::<f64>() - 0.5,
                r.gen::<f64>() - 0.5,
            ));
            let rot = Rotation3::from_axis_angle(&axis, r.gen::<f64>() * std::f64::consts::TAU);
            let g = |v: [f64; 3]| <[f64; 3]>::from(rot * Vector3::from(v));
            let rotated = m.rebound(&Hit {
                velocity: g(base_hit.velocity),
                spin: g(base_hit.spin),
                normal: g([0.0, if k % 2 == 0 { 1.0 } else { -2.0 }, 0.0]),
                lay: g([1.0, 0.3, 0.0]),
                ..base_hit
            });
            assert_eq!(rotated.status, HitStatus::Rebound);
            assert_eq!(rotated.candidate_walls, base.candidate_walls);
            let (want_u, want_w) = (g(base.velocity), g(base.spin));
            for i in 0..3 {
                assert!(
                    (rotated.velocity[i] - want_u[i]).abs() < 1e-12,
                    "{k}: {rotated:?}"
                );
                assert!(
                    (rotated.spin[i] - want_w[i]).abs() < 1e-9 * 300.0,
                    "{k}: {rotated:?}"
                );
            }
            assert!((rotated.gamma - base.gamma).abs() < 1e-12);
        }
    }

    #[test]
    fn a_smooth_elastic_wall_is_the_hosts_specular_rebound_bit_for_bit() {
        let m = WallModel::new(&WallParams::default()).unwrap().0;
        assert_eq!(m.law, CollisionLaw::Elastic);
        // code_saturne's CS_LAGR_REBOUND (cs_lagr_tracking.c): tmp = 2 (u·n), u_k -= tmp n_k.
        let host = |u: [f64; 3], n: [f64; 3]| {
            let tmp = 2. * (u[0] * n[0] + u[1] * n[1] + u[2] * n[2]);
            [u[0] - tmp * n[0], u[1] - tmp * n[1], u[2] - tmp * n[2]]
        };
        let mut r = rng::stream(17, &[2]);
        use rand::Rng;
        let mut v = || 2.0 * r.gen::<f64>() - 1.0;
        let mut rounded_lengths = 0;
        for k in 0..2000 {
            // A unit normal as a host computes it (n / |n|), either orientation; the
            // velocity towards the wall.
            let raw = [v(), v(), v()];
            let len = (raw[0] * raw[0] + raw[1] * raw[1] + raw[2] * raw[2]).sqrt();
            let n = raw.map(|x| x / len);
            if (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() != 1.0 {
                rounded_lengths += 1;
            }
            let mut u = [5.0 * v(), 5.0 * v(), 5.0 * v()];
            let un: f64 = (0..3).map(|i| u[i] * n[i]).sum();
            if un > 0.0 {
                u = u.map(|x| -x);
            }
            let normal = if k % 2 == 0 { n } else { n.map(|x| -x) };
            let spin = [v() * 100.0, v() * 100.0, v() * 100.0];
            let out = m.rebound(&Hit {
                velocity: u,
                spin,
                normal,
                lay: [v(), v(), v()],
                ..hit()
            });
            assert_eq!(out.status, HitStatus::Rebound);
            assert_eq!(
                out.velocity.map(f64::to_bits),
                host(u, n).map(f64::to_bits),
                "{k}"
            );
            assert_eq!(out.spin, spin);
            assert_eq!(
                (out.gamma, out.gamma_star, out.candidate_walls),
                (0.0, 0.0, 1)
            );
        }
        // Some of those normals are 1 ulp off unit length: the case that must not be
        // normalised again.
        assert!(rounded_lengths > 100, "{rounded_lengths}");
        // In the paper's frame it is `stochastic::rebound` on the smooth wall, bit for bit.
        let h = hit();
        let mut r = rng::stream(0, &[rng::domain::WALL_HITS, 12, 3]);
        let direct = rebound(
            Vector3::from(h.velocity),
            Vector3::zeros(),
            &m.wall,
            &m.law,
            m.psi,
            h.diameter_m,
            &mut r,
        );
        let out = m.rebound(&h);
        assert_eq!(out.velocity, <[f64; 3]>::from(direct.velocity));
        assert_eq!(out.candidate_walls, direct.tries);
        // A moving smooth wall: the specular rebound relative to it.
        let w = [0.3, 0.0, -0.2];
        let moving = m.rebound(&Hit {
            velocity: [h.velocity[0] + w[0], h.velocity[1], h.velocity[2] + w[2]],
            wall_velocity: w,
            ..h
        });
        for ((m, w), o) in moving.velocity.iter().zip(w).zip(out.velocity) {
            assert!((m - w - o).abs() < 1e-14, "{moving:?}");
        }
    }

    #[test]
    fn bad_inputs_are_statuses_never_nan() {
        let m = glass_steel();
        let h = hit();
        for bad in [
            Hit {
                velocity: [f64::NAN, -1.0, 0.0],
                ..h
            },
            Hit {
                spin: [0.0, f64::INFINITY, 0.0],
                ..h
            },
            Hit {
                normal: [0.0, 0.0, 0.0],
                ..h
            },
            Hit {
                lay: [0.0, 2.0, 0.0],
                ..h
            },
            Hit { lay: [0.0; 3], ..h },
            Hit {
                diameter_m: -1e-6,
                ..h
            },
            Hit {
                wall_velocity: [f64::NEG_INFINITY, 0.0, 0.0],
                ..h
            },
            Hit {
                velocity: [f64::INFINITY, -1.0, 0.0],
                ..h
            },
            Hit {
                normal: [0.0, f64::INFINITY, 0.0],
                ..h
            },
            Hit {
                normal: [f64::NAN, 1.0, 0.0],
                ..h
            },
            Hit {
                lay: [1.0, 0.0, f64::NAN],
                ..h
            },
            Hit {
                diameter_m: f64::INFINITY,
                ..h
            },
            Hit {
                diameter_m: f64::NAN,
                ..h
            },
        ] {
            let out = m.rebound(&bad);
            assert_eq!(out.status, HitStatus::InvalidInput, "{bad:?}");
            assert!(out.velocity.iter().chain(&out.spin).all(|x| x.is_finite()));
            if bad.velocity.iter().all(|x| x.is_finite()) {
                assert_eq!(out.velocity, bad.velocity, "unchanged");
            }
        }
        let along = m.rebound(&Hit {
            velocity: [3.0, 0.0, 1.0],
            ..h
        });
        assert_eq!(along.status, HitStatus::NotApproaching);
        let huge = m.rebound(&Hit {
            velocity: [1e308, -1e308, 1e308],
            ..h
        });
        assert!(huge.velocity.iter().all(|x| x.is_finite()));
    }

    #[test]
    fn parameters_are_checked_like_a_case_file() {
        let good = WallParams {
            delta_xi_deg: 3.8,
            delta_zeta_deg: 7.5,
            ..Default::default()
        };
        assert!(WallModel::new(&good).is_ok());
        let msg = |p: WallParams| WallModel::new(&p).unwrap_err().to_string();
        assert!(msg(WallParams {
            delta_xi_deg: -1.0,
            ..good.clone()
        })
        .contains("wall.delta_xi_deg"));
        assert!(msg(WallParams {
            delta_zeta_deg: f64::NAN,
            ..good.clone()
        })
        .contains("wall.delta_zeta_deg"));
        assert!(msg(WallParams {
            psi: Some(0.0),
            ..good.clone()
        })
        .contains("stochastic.psi"));
        let sh = |e_h| WallParams {
            collision: CollisionParams {
                model: Some("sommerfeld-huber".into()),
                preset: Some("glass-steel".into()),
                e_h: Some(e_h),
                ..Default::default()
            },
            ..good.clone()
        };
        assert!(msg(sh(1.5)).contains("collision.e_h"));
        let (_, warnings) = WallModel::new(&WallParams {
            delta_zeta_deg: 12.0,
            ..good
        })
        .unwrap();
        assert_eq!(warnings.len(), 1);
        assert!(warnings[0].contains("wall.delta_zeta_deg"));
    }

    /// An elastic rough wall (the paper's model and `calibrated`).
    fn elastic_rough(model: Option<&str>) -> WallModel {
        WallModel::new(&WallParams {
            delta_xi_deg: 2.5,
            delta_zeta_deg: 7.5,
            model: model.map(String::from),
            seed: 11,
            ..Default::default()
        })
        .unwrap()
        .0
    }

    fn close(a: [f64; 3], b: [f64; 3], rel: f64) -> bool {
        let scale = b.iter().map(|x| x.abs()).fold(0.0, f64::max);
        a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= rel * scale)
    }

    /// Normals, lay directions and velocities of any finite length, 1e-300 to 1e300: the
    /// same rebound as at unit length (the velocity's scaled with it), speed conserved by
    /// the elastic law, never the guard.
    #[test]
    fn any_vector_length_gives_the_unit_rebound() {
        for model in [None, Some("calibrated"), Some("sommerfeld-huber-1999")] {
            let wall = elastic_rough(model);
            for pid in 0..20u64 {
                let base = Hit {
                    velocity: [0.8, -0.35, -0.4],
                    spin: [0.0; 3],
                    normal: [0.0, 1.0, 0.0],
                    lay: [1.0, 0.0, 0.0],
                    wall_velocity: [0.0; 3],
                    diameter_m: 1e-4,
                    particle_id: pid,
                    collision_index: 0,
                };
                let want = wall.rebound(&base);
                assert_eq!(want.status, HitStatus::Rebound);
                for e in [-300, -200, -170, -160, -100, -10, 0, 10, 100, 154, 200, 300] {
                    let f = 10f64.powi(e);
                    let scaled = |v: [f64; 3]| v.map(|x| x * f);
                    for (what, hit) in [
                        (
                            "normal",
                            Hit {
                                normal: scaled(base.normal),
                                ..base
                            },
                        ),
                        (
                            "lay",
                            Hit {
                                lay: scaled(base.lay),
                                ..base
                            },
                        ),
                        (
                            "velocity",
                            Hit {
                                velocity: scaled(base.velocity),
                                ..base
                            },
                        ),
                    ] {
                        let got = wall.rebound(&hit);
                        assert_eq!(got.status, HitStatus::Rebound, "{model:?} {what} 1e{e}");
                        assert!(got.candidate_walls < crate::stochastic::MAX_TRIES);
                        let expect = if what == "velocity" {
                            want.velocity.map(|x| x * f)
                        } else {
                            want.velocity
                        };
                        assert!(
                            close(got.velocity, expect, 1e-12),
                            "{model:?} {what} 1e{e}: {:?} against {:?}",
                            got.velocity,
                            expect
                        );
                        let speed = |v: [f64; 3]| {
                            let m = v.iter().map(|x| x.abs()).fold(0.0, f64::max);
                            m * v.iter().map(|x| (x / m).powi(2)).sum::<f64>().sqrt()
                        };
                        let (s_in, s_out) = (speed(hit.velocity), speed(got.velocity));
                        assert!(
                            (s_out / s_in - 1.0).abs() < 1e-12,
                            "{model:?} {what} 1e{e}: |U| {s_in} → {s_out}"
                        );
                    }
                }
            }
        }
    }

    /// Scaling a direction by a power of two is exact, so a normal or lay direction off the
    /// axes scaled by 2^k gives the same rebound bit for bit, also beyond the range where its
    /// squared length would overflow or underflow (2^±600, 2^±1000); a velocity scaled by 2^k
    /// gives the rebound scaled by 2^k, bit for bit.
    #[test]
    fn power_of_two_lengths_give_the_same_rebound_bit_for_bit() {
        for model in [None, Some("calibrated"), Some("sommerfeld-huber-1999")] {
            let wall = elastic_rough(model);
            for pid in 0..20u64 {
                let base = Hit {
                    velocity: [0.8, -0.9, -0.4],
                    spin: [0.0; 3],
                    normal: [0.3, 1.0, -0.2],
                    lay: [1.0, 0.1, 0.7],
                    wall_velocity: [0.0; 3],
                    diameter_m: 1e-4,
                    particle_id: pid,
                    collision_index: 0,
                };
                let want = wall.rebound(&base);
                assert_eq!(want.status, HitStatus::Rebound);
                for k in [-1000, -600, -300, -1, 1, 300, 600, 1000] {
                    let f = 2f64.powi(k);
                    let scaled = |v: [f64; 3]| v.map(|x| x * f);
                    let normal = Hit {
                        normal: scaled(base.normal),
                        ..base
                    };
                    let lay = Hit {
                        lay: scaled(base.lay),
                        ..base
                    };
                    assert_eq!(wall.rebound(&normal), want, "{model:?} normal 2^{k}");
                    assert_eq!(wall.rebound(&lay), want, "{model:?} lay 2^{k}");
                    if k.abs() < 1000 {
                        let velocity = Hit {
                            velocity: scaled(base.velocity),
                            ..base
                        };
                        let got = wall.rebound(&velocity);
                        assert_eq!(got.velocity, scaled(want.velocity), "{model:?} 2^{k}");
                    }
                }
            }
        }
    }

    /// The elastic law returns the spin as given, on a smooth and on a rough wall.
    #[test]
    fn the_elastic_law_returns_the_spin_bit_unchanged() {
        let smooth = WallModel::new(&WallParams::default()).unwrap().0;
        for wall in [
            smooth,
            elastic_rough(None),
            elastic_rough(Some("calibrated")),
        ] {
            for pid in 0..1000u64 {
                let spin = [0.1 * pid as f64, -3.7e2, 1.0 / (pid as f64 + 3.0)];
                let hit = Hit {
                    velocity: [1.0, -0.3, 0.45],
                    spin,
                    normal: [0.3, 1.0, -0.2],
                    lay: [1.0, 0.2, 0.1],
                    wall_velocity: [0.0; 3],
                    diameter_m: 1e-4,
                    particle_id: pid,
                    collision_index: 1,
                };
                let out = wall.rebound(&hit);
                assert_eq!(out.status, HitStatus::Rebound);
                assert_eq!(out.spin, spin);
            }
        }
    }
}
