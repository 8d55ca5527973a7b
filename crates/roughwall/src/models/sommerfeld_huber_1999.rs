//! `sommerfeld-huber-1999`: Sommerfeld & Huber, Int. J. Multiphase Flow 25 (1999)
//! 1457–1489. An isotropic wall: the shadow-effect law of the roughness angle seen by a
//! particle (as Radenkovic & Simonin 2021, Eq. 31, write it) in the incident plane, an
//! independent normal law across it, one `Δγ` for both; a particle that does not return to
//! the flow meets a new virtual wall (Sommerfeld & Zivkovic 1992, as Radenkovic & Simonin
//! 2021, Sec. 1, describe it).

use super::isotropic::{Isotropic, IsotropicDraw, IsotropicIncidence};
use crate::stochastic::SeenWall;
use rand::Rng;
use rand_distr::StandardNormal;

/// Sommerfeld & Huber 1999: the shadow law in the incident plane, an independent normal law
/// across it.
pub type SommerfeldHuber1999 = Isotropic<SommerfeldHuberWall>;

/// The wall element of [`SommerfeldHuber1999`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SommerfeldHuberWall;

impl IsotropicDraw for SommerfeldHuberWall {
    const NAME: &'static str = "sommerfeld-huber-1999";

    /// An element: `γ` from the shadow law with `Δγ`, `γ* ~ N(0, Δγ)`.
    fn draw<R: Rng + ?Sized>(inc: &IsotropicIncidence, rng: &mut R) -> SeenWall {
        let gamma = inc.sampler.sample(rng);
        let z: f64 = rng.sample(StandardNormal);
        inc.wall_of_gammas(gamma, inc.delta_gamma * z)
    }
}
