//! `measured-wall`: the rebound law measured on the wall itself. Each hit draws the effective
//! wall element `(γ, γ*)` of the deterministic reference on the scan (in place, for the
//! particle's diameter) from the table `rebound scan --measured-wall` builds, and applies the
//! collision law in its frame (Radenkovic & Simonin 2021, Eqs. 20–23 for the element, Sec.
//! 3.1 for the reference; the physics and the table are [`crate::measured_wall`]). With the
//! elastic law a rebound always leaves; with another law a rebound that does not leave meets
//! the wall again with its rebound velocity, as the simpler models do.

use super::params::{refuse_delta_gamma, refuse_escape_table};
use super::rough_wall_model::{ModelParams, NamedModel, RoughWallModel};
use crate::angles::incident_angles;
use crate::error::{Error, Result};
use crate::measured_wall::{MeasuredWallIncidence, MeasuredWallTable};
use crate::stochastic::virtual_wall::guard_rebound;
use crate::stochastic::{Contact, Rebound, SeenWall, MAX_TRIES};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// The measured-wall model with its table (interned, [`MeasuredWallTable::intern`], so the
/// model stays a small `Copy` value).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeasuredWall {
    /// The wall's table.
    pub table: &'static MeasuredWallTable,
}

impl RoughWallModel for MeasuredWall {
    type Incidence = (MeasuredWallIncidence, &'static MeasuredWallTable);

    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn anisotropic(&self) -> bool {
        true
    }

    /// The deviations of the wall the table was measured on.
    fn roughness_angle(&self, _wall: &Deviations) -> f64 {
        let d = &self.table.deviations;
        0.5 * (d.delta_xi + d.delta_zeta)
    }

    fn wall(&self, _given: &Deviations) -> Deviations {
        self.table.deviations
    }

    fn incidence(&self, alpha: f64, beta: f64, _wall: &Deviations) -> Self::Incidence {
        (self.table.incidence(alpha, beta), self.table)
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
        rebound_off_table(table, inc, u_in, omega_in, contact, rng, observe)
    }
}

/// One rebound of the measured-wall model off `table` (borrowed: for a caller that holds a
/// table it has not interned), for a particle moving towards the wall whose direction falls
/// at `inc` ([`MeasuredWallTable::incidence`]): the body of
/// [`RoughWallModel::rebound_drawn`] for [`MeasuredWall`].
pub fn rebound_off_table<R: Rng + ?Sized>(
    table: &MeasuredWallTable,
    inc: &MeasuredWallIncidence,
    u_in: Vector3<f64>,
    omega_in: Vector3<f64>,
    contact: &Contact,
    rng: &mut R,
    mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
) -> Rebound {
    let (mut u, mut w) = (u_in, omega_in);
    let mut cur = *inc;
    let mut candidates = 0u32;
    let mut first = SeenWall::FLAT;
    for tries in 1..=MAX_TRIES {
        let (xi, zeta) = table.draw(&cur, rng);
        let seen = SeenWall::of_xi_zeta(xi, zeta, cur.sin_cos_beta);
        let un = u.dot(&seen.normal);
        // Every element of the table mirrors its history's particle off the wall; a drawn
        // one that does not (its two angles come from different histories of a rank bin,
        // or were measured at a neighbouring grid direction) is no element of the wall here:
        // drawn again.
        if un >= 0.0 || u.y - 2.0 * un * seen.normal.y <= 0.0 {
            continue;
        }
        candidates += 1;
        if candidates == 1 {
            first = seen;
        }
        observe(&u, &seen.normal, true);
        let (u_out, w_out) = contact.law.collide(u, w, seen.normal, contact.diameter_m);
        if u_out.y > 0.0 {
            return Rebound::off(&seen, u_out, w_out, tries, candidates, first);
        }
        // A law that is not elastic may keep the particle on the wall: it meets the wall
        // again with its rebound velocity.
        (u, w) = (u_out, w_out);
        let (alpha, beta) = incident_angles(&u);
        cur = table.incidence(alpha.min(-1e-12), beta);
    }
    guard_rebound(
        u,
        w,
        contact.law,
        contact.diameter_m,
        candidates,
        first,
        observe,
    )
}

impl NamedModel for MeasuredWall {
    const NAME: &'static str = "measured-wall";

    /// `stochastic.wall_table` (required), and no `Δγ` or escape table.
    fn from_params(params: &ModelParams) -> Result<Self> {
        refuse_delta_gamma(params, Self::NAME)?;
        refuse_escape_table(params, Self::NAME)?;
        match params.wall_table {
            Some(read) => Ok(MeasuredWall { table: read()? }),
            None => Err(Error::Input(format!(
                "model = \"{}\" needs `stochastic.wall_table`: the table `rebound scan --measured-wall` writes beside the wall card (a wall card's row names it)",
                Self::NAME
            ))),
        }
    }
}
