//! The library tests' helpers: where the repository is, the shipped cases, and the
//! deterministic tests' own surfaces and angle helpers ([`deterministic`]).
#![allow(dead_code)]

pub mod deterministic;

use std::path::{Path, PathBuf};

/// The repository's root (the workspace, two levels above this crate).
pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A shipped case file: `rel` under `configs/` (e.g. `cases/aniso.toml`).
pub fn shipped_case(rel: &str) -> PathBuf {
    let p = repo_root().join("configs").join(rel);
    assert!(p.is_file(), "no shipped case {}", p.display());
    p
}

/// Two-sample Kolmogorov–Smirnov distance (the library's, on copies).
pub fn ks(a: &[f64], b: &[f64]) -> f64 {
    roughwall::tally::ks_samples(&mut a.to_vec(), &mut b.to_vec())
}

/// KS distance two independent samples of these sizes exceed with probability 0.001.
pub fn ks_critical(n: usize, m: usize) -> f64 {
    1.95 * ((n + m) as f64 / (n as f64 * m as f64)).sqrt()
}
