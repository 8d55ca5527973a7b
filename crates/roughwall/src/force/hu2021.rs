//! Hu et al. 2021's hybrid model: Eq. (7) with the FE-calibrated ξ(λ, β) of Eq. (8).
use super::{hertz_sphere, ForceResult, Impact, Particle};
use crate::error::{Error, Result};

/// Aspect ratios calibrated by Hu et al. 2021 (Eq. 8), in the column order of Eq. (8).
pub const LAMBDAS: [f64; 3] = [1.5, 2.0, 3.0];

/// Hu et al. 2021, Eq. (8): polynomial coefficients of ξ(λ, β) in powers β⁰…β⁶, β in degrees,
/// one row per λ of [`LAMBDAS`] (the columns of the printed matrix).
pub const COEFFS: [[f64; 7]; 3] = [
    [
        0.7864,
        8.2293e-5,
        -5.2329e-4,
        1.6670e-5,
        -1.9929e-7,
        9.5851e-10,
        -1.1658e-12,
    ],
    [
        0.82837,
        -0.00652,
        -9.7135e-4,
        4.6124e-5,
        -8.1944e-7,
        6.6760e-9,
        -2.0774e-11,
    ],
    [0.9087, -0.0377, 8.1284e-4, -6.6192e-6, 1.9372e-8, 0.0, 0.0],
];

/// Index of λ in [`LAMBDAS`], or `None` (λ = 1 and uncalibrated λ).
fn lambda_index(lambda: f64) -> Option<usize> {
    LAMBDAS.iter().position(|&l| (l - lambda).abs() <= 1e-12)
}

/// `hu2021` exists for λ ∈ {1, 1.5, 2, 3} only (λ = 1 is Eq. 3).
pub fn check_lambda(lambda: f64) -> Result<()> {
    if lambda == 1.0 || lambda_index(lambda).is_some() {
        Ok(())
    } else {
        Err(Error::Input(format!(
            "invalid `lambda` = {lambda} for model `hu2021`: Hu et al. (2021) calibrated only λ = 1.5, 2, 3 \
             (λ = 1 is Eq. 3); use model `hertz-rigid` (or `hertz-dynamic`) for other aspect ratios"
        )))
    }
}

/// Hu et al. 2021, Eq. (8): ξ(λ, β) for λ ∈ {1.5, 2, 3}, β in degrees ∈ [0, 90]
/// (Horner evaluation of the sixth-degree polynomial); λ = 1 gives Eq. (3)'s coefficient.
pub fn xi(lambda: f64, beta_deg: f64) -> Result<f64> {
    check_lambda(lambda)?;
    match lambda_index(lambda) {
        None => Ok(hertz_sphere::xi_sphere()),
        Some(i) => Ok(COEFFS[i]
            .iter()
            .rev()
            .fold(0.0, |acc, &c| acc * beta_deg + c)),
    }
}

/// Hu et al. 2021, Eq. (7): `F_max = ξ(λ, β) ρ^0.6 U_N^1.2 D² [E/(1−σ²)]^0.4`. No contact time.
pub fn evaluate(p: &Particle, imp: &Impact) -> Result<ForceResult> {
    let xi = xi(imp.lambda, imp.beta.to_degrees())?;
    Ok(ForceResult {
        f_max: xi * p.force_scale(imp.u_n),
        xi,
        contact_time: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Eq. (8) evaluated by hand (term by term, written out below) at a few points.
    #[test]
    fn eq8_at_hand_evaluated_points() {
        // β = 0: the constant terms.
        assert_eq!(xi(1.5, 0.0).unwrap(), 0.7864);
        assert_eq!(xi(2.0, 0.0).unwrap(), 0.82837);
        assert_eq!(xi(3.0, 0.0).unwrap(), 0.9087);
        // λ = 2, β = 45: 0.82837 − 0.2934 − 1.966984 + 4.203050 − 3.360216 + 1.231910 − 0.172502 = 0.470227
        let hand: f64 = 0.82837 - 0.00652 * 45.0 - 9.7135e-4 * 2025.0 + 4.6124e-5 * 91125.0
            - 8.1944e-7 * 4_100_625.0
            + 6.6760e-9 * 184_528_125.0
            - 2.0774e-11 * 8_303_765_625.0;
        assert!((hand - 0.470227).abs() < 1e-6, "{hand}");
        assert!((xi(2.0, 45.0).unwrap() - hand).abs() < 1e-12);
        // λ = 2, β = 90: 0.82837 − 0.5868 − 7.867935 + 33.624396 − 53.763458 + 39.421112 − 11.040152
        let hand90 = 0.82837 - 0.5868 - 7.867935 + 33.624396 - 53.763458 + 39.421112 - 11.040155;
        assert!(
            (xi(2.0, 90.0).unwrap() - hand90).abs() < 1e-5,
            "{}",
            xi(2.0, 90.0).unwrap()
        );
        // λ = 3, β = 10: 0.9087 − 0.377 + 0.081284 − 0.0066192 + 0.00019372 = 0.60655852
        assert!((xi(3.0, 10.0).unwrap() - 0.60655852).abs() < 1e-12);
        // λ = 1.5, β = 30: 0.7864 + 0.00246879 − 0.470961 + 0.450090 − 0.16142490 + 0.0232918 − 0.000849868
        let hand15 =
            0.7864 + 0.00246879 - 0.470961 + 0.450090 - 0.1614249 + 0.02329179 - 0.00084987;
        assert!(
            (xi(1.5, 30.0).unwrap() - hand15).abs() < 1e-7,
            "{}",
            xi(1.5, 30.0).unwrap()
        );
    }

    #[test]
    fn lambda_one_is_eq3_and_others_name_hertz_rigid() {
        assert_eq!(xi(1.0, 37.0).unwrap(), hertz_sphere::XI_SPHERE);
        for bad in [1.2, 2.5, 4.0] {
            let e = xi(bad, 10.0).unwrap_err().to_string();
            assert!(e.contains("hertz-rigid") && !e.contains('\n'), "{e}");
        }
    }

    /// Hu et al. 2021, Sec. 4 / Fig. 6: largest at β = 0, smallest near 45°, a second,
    /// lower peak at 90°.
    #[test]
    fn fig6_shape() {
        for l in LAMBDAS {
            let v: Vec<f64> = (0..=90).map(|b| xi(l, b as f64).unwrap()).collect();
            let imin = (0..=90).min_by(|&a, &b| v[a].total_cmp(&v[b])).unwrap();
            assert!((35..=55).contains(&imin), "λ = {l}: min at {imin}");
            assert!(v[0] > v[90] && v[90] > v[imin]);
        }
    }
}
