//! Which format a file is: its first bytes (zip for X3P, `DIGITAL SURF`, the GSF magic line,
//! MetroPro's magic numbers, OPD's `Directory`), then its extension (`.plu` has no magic), then,
//! for text, its header lines.

use crate::error::{quote, ErrorKind, Problem, Result};
use crate::text::parse_numbers;
use crate::{gsf, gwyddion_text, metropro, opd, phase_text, sur, Format};
use std::io::{BufRead, Read};
use std::path::Path;

/// How much of the file detection looks at for magic bytes.
const HEAD: usize = 64 << 10;

/// Lines of text detection looks at: the header and the first rows of numbers.
const TEXT_LINES: usize = 80;

/// Bytes of text detection reads at most to find [`TEXT_LINES`] whole lines (a row of a wide
/// export is long: 8192 columns are about 130 KiB).
const TEXT_HEAD: u64 = 16 << 20;

pub(crate) fn detect(path: &Path) -> Result<Format> {
    let mut head = Vec::with_capacity(HEAD);
    std::fs::File::open(path)
        .and_then(|f| f.take(HEAD as u64).read_to_end(&mut head))
        .map_err(|e| Problem::io(&e))?;
    if let Some(f) = by_magic(&head) {
        return Ok(f);
    }
    // Text is judged on whole lines: a window that ends inside a number (a wide export's
    // first row is longer than the window) made a valid file unrecognisable (issue 42).
    let head = if head.len() == HEAD && !head.contains(&0) {
        text_head(path)?
    } else {
        head
    };
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    match ext.as_str() {
        "x3p" => return Ok(Format::X3p),
        "sur" => return Ok(Format::Sur),
        "gsf" => return Ok(Format::Gsf),
        "opd" => return Ok(Format::Opd),
        "plu" | "apx" => return Ok(Format::Plu),
        _ => {}
    }
    if let Some(f) = by_text(&head) {
        if f == Format::Matrix {
            // Named as what it is, before any advice to read it as a matrix (issue 39).
            let text = String::from_utf8_lossy(&head);
            let rows: Vec<Vec<f64>> = text
                .lines()
                .map(str::trim)
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .map_while(parse_numbers)
                .collect();
            crate::text::refuse_profile(rows.iter().map(Vec::as_slice))?;
        }
        return Ok(f);
    }
    Err(Problem::new(
        ErrorKind::UnknownFormat,
        format!(
            "neither the first bytes nor the extension {} name a format read here; allowed: \
             X3P (.x3p), Digital Surf (.sur), Gwyddion Simple Field (.gsf), Gwyddion text \
             export, phase-map text (h= w= pixel size=), Zygo MetroPro (.dat), Wyko (.opd), \
             Sensofar (.plu); a plain matrix or x y z text through read_matrix or read_xyz",
            quote(&format!(".{ext}"))
        ),
    ))
}

/// The first [`TEXT_LINES`] whole lines of `path` (at most [`TEXT_HEAD`] bytes), without a
/// line cut short by that limit.
fn text_head(path: &Path) -> Result<Vec<u8>> {
    let file = std::fs::File::open(path).map_err(|e| Problem::io(&e))?;
    let mut reader = std::io::BufReader::new(file.take(TEXT_HEAD));
    let mut head = Vec::new();
    for _ in 0..TEXT_LINES {
        let start = head.len();
        let n = reader
            .read_until(b'\n', &mut head)
            .map_err(|e| Problem::io(&e))?;
        if n == 0 {
            break;
        }
        if head.last() != Some(&b'\n') && head.len() as u64 == TEXT_HEAD {
            head.truncate(start);
            break;
        }
    }
    Ok(head)
}

