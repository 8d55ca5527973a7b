//! The notes of a wall card (`rebound scan`'s `wall_card.toml`, its warnings, and the
//! Python package's `roughwall.wall_card`): where a characterised scan is outside what the
//! models assume (deviations beyond the low-roughness range of Radenkovic & Simonin 2021,
//! Eq. 6, slopes far from Gaussian), too holed or too small to trust, and, per particle
//! diameter, where it is too small for the deviations that particle sees or they are
//! resolution-limited (the criteria of [`super::resolution`]). One line per note, in words.

use super::lay::Lay;
use super::resolution::{SeenBy, MAX_RESOLUTION_CHANGE, MIN_CORRELATION_AREAS, MIN_EXACT_FRACTION};
use super::{Characterisation, ScanField};
use crate::format::fmt_num;
use crate::wall::{LOW_ROUGHNESS_LIMIT_DEG, MAX_DEVIATION_DEG};

/// A slope quantum (the height step over the pixel) at least this share of the smaller
/// deviation is noted: the rebound angles then form a comb (plu-1: 0.98).
pub const MAX_SLOPE_QUANTUM_SHARE: f64 = 0.25;

/// Below this spread (rad) an angle is constant: its shape (skewness, kurtosis, correlation)
/// is undefined, as the library's `lay` takes it.
pub const NO_SPREAD_RAD: f64 = 1e-12;

/// A slope angle whose |skewness| exceeds this is noted as far from Gaussian.
pub const MAX_ABS_SKEWNESS: f64 = 0.5;
/// A slope angle whose |kurtosis − 3| exceeds this is noted as far from Gaussian.
pub const MAX_EXCESS_KURTOSIS: f64 = 1.0;
/// More missing points than this fraction are noted.
pub const MAX_MISSING_FRACTION: f64 = 0.10;
/// A scan with fewer points than this along a side is noted as small.
pub const MIN_SIDE_POINTS: usize = 100;

/// The fraction of the scan's points that are missing.
pub fn missing_fraction(c: &Characterisation) -> f64 {
    let f = &c.levelled;
    1.0 - c.parameters.valid_points as f64 / (f.nx * f.ny) as f64
}

/// The lay's statistics that are defined: `[ξ', ζ']` has a spread.
pub fn spread(l: &Lay) -> [bool; 2] {
    [l.delta_xi > NO_SPREAD_RAD, l.delta_zeta > NO_SPREAD_RAD]
}

/// What the Gaussian assumption costs on a scan, as its notes quote it (measured by
/// `crate::gaussian_cost`, which sits above the scan's modules).
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeEffect {
    /// In words: the paper's model against the scan and against a Gaussian control.
    pub phrase: String,
    /// Whether the scan is missed beyond the control and the check's noise.
    pub significant: bool,
}

