//! Numbers in text files, read line by line: header lines before the numbers, then rows of
//! equal length. Shared by the text formats (Gwyddion text, phase text, matrix, x-y-z).

use crate::error::{quote, ErrorKind, Problem, Result};
use crate::grid::MAX_POINTS;
use std::io::{BufRead, Read};
use std::path::Path;

/// The longest line read (64 MiB: a row of millions of numbers); a longer one is refused
/// rather than buffered.
const MAX_LINE: u64 = 64 << 20;

/// Rows of numbers: `values[row * ncols + col]`.
pub(crate) struct Rows {
    pub values: Vec<f64>,
    pub ncols: usize,
    pub nrows: usize,
}

/// A refusal when `rows` (each a row of numbers) are two columns whose first rises or falls
/// in equal steps: the x and z of a line profile, which read as a matrix would give a 2 × N
/// "surface" whose first column of heights is the positions (issue 39). A real two-column
/// height field has no such column.
pub(crate) fn refuse_profile<'a>(rows: impl Iterator<Item = &'a [f64]>) -> Result<()> {
    let firsts: Vec<f64> = rows
        .map(|r| if r.len() == 2 { r[0] } else { f64::NAN })
        .collect();
    if firsts.len() < 3 || firsts.iter().any(|v| !v.is_finite()) {
        return Ok(());
    }
    let step = firsts[1] - firsts[0];
    let scale = firsts
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()))
        .max(step.abs());
    let even = step != 0.0
        && firsts
            .windows(2)
            .all(|w| ((w[1] - w[0]) - step).abs() <= 1e-6 * scale);
    if even {
        return Err(Problem::unsupported(format!(
            "two columns whose first goes from {} in equal steps of {}: an x, z line profile, \
             not a surface; a height field is a grid of heights (one row per y, one column per \
             x), as an areal scan exports it",
            firsts[0], step
        )));
    }
    Ok(())
}

/// The numbers of a line split at whitespace, commas and semicolons, or `None` when a token
/// is not a number. `NaN`, `bad`, `inf` and `infinite` (any case, any sign) and infinite values
/// are missing points: NaN (as SurfaceTopography's Text.py reads them).
pub(crate) fn parse_numbers(line: &str) -> Option<Vec<f64>> {
    let mut out = Vec::new();
    for token in line
        .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|t| !t.is_empty())
    {
        let bare = token.trim_start_matches(['+', '-']).to_ascii_lowercase();
        let v = if matches!(
            bare.as_str(),
            "nan" | "bad" | "inf" | "infinite" | "infinity"
        ) {
            f64::NAN
        } else {
            let v: f64 = token.parse().ok()?;
            if v.is_finite() {
                v
            } else {
                f64::NAN
            }
        };
        out.push(v);
    }
    (!out.is_empty()).then_some(out)
}

/// Reads `path` line by line. Lines before the first row of numbers go to `header` (with their
/// 1-based line number); empty lines are skipped; after the numbers have started, any other
/// line is an error. At most [`MAX_POINTS`] numbers are kept.
pub(crate) fn read_rows(
    path: &Path,
    mut header: impl FnMut(usize, &str) -> Result<()>,
) -> Result<Rows> {
    let file = std::fs::File::open(path).map_err(|e| Problem::io(&e))?;
    let mut reader = std::io::BufReader::new(file);
    let mut rows = Rows {
        values: Vec::new(),
        ncols: 0,
        nrows: 0,
    };
    let mut buf = Vec::new();
    let mut line_no = 0;
    loop {
        buf.clear();
        let n = (&mut reader)
            .take(MAX_LINE + 1)
            .read_until(b'\n', &mut buf)
            .map_err(|e| Problem::io(&e))?;
        if n == 0 {
            break;
        }
        line_no += 1;
        if n as u64 > MAX_LINE {
            return Err(Problem::new(
                ErrorKind::TooLarge,
                format!("line {line_no} is longer than {MAX_LINE} bytes, the longest read"),
            ));
        }
        let line = decode(&buf, line_no == 1);
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        match parse_numbers(line) {
            Some(numbers) => {
                if rows.nrows == 0 {
                    rows.ncols = numbers.len();
                } else if numbers.len() != rows.ncols {
                    return Err(Problem::corrupt(format!(
                        "line {line_no} has {} numbers but the rows before it have {}; \
                         every row must have the same number of columns",
                        numbers.len(),
                        rows.ncols
                    )));
                }
                if rows.values.len() + numbers.len() > MAX_POINTS {
                    return Err(Problem::new(
                        ErrorKind::TooLarge,
                        format!(
                            "line {line_no}: the file holds more than {MAX_POINTS} (2^28) numbers, \
                             the most that is read"
                        ),
                    ));
                }
                rows.values.extend(numbers);
                rows.nrows += 1;
            }
            None if rows.nrows == 0 => header(line_no, line)?,
            None if line.starts_with('#') => {
                return Err(Problem::unsupported(format!(
                    "line {line_no} {} starts a second header after the numbers; one channel \
                     per file is read (export one channel at a time)",
                    quote(line)
                )))
            }
            None => {
                return Err(Problem::corrupt(format!(
                    "line {line_no} {} is not numbers; after the header every line must be a \
                     row of numbers (NaN for a missing point)",
                    quote(line)
                )))
            }
        }
    }
    if rows.nrows == 0 {
        return Err(Problem::new(
            ErrorKind::NoData,
            "the file holds no row of numbers; a height field is a matrix of numbers (or x y z \
             columns) after an optional header",
        ));
    }
    Ok(rows)
}

/// A line as text: UTF-8 when it is, else Latin-1 (the micro sign of older exports); a byte
/// order mark on the first line is dropped.
fn decode(bytes: &[u8], first: bool) -> String {
    let bytes = if first {
        bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes)
    } else {
        bytes
    };
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_string(),
        Err(_) => crate::bytes::latin1(bytes),
    }
}

/// A `key = value` or `key: value` line (after a leading `#`), split at the first `=`, `:` or
/// full-width colon.
pub(crate) fn key_value(line: &str) -> Option<(&str, &str)> {
    let line = line.trim_start_matches('#').trim();
    let i = line.find(['=', ':', '：'])?;
    let sep_len = line[i..].chars().next().map_or(1, char::len_utf8);
    Some((line[..i].trim(), line[i + sep_len..].trim()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_split_at_whitespace_commas_and_semicolons() {
        assert_eq!(parse_numbers("1 2.5\t-3e-2"), Some(vec![1.0, 2.5, -0.03]));
        assert_eq!(parse_numbers("1,2;3"), Some(vec![1.0, 2.0, 3.0]));
        let v = parse_numbers("1 NaN bad -inf").unwrap();
        assert_eq!(v[0], 1.0);
        assert!(v[1..].iter().all(|x| x.is_nan()));
        assert_eq!(parse_numbers("# Width: 1 µm"), None);
        assert_eq!(parse_numbers("h=650 w=650"), None);
        assert_eq!(parse_numbers("   "), None);
    }

    #[test]
    fn key_values_split_at_the_first_separator() {
        assert_eq!(key_value("# Width: 12.34 µm"), Some(("Width", "12.34 µm")));
        assert_eq!(
            key_value("height conversion factor (-> m)=6.3e-8"),
            Some(("height conversion factor (-> m)", "6.3e-8"))
        );
        assert_eq!(key_value("# 幅：10 µm"), Some(("幅", "10 µm")));
        assert_eq!(key_value("no separator"), None);
    }
}
