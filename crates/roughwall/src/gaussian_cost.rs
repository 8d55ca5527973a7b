//! What the Gaussian assumption costs on a measured wall: the paper's model (Radenkovic &
//! Simonin 2021, Sec. 5, whose facets have Gaussian slopes, Eqs. 9–10) given the scan's own
//! deviations, against the in-place deterministic reference on the scan itself (a point
//! particle, ideally elastic), over [`DIRECTIONS`]. A wall card's note on slopes far from
//! Gaussian quotes it, so that the note says what the shape does to `α⁺`, not only that the
//! kurtosis is large (issue 39, part 7).
//!
//! The reference's histories enter at uniform points of the scan's inner region
//! ([`crate::Tracker::in_place`]); a direction whose entry margins do not fit on the scan, or
//! from which more than [`crate::measured_wall::SERVED_LEFT_BOUND`] of the histories leave it,
//! is not compared (the scan is too small for it) and is counted instead.

use crate::angles::{incident_angles, velocity_from_angles};
use crate::collision::CollisionLaw;
use crate::deterministic::{history_entered, in_place_wall, Fate, LostReason, ModelSetup, Tracker};
use crate::error::Result;
use crate::incidence::{IncidentCondition, SpeedLaw, SpeedReference};
use crate::measured_wall::SERVED_LEFT_BOUND;
use crate::models::{rebound_with, AnyModel};
use crate::rng;
use crate::scan::{Lay, ScanField};
use crate::stochastic::{Contact, PSI_PAPER};
use crate::surface::Triangulation;
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;
use rayon::prelude::*;

/// The incident directions `(α⁻, β⁻)` (degrees, `β⁻` from the lay) compared: grazing,
/// moderate and steep, along, oblique to and across the lay both ways (a measured wall need
/// not be its own mirror image).
pub const DIRECTIONS: [(f64, f64); 12] = [
    (-5.0, 0.0),
    (-5.0, 45.0),
    (-5.0, 90.0),
    (-5.0, -90.0),
    (-15.0, 0.0),
    (-15.0, 45.0),
    (-15.0, 90.0),
    (-15.0, -90.0),
    (-35.0, 0.0),
    (-35.0, 45.0),
    (-35.0, 90.0),
    (-35.0, -90.0),
];

/// Histories of the reference, and rebounds of the paper's model, per direction.
pub const HISTORIES: u64 = 10_000;

/// The seed of both samples: the check is a property of the wall, the same on every run.
pub const SEED: u64 = 2021;

/// The two-sample KS distance (both samples of [`HISTORIES`]) the largest over the
/// [`DIRECTIONS`] exceeds with probability 0.1 % per direction when the two laws are equal:
/// `c(0.001) √(2 / n)`, `c(a) = √(−ln(a/2)/2)` (Massey 1951). Below it the check sees no
/// difference.
pub fn ks_noise() -> f64 {
    let c = (-(0.001f64 / 2.0).ln() / 2.0).sqrt();
    c * (2.0 / HISTORIES as f64).sqrt()
}

/// The paper's model against the scan's reference: the largest KS distance of `α⁺` and where,
/// the largest bias of mean `α⁺` (paper − reference, degrees) and where, over the directions
/// the scan serves; those it does not serve (too many histories leave it).
#[derive(Clone, Debug, PartialEq)]
pub struct GaussianCost {
    /// The largest KS distance of `α⁺` over the served directions.
    pub ks: f64,
    /// Its direction `(α⁻, β⁻)`, degrees.
    pub ks_at: (f64, f64),
    /// The largest bias of mean `α⁺`, paper − reference (degrees).
    pub bias_deg: f64,
    /// Its direction `(α⁻, β⁻)`, degrees.
    pub bias_at: (f64, f64),
    /// The directions not compared: more than [`SERVED_LEFT_BOUND`] of their histories left
    /// the scan.
    pub unserved: Vec<(f64, f64)>,
    /// The control: the same comparison on a generated Gaussian wall with the scan's
    /// deviations, rms height and pixel ([`control_wall`]), over the same served directions:
    /// the paper's model's own miss where the slopes are Gaussian, `(largest KS, largest bias
    /// of mean α⁺ in degrees)`. `None` when it could not be generated.
    pub control: Option<(f64, f64)>,
}

