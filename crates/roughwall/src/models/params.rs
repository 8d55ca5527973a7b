//! The checks the models share on their `[stochastic]` parameters: each model calls those of
//! the keys it refuses or takes, so that the same bad value gives the same message whichever
//! model reads it.

use super::rough_wall_model::ModelParams;
use crate::check::within;
use crate::error::{Error, Result};
use crate::wall::MAX_DEVIATION_DEG;

/// Refuses `stochastic.delta_gamma_deg` for a model that takes its `Δγ` from the wall.
pub fn refuse_delta_gamma(params: &ModelParams, model: &str) -> Result<()> {
    match params.delta_gamma_deg {
        None => Ok(()),
        Some(_) => Err(Error::Input(format!(
            "`stochastic.delta_gamma_deg` applies to the isotropic variants only; model = \"{model}\" takes its Δγ from the wall (Eq. 26)"
        ))),
    }
}

/// Refuses `stochastic.escape_table` for every model but `calibrated`.
pub fn refuse_escape_table(params: &ModelParams, model: &str) -> Result<()> {
    match params.escape_table {
        None => Ok(()),
        Some(_) => Err(Error::Input(format!(
            "`stochastic.escape_table` applies to model = \"calibrated\" only (model = \"{model}\")"
        ))),
    }
}

/// Refuses `stochastic.wall_table` for every model but `measured-wall`.
pub fn refuse_wall_table(params: &ModelParams, model: &str) -> Result<()> {
    match params.wall_table {
        None => Ok(()),
        Some(_) => Err(Error::Input(format!(
            "`stochastic.wall_table` applies to model = \"measured-wall\" only (model = \"{model}\")"
        ))),
    }
}

/// The isotropic models' roughness angle `stochastic.delta_gamma_deg` (rad), checked against
/// the wall models' range; `None` when not given (the wall's `(Δξ + Δζ)/2` then).
pub fn delta_gamma(params: &ModelParams) -> Result<Option<f64>> {
    params
        .delta_gamma_deg
        .map(|d| {
            within(
                "stochastic.delta_gamma_deg",
                d,
                0.0,
                MAX_DEVIATION_DEG,
                " degrees",
                "a roughness angle within the wall models' range",
            )
            .map(f64::to_radians)
        })
        .transpose()
}
