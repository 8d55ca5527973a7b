//! The stochastic rebound model (Radenkovic & Simonin 2021, Sec. 3.4–3.6, 4; docs/physics.md §3)
//! against its analytic limits, the paper's findings and the hard cases of docs/physics.md §9.
use crate::common::dev;
use nalgebra::Vector3;
use rand::SeedableRng;
use rand_xoshiro::Xoshiro256PlusPlus;
use roughwall::angles::{incident_angles, velocity_from_angles, wrap_pi};
use roughwall::stochastic::{rebound, Rebound, MAX_TRIES};
use roughwall::wall::rotated_moments;
use roughwall::Deviations;
use roughwall::{CollisionLaw, ShParams};

const D: f64 = 500e-6;

fn sh() -> CollisionLaw {
    CollisionLaw::SommerfeldHuber(ShParams::glass_steel())
}

/// `n` rebounds at `(α⁻, β⁻)` in degrees with speed 6 m/s and no spin.
fn run(wall: &Deviations, law: &CollisionLaw, a_deg: f64, b_deg: f64, n: usize) -> Vec<Rebound> {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(
        (a_deg * 1000.0) as i64 as u64 ^ ((b_deg * 7.0) as u64) << 20,
    );
    let u = velocity_from_angles(6.0, a_deg.to_radians(), b_deg.to_radians());
    (0..n)
        .map(|_| rebound(u, Vector3::zeros(), wall, law, 2.0, D, &mut rng))
        .collect()
}

fn dbeta(r: &Rebound, b_deg: f64) -> f64 {
    wrap_pi(incident_angles(&r.velocity).1 - b_deg.to_radians())
}

