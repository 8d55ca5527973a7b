//! `rebound scan` end to end (issue 29, parts 2 and 5): the built-in self-check gives back the
//! generated wall, a real scan gives what the library measures on it, a turned scan turns
//! its lay, the wall card pastes into a case and runs as `--wall-card`, the per-diameter
//! rows are the library's, bad input is one line, and the outputs do not depend on the
//! thread count.

use crate::common::*;
use roughwall::scan::characterise;
use roughwall::ScanField;
use std::path::{Path, PathBuf};

/// The files every run with a lay writes (`wall_card_diameters.csv` has the point particle's
/// row and, with diameters, one per sphere).
const OUTPUTS: [&str; 8] = [
    "scan_summary.csv",
    "wall_card.toml",
    "wall_card_diameters.csv",
    "height_map.svg",
    "slope_angle_pdfs.svg",
    "autocorrelation.svg",
    "autocorrelation_map.svg",
    "run.toml",
];

/// The single row of `scan_summary.csv` in `out`, its header checked against the docs.
fn summary(out: &Path) -> Csv {
    let c = Csv::read(&out.join("scan_summary.csv"));
    assert_eq!(c.header.join(","), headers::SCAN_SUMMARY);
    assert_eq!(c.rows.len(), 1);
    c
}

fn card(out: &Path) -> toml::Table {
    let text = std::fs::read_to_string(out.join("wall_card.toml")).unwrap();
    text.parse()
        .unwrap_or_else(|e| panic!("wall_card.toml: {e}\n{text}"))
}

fn real_scan(name: &str) -> PathBuf {
    repo_root().join("tests/data/scans").join(name)
}

/// What the library measures on a scan file, levelled by a plane.
fn library(path: &Path) -> roughwall::scan::Characterisation {
    let t = topography::read(path).unwrap();
    let f = ScanField::new(t.nx, t.ny, t.dx_m, t.dy_m, t.heights_m).unwrap();
    characterise(f, 1).unwrap()
}

/// `a` within `rel` of `b`.
fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// Without `--case`: the Sec. 3 wall (2.5°, 7.5°) generated and read as a scan gives itself
/// back, with the lay along the scan's x; the outputs are the same bytes for 1 and 2 threads.
#[test]
fn the_builtin_self_check_gives_back_the_generated_wall_for_any_thread_count() {
    let dir = Dir::new();
    let one = dir.join("one");
    let two = dir.join("two");
    let r = rebound(&["scan", "--threads", "1", "--out", one.to_str().unwrap()]).ok();
    assert!(
        r.stderr
            .starts_with("scan: 2560 × 2560 generated wall, lay "),
        "{}",
        r.stderr
    );
    rebound(&["scan", "--threads", "2", "--out", two.to_str().unwrap()]).ok();
    for f in OUTPUTS {
        assert!(one.join(f).is_file(), "{f}");
        if f != "run.toml" {
            assert_eq!(
                std::fs::read(one.join(f)).unwrap(),
                std::fs::read(two.join(f)).unwrap(),
                "{f} differs between --threads 1 and 2"
            );
        }
    }
    let c = summary(&one);
    let row = c.row(0);
    assert_eq!((&row["file"], &row["format"]), ("", "generated"));
    assert_eq!((row.num("nx"), row.num("ny")), (2560.0, 2560.0));
    // The wall is built so that its triangles have the deviations asked for
    // (`wall_deviations = "normal-angles"`): one 100-c_L surface is within its own scatter
    // (measured −0.35 %, −0.09 %); Eq. (15)'s grid would have had −1.0 % and −2.1 %.
    assert!(close(row.num("delta_xi_deg"), 2.5, 0.01), "{row:?}");
    assert!(close(row.num("delta_zeta_deg"), 7.5, 0.01), "{row:?}");
    assert!(row.num("lay_deg").abs() < 1.0, "{row:?}");
    // The generator's correlation lengths (run.toml [scan], c_L = √2 h/Δ), back from the
    // autocorrelation's 1/e lags within a few per cent.
    let manifest: toml::Table =
        toml::from_str(&std::fs::read_to_string(one.join("run.toml")).unwrap()).unwrap();
    let find = |key: &str| -> f64 {
        fn walk(t: &toml::Table, key: &str) -> Option<f64> {
            t.iter().find_map(|(k, v)| match v {
                toml::Value::Float(x) if k == key => Some(*x),
                toml::Value::Table(t) => walk(t, key),
                _ => None,
            })
        }
        walk(&manifest, key).unwrap_or_else(|| panic!("no {key} in run.toml"))
    };
    assert!(
        close(
            row.num("corr_length_along_um"),
            find("corr_length_x_um"),
            0.03
        ),
        "{row:?}"
    );
    assert!(
        close(
            row.num("corr_length_across_um"),
            find("corr_length_z_um"),
            0.03
        ),
        "{row:?}"
    );
    // Gaussian slopes, the scan's own axes are the lay's.
    for k in ["skewness_xi", "skewness_zeta"] {
        assert!(row.num(k).abs() < 0.1, "{row:?}");
    }
    for k in ["kurtosis_xi", "kurtosis_zeta"] {
        assert!((row.num(k) - 3.0).abs() < 0.2, "{row:?}");
    }
    assert!(close(
        row.num("delta_scan_x_deg"),
        row.num("delta_xi_deg"),
        1e-3
    ));
    assert!(close(
        row.num("delta_scan_y_deg"),
        row.num("delta_zeta_deg"),
        1e-3
    ));
    // The card says the same, and has nothing to warn about.
    let t = card(&one);
    assert_eq!(
        t["wall"]["delta_xi_deg"].as_float(),
        Some(row.num("delta_xi_deg"))
    );
    assert_eq!(
        t["wall"]["delta_zeta_deg"].as_float(),
        Some(row.num("delta_zeta_deg"))
    );
    assert_eq!(t["lay"]["angle_deg"].as_float(), Some(row.num("lay_deg")));
    assert_eq!(t["notes"].as_array().map(Vec::len), Some(0));
    // Without diameters: no dilation, no rows; the point particle's resolution check, which
    // the card's header points to, is still written.
    assert!(t.get("diameter").is_none());
    let rows = Csv::read(&one.join("wall_card_diameters.csv"));
    assert_eq!(rows.rows.len(), 1);
    assert_eq!(rows.row(0).num("diameter_um"), 0.0);
    assert_eq!(
        rows.row(0).num("delta_xi_deg"),
        t["wall"]["delta_xi_deg"].as_float().unwrap()
    );
    assert!(rows.row(0).num("delta_xi_deg_2x_pixel").is_finite());
    let manifest = std::fs::read_to_string(one.join("run.toml")).unwrap();
    assert!(!manifest.contains("centre_surfaces_s") && manifest.contains("correlation_map_s"));
    assert!(manifest.contains("[surface_choice]") && manifest.contains("source = \"auto\""));
    // The chain measures what `deterministic` measures on the same surface (same seed, same
    // automatic grid, its triangles but for the periodic seam), to the 4 decimals of its
    // run.toml: the shipped Sec. 3 case without its pin to the paper's Eq. (15) walls.
    let det = dir.join("det");
    let aniso = read_shipped_case("cases/aniso.toml");
    let unpinned = aniso.replace("wall_deviations = \"eq15\"\n", "");
    assert_ne!(unpinned, aniso);
    let case = dir.join("aniso-normal-angles.toml");
    std::fs::write(&case, unpinned).unwrap();
    run_case("deterministic", &case, &det, &["--particles", "1"]);
    let m: toml::Table = std::fs::read_to_string(det.join("run.toml"))
        .unwrap()
        .parse()
        .unwrap();
    for (key, col) in [
        ("measured_delta_xi_deg", "delta_xi_deg"),
        ("measured_delta_zeta_deg", "delta_zeta_deg"),
    ] {
        let want = m["surface_choice"][key].as_float().unwrap();
        assert!(
            (row.num(col) - want).abs() < 2e-4,
            "{col}: {row:?} vs {want}"
        );
    }
}

