//! The quantities of the pipe-flow study, as functions of a run's sums ([`super::sums`]),
//! each given a standard error by [`super::jackknife`].
//!
//! Conventions (docs/pipe-flow.md): the pipe axis is x, y is up (gravity −y), z horizontal;
//! `R` the pipe radius. Profiles bin y (vertical) or z (horizontal) over [−R, R]: slab
//! averages (each bin a chord band across the whole section), or strips along the vertical
//! and horizontal diameters (the other coordinate within ±R/5). Concentration is normalised
//! by the mean: the fraction of samples in a bin over the bin's share of the cross-section's
//! area, taken on the mesh's polygonal wall ([`super::section`]; 1 everywhere for a uniform
//! suspension).
//! The wall-normal velocity is the radial component `u_r = (u_y y + u_z z)/r`, positive
//! towards the wall. Erosion is a law's volume per particle mass (Finnie, Oka, DNV) summed
//! over the hits, at the impact angle on the wall element struck (the facet the library
//! drew) or on the mean wall, and divided by the wall area and by the mass of particles
//! conveyed through a cross-section (`Σ_p m_p x_p / L` for particles that travelled `x_p`):
//! the loss of wall thickness per mass conveyed, in µm per tonne.

use super::jackknife::{estimate, Estimate};
use super::section::CrossSection;
use super::sums::{Layout, RunSums, ALPHA_BINS, LAWS, LAY_BINS, THETA_BINS};

/// The centre of bin `b` of `nb` across a diameter, over R.
pub fn bin_centre_over_r(b: usize, nb: usize) -> f64 {
    -1.0 + (b as f64 + 0.5) * 2.0 / nb as f64
}

/// A whole-run quantity: its column name (docs/outputs.md says what each is) and its
/// statistic of one run's sums and the pipe radius (m).
pub struct Quantity {
    pub name: &'static str,
    pub f: fn(&Layout, &[f64], f64) -> f64,
}

fn total_over_bins(l: &Layout, s: &[f64], at: fn(&Layout, usize) -> usize) -> f64 {
    (0..l.nb).map(|b| s[at(l, b)]).sum()
}

/// The square root of a variance computed as a difference of means, which round-off may
/// push below 0; NaN (no sample) stays NaN (`f64::max` would make it 0).
fn sqrt_var(var: f64) -> f64 {
    if var.is_nan() {
        f64::NAN
    } else {
        var.max(0.0).sqrt()
    }
}

/// The rms fluctuation of a velocity component about its local mean: the variance within
/// each horizontal slab (about that slab's mean), averaged over the samples, so that the
/// mean profile's variation across the pipe does not count as fluctuation. Its sums and sums
/// of squares per slab are at `sum` and `sq`.
fn fluctuation_rms(
    l: &Layout,
    s: &[f64],
    sum: fn(&Layout, usize) -> usize,
    sq: fn(&Layout, usize) -> usize,
) -> f64 {
    let within: f64 = (0..l.nb)
        .filter(|&b| s[l.cy(b)] > 0.0)
        .map(|b| s[sq(l, b)] - s[sum(l, b)] * s[sum(l, b)] / s[l.cy(b)])
        .sum();
    sqrt_var(within / s[Layout::SAMPLES])
}

/// m/kg of wall thickness per mass conveyed → µm per tonne.
const M_PER_KG_TO_UM_PER_T: f64 = 1e9;

