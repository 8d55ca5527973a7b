//! The one boundary between the library's errors (and any panic) and Python exceptions:
//! a bad value is a `ValueError` with the library's one-line message (the C library's and
//! the command line's), a file problem an `OSError`, a bug a `RuntimeError`. No panic
//! unwinds into the interpreter.

use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::PyErr;
use roughwall::error::Error;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The Python exception for a library error.
pub fn to_py(e: Error) -> PyErr {
    match e {
        Error::Input(m) | Error::Model(m) => PyValueError::new_err(m),
        Error::Io(m) => PyOSError::new_err(m),
        Error::Internal(m) => {
            PyRuntimeError::new_err(format!("internal error in roughwall (please report): {m}"))
        }
    }
}

/// A `ValueError` naming the argument, the value and what is allowed, worded as the
/// library's [`Error::invalid`].
pub fn invalid(key: &str, value: impl std::fmt::Display, allowed: &str) -> PyErr {
    to_py(Error::invalid(key, value, allowed))
}

/// Runs `f`; a panic (a bug) becomes a `RuntimeError` instead of unwinding into Python.
pub fn guarded<T>(f: impl FnOnce() -> Result<T, PyErr>) -> Result<T, PyErr> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Err(PyRuntimeError::new_err(format!(
            "internal error in roughwall (please report): {what}"
        )))
    })
}

/// Runs `f` on a pool of `threads` threads (rayon), so that the library's parallel loops
/// use that many; 0 is every core.
pub fn on_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T, PyErr> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| PyRuntimeError::new_err(format!("could not start {threads} threads: {e}")))?;
    Ok(pool.install(f))
}
