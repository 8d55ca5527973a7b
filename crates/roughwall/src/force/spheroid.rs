//! Geometry of a prolate spheroid resting on a plane (docs/physics.md §7).
//!
//! Hu et al. 2021 define λ = b/a (b semi-major, a semi-minor axis, Sec. 1) and use the
//! *volume-equivalent* diameter D_p (Sec. 2, Table 1: "Volume equivalent diameter"). Hence
//! `a²b = (D/2)³`, i.e. `a = (D/2) λ^(−1/3)`, `b = λ a`: D is neither the minor axis nor the
//! major axis. β is the angle between the major axis and the wall (β = 0 lying flat, β = 90°
//! standing on its tip).
//!
//! Frame: the β plane contains the major axis and the wall normal; x along the wall in that
//! plane, y the wall normal. The body's lowest point is where its outward normal is −y.

/// A prolate spheroid with semi-axes a (twice, minor) and b = λ a (major).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spheroid {
    /// Semi-minor axis a (m).
    pub a: f64,
    /// Semi-major axis b = λ a (m).
    pub b: f64,
}

/// The spheroid's lowest point at inclination β.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowestPoint {
    /// Height of the centre above the lowest point, `h = √(b² sin²β + a² cos²β)`.
    pub height: f64,
    /// Lever arm: horizontal offset of the lowest point from the centre,
    /// `d = (b² − a²) sin β cos β / h` (= dh/dβ). Zero at β = 0 and 90°.
    pub lever_arm: f64,
    /// Principal radius of curvature in the β plane (along the meridian), `R' = a² b² / h³`.
    pub r_in_plane: f64,
    /// Principal radius of curvature normal to the β plane (along the parallel), `R'' = a² / h`.
    pub r_out_of_plane: f64,
}

impl Spheroid {
    /// Spheroid of volume-equivalent diameter `d` and aspect ratio `lambda` ≥ 1.
    pub fn from_volume_diameter(d: f64, lambda: f64) -> Self {
        let a = 0.5 * d / lambda.cbrt();
        Spheroid { a, b: lambda * a }
    }

    /// Volume `4π a² b / 3` (the unit test's check of the equal-volume semi-axes).
    #[cfg(test)]
    fn volume(&self) -> f64 {
        4.0 * std::f64::consts::PI * self.a * self.a * self.b / 3.0
    }

    /// Moment of inertia per unit mass about a centroidal axis normal to the major axis
    /// (the axis of rotation in the β plane): `I/m = (a² + b²)/5`.
    pub fn inertia_per_mass(&self) -> f64 {
        0.2 * (self.a * self.a + self.b * self.b)
    }

