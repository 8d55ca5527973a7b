//! Checkvalue-style helpers (after OpenMC's `checkvalue.py`): each check returns the value or
//! the one-line [`Error::invalid`] message naming the key, the value and what is allowed. The
//! range checks of every parameter go through them: the wall model's, and every section of a
//! case file in the application.

use crate::error::{Error, Result};
use std::path::Path;

pub use crate::warning::Warning;

/// `v` finite and within `[lo, hi]`; else the error with `allowed`.
pub fn check_range(key: &str, v: f64, lo: f64, hi: f64, allowed: &str) -> Result<f64> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(Error::invalid(key, v, allowed))
    }
}

/// `v` within `[lo, hi]` (the physical range of a key; `why` says what bounds it); the
/// message reads `lo to hi<unit> (why)`.
pub fn within(key: &str, v: f64, lo: f64, hi: f64, unit: &str, why: &str) -> Result<f64> {
    check_range(key, v, lo, hi, &format!("{lo} to {hi}{unit} ({why})"))
}

/// `v` finite and greater than `min` (or equal, with `equality`).
pub fn check_greater_than(
    key: &str,
    v: f64,
    min: f64,
    equality: bool,
    allowed: &str,
) -> Result<f64> {
    let ok = v.is_finite() && (v > min || (equality && v == min));
    if ok {
        Ok(v)
    } else {
        Err(Error::invalid(key, v, allowed))
    }
}

/// `v` finite and less than `max` (or equal, with `equality`).
pub fn check_less_than(key: &str, v: f64, max: f64, equality: bool, allowed: &str) -> Result<f64> {
    let ok = v.is_finite() && (v < max || (equality && v == max));
    if ok {
        Ok(v)
    } else {
        Err(Error::invalid(key, v, allowed))
    }
}

/// A positive finite number.
pub fn positive(key: &str, v: f64) -> Result<f64> {
    check_greater_than(key, v, 0.0, false, "a positive number")
}

/// An integer within `[lo, hi]`.
pub fn check_int_range(key: &str, v: i64, lo: i64, hi: i64, allowed: &str) -> Result<i64> {
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(Error::invalid(key, v, allowed))
    }
}

/// A name from a set: the index of `v` in `options`; else the error quoting `v`.
pub fn check_value(key: &str, v: &str, options: &[&str], allowed: &str) -> Result<usize> {
    options
        .iter()
        .position(|&o| o == v)
        .ok_or_else(|| Error::invalid(key, format!("\"{v}\""), allowed))
}

/// A list of at most `max` entries (`what`: the entries, e.g. "angles").
pub fn check_length(key: &str, len: usize, max: usize, what: &str, allowed: &str) -> Result<()> {
    if len > max {
        return Err(Error::invalid(
            key,
            format!("a list of {len} {what}"),
            allowed,
        ));
    }
    Ok(())
}

/// What a file type is, for messages: "a regular file", "a directory", "a symbolic link",
/// "a FIFO", "a character device", "a block device", "a socket".
pub fn file_type_name(ft: &std::fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if ft.is_fifo() {
        "a FIFO"
    } else if ft.is_char_device() {
        "a character device"
    } else if ft.is_block_device() {
        "a block device"
    } else if ft.is_socket() {
        "a socket"
    } else if ft.is_symlink() {
        "a symbolic link"
    } else if ft.is_dir() {
        "a directory"
    } else if ft.is_file() {
        "a regular file"
    } else {
        "not a regular file"
    }
}

/// What a path that exists but is not a regular file is ("a directory", "a FIFO", …; see
/// [`file_type_name`]); `None` for a regular file (after links) or a path that does not
/// exist. Read before opening: opening a FIFO would wait for a writer.
pub fn not_a_regular_file(path: &Path) -> Option<&'static str> {
    let t = std::fs::metadata(path).ok()?.file_type();
    (!t.is_file()).then(|| file_type_name(&t))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_key_value_and_allowed() {
        let e = check_range("a.b", 3.0, 0.0, 1.0, "0 to 1").unwrap_err();
        assert_eq!(e.to_string(), "invalid `a.b` = 3: allowed 0 to 1");
        assert!(check_range("a", f64::NAN, 0.0, 1.0, "").is_err());
        assert_eq!(positive("p", 2.0), Ok(2.0));
        assert!(positive("p", 0.0).is_err());
        assert!(check_greater_than("g", 0.0, 0.0, true, "").is_ok());
        assert!(check_less_than("l", 1.0, 1.0, false, "").is_err());
        assert_eq!(check_value("m", "b", &["a", "b"], "a or b"), Ok(1));
        let e = check_value("m", "c", &["a", "b"], "\"a\" or \"b\"").unwrap_err();
        assert_eq!(e.to_string(), "invalid `m` = \"c\": allowed \"a\" or \"b\"");
    }

    #[test]
    fn devices_and_directories_are_not_regular_files() {
        assert_eq!(
            not_a_regular_file(Path::new("/dev/null")),
            Some("a character device")
        );
        assert_eq!(not_a_regular_file(Path::new("/tmp")), Some("a directory"));
        assert_eq!(not_a_regular_file(Path::new("/definitely/not/here")), None);
        let here = Path::new(env!("CARGO_MANIFEST_DIR"));
        assert_eq!(not_a_regular_file(here), Some("a directory"));
        assert_eq!(not_a_regular_file(&here.join("Cargo.toml")), None);
    }
}
