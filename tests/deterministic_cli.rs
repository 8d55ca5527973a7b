//! `rebound deterministic` through the binary: bad input is a one-line error naming
//! the key or file, exit status 2, and nothing is written.

use crate::common::*;
use std::path::{Path, PathBuf};

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
    write_case(dir, "case.toml", &text)
}

/// Runs `deterministic` on a modified case and checks the refusal.
fn refuses(replace: &[(&str, &str)], extra: &[&str], needle: &str) {
    let dir = Dir::new();
    let case = case_with(dir.path(), replace);
    let out = dir.join("out");
    let mut args = vec![
        "deterministic",
        "--case",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    rebound(&args).refused(needle);
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
        &[(
            "side_per_corr_length = 20.0",
            "side_per_corr_length = 20.0\ntriangulation = \"diagonal\"",
        )],
        &[],
        "deterministic.triangulation",
    );
    for bad in ["surfaces = 0", "surfaces = 1025", "surfaces = -1"] {
        refuses(
            &[("side_per_corr_length = 20.0", bad)],
            &[],
            "deterministic.surfaces",
        );
    }
    refuses(
        &[("side_per_corr_length = 20.0", "colisions = 3")],
        &[],
        "colisions",
    );
}

#[test]
fn bad_surface_files() {
    let dir = Dir::new();
    let missing = dir.path().join("no-such-surface.bin");
    refuses(
        &[],
        &["--surface", missing.to_str().unwrap()],
        "no-such-surface.bin",
    );
    let garbage = dir.join("garbage.bin");
    std::fs::write(&garbage, b"this is not a height field at all, just text\n").unwrap();
    refuses(
        &[],
        &["--surface", garbage.to_str().unwrap()],
        "garbage.bin",
    );
    let empty = dir.join("empty.bin");
    std::fs::write(&empty, b"").unwrap();
    refuses(&[], &["--surface", empty.to_str().unwrap()], "empty.bin");
}

fn run_ok(args: &[&str]) -> String {
    rebound(args).ok().stderr
}

#[test]
fn outputs_are_byte_identical_for_one_and_two_threads() {
    let dir = Dir::new();
    let case = case_with(
        dir.path(),
        &[(
            "model = \"elastic\"",
            "model = \"sommerfeld-huber\"\npreset = \"glass-steel\"",
        )],
    );
    let mut outs = Vec::new();
    for threads in ["1", "2"] {
        let out = dir.path().join(format!("out{threads}"));
        let err = run_ok(&[
            "deterministic",
            "--case",
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--threads",
            threads,
        ]);
        assert!(!err.contains("warning"), "{err}");
        outs.push(out);
    }
    for f in ["summary.csv", "pdfs.csv", "moments.csv"] {
        let a = std::fs::read(outs[0].join(f)).unwrap();
        let b = std::fs::read(outs[1].join(f)).unwrap();
        assert!(a == b, "{f} differs between --threads 1 and 2");
    }
    let summary = Csv::read(&outs[0].join("summary.csv"));
    assert_eq!(summary.rows.len(), 2);
    for row in summary.records() {
        assert_eq!(&row["lost"], "0", "lost must be 0: {row:?}");
        assert!(
            row.cells().iter().all(|c| !c.is_empty()),
            "empty cell: {row:?}"
        );
    }
    let manifest = std::fs::read_to_string(outs[0].join("run.toml")).unwrap();
    for key in [
        "[surface_choice]",
        "particles_per_s",
        "wall_time_s",
        "measured_delta_zeta_deg",
    ] {
        assert!(manifest.contains(key), "run.toml lacks {key}");
    }
    for fig in [
        "fig06_alpha_out.svg",
        "fig07_dbeta.svg",
        "fig08_xi_first.svg",
        "fig09_zeta_first.svg",
        "fig12_p_single.svg",
    ] {
        assert!(outs[0].join(fig).is_file(), "{fig}");
    }
}

