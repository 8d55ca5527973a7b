//! Numbers the papers print, quoted so the report can set ours beside them.

/// Radenkovic & Simonin 2021, Table 1: `β*`, then the numerically generated surface's
/// `Δξ*`, `Δζ*` (deg), `ρ_ξ*ζ*`, `ρ_ξ*η*`, `ρ_η*ζ*`, then the statistical model's `Δξ*`, `Δζ*`, `ρ_ξ*ζ*`.
pub const TABLE1: [[f64; 9]; 4] = [
    [0.0, 2.32, 7.59, 0.05, 0.03, -0.02, 2.50, 7.50, 0.00],
    [30.0, 4.38, 6.09, -0.73, 0.02, 0.04, 4.53, 6.53, -0.76],
    [60.0, 6.66, 4.30, -0.73, -0.06, 0.00, 6.53, 4.53, -0.76],
    [90.0, 7.67, 2.45, -0.08, 0.00, 0.03, 7.50, 2.50, 0.00],
];

/// Hu et al., Sec. 3 (Fig. 4): FE against Eq. (3) for spheres, `φ ≤ 0.93 %` for `U_N ≤ 0.2 m/s`.
pub const HU_FIG4_PHI_MAX: f64 = 0.0093;

/// Hu et al., Sec. 4 (Fig. 11b): model against FE differs by 13.6 % at `U_N = 20 m/s`
/// (D = 10 µm, λ = 1.5, β = 45°).
pub const HU_FIG11B_DIFF: f64 = 0.136;
