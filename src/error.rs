//! TEMPORARY stand-in for the lead's `crate::error` (design.md); replaced by main's on merge.
use std::fmt::{self, Display};

/// Errors of `rebound`.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// Bad case/CLI/input file (exit 2).
    Input(String),
    /// Not implemented (exit 2).
    NotImplemented(String),
    /// I/O failure (exit 1).
    Io(String),
}

/// Result alias.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// "invalid `key` = VALUE: allowed ALLOWED".
    pub fn invalid(key: &str, value: impl Display, allowed: &str) -> Self {
        Error::Input(format!("invalid `{key}` = {value}: allowed {allowed}"))
    }
}

impl Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(s) | Error::NotImplemented(s) | Error::Io(s) => f.write_str(s),
        }
    }
}

impl std::error::Error for Error {}