impl GaussianCost {
    /// Whether the paper's model misses the scan by more than it misses the Gaussian control
    /// (or, without one, than nothing), beyond the check's noise: what the wall's shape costs,
    /// not the model's own error.
    pub fn significant(&self) -> bool {
        self.ks > self.control.map_or(0.0, |c| c.0) + ks_noise()
    }

    /// What the scan's notes quote ([`crate::scan::notes`]).
    pub fn effect(&self) -> crate::scan::ShapeEffect {
        crate::scan::ShapeEffect {
            phrase: self.phrase(),
            significant: self.significant(),
        }
    }

    /// What the paper's model misses this wall by, in words, for a card's note.
    pub fn phrase(&self) -> String {
        let unserved = match self.unserved.len() {
            0 => String::new(),
            n => format!(
                " ({n} of the {} directions not served: the scan is too small for them)",
                DIRECTIONS.len()
            ),
        };
        let control = match self.control {
            Some((ks, bias)) => format!(
                "; on a Gaussian wall of the same deviations and pixel it misses by {ks:.3} and {bias:+.2}°, its own error"
            ),
            None => String::new(),
        };
        let verdict = match self.significant() {
            true => "the wall's shape costs the difference: use model = \"measured-wall\" (`rebound scan --measured-wall` builds it) for rebounds as measured",
            false => "within that and the check's noise, the Gaussian models miss this wall no more than a Gaussian one",
        };
        format!(
            "on this scan the paper's model, given its deviations, misses the in-place reference (the scan itself) by a KS distance of α⁺ up to {:.3} (at α⁻ = {}°, β⁻ = {}°) and {:+.2}° in mean α⁺ (at {}°, {}°), over α⁻ = −5°, −15°, −35° × β⁻ = 0°, 45°, ±90°{unserved}, {} histories each (KS noise {:.3}){control}: {verdict}",
            self.ks,
            self.ks_at.0,
            self.ks_at.1,
            self.bias_deg,
            self.bias_at.0,
            self.bias_at.1,
            HISTORIES,
            ks_noise()
        )
    }
}

/// The paper's model against the in-place reference on the levelled scan `levelled` whose lay
/// is `lay` (a point particle, ideally elastic; the wall's deviations are those of the
/// reference's block, `lay`'s when it has none). `None` when the scan serves none of the
/// directions. The same for any thread count: direction `k`'s reference history `i` draws
/// from `rng::stream(SEED, [GAUSSIAN_COST, k, 2i])`, its model rebound from `[…, 2i + 1]`.
pub fn gaussian_cost(
    levelled: &ScanField,
    lay: &Lay,
    triangulation: Triangulation,
) -> Result<Option<GaussianCost>> {
    let window = central_window(levelled, MAX_CHECK_NODES);
    let levelled = window.as_ref();
    let wall = in_place_wall(levelled, lay.angle, None, triangulation)?;
    let tracker = wall.tracker()?;
    let deviations = wall.met_deviations(lay);
    let per_direction: Vec<Option<(f64, f64)>> = (0..DIRECTIONS.len())
        .into_par_iter()
        .map(|k| compare(&tracker, &deviations, k))
        .collect();
    // The control, over the directions the scan serves.
    let control = control_wall(levelled, &deviations).and_then(|f| {
        let tracker =
            Tracker::in_place(&f, crate::deterministic::DEFAULT_MAX_COLLISIONS, 0.0).ok()?;
        let dev = crate::surface::measured_deviations(&f);
        let misses: Vec<Option<(f64, f64)>> = (0..DIRECTIONS.len())
            .into_par_iter()
            .map(|k| match per_direction[k] {
                Some(_) => compare(&tracker, &dev, k),
                None => None,
            })
            .collect();
        misses.into_iter().flatten().fold(None, |acc, (ks, bias)| {
            let (k0, b0): (f64, f64) = acc.unwrap_or((0.0, 0.0));
            Some((k0.max(ks), if bias.abs() > b0.abs() { bias } else { b0 }))
        })
    });
    let mut cost = GaussianCost {
        ks: 0.0,
        ks_at: (0.0, 0.0),
        bias_deg: 0.0,
        bias_at: (0.0, 0.0),
        unserved: Vec::new(),
        control,
    };
    let mut served = false;
    for (k, r) in per_direction.into_iter().enumerate() {
        let at = DIRECTIONS[k];
        let Some((ks, bias)) = r else {
            cost.unserved.push(at);
            continue;
        };
        if !served || ks > cost.ks {
            (cost.ks, cost.ks_at) = (ks, at);
        }
        if !served || bias.abs() > cost.bias_deg.abs() {
            (cost.bias_deg, cost.bias_at) = (bias, at);
        }
        served = true;
    }
    Ok(served.then_some(cost))
}

