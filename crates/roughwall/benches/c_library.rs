//! Cost of the C library (issue 9): one `rw_rebound` call through the C ABI against the same
//! rebound through the Rust API (`WallModel::rebound`), and the batch call's rate on 2 threads,
//! for the Sec. 4 glass–steel scene in a rotated frame. Targets: C call ≤ 1.1 × Rust call;
//! batch ≥ 5 M rebounds/s on 2 threads. Run: `cargo bench --bench c_library`.
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use roughwall::ffi::{
    rw_batch, rw_hit, rw_rebound, rw_rebound_batch, rw_result, rw_wall, rw_wall_free, rw_wall_new,
    rw_wall_params, rw_wall_params_default, RW_LAW_SOMMERFELD_HUBER, RW_OK, RW_PRESET_GLASS_STEEL,
};
use roughwall::CollisionParams;
use roughwall::{Hit, WallModel, WallParams};
use std::time::Instant;

const N: usize = 100_000;

fn model() -> WallModel {
    WallModel::new(&WallParams {
        delta_xi_deg: 3.8,
        delta_zeta_deg: 7.5,
        collision: CollisionParams {
            model: Some("sommerfeld-huber".into()),
            preset: Some("glass-steel".into()),
            ..Default::default()
        },
        psi: Some(2.0),
        seed: 2021,
        ..Default::default()
    })
    .unwrap()
    .0
}

fn c_wall() -> *mut rw_wall {
    let mut p = std::mem::MaybeUninit::<rw_wall_params>::uninit();
    let mut p = unsafe {
        rw_wall_params_default(p.as_mut_ptr());
        p.assume_init()
    };
    p.delta_xi_deg = 3.8;
    p.delta_zeta_deg = 7.5;
    p.law = RW_LAW_SOMMERFELD_HUBER;
    p.preset = RW_PRESET_GLASS_STEEL;
    p.seed = 2021;
    let mut w = std::ptr::null_mut();
    assert_eq!(
        unsafe { rw_wall_new(&p, &mut w, std::ptr::null_mut(), 0) },
        RW_OK
    );
    w
}

/// Hits of the scene (α⁻ = −15°, β⁻ = 60°, |u_h| from 4 to 8 m/s) in a frame rotated about
/// (1, 2, 3) by 1.1 rad, the normal given pointing out of the flow.
fn hits(n: usize) -> Vec<Hit> {
    let rot = nalgebra::Rotation3::from_axis_angle(
        &nalgebra::Unit::new_normalize(nalgebra::Vector3::new(1.0, 2.0, 3.0)),
        1.1,
    );
    let g = |v: [f64; 3]| <[f64; 3]>::from(rot * nalgebra::Vector3::from(v));
    let (a, b) = ((-15f64).to_radians(), 60f64.to_radians());
    (0..n)
        .map(|i| {
            let speed = (4.0 + 4.0 * (i as f64 / n as f64)) / a.cos();
            Hit {
                velocity: g([
                    speed * a.cos() * b.cos(),
                    speed * a.sin(),
                    -speed * a.cos() * b.sin(),
                ]),
                spin: [0.0; 3],
                normal: g([0.0, -1.0, 0.0]),
                lay: g([1.0, 0.0, 0.0]),
                wall_velocity: [0.0; 3],
                diameter_m: 500e-6,
                particle_id: i as u64,
                collision_index: 0,
            }
        })
        .collect()
}

fn c_hit(h: &Hit) -> rw_hit {
    rw_hit {
        velocity: h.velocity,
        spin: h.spin,
        normal: h.normal,
        lay: h.lay,
        wall_velocity: h.wall_velocity,
        diameter: h.diameter_m,
        particle_id: h.particle_id,
        collision_index: h.collision_index,
    }
}

fn single_calls(c: &mut Criterion) {
    let m = model();
    let w = c_wall();
    let hs = hits(N);
    let chs: Vec<rw_hit> = hs.iter().map(c_hit).collect();
    let mut g = c.benchmark_group("wall_hit");
    g.throughput(Throughput::Elements(N as u64));
    g.sample_size(20);
    g.bench_function("rust_WallModel_rebound", |b| {
        b.iter(|| {
            let mut s = 0.0;
            for h in &hs {
                s += m.rebound(black_box(h)).velocity[1];
            }
            s
        })
    });
    g.bench_function("c_rw_rebound", |b| {
        b.iter(|| {
            let mut s = 0.0;
            let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
            for h in &chs {
                unsafe {
                    rw_rebound(w, black_box(h), r.as_mut_ptr());
                    s += r.assume_init_ref().velocity[1];
                }
            }
            s
        })
    });
    g.finish();
    unsafe { rw_wall_free(w) };
}

