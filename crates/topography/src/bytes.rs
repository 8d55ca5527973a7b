//! Reading a binary file whole (its size checked first) and bounds-checked little- and
//! big-endian fields of it: a field past the end is a one-line `Truncated` error, never a panic.

use crate::error::{ErrorKind, Problem, Result};
use crate::grid::MAX_POINTS;
use std::path::Path;

/// The largest binary file read: `MAX_POINTS` 8-byte values and 64 MiB of headers and side
/// images (PLU's colour images, OPD's intensity blocks).
pub(crate) const MAX_FILE_BYTES: u64 = MAX_POINTS as u64 * 8 + (64 << 20);

/// The bytes of `path`, refusing a file larger than [`MAX_FILE_BYTES`] before reading it.
pub(crate) fn read_file(path: &Path) -> Result<Vec<u8>> {
    let len = std::fs::metadata(path).map_err(|e| Problem::io(&e))?.len();
    if len > MAX_FILE_BYTES {
        return Err(Problem::new(
            ErrorKind::TooLarge,
            format!(
                "the file holds {len} bytes; a binary scan of at most {MAX_POINTS} points \
                 ({MAX_FILE_BYTES} bytes) is read"
            ),
        ));
    }
    std::fs::read(path).map_err(|e| Problem::io(&e))
}

/// A byte buffer with checked reads; `what` names it in messages (`SUR header`, `OPD file`).
pub(crate) struct Bytes<'a> {
    pub data: &'a [u8],
    pub what: &'static str,
}

impl<'a> Bytes<'a> {
    pub fn new(data: &'a [u8], what: &'static str) -> Bytes<'a> {
        Bytes { data, what }
    }

    /// `len` bytes from `offset`, or a `Truncated` error naming the byte needed.
    pub fn slice(&self, offset: usize, len: usize) -> Result<&'a [u8]> {
        match offset.checked_add(len) {
            Some(end) if end <= self.data.len() => Ok(&self.data[offset..end]),
            _ => Err(Problem::truncated(format!(
                "the {} is cut short: it ends at byte {}, before byte {} that it needs",
                self.what,
                self.data.len(),
                offset.saturating_add(len)
            ))),
        }
    }

    fn array<const N: usize>(&self, offset: usize) -> Result<[u8; N]> {
        let mut a = [0u8; N];
        a.copy_from_slice(self.slice(offset, N)?);
        Ok(a)
    }

    pub fn u8(&self, offset: usize) -> Result<u8> {
        Ok(self.array::<1>(offset)?[0])
    }
    pub fn u16_le(&self, offset: usize) -> Result<u16> {
        self.array(offset).map(u16::from_le_bytes)
    }
    pub fn i16_le(&self, offset: usize) -> Result<i16> {
        self.array(offset).map(i16::from_le_bytes)
    }
    pub fn u32_le(&self, offset: usize) -> Result<u32> {
        self.array(offset).map(u32::from_le_bytes)
    }
    pub fn i32_le(&self, offset: usize) -> Result<i32> {
        self.array(offset).map(i32::from_le_bytes)
    }
    pub fn f32_le(&self, offset: usize) -> Result<f32> {
        self.array(offset).map(f32::from_le_bytes)
    }
    pub fn f64_le(&self, offset: usize) -> Result<f64> {
        self.array(offset).map(f64::from_le_bytes)
    }
    pub fn u16_be(&self, offset: usize) -> Result<u16> {
        self.array(offset).map(u16::from_be_bytes)
    }
    pub fn i16_be(&self, offset: usize) -> Result<i16> {
        self.array(offset).map(i16::from_be_bytes)
    }
    pub fn u32_be(&self, offset: usize) -> Result<u32> {
        self.array(offset).map(u32::from_be_bytes)
    }
    pub fn i32_be(&self, offset: usize) -> Result<i32> {
        self.array(offset).map(i32::from_be_bytes)
    }
    pub fn f32_be(&self, offset: usize) -> Result<f32> {
        self.array(offset).map(f32::from_be_bytes)
    }

    /// A fixed-width text field: Latin-1 (as the instruments write it), cut at the first NUL,
    /// trimmed of spaces.
    pub fn text(&self, offset: usize, len: usize) -> Result<String> {
        let raw = self.slice(offset, len)?;
        let end = raw.iter().position(|&b| b == 0).unwrap_or(raw.len());
        Ok(latin1(&raw[..end]).trim().to_string())
    }
}

/// Latin-1 bytes as text (every byte is the code point of the same value).
pub(crate) fn latin1(bytes: &[u8]) -> String {
    bytes.iter().map(|&b| char::from(b)).collect()
}

/// `n` little-endian values of `size` bytes each from `data`, converted by `f`; the caller
/// has checked that `data` holds them.
pub(crate) fn decode_le<const N: usize>(
    data: &[u8],
    n: usize,
    f: impl Fn([u8; N]) -> f64,
) -> Vec<f64> {
    data.chunks_exact(N)
        .take(n)
        .map(|c| {
            let mut a = [0u8; N];
            a.copy_from_slice(c);
            f(a)
        })
        .collect()
}
