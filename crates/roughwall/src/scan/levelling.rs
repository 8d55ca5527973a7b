//! Form removal: the least-squares polynomial of total degree 1 (a plane) to 3 over the
//! valid points, subtracted (ISO 25178-2:2012 §3.1.4, the F-operator; for degree 1 the
//! tilt plane SurfaceTopography removes with `detrend_mode = "height"`,
//! `Uniform/Detrending.py`, `polyfit1_topography`).
//!
//! The polynomial is spanned by products of Legendre polynomials `P_a(u) P_b(v)`, `a + b ≤
//! degree`, in coordinates `u, v ∈ [−1, 1]` across the scan: nearly orthogonal on a
//! uniform grid, so the normal equations stay well conditioned. The fitted surface is the
//! same least-squares polynomial as in any other basis.

use super::ScanField;
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;

/// Highest degree of form removal.
pub const MAX_DEGREE: u32 = 3;

/// `P_0 … P_3` at `t`.
fn legendre(t: f64) -> [f64; 4] {
    [
        1.0,
        t,
        0.5 * (3.0 * t * t - 1.0),
        0.5 * t * (5.0 * t * t - 3.0),
    ]
}

/// The exponents `(a, b)` of the basis up to degree 3, in the order of [`basis`]: the first
/// 3, 6 or 10 are the basis of degree 1, 2 or 3.
const TERMS: [(usize, usize); 10] = [
    (0, 0),
    (1, 0),
    (0, 1),
    (2, 0),
    (1, 1),
    (0, 2),
    (3, 0),
    (2, 1),
    (1, 2),
    (0, 3),
];

/// The exponents `(a, b)` of the basis `P_a(u) P_b(v)` with `a + b ≤ degree`.
fn basis(degree: u32) -> Vec<(usize, usize)> {
    let d = degree as usize;
    (0..=d)
        .flat_map(|total| (0..=total).map(move |b| (total - b, b)))
        .collect()
}

/// Coordinate of node `i` of `n` in `[−1, 1]`.
#[inline]
fn coordinate(i: usize, n: usize) -> f64 {
    2.0 * i as f64 / (n - 1) as f64 - 1.0
}

/// The scan with its least-squares polynomial of total degree `degree` (1 … 3) removed,
/// and the polynomial's coefficients in the Legendre basis (metres). Missing points stay
/// missing. Refused when the valid points cannot fix the polynomial (fewer than its terms,
/// or all on one line).
pub fn level(f: &ScanField, degree: u32) -> Result<(ScanField, Vec<f64>)> {
    let mut levelled = f.clone();
    let coef = level_in_place(&mut levelled, degree)?;
    Ok((levelled, coef))
}

/// [`level`] without a copy: the polynomial is removed from `f` itself, whose heights are
/// left as they were when it is refused.
pub fn level_in_place(f: &mut ScanField, degree: u32) -> Result<Vec<f64>> {
    if !(1..=MAX_DEGREE).contains(&degree) {
        return Err(Error::invalid(
            "levelling degree",
            degree,
            "1 (plane), 2 or 3",
        ));
    }
    let terms = basis(degree);
    let k = terms.len();
    debug_assert_eq!(terms, TERMS[..k]);
    let pu: Vec<[f64; 4]> = (0..f.nx).map(|i| legendre(coordinate(i, f.nx))).collect();
    // Normal equations per row, added in row order (the sums do not depend on threads).
    let mut ata = DMatrix::<f64>::zeros(k, k);
    let mut atb = DVector::<f64>::zeros(k);
    match degree {
        1 => add_normal_equations::<3>(f, &pu, &mut ata, &mut atb),
        2 => add_normal_equations::<6>(f, &pu, &mut ata, &mut atb),
        _ => add_normal_equations::<10>(f, &pu, &mut ata, &mut atb),
    }
    for r in 0..k {
        for c in 0..r {
            ata[(r, c)] = ata[(c, r)];
        }
    }
    let refuse = || {
        Error::Input(format!(
            "scan: its {} valid points cannot fix a polynomial of degree {degree} ({k} terms): level with a lower degree",
            f.valid_count()
        ))
    };
    if f.valid_count() < k {
        return Err(refuse());
    }
    let diagonal: Vec<f64> = (0..k).map(|i| ata[(i, i)]).collect();
    let chol = ata.cholesky().ok_or_else(refuse)?;
    // A pivot lost to cancellation: the points do not fix that term (e.g. all on a line).
    let l = chol.l();
    if (0..k).any(|i| l[(i, i)] * l[(i, i)] <= 1e-10 * diagonal[i]) {
        return Err(refuse());
    }
    let coef = chol.solve(&atb);
    if coef.iter().any(|c| !c.is_finite()) {
        return Err(refuse());
    }
    let ny = f.ny;
    let coef: Vec<f64> = coef.iter().copied().collect();
    f.heights
        .par_chunks_mut(f.nx)
        .enumerate()
        .for_each(|(iy, row)| {
            let pv = legendre(coordinate(iy, ny));
            match degree {
                1 => subtract::<3>(row, &pu, pv, &coef),
                2 => subtract::<6>(row, &pu, pv, &coef),
                _ => subtract::<10>(row, &pu, pv, &coef),
            }
        });
    Ok(coef)
}

