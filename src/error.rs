//! One error type for the whole tool. Its variant decides the exit status:
//! bad input (case file, command line, input file) and not-yet-implemented
//! models exit with 2, everything else with 1.

use std::fmt::{self, Display};
use std::path::Path;

#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The user asked for something invalid: a wrong key, value or input file.
    Input(String),
    /// A model or subcommand that is not implemented: an honest refusal.
    NotImplemented(String),
    /// Reading or writing files failed.
    Io(String),
}

pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// The one-line message for a bad value: names the key, the value and what is allowed.
    pub fn invalid(key: &str, value: impl Display, allowed: &str) -> Error {
        Error::Input(format!("invalid `{key}` = {value}: allowed {allowed}"))
    }

    /// An I/O failure on `path`.
    pub fn io(path: &Path, err: impl Display) -> Error {
        Error::Io(format!("{}: {err}", path.display()))
    }

    /// Process exit status for this error.
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Input(_) | Error::NotImplemented(_) => 2,
            Error::Io(_) => 1,
        }
    }
}

impl Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(m) => write!(f, "{m}"),
            Error::NotImplemented(m) => write!(f, "not implemented yet: {m}"),
            Error::Io(m) => write!(f, "I/O error: {m}"),
        }
    }
}

impl std::error::Error for Error {}
