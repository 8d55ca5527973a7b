//! The line-plot renderer: [`Plot`]s of [`Series`] drawn with `plotters` into an SVG string
//! and written atomically like every other output.

use crate::write_atomic;
use plotters::prelude::*;
use roughwall::{Error, Result};
use std::path::Path;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    Line,
    /// A histogram outline: points are `(bin centre, value)`, drawn as steps.
    Step,
    Markers,
    Dashed,
}

/// One labelled series.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub kind: Kind,
    /// Error bars: half-width at each point (empty: none), drawn in the series' colour.
    pub err: Vec<f64>,
    /// Palette index of the colour (default: the series' position), so that two series of
    /// one thing (e.g. a line and its markers) share a colour.
    pub color: Option<usize>,
}

impl Series {
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, kind: Kind) -> Series {
        Series {
            label: label.into(),
            points,
            kind,
            err: Vec::new(),
            color: None,
        }
    }

    /// The series drawn in palette colour `i`.
    pub fn with_color(mut self, i: usize) -> Series {
        self.color = Some(i);
        self
    }

    /// The series with error bars of half-width `err` (one per point).
    pub fn with_err(mut self, err: Vec<f64>) -> Series {
        self.err = err;
        self
    }
}

/// One panel.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plot {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub log_x: bool,
    pub log_y: bool,
    /// Fixed x range; `None` fits the data.
    pub x_range: Option<(f64, f64)>,
}

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

/// Axis range of the data: padded, and kept where the plotting library draws it quickly and
/// well (a degenerate or huge range would make its tick search spin): at most
/// `MAX_DECADES` decades on a log axis, a finite span of at least 1e-9 of the values' size on
/// a linear one.
fn range(vals: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    const MAX_DECADES: f64 = 30.0;
    const LIMIT: f64 = 1e300;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in vals.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
        let v = v.clamp(-LIMIT, LIMIT);
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return if log { (0.1, 10.0) } else { (0.0, 1.0) };
    }
    if log {
        let (lo, hi) = (lo.max(1e-300), hi.max(1e-300));
        let lo = lo.max(hi / 10f64.powf(MAX_DECADES));
        if hi <= lo * (1.0 + 1e-9) {
            return (lo / 2.0, hi * 2.0);
        }
        return (lo / 1.2, hi * 1.2);
    }
    let scale = lo.abs().max(hi.abs());
    if hi - lo <= 1e-9 * scale || hi <= lo {
        // A single value (or a span lost in rounding): a window of ±1, or of ±5 % of the
        // value where ±1 would be lost in rounding.
        let mid = 0.5 * lo + 0.5 * hi;
        let half = if scale < 1e15 { 1.0 } else { 0.05 * scale };
        return (mid - half, mid + half);
    }
    let pad = 0.05 * hi - 0.05 * lo;
    (lo - pad, hi + pad)
}

/// An axis range `lo..hi` the plotting library can draw quickly: itself when finite and wide
/// enough to be resolved (more than 1e-9 of its size), else a window around what is finite of
/// it. Heat maps take their extents and colour ranges through it, as line plots take theirs
/// through `range` (issue 42: a 1e303 m side made the tick search spin for minutes).
pub fn drawable(lo: f64, hi: f64) -> (f64, f64) {
    let scale = lo.abs().max(hi.abs());
    if lo.is_finite() && hi.is_finite() && hi - lo > 1e-9 * scale && hi > lo {
        return (lo, hi);
    }
    range([lo, hi].into_iter(), false)
}

/// Keeps a coordinate within a few axis spans of the axis range (in log space on a log axis).
#[derive(Clone, Copy)]
struct Clamp {
    lo: f64,
    hi: f64,
}

impl Clamp {
    const SPANS: f64 = 4.0;

    fn new(lo: f64, hi: f64, log: bool) -> Self {
        let (lo, hi) = if log {
            let r = (hi / lo).max(1.0).powf(Self::SPANS);
            ((lo / r).max(f64::MIN_POSITIVE), hi * r)
        } else {
            let span = hi - lo;
            (lo - Self::SPANS * span, hi + Self::SPANS * span)
        };
        let lo = if lo.is_finite() { lo } else { f64::MIN };
        let hi = if hi.is_finite() { hi } else { f64::MAX };
        Clamp { lo, hi }
    }

    fn apply(self, v: f64) -> f64 {
        if v.is_nan() {
            v
        } else {
            v.clamp(self.lo, self.hi)
        }
    }
}

