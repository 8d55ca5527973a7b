//! Speed of `rebound deterministic` (issue 3): particle histories per second on the
//! (Δξ, Δζ) = (2.5°, 7.5°) wall at α⁻ = −12.5° (surface excluded), and the whole
//! `aniso.toml` scene at 10⁵ particles per condition (surface included).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use roughwall::case::{builtin, deterministic::prepare};
use roughwall::case::{IncidentCondition, SpeedLaw};
use roughwall::collision::CollisionLaw;
use roughwall::deterministic::scene::{
    build_surface, choose_surface, generate_surface, SceneOptions, SurfacePlan,
};
use roughwall::deterministic::{fill_block, tally_spec, ModelSetup, Realisations, Tracker};
use roughwall::erosion::{finnie::Finnie, ErosionModel, ErosionSetup};
use roughwall::output::OutputDir;
use roughwall::run_context::Context;
use roughwall::runner::{self, TallyOverrides};
use roughwall::surface::{HeightField, Triangulation};
use roughwall::tally::BlockTally;
use roughwall::wall::Deviations;
use roughwall::writers::deterministic::finish;
use std::path::Path;
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
    g.finish();
}

/// What `rebound deterministic --case cases/aniso.toml --particles 100000` does, through
/// the library: surface generation, tracking, tallies, CSVs, figures and run.toml.
fn run_case(dir: &Path) {
    let case = Path::new("cases/aniso.toml");
    let out = Some(dir.to_path_buf());
    let ctx = Context::new(
        Some(case),
        None,
        out,
        "deterministic",
        builtin::DETERMINISTIC,
    )
    .unwrap();
    let o = TallyOverrides {
        particles: Some(100_000),
        ..Default::default()
    };
    let p = prepare(&ctx.case, &o, None).unwrap();
    let (count, target) = (p.scene.count as u64, p.scene.target_se_deg);
    let plan = runner::plan(p.specs.clone(), count, target, None).unwrap();
    let sphere = p.options.sphere_diameter_m;
    let built = build_surface(
        p.surface.as_ref(),
        None,
        sphere,
        ctx.seed,
        p.options.triangulation,
    )
    .unwrap();
    let tracker = Realisations::from(Tracker::new(&built.field, p.options.max_collisions).unwrap());
    let out = OutputDir::begin(&ctx.out_dir, "--out").unwrap();
    let t0 = std::time::Instant::now();
    let done = runner::execute(&plan, "deterministic", |k, start, end, block| {
        let cond = &p.scene.conditions[k];
        fill_block(
            &tracker,
            &p.setup,
            cond,
            k as u64,
            ctx.seed,
            (start, end),
            block,
        )
    });
    let seconds = t0.elapsed().as_secs_f64();
    let (tallies, stats): (Vec<_>, Vec<_>) = done.into_iter().unzip();
    finish(
        out.path(),
        ctx.manifest,
        &p,
        &tallies,
        Some(&stats),
        seconds,
    )
    .unwrap();
    out.commit().unwrap();
}

/// The whole aniso.toml scene (12 conditions × 10⁵ particles), as the command runs it.
fn whole_case(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("rebound-bench-det-{}", std::process::id()));
    let mut g = c.benchmark_group("deterministic_case");
    g.sample_size(10).measurement_time(Duration::from_secs(40));
    g.bench_function("aniso_1e5_per_condition", |b| b.iter(|| run_case(&dir)));
    g.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group!(benches, histories, whole_case);
criterion_main!(benches);
