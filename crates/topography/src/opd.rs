//! Wyko (Bruker Vision) `.opd`, after SurfaceTopography 1.27.1's `IO/OPD.py` and Gwyddion's
//! `modules/file/opdfile.c`. Little-endian. Two bytes, then a directory of 24-byte entries
//! (name: 16 bytes, type: i16, length: i32, attributes: u16), the first named `Directory`
//! whose length is the directory's own; the blocks' contents follow the directory in its order,
//! each `length` bytes long.
//!
//! The first array block (type 3) named `RAW DATA`, `RAW_DATA`, `OPD`, `Raw` or `SAMPLE_DATA`
//! holds the heights: width (u16), height (u16), bytes per point (u16: 1, 2 or 4 for u8, i16,
//! f32), then the points with x as the slow index, and y reversed. Heights are in waves:
//! `raw × Wavelength / Mult` nanometres (`Mult` defaults to 1); `Pixel_size` is in
//! millimetres, the y pixel `Pixel_size × Aspect`. Points at or above 32766 (i16) or 1e38, or
//! not finite (f32), are invalid.

use crate::bytes::Bytes;
use crate::error::{Problem, Result};
use crate::grid::{check_data_len, check_pixel, check_shape};
use crate::{Format, Topography};

/// `Directory` after the two-byte prelude.
pub(crate) const MAGIC: &[u8] = b"Directory";
const ENTRY: usize = 24;
const HEIGHT_ARRAYS: [&str; 5] = ["RAW DATA", "RAW_DATA", "OPD", "Raw", "SAMPLE_DATA"];

/// A scalar or text block of the directory.
enum Value {
    Number(f64),
    Text(String),
}

pub(crate) fn parse(data: &[u8]) -> Result<Topography> {
    let b = Bytes::new(data, "OPD file");
    if b.text(2, 16)? != "Directory" {
        return Err(Problem::corrupt(
            "the file does not start with an OPD `Directory` block",
        ));
    }
    let dir_len = b.i32_le(20)?;
    if dir_len <= 0 || !(dir_len as usize).is_multiple_of(ENTRY) {
        return Err(Problem::corrupt(format!(
            "the directory is {dir_len} bytes long; it must be a positive multiple of {ENTRY}"
        )));
    }
    let dir_len = dir_len as usize;
    b.slice(2, dir_len)?;
    let mut pos = 2 + dir_len;
    let mut values: Vec<(String, Value)> = Vec::new();
    let mut raster = None;
    for i in 1..dir_len / ENTRY {
        let e = 2 + i * ENTRY;
        let name = b.text(e, 16)?;
        let kind = b.i16_le(e + 16)?;
        let len = b.i32_le(e + 18)?;
        if len <= 0 {
            continue;
        }
        let len = len as usize;
        let at = pos;
        pos = pos.saturating_add(len);
        let value = match (kind, len) {
            (3, _) if raster.is_none() && HEIGHT_ARRAYS.contains(&name.as_str()) => {
                raster = Some((name.clone(), at, len));
                continue;
            }
            (5, _) => Value::Text(b.text(at, len.min(256))?),
            (6, 2) | (7, 2) => Value::Number(b.i16_le(at)? as f64),
            (6, 4) | (12, 4..) => Value::Number(b.i32_le(at)? as f64),
            (7, 4..) => Value::Number(b.f32_le(at)? as f64),
            (8, 8..) => Value::Number(b.f64_le(at)?),
            _ => continue,
        };
        values.push((name, value));
    }
    let number = |key: &str| {
        values.iter().find_map(|(k, v)| match v {
            Value::Number(x) if k == key => Some(*x),
            _ => None,
        })
    };
    let Some((block, at, len)) = raster else {
        return Err(Problem::unsupported(format!(
            "no height array; the heights are an array block named one of {}",
            HEIGHT_ARRAYS.join(", ")
        )));
    };
    let wavelength = number("Wavelength").ok_or_else(|| {
        Problem::no_units("the file has no Wavelength block: the heights' scale is unknown")
    })?;
    let pixel_mm = number("Pixel_size").ok_or_else(|| {
        Problem::no_units("the file has no Pixel_size block: the lateral scale is unknown")
    })?;
    let mult = number("Mult").unwrap_or(1.0);
    let aspect = number("Aspect").unwrap_or(1.0);
    let r = Bytes::new(b.slice(at, len)?, "OPD height array");
    let (nx, ny, size) = (
        r.u16_le(0)? as i64,
        r.u16_le(2)? as i64,
        r.u16_le(4)? as usize,
    );
    let points = check_shape(nx, ny)?;
    if !matches!(size, 1 | 2 | 4) {
        return Err(Problem::unsupported(format!(
            "{size} bytes per point; 1, 2 and 4 (u8, i16, f32) are read"
        )));
    }
    let body = &r.data[6..];
    check_data_len(points, size, body.len(), &format!("OPD array {block}"))?;
    let (nx, ny) = (nx as usize, ny as usize);
    let scale = wavelength / mult * 1e-9;
    let mut heights = vec![0.0; points];
    for ix in 0..nx {
        for j in 0..ny {
            let k = ix * ny + j;
            let v = match size {
                1 => body[k] as f64,
                2 => {
                    let v = i16::from_le_bytes([body[2 * k], body[2 * k + 1]]);
                    if v >= 32766 {
                        f64::NAN
                    } else {
                        v as f64
                    }
                }
                _ => {
                    let v = f32::from_le_bytes([
                        body[4 * k],
                        body[4 * k + 1],
                        body[4 * k + 2],
                        body[4 * k + 3],
                    ]);
                    if !v.is_finite() || v >= 1e38 {
                        f64::NAN
                    } else {
                        v as f64
                    }
                }
            };
            heights[(ny - 1 - j) * nx + ix] = v * scale;
        }
    }
    let mut info = vec![
        ("vendor".to_string(), "Wyko".to_string()),
        ("channel".to_string(), block),
        ("wavelength".to_string(), format!("{wavelength:e} nm")),
    ];
    for (k, v) in &values {
        if let Value::Text(t) = v {
            if !t.is_empty() {
                info.push((k.to_lowercase(), t.clone()));
            }
        }
    }
    Ok(Topography {
        nx,
        ny,
        dx_m: check_pixel(pixel_mm * 1e-3, "x")?,
        dy_m: check_pixel(pixel_mm * aspect * 1e-3, "y")?,
        heights_m: heights,
        format: Format::Opd,
        info,
    })
}