/// The most nodes per side of the scan the check walks: a larger scan is checked on its
/// central window of this size (hundreds of correlation lengths on any scan that size), so that
/// the check costs a fraction of a second and little memory beside the scan's own.
pub const MAX_CHECK_NODES: usize = 2048;

/// The central `max × max` window of `f` (all of it when it is no larger).
fn central_window(f: &ScanField, max: usize) -> std::borrow::Cow<'_, ScanField> {
    if f.nx <= max && f.ny <= max {
        return std::borrow::Cow::Borrowed(f);
    }
    let (nx, ny) = (f.nx.min(max), f.ny.min(max));
    let (x0, y0) = ((f.nx - nx) / 2, (f.ny - ny) / 2);
    let heights = (y0..y0 + ny)
        .flat_map(|y| f.heights[y * f.nx + x0..y * f.nx + x0 + nx].iter().copied())
        .collect();
    std::borrow::Cow::Owned(ScanField {
        nx,
        ny,
        dx: f.dx,
        dy: f.dy,
        heights,
    })
}

/// The most nodes per side of the control wall: the model's own error depends on the
/// deviations and on how finely the pixel resolves a correlation length, not on the wall's
/// size once it holds the flights; a 4096² scan's control would cost seconds.
pub const MAX_CONTROL_NODES: usize = 1024;

/// The Gaussian control of [`gaussian_cost`] for the levelled scan `levelled` whose
/// deviations are `deviations`: a generated wall (Gaussian heights and autocorrelation,
/// [`crate::surface::generate`], seed [`SEED`]) with the scan's rms height `Sq`, its lay along
/// `x`, correlation lengths `c_L = √2 Sq / Δ` (Radenkovic & Simonin 2021, Eq. 15) so that its
/// deviations are the scan's, the pixel the geometric mean of the scan's two, and the scan's
/// extent (the geometric mean of its sides) up to [`MAX_CONTROL_NODES`] nodes, in multiples of
/// 64. `None` for a flat scan.
pub fn control_wall(
    levelled: &ScanField,
    deviations: &Deviations,
) -> Option<crate::surface::HeightField> {
    let sq = crate::scan::area_parameters(levelled).sq_m;
    let (dx, dy) = (levelled.dx, levelled.dy);
    let pixel = (dx * dy).sqrt();
    let side = ((levelled.nx as f64 * dx) * (levelled.ny as f64 * dy)).sqrt();
    let nodes = ((side / pixel / 64.0).round() as usize).clamp(1, MAX_CONTROL_NODES / 64) * 64;
    let c_l = |delta: f64| crate::wall::corr_length_from_deviation(sq, delta);
    if !(sq > 0.0 && pixel > 0.0) {
        return None;
    }
    let spec = crate::surface::SurfaceSpec {
        length_m: nodes as f64 * pixel,
        nodes,
        rms_height_m: sq,
        corr_length_x_m: c_l(deviations.delta_xi),
        corr_length_z_m: c_l(deviations.delta_zeta),
    };
    Some(crate::surface::generate(&spec, SEED))
}

