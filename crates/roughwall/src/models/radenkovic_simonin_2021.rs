//! `radenkovic-simonin-2021`, the default: the anisotropic virtual walls `γ`, `γ*` of Eqs. 26,
//! 29–33 with the shadow effect, and a rebound that does not leave rejected and redrawn for
//! the same incident particle (Eq. 34). The physics is [`crate::stochastic`]; this file
//! names it.

use super::params::{refuse_delta_gamma, refuse_escape_table, refuse_wall_table};
use super::rough_wall_model::{ModelParams, NamedModel, RoughWallModel};
use crate::error::Result;
use crate::stochastic::{Contact, Incidence, Rebound};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// Radenkovic & Simonin 2021 (Sec. 3.6, Fig. 13).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RadenkovicSimonin2021;

impl RoughWallModel for RadenkovicSimonin2021 {
    type Incidence = Incidence;

    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn anisotropic(&self) -> bool {
        true
    }

    fn incidence(&self, alpha: f64, beta: f64, wall: &Deviations) -> Incidence {
        Incidence::new(alpha, beta, wall)
    }

    #[inline]
    fn rebound_drawn<R: Rng + ?Sized>(
        &self,
        inc: &Incidence,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        contact: &Contact,
        rng: &mut R,
        observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    ) -> Rebound {
        inc.rebound_observed(u_in, omega_in, contact, rng, observe)
    }
}

impl NamedModel for RadenkovicSimonin2021 {
    const NAME: &'static str = "radenkovic-simonin-2021";

    fn from_params(params: &ModelParams) -> Result<Self> {
        refuse_delta_gamma(params, Self::NAME)?;
        refuse_escape_table(params, Self::NAME)?;
        refuse_wall_table(params, Self::NAME)?;
        Ok(RadenkovicSimonin2021)
    }
}
