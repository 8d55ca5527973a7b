//! The pipe's cross-section as the mesh has it: the study's gmsh O-grid makes the wall a
//! regular polygon with a vertex at 45° in the (y, z) plane (`pipe.geo`: 4 × NC sides), not
//! a circle. The areas of the slabs and strips that normalise the concentration profiles
//! are taken on that polygon (a circle when the number of sides is not known), so that a
//! uniform suspension reads 1 in every bin, the bins at the wall included.

use std::f64::consts::PI;

/// Midpoint subintervals per bin: the chord is piecewise linear (or smooth), so the error is
/// below 1e-6 of a bin's area.
const SUBINTERVALS: usize = 2000;

/// A unit-radius cross-section: a circle, or a regular polygon inscribed in it.
#[derive(Clone, Debug, PartialEq)]
pub struct CrossSection {
    /// Vertices `(y, z)` over R, in order; empty for a circle.
    vertices: Vec<(f64, f64)>,
}

impl CrossSection {
    /// The wall of a mesh of `sides` sides (at least 8), vertices at 45° + k·360°/sides;
    /// `None` or fewer sides: a circle.
    pub fn new(sides: Option<usize>) -> CrossSection {
        let vertices = match sides {
            Some(n) if n >= 8 => (0..n)
                .map(|k| {
                    let phi = PI / 4.0 + 2.0 * PI * k as f64 / n as f64;
                    (phi.cos(), phi.sin())
                })
                .collect(),
            _ => Vec::new(),
        };
        CrossSection { vertices }
    }

    /// Its area over R².
    pub fn area(&self) -> f64 {
        match self.vertices.len() {
            0 => PI,
            n => 0.5 * n as f64 * (2.0 * PI / n as f64).sin(),
        }
    }

    /// The extent `(lo, hi)` of the section along the other coordinate on the line where y
    /// (`along_y`) or z equals `t`; `None` outside.
    fn chord(&self, along_y: bool, t: f64) -> Option<(f64, f64)> {
        if self.vertices.is_empty() {
            let h = 1.0 - t * t;
            return (h > 0.0).then(|| (-h.sqrt(), h.sqrt()));
        }
        let coord = |p: (f64, f64)| if along_y { (p.0, p.1) } else { (p.1, p.0) };
        let n = self.vertices.len();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..n {
            let (c0, o0) = coord(self.vertices[i]);
            let (c1, o1) = coord(self.vertices[(i + 1) % n]);
            if (c0 - t) * (c1 - t) <= 0.0 && c0 != c1 {
                let o = o0 + (t - c0) / (c1 - c0) * (o1 - o0);
                lo = lo.min(o);
                hi = hi.max(o);
            }
        }
        (lo <= hi).then_some((lo, hi))
    }

    /// The share of the section's area with y (`along_y`) or z in `[lo, hi]` and, with
    /// `half_width`, the other coordinate within ±`half_width` (a strip along a diameter).
    pub fn share(&self, along_y: bool, lo: f64, hi: f64, half_width: Option<f64>) -> f64 {
        if self.vertices.is_empty() {
            return circle_area(lo, hi, half_width) / PI;
        }
        let h = (hi - lo) / SUBINTERVALS as f64;
        let area: f64 = (0..SUBINTERVALS)
            .map(|i| {
                let t = lo + (i as f64 + 0.5) * h;
                match self.chord(along_y, t) {
                    Some((a, b)) => {
                        let (a, b) = match half_width {
                            Some(w) => (a.max(-w), b.min(w)),
                            None => (a, b),
                        };
                        (b - a).max(0.0) * h
                    }
                    None => 0.0,
                }
            })
            .sum();
        area / self.area()
    }
}

/// The area of the unit circle with y in `[lo, hi]` and, with `half_width` w, |z| < w: in
/// closed form (the chord's square root at the wall would slow a quadrature), from
/// `∫ 2√(1 − y²) dy = y√(1 − y²) + asin y` where the chord is narrower than the strip and
/// `2w` per unit of y where it is wider.
fn circle_area(lo: f64, hi: f64, half_width: Option<f64>) -> f64 {
    let band = |a: f64, b: f64| {
        let g = |y: f64| {
            let y = y.clamp(-1.0, 1.0);
            y * (1.0 - y * y).max(0.0).sqrt() + y.asin()
        };
        if b > a {
            g(b) - g(a)
        } else {
            0.0
        }
    };
    let (lo, hi) = (lo.max(-1.0), hi.min(1.0));
    match half_width {
        None => band(lo, hi),
        Some(w) => {
            // |y| ≤ yw: the chord is wider than the strip
            let yw = (1.0 - w * w).max(0.0).sqrt();
            let inner = (hi.min(yw) - lo.max(-yw)).max(0.0) * 2.0 * w;
            inner + band(lo, hi.min(-yw)) + band(lo.max(yw), hi)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_cover_the_section_and_match_closed_forms() {
        for sides in [None, Some(32), Some(48)] {
            let s = CrossSection::new(sides);
            let total: f64 = (0..20)
                .map(|b| s.share(true, -1.0 + 0.1 * b as f64, -0.9 + 0.1 * b as f64, None))
                .sum();
            assert!((total - 1.0).abs() < 1e-6, "{sides:?}: {total}");
            // the polygon is symmetric under y <-> z
            let (a, b) = (
                s.share(true, -1.0, -0.9, None),
                s.share(false, -1.0, -0.9, None),
            );
            assert!((a - b).abs() < 1e-9, "{sides:?}: {a} {b}");
        }
        // the circle's band [0, 1/2]: ∫₀^½ 2√(1 − y²) dy = ½·√¾ + asin ½, over π
        let exact = (0.5 * 0.75f64.sqrt() + PI / 6.0) / PI;
        let c = CrossSection::new(None);
        assert!((c.share(true, 0.0, 0.5, None) - exact).abs() < 1e-7);
        // a strip |z| < 0.2 in the band [0, 0.5] of the circle is a 0.4 × 0.5 rectangle
        assert!((c.share(true, 0.0, 0.5, Some(0.2)) - 0.2 / PI).abs() < 1e-12);
        // the whole strip |z| < w of the circle, against the quadrature of the 4096-gon
        let fine = CrossSection::new(Some(4096));
        for (lo, hi) in [(-1.0, -0.9), (-0.98, 0.3), (0.95, 1.0)] {
            let (a, b) = (
                c.share(true, lo, hi, Some(0.2)),
                fine.share(true, lo, hi, Some(0.2)),
            );
            assert!((a - b).abs() < 1e-5, "[{lo}, {hi}]: {a} {b}");
        }
        // the 32-gon's band at the wall is smaller than the circle's (its vertex sits there)
        let p = CrossSection::new(Some(32));
        let (sp, sc) = (
            p.share(true, -1.0, -0.9, None),
            c.share(true, -1.0, -0.9, None),
        );
        assert!(sp < sc && sp > 0.9 * sc, "{sp} {sc}");
        // its area
        assert!((p.area() - 16.0 * (PI / 16.0).sin()).abs() < 1e-15);
    }
}
