//! The application's integration tests as one binary (ripgrep's `tests/tests.rs` is the
//! model): the `rebound` binary end to end, and the library's public API where a test sets
//! the command line beside it. Cargo compiles and links one test executable instead of one
//! per file. Each file of `tests/` is a module here, so its tests keep their names under the
//! file's (`cargo test zero_threads_is_rejected`, `cargo test --test integration cli::`).
//! `Cargo.toml` sets `autotests = false` and lists this target. `fuzz_cases.rs` stays a
//! binary of its own: it runs thousands of cases on every core under wall-time caps, so it
//! must not share the machine with the other tests; `real_systems/` is the target of the
//! tests against real systems (feature `real-systems`). The library's own tests are in
//! `crates/roughwall/tests/`. A new test file is added below (the test at the end fails
//! until it is).

mod common;

mod c_library;
mod calibrated_model;
mod cli;
mod compare_cli;
mod deterministic_cli;
mod effective_roughness;
mod erosion_cli;
mod force_sweep_cli;
mod layering;
mod out_dir_safety;
mod scripts;
mod shards_cli;
mod sphere_contact;
mod spin;
mod stochastic_cli;
mod stochastic_model;
mod stochastic_variants;
mod surface_cli;
mod wall_messages;

/// The test binaries `Cargo.toml` declares besides this one.
const OWN_BINARIES: [&str; 1] = ["fuzz_cases"];

/// With `autotests = false`, a file in `tests/` that is neither a module here nor its own
/// `[[test]]` would silently never run.
#[test]
fn every_test_file_is_a_module_of_this_binary_or_its_own_target() {
    let root = common::repo_root();
    let this = include_str!("integration.rs");
    let manifest = std::fs::read_to_string(root.join("Cargo.toml")).unwrap();
    for e in std::fs::read_dir(root.join("tests")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "rs") {
            continue;
        }
        let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
        if stem == "integration" {
            continue;
        }
        if OWN_BINARIES.contains(&stem.as_str()) {
            assert!(
                manifest.contains(&format!("path = \"tests/{stem}.rs\"")),
                "tests/{stem}.rs is not a [[test]] of Cargo.toml"
            );
        } else {
            assert!(
                this.lines().any(|l| l == format!("mod {stem};")),
                "tests/{stem}.rs is not a module of tests/integration.rs: add `mod {stem};`"
            );
        }
    }
}
