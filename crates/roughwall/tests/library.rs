//! The library's integration tests as one binary (ripgrep's `tests/tests.rs` is the model):
//! the physics through the public API only, no command line. Each file of `tests/` is a
//! module here, so its tests keep their names under the file's (`cargo test -p roughwall
//! --test library force_models::`). `no_allocation.rs` (a counting global allocator) and
//! `escape_table_bound.rs` (a per-process bound) stay binaries of their own. A new test file is added below (the test at the end fails
//! until it is).

mod common;

mod c_header;
mod deterministic_hard;
mod deterministic_physics;
mod force_models;
mod stochastic_sampler;
mod surface_table1;

/// The test binaries `Cargo.toml` declares besides this one.
const OWN_BINARIES: [&str; 2] = ["no_allocation", "escape_table_bound"];

/// With `autotests = false`, a file in `tests/` that is neither a module here nor its own
/// `[[test]]` would silently never run.
#[test]
fn every_test_file_is_a_module_of_this_binary_or_its_own_target() {
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let this = include_str!("library.rs");
    let manifest = std::fs::read_to_string(here.join("Cargo.toml")).unwrap();
    for e in std::fs::read_dir(here.join("tests")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "rs") {
            continue;
        }
        let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
        if stem == "library" {
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
                "tests/{stem}.rs is not a module of tests/library.rs: add `mod {stem};`"
            );
        }
    }
}
