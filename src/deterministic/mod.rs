//! `rebound deterministic`: particle-centre bouncing on a generated anisotropic
//! rough wall (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5 and 4; physics notes §5).
pub mod scene;
pub mod trace;

pub use trace::{Fate, History, HitInfo, LostReason, Tracker, DEFAULT_MAX_COLLISIONS};
