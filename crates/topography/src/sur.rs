//! Digital Surf `.sur` (MountainsMap), one surface object. The layout is that of
//! SurfaceTopography 1.27.1's `IO/SUR.py` and Gwyddion's `modules/file/surffile.c`: a
//! 512-byte little-endian header, a comment and a private zone of the sizes it states, then
//! ny rows of nx 16- or 32-bit signed integers.
//!
//! Header fields used (byte offset): magic `DIGITAL SURF` (0), object count (14), object type
//! (18: 1 profile, 2 surface), object and instrument names (20, 50), special points (86: 1 when
//! non-measured points exist), bits per point (98), zmin (100), nx (108), ny (112), point
//! count (116), x/y/z spacing (120, 124, 128, 32-bit floats), the x/y/z step units (180, 196,
//! 212, 16 characters each), inversion (290), date (306…316), comment and private zone sizes
//! (334, 336), z offset (474).
//!
//! A height is `raw × z spacing + z offset` in the z step unit, the offset added as Gwyddion's
//! `surffile.c` and HyperSpy's reader (`rsciio/digitalsurf`) add it (SurfaceTopography leaves it
//! out: `sur-3.sur` of its examples states −3.41 mm, the only difference between the two
//! readings, recorded in `info` as `z offset (m)`); a point whose raw value
//! is `zmin − 2` when special points are flagged is not measured (NaN), as in
//! SurfaceTopography and HyperSpy's reader. Inversion 1 negates the raw heights, 2 also mirrors
//! x, 3 also mirrors y (Gwyddion's `surffile.c`, SurfaceTopography), before the offset is added.

use crate::bytes::Bytes;
use crate::error::{Problem, Result};
use crate::grid::{check_data_len, check_pixel, check_shape};
use crate::units::require_length;
use crate::{Format, Topography};

pub(crate) const MAGIC: &[u8] = b"DIGITAL SURF";
const HEADER: usize = 512;

pub(crate) fn parse(data: &[u8]) -> Result<Topography> {
    let h = Bytes::new(data, "SUR header");
    if !data.starts_with(MAGIC) {
        return Err(Problem::corrupt(
            "the file does not start with `DIGITAL SURF`",
        ));
    }
    h.slice(0, HEADER)?;
    let objects = h.u16_le(14)?;
    let object_type = h.u16_le(18)?;
    if objects > 1 {
        return Err(Problem::unsupported(format!(
            "the file holds {objects} objects; one surface per file is read (export the \
             surface on its own from MountainsMap)"
        )));
    }
    if object_type != 2 && object_type != 1 {
        return Err(Problem::unsupported(format!(
            "the object type is {object_type}; a surface (2) is read, not a series, binary \
             image, spectrum or RGB object"
        )));
    }
    let special_points = h.u16_le(86)?;
    let bits = h.u16_le(98)?;
    if bits != 16 && bits != 32 {
        return Err(Problem::unsupported(format!(
            "points of {bits} bits; 16- and 32-bit integers are read"
        )));
    }
    let zmin = h.i32_le(100)?;
    let (nx, ny) = (h.i32_le(108)?, h.i32_le(112)?);
    let points = check_shape(nx as i64, ny as i64)?;
    let declared = h.u32_le(116)?;
    if declared as usize != points {
        return Err(Problem::corrupt(format!(
            "the header declares {declared} points but {nx} × {ny} = {points}"
        )));
    }
    let (sx, sy, sz) = (h.f32_le(120)?, h.f32_le(124)?, h.f32_le(128)?);
    let x_unit = h.text(180, 16)?;
    let y_unit = h.text(196, 16)?;
    let z_unit = h.text(212, 16)?;
    let inversion = h.u16_le(290)?;
    let comment_size = h.u16_le(334)? as usize;
    let private_size = h.u16_le(336)? as usize;
    let z_offset = h.f32_le(474)? as f64;
    let ux = require_length(&x_unit, "the x step unit")?;
    let uy = require_length(&y_unit, "the y step unit")?;
    let uz = require_length(&z_unit, "the z step unit")?;
    let start = HEADER + comment_size + private_size;
    let size = bits as usize / 8;
    let body = data.get(start..).unwrap_or(&[]);
    check_data_len(
        points,
        size,
        body.len(),
        &format!("SUR data ({bits}-bit integers)"),
    )?;
    let non_measured = (special_points == 1).then(|| zmin as i64 - 2);
    let (nx, ny) = (nx as usize, ny as usize);
    let sign = if matches!(inversion, 1..=3) {
        -1.0
    } else {
        1.0
    };
    let scale = sz as f64 * uz * sign;
    let z_offset_m = z_offset * uz;
    let mut heights = vec![0.0; points];
    for iy in 0..ny {
        for ix in 0..nx {
            let k = iy * nx + ix;
            let raw = match size {
                2 => i16::from_le_bytes([body[2 * k], body[2 * k + 1]]) as i64,
                _ => i32::from_le_bytes([
                    body[4 * k],
                    body[4 * k + 1],
                    body[4 * k + 2],
                    body[4 * k + 3],
                ]) as i64,
            };
            let (tx, ty) = match inversion {
                2 => (nx - 1 - ix, iy),
                3 => (ix, ny - 1 - iy),
                _ => (ix, iy),
            };
            heights[ty * nx + tx] = if Some(raw) == non_measured {
                f64::NAN
            } else {
                raw as f64 * scale + z_offset_m
            };
        }
    }
    let mut info = vec![
        ("vendor".to_string(), "Digital Surf".to_string()),
        ("x step unit".to_string(), x_unit),
        ("y step unit".to_string(), y_unit),
        ("z step unit".to_string(), z_unit),
    ];
    for (key, offset, len) in [("object name", 20, 30), ("instrument name", 50, 30)] {
        let v = h.text(offset, len)?;
        if !v.is_empty() {
            info.push((key.to_string(), v));
        }
    }
    let date: Vec<u16> = (0..6)
        .map(|i| h.u16_le(306 + 2 * i))
        .collect::<Result<_>>()?;
    if date[5] != 0 {
        info.push((
            "date".to_string(),
            format!(
                "{:04}-{:02}-{:02} {:02}:{:02}:{:02}",
                date[5], date[4], date[3], date[2], date[1], date[0]
            ),
        ));
    }
    if z_offset_m != 0.0 {
        info.push(("z offset (m)".to_string(), format!("{z_offset_m:e}")));
    }
    if inversion != 0 {
        info.push(("inversion".to_string(), inversion.to_string()));
    }
    if comment_size > 0 {
        let c = Bytes::new(data, "SUR comment").text(HEADER, comment_size)?;
        info.push(("comment".to_string(), c));
    }
    Ok(Topography {
        nx,
        ny,
        dx_m: check_pixel(sx as f64 * ux, "x")?,
        dy_m: check_pixel(sy as f64 * uy, "y")?,
        heights_m: heights,
        format: Format::Sur,
        info,
    })
}
