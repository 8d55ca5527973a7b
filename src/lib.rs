//! `rebound`: particles bouncing off anisotropic rough walls.
//!
//! The modules follow the pipeline of a run: case → wall (generated surface or
//! statistical wall) → incident particles → collision law → tallies → outputs.
pub mod rng;
pub mod surface;
pub mod stochastic;
pub mod compare;