/// A real scan with missing points (`sur-2.sur`) gives the same bytes for 1 and 2 threads:
/// every row sum of the levelling, the parameters, the lay and the autocorrelation is taken
/// in a fixed order, however the rows are shared out.
#[test]
fn a_scan_with_missing_points_gives_the_same_bytes_for_any_thread_count() {
    let dir = Dir::new();
    let scan = real_scan("sur-2.sur");
    let outs = ["1", "2"].map(|threads| {
        let out = dir.join(threads);
        rebound(&[
            "scan",
            "--scan",
            scan.to_str().unwrap(),
            "--threads",
            threads,
            "--out",
            out.to_str().unwrap(),
        ])
        .ok();
        out
    });
    assert!(summary(&outs[0]).row(0).num("missing_fraction") > 0.0);
    for f in OUTPUTS {
        if f != "run.toml" {
            assert_eq!(
                std::fs::read(outs[0].join(f)).unwrap(),
                std::fs::read(outs[1].join(f)).unwrap(),
                "{f} differs between --threads 1 and 2"
            );
        }
    }
}

/// The shipped cases of two real scans: Sq, Sdq, the deviations and the lay are what
/// `roughwall::scan::characterise` gives for the same file, to the 7 digits of the
/// CSV; the card's [wall] pastes into a stochastic case, which then runs on those deviations.
#[test]
fn a_real_scan_gives_what_the_library_measures_and_its_card_pastes_into_a_case() {
    let dir = Dir::new();
    for (case, file) in [
        ("scans/x3p-2.toml", "x3p-2.x3p"),
        ("scans/plu-1.toml", "plu-1.plu"),
    ] {
        let out = dir.join(file);
        run_case("scan", &shipped_case(case), &out, &[]);
        let c = summary(&out);
        let row = c.row(0);
        assert!(
            row["file"].ends_with(&format!("tests/data/scans/{file}")),
            "{row:?}"
        );
        assert!(!row["file"].contains(".."), "{row:?}");
        let lib = library(&real_scan(file));
        let p = lib.parameters;
        let lay = lib.lay.unwrap();
        for (col, want) in [
            ("sq_um", p.sq_m * 1e6),
            ("sdq", p.sdq.unwrap()),
            ("sdq_x", p.sdq_x.unwrap()),
            ("sdq_y", p.sdq_y.unwrap()),
            ("ssk", p.ssk),
            ("sku", p.sku),
            ("delta_xi_deg", lay.delta_xi.to_degrees()),
            ("delta_zeta_deg", lay.delta_zeta.to_degrees()),
            ("lay_deg", lay.angle.to_degrees()),
        ] {
            assert!(
                close(row.num(col), want, 1e-6),
                "{file} {col}: {row:?} vs {want}"
            );
        }
        assert_eq!(row.num("valid_points"), p.valid_points as f64);
        for f in OUTPUTS {
            assert!(out.join(f).is_file(), "{file}: {f}");
        }
        // Both real walls are far from Gaussian along the lay: the card says so.
        let t = card(&out);
        let notes: Vec<&str> = t["notes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_str().unwrap())
            .collect();
        let shape = notes
            .iter()
            .find(|n| n.starts_with("slopes far from Gaussian: ξ'"))
            .unwrap_or_else(|| panic!("{file}: {notes:?}"));
        // The note says what the shape does: the paper's model against the scan itself, by
        // more than the check's noise (x3p-2: KS 0.19; the study's 2 × 10⁵ histories: 0.12).
        let ks: f64 = shape
            .split("a KS distance of α⁺ up to ")
            .nth(1)
            .and_then(|r| r.split(' ').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or_else(|| panic!("{file}: {shape}"));
        assert!(
            ks > roughwall::gaussian_cost::ks_noise()
                && shape.contains("model = \"measured-wall\""),
            "{file}: {shape}"
        );
        // Paste [wall] into a stochastic case: it runs with the card's deviations.
        let text = std::fs::read_to_string(out.join("wall_card.toml")).unwrap();
        let wall = text
            .split("\n[wall]\n")
            .nth(1)
            .unwrap()
            .split("\n[")
            .next()
            .unwrap();
        let scene = dir.write_case(
            &format!("{file}.toml"),
            &format!(
                "name = \"pasted\"\n[wall]\n{wall}\n[incidence]\nalpha_deg = [-10.0]\n[particles]\ncount = 2000\n"
            ),
        );
        let sm = run_case("stochastic", &scene, &dir.join(format!("{file}-sm")), &[]);
        let s = Csv::read(&sm.join("summary.csv"));
        let r = s.row(0);
        assert_eq!(&r["delta_xi_deg"], &row["delta_xi_deg"]);
        assert_eq!(&r["delta_zeta_deg"], &row["delta_zeta_deg"]);
    }
}

/// The same scan turned by +90° (written as a plain matrix: row `iy'` of the turned scan is
/// column `iy'` of the original, read from its last row up) has its lay turned by 90° and the
/// same deviations, Sq and Sdq; Sdq's components swap.
#[test]
fn a_scan_turned_by_90_degrees_turns_its_lay_and_keeps_its_deviations() {
    let dir = Dir::new();
    let t = topography::read(&real_scan("x3p-2.x3p")).unwrap();
    let (nx, ny) = (t.nx, t.ny);
    // Turned: (x, y) → (−y, x). New point (i, j) is the old point (j, ny − 1 − i).
    let mut text = String::with_capacity(nx * ny * 24);
    for j in 0..nx {
        let row: Vec<String> = (0..ny)
            .map(|i| format!("{:e}", t.heights_m[(ny - 1 - i) * nx + j] * 1e6))
            .collect();
        text += &row.join(" ");
        text += "\n";
    }
    std::fs::write(dir.join("turned.txt"), text).unwrap();
    let case = dir.write_case(
        "turned.toml",
        &format!(
            "name = \"turned\"\n[scan]\nfile = \"turned.txt\"\nformat = \"matrix\"\npixel_um = [{:e}, {:e}]\nheight_unit_um = 1.0\n",
            t.dy_m * 1e6,
            t.dx_m * 1e6
        ),
    );
    let turned = run_case("scan", &case, &dir.join("turned"), &[]);
    let original = dir.join("original");
    rebound(&[
        "scan",
        "--scan",
        real_scan("x3p-2.x3p").to_str().unwrap(),
        "--out",
        original.to_str().unwrap(),
    ])
    .ok();
    let (a, b) = (summary(&original), summary(&turned));
    let (a, b) = (a.row(0), b.row(0));
    assert_eq!(&b["format"], "matrix");
    assert_eq!((b.num("nx"), b.num("ny")), (a.num("ny"), a.num("nx")));
    // The lay (in (−90°, 90°]) turns by 90°, modulo 180°.
    let turn = (b.num("lay_deg") - a.num("lay_deg")).rem_euclid(180.0);
    // Measured: 89.996°.
    assert!((turn - 90.0).abs() < 0.05, "{turn}: {a:?} {b:?}");
    // The triangles differ (the diagonals turn with the grid) and the forward differences
    // start from the other edge: the statistics agree to 10⁻⁵ (measured), not to the bit.
    for col in ["delta_xi_deg", "delta_zeta_deg"] {
        assert!(close(b.num(col), a.num(col), 1e-4), "{col}: {a:?} {b:?}");
    }
    assert!(close(b.num("sq_um"), a.num("sq_um"), 1e-6));
    assert!(close(b.num("sdq"), a.num("sdq"), 1e-4));
    assert!(close(b.num("sdq_x"), a.num("sdq_y"), 1e-4));
    assert!(close(b.num("sdq_y"), a.num("sdq_x"), 1e-4));
}

/// `--scan FILE` without a case names the run after the file; a relative `scan.file` is read
/// from the case file's directory, wherever the run starts.
#[test]
fn the_run_is_named_after_the_file_and_relative_paths_follow_the_case() {
    let dir = Dir::new();
    let plu = real_scan("plu-1.plu");
    dir.command()
        .args(["scan", "--scan", plu.to_str().unwrap()])
        .run()
        .ok();
    assert!(dir.join("results/plu-1/scan/wall_card.toml").is_file());
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    std::fs::create_dir_all(dir.join("data")).unwrap();
    std::fs::copy(&plu, dir.join("data/wall.plu")).unwrap();
    let case = dir.write_case(
        "cases/wall.toml",
        "name = \"wall\"\n[scan]\nfile = \"../data/wall.plu\"\nlevel_degree = 2\n",
    );
    let elsewhere = Dir::new();
    elsewhere
        .command()
        .args(["scan", "--case", case.to_str().unwrap()])
        .run()
        .ok();
    let out = elsewhere.join("results/wall/scan");
    let row = summary(&out);
    let row = row.row(0);
    assert_eq!((&row["format"], &row["level_degree"]), ("plu", "2"));
    assert!(row["file"].ends_with("data/wall.plu"), "{row:?}");
}

/// `--diameter-um` on a real scan: a row per diameter after the point's, each what the
/// library's `seen_by` gives to the 7 digits of the CSV; the deviations fall with the
/// diameter; the widest sphere's row says the scan is too small; the card's `[[diameter]]`
/// and run.toml's rows say the same; the same bytes for 1 and 2 threads.
#[test]
fn diameters_give_the_librarys_rows_falling_with_the_diameter_for_any_thread_count() {
    let dir = Dir::new();
    let file = real_scan("x3p-2.x3p");
    let run = |threads: &str, out: &Path| {
        rebound(&[
            "scan",
            "--scan",
            file.to_str().unwrap(),
            "--threads",
            threads,
            "--diameter-um",
            "5,50",
            "--diameter-um",
            "1000",
            "--out",
            out.to_str().unwrap(),
        ])
        .ok()
    };
    let (one, two) = (dir.join("one"), dir.join("two"));
    let r = run("1", &one);
    run("2", &two);
    for f in OUTPUTS {
        if f != "run.toml" {
            assert_eq!(
                std::fs::read(one.join(f)).unwrap(),
                std::fs::read(two.join(f)).unwrap(),
                "{f} differs between --threads 1 and 2"
            );
        }
    }
    let c = Csv::read(&one.join("wall_card_diameters.csv"));
    assert_eq!(c.header.join(","), headers::WALL_CARD_DIAMETERS);
    assert_eq!(c.rows.len(), 4);
    let lib = library(&file);
    let want = roughwall::scan::seen_by(&lib, &[5e-6, 50e-6, 1000e-6]).unwrap();
    let mut last = [f64::INFINITY; 2];
    for (k, w) in want.iter().enumerate() {
        let row = c.row(k);
        let l = w.seen.lay.unwrap();
        assert_eq!(row.num("diameter_um"), [0.0, 5.0, 50.0, 1000.0][k]);
        for (col, x) in [
            ("delta_xi_deg", l.delta_xi.to_degrees()),
            ("delta_zeta_deg", l.delta_zeta.to_degrees()),
            ("exact_fraction", w.resolution.exact_fraction),
            ("correlation_areas", w.resolution.correlation_areas),
        ] {
            assert!(close(row.num(col), x, 1e-6), "{col}: {row:?} vs {x}");
        }
        // The resolution check: the library's deviations at twice the pixel and their change.
        if let (Some(l2), Some([cx, cz])) = (w.at_double_pixel, w.resolution_change()) {
            for (col, x) in [
                ("delta_xi_deg_2x_pixel", l2.delta_xi.to_degrees()),
                ("delta_zeta_deg_2x_pixel", l2.delta_zeta.to_degrees()),
                ("change_xi_2x_pixel", cx),
                ("change_zeta_2x_pixel", cz),
            ] {
                assert!(close(row.num(col), x, 1e-6), "{col}: {row:?} vs {x}");
            }
            assert_eq!(
                row["note"].contains("resolution-limited"),
                w.resolution_limited(),
                "{row:?}"
            );
        }
        let now = [row.num("delta_xi_deg"), row.num("delta_zeta_deg")];
        assert!(
            now[0] < last[0] && now[1] < last[1],
            "{now:?} after {last:?}"
        );
        last = now;
    }
    // The point's row is the summary's [wall].
    let s = summary(&one);
    assert_eq!(&c.row(0)["delta_zeta_deg"], &s.row(0)["delta_zeta_deg"]);
    assert!(
        c.row(3)["note"].starts_with("too small: its exact part holds at most "),
        "{:?}",
        c.row(3)
    );
    // At 5 µm the sphere still sees the pixel: Δξ falls by 8.8 % at twice the pixel
    // (issue 39: a criterion on the Gaussian 1/e length never said so).
    assert!(
        c.row(1)["note"].starts_with("resolution-limited: Δξ and Δζ change by "),
        "{:?}",
        c.row(1)
    );
    assert!(
        r.stderr
            .contains("warning: D = 1000 µm: the scan is too small: "),
        "{}",
        r.stderr
    );
    let t = card(&one);
    let rows = t["diameter"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    for (k, row) in rows.iter().enumerate() {
        let csv = c.row(k + 1);
        assert_eq!(row["diameter_um"].as_float(), Some(csv.num("diameter_um")));
        assert_eq!(
            row["delta_xi_deg"].as_float(),
            Some(csv.num("delta_xi_deg"))
        );
        assert_eq!(row["note"].as_str(), Some(&csv["note"][..]));
    }
    let m: toml::Table = std::fs::read_to_string(one.join("run.toml"))
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(m["diameter"].as_array().unwrap().len(), 4);
    assert!(m["run"]["centre_surfaces_s"].as_float().is_some());
}

/// The two commands from a scan to rebounds: `scan --diameter-um 500`, then `stochastic
/// --wall-card` on the built-in case (500 µm glass beads) runs on the card's 500 µm row,
/// says it replaced the case's [wall] and records the card; `deterministic --wall-card`
/// runs on the card's [wall]. A card without rows gives `stochastic` its [wall]; a diameter
/// the card lacks, a card without [wall], and `--out` in the card's directory are refused.
#[test]
fn a_scan_becomes_a_stochastic_and_a_deterministic_run_in_two_commands() {
    let dir = Dir::new();
    let file = real_scan("x3p-2.x3p");
    dir.command()
        .args([
            "scan",
            "--scan",
            file.to_str().unwrap(),
            "--out",
            "results/wall/scan",
            "--diameter-um",
            "500",
        ])
        .run()
        .ok();
    let card_path = "results/wall/scan/wall_card.toml";
    let t = card(&dir.join("results/wall/scan"));
    let row = &t["diameter"].as_array().unwrap()[0];
    let sm = dir
        .command()
        .args([
            "stochastic",
            "--wall-card",
            card_path,
            "--particles",
            "2000",
            "--out",
            "sm",
        ])
        .run()
        .ok();
    assert!(
        sm.stderr.contains(&format!(
            "warning: `--wall-card` {card_path} replaces the case's [wall] (Δξ, Δζ) = (3.8°, 7.5°) by its [[diameter]] row of 500 µm: (Δξ, Δζ) = ("
        )),
        "{}",
        sm.stderr
    );
    let s = Csv::read(&dir.join("sm/summary.csv"));
    assert_eq!(s.rows.len(), 6);
    for r in s.records() {
        assert_eq!(Some(r.num("delta_xi_deg")), row["delta_xi_deg"].as_float());
        assert_eq!(
            Some(r.num("delta_zeta_deg")),
            row["delta_zeta_deg"].as_float()
        );
    }
    let m: toml::Table = std::fs::read_to_string(dir.join("sm/run.toml"))
        .unwrap()
        .parse()
        .unwrap();
    let w = &m["wall_card"];
    assert_eq!(w["file"].as_str(), Some(card_path));
    assert_eq!(
        (w["row"].as_str(), w["diameter_um"].as_float()),
        (Some("diameter"), Some(500.0))
    );
    assert_eq!(w["sha256"].as_str().map(str::len), Some(64));
    assert_eq!(
        m["case"]["wall"]["delta_xi_deg"].as_float(),
        row["delta_xi_deg"].as_float()
    );
    // deterministic: the wall's own deviations, whatever the diameter.
    dir.command()
        .args([
            "deterministic",
            "--case",
            "cases/aniso.toml",
            "--wall-card",
            card_path,
            "--particles",
            "100",
            "--out",
            "ds",
        ])
        .run()
        .ok();
    let d = Csv::read(&dir.join("ds/summary.csv"));
    assert_eq!(
        Some(d.row(0).num("delta_xi_deg")),
        t["wall"]["delta_xi_deg"].as_float()
    );
    assert_eq!(
        Some(d.row(0).num("delta_zeta_deg")),
        t["wall"]["delta_zeta_deg"].as_float()
    );
    // A card without rows: stochastic takes [wall].
    dir.command()
        .args(["scan", "--scan", file.to_str().unwrap(), "--out", "plain"])
        .run()
        .ok();
    let plain = card(&dir.join("plain"));
    dir.command()
        .args([
            "stochastic",
            "--wall-card",
            "plain/wall_card.toml",
            "--particles",
            "100",
            "--out",
            "sm-plain",
        ])
        .run()
        .ok();
    let s = Csv::read(&dir.join("sm-plain/summary.csv"));
    assert_eq!(
        Some(s.row(0).num("delta_zeta_deg")),
        plain["wall"]["delta_zeta_deg"].as_float()
    );
    // Refusals: one line, nothing written.
    let case = dir.write_case(
        "small.toml",
        "name = \"small\"\n[wall]\ndelta_xi_deg = 2.0\ndelta_zeta_deg = 2.0\n[incidence]\nalpha_deg = [-10.0]\n[particles]\ndiameter_um = 250.0\n",
    );
    std::fs::write(
        dir.join("no-wall.toml"),
        "notes = []\n[scan]\nformat = \"x3p\"\n",
    )
    .unwrap();
    for (args, needle) in [
        (
            vec!["stochastic", "--case", case.to_str().unwrap(), "--wall-card", card_path],
            format!("`--wall-card` {card_path} has no [[diameter]] row for the particles' 250 µm (`particles.diameter_um`, default 500): its rows are for 500 µm"),
        ),
        (
            vec!["stochastic", "--wall-card", "no-wall.toml"],
            "`--wall-card` no-wall.toml has no [wall]".to_string(),
        ),
        (
            vec!["deterministic", "--wall-card", "no-such-card.toml"],
            "`--wall-card` no-such-card.toml: ".to_string(),
        ),
    ] {
        let mut a = args.clone();
        a.extend(["--out", "never"]);
        dir.command().args(&a).run().refused(&needle);
        assert!(!dir.join("never").exists(), "{needle}");
    }
    // The point particle from a card with rows: its [wall], for particles of any diameter.
    dir.command()
        .args([
            "stochastic",
            "--case",
            case.to_str().unwrap(),
            "--wall-card",
            card_path,
            "--wall-card-point",
            "--particles",
            "100",
            "--out",
            "sm-point",
        ])
        .run()
        .ok();
    let s = Csv::read(&dir.join("sm-point/summary.csv"));
    assert_eq!(
        Some(s.row(0).num("delta_xi_deg")),
        t["wall"]["delta_xi_deg"].as_float()
    );
    let m: toml::Table = std::fs::read_to_string(dir.join("sm-point/run.toml"))
        .unwrap()
        .parse()
        .unwrap();
    assert_eq!(m["wall_card"]["row"].as_str(), Some("wall"));
    assert_eq!(m["wall_card"]["point"].as_str(), Some("--wall-card-point"));
    dir.command()
        .args(["stochastic", "--wall-card-point", "--out", "never"])
        .run()
        .refused("--wall-card");
    assert!(!dir.join("never").exists());
    dir.command()
        .args([
            "stochastic",
            "--wall-card",
            card_path,
            "--out",
            "results/wall/scan",
        ])
        .run()
        .refused("it is the directory of `--wall-card`");
    assert!(dir.join(card_path).is_file());
}

/// Bad input: one line naming the key (or the file), exit status 2, nothing in `--out`.
#[test]
fn bad_input_is_one_line_and_writes_nothing() {
    let dir = Dir::new();
    let x3p = real_scan("x3p-2.x3p");
    let x3p = x3p.to_str().unwrap();
    // A corrupt file: the first 100 kB of a real X3P, and bytes that are no zip at all.
    let bytes = std::fs::read(x3p).unwrap();
    std::fs::write(dir.join("truncated.x3p"), &bytes[..100_000]).unwrap();
    std::fs::write(dir.join("junk.x3p"), b"this is not a scan").unwrap();
    let cases = [
        ("[scan]\nfile = \"no-such.x3p\"\n", "invalid `scan.file` = \"no-such.x3p\""),
        (
            &format!("[scan]\nfile = \"{x3p}\"\nformat = \"x3q\"\n"),
            "invalid `scan.format` = \"x3q\": allowed \"auto\"",
        ),
        (
            &format!("[scan]\nfile = \"{x3p}\"\nlevel_degree = 4\n"),
            "invalid `scan.level_degree` = 4: allowed 1 (a plane), 2 or 3",
        ),
        (
            &format!("[scan]\nfile = \"{x3p}\"\npixel_um = [0.1, 0.1]\n"),
            "invalid `scan.pixel_um` = [0.1, 0.1]: allowed only with `scan.format` = \"matrix\" or \"xyz\"",
        ),
        (
            &format!("[scan]\nfile = \"{x3p}\"\nformat = \"matrix\"\n"),
            "`scan.format` = \"matrix\" needs `scan.pixel_um`",
        ),
        (
            "[scan]\nfile = \"truncated.x3p\"\n",
            "`scan.file`: ",
        ),
        ("[scan]\nfile = \"junk.x3p\"\n", "not a readable zip archive"),
        (
            "[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 0.0\n",
            "no roughness along z",
        ),
        ("[scan]\nlevel_degree = 2\n", "no wall to generate"),
        (
            &format!("[scan]\nfile = \"{x3p}\"\ndiameters_um = [100.0, 0.0]\n"),
            "invalid `scan.diameters_um` = 0: allowed 0.001 to 1000000 µm (a nanometre to a metre)",
        ),
    ];
    for (i, (body, needle)) in cases.iter().enumerate() {
        let case = dir.write_case(&format!("c{i}.toml"), &format!("name = \"bad\"\n{body}"));
        refuse_case("scan", &case, dir.path(), needle);
    }
    for (d, needle) in [
        (
            "nan",
            "invalid `--diameter-um` = NaN: allowed 0.001 to 1000000 µm",
        ),
        ("-1", "invalid `--diameter-um` = -1: allowed 0.001 to"),
        (
            "100,100",
            "invalid `--diameter-um` = 100: allowed each diameter once",
        ),
        ("wide", "--diameter-um"),
    ] {
        let out = dir.join("never");
        rebound(&[
            "scan",
            "--scan",
            x3p,
            "--diameter-um",
            d,
            "--out",
            out.to_str().unwrap(),
        ])
        .refused(needle);
        assert!(!out.exists());
    }
    for (file, needle) in [
        ("no-such.x3p", "invalid `--scan` = "),
        ("junk.x3p", "`--scan`: "),
    ] {
        let out = dir.join("never");
        rebound(&[
            "scan",
            "--scan",
            dir.join(file).to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .refused(needle);
        assert!(!out.exists());
    }
}

/// Issue 39, part 2: the lay carries its uncertainty from sub-patches, and a wall whose
/// anisotropy is not significant is called isotropic and gets no lay. x3p-2 (grooves) fixes
/// its lay to a fraction of a degree; opd-1, whose lay came out −21.6° where another
/// estimator gave −38.5°, is isotropic within what it shows: no `[lay]`, both deviations the
/// rms of the two, and a note that says so.
#[test]
fn the_lay_has_an_uncertainty_and_an_isotropic_wall_no_lay() {
    let dir = Dir::new();
    let out = dir.join("x3p");
    rebound(&[
        "scan",
        "--scan",
        real_scan("x3p-2.x3p").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    let t = card(&out);
    let se = t["lay"]["angle_se_deg"].as_float().unwrap();
    assert!(se > 0.0 && se < 1.0, "{se}");
    assert!(t["lay"]["anisotropy_t"].as_float().unwrap() > 3.0);
    let out = dir.join("opd");
    let r = rebound(&[
        "scan",
        "--case",
        "scans/opd-1.toml",
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    let t = card(&out);
    assert!(t.get("lay").is_none(), "{t:?}");
    let (xi, zeta) = (
        t["wall"]["delta_xi_deg"].as_float().unwrap(),
        t["wall"]["delta_zeta_deg"].as_float().unwrap(),
    );
    assert_eq!(xi, zeta);
    let lib = library(&real_scan("opd-1.opd")).lay.unwrap();
    let rms = (0.5 * (lib.delta_xi.powi(2) + lib.delta_zeta.powi(2))).sqrt();
    assert!(
        close(xi, rms.to_degrees(), 1e-6),
        "{xi} vs {}",
        rms.to_degrees()
    );
    let notes = t["notes"].as_array().unwrap();
    assert!(
        notes.iter().any(|n| n
            .as_str()
            .unwrap()
            .starts_with("isotropic within what the scan shows: ")),
        "{notes:?}"
    );
    assert!(
        r.stderr.contains("warning: isotropic within"),
        "{}",
        r.stderr
    );
}

/// The wall's own model end to end (issue 39, part 4): `scan --measured-wall` writes a table
/// per particle beside the card, which names them and says what the paper's model misses the
/// wall by; `stochastic --wall-card` with `model = "measured-wall"` takes the table of its row
/// and rebounds off that wall; a card without tables is refused naming the key it lacks.
#[test]
fn the_card_names_the_walls_own_model_and_stochastic_takes_it() {
    let dir = tempfile::tempdir().unwrap();
    let scan = real_scan("x3p-2.x3p");
    let out = dir.path().join("card");
    rebound(&[
        "scan",
        "--scan",
        scan.to_str().unwrap(),
        "--diameter-um",
        "20",
        "--measured-wall",
        "--measured-wall-histories",
        "1024",
        "--out",
        out.to_str().unwrap(),
    ])
    .ok();
    let c = card(&out);
    let point = c["wall"]["measured_wall_table"].as_str().unwrap();
    let row = c["diameter"].as_array().unwrap()[0].as_table().unwrap();
    let sphere = row["measured_wall_table"].as_str().unwrap();
    assert_eq!(
        (point, sphere),
        ("measured_wall_point.txt", "measured_wall_20um.txt")
    );
    for f in [point, sphere] {
        let text = std::fs::read_to_string(out.join(f)).unwrap();
        let t = roughwall::measured_wall::MeasuredWallTable::parse(&text, f).unwrap();
        assert_eq!(t.histories_per_cell(), 1024);
    }
    // x3p-2 is far from Gaussian: the paper's model misses its own law by a KS well above the
    // goal's 0.01 (0.195 at 2048 histories a cell).
    let versus = c["wall"]["measured_wall_versus_paper"].as_str().unwrap();
    let ks: f64 = versus
        .split("KS distance of α⁺ up to ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!(ks > 0.05, "{versus}");
    let manifest: toml::Table =
        toml::from_str(&std::fs::read_to_string(out.join("run.toml")).unwrap()).unwrap();
    assert_eq!(manifest["measured_wall"].as_array().unwrap().len(), 2);
    // stochastic with the card's 20 µm row and its table.
    let case = write_case(
        dir.path(),
        "mw.toml",
        "name = \"mw\"\n[incidence]\nalpha_deg = [-13.5]\nbeta_deg = [97.5]\n\
         [particles]\ncount = 2000\ndiameter_um = 20.0\n[stochastic]\nmodel = \"measured-wall\"\n",
    );
    let card_file = out.join("wall_card.toml");
    let run = run_case(
        "stochastic",
        &case,
        &dir.path().join("run"),
        &["--wall-card", card_file.to_str().unwrap()],
    );
    let m: toml::Table =
        toml::from_str(&std::fs::read_to_string(run.join("run.toml")).unwrap()).unwrap();
    let text = toml::to_string(&m).unwrap();
    assert!(text.contains("measured_wall_20um.txt"), "{text}");
    assert!(
        text.contains("rebounds off the wall its table was measured on"),
        "{text}"
    );
    // A card without tables: refused, naming what it lacks.
    let plain = dir.path().join("plain");
    rebound(&[
        "scan",
        "--scan",
        scan.to_str().unwrap(),
        "--diameter-um",
        "20",
        "--out",
        plain.to_str().unwrap(),
    ])
    .ok();
    let plain_card = plain.join("wall_card.toml");
    rebound(&[
        "stochastic",
        "--case",
        case.to_str().unwrap(),
        "--wall-card",
        plain_card.to_str().unwrap(),
        "--out",
        dir.path().join("never").to_str().unwrap(),
    ])
    .refused("measured_wall_table");
}

/// The rows each measured-wall table of a `scan --measured-wall` run in `out` added
/// (`run.toml`, `[[measured_wall]] refined_rows_deg`), in the order of its tables.
fn refined_rows(out: &Path) -> Vec<Vec<f64>> {
    let m: toml::Table = std::fs::read_to_string(out.join("run.toml"))
        .unwrap()
        .parse()
        .unwrap();
    m["measured_wall"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            e["refined_rows_deg"]
                .as_array()
                .unwrap()
                .iter()
                .map(|a| a.as_float().unwrap())
                .collect()
        })
        .collect()
}

/// On a striated metal land (x3ptools' sample-land) the point particle's table adds no row:
/// with one entry region for every direction its law is smooth between the base rows. Where
/// the region followed the direction, it slid across the land and the law bent near 39° with
/// it, and the build added six rows there (docs/design-notes.md, "Rows per wall" and "One
/// entry region"); rows are still added where a law bends (`measured_wall::refine`'s tests).
/// The table file lists its rows and reads back with them; the card names the region its
/// reference takes.
#[test]
fn one_entry_region_leaves_the_metal_land_no_bend_to_follow() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("card");
    run_case(
        "scan",
        &shipped_case("scans/sample-land.toml"),
        &out,
        &["--measured-wall"],
    );
    let rows = refined_rows(&out);
    assert_eq!(rows, vec![Vec::<f64>::new()]);
    let text = std::fs::read_to_string(out.join("measured_wall_point.txt")).unwrap();
    let table = roughwall::measured_wall::MeasuredWallTable::parse(&text, "t").unwrap();
    assert_eq!(
        table.alpha_rows_deg,
        roughwall::measured_wall::ALPHA_ROWS_DEG
    );
    let entry = card(&out)["wall"]["measured_wall_entry_alpha_deg"]
        .as_integer()
        .map(|a| a as f64)
        .or_else(|| card(&out)["wall"]["measured_wall_entry_alpha_deg"].as_float());
    assert_eq!(entry, Some(roughwall::measured_wall::ENTRY_ALPHA_DEG));
}

/// The wall's own model against its goal on small real scans (issue 39, "Done when"), the
/// study's comparison (scripts/measured-wall-model.sh) at one seed: `scan --measured-wall`
/// with the default histories a cell; the in-place reference on the scan itself, over the
/// entry region the card names; the model from `stochastic --wall-card`, at incident
/// directions between the table's grid points (configs/scans/own-model.toml); each with
/// 2 × 10⁵ particles, the PDFs in 0.02° bins (a tenth of these walls' spread of α⁺ or finer,
/// so that KS is that of the laws). Goal: KS of α⁺ ≤ 0.01 and |bias of mean α⁺| ≤ 0.05°.
/// metropro-1 has a smooth law; opd-1's 50 µm sphere a comb in each angle, which the
/// quantile functions' added knots keep (KS 0.0112 with fixed knots alone); plu-1 (slope
/// kurtosis 570 along the lay; heights in steps of 3.9 nm, so its α⁺ is a comb of spikes
/// 0.04° apart, in ξ' and ζ' jointly) meets it only through the joint atoms (0.0113 without
/// them), so losing either fails here. The paper's model misses metropro-1 by more than
/// twenty times the goal's KS and plu-1 by more than five: the comparison tells them apart.
#[test]
fn on_small_real_scans_the_walls_own_model_meets_its_goal() {
    let dir = tempfile::tempdir().unwrap();
    let directions = read_shipped_case("scans/own-model.toml");
    assert!(directions.contains("[particles]\ncount = 200000\n"));
    // (scan, the particle's diameter in µm, 0 the point particle; the KS by which the paper's
    // model must miss, where it is run)
    for (scan, diameter, paper_misses_by) in [
        ("metropro-1.dat", 0.0, Some(0.2)),
        ("opd-1.opd", 50.0, None),
        ("plu-1.plu", 0.0, Some(0.05)),
    ] {
        let tag = format!("{scan}-{diameter}");
        let out = dir.path().join(format!("card-{tag}"));
        let mut args = vec!["scan", "--scan"];
        let file = real_scan(scan);
        args.push(file.to_str().unwrap());
        let d = format!("{diameter}");
        if diameter > 0.0 {
            args.extend(["--diameter-um", &d]);
        }
        args.extend(["--measured-wall", "--out", out.to_str().unwrap()]);
        rebound(&args).ok();
        // A smooth wall's law does not bend between the base rows: no row is added.
        assert!(
            refined_rows(&out).iter().all(Vec::is_empty),
            "{tag}: {:?}",
            refined_rows(&out)
        );
        let card_file = out.join("wall_card.toml");
        // The reference enters over the region the table was built on, as the card says.
        let row = match diameter > 0.0 {
            true => card(&out)["diameter"].as_array().unwrap()[0].clone(),
            false => card(&out)["wall"].clone(),
        };
        let entry = &row["measured_wall_entry_alpha_deg"];
        let entry = entry
            .as_float()
            .or(entry.as_integer().map(|a| a as f64))
            .unwrap();
        assert_eq!(entry, roughwall::measured_wall::ENTRY_ALPHA_DEG, "{tag}");
        // plu-1's heights are whole 3.906 nm steps, 0.98 of its smaller deviation over the
        // pixel: its card says so; metropro-1's steps (0.009 nm) and opd-1's heights do not show.
        let quantized = card(&out)["notes"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|n| n.as_str())
            .any(|n| n.starts_with("heights in whole steps of 3.906 nm (21 % of Sq)"));
        assert_eq!(quantized, scan == "plu-1.plu", "{tag}");
        let particles = if diameter > 0.0 {
            format!("[particles]\ncount = 200000\ndiameter_um = {diameter}\n")
        } else {
            "[particles]\ncount = 200000\n".to_string()
        };
        let base = directions.replace(
            "[particles]\ncount = 200000\n",
            &format!("{particles}\n[output]\nbin_width_deg = 0.02\n"),
        );
        let contact = if diameter > 0.0 {
            "contact = \"sphere\"\n"
        } else {
            ""
        };
        let reference_case = write_case(
            dir.path(),
            &format!("ref-{tag}.toml"),
            &format!("{base}\n[deterministic]\nscan_level_degree = 1\nentry_alpha_deg = {entry}\n{contact}"),
        );
        let reference = dir.path().join(format!("ref-{tag}"));
        rebound(&[
            "deterministic",
            "--case",
            reference_case.to_str().unwrap(),
            "--surface",
            file.to_str().unwrap(),
            "--wall-card",
            card_file.to_str().unwrap(),
            "--out",
            reference.to_str().unwrap(),
        ])
        .ok();
        for model in ["measured-wall", "radenkovic-simonin-2021"] {
            if model != "measured-wall" && paper_misses_by.is_none() {
                continue;
            }
            let case = write_case(
                dir.path(),
                &format!("{model}-{tag}.toml"),
                &format!("{base}\n[stochastic]\nmodel = \"{model}\"\n"),
            );
            let run = run_case(
                "stochastic",
                &case,
                &dir.path().join(format!("{model}-{tag}")),
                &["--wall-card", card_file.to_str().unwrap()],
            );
            let cmp = dir.path().join(format!("cmp-{model}-{tag}"));
            rebound(&[
                "compare",
                "--a",
                reference.to_str().unwrap(),
                "--b",
                run.to_str().unwrap(),
                "--out",
                cmp.to_str().unwrap(),
            ])
            .ok();
            let c = Csv::read(&cmp.join("comparison.csv"));
            let rows: Vec<_> = c
                .records()
                .filter(|r| r["quantity"] == *"alpha_out")
                .map(|r| (r.num("ks"), r.num("mean_b") - r.num("mean_a")))
                .collect();
            assert_eq!(rows.len(), 9, "{scan}: {model}");
            let ks = rows.iter().map(|r| r.0).fold(0.0, f64::max);
            let bias = rows.iter().map(|r| r.1.abs()).fold(0.0, f64::max);
            if model == "measured-wall" {
                assert!(ks <= 0.01 && bias <= 0.05, "{tag}: KS {ks}, bias {bias}°");
            } else {
                let least = paper_misses_by.unwrap();
                assert!(ks > least, "{tag}: the paper's model: KS {ks}");
            }
        }
    }
}
