//! `rebound deterministic`: particle-centre bouncing on a generated anisotropic
//! rough wall (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5 and 4; physics notes §5).
pub mod plots;
pub mod scene;
pub mod trace;

pub use trace::{Fate, History, HitInfo, LostReason, Tracker, DEFAULT_MAX_COLLISIONS};

use crate::angles::{gamma_from_normal, incident_angles, wrap_pi, xi_zeta_of_normal};
use crate::case::{IncidentCondition, SpeedLaw};
use crate::collision::CollisionLaw;
use crate::incidence::{draw_speed, incident_velocity};
use crate::rng;
use crate::tally::{Bin, ConditionExtras, ConditionResult, Curve, Outcome};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;
use rayon::prelude::*;

/// Shoots `count` particles of one condition at the tracker's surface, in parallel;
/// particle `i` draws its start `(x, z)` (uniform over the period) and its
/// horizontal speed from `rng::stream(seed, &[DETERMINISTIC, cond_index, i])`, so
/// the histories (returned in particle order) do not depend on the thread count.
/// Incident spin is zero (Radenkovic & Simonin 2021, Sec. 4).
pub fn simulate<C>(
    tracker: &Tracker<'_>,
    collide: &C,
    cond: IncidentCondition,
    cond_index: u64,
    count: usize,
    seed: u64,
    speed: &SpeedLaw,
) -> Vec<History>
where
    C: Fn(Vector3<f64>, Vector3<f64>, Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) + Sync,
{
    let (lx, lz) = tracker.periods();
    (0..count)
        .into_par_iter()
        .map(|i| {
            let mut r = rng::stream(seed, &[rng::domain::DETERMINISTIC, cond_index, i as u64]);
            let x = r.gen::<f64>() * lx;
            let z = r.gen::<f64>() * lz;
            let u_h = draw_speed(speed, &mut r);
            let u = incident_velocity(cond.alpha_in, cond.beta_in, u_h);
            tracker.trace(x, z, u, Vector3::zeros(), collide)
        })
        .collect()
}

/// The tallied record of a followed history (`None` for a lost one).
///
/// `xi_first`, `zeta_first` are `ξ − 90°`, `ζ − 90°` of the first normal seen,
/// `γ`, `γ*` from Radenkovic & Simonin 2021, Eqs. (20)–(21) (notes §2) with the
/// incident `β⁻`; the deviations are wrapped into (−180°, 180°].
pub fn outcome(h: &History, beta_in: f64) -> Option<Outcome> {
    if h.fate != Fate::Escaped {
        return None;
    }
    let (alpha_out, beta_out) = incident_angles(&h.velocity);
    let (_, beta_first) = incident_angles(&h.first_velocity);
    let (xi, zeta) = xi_zeta_of_normal(&h.first_normal);
    let (gamma, gamma_star) = gamma_from_normal(&h.first_normal, beta_in);
    let s_in = h.incident.norm();
    Some(Outcome {
        alpha_out,
        beta_out,
        dbeta: wrap_pi(beta_out - beta_in),
        dbeta_first: Some(wrap_pi(beta_first - beta_in)),
        xi_first: xi,
        zeta_first: zeta,
        gamma_first: gamma,
        gamma_star_first: gamma_star,
        collisions: Some(h.collisions),
        speed_ratio: if s_in > 0.0 {
            h.velocity.norm() / s_in
        } else {
            1.0
        },
    })
}

/// Counts of lost histories by reason.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LostCounts {
    pub collision_cap: u64,
    pub below_surface: u64,
    pub step_budget: u64,
    pub stopped: u64,
}

impl LostCounts {
    pub fn total(&self) -> u64 {
        self.collision_cap + self.below_surface + self.step_budget + self.stopped
    }

    fn add(&mut self, r: LostReason) {
        match r {
            LostReason::CollisionCap => self.collision_cap += 1,
            LostReason::BelowSurface => self.below_surface += 1,
            LostReason::StepBudget => self.step_budget += 1,
            LostReason::Stopped => self.stopped += 1,
        }
    }

    /// `"N hit the cap …, M …"` for warnings; empty when nothing was lost.
    pub fn describe(&self) -> String {
        [
            (self.collision_cap, LostReason::CollisionCap),
            (self.below_surface, LostReason::BelowSurface),
            (self.step_budget, LostReason::StepBudget),
            (self.stopped, LostReason::Stopped),
        ]
        .iter()
        .filter(|(n, _)| *n > 0)
        .map(|(n, r)| format!("{n} {}", r.describe()))
        .collect::<Vec<_>>()
        .join(", ")
    }
}

/// Everything one condition produced.
#[derive(Clone, Debug)]
pub struct ConditionRun {
    pub condition: IncidentCondition,
    /// Outcomes of the followed histories, in particle order.
    pub outcomes: Vec<Outcome>,
    /// `(α⁺, β⁺)` of the first rebound of each followed history (rad), same order.
    pub first_rebound: Vec<(f64, f64)>,
    pub lost: LostCounts,
}

