//! `[collision]`: the collision law (elastic, or Sommerfeld & Huber's with its parameters;
//! Radenkovic & Simonin 2021, Eqs. 36–42), resolved by the library's
//! [`CollisionParams::law`], which the C library's wall handle calls too.

use super::schema::*;
use roughwall::Result;
use roughwall::{CollisionLaw, CollisionParams};

impl Case {
    /// The collision law of `[collision]` (default: ideally elastic).
    pub fn collision_law(&self) -> Result<CollisionLaw> {
        CollisionParams::from(self.collision.clone().unwrap_or_default()).law()
    }
}

impl From<CollisionSection> for CollisionParams {
    fn from(c: CollisionSection) -> CollisionParams {
        CollisionParams {
            model: c.model,
            preset: c.preset,
            e_h: c.e_h,
            alpha_e_deg: c.alpha_e_deg,
            mu_0: c.mu_0,
            mu_h: c.mu_h,
            alpha_mu_deg: c.alpha_mu_deg,
        }
    }
}
