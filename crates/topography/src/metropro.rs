//! Zygo MetroPro `.dat`: a big-endian header (834 bytes for header formats 1 and 2, 4096 for
//! format 3), the intensity data, then the phase data: `cn_height` rows of `cn_width` 32-bit
//! big-endian integers, values ≥ 2147483640 marking invalid points. The layout is that of
//! SurfaceTopography 1.27.1's `IO/MetroPro.py` (after Gwyddion's `modules/file/metropro.c`
//! and Zygo's MetroPro Reference Guide).
//!
//! Header fields used (byte offset): magic (0), header size (6), intensity width, height and
//! buckets (52, 54, 56), phase width, height and byte count (68, 70, 72), time stamp (76),
//! interferometric scale factor S (164), wavelength λ in metres (168), obliquity factor O
//! (176), lateral resolution in metres per pixel (184), phase resolution (218: 0, 1, 2 for R =
//! 4096, 32768, 131072), sign (232). A height is `raw × S × O × λ / R` metres, negated when the
//! sign is set.

use crate::bytes::Bytes;
use crate::error::{Problem, Result};
use crate::grid::{check_data_len, check_pixel, check_shape};
use crate::{Format, Topography};

pub(crate) const MAGICS: [[u8; 4]; 3] = [
    [0x88, 0x1b, 0x03, 0x6f],
    [0x88, 0x1b, 0x03, 0x70],
    [0x88, 0x1b, 0x03, 0x71],
];

/// Phase values at or above this are invalid points.
const INVALID: i32 = 2_147_483_640;

pub(crate) fn parse(data: &[u8]) -> Result<Topography> {
    let h = Bytes::new(data, "MetroPro header");
    let magic = h.slice(0, 4)?;
    let Some(format) = MAGICS.iter().position(|m| m == magic) else {
        return Err(Problem::corrupt(
            "the file does not start with a MetroPro magic number",
        ));
    };
    let header_size = h.u32_be(6)? as usize;
    let expected = if format == 2 { 4096 } else { 834 };
    if header_size != expected {
        return Err(Problem::unsupported(format!(
            "the header size is {header_size} bytes; header format {} has {expected}",
            format + 1
        )));
    }
    h.slice(0, header_size)?;
    let intensity = 2 * h.u16_be(52)? as usize * h.u16_be(54)? as usize * h.u16_be(56)? as usize;
    let (nx, ny) = (h.u16_be(68)? as i64, h.u16_be(70)? as i64);
    let points = check_shape(nx, ny)?;
    let n_bytes = h.u32_be(72)? as usize;
    if n_bytes != 4 * points {
        return Err(Problem::corrupt(format!(
            "the phase data is declared as {n_bytes} bytes but {nx} × {ny} points of 4 bytes \
             take {}",
            4 * points
        )));
    }
    let scale_factor = h.f32_be(164)? as f64;
    let wavelength = h.f32_be(168)? as f64;
    let obliquity = h.f32_be(176)? as f64;
    let lateral = h.f32_be(184)? as f64;
    let resolution = match h.i16_be(218)? {
        0 => 4096.0,
        1 => 32768.0,
        2 => 131072.0,
        r => {
            return Err(Problem::unsupported(format!(
                "phase resolution code {r}; codes 0, 1, 2 are defined"
            )))
        }
    };
    let sign = if h.i16_be(232)? != 0 { -1.0 } else { 1.0 };
    if lateral <= 0.0 {
        return Err(Problem::no_units(
            "the lateral resolution is 0: the file has no lateral calibration; calibrate the \
             scan in MetroPro before exporting",
        ));
    }
    let start = header_size + intensity;
    let body = data.get(start..).unwrap_or(&[]);
    check_data_len(
        points,
        4,
        body.len(),
        "MetroPro phase data (32-bit integers)",
    )?;
    let scale = sign * scale_factor * obliquity * wavelength / resolution;
    let heights_m = body
        .chunks_exact(4)
        .take(points)
        .map(|c| {
            let raw = i32::from_be_bytes([c[0], c[1], c[2], c[3]]);
            if raw >= INVALID {
                f64::NAN
            } else {
                raw as f64 * scale
            }
        })
        .collect();
    let mut info = vec![
        ("vendor".to_string(), "Zygo".to_string()),
        ("wavelength".to_string(), format!("{wavelength:e} m")),
        ("time stamp".to_string(), h.i32_be(76)?.to_string()),
    ];
    for (key, offset, len) in [
        ("comment", 80, 82),
        ("objective", 246, 12),
        ("part name", 258, 40),
    ] {
        let v = h.text(offset, len)?;
        if !v.is_empty() {
            info.push((key.to_string(), v));
        }
    }
    Ok(Topography {
        nx: nx as usize,
        ny: ny as usize,
        dx_m: check_pixel(lateral, "x")?,
        dy_m: check_pixel(lateral, "y")?,
        heights_m,
        format: Format::MetroPro,
        info,
    })
}
