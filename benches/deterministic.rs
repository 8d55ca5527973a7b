//! Speed of `rebound deterministic` (issue 3): particle histories per second on the
//! (Δξ, Δζ) = (2.5°, 7.5°) wall at α⁻ = −12.5° (surface excluded), and the whole
//! `aniso.toml` scene at 10⁵ particles per condition (surface included).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rebound::case::{IncidentCondition, SpeedLaw};
use rebound::cli::{CommonArgs, DeterministicArgs};
use rebound::collision::CollisionLaw;
use rebound::commands::deterministic::{generate_surface, SurfacePlan};
use rebound::deterministic::scene::{choose_surface, SceneOptions};
use rebound::deterministic::{run_condition, Tracker};
use rebound::surface::HeightField;
use std::time::Duration;

const UNIT: SpeedLaw = SpeedLaw {
    mean_m_s: 1.0,
    std_m_s: 0.0,
};

/// The surface `deterministic` would choose for the wall (default scene options).
fn surface(dxi: f64, dze: f64, seed: u64) -> HeightField {
    let c = choose_surface(dxi.to_radians(), dze.to_radians(), &SceneOptions::default()).unwrap();
    generate_surface(&SurfacePlan::Auto(c), seed).unwrap()
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

/// The whole aniso.toml scene (12 conditions × 10⁵ particles) through the command:
/// surface generation, tracking, tallies, CSVs, figures and run.toml.
fn whole_case(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("rebound-bench-det-{}", std::process::id()));
    let args = DeterministicArgs {
        common: CommonArgs {
            case: Some("cases/aniso.toml".into()),
            out: Some(dir.clone()),
            seed: None,
            threads: None,
        },
        surface: None,
        particles: Some(100_000),
    };
    let mut g = c.benchmark_group("deterministic_case");
    g.sample_size(10).measurement_time(Duration::from_secs(40));
    g.bench_function("aniso_1e5_per_condition", |b| {
        b.iter(|| rebound::commands::deterministic::run(&args).unwrap())
    });
    g.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group!(benches, histories, whole_case);
criterion_main!(benches);
