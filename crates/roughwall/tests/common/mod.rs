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
