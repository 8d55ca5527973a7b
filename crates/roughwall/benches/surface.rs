//! Criterion benchmarks of the surface generator and the Table 1 statistics
//! (`cargo bench --bench surface`). The N = 5001 cases are the Table 1 surface.
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use roughwall::surface::dilate_paraboloid;
use roughwall::surface::generate;
use roughwall::surface::surface_stats;
use roughwall::SurfaceSpec;

fn spec(n: usize) -> SurfaceSpec {
    // δ ≈ 1 µm and the roughness of Table 1 (h = 0.37 µm, c_L = 12 µm × 4 µm).
    SurfaceSpec {
        length_m: n as f64 * 1e-6,
        nodes: n,
        rms_height_m: 0.37e-6,
        corr_length_x_m: Some(12e-6),
        corr_length_z_m: Some(4e-6),
    }
}

fn bench(c: &mut Criterion) {
    let betas: Vec<f64> = [0.0f64, 30.0, 60.0, 90.0]
        .iter()
        .map(|b| b.to_radians())
        .collect();
    let mut g = c.benchmark_group("surface");
    g.sample_size(10);
    for n in [1024usize, 5001] {
        let s = spec(n);
        g.bench_with_input(BenchmarkId::new("generate", n), &s, |b, s| {
            b.iter(|| generate(s, 1))
        });
        let f = generate(&s, 1);
        g.bench_with_input(BenchmarkId::new("table1_stats", n), &f, |b, f| {
            b.iter(|| surface_stats(f, &betas, None))
        });
        // The centre surface of a 500 µm sphere (issue "the particle as a sphere": < 2 s
        // for N = 5001 on 2 cores).
        g.bench_with_input(
            BenchmarkId::new("dilate_paraboloid_d500um", n),
            &f,
            |b, f| b.iter(|| dilate_paraboloid(f, 250e-6)),
        );
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
