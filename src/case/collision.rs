//! `[collision]`: the collision law (elastic, or Sommerfeld & Huber's with its parameters;
//! Radenkovic & Simonin 2021, Eqs. 36–42).

use super::check::{check_greater_than, check_less_than, check_range, check_value};
use super::schema::*;
use crate::collision::{CollisionLaw, ShParams};
use crate::error::{Error, Result};

impl Case {
    /// The collision law of `[collision]` (default: ideally elastic).
    pub fn collision_law(&self) -> Result<CollisionLaw> {
        let c = self.collision.clone().unwrap_or_default();
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
