//! Phase-map text export: a header
//!
//! ```text
//! h=305 w=75
//! pixel size=3.69862e-007 m
//! data unit=rad
//! height conversion factor (-> m)=2.91818e-008
//! ```
//!
//! then `h` rows of `w` numbers (the phase, here in radians); a height is the number times the
//! conversion factor, in the unit named in `(-> …)`. `h` is the number of rows (points along
//! y), `w` the number of columns (along x), and the pixel is square. The keys are those
//! SurfaceTopography 1.27.1 reads in `IO/Text.py` (`AscReader`: `h`, `w`, `pixel size`,
//! `height conversion factor (-> unit)`); its examples `matrix-2.txt` and `matrix-4.txt` are
//! such files.

use crate::error::{quote, Problem, Result};
use crate::text::{key_value, read_rows};
use crate::units::{parse_length, require_length};
use crate::{Format, Topography};
use std::path::Path;

/// Whether a header line is one of this export's (used by format detection).
pub(crate) fn is_header_line(line: &str) -> bool {
    let l = line.trim();
    l.starts_with("h=") || l.starts_with("pixel size") || l.starts_with("height conversion factor")
}

/// `(-> m)=6.3e-8` in `height conversion factor (-> m)=6.3e-8`: the unit and the factor.
fn conversion(line: &str) -> Option<(&str, &str)> {
    let open = line.find("(->")?;
    let close = open + line[open..].find(')')?;
    let unit = line[open + 3..close].trim();
    let value = line[close + 1..].trim().strip_prefix('=')?.trim();
    Some((unit, value))
}

pub(crate) fn read(path: &Path) -> Result<Topography> {
    let (mut h, mut w, mut pixel, mut factor) = (None, None, None, None);
    let mut info = Vec::new();
    let rows = read_rows(path, |line_no, line| {
        let bad = || {
            Problem::corrupt(format!(
                "header line {line_no} {} is not understood; this export's header has \
                 `h=… w=…`, `pixel size=… m`, `data unit=…` and \
                 `height conversion factor (-> m)=…` lines",
                quote(line)
            ))
        };
        if line.starts_with("height conversion factor") {
            let (unit, value) = conversion(line).ok_or_else(bad)?;
            let unit_m = require_length(unit, "the unit of the height conversion factor")?;
            let f: f64 = value.parse().map_err(|_| bad())?;
            factor = Some(f * unit_m);
            info.push((
                "height conversion factor".to_string(),
                format!("{value} {unit}"),
            ));
        } else if line.starts_with("pixel size") {
            let (_, value) = key_value(line).ok_or_else(bad)?;
            pixel = Some(parse_length(value, "the pixel size")?);
        } else if line.starts_with("h=") || line.starts_with("w=") {
            for token in line.split_whitespace() {
                let (k, v) = token.split_once('=').ok_or_else(bad)?;
                let n: usize = v.parse().map_err(|_| bad())?;
                match k {
                    "h" => h = Some(n),
                    "w" => w = Some(n),
                    _ => return Err(bad()),
                }
            }
        } else {
            let (k, v) = key_value(line).ok_or_else(bad)?;
            info.push((k.to_string(), v.to_string()));
        }
        Ok(())
    })?;
    let missing = |what: &str| {
        Problem::no_units(format!(
            "the header has no `{what}` line; this export states `h=… w=…`, `pixel size=… m` \
             and `height conversion factor (-> m)=…`"
        ))
    };
    let pixel = pixel.ok_or_else(|| missing("pixel size=…"))?;
    let factor = factor.ok_or_else(|| missing("height conversion factor (-> m)=…"))?;
    let (nx, ny) = (rows.ncols, rows.nrows);
    for (declared, found, what) in [(w, nx, "w (columns)"), (h, ny, "h (rows)")] {
        if let Some(d) = declared {
            if d != found {
                return Err(Problem::corrupt(format!(
                    "the header declares {what} = {d} but the file has {found}; the numbers \
                     must fill h rows of w columns"
                )));
            }
        }
    }
    Ok(Topography {
        nx,
        ny,
        dx_m: pixel,
        dy_m: pixel,
        heights_m: rows.values.into_iter().map(|v| v * factor).collect(),
        format: Format::PhaseText,
        info,
    })
}
