//! The real instrument files of the workspace's `tests/data/scans/` (SurfaceTopography's
//! examples; `README.md` there says where each comes from): shape, pixel size, missing points
//! and a few heights per file. The expected values are SurfaceTopography 1.27.1's reading of
//! the same files (its dump by `tests/real_systems/surfacetopography_dump.py`), which the
//! workspace's `real_systems` test compares point by point; here they are fixed numbers, so
//! `cargo test -p topography` needs nothing but the toolchain.

use std::path::PathBuf;
use topography::{read, read_matrix, read_xyz, Format, Topography};

fn scan(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data/scans")
        .join(name)
}

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

/// Checks shape, pixel sizes, the count of missing points and heights at (ix, iy).
fn check(
    t: &Topography,
    format: Format,
    shape: (usize, usize),
    d: (f64, f64),
    missing: usize,
    points: &[(usize, usize, f64)],
) {
    assert_eq!(t.format, format);
    assert_eq!((t.nx, t.ny), shape);
    assert_eq!(t.heights_m.len(), shape.0 * shape.1);
    assert!(close(t.dx_m, d.0), "dx {} vs {}", t.dx_m, d.0);
    assert!(close(t.dy_m, d.1), "dy {} vs {}", t.dy_m, d.1);
    assert_eq!(t.heights_m.len() - t.valid_count(), missing);
    for &(ix, iy, h) in points {
        let ours = t.heights_m[iy * t.nx + ix];
        if h.is_nan() {
            assert!(ours.is_nan() && !t.is_valid(ix, iy), "({ix}, {iy}): {ours}");
        } else {
            assert!(close(ours, h), "({ix}, {iy}): {ours} vs {h}");
            assert!(t.is_valid(ix, iy));
        }
    }
}

#[test]
fn x3p_exported_by_mountainsmap() {
    let t = read(&scan("x3p-2.x3p")).unwrap();
    check(
        &t,
        Format::X3p,
        (650, 650),
        (1.27656509837346e-7, 3.14582113527746e-7),
        0,
        &[
            (0, 0, 6.579781341223288e-08),
            (649, 649, -3.276918658776711e-08),
            (325, 216, 9.285913412232885e-09),
            (216, 325, -2.380938658776711e-08),
        ],
    );
    assert_eq!(t.info_value("main.xml MD5"), Some("verified"));
    assert_eq!(t.info_value("point data MD5"), Some("verified"));
    assert_eq!(t.info_value("vendor"), Some("DIGITAL SURF"));
    assert_eq!(t.info_value("data type"), Some("D"));
}

#[test]
fn sur_with_non_measured_points() {
    let t = read(&scan("sur-2.sur")).unwrap();
    check(
        &t,
        Format::Sur,
        (563, 484),
        (3.4840002190321683e-06, 3.4840002190321683e-06),
        117,
        &[
            (0, 0, 1.014770011858701e-05),
            (562, 483, f64::NAN),
            (281, 161, 1.015350011865479e-05),
            (187, 242, 1.0169600118842937e-05),
            (301, 0, f64::NAN),
        ],
    );
    assert_eq!(t.info_value("z step unit"), Some("mm"));
}

#[test]
fn sur_in_nanometres_and_metres_with_a_z_offset() {
    let t = read(&scan("sur-3.sur")).unwrap();
    // SurfaceTopography leaves the file's z offset out; this reader adds it.
    let offset = -3.4143300727009773e-3;
    assert_eq!(t.info_value("z offset (m)"), Some("-3.4143300727009773e-3"));
    check(
        &t,
        Format::Sur,
        (512, 512),
        (2.95546e-4, 2.95546e-4),
        233009,
        &[
            (0, 0, f64::NAN),
            (511, 511, f64::NAN),
            (170, 256, 0.006954876803302645 + offset),
        ],
    );
    assert_eq!(t.info_value("x step unit"), Some("nm"));
    assert_eq!(t.info_value("date"), Some("2023-06-22 10:08:53"));
}

