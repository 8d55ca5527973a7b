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

/// The registered rough-wall models (`roughwall::AnyModel::NAMES`, whose order is the
/// C library's model index) have their `RW_MODEL_*` constant, with that index, in the header,
/// in the Fortran module, and their name in the benchmark's list (`scripts/wall-models.sh`):
/// a model added to the registry and forgotten in one of them fails here.
#[test]
fn every_registered_model_has_its_constant_in_c_fortran_and_the_benchmark() {
    let root = repo_root();
    let read = |p: &str| std::fs::read_to_string(root.join(p)).unwrap();
    let (header, fortran, bench) = (
        read("include/roughwall.h"),
        read("examples/fortran/roughwall.f90"),
        read("scripts/wall-models.sh"),
    );
    let names = roughwall::AnyModel::NAMES;
    let defined: Vec<(String, usize)> = header
        .lines()
        .filter_map(|l| l.strip_prefix("#define RW_MODEL_"))
        .filter_map(|l| {
            let (name, value) = l.split_once(' ')?;
            Some((format!("RW_MODEL_{name}"), value.trim().parse().ok()?))
        })
        .collect();
    let expected: Vec<(String, usize)> = names
        .iter()
        .enumerate()
        .map(|(i, n)| {
            (
                format!("RW_MODEL_{}", n.to_uppercase().replace('-', "_")),
                i,
            )
        })
        .collect();
    assert_eq!(
        defined, expected,
        "include/roughwall.h against the registry"
    );
    let fortran = fortran.replace(['&', '\n'], " ");
    let fortran: String = fortran.split_whitespace().collect::<Vec<_>>().join(" ");
    for (constant, i) in &expected {
        assert!(
            fortran.contains(&format!("{constant} = {i}")),
            "examples/fortran/roughwall.f90 lacks `{constant} = {i}`"
        );
    }
    let listed = bench
        .lines()
        .find_map(|l| l.strip_prefix("VARIANTS=\""))
        .and_then(|l| l.strip_suffix('"'))
        .expect("VARIANTS=\"…\" in scripts/wall-models.sh");
    assert_eq!(
        listed.split(' ').collect::<Vec<_>>(),
        names,
        "scripts/wall-models.sh's VARIANTS against the registry"
    );
}
