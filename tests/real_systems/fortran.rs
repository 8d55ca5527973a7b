//! The Fortran example (`examples/fortran/`) built with gfortran against `include/` and
//! `libroughwall.so`: for the same key, the Fortran call returns exactly the Rust call, and a
//! zero normal is a status (issue 9).

use crate::common::c_examples::{glass_steel, key_hit, run_program as run};
use crate::common::*;
use roughwall::wall_model::HitStatus;

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
