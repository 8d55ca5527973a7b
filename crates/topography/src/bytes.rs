//! Reading a binary file whole (its size checked first) and bounds-checked little- and
//! big-endian fields of it: a field past the end is a one-line `Truncated` error, never a panic.

use crate::error::{ErrorKind, Problem, Result};
use crate::grid::MAX_POINTS;
use std::io::Read;
use std::path::Path;

/// The largest binary file read: `MAX_POINTS` 8-byte values and 64 MiB of headers and side
/// images (PLU's colour images, OPD's intensity blocks).
pub(crate) const MAX_FILE_BYTES: u64 = MAX_POINTS as u64 * 8 + (64 << 20);

/// The most read from a file that reports a size of 0 (`/proc` files, some network mounts):
/// such a stream may never end (issue 42 read `/proc/self/pagemap` to 4 GB).
pub(crate) const STREAM_BYTES: u64 = 256 << 20;

/// The bytes of `path`: refused before reading when the size it reports is over
/// [`MAX_FILE_BYTES`]; read up to that size (or [`STREAM_BYTES`] when it reports none) and
/// refused when it goes on past it; refused, not aborted, when the memory runs out.
pub(crate) fn read_file(path: &Path) -> Result<Vec<u8>> {
    let too_large = |what: String| {
        Problem::new(
            ErrorKind::TooLarge,
            format!(
                "the file {what}; a binary scan of at most {MAX_POINTS} points \
                 ({MAX_FILE_BYTES} bytes) is read"
            ),
        )
    };
    let file = std::fs::File::open(path).map_err(|e| Problem::io(&e))?;
    let len = file.metadata().map_err(|e| Problem::io(&e))?.len();
    if len > MAX_FILE_BYTES {
        return Err(too_large(format!("holds {len} bytes")));
    }
    let limit = if len == 0 { STREAM_BYTES } else { len };
    // Room for what the file reports; a stream that reports nothing grows as it is read.
    let mut data = Vec::new();
    data.try_reserve_exact(len as usize)
        .map_err(|_| too_large(format!("of {len} bytes does not fit in memory")))?;
    // Whole chunks of 64 KiB: some special files refuse reads of other sizes (pagemap wants
    // multiples of 8), and one chunk past the limit tells a stream that goes on.
    let mut file = file;
    let mut chunk = vec![0u8; 64 << 10];
    while data.len() as u64 <= limit {
        let n = match file.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(Problem::io(&e)),
        };
        data.try_reserve(n).map_err(|_| {
            too_large(format!(
                "of over {} bytes does not fit in memory",
                data.len()
            ))
        })?;
        data.extend_from_slice(&chunk[..n]);
    }
    if data.len() as u64 > limit {
        return Err(too_large(if len == 0 {
            format!("reports no size and goes on past {STREAM_BYTES} bytes, the most read from such a stream")
        } else {
            format!("reports {len} bytes but goes on past them (it changed while being read)")
        }));
    }
    Ok(data)
}

/// Refuses what is not a regular file before it is opened: opening a FIFO blocks until a
/// writer comes, and a device or a directory is no scan (issue 42: Python's `read_scan`
/// blocked forever on a FIFO).
pub(crate) fn check_regular_file(path: &Path) -> Result<()> {
    let t = std::fs::metadata(path)
        .map_err(|e| Problem::io(&e))?
        .file_type();
    if t.is_file() {
        return Ok(());
    }
    use std::os::unix::fs::FileTypeExt;
    let kind = if t.is_dir() {
        "a directory"
    } else if t.is_fifo() {
        "a FIFO (named pipe)"
    } else if t.is_socket() {
        "a socket"
    } else if t.is_char_device() || t.is_block_device() {
        "a device"
    } else {
        "not a regular file"
    };
    Err(Problem::new(
        ErrorKind::Io,
        format!("this is {kind}; a scan is read from a regular file"),
    ))
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
