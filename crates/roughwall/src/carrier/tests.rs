//! The carrier-flow laws against their analytic limits and directions.
use super::*;

/// 100 µm glass in air at 20 °C.
fn bead() -> FluidPoint {
    FluidPoint {
        rho_f: 1.205,
        mu_f: 1.82e-5,
        rho_p: 2500.0,
        d_p: 100e-6,
        ..Default::default()
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn saffman_mei_tends_to_saffmans_lift_at_small_reynolds_numbers() {
    // Re_p = 0.01, β = 0.2: Mei's factor is 1 to 1e-3.
    let mut p = bead();
    let nu = p.mu_f / p.rho_f;
    let u = 0.01 * nu / p.d_p;
    let g = 0.4 * 0.01 * nu / (p.d_p * p.d_p); // Re_S = 2 β Re_p
    p.slip = [u, 0.0, 0.0];
    p.vorticity = [0.0, 0.0, -g];
    let a = saffman_mei_lift(&p);
    // Saffman (1965): F = 1.615 d² (ρ μ)^½ |ω|^½ |u| (here along +y)
    let m = p.rho_p * std::f64::consts::PI * p.d_p.powi(3) / 6.0;
    let f = 1.615 * p.d_p * p.d_p * (p.rho_f * p.mu_f).sqrt() * g.sqrt() * u;
    assert!(rel(a[1], f / m) < 2e-3, "{} vs {}", a[1], f / m);
    assert_eq!((a[0], a[2]), (0.0, 0.0));
    assert!((saffman_mei_factor(0.01, 0.004) - 1.0).abs() < 1e-3);
    assert_eq!(saffman_mei_factor(0.0, 1.0), 1.0);
}

#[test]
fn saffman_lift_pushes_a_lagging_particle_towards_the_faster_fluid() {
    // u_x = G y near a wall at y = 0: ∇ × u = (0, 0, −G). A particle slower than the fluid
    // is lifted off the wall (+y); a faster one is pushed towards it.
    let mut p = bead();
    p.vorticity = [0.0, 0.0, -2000.0];
    p.slip = [1.0, 0.0, 0.0];
    assert!(saffman_mei_lift(&p)[1] > 0.0);
    p.slip = [-1.0, 0.0, 0.0];
    assert!(saffman_mei_lift(&p)[1] < 0.0);
    // perpendicular to the slip and to the vorticity
    p.slip = [0.3, -0.2, 0.5];
    p.vorticity = [100.0, 40.0, -2000.0];
    let a = saffman_mei_lift(&p);
    let dot = |x: &[f64; 3], y: &[f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    assert!(dot(&a, &p.slip).abs() < 1e-12 * norm(&a) * norm(&p.slip));
    assert!(dot(&a, &p.vorticity).abs() < 1e-12 * norm(&a) * norm(&p.vorticity));
    // none without shear or without slip
    p.vorticity = [0.0; 3];
    assert_eq!(saffman_mei_lift(&p), [0.0; 3]);
}

#[test]
fn meis_factor_has_its_published_branches() {
    // Re_p = 20, Re_S = 4 (β = 0.1): (1 − 0.3314 √0.1) e^−2 + 0.3314 √0.1
    let beta: f64 = 0.1;
    let low = (1.0 - 0.3314 * beta.sqrt()) * (-2.0f64).exp() + 0.3314 * beta.sqrt();
    assert!(rel(saffman_mei_factor(20.0, 4.0), low) < 1e-12);
    // Re_p = 60, Re_S = 12 (β = 0.1): 0.0524 √(6)
    assert!(rel(saffman_mei_factor(60.0, 12.0), 0.0524 * 6.0f64.sqrt()) < 1e-12);
    // the lift falls with the particle Reynolds number (Mei 1992, Fig. 2)
    assert!(saffman_mei_factor(5.0, 1.0) > saffman_mei_factor(20.0, 4.0));
}

#[test]
fn magnus_tends_to_rubinow_keller_at_small_reynolds_numbers() {
    // Re_p = Re_R = 0.01: C_LR = Re_R/Re_p to 2e-3.
    let mut p = bead();
    let nu = p.mu_f / p.rho_f;
    let u = 0.01 * nu / p.d_p;
    let w = 0.01 * nu / (p.d_p * p.d_p);
    p.slip = [-u, 0.0, 0.0]; // the particle moves along +x through still fluid
    p.spin = [0.0, 0.0, w]; // backspin (counter-clockwise seen from +z)
    let a = magnus_lift(&p);
    // Rubinow & Keller (1961): F = (π/8) ρ_f d³ Ω × (u_f − v_p), Ω = −ω_p: along +y.
    let m = p.rho_p * std::f64::consts::PI * p.d_p.powi(3) / 6.0;
    let f = std::f64::consts::PI / 8.0 * p.rho_f * p.d_p.powi(3) * w * u;
    assert!(a[1] > 0.0, "backspin lifts: {a:?}");
    assert!(rel(a[1], f / m) < 2e-3, "{} vs {}", a[1], f / m);
    assert!(rel(magnus_coefficient(0.01, 0.01), 1.0) < 2e-3);
}

#[test]
fn magnus_coefficient_is_oesterle_and_bui_dinhs() {
    // Re_p = 50, Re_R = 25: 0.45 + 0.05 exp(−0.05684 · 25^0.4 · 50^0.3) = 0.475686…
    let x = 25f64.powf(0.4) * 50f64.powf(0.3);
    let c = 0.45 + 0.05 * (-0.05684 * x).exp();
    assert!(rel(magnus_coefficient(50.0, 25.0), c) < 1e-14);
    assert!((c - 0.4757).abs() < 1e-4);
    // the lift of a particle turning with the fluid is zero, and finite without slip
    let mut p = bead();
    p.vorticity = [0.0, 0.0, -2000.0];
    p.spin = [0.0, 0.0, -1000.0];
    p.slip = [1.0, 0.0, 0.0];
    assert_eq!(magnus_lift(&p), [0.0; 3]);
    p.spin = [0.0; 3];
    p.slip = [0.0; 3];
    assert_eq!(magnus_lift(&p), [0.0; 3]);
}

#[test]
fn spin_relaxes_as_the_stokes_torque_predicts() {
    // Re_R ≤ 32: dΩ/dt = −60 μ/(ρ_p d²) Ω exactly.
    let mut p = bead();
    p.vorticity = [0.0, 0.0, -2000.0];
    p.spin = [50.0, 0.0, 300.0];
    let re_r = p.rho_f * p.d_p * p.d_p * norm(&p.relative_rotation()) / p.mu_f;
    assert!(re_r < 32.0, "{re_r}");
    let dt = 1e-3;
    let lambda = 60.0 * p.mu_f / (p.rho_p * p.d_p * p.d_p);
    let w = relaxed_spin(&p, dt);
    for (k, wk) in w.iter().enumerate() {
        let rot = 0.5 * p.vorticity[k] - p.spin[k];
        let expect = 0.5 * p.vorticity[k] - rot * (-lambda * dt).exp();
        assert!((wk - expect).abs() < 1e-12 * (1.0 + expect.abs()), "{k}");
    }
    // two half steps are one step (exact exponential in the Stokes regime)
    let half = relaxed_spin(
        &FluidPoint {
            spin: relaxed_spin(&p, dt / 2.0),
            ..p
        },
        dt / 2.0,
    );
    for (h, wk) in half.iter().zip(&w) {
        assert!((h - wk).abs() < 1e-9 * (1.0 + wk.abs()));
    }
    // a particle turning with the fluid keeps turning so; a long time brings it there
    let with = FluidPoint {
        spin: [0.0, 0.0, -1000.0],
        ..p
    };
    assert_eq!(relaxed_spin(&with, dt), [0.0, 0.0, -1000.0]);
    let late = relaxed_spin(&p, 100.0);
    assert!((late[2] + 1000.0).abs() < 1e-9 && late[0].abs() < 1e-9);
}

#[test]
fn rotational_drag_branches_meet_and_the_spin_never_overshoots() {
    let (a, b) = (
        rotational_drag_coefficient(32.0),
        12.9 / 32f64.sqrt() + 128.4 / 32.0,
    );
    assert!(rel(a, b) < 2e-3, "{a} vs {b}");
    // a fast spin (Re_R ≈ 300) decays monotonically towards the fluid's rotation
    let mut p = bead();
    p.d_p = 1e-3;
    p.spin = [0.0, 0.0, 5000.0];
    for _ in 0..200 {
        let w = relaxed_spin(&p, 1e-3);
        assert!(w[2] < p.spin[2] && w[2] > 0.0);
        p.spin = w;
    }
}

#[test]
fn the_point_checks_its_numbers() {
    let p = bead();
    assert!(p.is_valid());
    assert!(!FluidPoint { mu_f: 0.0, ..p }.is_valid());
    assert!(!FluidPoint {
        slip: [f64::NAN, 0.0, 0.0],
        ..p
    }
    .is_valid());
    assert!(!FluidPoint { d_p: -1e-4, ..p }.is_valid());
}
