//! `rebound surface` end to end: outputs, reproducibility, special walls, bad input.
use crate::common::*;
use roughwall::surface::read_heights;
use std::path::Path;

const SMALL: &str = r#"
name = "small"
seed = 3
[surface]
length_um = 256.0
nodes = 256
rms_height_um = 0.37
corr_length_x_um = 12.0
corr_length_z_um = 4.0
[stats]
beta_star_deg = [0.0, 30.0, 60.0, 90.0]
"#;

fn run_ok(case: &Path, out: &Path, extra: &[&str]) -> Run {
    let mut args = vec![
        "surface",
        "--case",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    rebound(&args).ok()
}

fn csv(out: &Path, name: &str) -> String {
    std::fs::read_to_string(out.join(name)).unwrap()
}

#[test]
fn writes_every_output_with_the_exact_columns_reproducibly_for_any_thread_count() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "small.toml", SMALL);
    let (a, b) = (tmp.path().join("a"), tmp.path().join("b"));
    let (ha, hb) = (tmp.path().join("a.rbhf"), tmp.path().join("b.rbhf"));
    run_ok(
        &case,
        &a,
        &["--threads", "1", "--heights", ha.to_str().unwrap()],
    );
    run_ok(
        &case,
        &b,
        &["--threads", "2", "--heights", hb.to_str().unwrap()],
    );
    let summary = csv(&a, "surface_summary.csv");
    assert!(summary.starts_with(
        "nodes,length_um,spacing_um,rms_height_um,target_rms_height_um,rms_slope_x,target_rms_slope_x,rms_slope_z,target_rms_slope_z,delta_xi_deg,target_delta_xi_deg,delta_zeta_deg,target_delta_zeta_deg,max_height_um\n256,256,1,"
    ));
    let angles = csv(&a, "normal_angles.csv");
    assert!(angles.starts_with(
        "beta_star_deg,delta_xi_star_deg,delta_zeta_star_deg,rho_xi_zeta,rho_xi_eta,rho_eta_zeta,model_delta_xi_star_deg,model_delta_zeta_star_deg,model_rho_xi_zeta\n0,"
    ));
    assert_eq!(angles.lines().count(), 5);
    assert!(!angles.contains("NaN") && !summary.contains("NaN"));
    for f in ["height_map.svg", "normal_angle_pdfs.svg", "run.toml"] {
        assert!(a.join(f).is_file(), "{f}");
    }
    // Byte-identical for 1 and 2 threads; timings live only in run.toml.
    assert_eq!(summary, csv(&b, "surface_summary.csv"));
    assert_eq!(angles, csv(&b, "normal_angles.csv"));
    assert_eq!(std::fs::read(&ha).unwrap(), std::fs::read(&hb).unwrap());
    let run = csv(&a, "run.toml");
    assert!(run.contains("threads = 1") && run.contains("seed = 3"));
    assert!(csv(&b, "run.toml").contains("threads = 2"));
    // The heights file reads back as the 256 × 256 grid.
    let f = read_heights(&ha).unwrap();
    assert_eq!((f.nx, f.nz), (256, 256));
    assert!((f.dx - 1e-6).abs() < 1e-18);
    // Another seed gives another surface.
    let c = tmp.path().join("c");
    run_ok(&case, &c, &["--seed", "4"]);
    assert_ne!(angles, csv(&c, "normal_angles.csv"));
}

#[test]
fn generated_surface_is_periodic() {
    // Height differences across the periodic boundary have the same spread as those
    // between interior neighbours (a non-periodic field would jump by ~√2 h there).
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "small.toml", SMALL);
    let h = tmp.path().join("h.rbhf");
    run_ok(
        &case,
        &tmp.path().join("o"),
        &["--heights", h.to_str().unwrap()],
    );
    let f = read_heights(&h).unwrap();
    let n = f.nx;
    let rms = |pairs: &mut dyn Iterator<Item = (f64, f64)>| {
        let v: Vec<f64> = pairs.map(|(a, b)| (a - b) * (a - b)).collect();
        (v.iter().sum::<f64>() / v.len() as f64).sqrt()
    };
    let across_x = rms(&mut (0..n).map(|iz| (f.at(0, iz), f.at(n - 1, iz))));
    let inside_x = rms(&mut (0..n).map(|iz| (f.at(n / 2, iz), f.at(n / 2 - 1, iz))));
    let across_z = rms(&mut (0..n).map(|ix| (f.at(ix, 0), f.at(ix, n - 1))));
    let inside_z = rms(&mut (0..n).map(|ix| (f.at(ix, n / 2), f.at(ix, n / 2 - 1))));
    for (a, b) in [(across_x, inside_x), (across_z, inside_z)] {
        assert!((a / b - 1.0).abs() < 0.3, "{a} vs {b}");
    }
    // Expected neighbour spread along z: h √(2 (1 − exp(−δ²/c²))), δ/c = 1/4.
    let expect = 0.37e-6 * (2.0 * (1.0 - (-1.0f64 / 16.0).exp())).sqrt();
    assert!(
        (across_z / expect - 1.0).abs() < 0.3,
        "{across_z} vs {expect}"
    );
}

