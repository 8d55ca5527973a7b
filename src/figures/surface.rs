//! The figures of `rebound surface`:
//!
//! * `height_map.svg` ([`height_map`], the analogue of Radenkovic & Simonin 2021, Fig. 1): a
//!   window of at most 256 × 256 nodes at full resolution, drawn as one embedded
//!   indexed-colour PNG inside an SVG whose axes and colour bar come from `plotters`. One
//!   image instead of 65 536 rectangles keeps the file small (~100 kB). The line plots of
//!   [`super::plot`] do not draw heat maps; this is the one figure that draws its own.
//! * `normal_angle_pdfs.svg` ([`normal_angle_pdfs`]): the measured PDFs of `ξ*`, `ζ*` against
//!   Eqs. (12)–(13).
//! * `effective_roughness.svg` ([`effective_roughness`]): the effective roughness of a
//!   sphere's centre surface.

use super::plot::{draw_err, drawable};
use super::png::{base64, png_indexed};
use super::{plot_grid_svg, Kind, Plot, Series};
use crate::output::{fmt_num, write_atomic};
use plotters::prelude::*;
use roughwall::surface::EffectiveRoughness;
use roughwall::surface::{Histogram, RotatedStats, SurfaceStats};
use roughwall::HeightField;
use roughwall::{Error, Result};
use std::path::Path;

/// Largest window side (nodes).
pub const MAX_CELLS: usize = 256;

/// Viridis colour map, linearly interpolated between nine anchors.
pub(super) fn viridis(t: f64) -> [u8; 3] {
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
pub fn height_map(path: &Path, f: &HeightField, title: &str) -> Result<()> {
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
    heat_map(
        path,
        title,
        &HeatMap {
            size: (w, h),
            pixels: &pixels,
            palette: &palette,
            bar: &bar,
            origin_um: (0.0, 0.0),
            extent_um: (w as f64 * f.dx * 1e6, h as f64 * f.dz * 1e6),
            range: (lo, hi),
            axes: ("x (µm)", "z (µm)"),
            bar_label: "height (µm)",
            lines: &[],
        },
    )
}

/// A colour map drawn as one embedded image: `size.0 × size.1` palette indices, row 0 at the
/// top, over `extent_um` from `origin_um` (its lower left corner), beside a colour bar (`bar`:
/// its indices from top to bottom) labelled from `range.0` to `range.1`, with `lines` drawn
/// over it.
pub(super) struct HeatMap<'a> {
    pub size: (usize, usize),
    pub pixels: &'a [u8],
    pub palette: &'a [[u8; 3]],
    pub bar: &'a [u8],
    pub origin_um: (f64, f64),
    pub extent_um: (f64, f64),
    pub range: (f64, f64),
    /// Labels of the x and y axes.
    pub axes: (&'a str, &'a str),
    /// What the colours are (the colour bar's label).
    pub bar_label: &'a str,
    pub lines: &'a [MapLine],
}

/// A straight segment over a [`HeatMap`], in its axes' units (µm).
pub(super) struct MapLine {
    pub from: (f64, f64),
    pub to: (f64, f64),
    pub color: [u8; 3],
}

