//! The stochastic wall models: the anisotropic model of Radenkovic & Simonin 2021
//! (Secs. 3.4–3.6, Fig. 13; the procedure written out in docs/physics.md §3), the models CFD
//! codes ship, and the runs of many rebounds (the calibrated model is [`crate::calibrated`]).
//!
//! * [`shadow_effect`]: the exact sampler and density of `P_eff(γ | α⁻)` (Eqs. 31–33).
//! * [`virtual_wall`]: the wall element a particle meets, a rebound's outcome, and the loop
//!   of the models that follow a trapped particle.
//! * [`rebound_model`]: the paper's model (its [`Incidence`], the single-collision law).
//! * [`cfd_models`]: the simpler rough-wall models CFD codes ship, for the benchmark.
//! * [`variants`]: which model draws the walls (their names in case files, their checks).
//! * [`variant_rebound`]: one rebound from the model a variant names; [`rebound`], the
//!   paper's — the entry point a CFD code calls once per wall collision.
//! * [`simulate`]: many rebounds of one incident condition, parallel and reproducible.
pub mod cfd_models;
pub mod rebound_model;
pub mod shadow_effect;
pub mod simulate;
pub mod variant_rebound;
pub mod variants;
pub mod virtual_wall;

pub use rebound_model::{single_collision_probability, Incidence};
pub use shadow_effect::ShadowSampler;
pub use variant_rebound::{
    rebound, rebound_from, rebound_from_observed, rebound_variant, ModelIncidence,
};
pub use variants::{Variant, VariantKind};
pub use virtual_wall::{Rebound, SeenWall, MAX_TRIES};
