//! Heights an instrument wrote in whole steps (a digitiser's resolution): the step, found
//! on the scan as read, before levelling turns the steps into a plane's fractions.
//!
//! On such a scan a facet's slope along `x` is a whole number of steps over the pixel, so
//! when that slope quantum is a fair part of the wall's deviations, the point particle's
//! rebound angles form a comb of spikes a real wall would not show (plu-1: 3.906 nm steps
//! over 1.66 µm, 0.135° against deviations of 0.14°, 0.23°; docs/models.md, "The measured-wall
//! model"). No paper equation: a property of the data, which the card's notes report.

use super::ScanField;

/// Height differences examined at most (spread over the scan): a million pins the step
/// of any real digitiser, and bounds the work on the largest scan.
const MAX_DIFFERENCES: usize = 1 << 20;

/// Share of the non-zero differences that must be whole multiples of the step.
const ON_STEP_SHARE: f64 = 0.99;

/// How far from a whole multiple of the step (in steps) still counts as one: the rounding of
/// the scale factor a file applies to its integers, and of the difference itself (relative).
const ON_STEP_TOLERANCE: f64 = 1e-3;
const ON_STEP_RELATIVE: f64 = 1e-9;

/// The height step (m) of a scan read in whole steps of one size, `None` when its heights are
/// not (or too few differ). Judged on the differences between neighbours along `x`: on a
/// digitised scan every one is a whole number of steps, the least non-zero of them one step.
pub fn height_step(f: &ScanField) -> Option<f64> {
    let pairs = f.nx.saturating_sub(1) * f.ny;
    let stride = pairs.div_ceil(MAX_DIFFERENCES).max(1);
    let differences: Vec<f64> = (0..pairs)
        .step_by(stride)
        .filter_map(|k| {
            let (i, j) = (k % (f.nx - 1), k / (f.nx - 1));
            let a = f.heights[j * f.nx + i];
            let b = f.heights[j * f.nx + i + 1];
            let d = (b - a).abs();
            (d.is_finite() && d > 0.0).then_some(d)
        })
        .collect();
    if differences.len() < 16 {
        return None;
    }
    let step = differences.iter().copied().fold(f64::INFINITY, f64::min);
    let on_step = differences
        .iter()
        .filter(|&&d| {
            let k = d / step;
            (k - k.round()).abs() <= ON_STEP_TOLERANCE + ON_STEP_RELATIVE * k
        })
        .count();
    (on_step as f64 >= ON_STEP_SHARE * differences.len() as f64).then_some(step)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(heights: Vec<f64>, nx: usize) -> ScanField {
        let ny = heights.len() / nx;
        ScanField::new(nx, ny, 1e-6, 1e-6, heights).unwrap()
    }

    #[test]
    fn whole_steps_are_found_and_continuous_heights_are_not() {
        // Heights of a smooth wave in whole 3.906 nm steps, with an offset and a hole.
        let q = 1e-6 / 256.0;
        let (nx, ny) = (64, 48);
        let wave = |i: usize, j: usize| 2e-8 * ((i as f64 * 0.37).sin() + (j as f64 * 0.21).cos());
        let mut h: Vec<f64> = (0..nx * ny)
            .map(|k| 5e-6 + (wave(k % nx, k / nx) / q).round() * q)
            .collect();
        h[100] = f64::NAN;
        let step = height_step(&field(h.clone(), nx)).unwrap();
        assert!((step / q - 1.0).abs() < 1e-9, "{step}");
        // The same wave, not digitised; and the digitised one with a half-step dither.
        let smooth: Vec<f64> = (0..nx * ny).map(|k| wave(k % nx, k / nx)).collect();
        assert_eq!(height_step(&field(smooth, nx)), None);
        let dithered: Vec<f64> = h
            .iter()
            .enumerate()
            .map(|(k, x)| x + q * (((k * 7919) % 1000) as f64 / 1000.0 - 0.5))
            .collect();
        assert_eq!(height_step(&field(dithered, nx)), None);
        // A flat scan has no difference to judge by.
        assert_eq!(height_step(&field(vec![1e-6; nx * ny], nx)), None);
    }

    /// The card notes a step that shows in the slopes (a quarter of the smaller deviation or
    /// more), and not one that does not.
    #[test]
    fn a_step_the_slopes_show_is_noted() {
        let g = crate::scan::tests::sec3_wall(128, 3);
        let pixel = g.dx;
        // (2.5°, 7.5°) deviations: a step of 1.2° of slope over the pixel shows, 0.01° does not.
        for (slope_deg, noted) in [(1.2, true), (0.01, false)] {
            let q = pixel * f64::to_radians(slope_deg).tan();
            let h: Vec<f64> = g.heights.iter().map(|x| (x / q).round() * q).collect();
            let f = ScanField::new(g.nx, g.nz, g.dx, g.dz, h).unwrap();
            let c = crate::scan::characterise(f, 1).unwrap();
            assert!((c.height_step_m.unwrap() / q - 1.0).abs() < 1e-6);
            let notes = crate::scan::notes(&c, None);
            let note = notes
                .iter()
                .find(|n| n.starts_with("heights in whole steps"));
            assert_eq!(note.is_some(), noted, "{slope_deg}°: {notes:?}");
        }
    }
}
