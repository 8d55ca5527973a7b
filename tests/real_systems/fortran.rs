//! The Fortran example (`examples/fortran/`) built with gfortran against `include/` and
//! `libroughwall.so`: for the same key, the Fortran call returns exactly the Rust call, and a
//! zero normal is a status (issue 9).

use crate::common::*;
use roughwall::collision::CollisionParams;
use roughwall::wall_model::{Hit, HitStatus, WallModel, WallParams};
use std::path::Path;
use std::process::Command;

/// The wall of the examples' `keys` mode: Sec. 4 glass on steel.
fn glass_steel() -> WallModel {
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

/// The hits of the examples' `keys` mode (the same in C and Fortran).
fn key_hit(pid: u64) -> Hit {
    let uh = 4.0 + 0.25 * pid as f64;
    Hit {
        velocity: [uh * 0.5, -0.35 * uh, -uh * 0.866],
        spin: [0.0, 0.0, 100.0 * pid as f64],
        normal: [0.0, 1.0, 0.0],
        lay: [1.0, 0.0, 0.0],
        wall_velocity: [0.0; 3],
        diameter_m: 500e-6,
        particle_id: pid,
        collision_index: pid % 3,
    }
}

fn run(cmd: &Path, args: &[&str]) -> String {
    let o = Command::new(cmd).args(args).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap()
}

#[test]
fn the_fortran_example_gives_the_rust_rebounds() {
    crate::require(&["gfortran"]);
    let tmp = Dir::new();
    let root = repo_root();
    let exe = tmp.path().join("hits");
    let module_dir = tmp.path().to_str().unwrap().to_string();
    build_with_roughwall(
        "gfortran",
        &[
            &root.join("examples/fortran/roughwall.f90"),
            &root.join("examples/fortran/hits.f90"),
        ],
        &exe,
        &["-J", &module_dir],
    );
    let text = run(&exe, &[]);
    let model = glass_steel();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some(format!("roughwall {}", env!("CARGO_PKG_VERSION")).as_str())
    );
    let mut n = 0;
    for line in lines.by_ref().take(20) {
        let f: Vec<&str> = line.split_whitespace().collect();
        let pid: u64 = f[0].parse().unwrap();
        let want = model.rebound(&key_hit(pid));
        assert_eq!(want.status, HitStatus::Rebound);
        assert_eq!(f[2], "0", "{line}");
        // 17 significant digits read back are the same double.
        let got: Vec<f64> = f[3..9].iter().map(|x| x.parse().unwrap()).collect();
        let expect: Vec<f64> = want.velocity.iter().chain(&want.spin).copied().collect();
        assert_eq!(got, expect, "{line}");
        n += 1;
    }
    assert_eq!(n, 20);
    assert_eq!(lines.next(), Some("zero normal: status 2"));
}