/// The study's whole-run quantities (`summary.csv`, `comparisons.csv`), in column order.
pub const QUANTITIES: [Quantity; 16] = [
    Quantity {
        name: "collisions_per_m",
        f: |_, s, _| s[Layout::HITS] / s[Layout::DIST],
    },
    Quantity {
        name: "mean_ux_m_s",
        f: |l, s, _| total_over_bins(l, s, Layout::ux) / s[Layout::SAMPLES],
    },
    Quantity {
        name: "rms_ux_m_s",
        f: |l, s, _| fluctuation_rms(l, s, Layout::ux, Layout::ux2),
    },
    Quantity {
        name: "rms_ur_m_s",
        f: |l, s, _| fluctuation_rms(l, s, Layout::ur, Layout::ur2),
    },
    Quantity {
        name: "mean_height_over_r",
        f: |_, s, r| s[Layout::SUM_Y] / s[Layout::SAMPLES] / r,
    },
    Quantity {
        name: "bottom_half_fraction",
        f: |l, s, _| (0..l.nb / 2).map(|b| s[l.cy(b)]).sum::<f64>() / s[Layout::SAMPLES],
    },
    Quantity {
        name: "mean_alpha_in_deg",
        f: |l, s, _| s[l.sum_alpha_in()] / s[l.logged_hits()],
    },
    Quantity {
        name: "mean_alpha_element_deg",
        f: |l, s, _| s[l.sum_alpha_element()] / s[l.logged_hits()],
    },
    Quantity {
        name: "mean_alpha_change_deg",
        f: |l, s, _| s[l.sum_alpha_change()] / s[l.logged_hits()],
    },
    Quantity {
        name: "mean_deflection_deg",
        f: |l, s, _| s[l.sum_deflection()] / s[l.logged_hits()],
    },
    Quantity {
        name: "erosion_finnie_um_per_t",
        f: |l, s, r| erosion_um_per_t(l, s, r, 0, true),
    },
    Quantity {
        name: "erosion_oka_um_per_t",
        f: |l, s, r| erosion_um_per_t(l, s, r, 1, true),
    },
    Quantity {
        name: "erosion_dnv_um_per_t",
        f: |l, s, r| erosion_um_per_t(l, s, r, 2, true),
    },
    Quantity {
        name: "erosion_finnie_mean_wall_um_per_t",
        f: |l, s, r| erosion_um_per_t(l, s, r, 0, false),
    },
    Quantity {
        name: "erosion_oka_mean_wall_um_per_t",
        f: |l, s, r| erosion_um_per_t(l, s, r, 1, false),
    },
    Quantity {
        name: "erosion_dnv_mean_wall_um_per_t",
        f: |l, s, r| erosion_um_per_t(l, s, r, 2, false),
    },
];

/// Law `law`'s erosion (index into [`LAWS`]) averaged over the whole wall (µm per tonne
/// conveyed), at the impact angle on the element struck (`element`) or on the mean wall;
/// pipe radius `r` (m).
pub fn erosion_um_per_t(l: &Layout, s: &[f64], r: f64, law: usize, element: bool) -> f64 {
    s[l.sum_erosion(law, element)] / (2.0 * std::f64::consts::PI * r * s[Layout::DIST])
        * M_PER_KG_TO_UM_PER_T
}

/// Law `law`'s erosion (on the element struck) in circumferential bin `k` (folded: both
/// sides), µm per tonne conveyed.
pub fn erosion_theta_um_per_t(l: &Layout, s: &[f64], r: f64, law: usize, k: usize) -> f64 {
    let dtheta = std::f64::consts::PI / THETA_BINS as f64;
    s[l.erosion_theta(law, k)] / (2.0 * r * dtheta * s[Layout::DIST]) * M_PER_KG_TO_UM_PER_T
}

/// One profile point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfilePoint {
    pub position_over_r: f64,
    pub concentration: Estimate,
    /// Velocity statistics of the slab (vertical slab profile only).
    pub ux_mean: Option<Estimate>,
    pub ux_rms: Option<Estimate>,
    pub ur_mean: Option<Estimate>,
    pub ur_rms: Option<Estimate>,
}

/// Which profile: slab averages across the whole section, or strips along a diameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    /// Bins of y, each a band across the whole width (with the velocities).
    VerticalSlabs,
    /// Bins of z, each a band across the whole height.
    HorizontalSlabs,
    /// Bins of y within the strip |z| < R/5: along the vertical diameter.
    VerticalDiameter,
    /// Bins of z within |y| < R/5: along the horizontal diameter.
    HorizontalDiameter,
}

/// Half the width of the strips along the diameters, over R (pipe_tally.c).
pub const STRIP_HALF_WIDTH: f64 = 0.2;

