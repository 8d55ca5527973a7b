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

pub use check::Warning;
pub use load::{load, load_text, parse, resolve_path, DEFAULT_SEED};
pub use resolve::{IncidentCondition, Scene, SpeedLaw, SurfaceSpec, WallSource};
pub use schema::*;

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
