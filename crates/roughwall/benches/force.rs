//! `rebound force-sweep` speed: closed-form models (evaluations per second on a 2-thread pool,
//! issue 5 asks ≥ 10 M/s on 2 cores) and `hertz-dynamic` (time per impact).
use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rayon::prelude::*;
use roughwall::force::{hertz_dynamic, Impact, Model, Particle};

const GLASS: Particle = Particle {
    density: 2500.0,
    youngs: 64e9,
    poisson: 0.24,
    diameter: 2.45e-6,
};

/// 10⁶ impacts: λ ∈ {1.5, 2, 3}, β over [0°, 90°], U_N over [0.01, 20] m/s.
fn impacts() -> Vec<Impact> {
    (0..1_000_000)
        .map(|i| {
            let lambda = [1.5, 2.0, 3.0][i % 3];
            let beta = (i % 91) as f64;
            let u = 0.01 + 20.0 * ((i * 7919) % 1000) as f64 / 1000.0;
            Impact::from_deg(lambda, beta, u).unwrap()
        })
        .collect()
}

fn closed_form(c: &mut Criterion) {
    let imps = impacts();
    let pool2 = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let mut g = c.benchmark_group("force_closed_form_1e6");
    g.throughput(Throughput::Elements(imps.len() as u64));
    g.sample_size(10);
    for model in [Model::Hu2021, Model::HertzRigid] {
        g.bench_with_input(
            BenchmarkId::new(model.name(), "2 threads"),
            &imps,
            |b, imps| {
                b.iter(|| {
                    pool2.install(|| {
                        imps.par_iter()
                            .map(|imp| model.evaluate(&GLASS, imp).map(|r| r.f_max).unwrap_or(0.0))
                            .sum::<f64>()
                    })
                })
            },
        );
        g.bench_with_input(
            BenchmarkId::new(model.name(), "1 thread"),
            &imps,
            |b, imps| {
                b.iter(|| {
                    imps.iter()
                        .map(|imp| model.evaluate(&GLASS, imp).map(|r| r.f_max).unwrap_or(0.0))
                        .sum::<f64>()
                })
            },
        );
    }
    g.finish();
}

fn dynamic(c: &mut Criterion) {
    let mut g = c.benchmark_group("force_dynamic_per_impact");
    let imp = Impact::from_deg(2.0, 45.0, 0.0457).unwrap();
    for n in [16, 32, 64, 200] {
        let opts = hertz_dynamic::Options {
            steps_per_contact: n,
        };
        g.bench_function(
            BenchmarkId::new("glass 2.45 µm λ=2 β=45°", format!("{n} steps")),
            |b| b.iter(|| hertz_dynamic::simulate(black_box(&GLASS), black_box(&imp), &opts)),
        );
    }
    let steel = Particle {
        density: 7850.0,
        youngs: 210e9,
        poisson: 0.3,
        diameter: 5e-3,
    };
    let imp = Impact::from_deg(3.0, 40.0, 2.0).unwrap();
    let opts = hertz_dynamic::Options::default();
    g.bench_function("steel 5 mm λ=3 β=40° default (64) steps", |b| {
        b.iter(|| hertz_dynamic::simulate(black_box(&steel), black_box(&imp), &opts))
    });
    g.finish();
}

criterion_group!(benches, closed_form, dynamic);
criterion_main!(benches);
