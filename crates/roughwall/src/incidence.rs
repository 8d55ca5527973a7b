//! Incident particles: the horizontal-speed law and the incident velocity, shared by the
//! deterministic tracker and the stochastic model so both shoot the same particles.

use nalgebra::Vector3;
use rand::Rng;
use rand_distr::{Distribution, Normal};

/// Incident speed `~ N(mean, std)`: by default the *horizontal* speed, as in Radenkovic &
/// Simonin 2021, Sec. 4 (`|U| = u_h / cos α`); or the speed `|U|` itself, which an erosion
/// study against the impact angle needs (a fixed impact energy at every angle).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedLaw {
    /// Mean of the drawn speed (m/s): the horizontal speed `u_h` or `|U|`, as `reference` says.
    pub mean_m_s: f64,
    /// Standard deviation of the drawn speed (m/s); 0 draws nothing and every particle gets
    /// `mean_m_s`. Non-positive draws are redrawn ([`draw_speed`]).
    pub std_m_s: f64,
    /// Whether the drawn speed is the horizontal speed `u_h` (the convention of Radenkovic & Simonin 2021,
    /// Sec. 4, and the default: docs/physics.md §6) or the speed `|U|`.
    pub reference: SpeedReference,
}

/// What the drawn speed of a [`SpeedLaw`] is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SpeedReference {
    /// The horizontal speed `u_h` (Radenkovic & Simonin 2021, Sec. 4: `u⁻ ~ N(5.91, 1.16)`
    /// m/s is the horizontal projection; docs/physics.md §6).
    #[default]
    Horizontal,
    /// The speed `|U|`.
    Magnitude,
}

impl SpeedReference {
    /// The name in case files (`[incidence] speed_reference`).
    pub fn name(self) -> &'static str {
        match self {
            SpeedReference::Horizontal => "horizontal",
            SpeedReference::Magnitude => "magnitude",
        }
    }
}

impl SpeedLaw {
    /// A horizontal-speed law (Radenkovic & Simonin 2021, Sec. 4; docs/physics.md §6).
    pub const fn horizontal(mean_m_s: f64, std_m_s: f64) -> SpeedLaw {
        SpeedLaw {
            mean_m_s,
            std_m_s,
            reference: SpeedReference::Horizontal,
        }
    }

    /// The incident velocity for angles `alpha < 0`, `beta` (rad) and a drawn speed `s`:
    /// [`incident_velocity`] for a horizontal speed, `s` along the incident direction for
    /// a speed magnitude.
    #[inline]
    pub fn velocity(&self, alpha: f64, beta: f64, s: f64) -> Vector3<f64> {
        match self.reference {
            SpeedReference::Horizontal => incident_velocity(alpha, beta, s),
            SpeedReference::Magnitude => {
                let ca = alpha.cos();
                Vector3::new(ca * beta.cos(), alpha.sin(), -ca * beta.sin()) * s
            }
        }
    }
}

/// Incident angular velocity (rad/s, wall frame: `x` the main roughness direction, `y` the
/// wall normal): each component `~ N(mean, std)`, drawn per particle from its own stream.
/// Zero by default (Radenkovic & Simonin 2021, Sec. 4); with every `std` zero nothing is
/// drawn, so a run without spin uses the same random numbers as before spin existed.
/// At `β⁻ = 0` (incident along `+x`), `ω_z < 0` is topspin (forward rolling), `ω_z > 0`
/// backspin, `ω_x` sidespin and `ω_y` spin about the wall normal.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SpinLaw {
    /// Mean `(ω_x, ω_y, ω_z)` of the incident angular velocity (rad/s, wall frame).
    pub mean_rad_s: [f64; 3],
    /// Standard deviations of `(ω_x, ω_y, ω_z)` (rad/s); a component with 0 is not drawn.
    pub std_rad_s: [f64; 3],
}

impl SpinLaw {
    /// Whether every particle arrives without spin.
    pub fn is_zero(&self) -> bool {
        self.mean_rad_s == [0.0; 3] && self.std_rad_s == [0.0; 3]
    }

    /// The spin of one particle (draws only components with a spread).
    #[inline]
    pub fn draw<R: Rng + ?Sized>(&self, r: &mut R) -> Vector3<f64> {
        let mut w = self.mean_rad_s;
        for (c, &s) in w.iter_mut().zip(&self.std_rad_s) {
            if s > 0.0 {
                let z: f64 = r.sample(rand_distr::StandardNormal);
                *c += s * z;
            }
        }
        Vector3::from(w)
    }
}