#[test]
fn two_d_roughness_and_flat_walls_are_exact_with_finite_statistics() {
    let tmp = Dir::new();
    let two_d = SMALL.replace("corr_length_z_um = 4.0", "delta_zeta_deg = 0.0");
    let case = write_case(tmp.path(), "2d.toml", &two_d);
    let h = tmp.path().join("2d.rbhf");
    let out = tmp.path().join("2d");
    run_ok(&case, &out, &["--heights", h.to_str().unwrap()]);
    let f = read_heights(&h).unwrap();
    // Stored with nz = 1: exactly constant along z by construction.
    assert_eq!((f.nx, f.nz), (256, 1));
    assert!(f.heights.iter().any(|&y| y != 0.0));
    let summary = Csv::read(&out.join("surface_summary.csv"));
    assert_eq!(summary.rows.len(), 1);
    let row = summary.row(0);
    assert_eq!(&row["rms_slope_z"], "0");
    assert_eq!(&row["target_rms_slope_z"], "0");
    assert_eq!(&row["delta_zeta_deg"], "0");
    assert!(row.cells().iter().all(|c| !c.is_empty()));
    // Δξ* at β* = 90° is the (zero) ζ deviation. With Δζ = 0, Eq. (9) gives
    // Cov = sin β* cos β* Δξ², so ρ = +1 at β* = 30°: ξ* and ζ* both follow ξ exactly.
    let angles = Csv::read(&out.join("normal_angles.csv"));
    let at = |beta: &str| {
        angles
            .records()
            .find(|r| &r["beta_star_deg"] == beta)
            .unwrap_or_else(|| panic!("no β* = {beta}"))
    };
    assert_eq!(&at("90")["delta_xi_star_deg"], "0");
    let r30 = at("30");
    let rho = r30.num("rho_xi_zeta");
    let model = r30.num("model_rho_xi_zeta");
    assert!(
        (rho - model).abs() < 1e-6 && (model - 1.0).abs() < 1e-12,
        "{rho} {model}"
    );

    let flat = SMALL
        .replace("corr_length_z_um = 4.0", "delta_zeta_deg = 0.0")
        .replace("corr_length_x_um = 12.0", "delta_xi_deg = 0.0");
    let case = write_case(tmp.path(), "flat.toml", &flat);
    let h = tmp.path().join("flat.rbhf");
    let out = tmp.path().join("flat");
    run_ok(&case, &out, &["--heights", h.to_str().unwrap()]);
    assert!(read_heights(&h).unwrap().heights.iter().all(|&y| y == 0.0));
    let summary = Csv::read(&out.join("surface_summary.csv"));
    let row = summary.row(0);
    for (column, value) in [
        ("rms_height_um", "0"),
        ("target_rms_height_um", "0.37"),
        ("rms_slope_x", "0"),
        ("target_rms_slope_x", "0"),
        ("rms_slope_z", "0"),
        ("target_rms_slope_z", "0"),
        ("delta_xi_deg", "0"),
        ("target_delta_xi_deg", "0"),
        ("delta_zeta_deg", "0"),
        ("target_delta_zeta_deg", "0"),
        ("max_height_um", "0"),
    ] {
        assert_eq!(&row[column], value, "{column}");
    }
    assert_eq!(row.cells().len(), 3 + 11);
    let angles = Csv::read(&out.join("normal_angles.csv"));
    for r in angles.records() {
        for column in angles.header.iter().filter(|h| *h != "beta_star_deg") {
            assert_eq!(&r[column.as_str()], "0", "{column}: {r:?}");
        }
    }
}

