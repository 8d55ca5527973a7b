//! TOML case files: the schema (`schema`), loading with one-line errors (`load`), the
//! check helpers every section uses (`check`, OpenMC's checkvalue as the model), and one file
//! per section family with its validated SI view: `wall` (`[surface]`, `[wall]`, `[stats]`),
//! `scene` (`[incidence]`, `[particles]`, `[output]`), `collision`, `stochastic` (and `[stochastic]`),
//! `deterministic` (and `[deterministic]`), `erosion`, `force` (`[impactor]`, `[sweep]`),
//! `values` (sweep ranges). `sections` says which command reads which section; `builtin`
//! holds each command's built-in case.

pub mod builtin;
pub mod check;
pub mod collision;
pub mod deterministic;
pub mod erosion;
pub mod force;
pub mod load;
pub mod scene;
pub mod schema;
pub mod sections;
pub mod stochastic;
pub mod values;
pub mod wall;

pub use check::Warning;
pub use load::{load, load_text, parse, resolve_path, DEFAULT_SEED};
pub use scene::{IncidentCondition, Scene, SpeedLaw};
pub use schema::*;
pub use wall::{SurfaceSpec, WallSource};

use std::cell::RefCell;

thread_local! {
    /// Warnings collected instead of printed, while [`capture_warnings`] runs.
    static CAPTURED: RefCell<Option<Vec<String>>> = const { RefCell::new(None) };
}

/// Print a warning on stderr: the run goes on, the user should know. Inside
/// [`capture_warnings`] (the binary runs every command inside it, and prints once the command
/// has succeeded) it is collected instead. Resolution does not call it: it returns its
/// [`Warning`]s, and the command hands them here.
pub fn warn(msg: &str) {
    let captured = CAPTURED.with(|c| {
        c.borrow_mut()
            .as_mut()
            .map(|list| list.push(msg.to_string()))
            .is_some()
    });
    if !captured {
        eprintln!("warning: {msg}");
    }
}

/// Runs `f` and returns its result with the warnings it raised, none of them printed.
pub fn capture_warnings<T>(f: impl FnOnce() -> T) -> (T, Vec<String>) {
    let outer = CAPTURED.with(|c| c.borrow_mut().replace(Vec::new()));
    let out = f();
    let list = CAPTURED.with(|c| std::mem::replace(&mut *c.borrow_mut(), outer));
    (out, list.unwrap_or_default())
}
