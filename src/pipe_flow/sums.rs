//! One run's sums, in [`BATCHES`] batches of particles (particle id modulo [`BATCHES`]):
//! particles do not interact (one-way coupling), so the batches are independent samples of
//! the run and [`super::jackknife`] turns any statistic of the sums into a value with a
//! standard error. Wall hits go to their particle's batch.

use super::read::Run;
use roughwall::erosion::ErosionModel;

/// Batches of particles.
pub const BATCHES: usize = 20;
/// Impact-angle histogram: 1° bins over [0°, 90°].
pub const ALPHA_BINS: usize = 90;
/// Lay-angle histogram: 5° bins over [0°, 90°].
pub const LAY_BINS: usize = 18;
/// The erosion laws tallied side by side, in this order (`erosion_<law>_…` columns).
pub const LAWS: [&str; 3] = ["finnie", "oka", "dnv"];

/// Erosion around the circumference: 15° bins of the angle from the bottom, folded over the
/// vertical plane of symmetry, [0°, 180°] (0° the bottom, 180° the top).
pub const THETA_BINS: usize = 12;

/// Where each sum sits in a batch's vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// Bins across a diameter.
    pub nb: usize,
}

impl Layout {
    pub const SAMPLES: usize = 0;
    pub const DIST: usize = 1;
    pub const HITS: usize = 2;
    /// Σ y over the samples (m).
    pub const SUM_Y: usize = 3;
    pub fn cy(&self, b: usize) -> usize {
        4 + b
    }
    pub fn cz(&self, b: usize) -> usize {
        4 + self.nb + b
    }
    pub fn ux(&self, b: usize) -> usize {
        4 + 2 * self.nb + b
    }
    pub fn ux2(&self, b: usize) -> usize {
        4 + 3 * self.nb + b
    }
    pub fn ur(&self, b: usize) -> usize {
        4 + 4 * self.nb + b
    }
    pub fn ur2(&self, b: usize) -> usize {
        4 + 5 * self.nb + b
    }
    /// Samples along the vertical diameter, bin `b` of y.
    pub fn sy(&self, b: usize) -> usize {
        4 + 6 * self.nb + b
    }
    /// Samples along the horizontal diameter, bin `b` of z.
    pub fn sz(&self, b: usize) -> usize {
        4 + 7 * self.nb + b
    }
    fn h0(&self) -> usize {
        4 + 8 * self.nb
    }
    /// Hits logged (equal to the `HITS` column's sum when every hit was logged).
    pub fn logged_hits(&self) -> usize {
        self.h0()
    }
    pub fn sum_alpha_in(&self) -> usize {
        self.h0() + 1
    }
    /// Σ (α⁺ − α⁻) over hits.
    pub fn sum_alpha_change(&self) -> usize {
        self.h0() + 2
    }
    pub fn sum_deflection(&self) -> usize {
        self.h0() + 3
    }
    /// Σ of the impact angle on the element struck (degrees) over hits.
    pub fn sum_alpha_element(&self) -> usize {
        self.h0() + 4
    }
    /// Σ of law `law`'s volume per particle mass (m³/kg) over hits, at the impact angle on
    /// the element struck (`element`) or on the mean wall.
    pub fn sum_erosion(&self, law: usize, element: bool) -> usize {
        self.h0() + 5 + 2 * law + usize::from(!element)
    }
    fn h1(&self) -> usize {
        self.h0() + 5 + 2 * LAWS.len()
    }
    pub fn alpha_hist(&self, k: usize) -> usize {
        self.h1() + k
    }
    pub fn lay_hist(&self, k: usize) -> usize {
        self.h1() + ALPHA_BINS + k
    }
    /// Law `law`'s erosion (on the element struck) in circumferential bin `k`.
    pub fn erosion_theta(&self, law: usize, k: usize) -> usize {
        self.h1() + ALPHA_BINS + LAY_BINS + law * THETA_BINS + k
    }
    pub fn len(&self) -> usize {
        self.h1() + ALPHA_BINS + LAY_BINS + LAWS.len() * THETA_BINS
    }
}

