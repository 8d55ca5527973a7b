//! TOML case files: the schema (`schema`), loading with one-line errors (`load`),
//! and validated SI views of the sections each command needs (`resolve`).

pub mod load;
pub mod resolve;
pub mod schema;

pub use load::{load, load_text, parse, resolve_path, DEFAULT_SEED};
pub use resolve::{IncidentCondition, Scene, SpeedLaw, SurfaceSpec, WallSource};
pub use schema::*;

/// Print a warning on stderr: the run goes on, the user should know.
pub fn warn(msg: &str) {
    eprintln!("warning: {msg}");
}
