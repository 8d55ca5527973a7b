//! Hard cases of docs/physics.md §9 for the deterministic tracker, and thread-count
//! independence of its tallies.

use crate::common::deterministic::*;
use roughwall::deterministic::ConditionRun;
use roughwall::HeightField;
use roughwall::SpeedLaw;
use roughwall::Tracker;
use roughwall::{CollisionLaw, ShParams};
use std::time::Instant;

fn laws() -> [CollisionLaw; 2] {
    [
        CollisionLaw::Elastic,
        CollisionLaw::SommerfeldHuber(ShParams::glass_steel()),
    ]
}

const GS_SPEED: SpeedLaw = SpeedLaw::horizontal(5.91, 1.16);

/// Every summary cell and PDF value of a condition is a finite number.
fn assert_finite(r: &ConditionRun, what: &str) {
    assert_eq!(r.lost.total(), 0, "{what}: {}", r.lost.describe());
    let t = r.tally(1.0);
    // Every summary quantity is there (no erosion is tallied) and finite.
    let summary = format!("{:?}", t.summary).replace("erosion: None", "");
    for bad in ["NaN", "inf", "None"] {
        assert!(!summary.contains(bad), "{what}: {bad} in {summary}");
    }
    for pdf in &t.pdfs {
        let q = pdf.quantity;
        assert!(!pdf.bins.is_empty(), "{what}: empty {q:?}");
        assert!(
            pdf.bins
                .iter()
                .all(|b| b.value.is_finite() && b.lo.is_finite()),
            "{what}: {q:?}"
        );
    }
}

#[test]
fn grazing_and_normal_incidence_on_a_rough_wall() {
    let f = wall(2.5, 7.5, 8.0, 40.0, 11);
    let t = Tracker::new(&f, 1000).unwrap();
    let dv = dev(2.5, 7.5);
    for law in laws() {
        for (k, (a, b)) in [(-0.01, 0.0), (-0.01, 60.0), (-0.01, 90.0), (-90.0, 0.0)]
            .into_iter()
            .enumerate()
        {
            let t0 = Instant::now();
            let r = run(&t, &law, &dv, a, b, k as u64, 5000, GS_SPEED);
            assert!(t0.elapsed().as_secs_f64() < 20.0, "a {a}: too slow");
            assert_finite(&r, &format!("{law:?} a {a} b {b}"));
            if matches!(law, CollisionLaw::Elastic) {
                assert!(r
                    .outcomes
                    .iter()
                    .all(|o| (o.speed_ratio - 1.0).abs() < 1e-12));
            }
        }
    }
}

#[test]
fn flat_wall_is_a_mirror_for_the_elastic_law() {
    let f = HeightField {
        nx: 16,
        nz: 16,
        dx: 1e-6,
        dz: 1e-6,
        heights: vec![0.0; 256],
        triangulation: Default::default(),
    };
    let t = Tracker::new(&f, 1000).unwrap();
    let dv = dev(0.0, 0.0);
    for law in laws() {
        for (k, a) in [-0.01, -12.5, -90.0].into_iter().enumerate() {
            let r = run(&t, &law, &dv, a, 30.0, k as u64, 1000, GS_SPEED);
            assert_finite(&r, &format!("flat {law:?} a {a}"));
            for o in &r.outcomes {
                assert_eq!(o.collisions, Some(1));
                if matches!(law, CollisionLaw::Elastic) {
                    assert!((o.alpha_out.to_degrees() + a).abs() < 1e-9);
                    if a > -90.0 {
                        assert!(o.dbeta.abs() < 1e-12);
                    }
                }
            }
        }
    }
}

#[test]
fn two_d_roughness_at_the_hard_angles() {
    let f = wall(3.8, 0.0, 8.0, 40.0, 12);
    let t = Tracker::new(&f, 1000).unwrap();
    let dv = dev(3.8, 0.0);
    for law in laws() {
        for (k, (a, b)) in [
            (-0.01, 0.0),
            (-0.01, 90.0),
            (-15.0, 0.0),
            (-15.0, 90.0),
            (-90.0, 0.0),
        ]
        .into_iter()
        .enumerate()
        {
            let r = run(&t, &law, &dv, a, b, k as u64, 5000, GS_SPEED);
            assert_finite(&r, &format!("2-D {law:?} a {a} b {b}"));
        }
    }
}

#[test]
fn outputs_are_identical_for_any_thread_count() {
    let f = wall(2.5, 7.5, 8.0, 20.0, 13);
    let t = Tracker::new(&f, 1000).unwrap();
    let dv = dev(2.5, 7.5);
    let bytes = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let results: Vec<_> = [(-2.5, 60.0), (-32.5, 0.0)]
                .into_iter()
                .enumerate()
                .map(|(k, (a, b))| {
                    run(
                        &t,
                        &CollisionLaw::SommerfeldHuber(ShParams::glass_steel()),
                        &dv,
                        a,
                        b,
                        k as u64,
                        3000,
                        GS_SPEED,
                    )
                    .tally(1.0)
                })
                .collect();
            // `{:?}` writes every f64 so that it reads back to the same bits.
            format!("{results:?}")
        })
    };
    let one = bytes(1);
    let two = bytes(2);
    let three = bytes(3);
    assert!(one == two && two == three);
}
