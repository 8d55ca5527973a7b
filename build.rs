//! Build script: the source digest behind `BUILD_VERSION` (src/main.rs).
//!
//! The package version (`CARGO_PKG_VERSION`) does not change from commit to commit, so on its
//! own it cannot tell two builds apart. This script hashes what produces the results — every
//! `.rs` file of `src/` (the application), `crates/roughwall/src/` (the library),
//! `crates/topography/src/` (the scan readers) and `crates/outputs/src/` (CSV tables and
//! figures), and their four manifests and `Cargo.lock`, as
//! sorted relative paths with their contents (each length-prefixed) — with 64-bit FNV-1a, and
//! exports the 16 hex digits as `ROUGHWALL_SOURCE_DIGEST`. Partial tallies record
//! `version+src.DIGEST` and `rebound merge` refuses shards of another build. No dependency:
//! FNV-1a is a few lines and needs to tell builds apart, not resist an adversary (the partial
//! tally's checksum is SHA-256).

use std::path::{Path, PathBuf};

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

fn fnv1a(h: &mut u64, bytes: &[u8]) {
    for &b in bytes {
        *h ^= u64::from(b);
        *h = h.wrapping_mul(FNV_PRIME);
    }
}

/// Every `.rs` file under `dir`, recursively; announces every directory to Cargo.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    println!("cargo:rerun-if-changed={}", dir.display());
    let entries = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("build.rs: cannot list {}: {e}", dir.display()));
    for entry in entries {
        let path = entry
            .unwrap_or_else(|e| panic!("build.rs: cannot list {}: {e}", dir.display()))
            .path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            out.push(path);
        }
    }
}

fn main() {
    let root = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    rust_files(&root.join("crates/roughwall/src"), &mut files);
    rust_files(&root.join("crates/topography/src"), &mut files);
    rust_files(&root.join("crates/outputs/src"), &mut files);
    for name in [
        "Cargo.toml",
        "Cargo.lock",
        "crates/roughwall/Cargo.toml",
        "crates/topography/Cargo.toml",
        "crates/outputs/Cargo.toml",
        "crates/roughwall/src/calibrated/aniso-escape.csv",
    ] {
        let path = root.join(name);
        if path.is_file() {
            files.push(path);
        }
    }
    // Relative paths with `/` separators, sorted: the digest does not depend on where the
    // checkout lives, on the platform, or on the order the file system lists entries.
    let mut named: Vec<(String, PathBuf)> = files
        .into_iter()
        .map(|p| {
            let rel = p.strip_prefix(&root).unwrap_or(&p);
            let name = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/");
            (name, p)
        })
        .collect();
    named.sort();
    let mut h = FNV_OFFSET;
    for (name, path) in &named {
        println!("cargo:rerun-if-changed={}", path.display());
        let bytes = std::fs::read(path)
            .unwrap_or_else(|e| panic!("build.rs: cannot read {}: {e}", path.display()));
        fnv1a(&mut h, &(name.len() as u64).to_le_bytes());
        fnv1a(&mut h, name.as_bytes());
        fnv1a(&mut h, &(bytes.len() as u64).to_le_bytes());
        fnv1a(&mut h, &bytes);
    }
    println!("cargo:rustc-env=ROUGHWALL_SOURCE_DIGEST={h:016x}");
}
