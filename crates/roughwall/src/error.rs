//! One error type for the whole tool. Its kind decides the exit status:
//!
//! | status | kind |
//! | --- | --- |
//! | 0 | success |
//! | 1 | I/O: a file could not be read or written (disk full, permissions) |
//! | 2 | input: a wrong key, value, option or input file |
//! | 3 | model: valid input the model could not turn into a result (e.g. no particle history could be followed) |
//! | 4 | internal: a bug |

use std::fmt::{self, Display};
use std::path::Path;

/// An error of the library or the tool; its kind decides the process exit status
/// ([`Error::exit_code`], table in the module documentation). It displays on one line.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The user asked for something invalid: a wrong key, value or input file.
    Input(String),
    /// Reading or writing files failed.
    Io(String),
    /// Valid input that the model could not turn into a result.
    Model(String),
    /// A bug: something the code assumes did not hold.
    Internal(String),
}

/// `Result` with this crate's [`Error`].
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
            Error::Input(_) => 2,
            Error::Io(_) => 1,
            Error::Model(_) => 3,
            Error::Internal(_) => 4,
        }
    }
}

/// A message on one line, whatever it quotes (a case value may hold a newline).
fn one_line(m: &str) -> std::borrow::Cow<'_, str> {
    if m.contains(['\n', '\r']) {
        m.replace('\n', "\\n").replace('\r', "\\r").into()
    } else {
        m.into()
    }
}

impl Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(m) => write!(f, "{}", one_line(m)),
            Error::Io(m) => write!(f, "I/O error: {}", one_line(m)),
            Error::Model(m) => write!(f, "model: {}", one_line(m)),
            Error::Internal(m) => write!(f, "internal error (please report it): {}", one_line(m)),
        }
    }
}

impl std::error::Error for Error {}
