//! A finite sphere bouncing in `deterministic` (issue "the particle as a sphere", item 1):
//! `[deterministic] contact = "sphere"` puts the centre on the dilated surface. The hard
//! cases: D → 0 is the centre contact byte for byte, a sphere needs the absolute scale and
//! its diameter, D beyond the surface side is refused, 2-D roughness stays 2-D, grazing
//! incidence runs, and larger spheres see a smoother wall.

use crate::common::*;
use std::path::Path;

fn case(d_um: &str, extra: &str) -> String {
    format!(
        r#"name = "sphere"
seed = 5
[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-5.0, -25.0]
beta_deg = [0.0, 60.0]
speed_mean_m_s = 5.91
[particles]
count = 4000
diameter_um = {d_um}
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
[deterministic]
rms_height_um = 0.37
side_per_corr_length = 40.0
{extra}
"#
    )
}

fn run(dir: &Path, name: &str, body: &str) -> std::path::PathBuf {
    let c = write_case(dir, &format!("{name}.toml"), body);
    run_case("deterministic", &c, &dir.join(name), &[])
}

#[test]
fn a_vanishing_sphere_is_the_centre_contact_byte_for_byte() {
    let tmp = Dir::new();
    let centre = run(tmp.path(), "centre", &case("0.001", ""));
    let sphere = run(tmp.path(), "tiny", &case("0.001", "contact = \"sphere\""));
    assert_eq!(csv_files(&centre), csv_files(&sphere));
    let m = std::fs::read_to_string(sphere.join("run.toml")).unwrap();
    assert!(
        m.contains("[sphere_contact]") && m.contains("contact_fraction = 1.0"),
        "{m}"
    );
}

#[test]
fn larger_spheres_see_a_smoother_wall() {
    let tmp = Dir::new();
    let mut last_std = f64::INFINITY;
    let mut last_dev = f64::INFINITY;
    for d in ["0.001", "50", "250"] {
        let out = run(
            tmp.path(),
            &format!("d{d}"),
            &case(d, "contact = \"sphere\""),
        );
        let s = Csv::read(&out.join("summary.csv"));
        let row = s
            .rows
            .iter()
            .find(|r| s.num(r, "alpha_in_deg") == -25.0 && s.num(r, "beta_in_deg") == 0.0)
            .unwrap();
        let std = s.num(row, "std_alpha_out_deg");
        assert!(std < last_std, "D = {d}: std α⁺ {std} after {last_std}");
        last_std = std;
        let m: toml::Table =
            toml::from_str(&std::fs::read_to_string(out.join("run.toml")).unwrap()).unwrap();
        let dz = m["surface_choice"]["measured_delta_zeta_deg"]
            .as_float()
            .unwrap();
        assert!(dz < last_dev, "D = {d}: Δζ of the centre surface {dz}");
        last_dev = dz;
        assert_eq!(s.num(row, "lost"), 0.0);
    }
}

#[test]
fn two_dimensional_roughness_stays_two_dimensional_and_grazing_runs() {
    let tmp = Dir::new();
    let body = case("100", "contact = \"sphere\"")
        .replace("delta_zeta_deg = 7.5", "delta_zeta_deg = 0.0")
        .replace("alpha_deg = [-5.0, -25.0]", "alpha_deg = [-0.5, -25.0]")
        .replace("beta_deg = [0.0, 60.0]", "beta_deg = [0.0]");
    let out = run(tmp.path(), "twod", &body);
    let s = Csv::read(&out.join("summary.csv"));
    for row in &s.rows {
        // In the plane of the 2-D roughness nothing deviates sideways.
        assert!(s.num(row, "std_dbeta_deg") < 1e-6, "{row:?}");
        assert_eq!(s.num(row, "lost"), 0.0);
        assert!(s.num(row, "particles") > 0.0);
    }
}

#[test]
fn a_sphere_needs_its_scale_and_size_and_must_fit() {
    let tmp = Dir::new();
    for (body, needle) in [
        (
            case("100", "contact = \"sphere\"").replace("rms_height_um = 0.37", ""),
            "deterministic.rms_height_um",
        ),
        (
            case("100", "contact = \"sphere\"").replace("diameter_um = 100\n", ""),
            "particles.diameter_um",
        ),
        (
            case("5000", "contact = \"sphere\""),
            "at most the surface side",
        ),
        (case("100", "contact = \"ball\""), "deterministic.contact"),
    ] {
        let c = write_case(tmp.path(), "bad.toml", &body);
        refuse_case("deterministic", &c, tmp.path(), needle);
    }
}