/// The format whose magic bytes start `head`.
pub(crate) fn by_magic(head: &[u8]) -> Option<Format> {
    if head.starts_with(b"PK\x03\x04") {
        Some(Format::X3p)
    } else if head.starts_with(sur::MAGIC) {
        Some(Format::Sur)
    } else if head.starts_with(gsf::MAGIC) {
        Some(Format::Gsf)
    } else if metropro::MAGICS.iter().any(|m| head.starts_with(m)) {
        Some(Format::MetroPro)
    } else if head.get(2..2 + opd::MAGIC.len()) == Some(opd::MAGIC) {
        Some(Format::Opd)
    } else {
        None
    }
}

/// A text format, from the lines of `head` before its first row of numbers: Gwyddion's or the
/// phase-map header, x y z columns, or a plain matrix. `None` for binary content.
fn by_text(head: &[u8]) -> Option<Format> {
    if head.is_empty() || head.contains(&0) {
        return None;
    }
    let text = String::from_utf8_lossy(head);
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let mut header = Vec::new();
    let mut rows = Vec::new();
    for line in lines.by_ref() {
        match parse_numbers(line) {
            Some(row) => {
                rows.push(row);
                break;
            }
            None => header.push(line),
        }
    }
    rows.extend(lines.take(64).filter_map(parse_numbers));
    let first = rows.first()?;
    if header
        .iter()
        .any(|l| l.starts_with('#') && l.contains("Lateral units"))
        && first.len() == 3
    {
        return Some(Format::Xyz);
    }
    if header.iter().any(|l| gwyddion_text::is_header_line(l)) {
        return Some(Format::GwyddionText);
    }
    if header.iter().any(|l| phase_text::is_header_line(l)) {
        return Some(Format::PhaseText);
    }
    if header.iter().any(|l| !l.starts_with('#')) {
        return None;
    }
    // Without a header: x y z columns repeat a position along one axis from row to row.
    let repeats = |c: usize| rows.windows(2).any(|w| w[0].get(c) == w[1].get(c));
    if first.len() == 3 && rows.len() > 2 && (repeats(0) || repeats(1)) {
        Some(Format::Xyz)
    } else {
        Some(Format::Matrix)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_formats_are_told_apart_by_their_headers() {
        let gwy = b"# Channel: Z\n# Width: 1 um\n# Height: 1 um\n# Value units: m\n1 2 3\n4 5 6\n";
        assert_eq!(by_text(gwy), Some(Format::GwyddionText));
        let phase =
            b"h=2 w=3\npixel size=1e-6 m\nheight conversion factor (-> m)=1e-8\n1 2 3\n4 5 6\n";
        assert_eq!(by_text(phase), Some(Format::PhaseText));
        assert_eq!(by_text(b"0 0 1\n0 1 1\n1 0 2\n1 1 2\n"), Some(Format::Xyz));
        assert_eq!(by_text(b"1 2 3\n4 5 6\n7 8 9\n"), Some(Format::Matrix));
        assert_eq!(by_text(b"1 2 3 4\n5 6 7 8\n"), Some(Format::Matrix));
        assert_eq!(by_text(b"hello\nworld\n"), None);
        assert_eq!(by_text(b"\x00\x01\x02"), None);
    }

    /// A Gwyddion export whose first row is longer than the 64 KiB window, cut inside a
    /// number by that window wherever it falls, is still recognised (issue 42: 8192 columns).
    #[test]
    fn a_wide_text_export_is_recognised_wherever_the_window_ends() {
        let dir = tempfile::tempdir().unwrap();
        for pad in 0..12 {
            let mut text =
                String::from("# Channel: Z\n# Width: 8192 um\n# Height: 4 um\n# Value units: m\n");
            text.push_str(&"#".repeat(pad));
            text.push('\n');
            for row in 0..4 {
                let cells: Vec<String> = (0..8192)
                    .map(|i| format!("{:.9e}", 1e-7 * ((i * 7 + row) % 13) as f64 - 6e-7))
                    .collect();
                text.push_str(&cells.join(" "));
                text.push('\n');
            }
            let path = dir.path().join(format!("wide{pad}.txt"));
            std::fs::write(&path, &text).unwrap();
            assert_eq!(detect(&path).unwrap(), Format::GwyddionText, "pad {pad}");
        }
    }
}
