//! `rebound deterministic` through the binary: bad input is a one-line error naming
//! the key or file, exit status 2, and nothing is written.

use std::path::{Path, PathBuf};
use std::process::Command;

fn rebound(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rebound"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

const GOOD: &str = r#"
name = "t"
[wall]
delta_xi_deg = 2.5
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-12.5]
beta_deg = [0.0, 60.0]
[particles]
count = 2000
[collision]
model = "elastic"
[deterministic]
side_per_corr_length = 20.0
"#;

fn case_with(dir: &Path, replace: &[(&str, &str)]) -> PathBuf {
    let mut text = GOOD.to_string();
    for (a, b) in replace {
        assert!(text.contains(a), "{a}");
        text = text.replace(a, b);
    }
    let p = dir.join("case.toml");
    std::fs::write(&p, text).unwrap();
    p
}

/// Runs `deterministic` on a modified case and checks the refusal.
fn refuses(replace: &[(&str, &str)], extra: &[&str], needle: &str) {
    let dir = tempfile::tempdir().unwrap();
    let case = case_with(dir.path(), replace);
    let out = dir.path().join("out");
    let mut args = vec![
        "deterministic",
        "--case",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let (code, _, err) = rebound(&args);
    assert_eq!(code, 2, "{replace:?} {extra:?}: {err}");
    assert_eq!(err.trim().lines().count(), 1, "not one line: {err}");
    assert!(err.contains(needle), "`{needle}` not in: {err}");
    assert!(
        !out.exists(),
        "something was written for {replace:?} {extra:?}"
    );
}

#[test]
fn incident_angles_out_of_range() {
    refuses(
        &[("alpha_deg = [-12.5]", "alpha_deg = [5.0]")],
        &[],
        "incidence.alpha_deg",
    );
    refuses(
        &[("alpha_deg = [-12.5]", "alpha_deg = [0.0]")],
        &[],
        "incidence.alpha_deg",
    );
    refuses(
        &[("alpha_deg = [-12.5]", "alpha_deg = [-91.0]")],
        &[],
        "incidence.alpha_deg",
    );
    refuses(
        &[("beta_deg = [0.0, 60.0]", "beta_deg = [0.0, 181.0]")],
        &[],
        "incidence.beta_deg",
    );
    refuses(
        &[("alpha_deg = [-12.5]", "alpha_deg = [nan]")],
        &[],
        "alpha_deg",
    );
}

#[test]
fn non_positive_particle_counts() {
    refuses(&[("count = 2000", "count = 0")], &[], "particles.count");
    refuses(&[("count = 2000", "count = -5")], &[], "particles.count");
    refuses(&[], &["--particles", "0"], "--particles");
}

#[test]
fn unknown_collision_model_or_preset() {
    refuses(
        &[("model = \"elastic\"", "model = \"bouncy\"")],
        &[],
        "collision.model",
    );
    refuses(
        &[(
            "model = \"elastic\"",
            "model = \"sommerfeld-huber\"\npreset = \"rubber-ice\"",
        )],
        &[],
        "collision.preset",
    );
}

#[test]
fn bad_deterministic_section() {
    refuses(
        &[("side_per_corr_length = 20.0", "max_collisions = 0")],
        &[],
        "deterministic.max_collisions",
    );
    refuses(
        &[(
            "side_per_corr_length = 20.0",
            "spacing_per_corr_length = 0.1",
        )],
        &[],
        "deterministic.spacing_per_corr_length",
    );
    refuses(
        &[("side_per_corr_length = 20.0", "colisions = 3")],
        &[],
        "colisions",
    );
}

#[test]
fn bad_surface_files() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no-such-surface.bin");
    refuses(
        &[],
        &["--surface", missing.to_str().unwrap()],
        "no-such-surface.bin",
    );
    let garbage = dir.path().join("garbage.bin");
    std::fs::write(&garbage, b"this is not a height field at all, just text\n").unwrap();
    refuses(
        &[],
        &["--surface", garbage.to_str().unwrap()],
        "garbage.bin",
    );
    let empty = dir.path().join("empty.bin");
    std::fs::write(&empty, b"").unwrap();
    refuses(&[], &["--surface", empty.to_str().unwrap()], "empty.bin");
}
