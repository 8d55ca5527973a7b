//! Erosion checked against real tools no one here wrote (issue 12):
//!
//! * OpenFOAM v1912's `particleErosion` cloud function (Finnie; Debian's `openfoam`, which
//!   `scripts/install-deps.sh` installs): `scripts/openfoam-erosion/run.sh` runs the solver on a box whose
//!   parcels hit a smooth wall once each at 16 angles and 3 speeds, for two parameter sets,
//!   and writes each impact's eroded volume. The test runs it for real, checks the output
//!   against the committed `tests/data/openfoam_erosion.csv`, and checks `rebound`'s Finnie
//!   volumes on a smooth wall (both models, through the binary) against OpenFOAM's.
//! * Equinor's `pysand` (DNV RP-O501, installed by `scripts/install-deps.sh` in the project's
//!   virtual environment): `scripts/pysand/reference.sh` tabulates its angle function and erosion per unit mass; the
//!   test runs it, checks the committed `tests/data/dnv_pysand*.csv`, and checks
//!   `model = "dnv"` against them to 1e-9 relative.

use crate::common::{repo_root, run_case, write_case, Csv};
use roughwall::erosion::Finnie;
use roughwall::erosion::{AngleDependency, Dnv};
use roughwall::ErosionModel;
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    repo_root().to_path_buf()
}