/// Direction `k`: the KS distance of `α⁺` and the bias of mean `α⁺` (paper − reference,
/// degrees); `None` when the entry region's margins do not fit on the scan, or more than
/// [`SERVED_LEFT_BOUND`] of the histories leave it.
fn compare(tracker: &Tracker<'_>, deviations: &Deviations, k: usize) -> Option<(f64, f64)> {
    let (alpha_deg, beta_deg) = DIRECTIONS[k];
    let cond = IncidentCondition::from_degrees(alpha_deg, beta_deg);
    let law = CollisionLaw::Elastic;
    let setup = ModelSetup {
        law,
        diameter_m: 0.0,
        speed: SpeedLaw {
            mean_m_s: 1.0,
            std_m_s: 0.0,
            reference: SpeedReference::Magnitude,
        },
        wall: *deviations,
        psi: PSI_PAPER,
        erosion: None,
        spin: Default::default(),
    };
    let contact = Contact {
        wall: deviations,
        law: &law,
        psi: PSI_PAPER,
        diameter_m: 0.0,
    };
    let u = velocity_from_angles(1.0, alpha_deg.to_radians(), beta_deg.to_radians());
    // Entry margins that do not fit on the scan: its flights would leave it (and a spiky
    // scan's would be long); the direction is not served, and no history is shot.
    if let Some(patch) = tracker.patch() {
        if patch.margins(cond.alpha_in, &patch.to_field(&u)).clamped {
            return None;
        }
    }
    let prefix = rng::StreamPrefix::new(SEED, &[rng::domain::GAUSSIAN_COST, k as u64]);
    let alpha_out = |v: &Vector3<f64>| incident_angles(v).0.to_degrees();
    let (mut reference, mut model) = (Vec::new(), Vec::new());
    let mut left = 0u64;
    for i in 0..HISTORIES {
        let mut r = prefix.stream(2 * i);
        let entry: (f64, f64) = (r.gen(), r.gen());
        let h = history_entered(tracker, &setup, &cond, entry, &mut r, |_| {});
        match h.fate {
            Fate::Escaped => reference.push(alpha_out(&h.velocity)),
            Fate::Lost(LostReason::LeftPatch) => left += 1,
            Fate::Lost(_) => {}
        }
        let mut r = prefix.stream(2 * i + 1);
        let out = rebound_with(&AnyModel::PAPER, u, Vector3::zeros(), &contact, &mut r);
        model.push(alpha_out(&out.velocity));
    }
    if left as f64 > SERVED_LEFT_BOUND * HISTORIES as f64 || reference.is_empty() {
        return None;
    }
    let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len() as f64;
    let bias = mean(&model) - mean(&reference);
    Some((crate::tally::ks_samples(&mut model, &mut reference), bias))
}

