//! Issue 5, "Correctness it must show": the four force models of `rebound force-sweep`.
use roughwall::force::{hertz_dynamic, hertz_sphere, hu2021, material, Impact, Model, Particle};

const ALL: [Model; 4] = Model::ALL;
const SPHEROID_MODELS: [Model; 3] = [Model::Hu2021, Model::HertzRigid, Model::HertzDynamic];

/// Hu et al. 2021, Fig. 6 particle (figure captions: E = 64 GPa).
fn glass() -> Particle {
    Particle {
        density: 2500.0,
        youngs: 64e9,
        poisson: 0.24,
        diameter: 2.45e-6,
    }
}

fn f(model: Model, p: &Particle, lambda: f64, beta_deg: f64, u_n: f64) -> f64 {
    model
        .evaluate(p, &Impact::from_deg(lambda, beta_deg, u_n).unwrap())
        .unwrap()
        .f_max
}

fn models_for(lambda: f64) -> Vec<Model> {
    if lambda == 1.0 {
        ALL.to_vec()
    } else {
        SPHEROID_MODELS.to_vec()
    }
}

/// F_max ∝ U_N^1.2, D², ρ^0.6, [E/(1−σ²)]^0.4 — exactly for the closed-form models (they are
/// ξ(λ, β) × the scale of Eq. 7 by construction).
#[test]
fn scaling_exponents_closed_form_models() {
    let p = glass();
    for (lambda, beta) in [(1.0, 30.0), (1.5, 0.0), (2.0, 45.0), (3.0, 80.0)] {
        for m in models_for(lambda)
            .into_iter()
            .filter(|m| *m != Model::HertzDynamic)
        {
            let base = f(m, &p, lambda, beta, 0.1);
            let rel = |x: f64, y: f64| (x / y - 1.0).abs();
            assert!(
                rel(f(m, &p, lambda, beta, 0.3), base * 3f64.powf(1.2)) < 1e-12,
                "{m:?} U"
            );
            let pd = Particle {
                diameter: 3.0 * p.diameter,
                ..p
            };
            assert!(
                rel(f(m, &pd, lambda, beta, 0.1), base * 9.0) < 1e-12,
                "{m:?} D"
            );
            let pr = Particle {
                density: 3.0 * p.density,
                ..p
            };
            assert!(
                rel(f(m, &pr, lambda, beta, 0.1), base * 3f64.powf(0.6)) < 1e-12,
                "{m:?} ρ"
            );
            let pe = Particle {
                youngs: 3.0 * p.youngs,
                ..p
            };
            assert!(
                rel(f(m, &pe, lambda, beta, 0.1), base * 3f64.powf(0.4)) < 1e-12,
                "{m:?} E"
            );
            // σ enters through E/(1−σ²) only.
            let ps = Particle { poisson: 0.4, ..p };
            let ratio = ((1.0 - 0.24f64.powi(2)) / (1.0 - 0.16)).powf(0.4);
            assert!(
                rel(f(m, &ps, lambda, beta, 0.1), base * ratio) < 1e-12,
                "{m:?} σ"
            );
        }
    }
}

/// `hertz-dynamic`: exact in D (the contact is geometrically similar) and exact in
/// U_N, ρ, E* at β = 0°, 90° and for spheres (no rotation). For tilted spheroids the body turns
/// by O(δ/a) during the contact, so ξ depends weakly on Π = ρU_N²/E*: changes that keep Π fixed
/// leave ξ unchanged exactly, and the U_N exponent is 1.2 up to that O(δ/a) effect.
#[test]
fn scaling_exponents_dynamic_model() {
    let m = Model::HertzDynamic;
    let p = glass();
    let rel = |x: f64, y: f64| (x / y - 1.0).abs();
    for (lambda, beta) in [
        (1.0, 30.0),
        (2.0, 0.0),
        (3.0, 90.0),
        (2.0, 45.0),
        (3.0, 30.0),
    ] {
        let base = f(m, &p, lambda, beta, 0.1);
        let pd = Particle {
            diameter: 3.0 * p.diameter,
            ..p
        };
        assert!(
            rel(f(m, &pd, lambda, beta, 0.1), base * 9.0) < 1e-9,
            "D at λ={lambda} β={beta}"
        );
        // ρ × 4 with U_N / 2 keeps Π: F scales with 4^0.6 · 2^−1.2 = 1 exactly.
        let pr = Particle {
            density: 4.0 * p.density,
            ..p
        };
        assert!(
            rel(f(m, &pr, lambda, beta, 0.05), base) < 1e-9,
            "Π at λ={lambda} β={beta}"
        );
        // E × 4 with U_N × 2 keeps Π: F scales with 4^0.4 · 2^1.2 = 4.
        let pe = Particle {
            youngs: 4.0 * p.youngs,
            ..p
        };
        assert!(
            rel(f(m, &pe, lambda, beta, 0.2), 4.0 * base) < 1e-9,
            "Π·E at λ={lambda} β={beta}"
        );
        let exponent = (f(m, &p, lambda, beta, 0.2) / base).ln() / 2f64.ln();
        let no_rotation = lambda == 1.0 || beta == 0.0 || beta == 90.0;
        let tol = if no_rotation { 1e-7 } else { 1e-3 };
        assert!(
            (exponent - 1.2).abs() < tol,
            "U exponent {exponent} at λ={lambda} β={beta}"
        );
    }
}

