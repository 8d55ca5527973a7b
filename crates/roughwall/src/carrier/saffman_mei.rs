//! The shear lift of a sphere in a velocity gradient: Saffman's (1965, 1968) low-Reynolds
//! lift with Mei's (1992) correction for finite particle Reynolds numbers, in the form of
//! Crowe et al. (2012, Ch. 4) and Laín & Sommerfeld (2008):
//!
//! `F_LS = (ρ_f/2) (π/4) d_p³ C_LS [(u_f − v_p) × ω_f]`, `C_LS = 4.1126/√Re_S · f(Re_p, Re_S)`,
//!
//! with ω_f = ∇ × u_f, Re_S = ρ_f d_p² |ω_f| / μ_f and Mei's
//! `f = (1 − 0.3314 β^½) e^(−Re_p/10) + 0.3314 β^½` (Re_p ≤ 40),
//! `f = 0.0524 (β Re_p)^½` (Re_p > 40), β = Re_S / (2 Re_p).
//! For f = 1 this is Saffman's `F = 1.615 d_p² (ρ_f μ_f)^½ |ω_f|^−½ (u_f − v_p) × ω_f`.
//! Mei fitted it for 0.1 ≤ Re_p ≤ 100 and 0.005 ≤ β ≤ 0.4; outside, it is extrapolated.

use super::{cross, norm, FluidPoint};

/// Mei's (1992, *Int. J. Multiphase Flow* 18, 145–147) correction `f(Re_p, Re_S)` of
/// Saffman's lift. Written as `e^(−Re_p/10) + 0.3314 β^½ (1 − e^(−Re_p/10))` so that it tends
/// to Saffman's 1 as Re_p → 0 without dividing 0 by 0.
pub fn saffman_mei_factor(re_p: f64, re_s: f64) -> f64 {
    if re_p <= 0.0 {
        return 1.0;
    }
    let sqrt_beta = (re_s / (2.0 * re_p)).sqrt();
    if re_p <= 40.0 {
        let decay = (-re_p / 10.0).exp();
        decay + 0.3314 * sqrt_beta * -(-re_p / 10.0).exp_m1()
    } else {
        0.0524 * sqrt_beta * re_p.sqrt()
    }
}

/// The Saffman–Mei lift acceleration F_LS / m_p (m/s², m_p = ρ_p π d_p³ / 6; the module's
/// force): `(3/4)(ρ_f/ρ_p) C_LS (u_f − v_p) × ω_f`. Zero without slip or
/// without vorticity.
pub fn saffman_mei_lift(p: &FluidPoint) -> [f64; 3] {
    let w = norm(&p.vorticity);
    if w == 0.0 {
        return [0.0; 3];
    }
    let re_s = p.rho_f * p.d_p * p.d_p * w / p.mu_f;
    let c_ls = 4.1126 / re_s.sqrt() * saffman_mei_factor(p.reynolds_particle(), re_s);
    let k = 0.75 * p.rho_f / p.rho_p * c_ls;
    cross(&p.slip, &p.vorticity).map(|x| k * x)
}
