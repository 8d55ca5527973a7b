//! Table 1 of Radenkovic & Simonin 2021 on generated surfaces: the acceptance
//! criteria, at a CI-friendly size (same δ/c_L as Table 1, L/c_Lx = 128) and on the full
//! N = 5001 surface of `configs/cases/table1.toml` (about 2 s with the test profile).
use roughwall::surface::generate;
use roughwall::surface::surface_stats;
use roughwall::wall::rotated_moments;
use roughwall::Deviations;
use roughwall::SurfaceSpec;

fn check_table1(spec: &SurfaceSpec, seed: u64) {
    let betas: Vec<f64> = [0.0f64, 30.0, 60.0, 90.0]
        .iter()
        .map(|b| b.to_radians())
        .collect();
    let f = generate(spec, seed);
    let s = surface_stats(&f, &betas, None);
    let h = spec.rms_height_m;
    let dev = spec.deviations();
    // rms height within 2 % of h; rms slopes within 3 % of Eq. (14).
    assert!(
        (s.rms_height_m / h - 1.0).abs() < 0.02,
        "rms height {}",
        s.rms_height_m
    );
    let (sx, sz) = (dev.delta_xi, dev.delta_zeta); // √2 h / c_L (Eqs. 14–15)
    assert!(
        (s.rms_slope_x / sx - 1.0).abs() < 0.03,
        "{} vs {sx}",
        s.rms_slope_x
    );
    assert!(
        (s.rms_slope_z / sz - 1.0).abs() < 0.03,
        "{} vs {sz}",
        s.rms_slope_z
    );
    for r in &s.rotated {
        let m = rotated_moments(&Deviations { ..dev }, r.beta_star);
        let deg = |x: f64| x.to_degrees();
        let b = deg(r.beta_star).round();
        assert!(
            (deg(r.delta_xi_star) - deg(m.var_a.sqrt())).abs() < 0.4,
            "β* {b}: Δξ* {} vs {}",
            deg(r.delta_xi_star),
            deg(m.var_a.sqrt())
        );
        assert!(
            (deg(r.delta_zeta_star) - deg(m.var_b.sqrt())).abs() < 0.4,
            "β* {b}: Δζ* {} vs {}",
            deg(r.delta_zeta_star),
            deg(m.var_b.sqrt())
        );
        let model_rho = if b == 0.0 || b == 90.0 { 0.0 } else { m.rho() };
        assert!(
            (r.rho_xi_zeta - model_rho).abs() < 0.06,
            "β* {b}: ρ {} vs {model_rho}",
            r.rho_xi_zeta
        );
        if b == 30.0 || b == 60.0 {
            assert!(r.rho_xi_zeta < -0.5, "Table 1: negative at 30° and 60°");
        }
        // Table 1: ξ*, ζ* nearly uncorrelated with η*.
        assert!(r.rho_xi_eta.abs() < 0.1 && r.rho_eta_zeta.abs() < 0.1);
    }
}

#[test]
fn table1_statistics_at_ci_size() {
    // δ = 1 µm and the Table 1 roughness; L = 1536 µm (128 c_Lx) instead of 5 mm.
    let spec = SurfaceSpec {
        length_m: 1536e-6,
        nodes: 1536,
        rms_height_m: 0.37e-6,
        corr_length_x_m: Some(12e-6),
        corr_length_z_m: Some(4e-6),
    };
    for seed in [1, 2] {
        check_table1(&spec, seed);
    }
}

/// The full Table 1 surface (N = 5001, L = 5 mm, seed 1: `configs/cases/table1.toml`, which
/// `rebound surface` runs).
#[test]
fn table1_statistics_full_size() {
    let spec = SurfaceSpec {
        length_m: 5e-3,
        nodes: 5001,
        rms_height_m: 0.37e-6,
        corr_length_x_m: Some(12e-6),
        corr_length_z_m: Some(4e-6),
    };
    check_table1(&spec, 1);
}
