//! Speed of the deterministic model (issue 3): particle histories per second on the
//! (Δξ, Δζ) = (2.5°, 7.5°) wall at α⁻ = −12.5° (surface excluded), and the physics of the
//! whole `aniso.toml` scene at 10⁵ particles per condition (surface included).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use roughwall::deterministic::{choose_surface, generate_surface, SceneOptions, SurfacePlan};
use roughwall::deterministic::{fill_block, tally_spec, ModelSetup, Realisations};
use roughwall::erosion::Finnie;
use roughwall::tally::BlockTally;
use roughwall::tally::{self, Plan, Silent};
use roughwall::CollisionLaw;
use roughwall::Deviations;
use roughwall::Tracker;
use roughwall::{ErosionModel, ErosionSetup};
use roughwall::{HeightField, Triangulation};
use roughwall::{IncidentCondition, SpeedLaw};
use std::time::Duration;

const UNIT: SpeedLaw = SpeedLaw::horizontal(1.0, 0.0);

/// The surface `deterministic` would choose for the wall (default scene options).
fn surface(dxi: f64, dze: f64, seed: u64) -> HeightField {
    let c = choose_surface(dxi.to_radians(), dze.to_radians(), &SceneOptions::default()).unwrap();
    generate_surface(&SurfacePlan::Auto(c), seed, Triangulation::default()).unwrap()
}

/// Histories `0..n` of one condition, tallied in one block on one thread (tracker, collision
/// law and tally; no parallelism, so the figure is per core).
fn one_block(t: &Realisations<'_>, n: u64) -> BlockTally {
    one_block_eroding(t, n, None)
}

/// [`one_block`] with an erosion law (or none).
fn one_block_eroding(t: &Realisations<'_>, n: u64, erosion: Option<ErosionSetup>) -> BlockTally {
    let wall = Deviations {
        delta_xi: 2.5f64.to_radians(),
        delta_zeta: 7.5f64.to_radians(),
    };
    let setup = ModelSetup {
        law: CollisionLaw::Elastic,
        diameter_m: 500e-6,
        speed: UNIT,
        wall,
        psi: 2.0,
        erosion,
        spin: Default::default(),
    };
    let cond = IncidentCondition::from_degrees(-12.5, 0.0);
    let mut block = BlockTally::new(&tally_spec(&wall, cond, 1.0, erosion.as_ref()), 0);
    fill_block(t, &setup, &cond, 0, 1, (0, n), &mut block);
    block
}

fn histories(c: &mut Criterion) {
    let f = surface(2.5, 7.5, 1);
    let t = Realisations::from(Tracker::new(&f, 1000).unwrap());
    let n = 100_000;
    let mut g = c.benchmark_group("deterministic");
    g.throughput(Throughput::Elements(n));
    g.sample_size(10).measurement_time(Duration::from_secs(8));
    g.bench_function("histories_aniso_a-12.5_b0_one_core", |b| {
        b.iter(|| one_block(&t, n))
    });
    // Issue 13: the alternating triangulation (the default) against the uniform one.
    let f_uniform = HeightField {
        triangulation: Triangulation::Uniform,
        ..f.clone()
    };
    let t_uniform = Realisations::from(Tracker::new(&f_uniform, 1000).unwrap());
    g.bench_function(
        "histories_aniso_a-12.5_b0_one_core_uniform_triangulation",
        |b| b.iter(|| one_block(&t_uniform, n)),
    );
    let t_plain = Realisations::from(Tracker::new(&f, 1000).unwrap().without_tiles());
    g.bench_function("histories_aniso_a-12.5_b0_one_core_no_tile_map", |b| {
        b.iter(|| one_block(&t_plain, n))
    });
    // Issue 12: erosion costs at most 10 % when enabled (Finnie, steel, 500 µm glass).
    let finnie = ErosionSetup {
        model: ErosionModel::Finnie(Finnie {
            flow_stress_pa: 1e9,
            psi: 2.0,
            k: 2.0,
        }),
        particle_mass_kg: 2500.0 * std::f64::consts::PI / 6.0 * 500e-6f64.powi(3),
        diameter_m: 500e-6,
    };
    g.bench_function("histories_aniso_a-12.5_b0_one_core_finnie", |b| {
        b.iter(|| one_block_eroding(&t, n, Some(finnie)))
    });
    // Issue 39, part 9: the in-place reference on a scan against periodic `deterministic` on
    // a wall of the same size (the same generated wall taken as a patch, its lay at 30°, so
    // every history is turned): goal ≥ 0.5× the periodic rate.
    let t_patch = Realisations::from(Tracker::in_place(&f, 1000, 30f64.to_radians()).unwrap());
    g.bench_function("histories_aniso_a-12.5_b0_one_core_in_place", |b| {
        b.iter(|| one_block(&t_patch, n))
    });
    g.finish();
}