/// [`gaussian_cost`] of a characterised scan, for its card's notes: `None` without a lay,
/// when a deviation is beyond what the models take ([`crate::wall::MAX_DEVIATION_DEG`]: there
/// is no model to check), or when the scan cannot carry the in-place reference (no complete
/// 3 × 3 block, none of the directions served); a resource error stays an error.
pub fn of_scan(
    c: &crate::scan::Characterisation,
    triangulation: Triangulation,
) -> Result<Option<GaussianCost>> {
    let Some(lay) = &c.lay else {
        return Ok(None);
    };
    if lay.delta_xi.max(lay.delta_zeta).to_degrees() > crate::wall::MAX_DEVIATION_DEG {
        return Ok(None);
    }
    match gaussian_cost(&c.levelled, lay, triangulation) {
        Ok(cost) => Ok(cost),
        Err(crate::Error::Input(_)) => Ok(None),
        Err(e) => Err(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scan::{characterise, ScanField};

    /// V-grooves across `x` (facets at exactly ±`slope_deg`), with a slight random roughness so
    /// that the lay is defined: far from Gaussian (two facet families, not a bell).
    fn grooves(n: usize, slope_deg: f64) -> crate::scan::Characterisation {
        let period = 16.0;
        let t = slope_deg.to_radians().tan();
        let heights = (0..n * n)
            .map(|k| {
                let (i, j) = ((k % n) as f64, (k / n) as f64);
                let p = (j / period).fract();
                let tri = period * (p - 0.5).abs();
                t * tri * 1e-6 + 1e-9 * ((i * 12.9898 + j * 78.233).sin() * 43758.5453).fract()
            })
            .collect();
        characterise(ScanField::new(n, n, 1e-6, 1e-6, heights).unwrap(), 1).unwrap()
    }

    #[test]
    fn grooves_are_missed_by_the_gaussian_model_far_beyond_the_noise() {
        let c = grooves(512, 5.0);
        let cost = of_scan(&c, Triangulation::default()).unwrap().unwrap();
        assert!(cost.unserved.is_empty(), "{cost:?}");
        assert!(cost.significant() && cost.ks > 0.1, "{cost:?}");
        assert!(cost.phrase().contains("use model = \"measured-wall\""));
    }

    #[test]
    fn a_gaussian_scan_is_missed_no_more_than_its_gaussian_control() {
        // The Sec. 3 wall, 1024² nodes: the paper's model misses it by its own error only.
        let g = crate::scan::tests::sec3_wall(1024, 5);
        let f = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights).unwrap();
        let c = characterise(f, 1).unwrap();
        let cost = of_scan(&c, Triangulation::default()).unwrap().unwrap();
        let control = cost.control.unwrap();
        assert!(!cost.significant(), "{cost:?}");
        assert!(control.0 < 0.1 && cost.ks < 0.1, "{cost:?}");
    }

    #[test]
    fn the_check_is_the_same_on_any_thread_count() {
        let c = grooves(256, 3.0);
        let on = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| of_scan(&c, Triangulation::default()).unwrap())
        };
        assert_eq!(on(1), on(2));
    }

    #[test]
    fn a_scan_too_small_for_grazing_incidence_is_not_compared_there() {
        // 96 × 96 µm of 15° grooves 2.1 µm deep: at −5° the entry margins (3 Δh cot α⁻ a
        // side, as much again downstream: about 220 µm) do not fit on it; at −35° (27 µm) they do.
        let c = grooves(96, 15.0);
        let cost = of_scan(&c, Triangulation::default()).unwrap().unwrap();
        assert!(cost.unserved.iter().any(|d| d.0 == -5.0), "{cost:?}");
        assert!(cost.unserved.iter().all(|d| d.0 != -35.0), "{cost:?}");
        assert!(cost.ks_at.0 != -5.0 || !cost.unserved.contains(&cost.ks_at));
        assert!(cost.phrase().contains("not served"));
    }

    #[test]
    fn a_wall_beyond_the_models_range_is_not_checked() {
        // 25° grooves: Δζ ≈ 25°, beyond the 20° every model refuses: no model to check.
        let c = grooves(128, 25.0);
        assert!(c.lay.unwrap().delta_zeta.to_degrees() > crate::wall::MAX_DEVIATION_DEG);
        assert_eq!(of_scan(&c, Triangulation::default()).unwrap(), None);
        let notes = crate::scan::notes(&c, None);
        assert!(
            notes
                .iter()
                .any(|n| n.contains("not measured: the models refuse deviations beyond 20°")),
            "{notes:?}"
        );
    }

    #[test]
    fn the_noise_is_masseys_bound() {
        // c(0.001) = 1.949 (Massey 1951, Table 1 extended): 1.949 √(2/10000) = 0.0276.
        assert!((ks_noise() - 0.0276).abs() < 1e-4, "{}", ks_noise());
    }
}
