//! The stochastic wall model of Radenkovic & Simonin 2021 (Secs. 3.4–3.6, Fig. 13; the
//! procedure written out in docs/physics.md §3), and what every rough-wall model shares with
//! it. The other models, and the choice between them, are [`crate::models`], one layer up.
//!
//! * `shadow_effect`: the exact sampler and density of `P_eff(γ | α⁻)` (Eqs. 31–33).
//! * `virtual_wall`: the wall element a particle meets, a rebound's outcome, the rebounds
//!   that need no draw, and the loop of the models that follow a trapped particle.
//! * `rebound_model`: the paper's model (its [`Incidence`], the single-collision law of
//!   Eq. 34) and [`rebound`], the entry point a CFD code calls once per wall collision.
pub(crate) mod rebound_model;
pub(crate) mod shadow_effect;
pub(crate) mod virtual_wall;

pub use rebound_model::{
    checked_psi, rebound, single_collision_probability, Incidence, PSI_PAPER, PSI_RANGE,
};
pub use shadow_effect::ShadowSampler;
pub use shadow_effect::{bin_probability, density, sample_gamma};
pub use virtual_wall::{Contact, Rebound, SeenWall, MAX_TRIES};
