//! The anisotropic stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.3–3.6, Fig. 13; procedure written out in the physics notes §3).
//!
//! * [`shadow_effect`]: the exact sampler and density of `P_eff(γ | α⁻)` (Eqs. 31–33).
//! * [`rebound_model`]: [`rebound`], one rebound — the entry point a CFD code calls
//!   once per wall collision.
//! * [`simulate`]: many rebounds of one incident condition, parallel and reproducible.
//! * [`variants`]: the simpler rough-wall models CFD codes ship, for the benchmark.
//! * [`escape_table`]: the calibrated escape law of the `calibrated` model.
//! * [`transverse_memory`]: its later collisions' memory of the transverse inclination.
pub mod escape_table;
pub mod rebound_model;
pub mod shadow_effect;
pub mod simulate;
pub mod slope_space;
pub mod transverse_memory;
pub mod variants;

pub use rebound_model::{
    left_element_memory, rebound, rebound_from, rebound_from_observed, rebound_variant,
    single_collision_probability, transverse_residual, Incidence, Rebound, SeenWall, MAX_TRIES,
};
pub use shadow_effect::ShadowSampler;
pub use variants::{Variant, VariantKind};
