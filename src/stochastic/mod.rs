//! The anisotropic stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.3–3.6, Fig. 13; procedure written out in the physics notes §3).
pub mod rebound_model;
pub mod shadow_effect;

pub use rebound_model::{rebound, single_collision_probability, Rebound, MAX_TRIES};
pub use shadow_effect::ShadowSampler;