#[test]
fn a_saved_surface_is_reused_and_a_damaged_one_refused() {
    let dir = Dir::new();
    let surf_case = dir.path().join("surf.toml");
    std::fs::write(
        &surf_case,
        "name = 's'\n[surface]\nlength_um = 640.0\nnodes = 320\nrms_height_um = 1.0\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n",
    )
    .unwrap();
    let heights = dir.path().join("wall.rbhf");
    run_ok(&[
        "surface",
        "--case",
        surf_case.to_str().unwrap(),
        "--heights",
        heights.to_str().unwrap(),
        "--out",
        dir.path().join("s").to_str().unwrap(),
    ]);
    let case = case_with(dir.path(), &[]);
    let out = dir.path().join("det");
    run_ok(&[
        "deterministic",
        "--case",
        case.to_str().unwrap(),
        "--surface",
        heights.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let manifest = std::fs::read_to_string(out.join("run.toml")).unwrap();
    assert!(manifest.contains("source = \"file\""));
    // A truncated copy is refused with the file's name.
    let bytes = std::fs::read(&heights).unwrap();
    let cut = dir.path().join("cut.rbhf");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    refuses(&[], &["--surface", cut.to_str().unwrap()], "cut.rbhf");
    // A height file is one realisation.
    refuses(
        &[(
            "side_per_corr_length = 20.0",
            "side_per_corr_length = 20.0\nsurfaces = 2",
        )],
        &["--surface", heights.to_str().unwrap()],
        "deterministic.surfaces",
    );
}

/// `[deterministic] surfaces`: one realisation is the run without the key, byte for byte;
/// several give other histories on surfaces of the same statistics, the same outputs for
/// any thread count and shard split, and `run.toml` says how many, with the deviations
/// measured over all of them.
#[test]
fn surface_realisations() {
    let dir = Dir::new();
    let run = |name: &str, surfaces: Option<u32>, extra: &[&str]| {
        let key = surfaces.map_or(String::new(), |n| format!("\nsurfaces = {n}"));
        let case = case_with(
            dir.path(),
            &[(
                "side_per_corr_length = 20.0",
                &format!("side_per_corr_length = 20.0{key}"),
            )],
        );
        run_case("deterministic", &case, &dir.join(name), extra)
    };
    let plain = run("plain", None, &[]);
    let one = run("one", Some(1), &[]);
    assert_eq!(csv_files(&plain), csv_files(&one));
    let three = run("three", Some(3), &["--threads", "1"]);
    let three_2 = run("three-2", Some(3), &["--threads", "2"]);
    assert_eq!(csv_files(&three), csv_files(&three_2));
    assert_ne!(
        std::fs::read(plain.join("summary.csv")).unwrap(),
        std::fs::read(three.join("summary.csv")).unwrap(),
        "three realisations gave the histories of one"
    );
    let shards: Vec<PathBuf> = [2, 1]
        .iter()
        .map(|k| {
            run(
                &format!("shard{k}"),
                Some(3),
                &["--shard", &format!("{k}/2")],
            )
        })
        .collect();
    let merged = dir.join("merged");
    merge_shards(&merged, &shards);
    assert_eq!(csv_files(&three), csv_files(&merged));
    let measured = |d: &Path| -> (String, Vec<f64>) {
        let m = std::fs::read_to_string(d.join("run.toml")).unwrap();
        let v = m
            .lines()
            .filter_map(|l| l.strip_prefix("measured_delta_"))
            .map(|l| l.split(" = ").nth(1).unwrap().parse().unwrap())
            .collect();
        (m, v)
    };
    let (m1, d1) = measured(&plain);
    let (m3, d3) = measured(&three);
    assert!(!m1.contains("surfaces = "), "{m1}");
    // Under [surface_choice], not only in the case copy run.toml holds.
    let choice = m3.split("[surface_choice]").nth(1).unwrap();
    let choice = choice.split("\n[").next().unwrap();
    assert!(choice.contains("\nsurfaces = 3\n"), "{choice}");
    assert_eq!(d3.len(), 2, "{m3}");
    // Other surfaces of the same statistics: nearly the same deviations, not the same bits.
    assert_ne!(d1, d3);
    for (a, b) in d1.iter().zip(&d3) {
        assert!((a - b).abs() < 0.1, "measured deviations {d1:?} {d3:?}");
    }
}

/// `[deterministic] triangulation` reaches the tracker and the manifest: the alternating
/// split gives other histories on the same surface (its mirror symmetry is tested in the
/// library, `alternating_triangulation_is_mirror_symmetric`), nearly the same measured
/// deviations (each cell's two x-slopes and two z-slopes are the same edges either way; only
/// their pairing changes), and `run.toml` says which one ran.
#[test]
fn the_triangulation_key_reaches_the_tracker() {
    let dir = Dir::new();
    let mut summaries = Vec::new();
    let mut measured = Vec::new();
    for tri in ["uniform", "alternating"] {
        let case = case_with(
            dir.path(),
            &[(
                "side_per_corr_length = 20.0",
                &format!("side_per_corr_length = 20.0\ntriangulation = \"{tri}\""),
            )],
        );
        let out = dir.path().join(tri);
        run_ok(&[
            "deterministic",
            "--case",
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let manifest = std::fs::read_to_string(out.join("run.toml")).unwrap();
        assert!(
            manifest.contains(&format!("triangulation = \"{tri}\"")),
            "run.toml does not record {tri}"
        );
        let m: Vec<f64> = manifest
            .lines()
            .filter_map(|l| l.strip_prefix("measured_delta_"))
            .map(|l| l.split(" = ").nth(1).unwrap().parse().unwrap())
            .collect();
        assert_eq!(m.len(), 2, "{manifest}");
        measured.push(m);
        summaries.push(std::fs::read(out.join("summary.csv")).unwrap());
    }
    assert_ne!(
        summaries[0], summaries[1],
        "the triangulation changed nothing"
    );
    for (u, a) in measured[0].iter().zip(&measured[1]) {
        assert!((u - a).abs() < 0.01, "measured deviations {measured:?}");
    }
}

/// Issue 33: the standard error of a surface ensemble covers the spread between
/// ensembles. On a wall whose realisations differ strongly (4 correlation lengths a side,
/// so each surface has quirks of its own), independent ensembles of 16 surfaces (seeds
/// 1–24) scatter in mean α⁺ as the `se` each reports says, where the histories' own error
/// (`se_histories`, what `se` was before) is several times too small; and `compare`
/// between two ensembles forms its z from `se`.
#[test]
fn ensemble_standard_error_covers_the_spread_between_ensembles() {
    let dir = Dir::new();
    let case = case_with(
        dir.path(),
        &[
            (
                "side_per_corr_length = 20.0",
                "side_per_corr_length = 4.0\nsurfaces = 16",
            ),
            ("beta_deg = [0.0, 60.0]", "beta_deg = [0.0]"),
            ("count = 2000", "count = 64000"),
        ],
    );
    let runs: Vec<(PathBuf, [f64; 3])> = (1..=24)
        .map(|seed| {
            let out = run_case(
                "deterministic",
                &case,
                &dir.join(format!("seed{seed}")),
                &["--seed", &seed.to_string()],
            );
            let csv = Csv::read(&out.join("moments.csv"));
            let r = csv
                .records()
                .find(|r| &r["quantity"] == "alpha_out")
                .expect("alpha_out in moments.csv");
            (out, [r.num("mean"), r.num("se"), r.num("se_histories")])
        })
        .collect();
    let means: Vec<f64> = runs.iter().map(|r| r.1[0]).collect();
    let m = means.iter().sum::<f64>() / means.len() as f64;
    let spread =
        (means.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (means.len() - 1) as f64).sqrt();
    let rms =
        |k: usize| (runs.iter().map(|r| r.1[k] * r.1[k]).sum::<f64>() / runs.len() as f64).sqrt();
    let (se, se_histories) = (rms(1), rms(2));
    // 23 degrees of freedom: the spread is known to about ±15 %.
    assert!(
        (0.6..1.6).contains(&(spread / se)),
        "spread of ensemble means {spread}°, RMS ensemble SE {se}°"
    );
    assert!(
        se_histories < spread / 2.0,
        "the histories' own SE {se_histories}° already covers the spread {spread}°: the wall does not test the ensemble SE"
    );
    for r in &runs {
        assert!(r.1[1] >= r.1[2], "se below se_histories: {:?}", r.1);
    }
    // `compare` between the two most different ensembles: z from the ensemble errors.
    let lo = (0..runs.len())
        .min_by(|&a, &b| means[a].total_cmp(&means[b]))
        .unwrap();
    let hi = (0..runs.len())
        .max_by(|&a, &b| means[a].total_cmp(&means[b]))
        .unwrap();
    let out = dir.join("compare");
    let o = rebound(&[
        "compare",
        "--a",
        runs[lo].0.to_str().unwrap(),
        "--b",
        runs[hi].0.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    let csv = Csv::read(&out.join("comparison.csv"));
    let row = csv
        .records()
        .find(|r| &r["quantity"] == "alpha_out")
        .unwrap();
    let (a, b) = (runs[lo].1, runs[hi].1);
    let z = (b[0] - a[0]) / (a[1] * a[1] + b[1] * b[1]).sqrt();
    assert!(
        (row.num("z") - z).abs() < 1e-3 * z.abs().max(1.0),
        "{row:?} vs {z}"
    );
    let z_histories = (b[0] - a[0]) / (a[2] * a[2] + b[2] * b[2]).sqrt();
    assert!(z_histories > 2.0 * z, "{z_histories} vs {z}");
}

/// Over several surfaces a target error has a floor that particles cannot lower: the
/// warning for a target not reached says which key does lower it.
#[test]
fn an_unreached_target_over_surfaces_names_the_surfaces() {
    let dir = Dir::new();
    let case = case_with(
        dir.path(),
        &[
            (
                "side_per_corr_length = 20.0",
                "side_per_corr_length = 4.0\nsurfaces = 4",
            ),
            ("beta_deg = [0.0, 60.0]", "beta_deg = [0.0]"),
        ],
    );
    let out = dir.join("out");
    let o = rebound(&[
        "deterministic",
        "--case",
        case.to_str().unwrap(),
        "--target-se",
        "0.001",
        "--particles",
        "70000",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(
        o.stderr.contains("was not reached") && o.stderr.contains("over 4 surfaces"),
        "{}",
        o.stderr
    );
}

/// `--surface` with a measured scan: by default the in-place reference (issue 39, part 1),
/// the scan's own triangles with the incident directions turned by its lay, `run.toml`
/// saying which block and how many histories left it; with `scan_wall = "mirrored"` the
/// earlier reference (issue 29, part 4): levelled, turned to its lay, cropped and
/// mirror-tiled. A scan with missing points inside, a file that is no scan, or an unknown
/// `scan_wall` is one line naming it, exit 2, nothing written.
#[test]
fn a_measured_scan_is_a_wall_to_bounce_on() {
    let dir = Dir::new();
    let edits = [
        ("beta_deg = [0.0, 60.0]", "beta_deg = [0.0]"),
        ("count = 2000", "count = 1000"),
    ];
    let case = case_with(dir.path(), &edits);
    let scans = repo_root().join("tests/data/scans");
    let x3p = scans.join("x3p-2.x3p");
    let scan_table = |out: &Path| -> toml::Table {
        let manifest = std::fs::read_to_string(out.join("run.toml")).unwrap();
        toml::from_str::<toml::Table>(&manifest).unwrap()["scan"]
            .as_table()
            .unwrap()
            .clone()
    };
    let out = dir.join("x3p");
    run_case(
        "deterministic",
        &case,
        &out,
        &["--surface", x3p.to_str().unwrap()],
    );
    let scan = scan_table(&out);
    // The grooves of this scan run along its y: the lay is at about 87°.
    let lay = scan["lay_deg"].as_float().unwrap();
    assert!((80.0..=90.0).contains(&lay), "{scan:?}");
    assert_eq!(scan["format"].as_str(), Some("x3p"));
    assert_eq!(scan["reference"].as_str(), Some("in-place"));
    // 650 × 650 points, cut to 648 × 648 (a multiple of 8): nothing resampled.
    let block: Vec<i64> = scan["block_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_integer().unwrap())
        .collect();
    assert_eq!(block, [648, 648], "{scan:?}");
    let manifest: toml::Table =
        toml::from_str(&std::fs::read_to_string(out.join("run.toml")).unwrap()).unwrap();
    let row = &manifest["conditions"].as_array().unwrap()[0];
    let left = row["left_patch"].as_integer().unwrap();
    assert!(left < 10, "{left} of 1000 left the scan");
    // The deviations measured for the wall met are the scan's own along its lay.
    let met = manifest["surface_choice"]["measured_delta_xi_deg"]
        .as_float()
        .unwrap();
    let card = scan["delta_xi_deg"].as_float().unwrap();
    assert!((met / card - 1.0).abs() < 0.02, "{met} vs {card}");
    let summary = Csv::read(&out.join("summary.csv"));
    assert_eq!(summary.records().count(), 1);
    // A scan is one realisation: the error of mean α⁺ takes its 16 sub-patches as clusters,
    // and the spread between them (along its lay x3p-2 spans fewer than 4 c_L) exceeds what
    // the histories alone show.
    let per_history_ratio = |out: &Path| {
        let t = Csv::read(&out.join("summary.csv"));
        let r = t.row(0);
        let (se, sd) = (r.num("se_mean_alpha_out_deg"), r.num("std_alpha_out_deg"));
        se / (sd / r.num("particles").sqrt())
    };
    let ratio = per_history_ratio(&out);
    assert!(ratio >= 1.0, "in place: se / (std/√n) = {ratio}");
    // Grazing, across the lay (α⁻ = −5°, β⁻ = 90°): there the parts differ most (with 5 × 10⁴
    // histories the error was 18× the histories' own).
    let across_dir = dir.join("across");
    std::fs::create_dir(&across_dir).unwrap();
    let across = case_with(
        &across_dir,
        &[
            ("alpha_deg = [-12.5]", "alpha_deg = [-5.0]"),
            ("beta_deg = [0.0, 60.0]", "beta_deg = [90.0]"),
            edits[1],
        ],
    );
    let out_across = dir.join("x3p-across");
    run_case(
        "deterministic",
        &across,
        &out_across,
        &["--surface", x3p.to_str().unwrap()],
    );
    let ratio = per_history_ratio(&out_across);
    assert!(ratio > 2.0, "in place, (−5°, 90°): se / (std/√n) = {ratio}");
    // The earlier reference, on request (its case beside, not over, the first).
    let mirrored_dir = dir.join("mirrored");
    std::fs::create_dir(&mirrored_dir).unwrap();
    let mirrored = case_with(
        &mirrored_dir,
        &[
            edits[0],
            edits[1],
            (
                "side_per_corr_length = 20.0",
                "side_per_corr_length = 20.0\nscan_wall = \"mirrored\"",
            ),
        ],
    );
    let out_m = dir.join("x3p-mirrored");
    run_case(
        "deterministic",
        &mirrored,
        &out_m,
        &["--surface", x3p.to_str().unwrap()],
    );
    let scan = scan_table(&out_m);
    assert_eq!(scan["reference"].as_str(), Some("mirrored"));
    // A periodic wall of one surface: the histories' own error.
    let ratio = per_history_ratio(&out_m);
    assert!(
        (ratio - 1.0).abs() < 0.01,
        "mirrored: se / (std/√n) = {ratio}"
    );
    let fraction = scan["rectangle_area_fraction"].as_float().unwrap();
    assert!(fraction > 0.5 && fraction <= 1.0, "{scan:?}");
    // A scan with missing points inside: its largest complete rectangle (sur-2 has 117).
    let out_g = dir.join("sur-2");
    run_case(
        "deterministic",
        &case,
        &out_g,
        &["--surface", scans.join("sur-2.sur").to_str().unwrap()],
    );
    let scan = scan_table(&out_g);
    let fraction = scan["block_area_fraction"].as_float().unwrap();
    assert!(fraction > 0.3 && fraction < 1.0, "{scan:?}");
    // A file no reader takes: refused, naming it, and nothing written.
    let o = dir.join("README.md");
    rebound(&[
        "deterministic",
        "--case",
        case.to_str().unwrap(),
        "--surface",
        scans.join("README.md").to_str().unwrap(),
        "--out",
        o.to_str().unwrap(),
    ])
    .refused("README.md");
    assert!(!o.exists());
    refuses(
        &[(
            "side_per_corr_length = 20.0",
            "side_per_corr_length = 20.0\nscan_wall = \"tiled\"",
        )],
        &[],
        "deterministic.scan_wall",
    );
}

/// `entry_alpha_deg` on a scan in place: one entry region for every direction, that of the
/// angle's margins on every side (what a measured-wall table's build takes), recorded in
/// `run.toml`; the histories then sample the same part of the scan at every direction, so a
/// run differs from the one whose region follows the direction. Anywhere else (a generated
/// wall, the mirrored reference) or out of range, it is one line naming the key, exit 2.
#[test]
fn one_entry_region_on_a_scan_in_place() {
    let dir = Dir::new();
    let x3p = repo_root().join("tests/data/scans/x3p-2.x3p");
    let edits = [
        ("beta_deg = [0.0, 60.0]", "beta_deg = [0.0, 90.0]"),
        ("count = 2000", "count = 1000"),
    ];
    let follows = case_with(dir.path(), &edits);
    let one_dir = dir.join("one");
    std::fs::create_dir(&one_dir).unwrap();
    let one = case_with(
        &one_dir,
        &[
            edits[0],
            edits[1],
            (
                "side_per_corr_length = 20.0",
                "side_per_corr_length = 20.0\nentry_alpha_deg = 1.0",
            ),
        ],
    );
    let (out_f, out_1) = (dir.join("follows"), dir.join("one-region"));
    for (case, out) in [(&follows, &out_f), (&one, &out_1)] {
        run_case(
            "deterministic",
            case,
            out,
            &["--surface", x3p.to_str().unwrap()],
        );
    }
    let region = |out: &Path| -> String {
        let m: toml::Table =
            toml::from_str(&std::fs::read_to_string(out.join("run.toml")).unwrap()).unwrap();
        m["scan"]["entry_region"].as_str().unwrap().to_string()
    };
    assert!(
        region(&out_f).starts_with("follows each direction"),
        "{}",
        region(&out_f)
    );
    assert!(
        region(&out_1).contains("one for every direction") && region(&out_1).contains("= 1°"),
        "{}",
        region(&out_1)
    );
    // The same histories (seed, numbers) entered elsewhere: other rebounds.
    let mean = |out: &Path, k: usize| {
        Csv::read(&out.join("summary.csv"))
            .row(k)
            .num("mean_alpha_out_deg")
    };
    for k in 0..2 {
        assert_ne!(mean(&out_f, k), mean(&out_1, k), "condition {k}");
    }
    let key = "deterministic.entry_alpha_deg";
    let with = |v: &str| {
        (
            "side_per_corr_length = 20.0",
            format!("side_per_corr_length = 20.0\nentry_alpha_deg = {v}"),
        )
    };
    for v in ["0.0", "91.0", "-5.0"] {
        let (a, b) = with(v);
        refuses(&[(a, &b)], &["--surface", x3p.to_str().unwrap()], key);
    }
    // A generated wall has no entry region.
    let (a, b) = with("5.0");
    refuses(&[(a, &b)], &[], key);
    // Nor has the mirrored reference.
    let b = format!("{b}\nscan_wall = \"mirrored\"");
    refuses(&[(a, &b)], &["--surface", x3p.to_str().unwrap()], key);
}

/// A sphere on a scan in place (issue 39, part 1): its centre rides on the scan's centre
/// surface, known on a block that loses the dilation's reach at the edges; `run.toml` records
/// the sphere's contact and the block, and the sphere sees smaller deviations than the point.
#[test]
fn a_sphere_bounces_on_the_scan_through_its_centre_surface() {
    let dir = Dir::new();
    let edits = [
        ("beta_deg = [0.0, 60.0]", "beta_deg = [0.0]"),
        ("count = 2000", "count = 1000\ndiameter_um = 20.0"),
        (
            "side_per_corr_length = 20.0",
            "side_per_corr_length = 20.0\ncontact = \"sphere\"",
        ),
    ];
    let case = case_with(dir.path(), &edits);
    let x3p = repo_root().join("tests/data/scans/x3p-2.x3p");
    let out = dir.join("sphere");
    run_case(
        "deterministic",
        &case,
        &out,
        &["--surface", x3p.to_str().unwrap()],
    );
    let manifest: toml::Table =
        toml::from_str(&std::fs::read_to_string(out.join("run.toml")).unwrap()).unwrap();
    let scan = manifest["scan"].as_table().unwrap();
    let first: Vec<i64> = scan["block_first_point"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_integer().unwrap())
        .collect();
    assert!(first.iter().all(|&k| k > 0), "{scan:?}");
    let contact = manifest["sphere_contact"]["contact_fraction"]
        .as_float()
        .unwrap();
    assert!(contact > 0.0 && contact < 1.0, "{contact}");
    let met = manifest["surface_choice"]["measured_delta_xi_deg"]
        .as_float()
        .unwrap();
    let point = scan["delta_xi_deg"].as_float().unwrap();
    assert!(met < point, "the sphere sees {met}°, the point {point}°");
}
