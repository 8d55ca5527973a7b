//! Table 1 of Radenkovic & Simonin 2021 on generated surfaces.
use rebound::surface::stats::{surface_stats, SurfaceStats};
use rebound::surface::{generate, SurfaceParams};
use std::time::Instant;

fn run(n: usize, len_um: f64, seed: u64) -> SurfaceStats {
    let p = SurfaceParams {
        length_m: len_um * 1e-6,
        nodes: n,
        rms_height_m: 0.37e-6,
        corr_x_m: Some(12e-6),
        corr_z_m: Some(4e-6),
    };
    let t = Instant::now();
    let f = generate(&p, seed);
    let tg = t.elapsed();
    let betas: Vec<f64> = [0.0f64, 30.0, 60.0, 90.0]
        .iter()
        .map(|b| b.to_radians())
        .collect();
    let s = surface_stats(&f, &betas, None);
    eprintln!("generate {:?}, stats {:?}", tg, t.elapsed() - tg);
    s
}

#[test]
#[ignore]
fn table1_full_size() {
    let s = run(5001, 5000.0, 1);
    eprintln!("{s:#?}");
}
