//! Accepted rebounds per second of the stochastic model (issue 4 targets on 2 cores:
//! ≥ 5 M/s elastic (2.5°, 7.5°) at α⁻ = −12.5°, ≥ 2 M/s Sommerfeld–Huber Sec. 4 scene,
//! ≥ 1 M/s at grazing α⁻ = −0.5°), proposals per accepted γ of the shadow sampler, and
//! where the time of one rebound goes (issue 10): the steps of a tallied rebound timed
//! one by one on one core.
//!
//! Each batch runs `N` particles in parallel with rayon (one RNG stream per particle, as
//! `rebound stochastic` does). Run: `cargo bench --bench stochastic`.
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use nalgebra::Vector3;
use rand::Rng;
use rand_distr::StandardNormal;
use rayon::prelude::*;
use roughwall::angles::{alpha_xy_of_velocity, incident_angles, normal_from_gamma};
use roughwall::erosion::Finnie;
use roughwall::incidence::{draw_speed, incident_velocity};
use roughwall::models::rebound_from_observed;
use roughwall::models::{fill_block, outcome, tally_spec, ModelSetup};
use roughwall::rng;
use roughwall::stochastic::ShadowSampler;
use roughwall::stochastic::{rebound, Contact};
use roughwall::tally::BlockTally;
use roughwall::wall::{conditional_gamma_star, delta_gamma, rotated_moments};
use roughwall::Deviations;
use roughwall::IncidentCondition;
use roughwall::SpeedLaw;
use roughwall::{AnyModel, RoughWallModel};
use roughwall::{CollisionLaw, ShParams};
use roughwall::{ErosionModel, ErosionSetup};
use std::time::Instant;

const N: u64 = 200_000;

struct Scene {
    name: &'static str,
    wall: Deviations,
    law: CollisionLaw,
    alpha_deg: f64,
    beta_deg: f64,
    speed: SpeedLaw,
}

fn scenes() -> Vec<Scene> {
    let d = |x: f64, z: f64| Deviations {
        delta_xi: x.to_radians(),
        delta_zeta: z.to_radians(),
    };
    let fixed = SpeedLaw::horizontal(6.0, 0.0);
    vec![
        Scene {
            name: "elastic_2.5_7.5_alpha-12.5_beta60",
            wall: d(2.5, 7.5),
            law: CollisionLaw::Elastic,
            alpha_deg: -12.5,
            beta_deg: 60.0,
            speed: fixed,
        },
        Scene {
            name: "sommerfeld-huber_sec4_3.8_7.5_alpha-15_beta60",
            wall: d(3.8, 7.5),
            law: CollisionLaw::SommerfeldHuber(ShParams::glass_steel()),
            alpha_deg: -15.0,
            beta_deg: 60.0,
            speed: SpeedLaw::horizontal(5.91, 1.16),
        },
        Scene {
            name: "elastic_2.5_7.5_grazing_alpha-0.5_beta60",
            wall: d(2.5, 7.5),
            law: CollisionLaw::Elastic,
            alpha_deg: -0.5,
            beta_deg: 60.0,
            speed: fixed,
        },
    ]
}

/// One batch of `n` accepted rebounds in parallel; returns the total candidate walls.
fn batch(s: &Scene, n: u64, seed: u64) -> u64 {
    let per_unit = incident_velocity(s.alpha_deg.to_radians(), s.beta_deg.to_radians(), 1.0);
    (0..n)
        .into_par_iter()
        .map(|i| {
            let mut r = rng::stream(seed, &[rng::domain::STOCHASTIC, 0, i]);
            let u = per_unit * draw_speed(&s.speed, &mut r);
            let out = rebound(u, Vector3::zeros(), &s.wall, &s.law, 2.0, 500e-6, &mut r);
            black_box(out.velocity);
            out.tries as u64
        })
        .sum()
}

fn bench_rebounds(c: &mut Criterion) {
    let mut g = c.benchmark_group("stochastic_rebounds");
    g.throughput(Throughput::Elements(N));
    g.sample_size(20);
    for s in scenes() {
        g.bench_function(s.name, |bch| {
            let mut seed = 0;
            bch.iter(|| {
                seed += 1;
                batch(&s, N, seed)
            })
        });
    }
    g.finish();
}

