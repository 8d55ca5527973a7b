//! The application's integration tests as one binary (ripgrep's `tests/tests.rs` is the
//! model): the `rebound` binary end to end, and the library's public API where a test sets
//! the command line beside it. Cargo compiles and links one test executable instead of one
//! per file. Each file of `tests/` is a module here, so its tests keep their names under the
//! file's (`cargo test zero_threads_is_rejected`, `cargo test --test integration cli::`).
//! `Cargo.toml` sets `autotests = false` and lists this target. `fuzz_cases.rs` stays a
//! binary of its own: it runs thousands of cases on every core under wall-time caps, so it
//! does not share the machine with the other hermetic tests (`scripts/test-all.sh` runs the
//! real-system tests beside it: its caps are 20 s of CPU and 60 s of wall time a case, and its
//! heaviest cases, 100 000-point force sweeps, take 3.75 s of CPU alone and 16 s of wall time
//! among its four workers, 2026-11-30); `real_systems/` is the target of the
//! tests against real systems (`test = false`: `cargo test --test real_systems`). The
//! library's own tests are in `crates/roughwall/tests/`. A new test file is added below (the test at the end fails
//! until it is, for this crate's `tests/` and the library's).

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
mod pipe_stats_cli;
mod scan_cli;
mod scripts;
mod shards_cli;
mod sphere_contact;
mod spin;
mod stochastic_cli;
mod stochastic_model;
mod stochastic_variants;
mod surface_cli;
mod wall_messages;

/// With `autotests = false`, a test file that is neither a `[[test]]` target of its crate's
/// `Cargo.toml` nor a module of one would silently never run. Checked here for the three crates
/// of the workspace: their `tests/*.rs` and the files beside a target's `main.rs`.
#[test]
fn every_test_file_is_a_test_target_or_a_module_of_one() {
    for krate in [
        common::repo_root().to_path_buf(),
        common::repo_root().join("crates/roughwall"),
        common::repo_root().join("crates/topography"),
    ] {
        let manifest = std::fs::read_to_string(krate.join("Cargo.toml")).unwrap();
        let targets: Vec<&str> = manifest
            .lines()
            .filter_map(|l| l.strip_prefix("path = \"tests/")?.strip_suffix('"'))
            .collect();
        let harnesses: Vec<String> = targets
            .iter()
            .filter(|t| !t.contains('/'))
            .map(|t| std::fs::read_to_string(krate.join("tests").join(t)).unwrap())
            .collect();
        let is_module = |text: &str, stem: &str| text.lines().any(|l| l == format!("mod {stem};"));
        for stem in rust_stems(&krate.join("tests")) {
            assert!(
                targets.contains(&format!("{stem}.rs").as_str())
                    || harnesses.iter().any(|h| is_module(h, &stem)),
                "{}/tests/{stem}.rs is neither a [[test]] of its Cargo.toml nor a `mod {stem};` of one",
                krate.display()
            );
        }
        for dir_target in targets.iter().filter_map(|t| t.strip_suffix("/main.rs")) {
            let main =
                std::fs::read_to_string(krate.join("tests").join(dir_target).join("main.rs"))
                    .unwrap();
            for stem in rust_stems(&krate.join("tests").join(dir_target)) {
                assert!(
                    stem == "main" || is_module(&main, &stem),
                    "tests/{dir_target}/{stem}.rs is not a `mod {stem};` of tests/{dir_target}/main.rs"
                );
            }
        }
    }
}

/// The stems of the `.rs` files directly in `dir`.
fn rust_stems(dir: &std::path::Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect()
}