/// A height file read with `--surface` gives the roughness's absolute scale: a sphere needs
/// nothing more (before, the run asked for `--surface` while one was given).
#[test]
fn a_height_file_gives_a_sphere_its_scale() {
    let tmp = Dir::new();
    let surface = write_case(
        tmp.path(),
        "s.toml",
        "name = \"s\"\nseed = 3\n[surface]\nlength_um = 256.0\nnodes = 256\nrms_height_um = 0.37\ncorr_length_x_um = 12.0\ncorr_length_z_um = 6.0\n",
    );
    let heights = tmp.join("h.rbhf");
    run_case(
        "surface",
        &surface,
        &tmp.join("s"),
        &["--heights", heights.to_str().unwrap()],
    );
    let body = case("20", "contact = \"sphere\"").replace("rms_height_um = 0.37", "");
    let c = write_case(tmp.path(), "sphere.toml", &body);
    let out = run_case(
        "deterministic",
        &c,
        &tmp.join("d"),
        &["--surface", heights.to_str().unwrap()],
    );
    let manifest = std::fs::read_to_string(out.join("run.toml")).unwrap();
    assert!(manifest.contains("[sphere_contact]"), "{manifest}");
}

#[test]
fn the_sphere_run_does_not_repeat_the_scene_warnings() {
    // `effective_for_diameter` resolves the case's deterministic sphere run too; the
    // scene's warnings (here the roughness beyond Eq. 6's range) are given once.
    let tmp = Dir::new();
    let body = case(
        "250",
        "contact = \"sphere\"\n[stochastic]\neffective_for_diameter = true",
    )
    .replace("delta_zeta_deg = 7.5", "delta_zeta_deg = 9.0");
    let c = write_case(tmp.path(), "eff9.toml", &body);
    let out = tmp.path().join("eff9");
    let r = rebound(&[
        "stochastic",
        "--case",
        c.to_str().unwrap(),
        "--particles",
        "200",
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    let n = r.stderr.matches("low-roughness approximation").count();
    assert_eq!(n, 1, "{}", r.stderr);
}

#[test]
fn the_stochastic_model_takes_the_deviations_a_sphere_sees() {
    let tmp = Dir::new();
    let body = case(
        "250",
        "contact = \"sphere\"\n[stochastic]\neffective_for_diameter = true",
    );
    let c = write_case(tmp.path(), "eff.toml", &body);
    let out = run_case("stochastic", &c, &tmp.path().join("eff"), &[]);
    let m: toml::Table =
        toml::from_str(&std::fs::read_to_string(out.join("run.toml")).unwrap()).unwrap();
    let e = m["effective_for_diameter"].as_table().unwrap();
    let eff = e["effective_delta_zeta_deg"].as_float().unwrap();
    let surf = e["surface_delta_zeta_deg"].as_float().unwrap();
    assert!(eff < 0.5 * surf, "{eff} vs {surf}");
    // The summary is labelled with the deviations used.
    let s = Csv::read(&out.join("summary.csv"));
    let used = s.num(&s.rows[0], "delta_zeta_deg");
    assert!((used - eff).abs() < 1e-3, "{used} vs {eff}");
    // ... and it matches the deterministic sphere on the same surface.
    let det = run(tmp.path(), "det", &body);
    let cmp = tmp.path().join("cmp");
    rebound(&[
        "compare",
        "--a",
        det.to_str().unwrap(),
        "--b",
        out.to_str().unwrap(),
        "--out",
        cmp.to_str().unwrap(),
    ])
    .ok();
    let k = Csv::read(&cmp.join("comparison.csv"));
    for r in k
        .rows
        .iter()
        .filter(|r| k.cell(r, "quantity") == "alpha_out")
    {
        // 4000 particles each: KS noise ≈ 0.03 at 0.1 %.
        assert!(k.num(r, "ks") < 0.06, "{r:?}");
    }
    for (extra, needle) in [
        (
            "[stochastic]\neffective_for_diameter = true".to_string(),
            "deterministic.rms_height_um",
        ),
        (
            "contact = \"sphere\"\n[stochastic]\neffective_for_diameter = true".to_string(),
            "particles.diameter_um",
        ),
    ] {
        let mut b = case("250", &extra);
        if needle == "deterministic.rms_height_um" {
            b = b.replace("rms_height_um = 0.37", "");
        } else {
            b = b.replace("diameter_um = 250\n", "");
        }
        let c = write_case(tmp.path(), "bad.toml", &b);
        rebound(&["stochastic", "--case", c.to_str().unwrap()]).refused(needle);
    }
}