/// Renders `plots` side by side in a grid of `cols` columns into an SVG file.
pub fn plot_grid_svg(path: &Path, plots: &[Plot], cols: usize) -> Result<()> {
    let cols = cols.max(1);
    let rows = plots.len().div_ceil(cols).max(1);
    let (w, h) = (480 * cols as u32, 360 * rows as u32);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let areas = root.split_evenly((rows, cols));
        for (plot, area) in plots.iter().zip(areas.iter()) {
            draw(plot, area)?;
        }
        root.present().map_err(draw_err)?;
    }
    write_atomic(path, svg.as_bytes())
}

/// Renders one plot into an SVG file.
pub fn plot_svg(path: &Path, plot: &Plot) -> Result<()> {
    plot_grid_svg(path, std::slice::from_ref(plot), 1)
}

/// A `plotters` failure as the crate's error.
pub fn draw_err<E: std::fmt::Debug>(e: E) -> Error {
    Error::Io(format!("drawing figure: {e:?}"))
}

fn draw<DB: DrawingBackend>(
    plot: &Plot,
    area: &DrawingArea<DB, plotters::coord::Shift>,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let xs = plot
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0));
    let ys = plot.series.iter().flat_map(|s| {
        s.points.iter().enumerate().flat_map(move |(i, p)| {
            let e = s
                .err
                .get(i)
                .copied()
                .filter(|e| e.is_finite())
                .unwrap_or(0.0);
            [p.1 - e, p.1 + e]
        })
    });
    let (x0, x1) = plot.x_range.unwrap_or_else(|| range(xs, plot.log_x));
    let (y0, y1) = range(ys, plot.log_y);
    let y0 = if !plot.log_y && y0 > 0.0 && y0 < 0.3 * y1 {
        0.0
    } else {
        y0
    };
    // Points far outside the axes would map to pixel offsets past i32 inside the plotting
    // library; held a few chart widths out, they draw the same lines.
    let (cx, cy) = (
        Clamp::new(x0, x1, plot.log_x),
        Clamp::new(y0, y1, plot.log_y),
    );
    let clamp = |p: (f64, f64)| (cx.apply(p.0), cy.apply(p.1));
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(&plot.title, ("sans-serif", 16))
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(56);
    macro_rules! finish {
        ($chart:expr) => {{
            let mut chart = $chart;
            chart
                .configure_mesh()
                .x_desc(plot.x_label.as_str())
                .y_desc(plot.y_label.as_str())
                .disable_mesh()
                .x_labels(6)
                .y_labels(5)
                .draw()
                .map_err(draw_err)?;
            for (i, s) in plot.series.iter().enumerate() {
                let color = PALETTE[s.color.unwrap_or(i) % PALETTE.len()];
                let pts: Vec<(f64, f64)> = s
                    .points
                    .iter()
                    .copied()
                    .filter(|p| {
                        p.0.is_finite()
                            && p.1.is_finite()
                            && (!plot.log_x || p.0 > 0.0)
                            && (!plot.log_y || p.1 > 0.0)
                    })
                    .map(clamp)
                    .collect();
                let bars: Vec<(f64, f64, f64)> = s
                    .points
                    .iter()
                    .zip(&s.err)
                    .filter(|(p, e)| p.0.is_finite() && p.1.is_finite() && e.is_finite())
                    .map(|(p, e)| (cx.apply(p.0), cy.apply(p.1 - e), cy.apply(p.1 + e)))
                    .collect();
                chart
                    .draw_series(bars.into_iter().map(|(x, lo, hi)| {
                        PathElement::new(vec![(x, lo), (x, hi)], color.stroke_width(1))
                    }))
                    .map_err(draw_err)?;
                let pts = if s.kind == Kind::Step {
                    step_points(&pts)
                } else {
                    pts
                };
                let pts = if s.kind == Kind::Markers {
                    pts
                } else {
                    simplify(pts, |p| chart.backend_coord(&p))
                };
                let anno = match s.kind {
                    Kind::Line => chart
                        .draw_series(LineSeries::new(pts, color.stroke_width(2)))
                        .map_err(draw_err)?,
                    // plotters writes one SVG element per dash; a thin solid line in its own
                    // colour reads the same and keeps the file an order of magnitude smaller.
                    Kind::Dashed => chart
                        .draw_series(LineSeries::new(pts, color.stroke_width(1)))
                        .map_err(draw_err)?,
                    Kind::Step => chart
                        .draw_series(LineSeries::new(pts, color.stroke_width(2)))
                        .map_err(draw_err)?,
                    Kind::Markers => chart
                        .draw_series(pts.into_iter().map(|p| Circle::new(p, 3, color.filled())))
                        .map_err(draw_err)?,
                };
                // A series without a label has no legend entry.
                if !s.label.is_empty() {
                    anno.label(s.label.clone()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2))
                    });
                }
            }
            if plot.series.iter().any(|s| !s.label.is_empty()) {
                chart
                    .configure_series_labels()
                    .background_style(WHITE.mix(0.8))
                    .border_style(BLACK)
                    .position(SeriesLabelPosition::UpperRight)
                    .draw()
                    .map_err(draw_err)?;
            }
        }};
    }
    match (plot.log_x, plot.log_y) {
        (false, false) => finish!(builder
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(draw_err)?),
        (true, false) => finish!(builder
            .build_cartesian_2d((x0..x1).log_scale(), y0..y1)
            .map_err(draw_err)?),
        (false, true) => finish!(builder
            .build_cartesian_2d(x0..x1, (y0..y1).log_scale())
            .map_err(draw_err)?),
        (true, true) => finish!(builder
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(draw_err)?),
    }
    Ok(())
}