/// Runs a reference script for real; panics with its output when it fails.
fn run_script(script: &str, arg: &Path) -> String {
    let out = Command::new("bash")
        .arg(root().join(script))
        .arg(arg)
        .output()
        .unwrap_or_else(|e| panic!("run {script}: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{script}: {stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// The regenerated table equals the committed one: same header and text cells, numbers
/// within `rel` (relative).
fn assert_same_table(committed: &Csv, fresh: &Csv, rel: f64, what: &str) {
    assert_eq!(committed.header, fresh.header, "{what}");
    assert_eq!(committed.rows.len(), fresh.rows.len(), "{what}");
    for (a, b) in committed.rows.iter().zip(&fresh.rows) {
        for (x, y) in a.iter().zip(b) {
            match (x.parse::<f64>(), y.parse::<f64>()) {
                (Ok(x), Ok(y)) => assert!(
                    (x - y).abs() <= rel * x.abs().max(y.abs()),
                    "{what}: {x} vs {y}"
                ),
                _ => assert_eq!(x, y, "{what}"),
            }
        }
    }
}

/// `m|U|²/(p ψ K)`: the scale of Finnie's volume, against which the 90° rows (zero but for
/// rounding, `cos 90° ≈ 6e-17`) are compared.
fn finnie_scale(c: &Csv, row: &[String]) -> f64 {
    let u = c.num(row, "speed_m_s");
    c.num(row, "mass_kg") * u * u / (c.num(row, "p_pa") * c.num(row, "psi") * c.num(row, "k"))
}

#[test]
fn finnie_on_a_smooth_wall_equals_openfoams_particle_erosion() {
    let tmp = tempfile::tempdir().unwrap();
    let fresh_path = tmp.path().join("openfoam_erosion.csv");
    run_script("scripts/openfoam-erosion/run.sh", &fresh_path);
    let committed = Csv::read(&root().join("tests/data/openfoam_erosion.csv"));
    let fresh = Csv::read(&fresh_path);
    assert_same_table(&committed, &fresh, 1e-12, "OpenFOAM rerun");
    assert!(committed.rows.len() >= 90);

    // The library's law, impact by impact.
    for row in &fresh.rows {
        let f = Finnie {
            flow_stress_pa: fresh.num(row, "p_pa"),
            psi: fresh.num(row, "psi"),
            k: fresh.num(row, "k"),
        };
        let alpha = fresh.num(row, "alpha_deg").to_radians();
        let q = f.volume_per_mass(fresh.num(row, "speed_m_s"), alpha) * fresh.num(row, "mass_kg");
        let of = fresh.num(row, "q_openfoam_m3");
        assert!(
            (q - of).abs() <= 1e-12 * finnie_scale(&fresh, row),
            "{row:?}: {q} vs {of}"
        );
    }

    // The binary, on a smooth wall: one case per parameter set and speed, every angle.
    let mut groups: Vec<(String, Vec<&Vec<String>>)> = Vec::new();
    for row in &fresh.rows {
        let key = [
            "p_pa",
            "psi",
            "k",
            "speed_m_s",
            "diameter_m",
            "density_kg_m3",
        ]
        .map(|k| fresh.cell(row, k).to_string())
        .join(",");
        match groups.iter_mut().find(|g| g.0 == key) {
            Some(g) => g.1.push(row),
            None => groups.push((key, vec![row])),
        }
    }
    let mut checked = 0;
    for (g, (_, rows)) in groups.iter().enumerate() {
        let r0 = rows[0];
        let alphas: Vec<String> = rows
            .iter()
            .map(|r| format!("-{}", fresh.cell(r, "alpha_deg")))
            .collect();
        let case = write_case(
            tmp.path(),
            &format!("of{g}.toml"),
            &format!(
                "name = \"of{g}\"\n[wall]\ndelta_xi_deg = 0\ndelta_zeta_deg = 0\n\
                 [incidence]\nalpha_deg = [{}]\nspeed_mean_m_s = {}\nspeed_reference = \"magnitude\"\n\
                 [particles]\ncount = 2\ndiameter_um = {}\ndensity_kg_m3 = {}\n\
                 [erosion]\nmodel = \"finnie\"\nflow_stress_pa = {}\npsi = {}\nk = {}\n",
                alphas.join(", "),
                fresh.cell(r0, "speed_m_s"),
                fresh.num(r0, "diameter_m") * 1e6,
                fresh.cell(r0, "density_kg_m3"),
                fresh.cell(r0, "p_pa"),
                fresh.cell(r0, "psi"),
                fresh.cell(r0, "k"),
            ),
        );
        for model in ["deterministic", "stochastic"] {
            let out = run_case(
                model,
                &case,
                &tmp.path().join(format!("of{g}-{model}")),
                &[],
            );
            let s = Csv::read(&out.join("summary.csv"));
            for row in rows {
                let a = -fresh.num(row, "alpha_deg");
                let line = s
                    .rows
                    .iter()
                    .find(|l| s.num(l, "alpha_in_deg") == a)
                    .unwrap_or_else(|| panic!("{model}: no row for {a}"));
                assert_eq!(s.num(line, "mean_impacts"), 1.0);
                let q = s.num(line, "erosion_per_mass") * fresh.num(row, "mass_kg");
                let of = fresh.num(row, "q_openfoam_m3");
                let scale = finnie_scale(&fresh, row);
                // Six significant digits (the CSV keeps seven); at 90° both are rounding.
                let ok = if of > 1e-9 * scale {
                    (q - of).abs() <= 1e-6 * of
                } else {
                    q.abs() <= 1e-9 * scale
                };
                assert!(ok, "{model} α = {a}: {q} vs OpenFOAM {of}");
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 2 * fresh.rows.len());
}

fn dependency(s: &str) -> AngleDependency {
    match s {
        "ductile" => AngleDependency::Ductile,
        "brittle" => AngleDependency::Brittle,
        other => panic!("angle dependency {other}"),
    }
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    a == b || (a - b).abs() <= rel * a.abs().max(b.abs())
}

#[test]
fn dnv_matches_pysand_to_1e_9() {
    let tmp = tempfile::tempdir().unwrap();
    let stdout = run_script("scripts/pysand/reference.sh", tmp.path());
    assert!(stdout.contains("pysand 2.0.0"), "{stdout}");
    let data = root().join("tests/data");
    for name in ["dnv_pysand.csv", "dnv_pysand_F.csv"] {
        assert_same_table(
            &Csv::read(&data.join(name)),
            &Csv::read(&tmp.path().join(name)),
            1e-12,
            name,
        );
    }

    let f = Csv::read(&data.join("dnv_pysand_F.csv"));
    for row in &f.rows {
        let a = f.num(row, "alpha_rad");
        for (col, ad) in [
            ("F_ductile", AngleDependency::Ductile),
            ("F_brittle", AngleDependency::Brittle),
        ] {
            let d = Dnv {
                k: 2e-9,
                n: 2.6,
                target_density_kg_m3: 7800.0,
                angle_dependency: ad,
            };
            let (ours, theirs) = (d.angle_function(a), f.num(row, col));
            assert!(
                close(ours, theirs, 1e-9),
                "{col} at {a}: {ours} vs {theirs}"
            );
        }
    }

    let c = Csv::read(&data.join("dnv_pysand.csv"));
    assert_eq!(c.rows.len(), 384);
    for row in &c.rows {
        let d = Dnv {
            k: c.num(row, "K"),
            n: c.num(row, "n"),
            target_density_kg_m3: c.num(row, "rho_t"),
            angle_dependency: dependency(c.cell(row, "angle_dependency")),
        };
        let (a, u) = (c.num(row, "alpha_rad"), c.num(row, "U_p"));
        let theirs = c.num(row, "E_v_m3_per_kg");
        let ours = d.volume_per_mass(u, a);
        assert!(close(ours, theirs, 1e-9), "{row:?}: {ours}");
        // Through the law a run uses (angle clamped to [0, π/2], never NaN).
        let model = ErosionModel::Dnv(d);
        assert!(close(model.volume_per_mass(u, a, 1e-4), theirs, 1e-9));
    }

    // The binary, on a smooth wall: carbon steel at 30 m/s.
    let rows: Vec<&Vec<String>> = c
        .rows
        .iter()
        .filter(|r| {
            c.cell(r, "material") == "carbon_steel"
                && c.num(r, "U_p") == 30.0
                && c.num(r, "alpha_deg") >= 1.0
        })
        .collect();
    let alphas: Vec<String> = rows
        .iter()
        .map(|r| format!("-{}", c.num(r, "alpha_deg")))
        .collect();
    let case = write_case(
        tmp.path(),
        "dnv.toml",
        &format!(
            "name = \"dnv\"\n[wall]\ndelta_xi_deg = 0\ndelta_zeta_deg = 0\n\
             [incidence]\nalpha_deg = [{}]\nspeed_mean_m_s = 30\nspeed_reference = \"magnitude\"\n\
             [particles]\ncount = 1\n[erosion]\nmodel = \"dnv\"\nk = 2e-9\nn = 2.6\n\
             target_density_kg_m3 = 7800\n",
            alphas.join(", ")
        ),
    );
    let out = run_case("stochastic", &case, &tmp.path().join("dnv-run"), &[]);
    let s = Csv::read(&out.join("summary.csv"));
    assert_eq!(s.rows.len(), rows.len());
    for row in rows {
        let a = -c.num(row, "alpha_deg");
        let line = s
            .rows
            .iter()
            .find(|l| s.num(l, "alpha_in_deg") == a)
            .unwrap();
        let (ours, theirs) = (s.num(line, "erosion_per_mass"), c.num(row, "E_v_m3_per_kg"));
        assert!(close(ours, theirs, 1e-6), "α = {a}: {ours} vs {theirs}");
    }
}
