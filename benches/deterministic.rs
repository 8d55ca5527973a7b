//! Speed of `rebound deterministic` (issue 3): particle histories per second on the
//! (Δξ, Δζ) = (2.5°, 7.5°) wall at α⁻ = −12.5° (surface excluded), and the whole
//! `aniso.toml` scene at 10⁵ particles per condition (surface included).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rebound::case::{IncidentCondition, SpeedLaw};
use rebound::collision::CollisionLaw;
use rebound::deterministic::scene::{choose_surface, SceneOptions};
use rebound::deterministic::{run_condition, Tracker};
use rebound::surface::HeightField;
use rebound::wall::Deviations;
use std::time::Duration;

#[path = "../tests/deterministic_support/mod.rs"]
mod support;

const UNIT: SpeedLaw = SpeedLaw {
    mean_m_s: 1.0,
    std_m_s: 0.0,
};

/// The surface `deterministic` would choose for the wall (default scene options).
fn surface(dxi: f64, dze: f64, seed: u64) -> HeightField {
    let c = choose_surface(dxi.to_radians(), dze.to_radians(), &SceneOptions::default()).unwrap();
    support::gaussian_surface(
        c.nodes,
        c.spacing_m,
        c.rms_height_m,
        c.corr_length_x_m,
        c.corr_length_z_m,
        seed,
    )
}

fn histories(c: &mut Criterion) {
    let f = surface(2.5, 7.5, 1);
    let t = Tracker::new(&f, 1000).unwrap();
    let n = 200_000;
    let mut g = c.benchmark_group("deterministic");
    g.throughput(Throughput::Elements(n as u64));
    g.sample_size(10).measurement_time(Duration::from_secs(8));
    {
        g.bench_function("histories_aniso_a-12.5_b0", |b| {
            b.iter(|| {
                run_condition(
                    &t,
                    &CollisionLaw::Elastic,
                    500e-6,
                    IncidentCondition {
                        alpha_in: (-12.5f64).to_radians(),
                        beta_in: 0.0,
                    },
                    0,
                    n,
                    1,
                    &UNIT,
                )
            })
        });
    }
    let t_plain = Tracker::new(&f, 1000).unwrap().without_tiles();
    g.bench_function("histories_aniso_a-12.5_b0_no_tile_map", |b| {
        b.iter(|| {
            run_condition(
                &t_plain,
                &CollisionLaw::Elastic,
                500e-6,
                IncidentCondition {
                    alpha_in: (-12.5f64).to_radians(),
                    beta_in: 0.0,
                },
                0,
                n,
                1,
                &UNIT,
            )
        })
    });
    g.finish();
}

/// The whole aniso.toml scene (12 conditions × 10⁵ particles), surface included.
fn whole_case(c: &mut Criterion) {
    let mut g = c.benchmark_group("deterministic_case");
    g.sample_size(10).measurement_time(Duration::from_secs(30));
    g.bench_function("aniso_1e5_per_condition", |b| {
        b.iter(|| {
            let f = surface(2.5, 7.5, 2);
            let t = Tracker::new(&f, 1000).unwrap();
            let dv = Deviations {
                delta_xi: 2.5f64.to_radians(),
                delta_zeta: 7.5f64.to_radians(),
            };
            let mut k = 0;
            let mut rows = 0;
            for a in [-2.5f64, -12.5, -32.5] {
                for beta in [0.0f64, 30.0, 60.0, 90.0] {
                    let r = run_condition(
                        &t,
                        &CollisionLaw::Elastic,
                        500e-6,
                        IncidentCondition {
                            alpha_in: a.to_radians(),
                            beta_in: beta.to_radians(),
                        },
                        k,
                        100_000,
                        2,
                        &UNIT,
                    );
                    rows += r.tally(&dv, 2.0, 1.0).pdfs.len();
                    k += 1;
                }
            }
            rows
        })
    });
    g.finish();
}

criterion_group!(benches, histories, whole_case);
criterion_main!(benches);
