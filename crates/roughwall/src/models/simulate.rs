//! Many rebounds of one incident condition, reproducibly: each rebound from its own random
//! stream, tallied block by block (`rebound stochastic`, Radenkovic & Simonin 2021, Sec. 4).

use super::rebound::rebound_from_observed;
use super::registry::AnyModel;
use super::rough_wall_model::RoughWallModel;
use crate::angles::{alpha_xy_of_velocity, incident_angles, wrap_pi};
use crate::collision::CollisionLaw;
use crate::erosion::ErosionSetup;
use crate::incidence::{draw_speed, IncidentCondition, SpeedLaw, SpinLaw};
use crate::rng;
use crate::stochastic::shadow_effect;
use crate::stochastic::{Contact, Rebound, MAX_TRIES};
use crate::tally::{Bin, BlockTally, ErosionOutcome, ModelKind, Outcome, Pdf, Quantity, TallySpec};
use crate::wall::Deviations;
use nalgebra::Vector3;

/// The model's parameters for a run: any rough-wall model `M`, by default one a case file
/// names ([`AnyModel`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelSetup<M = AnyModel> {
    /// Normal-angle deviations `(Δξ, Δζ)` of the statistical wall (radians).
    pub wall: Deviations,
    /// The collision law applied in the frame of each sampled normal (ideal elastic or
    /// Sommerfeld–Huber; Radenkovic & Simonin 2021, Eqs. 36–42).
    pub law: CollisionLaw,
    /// `ψ` of the single-collision probability `P(n = 1 | α⁺) = tanh(ψ α⁺/Δγ(β⁺))` (Radenkovic &
    /// Simonin 2021, Eq. 34; 2 there and by default, 1.5 in Konan et al. 2009). Read by the
    /// paper's model; a value that is not positive and finite makes every model collide with
    /// the mean wall.
    pub psi: f64,
    /// Particle diameter `D` (m), the lever arm `R = D/2` of the spin in the collision law.
    pub diameter_m: f64,
    /// The law of the incident speed (m/s).
    pub speed: SpeedLaw,
    /// The erosion law, when the case tallies erosion.
    pub erosion: Option<ErosionSetup>,
    /// The rough-wall model (`[stochastic] model`; default Radenkovic & Simonin 2021).
    pub model: M,
    /// Incident spin (default zero).
    pub spin: SpinLaw,
}

/// The tallied record of one stochastic rebound (radians; `β⁻ = beta_in`).
pub fn outcome(r: &Rebound, u_in: &Vector3<f64>, beta_in: f64) -> Outcome {
    let (alpha_out, beta_out) = incident_angles(&r.velocity);
    let s_in = u_in.norm();
    Outcome {
        alpha_out,
        beta_out,
        alpha_out_xy: alpha_xy_of_velocity(&r.velocity),
        dbeta: wrap_pi(beta_out - beta_in),
        // The first wall seen, like the deterministic model's first normal (Figs. 10–11).
        xi_first: r.first.xi,
        zeta_first: r.first.zeta,
        gamma_first: r.first.gamma,
        gamma_star_first: r.first.gamma_star,
        speed_ratio: if s_in > 0.0 {
            r.velocity.norm() / s_in
        } else {
            1.0
        },
        ..Default::default()
    }
}

/// Rebound `i` of condition `cond` (index `cond_index` in the case): the particle draws
/// from its own stream `rng::stream(seed, &[STOCHASTIC, cond_index, i])`, so it does not
/// depend on which thread or shard runs it. Incident spin is zero (Radenkovic & Simonin
/// 2021, Sec. 4). Returns the incident velocity and the rebound.
pub fn rebound_of<M: RoughWallModel>(
    setup: &ModelSetup<M>,
    cond: &IncidentCondition,
    cond_index: u64,
    i: u64,
    seed: u64,
) -> (Vector3<f64>, Rebound) {
    let per_unit = setup.speed.velocity(cond.alpha_in, cond.beta_in, 1.0);
    let inc = setup
        .model
        .incidence(cond.alpha_in, cond.beta_in, &setup.wall);
    rebound_at(setup, &inc, &per_unit, &stream_prefix(seed, cond_index), i)
}

/// The part of a rebound's stream key shared by a condition: `(seed, STOCHASTIC, k)`.
fn stream_prefix(seed: u64, cond_index: u64) -> rng::StreamPrefix {
    rng::StreamPrefix::new(seed, &[rng::domain::STOCHASTIC, cond_index])
}

/// [`rebound_of`] with what a condition shares computed once: the incident direction's
/// incidence (the condition's exact angles), the velocity per unit horizontal speed and
/// the stream prefix.
#[inline]
fn rebound_at<M: RoughWallModel>(
    setup: &ModelSetup<M>,
    inc: &M::Incidence,
    per_unit: &Vector3<f64>,
    prefix: &rng::StreamPrefix,
    i: u64,
) -> (Vector3<f64>, Rebound) {
    rebound_observed(setup, inc, per_unit, prefix, i, |_, _, _| {})
}

