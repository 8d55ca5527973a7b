//! The figures of `rebound scan`:
//!
//! * `height_map.svg` ([`height_map`]): the levelled scan, downsampled to at most 256 × 256
//!   cells by block means of the valid points (a cell without one is grey), drawn as one
//!   embedded image like `surface`'s height map.
//! * `slope_angle_pdfs.svg` ([`angle_pdfs`]): the PDFs of `ξ'` and `ζ'`, the normal's angles
//!   along and across the lay, against the normal law of the same standard deviation (the
//!   Gaussian wall the models assume, Eqs. 12–13 of Radenkovic & Simonin 2021).
//! * `autocorrelation.svg` ([`autocorrelation`]): the autocorrelation along and across the lay.
//! * `autocorrelation_map.svg` ([`autocorrelation_map`]): the areal autocorrelation over the
//!   lags along the scan's x and y, its `1/e` contour and the lay through the origin.

use super::surface::{heat_map, viridis, HeatMap, MapLine};
use super::{plot_grid_svg, plot_svg, Kind, Plot, Series};
use crate::output::fmt_num;
use rayon::prelude::*;
use roughwall::scan::Correlation;
use roughwall::scan::CorrelationMap;
use roughwall::scan::Lay;
use roughwall::surface::Histogram;
use roughwall::Result;
use roughwall::ScanField;
use std::path::Path;

/// Most cells per side of the height map.
pub const MAX_CELLS: usize = 256;

/// Colour of a cell without a valid point.
const MISSING: [u8; 3] = [170, 170, 170];

/// A scan downsampled by block means.
pub struct BlockMeans {
    /// Cells along x and y.
    pub cells: (usize, usize),
    /// Points per cell along x and y (the last cell of a row or column may hold fewer).
    pub block: (usize, usize),
    /// The means (m), row-major, `y` rows from the first; `None` for a cell without a valid
    /// point.
    pub means: Vec<Option<f64>>,
}

/// The block means of `f` on a grid of at most [`MAX_CELLS`] × [`MAX_CELLS`] cells. Each
/// cell adds its points in row order: the same bits for any thread count.
pub fn block_means(f: &ScanField) -> BlockMeans {
    let (bx, by) = (f.nx.div_ceil(MAX_CELLS), f.ny.div_ceil(MAX_CELLS));
    let (w, h) = (f.nx.div_ceil(bx), f.ny.div_ceil(by));
    let rows: Vec<Vec<Option<f64>>> = (0..h)
        .into_par_iter()
        .map(|cy| {
            (0..w)
                .map(|cx| {
                    let (mut sum, mut n) = (0.0, 0usize);
                    for iy in cy * by..((cy + 1) * by).min(f.ny) {
                        for ix in cx * bx..((cx + 1) * bx).min(f.nx) {
                            if let Some(v) = f.at(ix, iy) {
                                sum += v;
                                n += 1;
                            }
                        }
                    }
                    (n > 0).then(|| sum / n as f64)
                })
                .collect()
        })
        .collect();
    BlockMeans {
        cells: (w, h),
        block: (bx, by),
        means: rows.into_iter().flatten().collect(),
    }
}

