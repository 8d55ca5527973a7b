//! How well a scan fixes its lay (issue 39, part 2): a scan is one realisation, and a
//! near-isotropic wall gives a definite lay angle from noise alone (opd-1: −21.6°, where
//! another estimator gave −38.5°).
//!
//! The scan is cut into `K = 4 × 4` sub-patches. In each, the lay angle is found again, and
//! the deviations are measured along and across the *whole scan's* lay. The lay's standard
//! error is the axial spread of the sub-patch angles (doubled-angle circular standard
//! deviation, Mardia & Jupp, *Directional Statistics*, 2000, Sec. 2.3.4 and 9.1: an axis is
//! an angle modulo 180°) over `√K`. The anisotropy is `Δζ − Δξ` in each sub-patch along the
//! fixed lay; it is significant when its mean exceeds [`ANISOTROPY_T`] standard errors of the
//! mean over the sub-patches (the sub-patches as clusters, as the ensemble standard errors
//! of `surfaces = N` take the realisations). A wall whose anisotropy is not significant is
//! isotropic within what the scan shows, and gets no lay.

use super::lay::{angle_and_mean, deviations_at};
use super::ScanField;

/// Sub-patches along each side of the scan.
pub const PATCHES_PER_SIDE: usize = 4;

/// Fewest points a sub-patch needs along each side.
const MIN_PATCH_POINTS: usize = 8;

/// Standard errors the mean anisotropy `Δζ − Δξ` must exceed to count: 3 (a false
/// "anisotropic" on an isotropic wall about once in 300 scans for Gaussian cluster means).
pub const ANISOTROPY_T: f64 = 3.0;

/// The lay's uncertainty and the anisotropy's significance, from sub-patches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LayUncertainty {
    /// Sub-patches with a lay (at most 16).
    pub patches: usize,
    /// Standard error of the lay angle (rad): the axial spread of the sub-patches' angles
    /// over `√patches`.
    pub angle_se: f64,
    /// Mean over the sub-patches of `Δζ − Δξ` along and across the scan's lay (rad).
    pub anisotropy: f64,
    /// Its standard error over the sub-patches (rad).
    pub anisotropy_se: f64,
}

impl LayUncertainty {
    /// Whether the anisotropy exceeds [`ANISOTROPY_T`] standard errors.
    pub fn significant(&self) -> bool {
        self.anisotropy > ANISOTROPY_T * self.anisotropy_se
    }

    /// The anisotropy in standard errors (infinite with no spread between sub-patches).
    pub fn t(&self) -> f64 {
        if self.anisotropy_se > 0.0 {
            self.anisotropy / self.anisotropy_se
        } else if self.anisotropy > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    }
}

/// The lay uncertainty of the levelled scan `f` whose lay is at `lay_angle` (rad); `None`
/// when fewer than 4 sub-patches of at least 8 × 8 points have a lay.
pub fn lay_uncertainty(f: &ScanField, lay_angle_rad: f64) -> Option<LayUncertainty> {
    let (px, py) = (f.nx / PATCHES_PER_SIDE, f.ny / PATCHES_PER_SIDE);
    if px < MIN_PATCH_POINTS || py < MIN_PATCH_POINTS {
        return None;
    }
    let mut angles = Vec::new();
    let mut differences = Vec::new();
    for jy in 0..PATCHES_PER_SIDE {
        for jx in 0..PATCHES_PER_SIDE {
            let heights = (jy * py..(jy + 1) * py)
                .flat_map(|iy| {
                    let row = iy * f.nx + jx * px;
                    f.heights[row..row + px].iter().copied()
                })
                .collect();
            let sub = ScanField {
                nx: px,
                ny: py,
                dx: f.dx,
                dy: f.dy,
                heights,
            };
            // One pass gives the sub-patch's own lay and the mean normal its deviations
            // along the scan's lay are taken about.
            if let Some((a, mean)) = angle_and_mean(&sub) {
                angles.push(a);
                let (delta_xi, delta_zeta) = deviations_at(&sub, lay_angle_rad, mean);
                differences.push(delta_zeta - delta_xi);
            }
        }
    }
    if angles.len() < 4 || differences.len() < 4 {
        return None;
    }
    // Axial statistics: the doubled angles' mean resultant length R gives the circular
    // standard deviation √(−2 ln R) of the doubled angle, half of it for the axis.
    let n = angles.len() as f64;
    let (c, s) = angles.iter().fold((0.0, 0.0), |(c, s), a| {
        (c + (2.0 * a).cos(), s + (2.0 * a).sin())
    });
    let r = ((c / n).powi(2) + (s / n).powi(2))
        .sqrt()
        .clamp(1e-300, 1.0);
    let axial_sd = 0.5 * (-2.0 * r.ln()).sqrt();
    let m = differences.len() as f64;
    let mean = differences.iter().sum::<f64>() / m;
    let var = differences.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (m - 1.0);
    Some(LayUncertainty {
        patches: angles.len(),
        angle_se: axial_sd / n.sqrt(),
        anisotropy: mean,
        anisotropy_se: (var / m).sqrt(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scan::tests::sec3_wall;
    use crate::scan::{characterise, ScanField};

    fn scan_of(g: &crate::surface::HeightField) -> ScanField {
        ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights.clone()).unwrap()
    }

    /// The Sec. 3 wall (2.5°, 7.5°) is clearly anisotropic and fixes its lay to a fraction of
    /// a degree; an isotropic Gaussian wall is not significantly anisotropic.
    #[test]
    fn an_anisotropic_wall_has_a_lay_an_isotropic_one_does_not() {
        let c = characterise(scan_of(&sec3_wall(512, 3)), 1).unwrap();
        let lay = c.lay.unwrap();
        let u = lay_uncertainty(&c.levelled, lay.angle).unwrap();
        assert_eq!(u.patches, 16);
        assert!(u.significant() && u.t() > 10.0, "{u:?}");
        assert!(u.angle_se.to_degrees() < 1.0, "{u:?}");
        let spec = crate::SurfaceSpec {
            length_m: 512.0 * 2e-6,
            nodes: 512,
            rms_height_m: 1e-6,
            corr_length_x_m: Some(16e-6),
            corr_length_z_m: Some(16e-6),
        };
        let mut isotropic = 0;
        for seed in 0..4 {
            let g = crate::surface::generate(&spec, seed);
            let c = characterise(scan_of(&g), 1).unwrap();
            let u = lay_uncertainty(&c.levelled, c.lay.unwrap().angle).unwrap();
            // The sub-patches disagree on the lay of an isotropic wall.
            assert!(u.angle_se.to_degrees() > 3.0, "{u:?}");
            isotropic += usize::from(!u.significant());
        }
        assert!(
            isotropic >= 3,
            "{isotropic} of 4 isotropic walls called isotropic"
        );
    }
}
