//! The reproduction scripts in reduced mode (issue 6): every expected file appears with its
//! header, so a script cannot rot silently. Runs `scripts/reproduce-all.sh` with
//! `REBOUND_QUICK=1` into a temporary directory, using the binary under test.

use crate::common::{headers, rebound_bin, repo_root};
use std::path::Path;
use std::process::Command;

fn header(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines().next().unwrap_or("").to_string()
}

#[test]
fn reproduce_all_in_reduced_mode_writes_every_expected_file() {
    let root = repo_root();
    let out = tempfile::tempdir().unwrap();
    let status = Command::new("bash")
        .arg(root.join("scripts/reproduce-all.sh"))
        .env("REBOUND_QUICK", "1")
        // The pipe-flow study needs code_saturne: tests/real_systems/pipe_flow.rs runs it.
        .env("REBOUND_WITHOUT_CFD", "1")
        .env("REBOUND_BIN", rebound_bin())
        .env("REBOUND_RESULTS", out.path())
        .status()
        .unwrap();
    assert!(status.success(), "reproduce-all.sh failed");
    let o = out.path();
    let summary = headers::SUMMARY.to_string();
    let pdfs = headers::PDFS.to_string();
    let moments = headers::MOMENTS.to_string();
    let comparison = headers::COMPARISON.to_string();
    let mut expect: Vec<(String, String)> = vec![
        ("radenkovic2021/table1/surface_summary.csv".into(), "nodes,length_um,spacing_um,rms_height_um,target_rms_height_um,rms_slope_x,target_rms_slope_x,rms_slope_z,target_rms_slope_z,delta_xi_deg,target_delta_xi_deg,delta_zeta_deg,target_delta_zeta_deg,max_height_um".into()),
        ("radenkovic2021/table1/normal_angles.csv".into(), "beta_star_deg,delta_xi_star_deg,delta_zeta_star_deg,rho_xi_zeta,rho_xi_eta,rho_eta_zeta,model_delta_xi_star_deg,model_delta_zeta_star_deg,model_rho_xi_zeta".into()),
        ("radenkovic2021/fig4/fig4.csv".into(), "axis,h_over_cl,rms_slope,delta_rad,eq14_rad".into()),
        ("speed_vs_error.csv".into(), "model,particles,spacing_per_corr_length,wall_time_s,us_per_particle,max_ks_alpha_out,max_ks_dbeta,max_abs_mean_alpha_out_err_deg,target_se_deg,max_se_mean_alpha_out_deg,max_abs_z_alpha_out".into()),
    ];
    for scene in [
        "sec3-aniso",
        "sec3-aniso-rev",
        "sec4-glass-steel",
        "sec4-glass-steel-2d",
        "sec4-glass-steel-iso",
        "sec4-glass-steel-fig16",
        "sec4-glass-steel-fig17",
    ] {
        for model in ["deterministic", "stochastic"] {
            expect.push((
                format!("radenkovic2021/{scene}/{model}/summary.csv"),
                summary.clone(),
            ));
            expect.push((
                format!("radenkovic2021/{scene}/{model}/pdfs.csv"),
                pdfs.clone(),
            ));
            expect.push((
                format!("radenkovic2021/{scene}/{model}/moments.csv"),
                moments.clone(),
            ));
        }
        expect.push((
            format!("radenkovic2021/{scene}/compare/comparison.csv"),
            comparison.clone(),
        ));
    }
    let force = "model,lambda,beta_deg,u_n_m_s,diameter_um,density_kg_m3,youngs_pa,poisson,f_max_n,xi,contact_time_s";
    for fig in ["fig4", "fig6", "fig8", "fig9", "fig10", "fig11", "fig12"] {
        expect.push((format!("hu2021/{fig}/force_sweep.csv"), force.into()));
    }
    let eroding = format!("{summary},{}", headers::SUMMARY_EROSION);
    for wall in ["smooth", "iso", "2d", "aniso", "aniso-rev"] {
        for model in ["deterministic", "stochastic"] {
            expect.push((
                format!("erosion/{wall}/{model}/summary.csv"),
                eroding.clone(),
            ));
        }
    }
    expect.push(("erosion/erosion.csv".into(), "wall,delta_xi_deg,delta_zeta_deg,model,beta_in_deg,alpha_nominal_deg,erosion_per_mass,se_erosion_per_mass,erosion_per_mass_rejected,se_erosion_per_mass_rejected,mean_impacts,ratio_to_smooth".into()));
    expect.push(("wall-models/wall_models.csv".into(), "scene,model,max_ks_alpha_out,max_ks_dbeta,max_abs_bias_mean_alpha_out_deg,max_abs_z_alpha_out,max_abs_bias_mean_dbeta_deg,max_abs_z_dbeta,max_ks_alpha_out_steep,max_abs_bias_mean_alpha_out_steep_deg".into()));
    expect.push((
        "finite-size/law/effective_roughness.csv".into(),
        headers::EFFECTIVE.to_string(),
    ));
    expect.push(("spin/spin.csv".into(), "axis,omega_rad_s,model,mean_alpha_out_deg,se_mean_alpha_out_deg,mean_dbeta_deg,se_mean_dbeta_deg".into()));
    expect.push(("finite-size/finite_size.csv".into(), "diameter_um,surface_delta_xi_deg,surface_delta_zeta_deg,effective_delta_xi_deg,effective_delta_zeta_deg,contact_fraction,max_ks_alpha_out_effective,max_ks_dbeta_effective,max_abs_bias_alpha_out_effective_deg,max_ks_alpha_out_nominal,max_ks_dbeta_nominal,max_abs_bias_alpha_out_nominal_deg".into()));
    for (file, head) in &expect {
        assert_eq!(&header(&o.join(file)), head, "{file}");
    }
    // Every run leaves its manifest and at least one figure.
    for dir in [
        "radenkovic2021/table1",
        "radenkovic2021/sec3-aniso/deterministic",
        "radenkovic2021/sec3-aniso/stochastic",
        "hu2021/fig6",
        "erosion/aniso/deterministic",
    ] {
        assert!(o.join(dir).join("run.toml").is_file(), "{dir}/run.toml");
        let svgs = std::fs::read_dir(o.join(dir))
            .unwrap()
            .filter(|e| {
                e.as_ref()
                    .unwrap()
                    .path()
                    .extension()
                    .is_some_and(|x| x == "svg")
            })
            .count();
        assert!(svgs > 0, "{dir} has no figure");
    }
    for svg in ["erosion/erosion.svg", "erosion/erosion_ratios.svg"] {
        assert!(o.join(svg).is_file(), "{svg}");
    }
    let report = std::fs::read_to_string(o.join("REPORT.md")).unwrap();
    for section in [
        "Table 1",
        "Fig. 4",
        "Sec. 3",
        "stochastic model (SM)",
        "Sec. 4.2",
        "Hu et al.",
        "Erosion on rough walls",
        "Which rough-wall model to trust",
        "Finite spheres",
        "Incident spin",
        "Speed against error",
        "Pneumatic conveying in a pipe",
    ] {
        assert!(report.contains(section), "REPORT.md lacks {section}");
    }
    assert!(
        !report.contains("*Not run"),
        "a stage did not run:\n{report}"
    );
}

