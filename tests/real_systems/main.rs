//! The tests against real systems that no one here wrote: code_saturne running the C
//! library at every wall hit, OpenFOAM's and pysand's erosion laws, a Slurm cluster running
//! shards, the Fortran example built with gfortran, and SurfaceTopography reading the
//! instrument scans that `crates/topography` reads. They need those tools, which
//! `scripts/install-deps.sh` installs; they run only when asked for:
//!
//! ```sh
//! scripts/install-deps.sh
//! cargo test --test real_systems
//! ```
//!
//! (`scripts/test-all.sh`, the README's test command, does both.) A tool that is missing is
//! a failed test naming it and the install step, never a skipped one. That every file here
//! is a module is checked by the hermetic `tests/integration.rs`.

#[path = "../common/mod.rs"]
mod common;

mod code_saturne;
mod erosion_references;
mod fortran;
mod pipe_flow;
mod pipe_forces;
mod python;
mod slurm;
mod surfacetopography;

/// Runs a code_saturne example script (`examples/code_saturne/…/run_checks.sh WORK`) against
/// this build's C library and header, with the extra environment `env`; panics with its
/// output unless it succeeds, and returns its stdout (also printed, for the test's log).
pub fn run_example_checks(
    script: &std::path::Path,
    work: &std::path::Path,
    env: &[(&str, &std::path::Path)],
) -> String {
    let root = common::repo_root();
    let out = std::process::Command::new(script)
        .arg(work)
        .env("ROUGHWALL_INCLUDE", root.join("include"))
        .env("ROUGHWALL_LIB", common::c_library_dir())
        .envs(env.iter().copied())
        .output()
        .unwrap_or_else(|e| panic!("run {}: {e}", script.display()));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    eprintln!("{stdout}");
    stdout
}

/// Fails, naming the install step, unless every command of `tools` is on the `PATH` or in
/// `/usr/sbin`, `/sbin` (where Debian puts daemons such as `slurmctld`, off a non-root
/// user's `PATH`; the scripts that start them add those folders).
pub fn require(tools: &[&str]) {
    let missing: Vec<&str> = tools
        .iter()
        .copied()
        .filter(|c| {
            !std::process::Command::new("sh")
                .args([
                    "-c",
                    &format!("PATH=\"$PATH:/usr/sbin:/sbin\" command -v {c}"),
                ])
                .output()
                .is_ok_and(|o| o.status.success())
        })
        .collect();
    assert!(
        missing.is_empty(),
        "{missing:?} not found: run scripts/install-deps.sh (it installs every tool the real-system tests need)"
    );
}