/// Finnie erosion (OpenFOAM's defaults, steel's flow stress) on 500 µm glass.
fn finnie() -> ErosionSetup {
    ErosionSetup {
        model: ErosionModel::Finnie(Finnie {
            flow_stress_pa: 1e9,
            psi: 2.0,
            k: 2.0,
        }),
        particle_mass_kg: 2500.0 * std::f64::consts::PI / 6.0 * 500e-6f64.powi(3),
        diameter_m: 500e-6,
    }
}

/// The cost of tallying erosion: one tallied block of rebounds on one core, without and
/// with `[erosion]` (issue 12: at most 10 % when enabled).
fn bench_erosion(c: &mut Criterion) {
    let mut g = c.benchmark_group("stochastic_erosion");
    let n = 65_536;
    g.throughput(Throughput::Elements(n));
    g.sample_size(20);
    for s in scenes().iter().take(2) {
        g.bench_function(format!("{}_tallied_block", s.name), |b| {
            b.iter(|| black_box(tallied_block_eroding(s, n, None)))
        });
        g.bench_function(format!("{}_tallied_block_finnie", s.name), |b| {
            b.iter(|| black_box(tallied_block_eroding(s, n, Some(finnie()))))
        });
    }
    g.finish();
}

/// The measured-wall model of a generated wall with about the scenes' deviations (Δξ ≈ 2.5°,
/// Δζ ≈ 7.5°: correlation lengths 12 and 4 µm, Eq. 15), its table of 1024 histories a cell
/// (the cost of a rebound does not depend on how many histories built the table); with
/// `height_step_m`, its heights rounded to whole steps of it (an instrument's quantization:
/// a comb-like law, whose quantile functions add knots and are read by bisection).
fn measured_wall_model(height_step_m: Option<f64>) -> AnyModel {
    let mut field = roughwall::surface::generate(
        &roughwall::SurfaceSpec {
            length_m: 256e-6,
            nodes: 256,
            rms_height_m: 0.37e-6,
            corr_length_x_m: Some(12e-6),
            corr_length_z_m: Some(4e-6),
        },
        3,
    );
    if let Some(step) = height_step_m {
        for h in &mut field.heights {
            *h = (*h / step).round() * step;
        }
    }
    let t = roughwall::Tracker::new(&field, 1000).unwrap();
    let dev = roughwall::surface::measured_deviations(&field);
    let opts = roughwall::measured_wall::BuildOptions {
        histories_per_cell: 1024,
        seed: 1,
    };
    let table = roughwall::measured_wall::build_table(&t, dev, "bench wall", &opts, &|_| {})
        .unwrap()
        .intern()
        .unwrap();
    AnyModel::MeasuredWall(roughwall::models::MeasuredWall { table })
}

/// The cost of each rough-wall variant: one tallied block of rebounds on one core (issue 39,
/// part 4: the measured-wall model at most 2× the paper's per rebound).
fn bench_variants(c: &mut Criterion) {
    let mut g = c.benchmark_group("stochastic_variants");
    let n = 65_536;
    g.throughput(Throughput::Elements(n));
    g.sample_size(20);
    let measured = measured_wall_model(None);
    // Steps of 0.02 µm over the 1 µm pixel: slopes 1.1° apart, a comb at these deviations.
    let quantized = measured_wall_model(Some(0.02e-6));
    for (k, s) in scenes().iter().take(2).enumerate() {
        for name in AnyModel::NAMES {
            let v = match *name {
                "measured-wall" => measured,
                _ => AnyModel::with_defaults(name).expect("a registered model"),
            };
            g.bench_function(format!("{}_{}", s.name, name), |b| {
                b.iter(|| black_box(tallied_block_with(s, n, None, v)))
            });
        }
        if k == 0 {
            g.bench_function(format!("{}_measured-wall-quantized", s.name), |b| {
                b.iter(|| black_box(tallied_block_with(s, n, None, quantized)))
            });
        }
    }
    g.finish();
}

