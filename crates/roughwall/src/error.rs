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
    /// A number far from 1 is written in its shortest exponent form (`1e-300`, not 300
    /// digits).
    pub fn invalid(key: &str, value: impl Display, allowed: &str) -> Error {
        let value = compact_number(value.to_string());
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

/// `text` unchanged, unless it is a number whose plain decimal form is long (below 1e-5 or
/// from 1e16 in magnitude): then the same number in its shortest round-trip exponent form.
fn compact_number(text: String) -> String {
    match text.parse::<f64>() {
        Ok(x)
            if x.is_finite()
                && text.len() > 18
                && text
                    .bytes()
                    .all(|b| b.is_ascii_digit() || b == b'.' || b == b'-') =>
        {
            format!("{x:e}")
        }
        _ => text,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_far_from_one_are_written_short() {
        let m = |v: f64| Error::invalid("k", v, "x").to_string();
        assert_eq!(m(25.0), "invalid `k` = 25: allowed x");
        assert_eq!(m(-0.5), "invalid `k` = -0.5: allowed x");
        assert_eq!(m(1e-300), "invalid `k` = 1e-300: allowed x");
        assert_eq!(m(-2.5e-7), "invalid `k` = -0.00000025: allowed x");
        assert_eq!(m(-2.5e-17), "invalid `k` = -2.5e-17: allowed x");
        assert_eq!(m(1e300), "invalid `k` = 1e300: allowed x");
        assert_eq!(m(f64::NAN), "invalid `k` = NaN: allowed x");
        assert_eq!(m(123456.789), "invalid `k` = 123456.789: allowed x");
        // Text stays text.
        assert_eq!(
            Error::invalid("k", "\"00000000000000000000001\"", "x").to_string(),
            "invalid `k` = \"00000000000000000000001\": allowed x"
        );
    }
}
