//! The one error of the crate: which file, what is wrong with it, what is allowed; displayed
//! on one line (the command line prints it and exits 2).

use std::path::{Path, PathBuf};

/// What kind of failure a [`ReadError`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// The file could not be opened or read.
    Io,
    /// Neither the first bytes nor the extension name a format this crate reads.
    UnknownFormat,
    /// A valid file using a feature this crate does not read (data type, axis type, series…).
    Unsupported,
    /// The file contradicts its own format: bad zip or XML, impossible header values.
    Corrupt,
    /// The file ends before the data its header announces.
    Truncated,
    /// The header announces more points than [`crate::MAX_POINTS`] (refused before allocating).
    TooLarge,
    /// The file states no pixel size or no length unit, or a unit that is not a length.
    NoUnits,
    /// A checksum stored in the file does not match its content.
    Checksum,
    /// Too few points, or no valid point at all.
    NoData,
    /// An argument of [`crate::read_matrix`] or [`crate::read_xyz`] is not a positive length.
    BadArgument,
}

/// A failure to read a scan. `Display` gives one line: `FILE: what is wrong; what is allowed`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ReadError {
    path: PathBuf,
    kind: ErrorKind,
    message: String,
}

impl ReadError {
    pub(crate) fn new(path: &Path, problem: Problem) -> ReadError {
        ReadError {
            path: path.to_path_buf(),
            kind: problem.kind,
            message: one_line(&problem.message),
        }
    }

    /// The file that could not be read.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// What kind of failure this is.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// What is wrong and what is allowed, without the file name.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}: {}",
            one_line(&self.path.display().to_string()),
            self.message
        )
    }
}

impl std::error::Error for ReadError {}

/// Control characters (line breaks from a file's own text, say) become spaces.
fn one_line(s: &str) -> String {
    s.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// A failure inside a reader, before the file name is attached.
#[derive(Debug, Clone)]
pub(crate) struct Problem {
    pub kind: ErrorKind,
    pub message: String,
}

impl Problem {
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Problem {
        Problem {
            kind,
            message: message.into(),
        }
    }

    pub fn corrupt(message: impl Into<String>) -> Problem {
        Problem::new(ErrorKind::Corrupt, message)
    }

    pub fn unsupported(message: impl Into<String>) -> Problem {
        Problem::new(ErrorKind::Unsupported, message)
    }

    pub fn truncated(message: impl Into<String>) -> Problem {
        Problem::new(ErrorKind::Truncated, message)
    }

    pub fn no_units(message: impl Into<String>) -> Problem {
        Problem::new(ErrorKind::NoUnits, message)
    }

    pub fn io(e: &std::io::Error) -> Problem {
        Problem::new(ErrorKind::Io, format!("cannot read the file: {e}"))
    }
}

pub(crate) type Result<T> = std::result::Result<T, Problem>;

/// A text value quoted for a message: at most 40 characters, control characters as spaces.
pub(crate) fn quote(s: &str) -> String {
    let mut q: String = s.chars().take(40).collect();
    if s.chars().count() > 40 {
        q.push('…');
    }
    format!("`{}`", one_line(&q))
}
