//! Warnings: something the user should know while the run goes on. Resolution returns
//! [`Warning`]s; commands hand them to [`warn`], which prints them on stderr
//! (`warning: <text>`) or, inside [`capture_warnings`], collects them. Low in the module
//! picture so that every layer (output directories, resolution, commands) can warn.
//! Re-exported from `case`.

use std::cell::RefCell;
use std::fmt::{self, Display};

/// Something the user should know while the run goes on (e.g. a roughness beyond the
/// low-roughness approximation). Resolution returns warnings; the binary prints them
/// (`warning: <text>`) once the command has succeeded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Warning(pub String);

impl Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

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
