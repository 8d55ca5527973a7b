//! The effective wall element of a history: the plane that mirrors its incident direction
//! into its rebound direction.

use crate::angles::gamma_from_normal;
use nalgebra::Vector3;

/// The unit normal of the plane that mirrors the direction of `u_in` into that of `u_out`:
/// `(û⁺ − û⁻)/|û⁺ − û⁻|`. For an ideally elastic bounce (`|U⁺| = |U⁻|`) reflecting `U⁻` off
/// it gives `U⁺` exactly (a specular reflection, Radenkovic & Simonin 2021, Sec. 3.1 with
/// Eq. 36 at `e = 1`, `μ = 0`), however many collisions the history had. `None` when the
/// directions are equal or a speed is zero; its `y` is positive whenever the particle came
/// down (`u_in.y < 0`) and left (`u_out.y > 0`).
pub fn effective_normal(u_in: &Vector3<f64>, u_out: &Vector3<f64>) -> Option<Vector3<f64>> {
    let (a, b) = (u_in.norm(), u_out.norm());
    if !(a > 0.0 && b > 0.0) {
        return None;
    }
    let d = u_out / b - u_in / a;
    let n = d.norm();
    (n > 0.0 && n.is_finite()).then(|| d / n)
}

/// The effective element's inclinations `(γ, γ*)` (rad) in the incident frame of direction
/// `beta_in` (Radenkovic & Simonin 2021, Eqs. 20–21).
pub fn effective_gammas(
    u_in: &Vector3<f64>,
    u_out: &Vector3<f64>,
    beta_in: f64,
) -> Option<(f64, f64)> {
    effective_normal(u_in, u_out).map(|n| gamma_from_normal(&n, beta_in))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::angles::{incident_angles, normal_from_gamma};
    use crate::collision::CollisionLaw;

    #[test]
    fn reflecting_off_the_effective_element_gives_the_rebound() {
        // Two successive specular bounces off different facets: one effective element.
        // A facet facing the particle, then a steep one facing back: it leaves upwards.
        let u = Vector3::new(3.0, -1.0, 0.7);
        let n1 = Vector3::new(-0.5, 1.0, 0.0).normalize();
        let n2 = Vector3::new(-1.0, 0.2, 0.0).normalize();
        let (u1, _) = CollisionLaw::Elastic.collide(u, Vector3::zeros(), n1, 0.0);
        assert!(u1.dot(&n2) < 0.0);
        let (u2, _) = CollisionLaw::Elastic.collide(u1, Vector3::zeros(), n2, 0.0);
        assert!(u2.y > 0.0);
        let n = effective_normal(&u, &u2).unwrap();
        assert!(n.y > 0.0);
        let (v, _) = CollisionLaw::Elastic.collide(u, Vector3::zeros(), n, 0.0);
        assert!((v - u2).norm() < 1e-12 * u.norm());
        // A single bounce: the element is the facet.
        let n1 = normal_from_gamma(0.1, -0.05, 0.3);
        let (v1, _) = CollisionLaw::Elastic.collide(u, Vector3::zeros(), n1, 0.0);
        assert!((effective_normal(&u, &v1).unwrap() - n1).norm() < 1e-12);
        let (_, beta) = incident_angles(&u);
        let (g, gs) = effective_gammas(&u, &v1, beta).unwrap();
        assert!((normal_from_gamma(g, gs, beta) - n1).norm() < 1e-12);
    }

    #[test]
    fn no_element_without_a_turn() {
        let u = Vector3::new(1.0, -1.0, 0.0);
        assert!(effective_normal(&u, &u).is_none());
        assert!(effective_normal(&u, &Vector3::zeros()).is_none());
    }
}