/// λ = 1: every model equals Eq. (3) (`hertz-sphere`) at every β.
#[test]
fn sphere_equalities() {
    for p in [
        glass(),
        Particle {
            density: 2560.0,
            youngs: 80e9,
            poisson: 0.22,
            diameter: 3.29e-6,
        },
    ] {
        for u in [0.0457, 1.0, 20.0] {
            let eq3 = hertz_sphere::XI_SPHERE * p.force_scale(u);
            for beta in [0.0, 33.0, 90.0] {
                for m in ALL {
                    let v = f(m, &p, 1.0, beta, u);
                    assert!(
                        (v / eq3 - 1.0).abs() < 1e-6,
                        "{m:?} β={beta} U={u}: {v} vs {eq3}"
                    );
                }
            }
        }
    }
}

/// At β = 0° and 90° the lever arm vanishes: rigid and dynamic agree.
#[test]
fn rigid_and_dynamic_agree_at_zero_lever_arm() {
    for lambda in [1.5, 2.0, 3.0, 7.0] {
        for beta in [0.0, 90.0] {
            for u in [0.0457, 5.0] {
                let r = f(Model::HertzRigid, &glass(), lambda, beta, u);
                let d = f(Model::HertzDynamic, &glass(), lambda, beta, u);
                assert!((d / r - 1.0).abs() < 1e-6, "λ={lambda} β={beta}: {r} {d}");
            }
        }
    }
}

/// Hu et al. 2021, Fig. 6 / Sec. 4: F_max has its minimum near β = 45° for λ = 2 and 3
/// (all three spheroid models), and is largest lying flat.
#[test]
fn minimum_near_45_degrees() {
    for lambda in [2.0, 3.0] {
        for m in SPHEROID_MODELS {
            let v: Vec<f64> = (0..=90)
                .map(|b| f(m, &glass(), lambda, b as f64, 0.0457))
                .collect();
            let imin = (0..=90).min_by(|&a, &b| v[a].total_cmp(&v[b])).unwrap();
            assert!(
                (38..=52).contains(&imin),
                "{m:?} λ={lambda}: minimum at {imin}°"
            );
            assert!(
                v[0] > v[90] && v[0] == v.iter().cloned().fold(0.0, f64::max),
                "{m:?} λ={lambda}"
            );
        }
    }
}

/// Hu et al. 2021, Eq. (7)–(8) through the model interface, against a hand evaluation.
#[test]
fn hu2021_force_from_eq7_and_eq8() {
    let p = glass();
    // λ = 3, β = 10°: ξ = 0.9087 − 0.377 + 0.081284 − 0.0066192 + 0.00019372 = 0.60655852
    let scale = 2500f64.powf(0.6)
        * 0.0457f64.powf(1.2)
        * 2.45e-6f64.powi(2)
        * (64e9_f64 / (1.0 - 0.0576)).powf(0.4);
    let v = f(Model::Hu2021, &p, 3.0, 10.0, 0.0457);
    assert!((v / (0.60655852 * scale) - 1.0).abs() < 1e-12, "{v}");
    assert_eq!(hu2021::xi(2.0, 0.0).unwrap(), 0.82837);
}

/// U_N = 0: zero force, finite ξ, no contact time — never NaN.
#[test]
fn zero_speed() {
    for lambda in [1.0, 1.5, 2.0, 3.0] {
        for m in models_for(lambda) {
            for beta in [0.0, 45.0, 90.0] {
                let r = m
                    .evaluate(&glass(), &Impact::from_deg(lambda, beta, 0.0).unwrap())
                    .unwrap();
                assert_eq!(r.f_max, 0.0);
                assert!(r.xi.is_finite() && r.xi > 0.0);
                assert_eq!(r.contact_time, None);
            }
        }
    }
}

/// Contact times where the model has one; the dynamic one converges to the rigid one at β = 0.
#[test]
fn contact_times() {
    let imp = Impact::from_deg(2.0, 0.0, 0.0457).unwrap();
    let r = Model::HertzRigid
        .evaluate(&glass(), &imp)
        .unwrap()
        .contact_time
        .unwrap();
    let d = Model::HertzDynamic
        .evaluate(&glass(), &imp)
        .unwrap()
        .contact_time
        .unwrap();
    assert!(
        (d / r - 1.0).abs() < 1e-6 && r > 1e-9 && r < 1e-7,
        "{r} {d}"
    );
    assert_eq!(
        Model::Hu2021.evaluate(&glass(), &imp).unwrap().contact_time,
        None
    );
}

