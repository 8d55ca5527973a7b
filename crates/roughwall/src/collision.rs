//! Collision laws applied in the local frame of a wall normal `n`
//! (Radenkovic & Simonin 2021, Sec. 3.1 and Eqs. 36–42; docs/physics.md §2, §6).
//!
//! One implementation serves both the deterministic tracker and the stochastic
//! model. The laws are written in vector form, so they do not depend on which
//! tangent basis of the local frame one would pick (docs/physics.md §2).

use crate::check::{check_greater_than, check_less_than, check_range, check_value};
use crate::error::{Error, Result};
use nalgebra::Vector3;

/// Parameters of Sommerfeld & Huber's angle-dependent restitution and friction
/// (Radenkovic & Simonin 2021, Eqs. 36–37). Angles in radians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShParams {
    /// Restitution coefficient beyond `alpha_e`.
    pub e_h: f64,
    /// Impact angle up to which restitution falls linearly from 1 to `e_h`.
    pub alpha_e: f64,
    /// Friction coefficient at grazing impact.
    pub mu_0: f64,
    /// Friction coefficient beyond `alpha_mu`.
    pub mu_h: f64,
    /// Impact angle up to which friction falls linearly from `mu_0` to `mu_h`.
    pub alpha_mu: f64,
}

impl ShParams {
    /// Glass beads on stainless steel, the literature fit of Laín & Sommerfeld (2008) quoted in
    /// docs/physics.md §6 (not in the seed papers): `e_w = 1 − 0.0136 α` up to 20.6° then 0.72,
    /// `μ_w = 0.5 − 0.0175 α` up to 22° then 0.115 (α in degrees).
    pub fn glass_steel() -> ShParams {
        ShParams {
            e_h: 0.72,
            alpha_e: 20.6f64.to_radians(),
            mu_0: 0.5,
            mu_h: 0.115,
            alpha_mu: 22.0f64.to_radians(),
        }
    }

    /// Restitution coefficient at impact angle `|α|` (Radenkovic & Simonin 2021, Eq. 36).
    pub fn restitution(&self, abs_alpha: f64) -> f64 {
        if abs_alpha <= self.alpha_e && self.alpha_e > 0.0 {
            (self.e_h - 1.0) / self.alpha_e * abs_alpha + 1.0
        } else {
            self.e_h
        }
    }

    /// Friction coefficient at impact angle `|α|` (Radenkovic & Simonin 2021, Eq. 37 as corrected
    /// in docs/physics.md §2: `α_μ` and `μ_h`, not `α_e` and `e_h`).
    pub fn friction(&self, abs_alpha: f64) -> f64 {
        if abs_alpha <= self.alpha_mu && self.alpha_mu > 0.0 {
            (self.mu_h - self.mu_0) / self.alpha_mu * abs_alpha + self.mu_0
        } else {
            self.mu_h
        }
    }
}

/// A collision law as a case file's `[collision]` section or a C host gives it: `model`
/// (`"elastic"`, the default, or `"sommerfeld-huber"`), an optional `preset`
/// (`"glass-steel"`) and Sommerfeld–Huber parameters overriding it (angles in degrees).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CollisionParams {
    /// `"elastic"` (default) or `"sommerfeld-huber"`.
    pub model: Option<String>,
    /// `"glass-steel"` ([`ShParams::glass_steel`]).
    pub preset: Option<String>,
    /// Restitution coefficient beyond `alpha_e_deg` (Radenkovic & Simonin 2021, Eq. 36), in
    /// (0, 1].
    pub e_h: Option<f64>,
    /// Impact angle (degrees) up to which restitution falls (Eq. 36), in (0, 90].
    pub alpha_e_deg: Option<f64>,
    /// Friction coefficient at grazing impact (Eq. 37 as corrected in docs/physics.md §2),
    /// in [0, 2] (2: a bound chosen here, far above measured wall friction).
    pub mu_0: Option<f64>,
    /// Friction coefficient beyond `alpha_mu_deg` (Eq. 37), in [0, 2].
    pub mu_h: Option<f64>,
    /// Impact angle (degrees) up to which friction falls (Eq. 37), in (0, 90].
    pub alpha_mu_deg: Option<f64>,
}