/// Radenkovic & Simonin 2021, Eq. (34) with Δγ(β⁺) of Eq. (35), at rebound angles
/// `(α⁺, β⁺)`: the stochastic model's own implementation, so both models use one formula.
pub fn p_single_model(dev: &Deviations, psi: f64, alpha_out: f64, beta_out: f64) -> f64 {
    let u = crate::angles::velocity_from_angles(1.0, alpha_out, beta_out);
    crate::stochastic::single_collision_probability(&u, alpha_out, dev, psi)
}

/// Per `α` bin of `bin_width_deg` on [−90°, 90°): the fraction of single-collision
/// histories and the model `tanh(ψ α/Δγ(β))` averaged over the bin's particles at
/// their own `(α, β)`; `angles` are the rebound angles binned (rad), `single` whether
/// the history had one collision. Returns `(measured, model)` curves.
pub fn p_single_curves(
    angles: &[(f64, f64)],
    single: impl Iterator<Item = bool>,
    dev: &Deviations,
    psi: f64,
    bin_width_deg: f64,
) -> (Vec<Bin>, Vec<Bin>) {
    let nb = (180.0 / bin_width_deg).ceil() as usize;
    let mut tot = vec![0u64; nb];
    let mut one = vec![0u64; nb];
    let mut model = vec![0.0; nb];
    for (&(a, b), s) in angles.iter().zip(single) {
        let i = (((a.to_degrees() + 90.0) / bin_width_deg).floor().max(0.0) as usize).min(nb - 1);
        tot[i] += 1;
        one[i] += s as u64;
        model[i] += p_single_model(dev, psi, a, b);
    }
    let bin = |i: usize, v: f64| Bin {
        lo: -90.0 + i as f64 * bin_width_deg,
        hi: -90.0 + (i + 1) as f64 * bin_width_deg,
        value: v,
    };
    let idx: Vec<usize> = (0..nb).filter(|&i| tot[i] > 0).collect();
    (
        idx.iter()
            .map(|&i| bin(i, one[i] as f64 / tot[i] as f64))
            .collect(),
        idx.iter()
            .map(|&i| bin(i, model[i] / tot[i] as f64))
            .collect(),
    )
}

/// Runs one condition with collision law `law` (sphere diameter `diameter_m`).
#[allow(clippy::too_many_arguments)]
pub fn run_condition(
    tracker: &Tracker<'_>,
    law: &CollisionLaw,
    diameter_m: f64,
    cond: IncidentCondition,
    cond_index: u64,
    count: usize,
    seed: u64,
    speed: &SpeedLaw,
) -> ConditionRun {
    let collide = |u, w, n| law.collide(u, w, n, diameter_m);
    let histories = simulate(tracker, &collide, cond, cond_index, count, seed, speed);
    let mut lost = LostCounts::default();
    let mut outcomes = Vec::with_capacity(histories.len());
    let mut first_rebound = Vec::with_capacity(histories.len());
    for h in &histories {
        match h.fate {
            Fate::Lost(r) => lost.add(r),
            Fate::Escaped => {
                if let Some(o) = outcome(h, cond.beta_in) {
                    outcomes.push(o);
                    first_rebound.push(incident_angles(&h.first_velocity));
                }
            }
        }
    }
    ConditionRun {
        condition: cond,
        outcomes,
        first_rebound,
        lost,
    }
}

impl ConditionRun {
    /// The Fig. 12 curves (Radenkovic & Simonin 2021, Eq. 34–35): `P(n = 1)` per bin of
    /// the *first* rebound angle `α⁺` — the probability the stochastic procedure
    /// (Fig. 13, step 6) uses to accept a rebound — and the model averaged over the
    /// bin's particles at their own first-rebound `(α⁺, β⁺)`.
    pub fn fig12_curves(
        &self,
        dev: &Deviations,
        psi: f64,
        bin_width_deg: f64,
    ) -> (Vec<Bin>, Vec<Bin>) {
        p_single_curves(
            &self.first_rebound,
            self.outcomes.iter().map(|o| o.collisions == Some(1)),
            dev,
            psi,
            bin_width_deg,
        )
    }

    /// The `summary.csv` row and `pdfs.csv` rows, plus the curves
    /// `p_single_given_alpha_first` and `p_single_model` (see [`ConditionRun::fig12_curves`]).
    pub fn tally(&self, dev: &Deviations, psi: f64, bin_width_deg: f64) -> ConditionResult {
        let (measured, model) = self.fig12_curves(dev, psi, bin_width_deg);
        ConditionResult::from_outcomes(
            self.condition,
            *dev,
            &self.outcomes,
            bin_width_deg,
            ConditionExtras {
                lost: Some(self.lost.total()),
                p_single: None,
                curves: vec![
                    Curve {
                        quantity: "p_single_given_alpha_first".into(),
                        bins: measured,
                    },
                    Curve {
                        quantity: "p_single_model".into(),
                        bins: model,
                    },
                    // PDF of the first rebound angle: with `particles` it gives the
                    // histories behind each bin of the two curves above.
                    Curve {
                        quantity: "alpha_first".into(),
                        bins: crate::tally::density(
                            &self
                                .first_rebound
                                .iter()
                                .map(|r| r.0.to_degrees())
                                .collect::<Vec<_>>(),
                            -90.0,
                            90.0,
                            bin_width_deg,
                        ),
                    },
                ],
            },
        )
    }
}
