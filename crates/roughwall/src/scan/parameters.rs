//! Areal height and gradient parameters of ISO 25178-2:2012 over the valid points.

use super::ScanField;
use rayon::prelude::*;

/// Height and gradient parameters of a (levelled) scan.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaParameters {
    /// Points with a height.
    pub valid_points: usize,
    /// Mean height (m): 0 after levelling, up to rounding.
    pub mean_m: f64,
    /// `Sq`, the root-mean-square height about the mean (m; ISO 25178-2 §4.1.1).
    pub sq_m: f64,
    /// `Ssk`, skewness `mean((h − h̄)³)/Sq³` (§4.1.2): 0 for Gaussian heights.
    pub ssk: f64,
    /// `Sku`, kurtosis `mean((h − h̄)⁴)/Sq⁴` (§4.1.3): 3 for Gaussian heights.
    pub sku: f64,
    /// `Sdq`, the root-mean-square gradient `√mean(s_x² + s_y²)` (§4.3.2), with first-order
    /// forward differences `s_x = (h[ix+1, iy] − h[ix, iy])/dx`, `s_y = (h[ix, iy+1] −
    /// h[ix, iy])/dy` over the nodes with both neighbours valid (the discretisation
    /// SurfaceTopography's `rms_gradient` uses on a non-periodic scan:
    /// `Uniform/Derivative.py`, `first_2d_x`, `first_2d_y`, trimmed at the far edges);
    /// `None` when no node has both neighbours.
    pub sdq: Option<f64>,
    /// Root-mean-square of `s_x` over the same nodes.
    pub sdq_x: Option<f64>,
    /// Root-mean-square of `s_y` over the same nodes.
    pub sdq_y: Option<f64>,
    /// Nodes with a gradient.
    pub gradient_points: usize,
}

/// [`AreaParameters`] of a scan (level it first: [`super::levelling::level`]).
pub fn area_parameters(f: &ScanField) -> AreaParameters {
    // Row partial sums, each in node order, added in row order: the same bits for any thread
    // count. Two passes: the count and mean, then the three central moments together with
    // the gradients (of the row and the next one).
    let (mut n, mut sum) = (0usize, 0.0);
    super::in_row_chunks(
        f.ny,
        |rows| {
            rows.into_par_iter()
                .map(|iy| {
                    f.heights[iy * f.nx..(iy + 1) * f.nx]
                        .iter()
                        .filter(|h| !h.is_nan())
                        .fold((0, 0.0), |(n, s), &h| (n + 1, s + h))
                })
                .collect()
        },
        |(rn, rs): (usize, f64)| {
            n += rn;
            sum += rs;
        },
    );
    let mean = sum / n as f64;
    let mut moments = [0.0; 3];
    let (mut sx, mut sz, mut k) = (0.0, 0.0, 0usize);
    super::in_row_chunks(
        f.ny,
        |rows| {
            rows.into_par_iter()
                .map(|iy| {
                    let row = &f.heights[iy * f.nx..(iy + 1) * f.nx];
                    let mut m = [0.0; 3];
                    for &h in row.iter().filter(|h| !h.is_nan()) {
                        let d = h - mean;
                        m[0] += d * d;
                        m[1] += d.powi(3);
                        m[2] += d.powi(4);
                    }
                    // Forward differences to the next node along x and along y, both valid.
                    let (mut sx, mut sz, mut k) = (0.0, 0.0, 0usize);
                    if iy + 1 < f.ny {
                        let next = &f.heights[(iy + 1) * f.nx..(iy + 2) * f.nx];
                        for ix in 0..f.nx - 1 {
                            let (h, hx, hz) = (row[ix], row[ix + 1], next[ix]);
                            if h.is_nan() || hx.is_nan() || hz.is_nan() {
                                continue;
                            }
                            let gx = (hx - h) / f.dx;
                            let gz = (hz - h) / f.dy;
                            sx += gx * gx;
                            sz += gz * gz;
                            k += 1;
                        }
                    }
                    (m, (sx, sz, k))
                })
                .collect()
        },
        |(m, r): ([f64; 3], (f64, f64, usize))| {
            for j in 0..3 {
                moments[j] += m[j];
            }
            (sx, sz, k) = (sx + r.0, sz + r.1, k + r.2);
        },
    );
    let [m2, m3, m4] = moments.map(|s| s / n as f64);
    let sq = m2.sqrt();
    let (ssk, sku) = if m2 > 0.0 {
        (m3 / m2.powf(1.5), m4 / (m2 * m2))
    } else {
        (0.0, 0.0)
    };
    let per = |s: f64| (k > 0).then(|| (s / k as f64).sqrt());
    AreaParameters {
        valid_points: n,
        mean_m: mean,
        sq_m: sq,
        ssk,
        sku,
        sdq: per(sx + sz),
        sdq_x: per(sx),
        sdq_y: per(sz),
        gradient_points: k,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sinusoid_has_its_analytic_parameters() {
        // h = A sin(2π x/λ) over whole periods: Sq = A/√2, Ssk = 0, Sku = 3/2, and the
        // forward-difference gradient of a sampled sine, (2A/δ) sin(πδ/λ)/√2.
        let (n, per, a, dx) = (400usize, 40usize, 1e-6, 1e-6);
        let lambda = per as f64 * dx;
        let h: Vec<f64> = (0..n * 3)
            .map(|i| a * (std::f64::consts::TAU * (i % n) as f64 * dx / lambda).sin())
            .collect();
        let f = ScanField::new(n, 3, dx, 2e-6, h).unwrap();
        let p = area_parameters(&f);
        assert!((p.sq_m / (a / 2f64.sqrt()) - 1.0).abs() < 1e-12, "{p:?}");
        assert!(p.ssk.abs() < 1e-9 && (p.sku - 1.5).abs() < 1e-9, "{p:?}");
        assert_eq!(p.sdq_y, Some(0.0));
        assert_eq!(p.gradient_points, (n - 1) * 2);
        let expect = 2.0 * a / dx * (std::f64::consts::PI * dx / lambda).sin() / 2f64.sqrt();
        let sdq = p.sdq.unwrap();
        assert!((sdq / expect - 1.0).abs() < 5e-3, "{sdq} vs {expect}");
    }

    #[test]
    fn missing_points_drop_out_of_heights_and_gradients() {
        let mut h = vec![0.0, 1.0, 0.0, 1.0, 0.0, 1.0];
        let full = area_parameters(&ScanField::new(3, 2, 1.0, 1.0, h.clone()).unwrap());
        assert_eq!((full.valid_points, full.gradient_points), (6, 2));
        h[1] = f64::NAN;
        let p = area_parameters(&ScanField::new(3, 2, 1.0, 1.0, h).unwrap());
        assert_eq!((p.valid_points, p.gradient_points), (5, 0));
        assert_eq!(p.sdq, None);
        assert!((p.mean_m - 0.4).abs() < 1e-15);
    }
}
