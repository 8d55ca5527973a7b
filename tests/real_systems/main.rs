//! The tests against real systems that no one here wrote: code_saturne running the C
//! library at every wall hit, OpenFOAM's and pysand's erosion laws, a Slurm cluster running
//! shards, and the Fortran example built with gfortran. They need those tools, which
//! `scripts/install-deps.sh` installs; they run only when asked for:
//!
//! ```sh
//! scripts/install-deps.sh
//! cargo test --features real-systems --test real_systems
//! ```
//!
//! (`scripts/test-all.sh`, the README's test command, does both.) A tool that is missing is
//! a failed test naming it and the install step, never a skipped one.

#[path = "../common/mod.rs"]
mod common;

mod code_saturne;
mod erosion_references;
mod fortran;
mod slurm;

/// Fails, naming the install step, unless every command of `tools` is on the `PATH`.
pub fn require(tools: &[&str]) {
    let missing: Vec<&str> = tools
        .iter()
        .copied()
        .filter(|c| {
            !std::process::Command::new("sh")
                .args(["-c", &format!("command -v {c}")])
                .output()
                .is_ok_and(|o| o.status.success())
        })
        .collect();
    assert!(
        missing.is_empty(),
        "{missing:?} not found: run scripts/install-deps.sh (it installs every tool the real-system tests need)"
    );
}

/// With `autotests = false`, a file here that is not a module would silently never run.
#[test]
fn every_file_here_is_a_module() {
    let here = common::repo_root().join("tests/real_systems");
    let this = include_str!("main.rs");
    for e in std::fs::read_dir(&here).unwrap() {
        let p = e.unwrap().path();
        let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
        if p.extension().is_some_and(|x| x == "rs") && stem != "main" {
            assert!(
                this.lines().any(|l| l == format!("mod {stem};")),
                "tests/real_systems/{stem}.rs is not a module of main.rs"
            );
        }
    }
}
