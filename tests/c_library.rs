//! The C library from C (issue 9): the example in `examples/c/` is built with the C compiler
//! the Rust toolchain links with, against `include/roughwall.h` and `libroughwall.so`, and run
//! (the Fortran example needs gfortran: `tests/real_systems/fortran.rs`).
//! * For the same key, the C call returns exactly the Rust call.
//! * Bad input (zero normal, lay along the normal, negative diameter, NaN, NULL) is a status.
//! * 10⁶ C calls on the Sec. 4 glass–steel scene in a rotated, moving frame give rebound
//!   angles whose PDFs match `rebound stochastic` on the same scene within KS 0.01.
//! * A single call starts no thread (`tests/c/threads.c`).

use crate::common::c_examples::{glass_steel, key_hit, run_program as run};
use crate::common::*;
use roughwall::tally::Histogram;

#[test]
fn the_c_example_gives_the_rust_rebounds_and_the_stochastic_statistics() {
    let tmp = Dir::new();
    let root = repo_root();
    let exe = tmp.path().join("rotated_scene");
    build_with_roughwall(
        "cc",
        &[&root.join("examples/c/rotated_scene.c")],
        &exe,
        &["-Wextra"],
    );

    // Identity: each key's rebound, bit for bit.
    let model = glass_steel();
    let keys = run(&exe, &["keys"]);
    let mut n = 0;
    for line in keys.lines().filter(|l| !l.starts_with("bad")) {
        let f: Vec<&str> = line.split_whitespace().collect();
        let pid: u64 = f[0].parse().unwrap();
        let want = model.rebound(&key_hit(pid));
        assert_eq!(f[2], "0", "{line}");
        let bits: Vec<u64> = f[3..9]
            .iter()
            .map(|h| u64::from_str_radix(h, 16).unwrap())
            .collect();
        let expect: Vec<u64> = want
            .velocity
            .iter()
            .chain(&want.spin)
            .map(|x| x.to_bits())
            .collect();
        assert_eq!(bits, expect, "{line}");
        assert_eq!(f[9].parse::<u32>().unwrap(), want.candidate_walls);
        n += 1;
    }
    assert_eq!(n, 20);
    // Zero normal, lay along the normal, negative diameter, NaN: invalid input (2); NULL: 4;
    // and no NaN comes back.
    let bad = keys.lines().find(|l| l.starts_with("bad")).unwrap();
    assert_eq!(bad, "bad 2 2 2 2 4 0");

    // Statistics: 10⁶ hits in a rotated frame against `rebound stochastic`, same scene.
    let bin = tmp.path().join("hits.bin");
    let summary = run(&exe, &["stats", "1000000", bin.to_str().unwrap()]);
    eprintln!("C example: {summary}");
    let bytes = std::fs::read(&bin).unwrap();
    let values: Vec<f64> = bytes
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    assert_eq!(values.len(), 2_000_000);
    let case = write_case(
        tmp.path(),
        "scene.toml",
        r#"name = "c-scene"
seed = 4
[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-15.0]
beta_deg = [60.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16
[particles]
count = 1000000
diameter_um = 500.0
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
"#,
    );
    let out = run_case("stochastic", &case, &tmp.path().join("sm"), &[]);
    for (q, column, lo, hi) in [("alpha_out", 0, -90.0, 90.0), ("dbeta", 1, -180.0, 180.0)] {
        let mut h = Histogram::new(lo, hi, 1.0);
        for v in values.iter().skip(column).step_by(2) {
            h.push(*v);
        }
        let ks = ks_against_run(&h, &out, q);
        eprintln!("C example against rebound stochastic: KS {q} = {ks:.4}");
        assert!(ks <= 0.01, "{q}: KS {ks}");
    }
}

/// A single call starts no thread: `tests/c/threads.c` counts the threads of its (fresh)
/// process in `/proc/self/task` around 3 × 10⁴ `rw_rebound` calls on three walls; the count
/// must see a thread the program starts itself, and the batch call's threads are joined.
#[test]
fn a_single_call_starts_no_thread() {
    let tmp = Dir::new();
    let root = repo_root();
    let exe = tmp.path().join("threads");
    build_with_roughwall(
        "cc",
        &[&root.join("tests/c/threads.c")],
        &exe,
        &["-pthread"],
    );
    let out = run(&exe, &[]);
    let counts: Vec<u32> = out.split_whitespace().map(|x| x.parse().unwrap()).collect();
    // start, after rw_wall_new, most during the calls, with a thread of its own, after a
    // 4-thread batch.
    assert_eq!(counts, [1, 1, 1, 2, 1], "{out}");
}