impl CollisionParams {
    /// The law these parameters give, checked: one-line errors naming the key as in a case
    /// file (`collision.e_h`, …), the value and what is allowed.
    pub fn law(&self) -> Result<CollisionLaw> {
        let c = self;
        let model = c.model.as_deref().unwrap_or("elastic");
        match model {
            "elastic" => {
                if c.preset.is_some()
                    || c.e_h.is_some()
                    || c.mu_0.is_some()
                    || c.mu_h.is_some()
                    || c.alpha_e_deg.is_some()
                    || c.alpha_mu_deg.is_some()
                {
                    return Err(Error::Input(
                        "[collision] model = \"elastic\" takes no preset or parameters (use model = \"sommerfeld-huber\")".into(),
                    ));
                }
                Ok(CollisionLaw::Elastic)
            }
            "sommerfeld-huber" => {
                let base = match c.preset.as_deref() {
                    Some(name) => {
                        check_value(
                            "collision.preset",
                            name,
                            &["glass-steel"],
                            "\"glass-steel\"",
                        )?;
                        Some(ShParams::glass_steel())
                    }
                    None => None,
                };
                let pick = |v: Option<f64>, b: Option<f64>, key: &str| -> Result<f64> {
                    v.or(b).ok_or_else(|| {
                        Error::Input(format!("[collision] sommerfeld-huber needs `{key}` (or preset = \"glass-steel\")"))
                    })
                };
                let e_h = pick(c.e_h, base.map(|b| b.e_h), "e_h")?;
                let alpha_e = pick(
                    c.alpha_e_deg.map(f64::to_radians),
                    base.map(|b| b.alpha_e),
                    "alpha_e_deg",
                )?;
                let mu_0 = pick(c.mu_0, base.map(|b| b.mu_0), "mu_0")?;
                let mu_h = pick(c.mu_h, base.map(|b| b.mu_h), "mu_h")?;
                let alpha_mu = pick(
                    c.alpha_mu_deg.map(f64::to_radians),
                    base.map(|b| b.alpha_mu),
                    "alpha_mu_deg",
                )?;
                let allowed = "a restitution coefficient in (0, 1]";
                check_greater_than("collision.e_h", e_h, 0.0, false, allowed)?;
                check_less_than("collision.e_h", e_h, 1.0, true, allowed)?;
                for (k, v) in [("collision.mu_0", mu_0), ("collision.mu_h", mu_h)] {
                    check_range(k, v, 0.0, 2.0, "a friction coefficient in [0, 2]")?;
                }
                for (k, v) in [
                    ("collision.alpha_e_deg", alpha_e),
                    ("collision.alpha_mu_deg", alpha_mu),
                ] {
                    if !(v > 0.0 && v <= std::f64::consts::FRAC_PI_2) {
                        return Err(Error::invalid(
                            k,
                            v.to_degrees(),
                            "an angle in (0, 90] degrees",
                        ));
                    }
                }
                Ok(CollisionLaw::SommerfeldHuber(ShParams {
                    e_h,
                    alpha_e,
                    mu_0,
                    mu_h,
                    alpha_mu,
                }))
            }
            other => Err(Error::invalid(
                "collision.model",
                format!("\"{other}\""),
                "\"elastic\" or \"sommerfeld-huber\"",
            )),
        }
    }
}

/// How a particle leaves a wall element it hits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CollisionLaw {
    /// Ideally elastic, frictionless: `U⁺ = U⁻ − 2(U⁻·n)n`, spin unchanged (Sec. 3.1).
    Elastic,
    /// Inelastic with friction, rolling and sliding branches (Eqs. 36–42).
    SommerfeldHuber(ShParams),
}

impl CollisionLaw {
    /// Rebound velocity and spin for incident velocity `u`, spin `omega`, at a wall of unit
    /// normal `n` (into the flow), for a sphere of diameter `diameter_m`.
    ///
    /// Precondition: `u·n < 0` (the particle moves into the wall element). For the
    /// Sommerfeld–Huber law, `e_w` and `μ_w` are evaluated at the local impact angle
    /// `asin(−u·n/|u|)`, the angle of Eqs. (36)–(37) in the frame where they are applied.
    pub fn collide(
        &self,
        u: Vector3<f64>,
        omega: Vector3<f64>,
        n: Vector3<f64>,
        diameter_m: f64,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let un = u.dot(&n);
        match self {
            CollisionLaw::Elastic => (u - 2.0 * un * n, omega),
            CollisionLaw::SommerfeldHuber(p) => sommerfeld_huber(p, u, omega, n, un, diameter_m),
        }
    }
}

