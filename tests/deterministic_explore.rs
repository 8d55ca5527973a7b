mod deterministic_support;
use deterministic_support::*;
use rebound::collision::CollisionLaw;
use rebound::deterministic::{p_single_model, Tracker};

#[test]
#[ignore]
fn explore_fig12() {
    for (dxi, dze, per_c, side) in [(2.5, 7.5, 8.0, 100.0), (7.5, 2.5, 8.0, 100.0)] {
        let f = wall(dxi, dze, per_c, side, 1);
        let t = Tracker::new(&f, 1000).unwrap();
        let dv = dev(dxi, dze);
        for a in [-2.5, -12.5, -32.5] {
            for b in [0.0, 60.0] {
                let r = run(&t, &CollisionLaw::Elastic, &dv, a, b, 0, 40000, UNIT);
                let mut bins = vec![(0u64, 0u64, 0.0f64); 90];
                let cond = rebound::case::IncidentCondition {
                    alpha_in: (a as f64).to_radians(),
                    beta_in: (b as f64).to_radians(),
                };
                let hs = rebound::deterministic::simulate(
                    &t,
                    &|u, w, n| (u - 2.0 * u.dot(&n) * n, w),
                    cond,
                    0,
                    40000,
                    42,
                    &UNIT,
                );
                for h in &hs {
                    let (a1, b1) = rebound::angles::incident_angles(&h.first_velocity);
                    if a1 < 0.0 {
                        continue;
                    }
                    let i = (a1.to_degrees().floor() as usize).min(89);
                    bins[i].0 += 1;
                    bins[i].1 += (h.collisions == 1) as u64;
                    bins[i].2 += p_single_model(&dv, 2.0, a1, b1);
                }
                let _ = &r;
                let line: Vec<String> = bins
                    .iter()
                    .enumerate()
                    .filter(|b| b.1 .0 >= 1000)
                    .map(|(i, &(n, s, m))| {
                        format!("{i}:{:.3}/{:.3}", s as f64 / n as f64, m / n as f64)
                    })
                    .collect();
                eprintln!("({dxi},{dze}) c/{per_c} a {a} b {b}: {}", line.join(" "));
            }
        }
    }
}

#[test]
#[ignore]
fn explore_iso() {
    for per_c in [8.0, 16.0] {
        for seed in [1, 2, 3] {
            let f = wall(5.0, 5.0, per_c, 40.0, seed);
            let t = Tracker::new(&f, 1000).unwrap();
            let dv = dev(5.0, 5.0);
            let mut s = String::new();
            for b in [0.0, 90.0, 45.0, -45.0] {
                let r = run(&t, &CollisionLaw::Elastic, &dv, -5.0, b, 0, 40000, UNIT);
                let v: Vec<f64> = r.outcomes.iter().map(|o| o.dbeta.to_degrees()).collect();
                let (m, se) = mean_se(&v);
                s += &format!(" b {b}: {m:.3}±{se:.3}");
            }
            eprintln!("c/{per_c} seed {seed}:{s}");
        }
    }
}

#[test]
#[ignore]
fn explore_sorting() {
    use rand::Rng;
    use rebound::deterministic::scene::{choose_surface, SceneOptions};
    let c = choose_surface(
        2.5f64.to_radians(),
        7.5f64.to_radians(),
        &SceneOptions::default(),
    )
    .unwrap();
    let f = gaussian_surface(
        c.nodes,
        c.spacing_m,
        c.rms_height_m,
        c.corr_length_x_m,
        c.corr_length_z_m,
        1,
    );
    let t = Tracker::new(&f, 1000).unwrap();
    let (lx, lz) = t.periods();
    let cond = rebound::case::IncidentCondition {
        alpha_in: (-12.5f64).to_radians(),
        beta_in: 0.0,
    };
    let refl =
        |u: nalgebra::Vector3<f64>, w, n: nalgebra::Vector3<f64>| (u - 2.0 * u.dot(&n) * n, w);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    pool.install(|| {
        for _ in 0..3 {
            let t0 = std::time::Instant::now();
            let hs = rebound::deterministic::simulate(&t, &refl, cond, 0, 200_000, 1, &UNIT);
            let a = t0.elapsed().as_secs_f64();
            let t0 = std::time::Instant::now();
            let mut n = 0;
            for i in 0..200_000u64 {
                let mut r = rebound::rng::stream(1, &[2, 0, i]);
                let x = r.gen::<f64>() * lx;
                let z = r.gen::<f64>() * lz;
                let u = rebound::deterministic::incident_velocity(cond.alpha_in, 0.0, 1.0);
                n += t
                    .trace(x, z, u, nalgebra::Vector3::zeros(), refl)
                    .collisions;
            }
            let b = t0.elapsed().as_secs_f64();
            eprintln!(
                "sorted {:.0}/s unsorted {:.0}/s ({} {})",
                2e5 / a,
                2e5 / b,
                hs.len(),
                n
            );
        }
    });
}
