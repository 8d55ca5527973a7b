//! The roughness a finite sphere sees (issue "the particle as a sphere", item 2):
//! `rebound surface` with `[stats] diameter_um` writes `effective_roughness.csv` and its
//! figure, from the centre surfaces of the spheres (paraboloid dilation).

use crate::common::*;

/// The surface of the issue's own brute-force check: h = 0.37 µm, Δξ = 3.8°, Δζ = 7.5°
/// (c_Lz ≈ 4 µm), L = 512 µm.
const CASE: &str = r#"name = "effective"
seed = 3
[surface]
length_um = 512.0
nodes = 512
rms_height_um = 0.37
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[stats]
diameter_um = [0.001, 5.0, 50.0, 100.0, 500.0]
"#;

#[test]
fn spheres_see_a_smoother_wall_as_the_issue_measured() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", CASE);
    let out = run_case("surface", &case, &tmp.path().join("out"), &[]);
    let c = Csv::read(&out.join("effective_roughness.csv"));
    assert_eq!(c.header.join(","), headers::EFFECTIVE);
    assert!(out.join("effective_roughness.svg").is_file());
    let row = |d: f64| {
        c.rows
            .iter()
            .find(|r| (c.num(r, "diameter_um") - d).abs() < 1e-9)
            .unwrap()
    };
    // D → 0: the surface itself, every node touched.
    let r0 = row(0.001);
    assert_eq!(c.num(r0, "delta_xi_ratio"), 1.0);
    assert_eq!(c.num(r0, "delta_zeta_ratio"), 1.0);
    assert_eq!(c.num(r0, "contact_fraction"), 1.0);
    // The issue's brute-force paraboloid check (forward differences of the dilated
    // surface, another seed): Δξ_eff, Δζ_eff in degrees, within 8 %.
    for (d, xi, zeta) in [
        (5.0, 3.84, 7.33),
        (50.0, 3.6, 5.1),
        (100.0, 3.1, 3.6),
        (500.0, 1.5, 1.5),
    ] {
        let r = row(d);
        let (x, z) = (c.num(r, "delta_xi_eff_deg"), c.num(r, "delta_zeta_eff_deg"));
        assert!((x / xi - 1.0).abs() < 0.08, "D = {d}: Δξ_eff {x} vs {xi}");
        assert!(
            (z / zeta - 1.0).abs() < 0.08,
            "D = {d}: Δζ_eff {z} vs {zeta}"
        );
    }
    // Larger spheres: smoother in both directions, fewer contacts; anisotropy fades.
    let mut last = (1.0, 1.0, 1.0);
    for d in [5.0, 50.0, 100.0, 500.0] {
        let r = row(d);
        let now = (
            c.num(r, "delta_xi_ratio"),
            c.num(r, "delta_zeta_ratio"),
            c.num(r, "contact_fraction"),
        );
        assert!(
            now.0 <= last.0 && now.1 <= last.1 && now.2 < last.2,
            "D = {d}"
        );
        last = now;
    }
    let big = row(500.0);
    let aniso = c.num(big, "delta_zeta_eff_deg") / c.num(big, "delta_xi_eff_deg");
    assert!(aniso < 1.1, "{aniso}");
    assert!((c.num(big, "d_over_cl_z") - 125.0).abs() < 1.0);
}

#[test]
fn diameters_beyond_the_side_or_out_of_range_are_refused() {
    let tmp = Dir::new();
    for (list, needle) in [
        ("[600.0]", "at most the surface side"),
        ("[-1.0]", "stats.diameter_um"),
        ("[1e7]", "stats.diameter_um"),
    ] {
        let case = write_case(
            tmp.path(),
            "bad.toml",
            &CASE.replace("[0.001, 5.0, 50.0, 100.0, 500.0]", list),
        );
        refuse_case("surface", &case, tmp.path(), needle);
    }
    // Without diameters nothing is computed or written.
    let case = write_case(
        tmp.path(),
        "none.toml",
        &CASE.replace("diameter_um = [0.001, 5.0, 50.0, 100.0, 500.0]", ""),
    );
    let out = run_case("surface", &case, &tmp.path().join("none"), &[]);
    assert!(!out.join("effective_roughness.csv").exists());
}

/// The pipe-flow study's rough wall (`configs/cases/pipe-wall.toml`, issue 40, part 3): its
/// 500 µm spheres see the Sec. 4 wall, (3.8°, 7.5°), to 0.5 %, and smaller beads see more
/// across the lay, not along it, by the amounts docs/pipe-flow.md quotes (to 0.5 %).
#[test]
fn the_pipe_walls_500_um_row_is_the_sec4_wall() {
    let tmp = Dir::new();
    let out = run_case(
        "surface",
        &shipped_case("cases/pipe-wall.toml"),
        &tmp.path().join("out"),
        &[],
    );
    let c = Csv::read(&out.join("effective_roughness.csv"));
    let seen = |d: f64| {
        let r = c
            .rows
            .iter()
            .find(|r| (c.num(r, "diameter_um") - d).abs() < 1e-9)
            .unwrap();
        (c.num(r, "delta_xi_eff_deg"), c.num(r, "delta_zeta_eff_deg"))
    };
    for (d, xi, zeta) in [
        (500.0, 3.8, 7.5),
        (200.0, 3.815, 8.352),
        (100.0, 3.815, 8.387),
    ] {
        let (x, z) = seen(d);
        assert!(
            (x / xi - 1.0).abs() < 0.005 && (z / zeta - 1.0).abs() < 0.005,
            "D = {d} µm: ({x}, {z}) vs ({xi}, {zeta})"
        );
    }
}
