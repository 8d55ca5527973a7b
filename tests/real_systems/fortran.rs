//! The Fortran example (`examples/fortran/`) built with gfortran against `libroughwall.so`
//! by the build line `docs/c-library.md` gives: for the same key, the Fortran call returns
//! exactly the Rust call, and a zero normal is a status (issue 9).

use crate::common::c_examples::{glass_steel, key_hit, run_program};
use crate::common::*;
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
}