#[test]
fn metropro_from_a_zygo_interferometer() {
    let t = read(&scan("metropro-1.dat")).unwrap();
    check(
        &t,
        Format::MetroPro,
        (640, 480),
        (1.0982520279867458e-06, 1.0982520279867458e-06),
        0,
        &[
            (0, 0, 5.05753145602552e-05),
            (639, 479, 5.085188667204241e-05),
            (320, 160, 5.075044761610435e-05),
            (213, 240, 5.0708221206383075e-05),
        ],
    );
    assert_eq!(t.info_value("objective"), Some("20X  Mirau"));
}

#[test]
fn opd_from_a_wyko_interferometer() {
    let t = read(&scan("opd-1.opd")).unwrap();
    check(
        &t,
        Format::Opd,
        (640, 480),
        (1.9673303177114576e-07, 1.9673303177114576e-07),
        116,
        &[
            (0, 0, -2.6550621614908414e-07),
            (639, 479, -2.73773812086265e-07),
            (320, 160, -2.746491716046585e-07),
            (213, 240, -2.731203075766116e-07),
            (476, 234, f64::NAN),
        ],
    );
    assert_eq!(t.info_value("channel"), Some("Raw"));
}

#[test]
fn plu_from_a_sensofar_profiler() {
    let t = read(&scan("plu-1.plu")).unwrap();
    check(
        &t,
        Format::Plu,
        (768, 576),
        (1.6600000858306884e-06, 1.6600000858306884e-06),
        0,
        &[
            (0, 0, -0.0001112265625),
            (767, 575, -0.00010121484375),
            (384, 192, -0.00010626171874999999),
            (256, 288, -0.00010782421875),
        ],
    );
}

#[test]
fn gwyddion_text_exports_in_english_and_german() {
    for name in ["gwyddion-export-english.txt", "gwyddion-export-german.txt"] {
        let t = read(&scan(name)).unwrap();
        // # Width: 12.34 µm over 3 columns, # Height: 5678.9 nm over 4 rows.
        check(
            &t,
            Format::GwyddionText,
            (3, 4),
            (4.113333333333333e-06, 1.419725e-06),
            0,
            &[(0, 0, 1.0), (2, 3, 9.0), (1, 1, -3.0), (1, 2, 0.0)],
        );
        assert_eq!(t.info_value("channel"), Some("My Channel Name"));
    }
}

#[test]
fn gwyddion_text_of_an_afm_scan() {
    let t = read(&scan("matrix-3.txt")).unwrap();
    check(
        &t,
        Format::GwyddionText,
        (256, 256),
        (3.9062499999999997e-08, 3.9062499999999997e-08),
        0,
        &[
            (0, 0, 1.8823e-08),
            (255, 255, -7.5542e-08),
            (128, 85, -6.232e-08),
            (85, 128, -1.4726e-08),
        ],
    );
    assert_eq!(t.info_value("channel"), Some("ZSensor"));
    let t = read(&scan("matrix-6.txt")).unwrap();
    check(
        &t,
        Format::GwyddionText,
        (4, 3),
        (2.4999999999999998e-06, 3.333333333333333e-06),
        0,
        &[(0, 0, 1.0), (3, 2, 12.0), (2, 1, 7.0), (1, 1, 6.0)],
    );
}

#[test]
fn phase_text_with_a_height_conversion_factor() {
    let t = read(&scan("matrix-4.txt")).unwrap();
    check(
        &t,
        Format::PhaseText,
        (75, 305),
        (3.69862e-07, 3.69862e-07),
        0,
        &[
            (0, 0, -1.298199355698e-07),
            (74, 304, 1.980200491684e-07),
            (37, 101, 9.338730454199999e-09),
            (25, 152, -1.286590835658e-07),
        ],
    );
}

#[test]
fn a_plain_matrix_needs_its_units_from_the_caller() {
    let e = read(&scan("matrix-5.txt")).unwrap_err();
    assert_eq!(e.kind(), topography::ErrorKind::NoUnits);
    assert!(e.to_string().contains("read_matrix"), "{e}");
    let t = read_matrix(&scan("matrix-5.txt"), 1e-6, 2e-6, 1e-9).unwrap();
    check(
        &t,
        Format::Matrix,
        (10, 10),
        (1e-6, 2e-6),
        0,
        &[(0, 0, 2e-9), (9, 4, 2e-9), (0, 5, 0.0), (9, 9, 0.0)],
    );
}

