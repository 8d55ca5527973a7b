//! Warnings: something the user should know while the run goes on. Library code returns
//! [`Warning`]s and never prints them; the binary prints them once the command has
//! succeeded. Low in the module picture so that every layer (output directories,
//! resolution, writers) can return them. Re-exported from `case`.

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
