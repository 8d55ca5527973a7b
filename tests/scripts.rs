//! The reproduction scripts in reduced mode (issues 6, 43): every expected file appears with
//! its header, so a script cannot rot silently, and the reproduction runs from what a clone
//! holds. Runs `scripts/reproduce-all.sh` with `REBOUND_QUICK=1`, using the binary under test,
//! over a copy of the `results/` files git tracks — the tree a fresh clone has, whose tables
//! lack the per-run PDFs `.gitignore` drops — then once more over its own output.

use crate::common::{headers, rebound_bin, repo_root};
use std::path::Path;
use std::process::Command;

fn header(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines().next().unwrap_or("").to_string()
}

/// The files of `results/` that git tracks, relative to `results/`.
fn tracked_results() -> Vec<std::path::PathBuf> {
    let listed = Command::new("git")
        .args(["ls-files", "-z", "--", "results"])
        .current_dir(repo_root())
        .output()
        .expect("git ls-files (the tests read results/ as a clone has it)");
    assert!(listed.status.success(), "git ls-files failed");
    let files: Vec<std::path::PathBuf> = listed
        .stdout
        .split(|&b| b == 0)
        .filter(|f| !f.is_empty())
        .map(|f| {
            Path::new(std::str::from_utf8(f).unwrap())
                .strip_prefix("results")
                .unwrap()
                .to_path_buf()
        })
        .collect();
    assert!(
        files.len() > 100,
        "git tracks only {} files under results/",
        files.len()
    );
    files
}

/// Copies the files of `results/` that git tracks into `dest`, as a clone would have them.
fn copy_tracked_results(dest: &Path) {
    let root = repo_root();
    for rel in tracked_results() {
        let to = dest.join(&rel);
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(root.join("results").join(&rel), &to)
            .unwrap_or_else(|e| panic!("results/{}: {e}", rel.display()));
    }
}

/// The tracked results name no path of the machine that made them: a case file under
/// `results/` (a `wall_table`, a `--surface`) must rerun from a clone, and a manifest's inputs
/// must be where a clone has them. So no TOML string there starts with `/`, and no file names
/// a temporary directory (`scripts/common.sh` writes paths relative to the repository).
#[test]
fn tracked_results_name_no_path_of_the_machine_that_made_them() {
    let mut found = Vec::new();
    for rel in tracked_results() {
        let Ok(text) = std::fs::read_to_string(repo_root().join("results").join(&rel)) else {
            continue; // not text
        };
        let is_toml = rel.extension().is_some_and(|x| x == "toml");
        for (k, line) in text.lines().enumerate() {
            let absolute = is_toml
                && (line.contains("= \"/") || line.contains("[\"/") || line.contains(", \"/"));
            if absolute || line.contains("/tmp/") {
                found.push(format!(
                    "results/{}:{}: {}",
                    rel.display(),
                    k + 1,
                    line.trim()
                ));
            }
        }
    }
    assert!(
        found.is_empty(),
        "{} lines of the tracked results name a machine's path (rerun the reproduction with \
         REBOUND_RESULTS unset), the first: {:#?}",
        found.len(),
        &found[..found.len().min(5)]
    );
}

/// What keeps the tracked results free of machine paths at their source: with
/// `REBOUND_RESULTS` unset, `scripts/common.sh` writes into `results` relative to the
/// repository, so the case files and manifests the scripts write name repository paths.
#[test]
fn the_scripts_write_into_a_results_root_relative_to_the_repository() {
    let run = Command::new("bash")
        .arg("-c")
        .arg("source \"$1\" && printf '%s' \"$OUT\"")
        .arg("bash")
        .arg(repo_root().join("scripts/common.sh"))
        .current_dir(repo_root().join("src")) // common.sh moves to the root itself
        .env_remove("REBOUND_RESULTS")
        .env("REBOUND_BIN", rebound_bin()) // no build
        .env("REBOUND_NESTED", "1") // leave the run log as it is
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&run.stdout), "results");
}

fn reproduce_quick(out: &Path) -> String {
    let run = Command::new("bash")
        .arg(repo_root().join("scripts/reproduce-all.sh"))
        .env("REBOUND_QUICK", "1")
        // The pipe-flow study needs code_saturne: tests/real_systems/pipe_flow.rs runs it.
        .env("REBOUND_WITHOUT_CFD", "1")
        .env("REBOUND_BIN", rebound_bin())
        .env("REBOUND_RESULTS", out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "reproduce-all.sh failed over {}:\n{}\n{}",
        out.display(),
        &stdout[stdout.len().saturating_sub(3000)..],
        String::from_utf8_lossy(&run.stderr)
    );
    std::fs::read_to_string(out.join("reproducibility.txt")).expect("reproducibility.txt")
}

/// The number after `key` on its line of a `reproducibility.txt`.
fn count(text: &str, key: &str) -> usize {
    let line = text
        .lines()
        .find(|l| l.starts_with(key))
        .unwrap_or_else(|| panic!("no `{key}` in\n{text}"));
    line[key.len()..]
        .split_whitespace()
        .next()
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{line}"))
}

#[test]
fn reproduce_all_in_reduced_mode_runs_from_a_clone_and_writes_every_expected_file() {
    let out = tempfile::tempdir().unwrap();
    let o = out.path();
    copy_tracked_results(o);
    let csvs_in_clone = walk_csvs(o);
    // 1. From the clone's tree: every CSV it had is byte-identical or differs for a stated
    //    reason (the clone's were made in full mode, this run is quick).
    let first = reproduce_quick(o);
    assert!(first.starts_with("mode: quick\n"), "{first}");
    assert_eq!(
        count(&first, "CSV files present before this run: "),
        csvs_in_clone,
        "{first}"
    );
    let different = count(&first, "different: ");
    if different > 0 {
        assert!(
            first.contains(
                "(explained: the files before were made in full mode, this run in quick mode)"
            ),
            "{first}"
        );
    }
    // 2. Again over its own output: the same seeds give the same bytes, for every CSV.
    let second = reproduce_quick(o);
    assert_eq!(count(&second, "different: "), 0, "{second}");
    assert_eq!(
        count(
            &second,
            "byte-identical after re-running with the same seeds: "
        ),
        walk_csvs(o),
        "{second}"
    );
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

/// The CSV files under `dir` that the reproduction fingerprints (all but speed_vs_error.csv and
/// costs.csv, which hold wall and CPU times).
fn walk_csvs(dir: &Path) -> usize {
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            n += walk_csvs(&p);
        } else if p.extension().is_some_and(|x| x == "csv")
            && p.file_name()
                .is_some_and(|f| f != "speed_vs_error.csv" && f != "costs.csv")
        {
            n += 1;
        }
    }
    n
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