#[test]
fn xyz_on_a_regular_grid_in_any_order() {
    for name in ["xyz-1.txt", "xyz-1-different-order.txt"] {
        assert_eq!(
            read(&scan(name)).unwrap_err().kind(),
            topography::ErrorKind::NoUnits
        );
        let t = read_xyz(&scan(name), 1e-3, 1e-6).unwrap();
        // Rows are x y z; x = 1, y = 1 and x = 1, y = 2 are 2 in xyz-1.
        check(
            &t,
            Format::Xyz,
            (4, 4),
            (1e-3, 1e-3),
            0,
            &[(0, 0, 1e-6), (1, 1, 2e-6), (1, 2, 2e-6), (2, 1, 1e-6)],
        );
    }
    let t = read_xyz(&scan("xyz-2.txt"), 1.0, 1.0).unwrap();
    check(
        &t,
        Format::Xyz,
        (4, 4),
        (1.0, 1.0),
        2,
        &[(1, 0, f64::NAN), (2, 1, f64::NAN), (2, 2, 2.0), (0, 3, 1.0)],
    );
}

/// x3ptools' `sample-land.x3p` (a Sensofar confocal scan of a machined metal surface, a
/// bullet land; MIT): `main.xml` in a folder of the archive and an empty `<Offset/>`. The
/// expected heights are its `bindata/data.bin` decoded independently (little-endian f64 ×
/// Increment 1; NaN marks the 25,292 masked points).
#[test]
fn x3p_from_x3ptools_with_a_folder_and_an_empty_offset() {
    let t = read(&scan("x3ptools-sample-land.x3p")).unwrap();
    check(
        &t,
        Format::X3p,
        (918, 256),
        (2.58e-6, 2.58e-6),
        25_292,
        &[
            (0, 0, -5.421108289738186e-05),
            (917, 255, f64::NAN),
            (459, 128, 4.1360955947311595e-05),
            (100, 200, -5.7384844694752246e-05),
        ],
    );
    assert_eq!(t.info_value("main.xml MD5"), Some("verified"));
    assert_eq!(t.info_value("point data MD5"), Some("verified"));
    assert!(t.info_value("main.xml").unwrap().contains("sample-land/"));
    assert_eq!(t.info_value("vendor"), Some("Sensofar"));
}

/// CSAFE's processed Weller scan TW05-08 (cartridgeCaseScans, CC-BY 4.0): the breech-face
/// impression on a fired 9 mm cartridge case's primer (metal), a NanoFocus µsurf confocal scan,
/// band-pass filtered and downsampled by its authors; the firing-pin hole and the outside of
/// the primer are NaN. Its `main.xml` states a `<Mask>` whose image the archive does not
/// hold: the heights are read, the mask is not needed. The expected heights are its
/// `bindata/data.bin` decoded independently (little-endian f64 × Increment 1).
#[test]
fn x3p_of_a_cartridge_case_with_a_mask_record_and_no_mask_image() {
    let t = read(&scan("csafe-cartridge-case-TW05-08.x3p")).unwrap();
    check(
        &t,
        Format::X3p,
        (631, 631),
        (6.25e-6, 6.25e-6),
        216_633,
        &[
            (0, 0, f64::NAN),
            (315, 315, f64::NAN),
            (100, 200, -3.418991157676885e-07),
            (200, 100, 1.5655955490759868e-06),
            (560, 320, -5.366284091612832e-07),
            (320, 560, -7.243953590227254e-07),
        ],
    );
    assert_eq!(t.info_value("main.xml MD5"), Some("verified"));
    assert_eq!(t.info_value("point data MD5"), Some("verified"));
    assert_eq!(t.info_value("vendor"), Some("NanoFocus"));
}