/// The README's performance table is what `scripts/bench-readme.sh` prints (issue 33): the
/// same header, every row's "what" and target in the script's own format strings, and the
/// date-and-CPU line under it, so anyone can refresh it and its figures are same-run ratios.
#[test]
fn the_readme_performance_table_is_what_bench_readme_prints() {
    let readme = std::fs::read_to_string(repo_root().join("README.md")).unwrap();
    let script = std::fs::read_to_string(repo_root().join("scripts/bench-readme.sh")).unwrap();
    let section = readme
        .split("\n## Performance\n")
        .nth(1)
        .and_then(|s| s.split("\n## ").next())
        .expect("README has a Performance section");
    let table: Vec<&str> = section.lines().filter(|l| l.starts_with('|')).collect();
    let header = "| what | ratio, same run | absolute, this run | target |";
    assert_eq!(table.first(), Some(&header), "the README's table header");
    assert!(
        script.contains(&format!("echo \"{header}\"")),
        "the script's header"
    );
    assert!(table.len() >= 4, "{table:?}");
    for row in &table[2..] {
        let cells: Vec<&str> = row.trim_matches('|').split(" | ").map(str::trim).collect();
        assert_eq!(cells.len(), 4, "{row}");
        assert!(cells[1].contains('×'), "not a ratio: {row}");
        for cell in [cells[0], cells[3]] {
            assert!(
                script.contains(&format!("| {cell} |")),
                "`{cell}` is not a row scripts/bench-readme.sh prints"
            );
        }
    }
    let measured = section
        .lines()
        .find(|l| l.starts_with("Measured "))
        .expect("a `Measured DATE, CPU, cores` line under the table");
    let date = &measured["Measured ".len()..][..10];
    assert!(
        date.as_bytes()
            .iter()
            .enumerate()
            .all(|(i, b)| if i == 4 || i == 7 {
                *b == b'-'
            } else {
                b.is_ascii_digit()
            }),
        "{measured}"
    );
}