/// One incident condition `(α⁻, β⁻)`: in radians for the physics, and in degrees exactly as
/// the case gave them, so that outputs name the condition the user asked for (`-15`, never
/// `-14.999999999999998`) and two conditions that differ in the case never merge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IncidentCondition {
    /// `α⁻`, the incident angle to the mean wall (radians, `α⁻ = asin(v⁻/|U⁻|)` in
    /// `[−π/2, 0)`, negative towards the wall; docs/physics.md §1). Must match the degrees of
    /// [`alpha_in_deg`](Self::alpha_in_deg): build conditions with
    /// [`from_degrees`](Self::from_degrees).
    pub alpha_in: f64,
    /// `β⁻`, the incident angle in the wall plane from the principal roughness direction `x`
    /// (radians; `β⁻ = atan2(−w⁻, u⁻)` in `[−π, π]`, docs/physics.md §1). Must match the
    /// degrees of [`beta_in_deg`](Self::beta_in_deg): build conditions with
    /// [`from_degrees`](Self::from_degrees).
    pub beta_in: f64,
    alpha_deg: f64,
    beta_deg: f64,
}

impl IncidentCondition {
    /// The condition of angles given in degrees.
    pub fn from_degrees(alpha_in_deg: f64, beta_in_deg: f64) -> IncidentCondition {
        IncidentCondition {
            alpha_in: alpha_in_deg.to_radians(),
            beta_in: beta_in_deg.to_radians(),
            alpha_deg: alpha_in_deg,
            beta_deg: beta_in_deg,
        }
    }

    /// `α⁻` in degrees, as given.
    pub fn alpha_in_deg(&self) -> f64 {
        self.alpha_deg
    }

    /// `β⁻` in degrees, as given.
    pub fn beta_in_deg(&self) -> f64 {
        self.beta_deg
    }
}

/// An angle of a condition key in the CSV files: the shortest decimal that reads back as the
/// same number (`-15`, `-89.999999`, `1e-9`), so keys round-trip exactly; `-0` is written `0`.
pub fn fmt_key(deg: f64) -> String {
    if deg == 0.0 {
        "0".into()
    } else {
        format!("{deg}")
    }
}

/// Draws the horizontal speed `~ N(mean, std)` (Radenkovic & Simonin 2021, Sec. 4);
/// non-positive draws are redrawn (up to 64 times, then the mean is used).
/// With `std = 0` nothing is drawn.
pub fn draw_speed<R: Rng + ?Sized>(law: &SpeedLaw, r: &mut R) -> f64 {
    if law.std_m_s > 0.0 {
        if let Ok(n) = Normal::new(law.mean_m_s, law.std_m_s) {
            for _ in 0..64 {
                let v = n.sample(r);
                if v > 0.0 && v.is_finite() {
                    return v;
                }
            }
        }
    }
    law.mean_m_s
}

/// Incident velocity for angles `alpha < 0`, `beta` (rad) and horizontal speed
/// `u_h` (docs/physics.md §1: `U = |U| (cos α cos β, sin α, −cos α sin β)`,
/// `|U| = u_h / cos α`). At normal incidence (`cos α ≤ 1e-9`) the drawn speed is
/// taken as `|U|`.
pub fn incident_velocity(alpha: f64, beta: f64, u_h: f64) -> Vector3<f64> {
    let ca = alpha.cos();
    let speed = if ca > 1e-9 { u_h / ca } else { u_h };
    Vector3::new(ca * beta.cos(), alpha.sin(), -ca * beta.sin()) * speed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horizontal_speed_is_the_drawn_one_and_angles_are_kept() {
        let u = incident_velocity(-0.3, 1.0, 5.91);
        assert!(((u.x * u.x + u.z * u.z).sqrt() - 5.91).abs() < 1e-12);
        let (a, b) = crate::angles::incident_angles(&u);
        assert!((a + 0.3).abs() < 1e-12 && (b - 1.0).abs() < 1e-12);
        let down = incident_velocity(-std::f64::consts::FRAC_PI_2, 0.0, 2.0);
        assert!((down.norm() - 2.0).abs() < 1e-12 && down.y < 0.0);
    }

    #[test]
    fn a_speed_magnitude_is_the_impact_speed_at_every_angle() {
        let law = SpeedLaw {
            reference: SpeedReference::Magnitude,
            ..SpeedLaw::horizontal(7.0, 0.0)
        };
        for a in [-1e-4, -0.3, -1.2, -std::f64::consts::FRAC_PI_2] {
            let u = law.velocity(a, 0.7, 7.0);
            assert!((u.norm() - 7.0).abs() < 1e-12, "{a}");
            let (aa, bb) = crate::angles::incident_angles(&u);
            assert!((aa - a).abs() < 1e-12);
            if a > -1.5 {
                assert!((bb - 0.7).abs() < 1e-12);
            }
        }
        // The paper's convention is the plain incident velocity, bit for bit.
        let h = SpeedLaw::horizontal(7.0, 0.0);
        assert_eq!(
            h.velocity(-0.3, 0.7, 7.0),
            incident_velocity(-0.3, 0.7, 7.0)
        );
    }

    #[test]
    fn speeds_are_positive() {
        let mut r = crate::rng::stream(1, &[5]);
        let law = SpeedLaw::horizontal(0.5, 1.0);
        assert!((0..10_000).all(|_| draw_speed(&law, &mut r) > 0.0));
    }
}
