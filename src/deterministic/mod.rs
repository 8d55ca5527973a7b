//! `rebound deterministic`: particle-centre bouncing on a generated anisotropic
//! rough wall (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5 and 4; physics notes §5).
pub mod scene;
pub mod trace;

pub use trace::{Fate, History, HitInfo, LostReason, Tracker, DEFAULT_MAX_COLLISIONS};

use crate::rng;
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::{Distribution, Normal};
use rayon::prelude::*;

/// Law of the incident horizontal speed `|U⁻| cos α⁻` (m/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpeedLaw {
    /// Every particle has `|U⁻| = 1 m/s` (ideal elastic results do not depend on it).
    Unit,
    /// Normal law of the horizontal speed (Radenkovic & Simonin 2021, Sec. 4:
    /// `N(5.91, 1.16)` m/s after Sommerfeld & Huber); non-positive draws are redrawn.
    Normal { mean: f64, std: f64 },
}

/// Draws the horizontal speed: redraws non-positive values (up to 64 times),
/// then falls back to the mean.
fn draw_speed<R: Rng>(law: SpeedLaw, r: &mut R) -> f64 {
    match law {
        SpeedLaw::Unit => 1.0,
        SpeedLaw::Normal { mean, std } => {
            if let Ok(n) = Normal::new(mean, std.max(0.0)) {
                for _ in 0..64 {
                    let v = n.sample(r);
                    if v > 0.0 && v.is_finite() {
                        return v;
                    }
                }
            }
            mean.abs().max(f64::MIN_POSITIVE)
        }
    }
}

/// Incident velocity for angles `alpha < 0`, `beta` (rad) and horizontal speed
/// `u_h` (physics notes §1: `U = |U| (cos α cos β, sin α, −cos α sin β)`).
/// At normal incidence (`cos α ≈ 0`) the drawn speed is taken as `|U|`.
pub fn incident_velocity(alpha: f64, beta: f64, u_h: f64) -> Vector3<f64> {
    let ca = alpha.cos();
    let speed = if ca > 1e-9 { u_h / ca } else { u_h };
    Vector3::new(ca * beta.cos(), alpha.sin(), -ca * beta.sin()) * speed
}

/// One incident condition of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Condition {
    /// Index of the condition in the case (keys the random streams).
    pub index: u64,
    /// Incident angles (rad).
    pub alpha: f64,
    pub beta: f64,
}

/// Shoots `count` particles of condition `cond` at the tracker's surface, in
/// parallel; particle `i` draws its start `(x, z)` (uniform over the period) and
/// speed from `rng::stream(seed, &[DETERMINISTIC, cond.index, i])`, so the
/// histories (returned in particle order) do not depend on the thread count.
/// Incident spin is zero (Radenkovic & Simonin 2021, Sec. 4).
pub fn simulate<C>(
    tracker: &Tracker<'_>,
    collide: &C,
    cond: Condition,
    count: usize,
    seed: u64,
    speed: SpeedLaw,
) -> Vec<History>
where
    C: Fn(Vector3<f64>, Vector3<f64>, Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) + Sync,
{
    let (lx, lz) = tracker.periods();
    (0..count)
        .into_par_iter()
        .map(|i| {
            let mut r = rng::stream(seed, &[rng::domain::DETERMINISTIC, cond.index, i as u64]);
            let x = r.gen::<f64>() * lx;
            let z = r.gen::<f64>() * lz;
            let u_h = draw_speed(speed, &mut r);
            let u = incident_velocity(cond.alpha, cond.beta, u_h);
            tracker.trace(x, z, u, Vector3::zeros(), |u, w, n| collide(u, w, n))
        })
        .collect()
}
