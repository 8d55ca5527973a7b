//! The anisotropic stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.3–3.6, Fig. 13; procedure written out in the physics notes §3).
pub mod shadow_effect;