/// Writes `path`: the heights (µm) of the levelled scan `f` as block means, over the
/// scan's `x`, `y` (µm), with a colour bar; missing cells grey.
pub fn height_map(path: &Path, f: &ScanField, name: &str) -> Result<()> {
    let BlockMeans {
        cells: (w, h),
        block: (bx, by),
        means: cells,
    } = block_means(f);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in cells.iter().flatten() {
        lo = lo.min(v * 1e6);
        hi = hi.max(v * 1e6);
    }
    if hi <= lo {
        // Flat (or no valid cell): any non-empty colour range.
        let mid = if lo.is_finite() { lo } else { 0.0 };
        lo = mid - 1e-3;
        hi = mid + 1e-3;
    }
    // 255 colour levels and grey.
    let mut palette: Vec<[u8; 3]> = (0..255).map(|i| viridis(i as f64 / 254.0)).collect();
    palette.push(MISSING);
    let level = |v: f64| {
        (((v * 1e6 - lo) / (hi - lo)) * 254.0)
            .round()
            .clamp(0.0, 254.0) as u8
    };
    // Image row 0 is the top of the plot: the largest y.
    let mut pixels = Vec::with_capacity(w * h);
    for r in 0..h {
        let cy = h - 1 - r;
        pixels.extend(cells[cy * w..(cy + 1) * w].iter().map(|c| match c {
            Some(v) => level(*v),
            None => 255,
        }));
    }
    let bar: Vec<u8> = (0..255).rev().map(|i| i as u8).collect();
    let title = if (bx, by) == (1, 1) {
        format!("{name}: levelled heights, {w} × {h} points")
    } else {
        format!("{name}: levelled heights, means of {bx} × {by} points")
    };
    heat_map(
        path,
        &title,
        &HeatMap {
            size: (w, h),
            pixels: &pixels,
            palette: &palette,
            bar: &bar,
            origin_um: (0.0, 0.0),
            extent_um: (f.nx as f64 * f.dx * 1e6, f.ny as f64 * f.dy * 1e6),
            range: (lo, hi),
            axes: ("x (µm)", "y (µm)"),
            bar_label: "height (µm)",
            lines: &[],
        },
    )
}

/// Normal density of std `sd` and mean 0 (degrees) on `[-half, half]`, per degree; empty
/// for `sd = 0`.
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

/// Writes `path`: the histograms of `ξ'` and `ζ'` (`hists`, rad) against the normal laws of
/// std `Δξ` and `Δζ` of `lay`, one panel each, in degrees.
pub fn angle_pdfs(path: &Path, hists: &[Histogram; 2], lay: &Lay) -> Result<()> {
    let panels = [
        ("ξ' (along the lay)", "Δξ", &hists[0], lay.delta_xi),
        ("ζ' (across the lay)", "Δζ", &hists[1], lay.delta_zeta),
    ];
    let plots: Vec<Plot> = panels
        .into_iter()
        .map(|(what, symbol, h, delta)| {
            let half = h.half_range.to_degrees();
            let per_deg: Vec<(f64, f64)> = h
                .density()
                .into_iter()
                .map(|(x, p)| (x.to_degrees(), p.to_radians()))
                .collect();
            let sd = delta.to_degrees();
            Plot {
                title: format!("{what}: {symbol} = {}°", fmt_num((sd * 1e3).round() / 1e3)),
                x_label: "angle (deg)".into(),
                y_label: "PDF (1/deg)".into(),
                series: vec![
                    Series::new("scan", per_deg, Kind::Step),
                    Series::new(
                        format!("normal, std {symbol}"),
                        normal_curve(sd, half),
                        Kind::Dashed,
                    ),
                ],
                x_range: Some((-half, half)),
                ..Plot::default()
            }
        })
        .collect();
    plot_grid_svg(path, &plots, 2)
}

/// Writes `path`: the autocorrelation `R(τ)/R(0)` along and across the lay (`corr.angle`,
/// drawn from the scan's x towards its y) against the lag in µm, with the `1/e` level whose
/// crossings are the correlation lengths of `scan_summary.csv`.
pub fn autocorrelation(path: &Path, corr: &Correlation) -> Result<()> {
    let curve = |r: &[f64]| -> Vec<(f64, f64)> {
        corr.lags_m
            .iter()
            .zip(r)
            .filter(|(_, r)| r.is_finite())
            .map(|(t, r)| (t * 1e6, *r))
            .collect()
    };
    let last = corr.lags_m.last().copied().unwrap_or(0.0) * 1e6;
    let plot = Plot {
        title: format!(
            "autocorrelation along the lay ({}° from the scan's x) and across it",
            fmt_num((corr.angle.to_degrees() * 100.0).round() / 100.0)
        ),
        x_label: "lag (µm)".into(),
        y_label: "R(τ)/R(0)".into(),
        series: vec![
            Series::new("along the lay", curve(&corr.along), Kind::Line),
            Series::new("across the lay", curve(&corr.across), Kind::Line).with_color(1),
            Series::new(
                "1/e",
                vec![(0.0, (-1f64).exp()), (last, (-1f64).exp())],
                Kind::Dashed,
            )
            .with_color(2),
        ],
        ..Plot::default()
    };
    plot_svg(path, &plot)
}