fn bench_sampler(c: &mut Criterion) {
    let mut g = c.benchmark_group("shadow_sampler");
    g.throughput(Throughput::Elements(1));
    for (a, dg) in [(-0.01, 3.8), (-12.5, 3.8), (-90.0, 15.0)] {
        let sm = ShadowSampler::new(f64::to_radians(a), f64::to_radians(dg));
        let mut r = rng::stream(1, &[9]);
        g.bench_function(format!("alpha{a}_dgamma{dg}"), |b| {
            b.iter(|| black_box(sm.sample(&mut r)))
        });
    }
    g.finish();
}

/// CPU seconds (user + system) of this process so far, from `/proc/self/stat` (Linux;
/// clock ticks of 10 ms), `None` elsewhere.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let rest = &stat[stat.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// Plain-timer summary printed once: rebounds/s (wall clock, all threads), candidate
/// walls per rebound, and proposals per accepted γ of the sampler at the worst points.
fn report(_: &mut Criterion) {
    println!(
        "\n== stochastic model summary ({} rayon threads) ==",
        rayon::current_num_threads()
    );
    for s in scenes() {
        batch(&s, N, 99); // warm-up
        let reps = 5;
        let cpu0 = cpu_seconds();
        let t = Instant::now();
        let mut tries = 0;
        for k in 0..reps {
            tries += batch(&s, 1_000_000, 1000 + k);
        }
        let secs = t.elapsed().as_secs_f64();
        let cpu = cpu_seconds().zip(cpu0).map(|(b, a)| b - a);
        println!(
            "{:48} {:6.2} M accepted rebounds/s wall clock; {} ns CPU per rebound; {:.4} candidate walls/rebound, Δγ(β⁻) = {:.2}°",
            s.name,
            reps as f64 * 1e6 / secs / 1e6,
            cpu.map_or("?".to_string(), |c| format!("{:.0}", c / (reps as f64 * 1e6) * 1e9)),
            tries as f64 / (reps as f64 * 1e6),
            delta_gamma(&s.wall, s.beta_deg.to_radians()).to_degrees()
        );
    }
    let mut worst = (0.0, 0.0, 0.0);
    let mut r = rng::stream(2, &[3]);
    for a in [-0.01, -0.5, -2.5, -12.5, -45.0, -89.99, -90.0] {
        for dg in [0.01, 0.5, 2.0, 3.8, 7.5, 15.0, 20.0] {
            let sm = ShadowSampler::new(f64::to_radians(a), f64::to_radians(dg));
            let n = 200_000;
            let total: u64 = (0..n).map(|_| sm.sample_counted(&mut r).1 as u64).sum();
            let per = total as f64 / n as f64;
            if per > worst.0 {
                worst = (per, a, dg);
            }
        }
    }
    println!(
        "shadow sampler: worst {:.4} proposals per accepted γ (α⁻ = {}°, Δγ = {}°) on α⁻ ∈ [−90°, −0.01°] × Δγ ∈ [0.01°, 20°]",
        worst.0, worst.1, worst.2
    );
}

/// One tallied block of `n` rebounds of a scene on one core: what `rebound stochastic` does
/// per worker.
fn tallied_block(s: &Scene, n: u64) -> BlockTally {
    tallied_block_eroding(s, n, None)
}

/// [`tallied_block`] with an erosion law (or none).
fn tallied_block_eroding(s: &Scene, n: u64, erosion: Option<ErosionSetup>) -> BlockTally {
    tallied_block_with(s, n, erosion, AnyModel::default())
}

/// [`tallied_block`] with an erosion law (or none) and a rough-wall variant.
fn tallied_block_with(
    s: &Scene,
    n: u64,
    erosion: Option<ErosionSetup>,
    model: AnyModel,
) -> BlockTally {
    let setup = ModelSetup {
        wall: s.wall,
        law: s.law,
        psi: 2.0,
        diameter_m: 500e-6,
        speed: s.speed,
        erosion,
        model,
        spin: Default::default(),
    };
    let cond = IncidentCondition::from_degrees(s.alpha_deg, s.beta_deg);
    let mut block = BlockTally::new(&tally_spec(&s.wall, cond, 1.0, erosion.as_ref()), 0);
    fill_block(&setup, &cond, 0, 1, (0, n), &mut block);
    block
}

