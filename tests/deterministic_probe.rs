mod deterministic_support;
use deterministic_support::*;
use nalgebra::Vector3;
use rebound::deterministic::{simulate, Condition, Fate, SpeedLaw, Tracker};

fn reflect(u: Vector3<f64>, w: Vector3<f64>, n: Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    (u - 2.0 * u.dot(&n) * n, w)
}

#[test]
#[ignore]
fn probe() {
    for (dxi, dze) in [(2.5f64, 7.5f64), (7.5, 2.5)] {
        let h = 1.0;
        let cx = 2f64.sqrt() * h / dxi.to_radians();
        let cz = 2f64.sqrt() * h / dze.to_radians();
        let d = cx.min(cz) / 8.0;
        let n = 1200;
        let t0 = std::time::Instant::now();
        let f = gaussian_surface(n, d, h, Some(cx), Some(cz), 1);
        eprintln!(
            "surface {:?} L/cmax {}",
            t0.elapsed(),
            n as f64 * d / cx.max(cz)
        );
        let tr = Tracker::new(&f, 1000).unwrap();
        for (ci, (a, b)) in [
            (-2.5f64, 0f64),
            (-2.5, 60.0),
            (-12.5, 0.0),
            (-12.5, 60.0),
            (-32.5, 0.0),
            (-32.5, 60.0),
        ]
        .iter()
        .enumerate()
        {
            let t0 = std::time::Instant::now();
            let hs = simulate(
                &tr,
                &reflect,
                Condition {
                    index: ci as u64,
                    alpha: a.to_radians(),
                    beta: b.to_radians(),
                },
                100000,
                7,
                SpeedLaw::Unit,
            );
            let el = t0.elapsed();
            let lost = hs.iter().filter(|h| h.fate != Fate::Escaped).count();
            let ao: Vec<f64> = hs
                .iter()
                .map(|h| angles(&h.velocity).0.to_degrees())
                .collect();
            let db: Vec<f64> = hs
                .iter()
                .map(|h| wrap(angles(&h.velocity).1 - b.to_radians()).to_degrees())
                .collect();
            let db1: Vec<f64> = hs
                .iter()
                .map(|h| wrap(angles(&h.first_velocity).1 - b.to_radians()).to_degrees())
                .collect();
            let xi: Vec<f64> = hs
                .iter()
                .map(|h| -h.first_normal.x.asin().to_degrees())
                .collect();
            let ze: Vec<f64> = hs
                .iter()
                .map(|h| -h.first_normal.z.asin().to_degrees())
                .collect();
            let single = hs.iter().filter(|h| h.collisions == 1).count() as f64 / hs.len() as f64;
            let mc = hs.iter().map(|h| h.collisions as f64).sum::<f64>() / hs.len() as f64;
            eprintln!(
                "({dxi},{dze}) a {a} b {b}: lost {lost} mean a+ {:.3} dbeta {:.3}±{:.3} dbeta1 {:.3} std {:.3}/{:.3} xi std {:.3} zeta std {:.3} p1 {:.3} mc {:.3} {:.0}/s",
                mean_se(&ao).0, mean_se(&db).0, mean_se(&db).1, mean_se(&db1).0, std(&db), std(&db1), std(&xi), std(&ze), single, mc,
                1e5 / el.as_secs_f64()
            );
        }
    }
}