fn mean_std(xs: impl Iterator<Item = f64>) -> (f64, f64, usize) {
    let v: Vec<f64> = xs.collect();
    let n = v.len() as f64;
    let m = v.iter().sum::<f64>() / n;
    let s = (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    (m, s, v.len())
}

#[test]
fn isotropic_wall_has_zero_mean_transverse_deviation() {
    let wall = dev(3.8, 3.8);
    for law in [CollisionLaw::Elastic, sh()] {
        for b in [0.0, 30.0, 60.0, 90.0, 135.0] {
            let out = run(&wall, &law, -15.0, b, 40_000);
            let (m, s, n) = mean_std(out.iter().map(|r| dbeta(r, b)));
            assert!(
                m.abs() < 4.5 * s / (n as f64).sqrt(),
                "β⁻={b}: mean {m} (se {})",
                s / (n as f64).sqrt()
            );
        }
    }
}

#[test]
fn two_d_wall_at_beta_zero_gives_exactly_zero_transverse_deviation() {
    let wall = dev(3.8, 0.0);
    for law in [CollisionLaw::Elastic, sh()] {
        for a in [-0.01, -5.0, -25.0, -89.0] {
            for r in run(&wall, &law, a, 0.0, 5_000) {
                assert_eq!(r.velocity.z, 0.0);
                assert_eq!(r.gamma_star, 0.0);
                // In the incident plane: forward (0) or, near normal incidence, backward (180°).
                let db = dbeta(&r, 0.0);
                assert!(
                    db == 0.0 || (a < -45.0 && db == std::f64::consts::PI),
                    "{db}"
                );
            }
        }
    }
}

#[test]
fn smooth_wall_is_specular_for_the_elastic_law() {
    let wall = dev(0.0, 0.0);
    for (a, b) in [(-0.01, 0.0), (-12.5, 60.0), (-90.0, 0.0), (-45.0, -170.0)] {
        for r in run(&wall, &CollisionLaw::Elastic, a, b, 10) {
            let (ao, bo) = incident_angles(&r.velocity);
            assert!((ao - (-a).to_radians()).abs() < 1e-12);
            if a > -90.0 {
                assert!(wrap_pi(bo - b.to_radians()).abs() < 1e-12);
            }
            assert_eq!(r.tries, 1);
        }
    }
}

#[test]
fn without_shadow_effect_gamma_pair_has_the_moments_of_eq26() {
    // |α⁻| = 85° ≫ Δγ: (γ, γ*) bivariate normal with the moments of Eq. (26). The shadow
    // factor sin(γ − α⁻) shifts the mean by Δγ² cot 85° (< 0.7 % of Δγ here) and changes
    // the variance by ~Δγ² csc² 85° < 0.6 %.
    for (wall, b) in [
        (dev(2.5, 7.5), 30.0),
        (dev(7.5, 2.5), 60.0),
        (dev(3.8, 7.5), 135.0),
    ] {
        let out = run(&wall, &CollisionLaw::Elastic, -85.0, b, 100_000);
        let m = rotated_moments(&wall, f64::to_radians(b));
        let n = out.len() as f64;
        let (mg, vg) = (
            out.iter().map(|r| r.first.gamma).sum::<f64>() / n,
            out.iter().map(|r| r.first.gamma.powi(2)).sum::<f64>() / n,
        );
        let vs = out.iter().map(|r| r.first.gamma_star.powi(2)).sum::<f64>() / n;
        let cov = out
            .iter()
            .map(|r| r.first.gamma * r.first.gamma_star)
            .sum::<f64>()
            / n;
        let scale = m.var_a.max(m.var_b);
        assert!(mg.abs() < 0.02 * m.var_a.sqrt(), "mean γ {mg}");
        assert!(
            (vg / m.var_a - 1.0).abs() < 0.03,
            "Var γ {vg} vs {}",
            m.var_a
        );
        assert!(
            (vs / m.var_b - 1.0).abs() < 0.03,
            "Var γ* {vs} vs {}",
            m.var_b
        );
        assert!((cov - m.cov).abs() < 0.03 * scale, "Cov {cov} vs {}", m.cov);
    }
}

#[test]
fn gamma_star_given_gamma_follows_eq30() {
    // Within a thin slice of γ, γ* has mean Cov/Δγ² γ and variance Δγ*² − Cov²/Δγ².
    let wall = dev(2.5, 7.5);
    let b = 30.0f64;
    let m = rotated_moments(&wall, f64::to_radians(b));
    let out = run(&wall, &CollisionLaw::Elastic, -12.5, b, 200_000);
    let sd = m.var_a.sqrt();
    for g0 in [-1.0, 0.0, 1.0, 2.0] {
        let g0 = g0 * sd;
        let sel: Vec<f64> = out
            .iter()
            .filter(|r| (r.first.gamma - g0).abs() < 0.05 * sd)
            .map(|r| r.first.gamma_star - m.cov / m.var_a * (r.first.gamma - g0))
            .collect();
        let (mean, std, k) = mean_std(sel.into_iter());
        let cmean = m.cov / m.var_a * g0;
        let cvar = m.var_b - m.cov * m.cov / m.var_a;
        let se = std / (k as f64).sqrt();
        assert!(k > 1000, "{k}");
        assert!((mean - cmean).abs() < 4.5 * se, "γ={g0}: {mean} vs {cmean}");
        assert!(
            (std * std / cvar - 1.0).abs() < 0.1,
            "γ={g0}: {} vs {cvar}",
            std * std
        );
    }
}

#[test]
fn rho_plus_minus_one_makes_gamma_star_a_linear_function_of_gamma() {
    // Δζ = 0, β⁻ = ±60°: ρ = ±1, Var(γ*|γ) = 0 and γ* = tan β⁻ · γ (Eq. 30).
    let wall = dev(3.8, 0.0);
    for b in [60.0f64, -60.0] {
        let m = rotated_moments(&wall, f64::to_radians(b));
        let rho = m.cov / (m.var_a * m.var_b).sqrt();
        assert!((rho.abs() - 1.0).abs() < 1e-12);
        for r in run(&wall, &sh(), -15.0, b, 5_000) {
            let expect = b.to_radians().tan() * r.gamma;
            assert!((r.gamma_star - expect).abs() < 1e-8);
            assert!(r.velocity.iter().all(|c| c.is_finite()));
        }
    }
}

#[test]
fn beta60_mean_transverse_deviation_has_the_papers_sign() {
    // Sec. 4.2, Figs. 16–17: at β⁻ = 60° the mean β⁺ − β⁻ is negative for Δξ < Δζ,
    // positive for Δξ > Δζ and for 2-D roughness (Δζ = 0); a few degrees at α⁻ = −25°.
    for a in [-5.0, -15.0, -25.0, -45.0] {
        let m = |wall: Deviations| {
            let out = run(&wall, &sh(), a, 60.0, 40_000);
            let (m, s, n) = mean_std(out.iter().map(|r| dbeta(r, 60.0)));
            (m.to_degrees(), (s / (n as f64).sqrt()).to_degrees())
        };
        let (hra, se1) = m(dev(3.8, 7.5));
        let (two_d, se2) = m(dev(3.8, 0.0));
        let (inv, se3) = m(dev(7.5, 2.5));
        assert!(hra < -4.0 * se1, "α⁻={a}: HRA mean {hra}");
        assert!(two_d > 4.0 * se2, "α⁻={a}: 2-D mean {two_d}");
        assert!(inv > 4.0 * se3, "α⁻={a}: Δξ>Δζ mean {inv}");
        if a == -25.0 {
            assert!((1.0..5.0).contains(&-hra), "HRA at −25°: {hra}");
            assert!((0.2..5.0).contains(&two_d), "2-D at −25°: {two_d}");
        }
    }
}

#[test]
fn elastic_conserves_speed_and_sommerfeld_huber_never_gains_energy() {
    let wall = dev(3.8, 7.5);
    let mass_free_energy = |u: &Vector3<f64>, w: &Vector3<f64>| {
        // E/m = |U|²/2 + I|ω|²/2m with I = m D²/10 (solid sphere).
        0.5 * u.norm_squared() + 0.5 * D * D / 10.0 * w.norm_squared()
    };
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(9);
    for a in [-0.5, -5.0, -25.0, -60.0] {
        for b in [0.0, 60.0, 170.0] {
            let u = velocity_from_angles(6.0, f64::to_radians(a), f64::to_radians(b));
            let spin = Vector3::new(300.0, -50.0, 800.0);
            for _ in 0..2000 {
                let r = rebound(u, spin, &wall, &CollisionLaw::Elastic, 2.0, D, &mut rng);
                assert!((r.velocity.norm() - 6.0).abs() < 1e-12);
                assert_eq!(r.spin, spin);
                let s = rebound(u, spin, &wall, &sh(), 2.0, D, &mut rng);
                let (e0, e1) = (
                    mass_free_energy(&u, &spin),
                    mass_free_energy(&s.velocity, &s.spin),
                );
                assert!(e1 <= e0 * (1.0 + 1e-12), "energy gain {e0} → {e1}");
                // The same vector-form law as `deterministic`: one implementation.
                let (uc, wc) = sh().collide(u, spin, s.normal, D);
                assert_eq!((uc, wc), (s.velocity, s.spin));
                assert!(s.velocity.y > 0.0 && s.tries >= 1 && s.tries < MAX_TRIES);
            }
        }
    }
}

#[test]
fn hard_cases_give_finite_rebounds_quickly() {
    let walls = [
        dev(0.0, 0.0),
        dev(3.8, 0.0),
        dev(0.0, 3.8),
        dev(3.8, 7.5),
        dev(20.0, 20.0),
        dev(20.0, 0.0),
    ];
    for wall in walls {
        for law in [CollisionLaw::Elastic, sh()] {
            for (a, b) in [
                (-0.01, 0.0),
                (-0.01, 90.0),
                (-0.01, 60.0),
                (-90.0, 0.0),
                (-45.0, 90.0),
                (-45.0, 180.0),
                (-0.5, -90.0),
            ] {
                let out = run(&wall, &law, a, b, 3000);
                let tries: u64 = out.iter().map(|r| r.tries as u64).sum();
                assert!(tries < 3000 * 20, "{wall:?} {a} {b}: {tries} tries");
                for r in out {
                    assert!(r.velocity.iter().all(|c| c.is_finite()));
                    assert!(r.spin.iter().all(|c| c.is_finite()));
                    assert!(r.gamma.is_finite() && r.gamma_star.is_finite());
                    assert!(r.velocity.y > 0.0, "{wall:?} {a} {b}: {:?}", r.velocity);
                    assert!(r.tries < MAX_TRIES);
                }
            }
        }
    }
    // Not moving towards the wall: returned unchanged, no candidate drawn.
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(1);
    let up = Vector3::new(1.0, 0.5, 0.0);
    let r = rebound(
        up,
        Vector3::zeros(),
        &dev(3.8, 3.8),
        &sh(),
        2.0,
        D,
        &mut rng,
    );
    assert_eq!((r.velocity, r.tries), (up, 0));
    let nan = Vector3::new(f64::NAN, -1.0, 0.0);
    let r = rebound(
        nan,
        Vector3::zeros(),
        &dev(3.8, 3.8),
        &sh(),
        2.0,
        D,
        &mut rng,
    );
    assert_eq!(r.tries, 0);
}

#[test]
fn first_wall_seen_follows_the_shadow_effect_law() {
    // Figs. 10: γ of the first wall seen follows P_eff(γ | α⁻) (Eqs. 31–33); the exact 3-D
    // visibility test U⁻·n < 0 (step 4) removes almost nothing beyond it.
    use roughwall::stochastic::bin_probability;
    for (wall, a, b) in [(dev(2.5, 7.5), -2.5, 0.0), (dev(3.8, 7.5), -5.0, 60.0)] {
        let out = run(&wall, &sh(), a, b, 40_000);
        let dg = rotated_moments(&wall, f64::to_radians(b)).var_a.sqrt();
        let mut g: Vec<f64> = out.iter().map(|r| r.first.gamma).collect();
        g.sort_by(|x, y| x.total_cmp(y));
        let n = g.len() as f64;
        let mut ks: f64 = 0.0;
        for k in 0..=60 {
            let x = f64::to_radians(a) + k as f64 * 0.2 * dg;
            let model = bin_probability(-1.0, x, f64::to_radians(a), dg);
            let emp = g.partition_point(|v| *v <= x) as f64 / n;
            ks = ks.max((model - emp).abs());
        }
        assert!(ks < 0.012, "α⁻={a} β⁻={b}: KS {ks}");
    }
}