/// The notes of the wall card (and the run's warnings): where the wall is outside what the
/// models assume, or the scan too small or too holed to trust. `cost` is what the Gaussian
/// assumption costs on this scan (`None`: not measured, the scan serving none of the check's
/// directions): a note on slopes far from Gaussian says it, and where the slopes look Gaussian
/// but the paper's model still misses the scan, that is a note of its own.
pub fn notes(c: &Characterisation, cost: Option<&ShapeEffect>) -> Vec<String> {
    let mut out = Vec::new();
    let mut shape_noted = false;
    match &c.lay {
        None => out.push(
            "no cell of the scan has four valid corners: no lay and no deviations ([wall] and [lay] are left out)"
                .to_string(),
        ),
        Some(l) => {
            for (symbol, where_, d) in [
                ("Δξ", "along the lay", l.delta_xi),
                ("Δζ", "across the lay", l.delta_zeta),
            ] {
                let deg = d.to_degrees();
                if deg > MAX_DEVIATION_DEG {
                    out.push(format!(
                        "{symbol} = {}° ({where_}) is beyond {MAX_DEVIATION_DEG}°: the wall models refuse it (they stop at {MAX_DEVIATION_DEG}°; the low-roughness approximation, Eq. 6, at ~{LOW_ROUGHNESS_LIMIT_DEG}°)",
                        fmt_num(deg)
                    ));
                } else if deg > LOW_ROUGHNESS_LIMIT_DEG {
                    out.push(format!(
                        "{symbol} = {}° ({where_}) is beyond {LOW_ROUGHNESS_LIMIT_DEG}°, outside the low-roughness approximation (Eq. 6): the models' results are extrapolated",
                        fmt_num(deg)
                    ));
                }
            }
            if let Some(note) = quantized_note(c, l) {
                out.push(note);
            }
            let mut shapes = Vec::new();
            for (k, (angle, where_)) in [("ξ'", "along the lay"), ("ζ'", "across the lay")]
                .into_iter()
                .enumerate()
            {
                if !spread(l)[k] {
                    continue;
                }
                let (sk, ku) = (l.skewness[k], l.kurtosis[k]);
                let mut far = Vec::new();
                if sk.abs() > MAX_ABS_SKEWNESS {
                    far.push(format!("skewness {sk:.2} (|skewness| > {MAX_ABS_SKEWNESS})"));
                }
                if (ku - 3.0).abs() > MAX_EXCESS_KURTOSIS {
                    far.push(format!("kurtosis {ku:.2} (|kurtosis − 3| > {MAX_EXCESS_KURTOSIS})"));
                }
                if !far.is_empty() {
                    shapes.push(format!("{angle} ({where_}) has {}", far.join(" and ")));
                }
            }
            if !shapes.is_empty() {
                let beyond = l.delta_xi.max(l.delta_zeta).to_degrees() > MAX_DEVIATION_DEG;
                let effect = match cost {
                    Some(cost) => cost.phrase.clone(),
                    None if beyond => format!("what this does to rebounds is not measured: the models refuse deviations beyond {MAX_DEVIATION_DEG}°"),
                    None => "what this does to rebounds is not measured: the scan is too small for the in-place reference's directions".to_string(),
                };
                out.push(format!(
                    "slopes far from Gaussian: {}; Gaussian slopes have 0 and 3, and the models assume them: {effect}",
                    shapes.join("; ")
                ));
                shape_noted = true;
            }
            if let Some(u) = c.lay_uncertainty {
                if !u.significant() && spread(l).iter().any(|&s| s) {
                    out.push(format!(
                        "isotropic within what the scan shows: Δζ − Δξ = {}° ± {}° over {} sub-patches ({} standard errors, fewer than {}), and the sub-patches put the lay {}° apart: no lay is given, and [wall] has the rms of the two deviations for both",
                        fmt_num(significant(u.anisotropy.to_degrees(), 3)),
                        fmt_num(significant(u.anisotropy_se.to_degrees(), 2)),
                        u.patches,
                        fmt_num(round(u.t(), 1)),
                        super::lay_uncertainty::ANISOTROPY_T,
                        fmt_num(significant((u.angle_se * (u.patches as f64).sqrt()).to_degrees(), 2)),
                    ));
                }
            }
        }
    }
    if let Some(cost) = cost.filter(|c| !shape_noted && c.significant) {
        out.push(format!(
            "the Gaussian models miss this wall by more than the check's noise, although its slopes' skewness and kurtosis look Gaussian: {}",
            cost.phrase
        ));
    }
    let missing = missing_fraction(c);
    if missing > MAX_MISSING_FRACTION {
        out.push(format!(
            "{:.1} % of the points are missing (more than {:.0} %): the statistics are those of the measured part",
            100.0 * missing,
            100.0 * MAX_MISSING_FRACTION
        ));
    }
    let f = &c.levelled;
    if f.nx < MIN_SIDE_POINTS || f.ny < MIN_SIDE_POINTS {
        out.push(format!(
            "a {} × {} scan has fewer than {MIN_SIDE_POINTS} × {MIN_SIDE_POINTS} points: its statistics are uncertain",
            f.nx, f.ny
        ));
    }
    out
}

/// The note on heights written in whole steps coarse enough to show in the slopes
/// ([`super::height_step`], [`MAX_SLOPE_QUANTUM_SHARE`]).
fn quantized_note(c: &Characterisation, l: &Lay) -> Option<String> {
    let step = c.height_step_m?;
    let f = &c.levelled;
    // The least slope step a facet can have, along the longer pixel side.
    let quantum = (step / f.dx.max(f.dy)).atan();
    let smaller = l.delta_xi.min(l.delta_zeta);
    if !(smaller > 0.0 && quantum >= MAX_SLOPE_QUANTUM_SHARE * smaller) {
        return None;
    }
    Some(format!(
        "heights in whole steps of {} nm ({} % of Sq), the instrument's resolution: facet slopes take values {}° apart, {} of the smaller deviation ({}°), so rebound angles off the scan form a comb of spikes the wall itself would not show; the in-place reference and the measured-wall tables inherit it, and the measured-wall model, whose tables keep each angle's spikes but pair them only within rank bins, had KS above 0.011 against its goal of 0.01 on such a scan (plu-1, REPORT.md \"The wall's own model against the scan itself\") and met it once the heights were dithered by half a step (docs/models.md): measure with a finer height resolution where the instrument has one",
        fmt_num(significant(step * 1e9, 4)),
        fmt_num(significant(100.0 * step / c.parameters.sq_m, 2)),
        fmt_num(significant(quantum.to_degrees(), 3)),
        fmt_num(significant(quantum / smaller, 2)),
        fmt_num(significant(smaller.to_degrees(), 3)),
    ))
}