    /// The lowest point at inclination `beta` (rad, [0, π/2]). For the ellipsoid
    /// `xᵀ A x = 1`, the surface point of outward normal n is `A⁻¹n / √(nᵀA⁻¹n)`; the
    /// principal radii of a surface of revolution are the meridian's curvature radius and the
    /// distance to the axis along the normal (Johnson 1985, §4.1 for their use in contact).
    pub fn lowest_point(&self, beta: f64) -> LowestPoint {
        let (s, c) = beta.sin_cos();
        let (a2, b2) = (self.a * self.a, self.b * self.b);
        let h2 = b2 * s * s + a2 * c * c;
        let h = h2.sqrt();
        LowestPoint {
            height: h,
            lever_arm: (b2 - a2) * s * c / h,
            r_in_plane: a2 * b2 / (h2 * h),
            r_out_of_plane: a2 / h,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn volume_equivalent_diameter() {
        for lambda in [1.0, 1.5, 2.0, 3.0, 10.0] {
            let s = Spheroid::from_volume_diameter(2.0, lambda);
            assert!((s.volume() - 4.0 * std::f64::consts::PI / 3.0).abs() < 1e-12);
            assert!((s.b / s.a - lambda).abs() < 1e-12);
        }
    }

    #[test]
    fn limits_of_the_lowest_point() {
        let s = Spheroid::from_volume_diameter(2.0, 2.0);
        let (a, b) = (s.a, s.b);
        let flat = s.lowest_point(0.0);
        assert!((flat.height - a).abs() < 1e-15 && flat.lever_arm == 0.0);
        assert!(
            (flat.r_in_plane - b * b / a).abs() < 1e-12 && (flat.r_out_of_plane - a).abs() < 1e-15
        );
        let tip = s.lowest_point(FRAC_PI_2);
        assert!((tip.height - b).abs() < 1e-15 && tip.lever_arm.abs() < 1e-15);
        assert!(
            (tip.r_in_plane - a * a / b).abs() < 1e-12
                && (tip.r_out_of_plane - a * a / b).abs() < 1e-12
        );
        // Sphere: radius everywhere, no lever arm.
        let sph = Spheroid::from_volume_diameter(2.0, 1.0);
        for beta in [0.0, 0.3, 1.2] {
            let p = sph.lowest_point(beta);
            assert!((p.height - 1.0).abs() < 1e-15 && p.lever_arm.abs() < 1e-15);
            assert!((p.r_in_plane - 1.0).abs() < 1e-15 && (p.r_out_of_plane - 1.0).abs() < 1e-15);
        }
    }

    /// Both principal radii against the normal curvature of the implicit surface
    /// `xᵀAx = 1`: `κ(t) = tᵀAt / |Ap|` for a unit tangent t at the point p.
    #[test]
    fn radii_from_implicit_surface_curvature() {
        for lambda in [1.5, 2.0, 3.0] {
            let s = Spheroid::from_volume_diameter(2.0, lambda);
            for beta in [0.0_f64, 0.3, 0.8, 1.2, FRAC_PI_2] {
                let (sb, cb) = beta.sin_cos();
                // Body axes: e1 (major) = (cos β, sin β), e2 = (−sin β, cos β), e3 = z.
                let inv = [1.0 / (s.b * s.b), 1.0 / (s.a * s.a), 1.0 / (s.a * s.a)];
                // Lowest point: outward normal −y, in body components (−sin β, −cos β, 0).
                let n = [-sb, -cb, 0.0];
                let norm = (n[0] * n[0] / inv[0] + n[1] * n[1] / inv[1]).sqrt();
                let p = [n[0] / inv[0] / norm, n[1] / inv[1] / norm, 0.0];
                let ap = ((inv[0] * p[0]).powi(2) + (inv[1] * p[1]).powi(2)).sqrt();
                // In-plane tangent: world x = (cos β, −sin β, 0) in body components; out of plane: z.
                let k_in = (inv[0] * cb * cb + inv[1] * sb * sb) / ap;
                let k_out = inv[2] / ap;
                let lp = s.lowest_point(beta);
                assert!(
                    (lp.r_in_plane * k_in - 1.0).abs() < 1e-12,
                    "λ={lambda} β={beta}"
                );
                assert!(
                    (lp.r_out_of_plane * k_out - 1.0).abs() < 1e-12,
                    "λ={lambda} β={beta}"
                );
                assert!((-(p[0] * sb + p[1] * cb) - lp.height).abs() < 1e-12);
            }
        }
    }

    /// The closed forms against a brute-force search over the ellipse in the β plane.
    #[test]
    fn lowest_point_matches_brute_force() {
        let s = Spheroid::from_volume_diameter(2.0, 3.0);
        let beta: f64 = 0.6;
        let (sb, cb) = beta.sin_cos();
        // Body point (b cos t, a sin t) → world (x, y) rotated by β.
        let world = |t: f64| {
            let (u, r) = (s.b * t.cos(), s.a * t.sin());
            (u * cb - r * sb, u * sb + r * cb)
        };
        // Golden-section minimisation of y(t).
        let (mut lo, mut hi) = (std::f64::consts::PI, 2.0 * std::f64::consts::PI);
        for _ in 0..200 {
            let m1 = lo + (hi - lo) * 0.381_966;
            let m2 = lo + (hi - lo) * 0.618_034;
            if world(m1).1 < world(m2).1 {
                hi = m2
            } else {
                lo = m1
            }
        }
        let t = 0.5 * (lo + hi);
        let (x, y) = world(t);
        let lp = s.lowest_point(beta);
        assert!((-y - lp.height).abs() < 1e-12);
        assert!((-x - lp.lever_arm).abs() < 1e-6, "{x} {}", lp.lever_arm);
        // dh/dβ = d.
        let e = 1e-6;
        let dh = (s.lowest_point(beta + e).height - s.lowest_point(beta - e).height) / (2.0 * e);
        assert!((dh - lp.lever_arm).abs() < 1e-8);
        // In-plane curvature radius from three nearby points of the curve y(x): R = 1/y''.
        let hstep = 1e-4;
        let pts: Vec<(f64, f64)> = [-hstep, 0.0, hstep]
            .iter()
            .map(|dt| world(t + dt))
            .collect();
        let (x0, y0) = pts[0];
        let (x1, y1) = pts[1];
        let (x2, y2) = pts[2];
        let d1 = (y1 - y0) / (x1 - x0);
        let d2 = (y2 - y1) / (x2 - x1);
        let curv = (d2 - d1) / (0.5 * (x2 - x0));
        assert!(
            (1.0 / curv - lp.r_in_plane).abs() / lp.r_in_plane < 1e-4,
            "{}",
            1.0 / curv
        );
    }
}
