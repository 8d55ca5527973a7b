//! The Python package `roughwall` (issue 32, crates/roughwall-py): built into an abi3 wheel
//! by maturin, installed with one `pip install` into the project's virtual environment
//! ($REBOUND_VENV, default .venv, where scripts/install-deps.sh puts maturin, pytest, NumPy
//! and matplotlib), then its pytest suite (crates/roughwall-py/tests), which checks the
//! package against the C library of this build (every bit of 10⁵ rebounds, the one-line
//! messages) and against this build's `rebound` (wall cards, stochastic and deterministic
//! runs), and runs the example client examples/python/channel.py small. The crate is not a
//! member of the workspace (it needs Python to build), so its formatting and lints are
//! checked here too.

use crate::common::{c_library_dir, rebound_bin, repo_root};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

fn venv() -> PathBuf {
    std::env::var_os("REBOUND_VENV")
        .map(PathBuf::from)
        .unwrap_or_else(|| repo_root().join(".venv"))
}

/// The venv's `tool`, or a failure naming the install step.
fn venv_tool(tool: &str) -> PathBuf {
    let p = venv().join("bin").join(tool);
    assert!(
        p.is_file(),
        "{} not found: run scripts/install-deps.sh (it installs maturin, pytest, NumPy and matplotlib into the virtual environment)",
        p.display()
    );
    p
}

fn run(cmd: &mut Command, what: &str) {
    let status = cmd
        .status()
        .unwrap_or_else(|e| panic!("{what}: could not start: {e}"));
    assert!(status.success(), "{what} failed ({status})");
}

/// PATH with the venv's bin first, so that maturin and cargo find the venv's Python.
fn path_with_venv() -> String {
    let old = std::env::var("PATH").unwrap_or_default();
    format!("{}:{old}", venv().join("bin").display())
}

fn crate_dir() -> PathBuf {
    repo_root().join("crates/roughwall-py")
}

/// The wheel, built and installed once per test process (the tests share it; pip must not
/// install it twice at once).
fn installed() -> &'static Path {
    static WHEEL: OnceLock<PathBuf> = OnceLock::new();
    WHEEL.get_or_init(|| {
        let out = repo_root().join("target/python-wheel");
        let _ = std::fs::remove_dir_all(&out);
        std::fs::create_dir_all(&out).unwrap();
        build_and_install(&out)
    })
}

/// Builds the wheel into `out` and installs it; returns the wheel.
fn build_and_install(out: &Path) -> PathBuf {
    let (maturin, python) = (venv_tool("maturin"), venv_tool("python"));
    run(
        Command::new(&maturin)
            .args(["build", "--release", "--out"])
            .arg(out)
            .arg("--interpreter")
            .arg(&python)
            .current_dir(crate_dir())
            .env("PATH", path_with_venv())
            .env("CARGO_BUILD_JOBS", "2"),
        "maturin build",
    );
    let wheel = std::fs::read_dir(out)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| p.extension().is_some_and(|x| x == "whl"))
        .expect("maturin wrote no wheel");
    let name = wheel.file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        name.contains("-cp39-abi3-"),
        "not an abi3 wheel for CPython ≥ 3.9: {name}"
    );
    run(
        Command::new(&python)
            .args([
                "-m",
                "pip",
                "install",
                "--quiet",
                "--force-reinstall",
                "--no-deps",
            ])
            .arg(&wheel),
        "pip install of the wheel",
    );
    wheel
}

#[test]
fn the_wheel_installs_and_its_tests_pass() {
    let pytest = venv_tool("pytest");
    installed();
    let out = tempfile::tempdir().unwrap();
    let lib = c_library_dir().join("libroughwall.so");
    run(
        Command::new(venv_tool("python"))
            .args(["-m", "pytest", "-q", "-p", "no:cacheprovider"])
            .arg(crate_dir().join("tests"))
            .current_dir(out.path())
            .env("ROUGHWALL_CLIB", &lib)
            .env("REBOUND_BIN", rebound_bin()),
        &format!("{} (crates/roughwall-py/tests)", pytest.display()),
    );
}

#[test]
fn the_example_writes_its_figure() {
    let python = venv_tool("python");
    installed();
    let out = tempfile::tempdir().unwrap();
    let fig = out.path().join("channel.png");
    run(
        Command::new(&python)
            .arg(repo_root().join("examples/python/channel.py"))
            .args(["--particles", "300", "--steps", "600", "--out"])
            .arg(&fig)
            .current_dir(out.path()),
        "examples/python/channel.py",
    );
    let png = std::fs::read(&fig).unwrap();
    assert!(
        png.starts_with(b"\x89PNG") && png.len() > 10_000,
        "{}",
        fig.display()
    );
}

#[test]
fn the_crate_is_formatted_and_lint_free() {
    let manifest = crate_dir().join("Cargo.toml");
    run(
        Command::new("cargo")
            .args(["fmt", "--check", "--manifest-path"])
            .arg(&manifest),
        "cargo fmt --check (crates/roughwall-py)",
    );
    run(
        Command::new("cargo")
            .args(["clippy", "-j", "2", "--all-targets", "--manifest-path"])
            .arg(&manifest)
            .args(["--", "-D", "warnings"])
            .env("PATH", path_with_venv()),
        "cargo clippy (crates/roughwall-py)",
    );
}
