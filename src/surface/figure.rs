//! The height-map figure of `rebound surface` (the analogue of Radenkovic & Simonin
//! 2021, Fig. 1): a window of at most 256 × 256 nodes at full resolution, drawn as one
//! embedded indexed-colour PNG inside an SVG whose axes and colour bar come from
//! `plotters`. One image instead of 65 536 rectangles keeps the file small (~100 kB).
//!
//! `crate::figures` draws line plots only; this module adds the heat map next to the
//! surface code that needs it.

use crate::error::{Error, Result};
use crate::output::write_atomic;
use crate::surface::HeightField;
use plotters::prelude::*;
use std::path::Path;

/// Largest window side (nodes).
pub const MAX_CELLS: usize = 256;

/// Viridis colour map, linearly interpolated between nine anchors.
fn viridis(t: f64) -> [u8; 3] {
    const A: [[f64; 3]; 9] = [
        [68.0, 1.0, 84.0],
        [71.0, 44.0, 122.0],
        [59.0, 81.0, 139.0],
        [44.0, 113.0, 142.0],
        [33.0, 144.0, 141.0],
        [39.0, 173.0, 129.0],
        [92.0, 200.0, 99.0],
        [170.0, 220.0, 50.0],
        [253.0, 231.0, 37.0],
    ];
    let x = t.clamp(0.0, 1.0) * 8.0;
    let i = (x.floor() as usize).min(7);
    let f = x - i as f64;
    let mut c = [0u8; 3];
    for (k, ck) in c.iter_mut().enumerate() {
        *ck = (A[i][k] + f * (A[i + 1][k] - A[i][k])).round() as u8;
    }
    c
}

