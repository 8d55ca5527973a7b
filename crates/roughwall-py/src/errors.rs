//! The one boundary between the library's errors (and any panic) and Python exceptions:
//! a bad value is a `ValueError` with the library's one-line message (the C library's and
//! the command line's), a file problem an `OSError`, a size the process cannot hold a
//! `MemoryError` naming the argument that asked for it, a bug a `RuntimeError`. No panic
//! unwinds into the interpreter, and no allocation proportional to an argument aborts it:
//! each is checked against what the process may allocate ([`require`]) and made with
//! `try_reserve_exact` ([`zeroed`]).

use pyo3::exceptions::{PyMemoryError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::PyErr;
use roughwall::memory::FITS_IN_MEMORY;
use roughwall::Error;
use std::fmt::Display;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The Python exception for a library error: a size the library refuses because it does
/// not fit in memory (`roughwall::memory::require`, deep in a run or a characterisation) is a
/// `MemoryError`, as the binding's own checks make it.
pub fn to_py(e: Error) -> PyErr {
    match e {
        Error::Input(m) if m.contains(&format!("allowed {FITS_IN_MEMORY}")) => {
            PyMemoryError::new_err(m)
        }
        Error::Input(m) | Error::Model(m) => PyValueError::new_err(m),
        Error::Io(m) => PyOSError::new_err(m),
        Error::Internal(m) => {
            PyRuntimeError::new_err(format!("internal error in roughwall (please report): {m}"))
        }
    }
}

/// A `ValueError` naming the argument, the value and what is allowed, worded as the
/// library's [`Error::invalid`].
pub fn invalid(key: &str, value: impl Display, allowed: &str) -> PyErr {
    to_py(Error::invalid(key, value, allowed))
}

/// A `MemoryError` with the one-line message of [`Error::invalid`].
fn memory_error(key: &str, value: impl Display, allowed: &str) -> PyErr {
    PyMemoryError::new_err(Error::invalid(key, value, allowed).to_string())
}

/// `count · each` bytes, or a `MemoryError` naming `key = value` when the product does not
/// fit in 64 bits (no machine holds it).
pub fn bytes_of(
    key: &str,
    value: impl Display,
    count: usize,
    each: u64,
    what: &str,
) -> Result<u64, PyErr> {
    (count as u64).checked_mul(each).ok_or_else(|| {
        memory_error(
            key,
            value,
            &format!("{FITS_IN_MEMORY}: {what} needs {count} × {each} bytes, more than 2⁶⁴"),
        )
    })
}

/// `Ok` when the process may allocate `bytes` (the least of the address-space limit, the
/// cgroup limit and the free memory: `roughwall::memory::require`), else a `MemoryError`
/// naming `key = value` and what `what` needs.
pub fn require(key: &str, value: impl Display, bytes: u64, what: &str) -> Result<(), PyErr> {
    roughwall::memory::require(key, value, bytes, what).map_err(|e| match e {
        Error::Input(m) => PyMemoryError::new_err(m),
        other => to_py(other),
    })
}

/// An empty vector with room for `n` values, reserved with `try_reserve_exact`: an
/// allocation that fails is a `MemoryError` naming `key = value` and `what`, never an abort
/// of the interpreter.
pub fn with_capacity<T>(
    key: &str,
    value: impl Display,
    n: usize,
    what: &str,
) -> Result<Vec<T>, PyErr> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|e| {
        memory_error(
            key,
            value,
            &format!(
                "{FITS_IN_MEMORY}: {what} ({n} values of {} bytes) could not be allocated ({e})",
                std::mem::size_of::<T>()
            ),
        )
    })?;
    Ok(v)
}

/// `n` default values (zeros), allocated as [`with_capacity`] does.
pub fn zeroed<T: Clone + Default>(
    key: &str,
    value: impl Display,
    n: usize,
    what: &str,
) -> Result<Vec<T>, PyErr> {
    let mut v = with_capacity(key, value, n, what)?;
    v.resize(n, T::default());
    Ok(v)
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
        .map_err(|e| {
            let n = match threads {
                0 => "None (every core)".to_string(),
                t => t.to_string(),
            };
            PyOSError::new_err(format!(
                "`threads` = {n}: could not start the threads ({e})"
            ))
        })?;
    Ok(pool.install(f))
}