/// Micrometre glass (ns contacts) and 5 mm steel (µs contacts) converge alike.
#[test]
fn dynamic_converges_at_both_scales() {
    let steel = Particle {
        density: 7850.0,
        youngs: 210e9,
        poisson: 0.3,
        diameter: 5e-3,
    };
    for p in [glass(), steel] {
        let imp = Impact::from_deg(3.0, 40.0, 2.0).unwrap();
        let fine = hertz_dynamic::simulate(
            &p,
            &imp,
            &hertz_dynamic::Options {
                steps_per_contact: 2000,
            },
        );
        let dflt = hertz_dynamic::simulate(&p, &imp, &hertz_dynamic::Options::default());
        assert!((dflt.f_max / fine.f_max - 1.0).abs() < 1e-6);
        assert!((dflt.contact_time.unwrap() / fine.contact_time.unwrap() - 1.0).abs() < 1e-6);
    }
}

/// Bad input is a one-line `Error::Input` with a clear message.
#[test]
fn errors() {
    let one_line = |e: roughwall::Error| {
        let s = e.to_string();
        assert!(
            matches!(e, roughwall::Error::Input(_)) && !s.contains('\n'),
            "{s}"
        );
        s
    };
    for beta in [-1.0, 90.5, f64::NAN] {
        assert!(one_line(Impact::from_deg(2.0, beta, 1.0).unwrap_err()).contains("beta_deg"));
    }
    assert!(one_line(Impact::from_deg(0.5, 10.0, 1.0).unwrap_err()).contains("oblate"));
    assert!(one_line(Impact::from_deg(2.0, 10.0, -1.0).unwrap_err()).contains("u_n_m_s"));
    assert!(one_line(Model::from_name("dem").unwrap_err()).contains("dem"));
    assert!(one_line(material::preset("impactor.preset", "steel").unwrap_err()).contains("steel"));
    let imp = Impact::from_deg(2.5, 10.0, 1.0).unwrap();
    assert!(one_line(Model::Hu2021.evaluate(&glass(), &imp).unwrap_err()).contains("hertz-rigid"));
    assert!(
        one_line(Model::HertzSphere.evaluate(&glass(), &imp).unwrap_err()).contains("hertz-rigid")
    );
    let bad = Particle {
        poisson: 0.7,
        ..glass()
    };
    assert!(one_line(Model::HertzRigid.evaluate(&bad, &imp).unwrap_err()).contains("poisson"));
}

/// Extreme but valid speeds and sizes (docs/physics.md §9): finite numbers out, never NaN; and
/// speeds outside the physical range (0, or 1e-6 … 1e4 m/s) refused rather than computed.
#[test]
fn extreme_inputs_stay_finite() {
    for u in [1e-300, 1e-20, 5e-7, 1.1e4, 1e308] {
        assert!(Impact::from_deg(2.0, 45.0, u).is_err(), "U = {u}");
    }
    let tiny = Particle {
        diameter: 1e-9,
        ..glass()
    };
    let huge = Particle {
        diameter: 1.0,
        density: 20_000.0,
        ..glass()
    };
    for p in [glass(), tiny, huge] {
        for u in [0.0, 1e-6, 1e-3, 100.0, 1e4] {
            for lambda in [1.0, 1.5, 3.0, 10.0] {
                for beta in [0.0, 0.5, 45.0, 89.9, 90.0] {
                    for m in models_for(lambda) {
                        if m == Model::Hu2021 && lambda == 10.0 {
                            continue;
                        }
                        let r = m
                            .evaluate(&p, &Impact::from_deg(lambda, beta, u).unwrap())
                            .unwrap();
                        assert!(
                            r.f_max.is_finite() && r.f_max >= 0.0,
                            "{m:?} U={u} λ={lambda} β={beta}"
                        );
                        assert!(
                            r.xi.is_finite() && r.xi > 0.0,
                            "{m:?} U={u} λ={lambda} β={beta}: ξ={}",
                            r.xi
                        );
                        if u > 0.0 {
                            assert!(r.f_max > 0.0, "{m:?} U={u} λ={lambda} β={beta}");
                        }
                        if let Some(t) = r.contact_time {
                            assert!(t.is_finite() && t >= 0.0, "{m:?} U={u}");
                        }
                    }
                }
            }
        }
    }
}

/// Slender spheroids (beyond Johnson's F₂ range, where the exact elliptic solution takes over):
/// finite forces, rigid and dynamic still agree at zero lever arm.
#[test]
fn slender_spheroids() {
    for lambda in [30.0, 1000.0] {
        for beta in [0.0, 0.5, 30.0, 90.0] {
            let r = f(Model::HertzRigid, &glass(), lambda, beta, 1.0);
            let d = f(Model::HertzDynamic, &glass(), lambda, beta, 1.0);
            assert!(
                r.is_finite() && r > 0.0 && d.is_finite() && d > 0.0,
                "λ={lambda} β={beta}"
            );
            if beta == 0.0 || beta == 90.0 {
                assert!((d / r - 1.0).abs() < 1e-6, "λ={lambda} β={beta}: {r} {d}");
            }
        }
    }
}