/// A run's batch sums.
#[derive(Clone, Debug)]
pub struct RunSums {
    pub layout: Layout,
    /// `BATCHES` vectors of `layout.len()` sums.
    pub batches: Vec<Vec<f64>>,
}

fn bin(x: f64, lo: f64, hi: f64, n: usize) -> usize {
    let b = ((x - lo) / (hi - lo) * n as f64).floor();
    if b.is_nan() || b < 0.0 {
        0
    } else {
        (b as usize).min(n - 1)
    }
}

/// The angle of a hit point from the bottom of the pipe, folded to [0°, 180°] (y is up).
pub fn theta_from_bottom_deg(y: f64, z: f64) -> f64 {
    z.atan2(-y).abs().to_degrees()
}

/// The sums of `run`, with the erosion laws `laws` (in the order of [`LAWS`]).
pub fn sums(run: &Run, laws: &[ErosionModel; 3]) -> RunSums {
    let layout = Layout {
        nb: run.params.n_bins,
    };
    let mut batches = vec![vec![0.0; layout.len()]; BATCHES];
    for p in &run.particles {
        let s = &mut batches[p.id % BATCHES];
        s[Layout::SAMPLES] += p.samples;
        s[Layout::DIST] += p.dist;
        s[Layout::HITS] += p.hits;
        s[Layout::SUM_Y] += p.sum_y;
        for b in 0..layout.nb {
            s[layout.cy(b)] += p.cy[b];
            s[layout.cz(b)] += p.cz[b];
            s[layout.ux(b)] += p.ux[b];
            s[layout.ux2(b)] += p.ux2[b];
            s[layout.ur(b)] += p.ur[b];
            s[layout.ur2(b)] += p.ur2[b];
            s[layout.sy(b)] += p.sy[b];
            s[layout.sz(b)] += p.sz[b];
        }
    }
    let d = run.params.particle_diameter_m;
    for h in &run.hits {
        let s = &mut batches[h.particle_id % BATCHES];
        s[layout.logged_hits()] += 1.0;
        s[layout.sum_alpha_in()] += h.alpha_in_deg;
        s[layout.sum_alpha_change()] += h.alpha_out_deg - h.alpha_in_deg;
        s[layout.sum_deflection()] += h.deflection_deg;
        s[layout.sum_alpha_element()] += h.alpha_element_deg;
        s[layout.alpha_hist(bin(h.alpha_in_deg, 0.0, 90.0, ALPHA_BINS))] += 1.0;
        s[layout.lay_hist(bin(h.lay_angle_deg, 0.0, 90.0, LAY_BINS))] += 1.0;
        let theta = bin(theta_from_bottom_deg(h.y, h.z), 0.0, 180.0, THETA_BINS);
        for (k, law) in laws.iter().enumerate() {
            let on_element = law.volume_per_mass(h.speed_in, h.alpha_element_deg.to_radians(), d);
            s[layout.sum_erosion(k, true)] += on_element;
            s[layout.sum_erosion(k, false)] +=
                law.volume_per_mass(h.speed_in, h.alpha_in_deg.to_radians(), d);
            s[layout.erosion_theta(k, theta)] += on_element;
        }
    }
    RunSums { layout, batches }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn theta_is_zero_at_the_bottom_and_180_at_the_top() {
        assert_eq!(theta_from_bottom_deg(-1.0, 0.0), 0.0);
        assert!((theta_from_bottom_deg(1.0, 0.0) - 180.0).abs() < 1e-12);
        assert!((theta_from_bottom_deg(0.0, 1.0) - 90.0).abs() < 1e-12);
        assert!((theta_from_bottom_deg(0.0, -1.0) - 90.0).abs() < 1e-12);
    }

    #[test]
    fn bins_clamp_and_never_panic() {
        assert_eq!(bin(-1.0, 0.0, 90.0, 90), 0);
        assert_eq!(bin(90.0, 0.0, 90.0, 90), 89);
        assert_eq!(bin(f64::NAN, 0.0, 90.0, 90), 0);
        assert_eq!(bin(45.5, 0.0, 90.0, 90), 45);
    }
}