/// Writes `path`: heights (µm) of the window `ix, iz < 256` of `f` as a colour map over
/// `x`, `z` (µm), with a colour bar.
pub fn height_map_svg(path: &Path, f: &HeightField, title: &str) -> Result<()> {
    let (w, h) = (f.nx.min(MAX_CELLS), f.nz.max(f.nx).min(MAX_CELLS));
    // A surface stored with nz = 1 is constant along z: show it over a square window.
    let node = |ix: usize, iz: usize| f.at(ix, iz) * 1e6;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for iz in 0..h {
        for ix in 0..w {
            lo = lo.min(node(ix, iz));
            hi = hi.max(node(ix, iz));
        }
    }
    if hi <= lo {
        // Flat window: any non-empty colour range.
        lo -= 1e-3;
        hi += 1e-3;
    }
    let palette: Vec<[u8; 3]> = (0..256).map(|i| viridis(i as f64 / 255.0)).collect();
    let level = |v: f64| (((v - lo) / (hi - lo)) * 255.0).round().clamp(0.0, 255.0) as u8;
    // Image row 0 is the top of the plot: the largest z.
    let mut pixels = Vec::with_capacity(w * h);
    for r in 0..h {
        let iz = h - 1 - r;
        pixels.extend((0..w).map(|ix| level(node(ix, iz))));
    }
    let bar: Vec<u8> = (0..256).rev().map(|i| i as u8).collect();
    let map_png = png_indexed(w, h, &pixels, &palette);
    let bar_png = png_indexed(1, 256, &bar, &palette);

    let (dx, dz) = (f.dx * 1e6, f.dz * 1e6);
    let (width_um, height_um) = (w as f64 * dx, h as f64 * dz);
    let (cw, ch) = (640u32, 560u32);
    let mut svg = String::new();
    let (map_px, bar_px);
    {
        let root = SVGBackend::with_string(&mut svg, (cw, ch)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let (left, right) = root.split_horizontally(cw - 110);
        let mut chart = ChartBuilder::on(&left)
            .caption(title, ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d(0.0..width_um, 0.0..height_um)
            .map_err(draw_err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x (µm)")
            .y_desc("z (µm)")
            .draw()
            .map_err(draw_err)?;
        map_px = chart.plotting_area().get_pixel_range();
        let mut cbar = ChartBuilder::on(&right)
            .margin_top(40)
            .margin_bottom(52)
            .margin_right(8)
            .y_label_area_size(64)
            .build_cartesian_2d(0.0..1.0, lo..hi)
            .map_err(draw_err)?;
        cbar.configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_desc("height (µm)")
            .draw()
            .map_err(draw_err)?;
        bar_px = cbar.plotting_area().get_pixel_range();
        root.present().map_err(draw_err)?;
    }
    let image = |px: &(std::ops::Range<i32>, std::ops::Range<i32>), png: &[u8]| {
        format!(
            "<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" \
             style=\"image-rendering:pixelated\" href=\"data:image/png;base64,{}\"/>\n",
            px.0.start,
            px.1.start,
            px.0.end - px.0.start,
            px.1.end - px.1.start,
            base64(png)
        )
    };
    let images = image(&map_px, &map_png) + &image(&bar_px, &bar_png);
    let end = svg
        .rfind("</svg>")
        .ok_or_else(|| Error::Io("drawing figure: SVG without an end tag".into()))?;
    svg.insert_str(end, &images);
    write_atomic(path, svg.as_bytes())
}

fn draw_err<E: std::fmt::Debug>(e: E) -> Error {
    Error::Io(format!("drawing figure: {e:?}"))
}

/// A PNG (colour type 3: 8-bit palette indices) with stored (uncompressed) deflate
/// blocks; small enough for ≤ 256 × 256 images and needs no compression library.
fn png_indexed(width: usize, height: usize, pixels: &[u8], palette: &[[u8; 3]]) -> Vec<u8> {
    let mut raw = Vec::with_capacity(height * (width + 1));
    for row in pixels.chunks(width.max(1)) {
        raw.push(0); // filter: none
        raw.extend_from_slice(row);
    }
    let mut z = vec![0x78, 0x01];
    let mut blocks = raw.chunks(65_535).peekable();
    if blocks.peek().is_none() {
        z.extend_from_slice(&[1, 0, 0, 0xff, 0xff]);
    }
    while let Some(b) = blocks.next() {
        z.push(u8::from(blocks.peek().is_none()));
        let n = b.len() as u16;
        z.extend_from_slice(&n.to_le_bytes());
        z.extend_from_slice(&(!n).to_le_bytes());
        z.extend_from_slice(b);
    }
    z.extend_from_slice(&adler32(&raw).to_be_bytes());

    let mut ihdr = Vec::with_capacity(13);
    ihdr.extend_from_slice(&(width as u32).to_be_bytes());
    ihdr.extend_from_slice(&(height as u32).to_be_bytes());
    ihdr.extend_from_slice(&[8, 3, 0, 0, 0]);
    let plte: Vec<u8> = palette.iter().flatten().copied().collect();

    let mut png = vec![0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];
    for (kind, data) in [
        (b"IHDR", &ihdr[..]),
        (b"PLTE", &plte[..]),
        (b"IDAT", &z[..]),
        (b"IEND", &[][..]),
    ] {
        png.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let start = png.len();
        png.extend_from_slice(kind);
        png.extend_from_slice(data);
        let crc = crc32(&png[start..]);
        png.extend_from_slice(&crc.to_be_bytes());
    }
    png
}

fn crc32(data: &[u8]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for &b in data {
        c ^= b as u32;
        for _ in 0..8 {
            c = if c & 1 != 0 {
                0xedb8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

fn adler32(data: &[u8]) -> u32 {
    let (mut a, mut b) = (1u32, 0u32);
    for &x in data {
        a = (a + x as u32) % 65_521;
        b = (b + a) % 65_521;
    }
    (b << 16) | a
}

fn base64(data: &[u8]) -> String {
    const T: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(data.len().div_ceil(3) * 4);
    for c in data.chunks(3) {
        let n = (c[0] as u32) << 16
            | (c.get(1).copied().unwrap_or(0) as u32) << 8
            | c.get(2).copied().unwrap_or(0) as u32;
        for k in 0..4 {
            if k <= c.len() {
                s.push(T[(n >> (18 - 6 * k)) as usize & 63] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checksums_and_base64_match_known_values() {
        assert_eq!(crc32(b"123456789"), 0xcbf4_3926);
        assert_eq!(adler32(b"Wikipedia"), 0x11e6_0398);
        assert_eq!(base64(b"Man"), "TWFu");
        assert_eq!(base64(b"Ma"), "TWE=");
        assert_eq!(base64(b"M"), "TQ==");
    }

    #[test]
    fn height_map_is_a_small_svg_with_one_embedded_png() {
        let n = 300;
        let f = HeightField {
            nx: n,
            nz: 1,
            dx: 1e-6,
            dz: 1e-6,
            heights: (0..n).map(|i| (i as f64 * 0.3).sin() * 1e-7).collect(),
        };
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("map.svg");
        height_map_svg(&p, &f, "test").unwrap();
        let s = std::fs::read_to_string(&p).unwrap();
        assert!(s.contains("data:image/png;base64,iVBORw0KGgo"));
        assert_eq!(s.matches("<image").count(), 2);
        assert!(s.len() < 200_000, "{} bytes", s.len());
        // A flat wall does not break the colour range.
        let flat = HeightField {
            heights: vec![0.0; n],
            ..f
        };
        height_map_svg(&p, &flat, "flat").unwrap();
    }
}