/// The outline of a histogram given by `(bin centre, value)` points: a horizontal segment per bin.
fn step_points(pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let half = if pts.len() > 1 {
        0.5 * (pts[1].0 - pts[0].0)
    } else {
        0.5
    };
    pts.iter()
        .flat_map(|&(x, y)| [(x - half, y), (x + half, y)])
        .collect()
}

/// Drops the points that do not change the drawing: repeats of the same pixel and the
/// middle points of horizontal or vertical pixel runs. Keeps SVG files small (a 1° histogram
/// over ±180° is mostly flat runs) without changing what is drawn.
fn simplify(pts: Vec<(f64, f64)>, to_pixel: impl Fn((f64, f64)) -> (i32, i32)) -> Vec<(f64, f64)> {
    if pts.len() < 3 {
        return pts;
    }
    let px: Vec<(i32, i32)> = pts.iter().map(|&p| to_pixel(p)).collect();
    let mut keep: Vec<usize> = vec![0];
    for i in 1..pts.len() {
        let last = *keep.last().unwrap_or(&0);
        if px[i] == px[last] {
            continue;
        }
        if keep.len() >= 2 {
            let prev = keep[keep.len() - 2];
            let (a, b, c) = (px[prev], px[last], px[i]);
            if (a.0 == b.0 && b.0 == c.0) || (a.1 == b.1 && b.1 == c.1) {
                keep.pop();
            }
        }
        keep.push(i);
    }
    keep.into_iter().map(|i| pts[i]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_an_svg_with_every_label() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("f.svg");
        let plot = Plot {
            title: "t".into(),
            x_label: "x (deg)".into(),
            y_label: "pdf".into(),
            series: vec![
                Series::new("DS", vec![(0.0, 1.0), (1.0, 2.0)], Kind::Step),
                Series::new("SM", vec![(0.0, 1.5), (1.0, 2.5)], Kind::Line),
            ],
            ..Default::default()
        };
        plot_svg(&p, &plot).unwrap();
        let s = std::fs::read_to_string(&p).unwrap();
        assert!(s.starts_with("<svg") && s.contains("DS") && s.contains("SM"));
    }

    #[test]
    fn simplify_keeps_the_drawing() {
        // A flat run collapses to its ends; a corner survives.
        let pts = vec![(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0)];
        let out = simplify(pts, |p| (p.0 as i32, p.1 as i32));
        assert_eq!(out, vec![(0.0, 0.0), (2.0, 0.0), (2.0, 1.0)]);
    }
}

#[cfg(test)]
mod degenerate {
    use super::*;

    #[test]
    fn drawable_keeps_good_ranges_and_mends_the_rest() {
        assert_eq!(drawable(0.0, 83.0), (0.0, 83.0));
        for (lo, hi) in [
            (0.0, f64::INFINITY),
            (f64::NAN, 1.0),
            (1e300, 1e300),
            (1e300, 1e300 + 1e-6),
            (5.0, 5.0),
        ] {
            let (a, b) = drawable(lo, hi);
            assert!(
                a.is_finite() && b.is_finite() && b - a > 1e-9 * a.abs().max(b.abs()),
                "{lo} {hi} -> {a} {b}"
            );
        }
    }

    #[test]
    fn huge_and_degenerate_ranges_draw_quickly() {
        let dir = tempfile::tempdir().unwrap();
        let t = std::time::Instant::now();
        for (log, pts) in [
            (true, vec![(0.1, 1.0), (1e308, 2.0)]),
            (false, vec![(0.0, 1e308), (1.0, -1e308)]),
            (false, vec![(5e-324, 0.0), (1e-323, 0.0)]),
            (true, vec![(1e-300, 1e-300), (1e300, 1e300)]),
        ] {
            let plot = Plot {
                title: "t".into(),
                series: vec![Series::new("s", pts, Kind::Line)],
                log_x: log,
                log_y: log,
                ..Default::default()
            };
            plot_svg(&dir.path().join("f.svg"), &plot).unwrap();
        }
        assert!(t.elapsed().as_secs_f64() < 5.0, "{:?}", t.elapsed());
    }
}
