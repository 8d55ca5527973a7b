//! The rotational (Magnus) lift of a sphere spinning relative to the fluid, in the form of
//! Crowe et al. (2012, Ch. 4) and Laín & Sommerfeld (2008):
//!
//! `F_LR = (ρ_f/2) (π/4) d_p² C_LR |u_f − v_p| [Ω × (u_f − v_p)] / |Ω|`, Ω = ½ ∇ × u_f − ω_p,
//!
//! with Oesterlé & Bui Dinh's (1998, *Exp. Fluids* 25, 16–22) coefficient
//! `C_LR = 0.45 + (Re_R/Re_p − 0.45) exp(−0.05684 Re_R^0.4 Re_p^0.3)`, Re_R = ρ_f d_p² |Ω|/μ_f,
//! fitted for Re_p < 140. As Re_R, Re_p → 0 it tends to Re_R/Re_p, Rubinow & Keller's (1961)
//! `F = (π/8) ρ_f d_p³ Ω × (u_f − v_p)`.

use super::{cross, norm, FluidPoint};

/// Oesterlé & Bui Dinh's high-Reynolds limit of `C_LR`.
const C_LR_LIMIT: f64 = 0.45;

/// The weight `exp(−0.05684 Re_R^0.4 Re_p^0.3)` that takes Oesterlé & Bui Dinh's `C_LR`
/// from Rubinow & Keller's `Re_R/Re_p` (weight 1) to [`C_LR_LIMIT`] (weight 0).
fn oesterle_weight(re_p: f64, re_r: f64) -> f64 {
    (-0.05684 * re_r.powf(0.4) * re_p.powf(0.3)).exp()
}

/// `C_LR |u_f − v_p|` (m/s): [`magnus_coefficient`] times the slip speed, written as
/// `0.45 |u| + (d_p |Ω| − 0.45 |u|) w` (Re_R/Re_p |u| = d_p |Ω|), finite as the slip
/// vanishes.
fn coefficient_times_slip(p: &FluidPoint, omega: f64) -> f64 {
    let u = norm(&p.slip);
    let re_r = p.rho_f * p.d_p * p.d_p * omega / p.mu_f;
    let w = oesterle_weight(p.reynolds_particle(), re_r);
    C_LR_LIMIT * u + (p.d_p * omega - C_LR_LIMIT * u) * w
}

/// Oesterlé & Bui Dinh's (1998) lift coefficient
/// `C_LR = 0.45 + (Re_R/Re_p − 0.45) exp(−0.05684 Re_R^0.4 Re_p^0.3)`; `Re_p > 0`.
pub fn magnus_coefficient(re_p: f64, re_r: f64) -> f64 {
    C_LR_LIMIT + (re_r / re_p - C_LR_LIMIT) * oesterle_weight(re_p, re_r)
}

/// The Magnus lift acceleration F_LR / m_p (m/s², m_p = ρ_p π d_p³ / 6; the module's
/// force): `(3/4)(ρ_f/ρ_p) (C_LR |u_f − v_p| / d_p) Ω̂ × (u_f − v_p)`. Zero when the
/// particle turns with the fluid (Ω = 0) or without slip.
pub fn magnus_lift(p: &FluidPoint) -> [f64; 3] {
    let rot = p.relative_rotation();
    let omega = norm(&rot);
    if omega == 0.0 {
        return [0.0; 3];
    }
    let k = 0.75 * p.rho_f / p.rho_p * coefficient_times_slip(p, omega) / (p.d_p * omega);
    cross(&rot, &p.slip).map(|x| k * x)
}
