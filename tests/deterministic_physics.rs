//! Physics of `rebound deterministic` (Radenkovic & Simonin 2021, Sec. 3.1–3.5):
//! invariants, symmetries and the paper's findings on the two walls of Sec. 3.
//! CI-sized: walls of ~40 correlation lengths, 10⁴ particles per condition.

mod deterministic_support;
use deterministic_support::*;
use rebound::collision::{CollisionLaw, ShParams};
use rebound::deterministic::{ConditionRun, Tracker};
use rebound::wall::delta_gamma;

const N: usize = 10_000;

fn stats(run: &ConditionRun, f: impl Fn(&rebound::tally::Outcome) -> f64) -> (f64, f64, f64) {
    let v: Vec<f64> = run.outcomes.iter().map(|o| f(o).to_degrees()).collect();
    let (m, se) = mean_se(&v);
    (m, se, std(&v))
}

/// The two walls of Sec. 3 and the four β⁻ at α⁻ = −2.5°, −12.5°, −32.5°.
fn sec3(dxi: f64, dze: f64, seed: u64) -> Vec<(f64, f64, ConditionRun)> {
    let f = wall(dxi, dze, 8.0, 40.0, seed);
    let t = Tracker::new(&f, 1000).unwrap();
    let dv = dev(dxi, dze);
    let mut out = Vec::new();
    let mut k = 0;
    for a in [-2.5, -12.5, -32.5] {
        for b in [0.0, 60.0, 90.0, -60.0] {
            out.push((a, b, run(&t, &CollisionLaw::Elastic, &dv, a, b, k, N, UNIT)));
            k += 1;
        }
    }
    out
}

fn find(rs: &[(f64, f64, ConditionRun)], a: f64, b: f64) -> &ConditionRun {
    &rs.iter().find(|r| r.0 == a && r.1 == b).unwrap().2
}

#[test]
fn sec3_walls_reproduce_the_papers_findings() {
    let w1 = sec3(2.5, 7.5, 1);
    let w2 = sec3(7.5, 2.5, 2);
    for (name, ws, dv) in [
        ("(2.5, 7.5)", &w1, dev(2.5, 7.5)),
        ("(7.5, 2.5)", &w2, dev(7.5, 2.5)),
    ] {
        for (a, b, r) in ws.iter() {
            // Ideal elastic: nothing lost, |U⁺| = |U⁻| to 1e-12 after any number of collisions.
            assert_eq!(r.lost.total(), 0, "{name} a {a} b {b}");
            assert_eq!(r.outcomes.len(), N);
            for o in &r.outcomes {
                assert!((o.speed_ratio - 1.0).abs() < 1e-12);
                assert!(o.alpha_out > 0.0);
            }
            let (ma, _, _) = stats(r, |o| o.alpha_out);
            if *a == -2.5 {
                // Low incidence: mean α⁺ larger than |α⁻| (Sec. 3.2).
                assert!(ma > 2.5, "{name} a {a} b {b}: mean α⁺ {ma}");
            }
            if *a == -32.5 {
                // Large incidence: α⁺ ≈ |α⁻|, shifted to second order by the shadow
                // effect (+2Δγ² cot|α⁻|, Eqs. 31–32) and the transverse tilt (−2Δγ*² tan|α⁻|).
                let br = b.to_radians();
                let dg = delta_gamma(&dv, br);
                let dgs = delta_gamma(&dv, br + std::f64::consts::FRAC_PI_2);
                let ar = 32.5f64.to_radians();
                let pred =
                    (ar + 2.0 * dg * dg / ar.tan() - 2.0 * dgs * dgs * ar.tan()).to_degrees();
                assert!(
                    (ma - pred).abs() < 0.5,
                    "{name} b {b}: mean α⁺ {ma}, predicted {pred}"
                );
            }
            // Fig. 7: first and final transverse deviations have nearly the same PDF.
            let (m1, _, s1) = stats(r, |o| o.dbeta_first.unwrap());
            let (m2, _, s2) = stats(r, |o| o.dbeta);
            assert!(
                (m1 - m2).abs() < 0.25 && (s1 / s2 - 1.0).abs() < 0.05,
                "{name} a {a} b {b}: {m1} {s1} vs {m2} {s2}"
            );
        }
        // The literal claim of Sec. 3.2 where the in-plane deviation is small.
        let (ma, _, _) = stats(
            find(ws, -32.5, if name == "(2.5, 7.5)" { 0.0 } else { 60.0 }),
            |o| o.alpha_out,
        );
        assert!((ma - 32.5).abs() < 1.5, "{name}: mean α⁺ {ma}");
        // Sec. 3.3: at α⁻ = −32.5°, β⁻ = 0° the first normal seen has std ≈ (Δξ, Δζ).
        let r = find(ws, -32.5, 0.0);
        let (_, _, sx) = stats(r, |o| o.xi_first);
        let (_, _, sz) = stats(r, |o| o.zeta_first);
        assert!(
            (sx / dv.delta_xi.to_degrees() - 1.0).abs() < 0.1,
            "{name}: std ξ {sx}"
        );
        assert!(
            (sz / dv.delta_zeta.to_degrees() - 1.0).abs() < 0.1,
            "{name}: std ζ {sz}"
        );
    }
    // Sec. 3.2: at β⁻ = 60° particles are pushed towards the direction of low roughness.
    for a in [-2.5, -12.5, -32.5] {
        let (m1, se1, _) = stats(find(&w1, a, 60.0), |o| o.dbeta);
        let (m2, se2, _) = stats(find(&w2, a, 60.0), |o| o.dbeta);
        eprintln!("a {a}: mean dbeta at 60°: (2.5, 7.5) {m1:.3} ± {se1:.3}, (7.5, 2.5) {m2:.3} ± {se2:.3}");
        assert!(m1 < -3.0 * se1, "(2.5, 7.5) a {a}: {m1} ± {se1}");
        assert!(m2 > 3.0 * se2, "(7.5, 2.5) a {a}: {m2} ± {se2}");
    }
    for ws in [&w1, &w2] {
        for a in [-2.5, -12.5, -32.5] {
            // Mirror symmetry β⁻ → −β⁻ mirrors dbeta (within the combined standard error).
            let (mp, sep, _) = stats(find(ws, a, 60.0), |o| o.dbeta);
            let (mm, sem, _) = stats(find(ws, a, -60.0), |o| o.dbeta);
            let se = (sep * sep + sem * sem).sqrt();
            assert!((mp + mm).abs() < 3.0 * se, "a {a}: {mp} vs {mm} ± {se}");
            // Along a principal direction the mean deviation vanishes.
            for b in [0.0, 90.0] {
                let (m, se, _) = stats(find(ws, a, b), |o| o.dbeta);
                assert!(m.abs() < 3.0 * se, "a {a} b {b}: mean dbeta {m} ± {se}");
            }
        }
    }
}
