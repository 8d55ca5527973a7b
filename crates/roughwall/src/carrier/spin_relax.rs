//! The particle's spin between hits: the fluid's torque on a sphere rotating relative to it,
//! `T = (ρ_f/2) (d_p/2)⁵ C_R |Ω| Ω`, Ω = ½ ∇ × u_f − ω_p (in the form of Crowe et al. 2012,
//! Ch. 4, and Laín & Sommerfeld 2008), with Dennis, Singh & Ingham's (1980, *J. Fluid Mech.*
//! 101, 257–279) coefficient: `C_R = 64π/Re_R` (Re_R ≤ 32, the Stokes torque π μ_f d_p³ Ω)
//! and `C_R = 12.9/Re_R^½ + 128.4/Re_R` (32 < Re_R < 1000; extrapolated above),
//! Re_R = ρ_f d_p² |Ω| / μ_f. With the moment of inertia I = π ρ_p d_p⁵ / 60 the relative
//! rotation decays as `dΩ/dt = −λ Ω`, `λ = (15/16π) (ρ_f/ρ_p) C_R |Ω|`, for a fluid rotation
//! that is constant over the step.

use super::{norm, FluidPoint};

/// `C_R Re_R` in the Stokes regime: 64π (the Stokes torque π μ_f d_p³ Ω).
const STOKES_C_R_RE: f64 = 64.0 * std::f64::consts::PI;

/// The Re_R up to which the Stokes branch holds (Dennis, Singh & Ingham 1980).
const STOKES_LIMIT: f64 = 32.0;

/// Dennis, Singh & Ingham's (1980) rotational drag coefficient `C_R(Re_R)`, as Crowe et al.
/// (2012, Ch. 4) quote it; the two branches meet at Re_R = 32 to 0.2 %.
pub fn rotational_drag_coefficient(re_r: f64) -> f64 {
    if re_r <= STOKES_LIMIT {
        STOKES_C_R_RE / re_r
    } else {
        12.9 / re_r.sqrt() + 128.4 / re_r
    }
}

/// The particle's spin after `dt` seconds: `ω_p' = ½ ∇ × u_f − Ω e^(−λ dt)`, the rate λ
/// (1/s) of the module's equation taken at the start of the step and held over it, which is
/// exact in the Stokes regime (Re_R ≤ 32, λ = 60 μ_f / (ρ_p d_p²)) for a fluid rotation that
/// is constant over the step, and never overshoots the fluid's rotation.
pub fn relaxed_spin(p: &FluidPoint, dt: f64) -> [f64; 3] {
    let rot = p.relative_rotation();
    let omega = norm(&rot);
    let re_r = p.rho_f * p.d_p * p.d_p * omega / p.mu_f;
    // C_R |Ω| without dividing by |Ω| in the Stokes branch (finite at Ω = 0)
    let c_r_omega = if re_r <= STOKES_LIMIT {
        STOKES_C_R_RE * p.mu_f / (p.rho_f * p.d_p * p.d_p)
    } else {
        rotational_drag_coefficient(re_r) * omega
    };
    let lambda = 15.0 / (16.0 * std::f64::consts::PI) * p.rho_f / p.rho_p * c_r_omega;
    let decay = (-lambda * dt).exp();
    std::array::from_fn(|k| 0.5 * p.vorticity[k] - rot[k] * decay)
}