/// [`rebound_at`] reporting every candidate rebound to `observe`: the incident velocity,
/// the virtual wall's normal and whether the rebound was accepted.
#[inline]
fn rebound_observed<M: RoughWallModel>(
    setup: &ModelSetup<M>,
    inc: &M::Incidence,
    per_unit: &Vector3<f64>,
    prefix: &rng::StreamPrefix,
    i: u64,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> (Vector3<f64>, Rebound) {
    let mut r = prefix.stream(i);
    let u = per_unit * draw_speed(&setup.speed, &mut r);
    let w = setup.spin.draw(&mut r);
    let contact = Contact {
        wall: &setup.wall,
        law: &setup.law,
        psi: setup.psi,
        diameter_m: setup.diameter_m,
    };
    let reb = rebound_from_observed(
        &setup.model,
        inc,
        u,
        w,
        &contact,
        &mut r,
        |u_hit, n, accepted| observe(u_hit, n, accepted),
    );
    (u, reb)
}

/// Tallies rebounds `start..end` of a condition into `block`, in particle order.
pub fn fill_block<M: RoughWallModel>(
    setup: &ModelSetup<M>,
    cond: &IncidentCondition,
    cond_index: u64,
    seed: u64,
    (start, end): (u64, u64),
    block: &mut BlockTally,
) {
    let per_unit = setup.speed.velocity(cond.alpha_in, cond.beta_in, 1.0);
    let inc = setup
        .model
        .incidence(cond.alpha_in, cond.beta_in, &setup.wall);
    let prefix = stream_prefix(seed, cond_index);
    if let Some(erosion) = &setup.erosion {
        for i in start..end {
            // The accepted virtual wall's impact erodes; the rejected candidates stand for
            // the repeated hits of a multiple collision, tallied apart.
            let (mut accepted, mut rejected) = (0.0, 0.0);
            // The paper's model hits with the incident velocity every time: its norm once.
            let mut last = (Vector3::zeros(), 0.0);
            let (u, reb) = rebound_observed(setup, &inc, &per_unit, &prefix, i, |u, n, ok| {
                if *u != last.0 {
                    last = (*u, u.norm());
                }
                let (a, v) = erosion.impact(u, last.1, n);
                if ok {
                    accepted += v;
                } else {
                    rejected += v;
                }
                block.push_impact(a.alpha, !ok);
            });
            let o = Outcome {
                erosion: Some(ErosionOutcome {
                    per_mass: accepted,
                    rejected_per_mass: Some(rejected),
                }),
                ..outcome(&reb, &u, cond.beta_in)
            };
            block.push(&o);
            block.push_candidates(reb.tries, reb.candidates, reb.tries >= MAX_TRIES);
        }
        return;
    }
    for i in start..end {
        let (u, reb) = rebound_at(setup, &inc, &per_unit, &prefix, i);
        block.push(&outcome(&reb, &u, cond.beta_in));
        block.push_candidates(reb.tries, reb.candidates, reb.tries >= MAX_TRIES);
    }
}

/// The tally specification of a condition of this model.
pub fn tally_spec(
    wall: &Deviations,
    cond: IncidentCondition,
    bin_width_deg: f64,
    erosion: Option<&ErosionSetup>,
) -> TallySpec {
    TallySpec {
        condition: cond,
        deviations: *wall,
        bin_width_deg,
        model: ModelKind::Stochastic,
        erosion_particle_mass_kg: erosion.map(|e| e.particle_mass_kg),
        realisations: 1,
    }
}

/// The model curve `gamma_model`: `P_eff(γ | α⁻)` (Radenkovic & Simonin 2021,
/// Eqs. 31–33, with `Δγ` of Eq. 26 at `β⁻`) at the centres of the bins of width
/// `bin_width_deg` aligned like the tally's `gamma_first` histogram (multiples of the
/// width from −90°), in 1/degree. `Δγ = 0` is a point mass at 0: the bin holding 0
/// gets `1/width`.
pub fn gamma_model_curve(wall: &Deviations, cond: &IncidentCondition, bin_width_deg: f64) -> Pdf {
    let dg = crate::wall::delta_gamma(wall, cond.beta_in);
    let w = bin_width_deg;
    let nb = (180.0 / w).ceil() as usize;
    let a_deg = cond.alpha_in_deg();
    let bins: Vec<Bin> = if dg == 0.0 {
        (0..nb)
            .map(|i| (-90.0 + i as f64 * w, -90.0 + (i + 1) as f64 * w))
            .filter(|&(lo, hi)| lo <= 0.0 && 0.0 < hi)
            .map(|(lo, hi)| Bin {
                lo,
                hi,
                value: 1.0 / w,
                se: None,
            })
            .collect()
    } else {
        let lo_deg = a_deg.max(-11.0 * dg.to_degrees());
        let hi_deg = (11.0 * dg.to_degrees()).min(90.0);
        let edges: Vec<(f64, f64)> = (0..nb)
            .map(|i| (-90.0 + i as f64 * w, -90.0 + (i + 1) as f64 * w))
            .filter(|&(lo, hi)| hi > lo_deg && lo < hi_deg)
            .collect();
        let centres: Vec<f64> = edges
            .iter()
            .map(|&(lo, hi)| (0.5 * (lo + hi)).to_radians())
            .collect();
        let dens = shadow_effect::density_curve(&centres, cond.alpha_in, dg);
        edges
            .iter()
            .zip(dens)
            .map(|(&(lo, hi), p)| Bin {
                lo,
                hi,
                // per radian → per degree
                value: p * std::f64::consts::PI / 180.0,
                se: None,
            })
            .collect()
    };
    Pdf::new(Quantity::GammaModel, bins)
}
