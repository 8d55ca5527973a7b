//! Gwyddion Simple Field `.gsf`, per its specification
//! (<http://gwyddion.net/documentation/user-guide-en/gsf.html>): the magic line
//! `Gwyddion Simple Field 1.0`, header lines `name = value` (XRes, YRes mandatory; XReal,
//! YReal, XOffset, YOffset, XYUnits, ZUnits, Title… optional), one to four NUL bytes padding
//! the header to a multiple of 4, then XRes × YRes little-endian 32-bit floats, row by row
//! (x fast). NaN marks a missing point.
//!
//! The specification lets XReal, YReal default to 1 and the units be absent; a wall scan
//! needs them, so a file without XReal, YReal, XYUnits or ZUnits is refused.

use crate::bytes::{decode_le, latin1};
use crate::error::{quote, Problem, Result};
use crate::grid::{check_data_len, check_pixel, check_shape};
use crate::units::require_length;
use crate::{Format, Topography};

pub(crate) const MAGIC: &[u8] = b"Gwyddion Simple Field 1.0\n";

pub(crate) fn parse(data: &[u8]) -> Result<Topography> {
    if !data.starts_with(MAGIC) {
        return Err(Problem::corrupt(
            "the file does not start with the line `Gwyddion Simple Field 1.0`",
        ));
    }
    let Some(nul) = data.iter().position(|&b| b == 0) else {
        return Err(Problem::truncated(
            "the header is not ended by a NUL byte (the file is cut short or is not GSF)",
        ));
    };
    let start = (nul / 4 + 1) * 4;
    if start > data.len() || data[nul..start].iter().any(|&b| b != 0) {
        return Err(Problem::corrupt(format!(
            "the header ends at byte {nul} but bytes {nul}..{start} are not all NUL; the header \
             is padded with 1 to 4 NUL bytes to a multiple of 4"
        )));
    }
    let header = match std::str::from_utf8(&data[MAGIC.len()..nul]) {
        Ok(s) => s.to_string(),
        Err(_) => latin1(&data[MAGIC.len()..nul]),
    };
    let mut fields: Vec<(String, String)> = Vec::new();
    for line in header.lines().map(str::trim).filter(|l| !l.is_empty()) {
        let Some((k, v)) = line.split_once('=') else {
            return Err(Problem::corrupt(format!(
                "header line {} is not `name = value`",
                quote(line)
            )));
        };
        fields.push((k.trim().to_string(), v.trim().to_string()));
    }
    let get = |name: &str| {
        fields
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    };
    let int = |name: &str| -> Result<i64> {
        let v = get(name).ok_or_else(|| {
            Problem::corrupt(format!(
                "the header has no {name}; XRes and YRes are mandatory"
            ))
        })?;
        v.parse()
            .map_err(|_| Problem::corrupt(format!("{name} = {} is not a whole number", quote(v))))
    };
    let real = |name: &str| -> Result<f64> {
        let v = get(name).ok_or_else(|| {
            Problem::no_units(format!(
                "the header has no {name}; the physical size is needed (XReal, YReal with XYUnits)"
            ))
        })?;
        v.parse()
            .map_err(|_| Problem::corrupt(format!("{name} = {} is not a number", quote(v))))
    };
    let unit = |name: &str| -> Result<f64> {
        let v = get(name).ok_or_else(|| {
            Problem::no_units(format!(
                "the header has no {name}; a wall scan needs its lengths' unit (e.g. {name} = m)"
            ))
        })?;
        require_length(v, name)
    };
    let (xres, yres) = (int("XRes")?, int("YRes")?);
    let points = check_shape(xres, yres)?;
    let body = &data[start..];
    check_data_len(points, 4, body.len(), "GSF data (32-bit floats)")?;
    if body.len() != points * 4 {
        return Err(Problem::corrupt(format!(
            "{} bytes follow the header but XRes × YRes = {points} floats take {}; the file \
             must end with the data",
            body.len(),
            points * 4
        )));
    }
    let xy = unit("XYUnits")?;
    let z = unit("ZUnits")?;
    let (nx, ny) = (xres as usize, yres as usize);
    let dx_m = check_pixel(real("XReal")? * xy / nx as f64, "x")?;
    let dy_m = check_pixel(real("YReal")? * xy / ny as f64, "y")?;
    let heights_m = decode_le::<4>(body, points, |b| f32::from_le_bytes(b) as f64 * z);
    let info = fields
        .into_iter()
        .filter(|(k, _)| !matches!(k.as_str(), "XRes" | "YRes"))
        .collect();
    Ok(Topography {
        nx,
        ny,
        dx_m,
        dy_m,
        heights_m: heights_m
            .into_iter()
            .map(|h| if h.is_finite() { h } else { f64::NAN })
            .collect(),
        format: Format::Gsf,
        info,
    })
}
