//! Many rebounds of one incident condition, in parallel and reproducibly
//! (`rebound stochastic`, Radenkovic & Simonin 2021, Sec. 4).

use super::rebound_model::{rebound, Rebound, MAX_TRIES};
use super::shadow_effect;
use crate::angles::{incident_angles, wrap_pi, xi_zeta_of_normal};
use crate::case::{IncidentCondition, SpeedLaw};
use crate::collision::CollisionLaw;
use crate::incidence::{draw_speed, incident_velocity};
use crate::rng;
use crate::tally::{Bin, Curve, Outcome};
use crate::wall::{rotated_moments, Deviations};
use nalgebra::Vector3;
use rayon::prelude::*;

/// The model's parameters for a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelSetup {
    pub wall: Deviations,
    pub law: CollisionLaw,
    pub psi: f64,
    pub diameter_m: f64,
    pub speed: SpeedLaw,
}

/// Everything one condition produced, in particle order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConditionRun {
    pub outcomes: Vec<Outcome>,
    /// Candidate walls drawn in total (steps 2–6 of the procedure).
    pub tries: u64,
    /// Candidate rebounds computed in total (`U⁻·n < 0`).
    pub candidates: u64,
    /// Particles whose rebound hit the [`MAX_TRIES`] guard.
    pub capped: u64,
}

impl ConditionRun {
    /// Accepted fraction of candidate rebounds (the run's `p_single`).
    pub fn p_single(&self) -> f64 {
        if self.candidates > 0 {
            self.outcomes.len() as f64 / self.candidates as f64
        } else {
            1.0
        }
    }
}

/// The tallied record of one stochastic rebound (radians; `β⁻ = beta_in`).
pub fn outcome(r: &Rebound, u_in: &Vector3<f64>, beta_in: f64) -> Outcome {
    let (alpha_out, beta_out) = incident_angles(&r.velocity);
    // The first wall seen, like the deterministic model's first normal (Figs. 10–11).
    let (xi, zeta) = xi_zeta_of_normal(&r.first.normal);
    let s_in = u_in.norm();
    Outcome {
        alpha_out,
        beta_out,
        dbeta: wrap_pi(beta_out - beta_in),
        dbeta_first: None,
        xi_first: xi,
        zeta_first: zeta,
        gamma_first: r.first.gamma,
        gamma_star_first: r.first.gamma_star,
        collisions: None,
        speed_ratio: if s_in > 0.0 {
            r.velocity.norm() / s_in
        } else {
            1.0
        },
    }
}

/// `count` rebounds at condition `cond` (index `cond_index` in the case): particle `i`
/// draws from `rng::stream(seed, &[STOCHASTIC, cond_index, i])`, so the outcomes
/// (returned in particle order) do not depend on the thread count. Incident spin is
/// zero (Radenkovic & Simonin 2021, Sec. 4).
pub fn run_condition(
    setup: &ModelSetup,
    cond: IncidentCondition,
    cond_index: u64,
    count: usize,
    seed: u64,
) -> ConditionRun {
    // The velocity per unit horizontal speed, once per condition.
    let per_unit = incident_velocity(cond.alpha_in, cond.beta_in, 1.0);
    let per: Vec<(Outcome, u32, u32)> = (0..count)
        .into_par_iter()
        .map(|i| {
            let mut r = rng::stream(seed, &[rng::domain::STOCHASTIC, cond_index, i as u64]);
            let u = per_unit * draw_speed(&setup.speed, &mut r);
            let reb = rebound(
                u,
                Vector3::zeros(),
                &setup.wall,
                &setup.law,
                setup.psi,
                setup.diameter_m,
                &mut r,
            );
            (outcome(&reb, &u, cond.beta_in), reb.tries, reb.candidates)
        })
        .collect();
    let mut run = ConditionRun {
        outcomes: Vec::with_capacity(per.len()),
        ..Default::default()
    };
    for (o, t, c) in per {
        run.outcomes.push(o);
        run.tries += t as u64;
        run.candidates += c as u64;
        run.capped += (t >= MAX_TRIES) as u64;
    }
    run
}

/// The model curve `gamma_model`: `P_eff(γ | α⁻)` (Radenkovic & Simonin 2021,
/// Eqs. 31–33, with `Δγ` of Eq. 26 at `β⁻`) at the centres of the bins of width
/// `bin_width_deg` aligned like the tally's `gamma_first` histogram (multiples of the
/// width from −90°), in 1/degree. `Δγ = 0` is a point mass at 0: the bin holding 0
/// gets `1/width`.
pub fn gamma_model_curve(wall: &Deviations, cond: &IncidentCondition, bin_width_deg: f64) -> Curve {
    let dg = rotated_moments(wall, cond.beta_in).var_a.max(0.0).sqrt();
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
            })
            .collect()
    };
    Curve {
        quantity: "gamma_model".into(),
        bins,
    }
}