/// `2nd`, `3rd`, `4th`, `21st`…
fn ordinal(n: usize) -> String {
    let suffix = match (n % 10, n % 100) {
        (_, 11..=13) => "th",
        (1, _) => "st",
        (2, _) => "nd",
        (3, _) => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// Palette of [`autocorrelation_map`]: viridis levels, then grey (no pair), then the contour.
const MAP_LEVELS: usize = 254;

/// Writes `path`: the areal autocorrelation `R(τ)/R(0)` of `map` over its window of lags along
/// the scan's `x` and `y` (µm), lags without a pair of valid points grey, the `1/e` contour
/// white (the correlation ellipse of a Gaussian wall, whose radii are `c_L`), and the lay
/// (`lay_angle`, rad from the scan's x towards its y) drawn through the origin in red.
pub fn autocorrelation_map(
    path: &Path,
    map: &CorrelationMap,
    lay_angle: Option<f64>,
) -> Result<()> {
    let [hx, hy] = map.half;
    let (w, h) = (2 * hx + 1, 2 * hy + 1);
    let level = (-1.0f64).exp();
    let lo = map
        .values
        .iter()
        .filter(|v| v.is_finite())
        .fold(1.0f64, |a, &v| a.min(v));
    let lo = if lo < 1.0 { lo } else { 1.0 - 1e-3 };
    let mut palette: Vec<[u8; 3]> = (0..MAP_LEVELS)
        .map(|i| viridis(i as f64 / (MAP_LEVELS - 1) as f64))
        .collect();
    palette.push(MISSING);
    palette.push([255, 255, 255]);
    let (grey, white) = (MAP_LEVELS as u8, MAP_LEVELS as u8 + 1);
    let at = |kx: isize, ky: isize| map.at(kx, ky);
    // Image row 0 is the top of the plot: the largest y lag.
    let mut pixels = Vec::with_capacity(w * h);
    for r in 0..h {
        let ky = hy as isize - r as isize;
        for c in 0..w {
            let kx = c as isize - hx as isize;
            let v = at(kx, ky);
            let edge = [(1, 0), (-1, 0), (0, 1), (0, -1)]
                .iter()
                .any(|(dx, dy)| at(kx + dx, ky + dy) < level);
            pixels.push(match v {
                v if v.is_nan() => grey,
                v if v >= level && edge => white,
                v => ((v - lo) / (1.0 - lo) * (MAP_LEVELS - 1) as f64)
                    .round()
                    .clamp(0.0, (MAP_LEVELS - 1) as f64) as u8,
            });
        }
    }
    let bar: Vec<u8> = (0..MAP_LEVELS as u8).rev().collect();
    let [sx, sy] = map.step_m.map(|s| s * 1e6);
    // Each lag is a cell centred on it.
    let (half_x, half_y) = ((hx as f64 + 0.5) * sx, (hy as f64 + 0.5) * sy);
    let lines: Vec<MapLine> = lay_angle
        .map(|a| {
            let (c, s) = (a.cos(), a.sin());
            let reach = |half: f64, d: f64| match d.abs() > 1e-12 {
                true => half / d.abs(),
                false => f64::INFINITY,
            };
            let t = reach(half_x, c).min(reach(half_y, s));
            MapLine {
                from: (-t * c, -t * s),
                to: (t * c, t * s),
                color: [214, 39, 40],
            }
        })
        .into_iter()
        .collect();
    let every = match map.stride {
        1 => String::new(),
        s => format!(", every {} point", ordinal(s)),
    };
    let title = match lay_angle {
        Some(a) => format!(
            "R(τ)/R(0): lay at {}° (red), 1/e (white){every}",
            fmt_num((a.to_degrees() * 100.0).round() / 100.0)
        ),
        None => format!("R(τ)/R(0): 1/e (white){every}"),
    };
    heat_map(
        path,
        &title,
        &HeatMap {
            size: (w, h),
            pixels: &pixels,
            palette: &palette,
            bar: &bar,
            origin_um: (-half_x, -half_y),
            extent_um: (2.0 * half_x, 2.0 * half_y),
            range: (lo, 1.0),
            axes: ("lag along x (µm)", "lag along y (µm)"),
            bar_label: "R(τ)/R(0)",
            lines: &lines,
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_means_skip_missing_points_and_cover_the_scan() {
        // 600 × 3 points: 3 points a cell along x (200 cells), one row a cell along y.
        let mut h: Vec<f64> = (0..1800).map(|i| (i % 600) as f64).collect();
        h[1] = f64::NAN;
        for v in &mut h[1203..1206] {
            *v = f64::NAN;
        }
        let f = ScanField::new(600, 3, 1e-6, 1e-6, h).unwrap();
        let BlockMeans {
            cells: (w, ht),
            block: (bx, by),
            means: cells,
        } = block_means(&f);
        assert_eq!((w, ht, bx, by), (200, 3, 3, 1));
        assert_eq!(cells[0], Some(1.0)); // (0 + 2)/2
        assert_eq!(cells[1], Some(4.0));
        assert_eq!(cells[2 * 200 + 1], None);
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("map.svg");
        height_map(&p, &f, "t").unwrap();
        let s = std::fs::read_to_string(&p).unwrap();
        assert_eq!(s.matches("<image").count(), 2);
        assert!(s.len() < 200_000, "{}", s.len());
    }

    /// The map's lay line runs through the origin, corner to corner for a lay at 45° on a
    /// square window of lags.
    #[test]
    fn the_lay_is_drawn_through_the_origin_of_the_map() {
        let map = CorrelationMap {
            stride: 1,
            step_m: [1e-6, 1e-6],
            half: [2, 2],
            values: (0..25)
                .map(|k| {
                    let (x, y) = ((k % 5) as f64 - 2.0, (k / 5) as f64 - 2.0);
                    (-(x * x + y * y) / 2.0).exp()
                })
                .collect(),
        };
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("map.svg");
        autocorrelation_map(&p, &map, Some(std::f64::consts::FRAC_PI_4)).unwrap();
        let s = std::fs::read_to_string(&p).unwrap();
        let attr = |tag: &str, k: &str| -> f64 {
            let element = format!(" {}", s.split(&format!("<{tag} ")).nth(1).unwrap());
            element
                .split(&format!(" {k}=\""))
                .nth(1)
                .unwrap()
                .split('"')
                .next()
                .unwrap()
                .parse()
                .unwrap()
        };
        let line = |k: &str| attr("line", k);
        let image = |k: &str| attr("image", k);
        // The map's image spans the window: the line runs from its lower left corner to its
        // upper right one (SVG's y grows downwards).
        let (left, top) = (image("x"), image("y"));
        let (right, bottom) = (left + image("width"), top + image("height"));
        for (got, want) in [
            (line("x1"), left),
            (line("y1"), bottom),
            (line("x2"), right),
            (line("y2"), top),
        ] {
            assert!((got - want).abs() < 0.6, "{got} vs {want}");
        }
        assert!(s.contains("lay at 45° (red)"));
        assert_eq!(
            [2, 3, 4, 11, 21, 112].map(ordinal),
            ["2nd", "3rd", "4th", "11th", "21st", "112th"]
        );
    }
}
