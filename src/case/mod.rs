//! TOML case files: the schema (`schema`), loading with one-line errors (`load`),
//! and validated SI views of the sections each command needs (`resolve`).

pub mod builtin;
pub mod check;
pub mod deterministic;
pub mod erosion;
pub mod force;
pub mod load;
pub mod resolve;
pub mod schema;
pub mod sections;
pub mod stochastic;

pub use crate::warning::{capture_warnings, warn, Warning};
pub use load::{load, load_text, parse, resolve_path, DEFAULT_SEED};
pub use resolve::{IncidentCondition, Scene, SpeedLaw, SurfaceSpec, WallSource};
pub use schema::*;
