//! The Fortran example (`examples/fortran/`) built with gfortran against `libroughwall.so`
//! by the build line `docs/c-library.md` gives: for the same key, the Fortran call returns
//! exactly the Rust call, and a zero normal is a status (issue 9); the carrier laws between
//! hits (`rw_saffman_mei_lift`, `rw_magnus_lift`, `rw_spin_relax`) through the module's
//! interfaces return exactly `roughwall::carrier`'s, and a negative time step is a status.

use crate::common::c_examples::{glass_steel, key_hit, run_program};
use crate::common::*;
use roughwall::carrier::{magnus_lift, relaxed_spin, saffman_mei_lift, FluidPoint};
use roughwall::HitStatus;

#[test]
fn the_fortran_example_gives_the_rust_rebounds() {
    crate::require(&["gfortran"]);
    let tmp = Dir::new();
    let root = repo_root();
    // The documented build line, run as written in a folder laid out like the repository
    // (`target/release` the library this test was built with), and the program run without
    // LD_LIBRARY_PATH: it must find the library by itself.
    let doc = std::fs::read_to_string(root.join("docs/c-library.md")).unwrap();
    let line = doc
        .lines()
        .find_map(|l| l.strip_prefix("Build: `gfortran"))
        .and_then(|l| l.split('`').next())
        .map(|rest| format!("gfortran{rest}"))
        .expect("docs/c-library.md has a `Build: gfortran …` line");
    for f in ["roughwall.f90", "hits.f90"] {
        let to = if f == "hits.f90" { "app.f90" } else { f };
        std::fs::copy(root.join("examples/fortran").join(f), tmp.join(to)).unwrap();
    }
    std::fs::create_dir_all(tmp.join("target")).unwrap();
    std::os::unix::fs::symlink(c_library_dir(), tmp.join("target/release")).unwrap();
    let built = std::process::Command::new("sh")
        .args(["-c", &line])
        .current_dir(tmp.path())
        .output()
        .unwrap();
    assert!(
        built.status.success(),
        "{line}: {}",
        String::from_utf8_lossy(&built.stderr)
    );
    let text = run_program(&tmp.join("a.out"), &[]);
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
    // The states the program sets (hits.f90), and what the Rust laws give for them.
    for pid in 0..3 {
        let line = lines.next().expect("a carrier line");
        let f: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(f[..2], ["carrier", &pid.to_string()], "{line}");
        let k = pid as f64;
        let p = FluidPoint {
            rho_f: 1.204,
            mu_f: 1.825e-5,
            rho_p: 2500.0,
            d_p: 100.0e-6,
            slip: [1.5 - 0.5 * k, -0.05 * k, 0.02],
            vorticity: [0.0, 30.0 * k, -800.0 - 400.0 * k],
            spin: [10.0 * k, -20.0, 3000.0 - 1500.0 * k],
        };
        let got: Vec<f64> = f[2..11].iter().map(|x| x.parse().unwrap()).collect();
        let expect: Vec<f64> = saffman_mei_lift(&p)
            .into_iter()
            .chain(magnus_lift(&p))
            .chain(relaxed_spin(&p, 1.0e-3))
            .collect();
        assert_eq!(got, expect, "{line}");
        // Not a trivial state: both lifts act and the spin moves.
        assert!(got[..3].iter().any(|a| a.abs() > 0.1), "{line}");
        assert!(got[3..6].iter().any(|a| a.abs() > 0.1), "{line}");
        assert_ne!(got[6..], p.spin[..], "{line}");
    }
    assert_eq!(lines.next(), Some("negative dt: status 2"));
    assert_eq!(lines.next(), None);
}