/// Where the scan is too small for the particle of `s`, or its deviations resolution-limited
/// (they change by more than 5 % at twice the pixel), one line per criterion met (none: the
/// scan serves it).
pub fn criteria(s: &SeenBy, f: &ScanField) -> Vec<String> {
    let r = &s.resolution;
    let point = s.seen.diameter_m == 0.0;
    let mut out = Vec::new();
    let [rx, ry] = reach_um(s, f);
    let band = format!(
        "the edges lose a band of √(2RΔh) = {} µm along x, {} µm along y",
        fmt_num(significant(rx, 3)),
        fmt_num(significant(ry, 3))
    );
    if s.seen.lay.is_none() {
        out.push(format!(
            "too small: no triangle of the centre surface is exact ({band}): no deviations"
        ));
    } else if r.too_small() {
        let mut why = Vec::new();
        if r.correlation_areas < MIN_CORRELATION_AREAS {
            let part = if point { "valid part" } else { "exact part" };
            let areas = r.correlation_areas.round();
            let se = (100.0 * r.relative_error()).round();
            // A length only bounded by a quarter of the scan makes the count an upper bound.
            why.push(match r.bounded {
                [false, false] => format!(
                    "its {part} holds {areas} correlation areas (fewer than {MIN_CORRELATION_AREAS}): Δ is uncertain by about {se} %"
                ),
                [along, _] => format!(
                    "its {part} holds at most {areas} correlation areas (fewer than {MIN_CORRELATION_AREAS}; the autocorrelation does not fall to 1/e within a quarter of the scan {} the lay): Δ is uncertain by about {se} % or more",
                    if along { "along" } else { "across" }
                ),
            });
        }
        if r.exact_fraction < MIN_EXACT_FRACTION {
            let what = if point {
                "of its points are valid".to_string()
            } else {
                format!("of it is exact ({band})")
            };
            why.push(format!(
                "only {} % {what}, less than {} %",
                fmt_num(significant(100.0 * r.exact_fraction, 3)),
                100.0 * MIN_EXACT_FRACTION
            ));
        }
        out.push(format!("too small: {}", why.join("; ")));
    }
    if s.resolution_limited() {
        let [xi, zeta] = s.resolution_change().unwrap_or([0.0, 0.0]);
        let pct = |x: f64| format!("{:+.1} %", 100.0 * x);
        let what = if point {
            "a point particle's deviations are those of the pixel: measure with a finer pixel, or take the row of the particle's diameter"
        } else {
            "measure with a finer pixel, or this diameter's deviations are a bound (a larger particle settles sooner)"
        };
        out.push(format!(
            "resolution-limited: Δξ and Δζ change by {} and {} when the pixel is doubled (more than {} %): {what}",
            pct(xi),
            pct(zeta),
            100.0 * MAX_RESOLUTION_CHANGE,
        ));
    }
    out
}

/// The notes of one particle for the run's warnings and the card's `notes`: each criterion
/// met, labelled with the particle.
pub fn labelled(s: &SeenBy, f: &ScanField) -> Vec<String> {
    let label = match s.seen.diameter_m {
        0.0 => "point particle ([wall])".to_string(),
        d => format!("D = {} µm", fmt_num(d * 1e6)),
    };
    criteria(s, f)
        .into_iter()
        .map(|n| format!("{label}: the scan is {n}"))
        .collect()
}

/// The reach `√(2RΔh)` (µm) along the scan's `x` and `y`: the band the edges lose.
pub fn reach_um(s: &SeenBy, f: &ScanField) -> [f64; 2] {
    let [rx, ry] = s.seen.reach;
    [rx as f64 * f.dx * 1e6, ry as f64 * f.dy * 1e6]
}

/// `x` rounded to `digits` decimals.
fn round(x: f64, digits: i32) -> f64 {
    let p = 10f64.powi(digits);
    (x * p).round() / p
}

/// `x` rounded to `digits` significant digits.
fn significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    round(x, digits - 1 - x.abs().log10().floor() as i32)
}
