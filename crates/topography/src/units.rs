//! Length units as files write them (`m`, `mm`, `µm` in its several spellings, `nm`, …) and
//! their size in metres.

use crate::error::{quote, Problem, Result};

/// The units accepted, for messages.
pub(crate) const ALLOWED: &str = "m, cm, mm, µm (um), nm, pm, Å";

/// The length of one `unit` in metres, or `None` when `unit` is not a length unit. Accepts the
/// micro sign as U+00B5 or the Greek mu U+03BC, `u`, and `æ` (the micro sign of the MS-DOS code
/// page 437 read as Latin-1, as old Digital Surf files have it; SurfaceTopography's SUR.py
/// maps it the same way).
pub(crate) fn length_unit_m(unit: &str) -> Option<f64> {
    let u = unit.trim();
    let (prefix, rest) = match u.char_indices().nth(1) {
        Some((i, _)) => (&u[..i], &u[i..]),
        None => ("", u),
    };
    if u == "m" {
        return Some(1.0);
    }
    if u == "Å" || u == "A" || u == "\u{212B}" {
        return Some(1e-10);
    }
    if rest != "m" {
        return None;
    }
    match prefix {
        "k" => Some(1e3),
        "c" => Some(1e-2),
        "m" => Some(1e-3),
        "µ" | "μ" | "u" | "æ" => Some(1e-6),
        "n" => Some(1e-9),
        "p" => Some(1e-12),
        _ => None,
    }
}

/// Like [`length_unit_m`], but a unit that is not a length is an error naming `what`
/// (e.g. "the Value units").
pub(crate) fn require_length(unit: &str, what: &str) -> Result<f64> {
    length_unit_m(unit).ok_or_else(|| {
        Problem::no_units(format!(
            "{what} {} is not a length unit; allowed: {ALLOWED}",
            quote(unit)
        ))
    })
}

/// A length written as a number and a unit (`12.34 µm`, `1.0e-6 m`, `10.00µm`), in metres.
pub(crate) fn parse_length(s: &str, what: &str) -> Result<f64> {
    let s = s.trim();
    let split = s
        .char_indices()
        .find(|&(i, c)| {
            !(c.is_ascii_digit()
                || c == '.'
                || c == '+'
                || c == '-'
                || ((c == 'e' || c == 'E')
                    && s[i + 1..]
                        .starts_with(|d: char| d.is_ascii_digit() || d == '-' || d == '+')))
        })
        .map_or(s.len(), |(i, _)| i);
    let value: f64 = s[..split].trim().parse().map_err(|_| {
        Problem::corrupt(format!(
            "{what} {} is not a number followed by a unit (e.g. 10.5 µm)",
            quote(s)
        ))
    })?;
    let unit = s[split..].trim();
    if unit.is_empty() {
        return Err(Problem::no_units(format!(
            "{what} {} has no unit; allowed: {ALLOWED}",
            quote(s)
        )));
    }
    Ok(value * require_length(unit, &format!("the unit of {what}"))?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings_of_the_micrometre_are_one_unit() {
        for u in ["µm", "μm", "um", "æm", " µm "] {
            assert_eq!(length_unit_m(u), Some(1e-6), "{u}");
        }
        assert_eq!(length_unit_m("m"), Some(1.0));
        assert_eq!(length_unit_m("nm"), Some(1e-9));
        assert_eq!(length_unit_m("mm"), Some(1e-3));
        assert_eq!(length_unit_m("rad"), None);
        assert_eq!(length_unit_m("V"), None);
        assert_eq!(length_unit_m(""), None);
    }

    #[test]
    fn a_length_is_a_number_and_a_unit() {
        assert!((parse_length("12.34 µm", "Width").unwrap() - 12.34e-6).abs() < 1e-20);
        assert!((parse_length("1.0e-6 m", "Width").unwrap() - 1e-6).abs() < 1e-20);
        assert!((parse_length("10.00µm", "Width").unwrap() - 1e-5).abs() < 1e-20);
        assert!((parse_length("5678.9 nm", "Height").unwrap() - 5.6789e-6).abs() < 1e-20);
        assert!(parse_length("10", "Width").is_err());
        assert!(parse_length("ten µm", "Width").is_err());
        assert!(parse_length("10 V", "Width").is_err());
    }
}
