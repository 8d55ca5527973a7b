//! What the tests of the C and Fortran examples share: the wall and the keyed hits of their
//! `keys` mode, and running a built example.

use roughwall::CollisionParams;
use roughwall::{Hit, WallModel, WallParams};
use std::path::Path;
use std::process::Command;

/// The wall of the C and Fortran examples' `keys` mode: Sec. 4 glass on steel, seed 2021.
pub fn glass_steel() -> WallModel {
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
pub fn key_hit(pid: u64) -> Hit {
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

/// Runs a built example without `LD_LIBRARY_PATH` (it must find `libroughwall.so` by the
/// path it was linked with); panics with its stderr unless it succeeds; its stdout.
pub fn run_program(cmd: &Path, args: &[&str]) -> String {
    let o = Command::new(cmd)
        .args(args)
        .env_remove("LD_LIBRARY_PATH")
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "{}: {}",
        cmd.display(),
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8(o.stdout).unwrap()
}