/// Sommerfeld–Huber collision in vector form (Radenkovic & Simonin 2021, Eqs. 38–42; docs/physics.md §2).
///
/// With `R = D/2`, the slip velocity of the contact point is `s = u_t − R (ω × n)` (Eq. 39 is `|s|`).
/// Non-sliding when `|s| < (7/2) μ_w (1 + e_w) |u·n|` (Eq. 38): `u_t⁺ = u_t − (2/7) s` (Eq. 40,
/// `u⁺ = 5/7 (u − D/5 ω_z)` in the wall frame) and the tangential spin rolls on the rebound velocity,
/// `ω_t⁺ = (n × u_t⁺)/R` (docs/physics.md §2: `ω_x⁺ = 2w⁺/D`, `ω_z⁺ = −2u⁺/D`).
/// Sliding otherwise: `u_t⁺ = u_t + μ_w (1+e_w) (u·n) ŝ`, `ω⁺ = ω − (5/(2R)) μ_w (1+e_w) (u·n) (n × ŝ)` (Eqs. 41–42).
/// In both branches `u_n⁺ = −e_w u_n` and the spin about `n` is unchanged.
fn sommerfeld_huber(
    p: &ShParams,
    u: Vector3<f64>,
    omega: Vector3<f64>,
    n: Vector3<f64>,
    un: f64,
    diameter_m: f64,
) -> (Vector3<f64>, Vector3<f64>) {
    let speed = u.norm();
    let abs_alpha = if speed > 0.0 {
        (-un / speed).clamp(0.0, 1.0).asin()
    } else {
        0.0
    };
    let e = p.restitution(abs_alpha);
    let mu = p.friction(abs_alpha);
    let r = 0.5 * diameter_m;
    let u_t = u - un * n;
    let slip = u_t - r * omega.cross(&n);
    let slip_norm = slip.norm();
    let omega_n = omega.dot(&n) * n;
    if slip_norm < 3.5 * mu * (1.0 + e) * (-un) {
        let u_t_out = u_t - (2.0 / 7.0) * slip;
        let omega_out = if r > 0.0 {
            n.cross(&u_t_out) / r + omega_n
        } else {
            omega
        };
        (u_t_out - e * un * n, omega_out)
    } else {
        let s_hat = slip / slip_norm;
        let k = mu * (1.0 + e) * un;
        let u_t_out = u_t + k * s_hat;
        let omega_out = if r > 0.0 {
            omega - (2.5 / r) * k * n.cross(&s_hat)
        } else {
            omega
        };
        (u_t_out - e * un * n, omega_out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const D: f64 = 500e-6;

    fn kinetic(u: &Vector3<f64>, w: &Vector3<f64>) -> f64 {
        // per unit mass, solid sphere: ½u² + ½ (2/5) R² ω²
        let r = 0.5 * D;
        0.5 * u.norm_squared() + 0.2 * r * r * w.norm_squared()
    }

    #[test]
    fn elastic_conserves_speed_and_mirrors() {
        let n = Vector3::new(0.1, 0.99, -0.05).normalize();
        let u = Vector3::new(3.0, -1.0, 0.5);
        let (up, _) = CollisionLaw::Elastic.collide(u, Vector3::zeros(), n, D);
        assert!(((up.norm() - u.norm()) / u.norm()).abs() < 1e-15);
        assert!((up.dot(&n) + u.dot(&n)).abs() < 1e-14);
    }

    #[test]
    fn rolling_branch_hand_worked() {
        // Flat wall n = j, glass-steel preset, u = (0.5, −2, 0): |α| = 75.96° > α_e, α_μ so
        // e = 0.72, μ = 0.115; slip 0.5 < 3.5·0.115·1.72·2 = 1.3846 → non-sliding (Eq. 38).
        let law = CollisionLaw::SommerfeldHuber(ShParams::glass_steel());
        let (up, wp) = law.collide(
            Vector3::new(0.5, -2.0, 0.0),
            Vector3::zeros(),
            Vector3::y(),
            D,
        );
        // Eq. 40: u⁺ = 5/7·0.5, v⁺ = 0.72·2, w⁺ = 0, ω_z⁺ = −2u⁺/D.
        assert!((up.x - 2.5 / 7.0).abs() < 1e-14);
        assert!((up.y - 1.44).abs() < 1e-14);
        assert!(up.z.abs() < 1e-15);
        assert!((wp.z + 2.0 * up.x / D).abs() < 1e-9);
        assert!(wp.x.abs() < 1e-12);
    }

    #[test]
    fn sliding_branch_hand_worked() {
        // u = (2, −0.5, 1), n = j, ω = 0: |α| = asin(0.5/√5.25) = 12.60°.
        // e = 1 − 0.28/20.6·12.60, μ = 0.5 − 0.385/22·12.60. Slip |s| = √5 > 3.5 μ (1+e) 0.5 → sliding.
        let p = ShParams::glass_steel();
        let law = CollisionLaw::SommerfeldHuber(p);
        let u: Vector3<f64> = Vector3::new(2.0, -0.5, 1.0);
        let a = (0.5 / u.norm()).asin();
        let e = 1.0 - 0.28 / 20.6 * a.to_degrees();
        let mu = 0.5 - 0.385 / 22.0 * a.to_degrees();
        let (up, wp) = law.collide(u, Vector3::zeros(), Vector3::y(), D);
        let (ex, ez) = (2.0 / 5f64.sqrt(), 1.0 / 5f64.sqrt());
        // Eq. 41 with v⁻ = −0.5
        assert!((up.x - (2.0 + ex * mu * (1.0 + e) * -0.5)).abs() < 1e-12);
        assert!((up.y - 0.5 * e).abs() < 1e-12);
        assert!((up.z - (1.0 + ez * mu * (1.0 + e) * -0.5)).abs() < 1e-12);
        assert!((wp.x - (-5.0 * ez * mu * (1.0 + e) * -0.5 / D)).abs() < 1e-6);
        assert!((wp.z - (5.0 * ex * mu * (1.0 + e) * -0.5 / D)).abs() < 1e-6);
    }

    #[test]
    fn never_gains_energy_and_is_basis_free() {
        let law = CollisionLaw::SommerfeldHuber(ShParams::glass_steel());
        let mut rng = crate::rng::stream(3, &[99]);
        use rand::Rng;
        for _ in 0..20_000 {
            let n =
                Vector3::new(rng.gen_range(-0.3..0.3), 1.0, rng.gen_range(-0.3..0.3)).normalize();
            let mut u = Vector3::new(
                rng.gen_range(-5.0..5.0),
                rng.gen_range(-5.0..0.0),
                rng.gen_range(-5.0..5.0),
            );
            if u.dot(&n) >= 0.0 {
                u -= 2.0 * u.dot(&n) * n;
            }
            let w = Vector3::new(
                rng.gen_range(-1e4..1e4),
                rng.gen_range(-1e4..1e4),
                rng.gen_range(-1e4..1e4),
            );
            let (up, wp) = law.collide(u, w, n, D);
            assert!(kinetic(&up, &wp) <= kinetic(&u, &w) * (1.0 + 1e-12));
            // Same law in a rotated global frame: rotate everything, collide, rotate back.
            let rot = nalgebra::Rotation3::from_euler_angles(0.3, -1.1, 2.0);
            let (up2, wp2) = law.collide(rot * u, rot * w, rot * n, D);
            assert!((rot.inverse() * up2 - up).norm() < 1e-9 * (1.0 + u.norm()));
            assert!((rot.inverse() * wp2 - wp).norm() < 1e-6 * (1.0 + w.norm()));
        }
    }

    #[test]
    fn eq36_37_piecewise_values() {
        let p = ShParams::glass_steel();
        assert!((p.restitution(0.0) - 1.0).abs() < 1e-15);
        assert!((p.restitution(20.6f64.to_radians()) - 0.72).abs() < 1e-12);
        assert_eq!(p.restitution(0.8), 0.72);
        assert!((p.friction(0.0) - 0.5).abs() < 1e-15);
        assert!((p.friction(22f64.to_radians()) - 0.115).abs() < 1e-12);
        assert_eq!(p.friction(0.5), 0.115);
    }
}