/// The steps of one tallied rebound on one core, each timed over the same particles:
/// the cumulative cost of the procedure up to a step, minus the one before, is that step's
/// share. Printed as a table for the README's breakdown.
fn breakdown(_: &mut Criterion) {
    let s = &scenes()[0];
    let cond = IncidentCondition::from_degrees(s.alpha_deg, s.beta_deg);
    let model = AnyModel::PAPER;
    let inc = model.incidence(cond.alpha_in, cond.beta_in, &s.wall);
    let contact = Contact {
        wall: &s.wall,
        law: &s.law,
        psi: 2.0,
        diameter_m: 500e-6,
    };
    let m = rotated_moments(&s.wall, cond.beta_in);
    let per_unit = incident_velocity(cond.alpha_in, cond.beta_in, 1.0);
    let prefix = rng::StreamPrefix::new(1, &[rng::domain::STOCHASTIC, 0]);
    let sampler = ShadowSampler::new(cond.alpha_in, m.var_a.sqrt());
    let n = 2_000_000u64;
    let time = |f: &dyn Fn(u64) -> f64| {
        let t = Instant::now();
        let mut acc = 0.0;
        for i in 0..n {
            acc += f(i);
        }
        black_box(acc);
        t.elapsed().as_secs_f64() * 1e9 / n as f64
    };
    let stream = time(&|i| {
        let mut r = prefix.stream(i);
        r.gen::<f64>()
    });
    let speed = time(&|i| {
        let mut r = prefix.stream(i);
        draw_speed(&s.speed, &mut r)
    });
    let wall = time(&|i| {
        let mut r = prefix.stream(i);
        let g = sampler.sample(&mut r);
        let (mean, var) = conditional_gamma_star(&m, g);
        let z: f64 = r.sample(StandardNormal);
        normal_from_gamma(g, mean + var.sqrt() * z, cond.beta_in).x
    });
    let whole = time(&|i| {
        let mut r = prefix.stream(i);
        let u = per_unit * draw_speed(&s.speed, &mut r);
        rebound_from_observed(
            &model,
            &inc,
            u,
            Vector3::zeros(),
            &contact,
            &mut r,
            |_, _, _| {},
        )
        .velocity
        .y
    });
    let angles = time(&|i| {
        let mut r = prefix.stream(i);
        let u = per_unit * draw_speed(&s.speed, &mut r);
        let out = rebound_from_observed(
            &model,
            &inc,
            u,
            Vector3::zeros(),
            &contact,
            &mut r,
            |_, _, _| {},
        );
        let (a, b) = incident_angles(&out.velocity);
        a + b + alpha_xy_of_velocity(&out.velocity)
    });
    let t = Instant::now();
    black_box(tallied_block(s, n));
    let tallied = t.elapsed().as_secs_f64() * 1e9 / n as f64;
    let _ = outcome; // (the tallied record: angles above plus the first wall's, no extra cost)
    println!(
        "\n== where one tallied rebound goes, {} (one core, ns) ==",
        s.name
    );
    println!("| step | ns per rebound | share |\n|---|---|---|");
    let rows = [
        ("random stream (key → xoshiro256++) and one uniform", stream),
        ("incident speed N(mean, std)", speed - stream),
        (
            "candidate wall: γ (shadow sampler), γ* (Eq. 30), normal (Eq. 23)",
            wall - stream,
        ),
        (
            "collision law, Eq. (34) acceptance, redraws (rest of the procedure)",
            whole - speed - (wall - stream),
        ),
        ("rebound angles α⁺, β⁺, α⁺_xy", angles - whole),
        (
            "tally (the histograms and moment sums of every tallied quantity; no erosion here)",
            tallied - angles,
        ),
    ];
    for (what, ns) in rows {
        println!("| {what} | {ns:.0} | {:.0} % |", 100.0 * ns / tallied);
    }
    println!("| **total, tallied rebound** | **{tallied:.0}** | 100 % |");
}

criterion_group!(
    benches,
    report,
    breakdown,
    bench_rebounds,
    bench_sampler,
    bench_erosion,
    bench_variants
);
criterion_main!(benches);
