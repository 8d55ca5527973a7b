//! What the carrier fluid does to a particle between two wall hits, beyond drag: the shear
//! lift (Saffman–Mei), the rotational lift (Magnus) and the rotational drag that relaxes
//! the particle's spin. A CFD code that hands the wall model a particle's spin
//! ([`crate::wall_model::Hit::spin`]) has to carry that spin between hits; these are the
//! laws Euler–Lagrange codes of dilute gas–solid flow use for it (Sommerfeld's school:
//! Laín & Sommerfeld 2008, *Powder Technol.* 184, 76–88; Crowe, Schwarzkopf, Sommerfeld &
//! Tsuji 2012, *Multiphase Flows with Droplets and Particles*, 2nd ed., Ch. 4).
//!
//! Every law takes one [`FluidPoint`], the state of the fluid and the particle where the
//! particle is, and gives an acceleration (force over the particle's mass) or a new spin.
//! The conventions are the CFD code's global frame: the slip is the fluid's velocity minus
//! the particle's, the vorticity is the curl of the fluid's velocity, `∇ × u`, so the
//! fluid rotates at half of it.

mod magnus;
mod saffman_mei;
mod spin_relax;

pub use magnus::{magnus_coefficient, magnus_lift};
pub use saffman_mei::{saffman_mei_factor, saffman_mei_lift};
pub use spin_relax::{relaxed_spin, rotational_drag_coefficient};

/// The fluid and the particle at the particle's position.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FluidPoint {
    /// Fluid density ρ_f (kg/m³, > 0).
    pub rho_f: f64,
    /// Fluid dynamic viscosity μ_f (Pa s, > 0).
    pub mu_f: f64,
    /// Particle density ρ_p (kg/m³, > 0).
    pub rho_p: f64,
    /// Particle diameter d_p (m, > 0).
    pub d_p: f64,
    /// Slip velocity u_f − v_p: the fluid's velocity (as the particle sees it) minus the
    /// particle's (m/s).
    pub slip: [f64; 3],
    /// The fluid's vorticity ∇ × u_f (1/s).
    pub vorticity: [f64; 3],
    /// The particle's angular velocity ω_p (rad/s).
    pub spin: [f64; 3],
}

impl FluidPoint {
    /// Whether every number is finite and the four properties are positive: the laws
    /// are defined only then (the C entry points return `RW_INVALID_INPUT` otherwise).
    pub fn is_valid(&self) -> bool {
        let positive = [self.rho_f, self.mu_f, self.rho_p, self.d_p]
            .iter()
            .all(|&x| x.is_finite() && x > 0.0);
        positive
            && self
                .slip
                .iter()
                .chain(&self.vorticity)
                .chain(&self.spin)
                .all(|x| x.is_finite())
    }

    /// Ω = ½ ∇ × u_f − ω_p: the fluid's rotation relative to the particle's (1/s).
    pub fn relative_rotation(&self) -> [f64; 3] {
        std::array::from_fn(|k| 0.5 * self.vorticity[k] - self.spin[k])
    }

    /// The particle Reynolds number Re_p = ρ_f d_p |u_f − v_p| / μ_f.
    pub fn reynolds_particle(&self) -> f64 {
        self.rho_f * self.d_p * norm(&self.slip) / self.mu_f
    }
}

pub(crate) fn norm(a: &[f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

pub(crate) fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests;
