//! What each command writes: tables, figures and `run.toml` of a finished run, from the
//! resolved case, the tallies and the physics. High in the module picture: it may use every
//! library module below it (`case`, `figures`, the physics, `tally`, `output`); none of
//! those uses it.
//!
//! * [`deterministic`], [`stochastic`]: `finish` of a Monte Carlo run (and of `merge`).
//! * [`surface`]: the tables of `rebound surface`.

pub mod deterministic;
pub mod stochastic;
pub mod surface;