impl Profile {
    pub const ALL: [Profile; 4] = [
        Profile::VerticalSlabs,
        Profile::HorizontalSlabs,
        Profile::VerticalDiameter,
        Profile::HorizontalDiameter,
    ];

    /// Its name in `profiles.csv`.
    pub fn name(self) -> &'static str {
        match self {
            Profile::VerticalSlabs => "vertical",
            Profile::HorizontalSlabs => "horizontal",
            Profile::VerticalDiameter => "vertical_diameter",
            Profile::HorizontalDiameter => "horizontal_diameter",
        }
    }

    fn along_y(self) -> bool {
        matches!(self, Profile::VerticalSlabs | Profile::VerticalDiameter)
    }
}

/// A profile of a run; `section` gives the bins' areas.
pub fn profile(run: &RunSums, section: &CrossSection, kind: Profile) -> Vec<ProfilePoint> {
    let l = run.layout;
    let w = 2.0 / l.nb as f64;
    (0..l.nb)
        .map(|b| {
            let lo = -1.0 + b as f64 * w;
            let strip = match kind {
                Profile::VerticalDiameter | Profile::HorizontalDiameter => Some(STRIP_HALF_WIDTH),
                _ => None,
            };
            let share = section.share(kind.along_y(), lo, lo + w, strip);
            let at = match kind {
                Profile::VerticalSlabs => l.cy(b),
                Profile::HorizontalSlabs => l.cz(b),
                Profile::VerticalDiameter => l.sy(b),
                Profile::HorizontalDiameter => l.sz(b),
            };
            let concentration = estimate(&[run], |s| s[0][at] / s[0][Layout::SAMPLES] / share);
            let (cy, ux, ux2, ur, ur2) = (l.cy(b), l.ux(b), l.ux2(b), l.ur(b), l.ur2(b));
            let mean = move |sum: usize| move |s: &[&[f64]]| s[0][sum] / s[0][cy];
            let rms = move |sum: usize, sq: usize| {
                move |s: &[&[f64]]| {
                    let m = s[0][sum] / s[0][cy];
                    sqrt_var(s[0][sq] / s[0][cy] - m * m)
                }
            };
            let velocities = kind == Profile::VerticalSlabs;
            ProfilePoint {
                position_over_r: bin_centre_over_r(b, l.nb),
                concentration,
                ux_mean: velocities.then(|| estimate(&[run], mean(ux))),
                ux_rms: velocities.then(|| estimate(&[run], rms(ux, ux2))),
                ur_mean: velocities.then(|| estimate(&[run], mean(ur))),
                ur_rms: velocities.then(|| estimate(&[run], rms(ur, ur2))),
            }
        })
        .collect()
}

/// One bin of a distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DistBin {
    pub lo: f64,
    pub hi: f64,
    pub value: Estimate,
}

/// The PDF (per degree) of the impact angle, or (`lay`) of the angle between the incident
/// plane and the lay.
pub fn angle_pdf(run: &RunSums, lay: bool) -> Vec<DistBin> {
    let l = run.layout;
    let (n, width) = if lay {
        (LAY_BINS, 90.0 / LAY_BINS as f64)
    } else {
        (ALPHA_BINS, 90.0 / ALPHA_BINS as f64)
    };
    (0..n)
        .map(|k| {
            let at = if lay { l.lay_hist(k) } else { l.alpha_hist(k) };
            DistBin {
                lo: k as f64 * width,
                hi: (k + 1) as f64 * width,
                value: estimate(&[run], |s| s[0][at] / s[0][l.logged_hits()] / width),
            }
        })
        .collect()
}

/// Law `law`'s erosion (on the element struck) around the circumference (folded), pipe
/// radius `r`.
pub fn erosion_profile(run: &RunSums, r: f64, law: usize) -> Vec<DistBin> {
    debug_assert!(law < LAWS.len());
    let l = run.layout;
    let width = 180.0 / THETA_BINS as f64;
    (0..THETA_BINS)
        .map(|k| DistBin {
            lo: k as f64 * width,
            hi: (k + 1) as f64 * width,
            value: estimate(&[run], |s| erosion_theta_um_per_t(&l, s[0], r, law, k)),
        })
        .collect()
}