/// The basis functions `P_a(u) P_b(v)` of the first `K` terms at one node.
#[inline(always)]
fn phi<const K: usize>(pu: &[f64; 4], pv: &[f64; 4]) -> [f64; K] {
    std::array::from_fn(|t| pu[TERMS[t].0] * pv[TERMS[t].1])
}

/// Adds the normal equations of every row of `f` to `ata` (upper triangle) and `atb`, row by
/// row in row order, a chunk of rows at a time ([`super::in_row_chunks`]).
fn add_normal_equations<const K: usize>(
    f: &ScanField,
    pu: &[[f64; 4]],
    ata: &mut DMatrix<f64>,
    atb: &mut DVector<f64>,
) {
    super::in_row_chunks(
        f.ny,
        |rows| {
            rows.into_par_iter()
                .map(|iy| {
                    let row = &f.heights[iy * f.nx..(iy + 1) * f.nx];
                    normal_equations::<K>(row, pu, legendre(coordinate(iy, f.ny)))
                })
                .collect()
        },
        |(m, v)| {
            for r in 0..K {
                atb[r] += v[r];
                for c in r..K {
                    ata[(r, c)] += m[r][c];
                }
            }
        },
    );
}

/// The normal equations' `AᵀA` (upper triangle) and `Aᵀh` of one row of heights, summed in
/// node order.
fn normal_equations<const K: usize>(
    row: &[f64],
    pu: &[[f64; 4]],
    pv: [f64; 4],
) -> ([[f64; K]; K], [f64; K]) {
    let mut ata = [[0.0; K]; K];
    let mut atb = [0.0; K];
    for (&h, pu) in row.iter().zip(pu) {
        if h.is_nan() {
            continue;
        }
        let p: [f64; K] = phi(pu, &pv);
        for r in 0..K {
            atb[r] += p[r] * h;
            for c in r..K {
                ata[r][c] += p[r] * p[c];
            }
        }
    }
    (ata, atb)
}

/// Subtracts the polynomial of coefficients `coef` from one row of heights.
fn subtract<const K: usize>(row: &mut [f64], pu: &[[f64; 4]], pv: [f64; 4], coef: &[f64]) {
    let coef = &coef[..K];
    for (h, pu) in row.iter_mut().zip(pu) {
        if !h.is_nan() {
            // Σ c·P_a(u)·P_b(v), term by term in basis order.
            let mut form = coef[0] * pu[TERMS[0].0] * pv[TERMS[0].1];
            for t in 1..K {
                form += coef[t] * pu[TERMS[t].0] * pv[TERMS[t].1];
            }
            *h -= form;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::tilted;
    use super::*;

    #[test]
    fn a_plane_is_removed_exactly_and_leaves_the_texture() {
        let f = tilted(64, 40);
        let (l, _) = level(&f, 1).unwrap();
        assert!(l.heights[65].is_nan());
        let valid: Vec<f64> = l.heights.iter().copied().filter(|h| !h.is_nan()).collect();
        let mean = valid.iter().sum::<f64>() / valid.len() as f64;
        assert!(mean.abs() < 1e-18, "{mean}");
        // What remains is the sinusoid (amplitude 1e-7) less its own best plane: no tilt.
        let max = valid.iter().fold(0f64, |m, h| m.max(h.abs()));
        assert!(max < 1.3e-7, "{max}");
        // Removing the plane again changes nothing.
        let (again, c) = level(&l, 1).unwrap();
        assert!(c.iter().all(|c| c.abs() < 1e-18), "{c:?}");
        for (a, b) in again.heights.iter().zip(&l.heights) {
            assert!(a.is_nan() && b.is_nan() || (a - b).abs() < 1e-20);
        }
    }

    #[test]
    fn a_cubic_form_is_removed_by_degree_3_only() {
        let (nx, ny) = (30, 20);
        let h: Vec<f64> = (0..nx * ny)
            .map(|i| {
                let (x, z) = ((i % nx) as f64, (i / nx) as f64);
                1e-9 * (x * x * x - 2.0 * x * z * z + 5.0 * z)
            })
            .collect();
        let f = ScanField::new(nx, ny, 1e-6, 1e-6, h).unwrap();
        let rms = |f: &ScanField| {
            (f.heights.iter().map(|h| h * h).sum::<f64>() / f.heights.len() as f64).sqrt()
        };
        let (l3, c) = level(&f, 3).unwrap();
        assert_eq!(c.len(), 10);
        assert!(rms(&l3) < 1e-20 * rms(&f).max(1.0), "{}", rms(&l3));
        let (l1, _) = level(&f, 1).unwrap();
        assert!(rms(&l1) > 1e-3 * rms(&f));
        assert!(level(&f, 0)
            .unwrap_err()
            .to_string()
            .contains("levelling degree"));
        assert!(level(&f, 4).is_err());
    }

    #[test]
    fn too_few_points_for_the_degree_are_refused() {
        let mut h = vec![f64::NAN; 16];
        h[0] = 1.0;
        h[5] = 2.0;
        h[10] = 3.0;
        let f = ScanField::new(4, 4, 1.0, 1.0, h).unwrap();
        // Three points on one line: no plane.
        let e = level(&f, 1).unwrap_err().to_string();
        assert!(e.contains("cannot fix a polynomial of degree 1"), "{e}");
    }
}