/// Plain-timer summary: the C/Rust ratio (median of 7 alternating rounds) and the batch rate.
fn report(_: &mut Criterion) {
    let m = model();
    let w = c_wall();
    let hs = hits(1_000_000);
    let chs: Vec<rw_hit> = hs.iter().map(c_hit).collect();
    let time = |f: &dyn Fn() -> f64| {
        let t = Instant::now();
        black_box(f());
        t.elapsed().as_secs_f64()
    };
    let rust = || hs.iter().map(|h| m.rebound(h).velocity[1]).sum::<f64>();
    let c = || {
        let mut s = 0.0;
        let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
        for h in &chs {
            unsafe {
                rw_rebound(w, h, r.as_mut_ptr());
                s += r.assume_init_ref().velocity[1];
            }
        }
        s
    };
    let mut ratios = Vec::new();
    let (mut t_rust, mut t_c) = (Vec::new(), Vec::new());
    for _ in 0..7 {
        let a = time(&rust);
        let b = time(&c);
        t_rust.push(a);
        t_c.push(b);
        ratios.push(b / a);
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let n = hs.len() as f64;
    println!(
        "\n== roughwall C library, glass-steel scene, rotated frame, one core ==\nRust WallModel::rebound {:.0} ns/hit, C rw_rebound {:.0} ns/hit, C/Rust {:.3} (median of 7 alternating rounds of 10^6 hits)",
        median(&mut t_rust) / n * 1e9,
        median(&mut t_c) / n * 1e9,
        median(&mut ratios)
    );
    // Batch, struct of arrays.
    let col = |f: &dyn Fn(&Hit) -> f64| hs.iter().map(f).collect::<Vec<f64>>();
    let (ux, uy, uz) = (
        col(&|h| h.velocity[0]),
        col(&|h| h.velocity[1]),
        col(&|h| h.velocity[2]),
    );
    let (nx, ny, nz) = (
        col(&|h| h.normal[0]),
        col(&|h| h.normal[1]),
        col(&|h| h.normal[2]),
    );
    let (lx, ly, lz) = (col(&|h| h.lay[0]), col(&|h| h.lay[1]), col(&|h| h.lay[2]));
    let d = col(&|h| h.diameter_m);
    let pid: Vec<u64> = hs.iter().map(|h| h.particle_id).collect();
    let cid = vec![0u64; hs.len()];
    let (mut ox, mut oy, mut oz) = (
        vec![0.0; hs.len()],
        vec![0.0; hs.len()],
        vec![0.0; hs.len()],
    );
    let mut st = vec![0i32; hs.len()];
    for threads in [1, 2] {
        let batch = rw_batch {
            n: hs.len(),
            ux: ux.as_ptr(),
            uy: uy.as_ptr(),
            uz: uz.as_ptr(),
            wx: std::ptr::null(),
            wy: std::ptr::null(),
            wz: std::ptr::null(),
            nx: nx.as_ptr(),
            ny: ny.as_ptr(),
            nz: nz.as_ptr(),
            lx: lx.as_ptr(),
            ly: ly.as_ptr(),
            lz: lz.as_ptr(),
            vx: std::ptr::null(),
            vy: std::ptr::null(),
            vz: std::ptr::null(),
            diameter: d.as_ptr(),
            particle_id: pid.as_ptr(),
            collision_index: cid.as_ptr(),
            out_ux: ox.as_mut_ptr(),
            out_uy: oy.as_mut_ptr(),
            out_uz: oz.as_mut_ptr(),
            out_wx: std::ptr::null_mut(),
            out_wy: std::ptr::null_mut(),
            out_wz: std::ptr::null_mut(),
            out_gamma: std::ptr::null_mut(),
            out_gamma_star: std::ptr::null_mut(),
            out_candidate_walls: std::ptr::null_mut(),
            out_status: st.as_mut_ptr(),
        };
        let mut ts: Vec<f64> = (0..5)
            .map(|_| time(&|| unsafe { rw_rebound_batch(w, &batch, threads) } as f64))
            .collect();
        println!(
            "rw_rebound_batch, {threads} thread(s): {:.2} M rebounds/s (median of 5 batches of 10^6 hits)",
            n / median(&mut ts) / 1e6
        );
    }
    unsafe { rw_wall_free(w) };
}

criterion_group!(benches, report, single_calls);
criterion_main!(benches);