#[test]
fn bad_cases_fail_with_one_line_and_exit_2_writing_nothing() {
    let tmp = Dir::new();
    let mut cases: Vec<(&str, String, &str)> = vec![
        (
            "unknown key",
            SMALL.replace("nodes = 256", "nodes = 256\nnodez = 3"),
            "nodez",
        ),
        (
            "wrong type",
            SMALL.replace("nodes = 256", "nodes = \"many\""),
            "nodes",
        ),
        (
            "missing key",
            SMALL.replace("rms_height_um = 0.37\n", ""),
            "rms_height_um",
        ),
        (
            "negative length",
            SMALL.replace("length_um = 256.0", "length_um = -1.0"),
            "length_um",
        ),
        (
            "zero length",
            SMALL.replace("length_um = 256.0", "length_um = 0.0"),
            "length_um",
        ),
        (
            "too few nodes",
            SMALL.replace("nodes = 256", "nodes = 15"),
            "nodes",
        ),
        (
            "nan",
            SMALL.replace("rms_height_um = 0.37", "rms_height_um = nan"),
            "rms_height_um",
        ),
        (
            "both corr length and delta",
            SMALL.replace(
                "corr_length_x_um = 12.0",
                "corr_length_x_um = 12.0\ndelta_xi_deg = 2.5",
            ),
            "delta_xi_deg",
        ),
        (
            "grid too coarse",
            SMALL.replace("nodes = 256", "nodes = 100"),
            "nodes",
        ),
    ];
    // 40 000² nodes need 25.6 GB: refused up front where that exceeds free memory.
    let avail_kb: Option<u64> = std::fs::read_to_string("/proc/meminfo").ok().and_then(|t| {
        let l = t
            .lines()
            .find(|l| l.starts_with("MemAvailable:"))?
            .to_owned();
        l.split_whitespace().nth(1)?.parse().ok()
    });
    if avail_kb.is_some_and(|kb| kb * 1024 < 25_000_000_000) {
        cases.push((
            "grid too large for memory",
            SMALL
                .replace("nodes = 256", "nodes = 40000")
                .replace("length_um = 256.0", "length_um = 40000.0"),
            "nodes",
        ));
    }
    for (what, text, key) in cases {
        let case = write_case(tmp.path(), "bad.toml", &text);
        let out = tmp.path().join("out");
        let o = rebound(&[
            "surface",
            "--case",
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let err = &o.stderr;
        assert_eq!(o.code, 2, "{what}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{what}: {err}");
        assert!(err.contains(key), "{what}: `{key}` not in {err}");
        assert!(!out.exists(), "{what}: wrote {}", out.display());
    }
}

#[test]
fn a_small_domain_warns_but_runs() {
    let tmp = Dir::new();
    // L = 64 µm < 20 c_Lx = 240 µm.
    let text = SMALL
        .replace("length_um = 256.0", "length_um = 64.0")
        .replace("nodes = 256", "nodes = 64");
    let case = write_case(tmp.path(), "tiny.toml", &text);
    let err = run_ok(&case, &tmp.path().join("o"), &[]).stderr;
    assert!(
        err.contains("warning") && err.contains("corr_length_x_um"),
        "{err}"
    );
}

#[test]
fn a_foreign_or_truncated_heights_file_is_rejected() {
    let tmp = Dir::new();
    let p = tmp.path().join("x.rbhf");
    std::fs::write(&p, b"P6\n2 2\n255\n0123456789ab").unwrap();
    let e = read_heights(&p).unwrap_err();
    assert_eq!(e.exit_code(), 2);
    assert!(e.to_string().contains("x.rbhf"));
}

/// A sphere on a flat surface sees no roughness, and its ratios to the surface's deviations
/// are 0/0: `[stats] diameter_um` on a surface of rms height 0 is refused, naming the key,
/// with nothing written.
#[test]
fn effective_roughness_of_a_flat_surface_is_refused() {
    let tmp = Dir::new();
    let case = write_case(
        tmp.path(),
        "flat.toml",
        "name = \"flat\"\n[surface]\nlength_um = 256.0\nnodes = 256\nrms_height_um = 0.0\n\
         delta_xi_deg = 3.0\ndelta_zeta_deg = 3.0\n[stats]\ndiameter_um = [50.0]\n",
    );
    refuse_case("surface", &case, tmp.path(), "stats.diameter_um");
}
