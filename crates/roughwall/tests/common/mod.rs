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

/// Two-sample Kolmogorov–Smirnov distance.
pub fn ks(a: &[f64], b: &[f64]) -> f64 {
    let mut a = a.to_vec();
    let mut b = b.to_vec();
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    let (mut i, mut j, mut d) = (0, 0, 0.0f64);
    while i < a.len() && j < b.len() {
        let x = a[i].min(b[j]);
        while i < a.len() && a[i] <= x {
            i += 1;
        }
        while j < b.len() && b[j] <= x {
            j += 1;
        }
        d = d.max((i as f64 / a.len() as f64 - j as f64 / b.len() as f64).abs());
    }
    d
}

/// KS distance two independent samples of these sizes exceed with probability 0.001.
pub fn ks_critical(n: usize, m: usize) -> f64 {
    1.95 * ((n + m) as f64 / (n as f64 * m as f64)).sqrt()
}
