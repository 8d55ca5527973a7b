//! Sensofar `.plu` / `.apx`, after SurfaceTopography 1.27.1's `IO/PLU.py` and Gwyddion's
//! `modules/file/sensofar.c`. Little-endian; no magic bytes (the file starts with a date
//! string), so it is recognised by its extension.
//!
//! Fields used (byte offset): date (0, 128 characters), comment (132, 256), rows and columns
//! (388, 392), µm per pixel along x and y (404, 408), measurement type (428: 3 is a
//! topography), number of layers (489). The first layer follows at byte 500: rows (u32),
//! columns (u32), then rows × columns 32-bit floats in µm, x fast; 1000001 marks a point not
//! measured.

use crate::bytes::Bytes;
use crate::error::{Problem, Result};
use crate::grid::{check_data_len, check_pixel, check_shape};
use crate::{Format, Topography};

const TOPOGRAPHY: u32 = 3;
const NOT_MEASURED: f32 = 1_000_001.0;
const LAYERS: usize = 500;

pub(crate) fn parse(data: &[u8]) -> Result<Topography> {
    let b = Bytes::new(data, "PLU header");
    let kind = b.u32_le(428)?;
    if kind != TOPOGRAPHY {
        return Err(Problem::unsupported(format!(
            "the measurement type is {kind}; a topography (3) is read, not a profile or image"
        )));
    }
    if b.u8(489)? == 0 {
        return Err(Problem::corrupt("the file declares no data layer"));
    }
    let (rows, cols) = (b.u32_le(LAYERS)? as i64, b.u32_le(LAYERS + 4)? as i64);
    let (header_rows, header_cols) = (b.u32_le(388)? as i64, b.u32_le(392)? as i64);
    if (rows, cols) != (header_rows, header_cols) {
        return Err(Problem::corrupt(format!(
            "the header declares {header_cols} × {header_rows} points but the data layer \
             {cols} × {rows}"
        )));
    }
    let points = check_shape(cols, rows)?;
    let body = data.get(LAYERS + 8..).unwrap_or(&[]);
    check_data_len(points, 4, body.len(), "PLU heights (32-bit floats)")?;
    let heights_m = body
        .chunks_exact(4)
        .take(points)
        .map(|c| {
            let v = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
            if v == NOT_MEASURED || !v.is_finite() {
                f64::NAN
            } else {
                v as f64 * 1e-6
            }
        })
        .collect();
    let mut info = vec![("vendor".to_string(), "Sensofar".to_string())];
    for (key, offset, len) in [("date", 0, 128), ("comment", 132, 256)] {
        let v = b.text(offset, len)?;
        if !v.is_empty() {
            info.push((key.to_string(), v));
        }
    }
    Ok(Topography {
        nx: cols as usize,
        ny: rows as usize,
        dx_m: check_pixel(b.f32_le(404)? as f64 * 1e-6, "x")?,
        dy_m: check_pixel(b.f32_le(408)? as f64 * 1e-6, "y")?,
        heights_m,
        format: Format::Plu,
        info,
    })
}
