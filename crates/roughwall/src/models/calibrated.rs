//! `calibrated`: Radenkovic & Simonin 2021's virtual walls in the wall's slopes, corrected by
//! the element law, escape law and transverse memory that `rebound calibrate` measures on a
//! deterministic run; a particle that does not escape meets the wall again with its rebound
//! velocity. The physics is [`crate::calibrated`]; this file names it and its table.

use super::params::{refuse_delta_gamma, refuse_wall_table};
use super::rough_wall_model::{ModelParams, NamedModel, RoughWallModel};
use crate::calibrated::{CalibratedIncidence, EscapeTable};
use crate::error::Result;
use crate::stochastic::{Contact, Rebound};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// The calibrated model with its escape table.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Calibrated {
    /// The escape law (`None`: the built-in table). Interned ([`EscapeTable::intern`]), so
    /// the model stays a small `Copy` value.
    pub escape: Option<&'static EscapeTable>,
}

impl Calibrated {
    /// The escape table this model reads.
    pub fn escape_table(&self) -> &'static EscapeTable {
        self.escape.unwrap_or_else(EscapeTable::builtin)
    }
}

impl RoughWallModel for Calibrated {
    type Incidence = (CalibratedIncidence, &'static EscapeTable);

    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn anisotropic(&self) -> bool {
        true
    }

    fn incidence(&self, alpha: f64, beta: f64, wall: &Deviations) -> Self::Incidence {
        (
            CalibratedIncidence::new(alpha, beta, wall),
            self.escape_table(),
        )
    }

    #[inline]
    fn rebound_drawn<R: Rng + ?Sized>(
        &self,
        (inc, table): &Self::Incidence,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        contact: &Contact,
        rng: &mut R,
        observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    ) -> Rebound {
        crate::calibrated::rebound(inc, table, u_in, omega_in, contact, rng, observe)
    }
}

impl NamedModel for Calibrated {
    const NAME: &'static str = "calibrated";

    fn from_params(params: &ModelParams) -> Result<Self> {
        refuse_delta_gamma(params, Self::NAME)?;
        refuse_wall_table(params, Self::NAME)?;
        let escape = params.escape_table.map(|read| read()).transpose()?;
        Ok(Calibrated { escape })
    }
}