/// The physics of `rebound deterministic --case cases/aniso.toml --particles 100000`
/// through the library: the surface the scene chooses (seed 2021), then 12 conditions ×
/// 10⁵ histories through the block engine on every core, tallies included (the CSVs and
/// figures are the application's: whole-process timings are `scripts/bench-scale.sh`'s).
fn run_case() -> usize {
    let (dxi, dze) = (2.5f64, 7.5f64);
    let wall = Deviations {
        delta_xi: dxi.to_radians(),
        delta_zeta: dze.to_radians(),
    };
    let field = surface(dxi, dze, 2021);
    let tracker = Realisations::from(Tracker::new(&field, 1000).unwrap());
    let setup = ModelSetup {
        law: CollisionLaw::Elastic,
        diameter_m: 500e-6,
        speed: UNIT,
        wall,
        psi: 2.0,
        erosion: None,
        spin: Default::default(),
    };
    let conditions: Vec<IncidentCondition> = [-2.5, -12.5, -32.5]
        .into_iter()
        .flat_map(|a| [0.0, 30.0, 60.0, 90.0].map(|b| IncidentCondition::from_degrees(a, b)))
        .collect();
    let plan = Plan {
        specs: conditions
            .iter()
            .map(|c| tally_spec(&wall, *c, 1.0, None))
            .collect(),
        count: 100_000,
        target_se_deg: None,
        shard: None,
    };
    let done = tally::run(&plan, &Silent, |k, start, end, block| {
        fill_block(
            &tracker,
            &setup,
            &conditions[k],
            k as u64,
            2021,
            (start, end),
            block,
        )
    });
    done.len()
}

/// The whole aniso.toml scene (12 conditions × 10⁵ particles) through the library.
fn whole_case(c: &mut Criterion) {
    let mut g = c.benchmark_group("deterministic_case");
    g.sample_size(10).measurement_time(Duration::from_secs(40));
    g.bench_function("aniso_1e5_per_condition", |b| b.iter(run_case));
    g.finish();
}

/// Issue 39, part 9: building the wall's own model (`rebound scan --measured-wall`'s table,
/// 17 711 histories in each of the grid's 1032 base cells, and in the rows the build adds
/// where the law bends) from a 4096² scan, here a generated (2.5°, 7.5°) wall taken as a
/// patch with its lay at 30°, on every core: goal ≤ 10 s on 2.
fn measured_wall_build(c: &mut Criterion) {
    let f = roughwall::surface::generate(
        &roughwall::SurfaceSpec {
            length_m: 4096e-6,
            nodes: 4096,
            rms_height_m: 0.37e-6,
            corr_length_x_m: Some(12e-6),
            corr_length_z_m: Some(4e-6),
        },
        3,
    );
    let t = Tracker::in_place(&f, 1000, 30f64.to_radians()).unwrap();
    let dev = roughwall::surface::measured_deviations(&f);
    let opts = roughwall::measured_wall::BuildOptions::default();
    // What is timed: the base grid and the rows this wall's law adds (none expected on a
    // smooth Gaussian wall).
    let built = roughwall::measured_wall::build_table(&t, dev, "bench", &opts, &|_| {}).unwrap();
    eprintln!("rows added: {:?}", built.refined_rows_deg());
    let mut g = c.benchmark_group("measured_wall");
    g.sample_size(10).measurement_time(Duration::from_secs(100));
    g.bench_function("build_table_4096_squared", |b| {
        b.iter(|| roughwall::measured_wall::build_table(&t, dev, "bench", &opts, &|_| {}).unwrap())
    });
    g.finish();
}

criterion_group!(benches, histories, whole_case, measured_wall_build);
criterion_main!(benches);
