//! What a rough-wall model is: the trait every model implements ([`RoughWallModel`]: how it
//! draws the virtual wall a particle meets and what becomes of a rebound that does not leave)
//! and the one a case file names it by ([`NamedModel`]: its name and its parameters' checks).

use crate::calibrated::EscapeTable;
use crate::error::Result;
use crate::measured_wall::MeasuredWallTable;
use crate::stochastic::{Contact, Rebound};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// A rough-wall model: a virtual wall element drawn from the incident state, the collision
/// law applied in its frame, and a rule for a rebound that does not leave the wall.
///
/// The rebound is split in two so that a run of many particles with one incident direction
/// pays for the direction once: [`RoughWallModel::incidence`] precomputes what depends on the
/// direction `(α, β)` and the wall, [`RoughWallModel::rebound_drawn`] draws one rebound. The
/// cases that need no draw (a particle not moving towards the wall, a smooth wall) are ruled
/// out before, for every model alike ([`super::rebound_from_observed`]).
///
/// Dispatch is static: a run is generic over its model, and the models a case file names are
/// one enum ([`super::AnyModel`]), so the hot loop of a run inlines its model.
pub trait RoughWallModel: Copy + std::fmt::Debug + PartialEq + Send + Sync {
    /// What the model precomputes for one incident direction on a wall.
    type Incidence: Copy + std::fmt::Debug + Send + Sync;

    /// The name in case files (`[stochastic] model`), the C library and Python.
    fn name(&self) -> &'static str;

    /// Whether the virtual walls follow the wall's two deviations along and across its lay
    /// (Eq. 26) rather than one isotropic roughness angle.
    fn anisotropic(&self) -> bool;

    /// The one roughness angle `Δγ` (rad) this model reports on `wall` (`run.toml`): an
    /// isotropic model's own, otherwise the mean of the wall's deviations `(Δξ + Δζ)/2`.
    fn roughness_angle(&self, wall: &Deviations) -> f64 {
        0.5 * (wall.delta_xi + wall.delta_zeta)
    }

    /// The wall this model rebounds off when a run gives `given`: `given` itself, except for
    /// a model measured on a wall of its own (`measured-wall`: that wall's deviations).
    fn wall(&self, given: &Deviations) -> Deviations {
        *given
    }

    /// The incident direction `(α, β)` (rad) on `wall`.
    fn incidence(&self, alpha: f64, beta: f64, wall: &Deviations) -> Self::Incidence;

    /// One rebound of a particle of velocity `u_in` (moving towards the rough wall, finite)
    /// and spin `omega_in`, whose direction's incidence is `inc`. Every collision with a
    /// virtual wall element is reported to `observe`: the velocity it hit with, the element's
    /// normal, and whether the rebound was accepted (`false`: rejected as a multiple
    /// collision, Radenkovic & Simonin 2021, Eq. 34).
    fn rebound_drawn<R: Rng + ?Sized>(
        &self,
        inc: &Self::Incidence,
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        contact: &Contact,
        rng: &mut R,
        observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    ) -> Rebound;
}

/// A model that case files, the C library and Python name: its name, and the model built
/// from the parameters a case file gives it, checked by the model itself.
pub trait NamedModel: RoughWallModel + Sized {
    /// The name in case files (`[stochastic] model`).
    const NAME: &'static str;

    /// The model with `params`, or a one-line error naming the key that does not apply to
    /// it or is out of range (`super::params` has the shared checks).
    fn from_params(params: &ModelParams) -> Result<Self>;
}

/// The parameters of a `[stochastic]` section that belong to a rough-wall model. Each model
/// takes those it uses and refuses the others.
#[derive(Clone, Copy, Default)]
pub struct ModelParams<'a> {
    /// `stochastic.delta_gamma_deg`: the one roughness angle of the isotropic models
    /// (degrees).
    pub delta_gamma_deg: Option<f64>,
    /// `stochastic.escape_table`: how to read the escape table of `calibrated`, called only
    /// once the model has accepted the key (so that a key that does not apply is refused
    /// before any file is read).
    pub escape_table: Option<&'a dyn Fn() -> Result<&'static EscapeTable>>,
    /// `stochastic.wall_table`: how to read the table of `measured-wall`, called only once
    /// the model has accepted the key.
    pub wall_table: Option<&'a dyn Fn() -> Result<&'static MeasuredWallTable>>,
}

impl std::fmt::Debug for ModelParams<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ModelParams")
            .field("delta_gamma_deg", &self.delta_gamma_deg)
            .field("escape_table", &self.escape_table.map(|_| "given"))
            .field("wall_table", &self.wall_table.map(|_| "given"))
            .finish()
    }
}