/// Writes `path`: `m` as indexed-colour PNGs inside an SVG whose axes and colour bar come from
/// `plotters`.
pub(super) fn heat_map(path: &Path, title: &str, m: &HeatMap) -> Result<()> {
    let (w, h) = m.size;
    let (lo, hi) = drawable(m.range.0, m.range.1);
    let map_png = png_indexed(w, h, m.pixels, m.palette);
    let bar_png = png_indexed(1, m.bar.len(), m.bar, m.palette);
    let (x0, x1) = drawable(m.origin_um.0, m.origin_um.0 + m.extent_um.0);
    let (y0, y1) = drawable(m.origin_um.1, m.origin_um.1 + m.extent_um.1);
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
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(draw_err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .label_style(("sans-serif", 12))
            .axis_desc_style(("sans-serif", 13))
            .x_desc(m.axes.0)
            .y_desc(m.axes.1)
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
            .y_labels(8)
            .label_style(("sans-serif", 12))
            .axis_desc_style(("sans-serif", 13))
            .y_desc(m.bar_label)
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
    // Over the image, in its pixels: x from the left, y from the top.
    let to_px = |(x, y): (f64, f64)| {
        let (px, py) = (&map_px.0, &map_px.1);
        (
            px.start as f64 + (x - x0) / (x1 - x0) * (px.end - px.start) as f64,
            py.end as f64 - (y - y0) / (y1 - y0) * (py.end - py.start) as f64,
        )
    };
    let lines: String = m
        .lines
        .iter()
        .map(|l| {
            let ((ax, ay), (bx, by)) = (to_px(l.from), to_px(l.to));
            let [r, g, b] = l.color;
            format!(
                "<line x1=\"{ax:.1}\" y1=\"{ay:.1}\" x2=\"{bx:.1}\" y2=\"{by:.1}\" stroke=\"rgb({r},{g},{b})\" stroke-width=\"2\"/>\n"
            )
        })
        .collect();
    let images = image(&map_px, &map_png) + &image(&bar_px, &bar_png) + &lines;
    let end = svg
        .rfind("</svg>")
        .ok_or_else(|| Error::Io("drawing figure: SVG without an end tag".into()))?;
    svg.insert_str(end, &images);
    write_atomic(path, svg.as_bytes())
}

/// `Δ_eff/Δ` against `D/c_L` for both axes (`corr_length_x_m`, `corr_length_z_m`: the
/// surface's correlation lengths, `None` for `c_L = ∞`), and the contact fraction.
pub fn effective_roughness(
    path: &Path,
    corr_length_x_m: Option<f64>,
    corr_length_z_m: Option<f64>,
    s: &SurfaceStats,
    eff: &[EffectiveRoughness],
) -> Result<()> {
    let mut series = Vec::new();
    for (label, c, base, pick) in [
        (
            "Δξ_eff/Δξ against D/c_Lx",
            corr_length_x_m,
            s.delta_xi,
            (|e: &EffectiveRoughness| e.delta_xi) as fn(&EffectiveRoughness) -> f64,
        ),
        (
            "Δζ_eff/Δζ against D/c_Lz",
            corr_length_z_m,
            s.delta_zeta,
            |e: &EffectiveRoughness| e.delta_zeta,
        ),
    ] {
        let (Some(c), true) = (c, base > 0.0) else {
            continue;
        };
        let pts: Vec<(f64, f64)> = eff
            .iter()
            .filter(|e| e.diameter_m > 0.0)
            .map(|e| (e.diameter_m / c, pick(e) / base))
            .collect();
        series.push(Series::new(label, pts, Kind::Line));
    }
    let contact = Plot {
        title: "nodes a resting sphere touches".into(),
        x_label: "D (µm)".into(),
        y_label: "fraction of nodes".into(),
        series: vec![Series::new(
            "",
            eff.iter()
                .filter(|e| e.diameter_m > 0.0)
                .map(|e| (e.diameter_m * 1e6, e.contact_fraction))
                .collect(),
            Kind::Line,
        )],
        log_x: true,
        log_y: true,
        ..Plot::default()
    };
    let ratio = Plot {
        title: "effective roughness of a sphere's centre surface".into(),
        x_label: "D / c_L".into(),
        y_label: "Δ_eff / Δ".into(),
        series,
        log_x: true,
        ..Plot::default()
    };
    plot_grid_svg(path, &[ratio, contact], 2)
}

/// Normal density of std `sd` (degrees) on `[-half, half]`, per degree (Eqs. 12–13 for
/// the fluctuations `ξ* − 90°`, `ζ* − 90°`). Empty for `sd = 0` (a Dirac peak).
fn normal_curve(sd: f64, half: f64) -> Vec<(f64, f64)> {
    if sd <= 0.0 {
        return Vec::new();
    }
    let n = 200;
    (0..=n)
        .map(|i| {
            let x = -half + 2.0 * half * i as f64 / n as f64;
            let y = (-0.5 * (x / sd).powi(2)).exp() / (sd * (2.0 * std::f64::consts::PI).sqrt());
            (x, y)
        })
        .collect()
}

/// One panel: the measured PDFs at `r.beta_star` and the normal laws of std `mx`, `mz`
/// (rad; Eq. 9 with the target deviations of Eq. 15).
fn pdf_panel(r: &RotatedStats, (mx, mz): (f64, f64)) -> Plot {
    let per_deg = |h: &Histogram| -> Vec<(f64, f64)> {
        h.density()
            .into_iter()
            .map(|(x, p)| (x.to_degrees(), p.to_radians()))
            .collect()
    };
    let mut series = Vec::new();
    let mut half = 1.0;
    if let Some(h) = &r.hist_xi {
        half = h.half_range.to_degrees();
        series.push(Series::new("ξ* − 90° (surface)", per_deg(h), Kind::Step));
    }
    if let Some(h) = &r.hist_zeta {
        series.push(Series::new("ζ* − 90° (surface)", per_deg(h), Kind::Step));
    }
    series.push(Series::new(
        "Eq. (12)",
        normal_curve(mx.to_degrees(), half),
        Kind::Dashed,
    ));
    series.push(Series::new(
        "Eq. (13)",
        normal_curve(mz.to_degrees(), half),
        Kind::Dashed,
    ));
    Plot {
        title: format!("β* = {}°", fmt_num(r.beta_star.to_degrees())),
        x_label: "angle − 90° (deg)".into(),
        y_label: "PDF (1/deg)".into(),
        series,
        x_range: Some((-half, half)),
        ..Plot::default()
    }
}

/// The PDFs of `ξ* − 90°` and `ζ* − 90°` of every rotation in `s.rotated`, each against the
/// normal laws of Eqs. (12)–(13) whose stds (rad) `model` gives in the same order. Writes
/// nothing without rotations.
pub fn normal_angle_pdfs(path: &Path, s: &SurfaceStats, model: &[(f64, f64)]) -> Result<()> {
    let plots: Vec<Plot> = s
        .rotated
        .iter()
        .zip(model)
        .map(|(r, &m)| pdf_panel(r, m))
        .collect();
    if plots.is_empty() {
        return Ok(());
    }
    plot_grid_svg(path, &plots, plots.len().min(2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn height_map_is_a_small_svg_with_one_embedded_png() {
        let n = 300;
        let f = HeightField {
            nx: n,
            nz: 1,
            dx: 1e-6,
            dz: 1e-6,
            heights: (0..n).map(|i| (i as f64 * 0.3).sin() * 1e-7).collect(),
            triangulation: Default::default(),
        };
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("map.svg");
        height_map(&p, &f, "test").unwrap();
        let s = std::fs::read_to_string(&p).unwrap();
        assert!(s.contains("data:image/png;base64,iVBORw0KGgo"));
        assert_eq!(s.matches("<image").count(), 2);
        assert!(s.len() < 200_000, "{} bytes", s.len());
        // A flat wall does not break the colour range.
        let flat = HeightField {
            heights: vec![0.0; n],
            ..f
        };
        height_map(&p, &flat, "flat").unwrap();
    }
}
