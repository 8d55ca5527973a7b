//! `include/roughwall.h` is what cbindgen generates from `crates/roughwall/src/ffi.rs` (with
//! `crates/roughwall/cbindgen.toml`), so the C header and the Rust declarations cannot drift.
//! After changing `ffi.rs`, regenerate it with
//! `ROUGHWALL_BLESS=1 cargo test -p roughwall --test library c_header`.

use crate::common::repo_root;

#[test]
fn the_header_is_what_cbindgen_generates_from_the_ffi_module() {
    let root = repo_root();
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(here.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_config(config)
        .with_src(here.join("src/ffi.rs"))
        .generate()
        .expect("cbindgen parses src/ffi.rs")
        .write(&mut generated);
    let path = root.join("include/roughwall.h");
    if std::env::var_os("ROUGHWALL_BLESS").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/roughwall.h differs from what cbindgen generates from crates/roughwall/src/ffi.rs; regenerate: ROUGHWALL_BLESS=1 cargo test -p roughwall --test library c_header"
    );
    let text = String::from_utf8(generated).unwrap();
    for name in [
        "rw_wall_new",
        "rw_rebound",
        "rw_rebound_batch",
        "rw_version",
        "typedef struct rw_wall rw_wall",
    ] {
        assert!(text.contains(name), "{name}");
    }
}
