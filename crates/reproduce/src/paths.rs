//! The layout of `results/`: the names of the directories the reproduction scripts
//! (`scripts/*.sh`) write and `rebound report` reads, written once.
//!
//! The scripts read the same names from `scripts/paths.sh`, which is generated from
//! `SHELL` by a unit test of this module, which fails when the committed file differs;
//! `ROUGHWALL_BLESS=1 cargo test -p reproduce paths_sh` rewrites it. Some names exist only
//! for the scripts (the report does not read them).
//! `scripts/common.sh` sources it. The files inside a run directory (`summary.csv`,
//! `run.toml`, …) are named by the command that writes them, not here.

/// `scripts/reproduce-all.sh`'s record of whether re-running gave the same bytes.
pub const REPRODUCIBILITY: &str = "reproducibility.txt";

/// Radenkovic & Simonin 2021 (`scripts/radenkovic2021.sh`).
pub const RADENKOVIC2021: &str = "radenkovic2021";
/// Hu et al. 2021 (`scripts/hu2021.sh`).
pub const HU2021: &str = "hu2021";
/// Every stochastic variant against `deterministic` (`scripts/wall-models.sh`).
pub const WALL_MODELS: &str = "wall-models";
/// The calibrated escape law (`scripts/calibrate.sh`).
pub const CALIBRATION: &str = "calibration";
/// Erosion on rough walls (`scripts/erosion.sh`).
pub const EROSION: &str = "erosion";
/// Finite spheres (`scripts/finite-size.sh`).
pub const FINITE_SIZE: &str = "finite-size";
/// Incident spin (`scripts/spin.sh`).
pub const SPIN: &str = "spin";
/// Speed against error (`scripts/speed-vs-error.sh`).
pub const SPEED_VS_ERROR: &str = "speed-vs-error";
/// Mirror symmetry of the deterministic wall (`scripts/mirror.sh`).
pub const MIRROR: &str = "mirror";
/// Your own wall: nominal deviations and real scans (`scripts/measured-walls.sh`).
pub const MEASURED_WALLS: &str = "measured-walls";
/// Pneumatic conveying in a pipe with rough walls, in code_saturne (`scripts/pipe-flow.sh`).
pub const PIPE_FLOW: &str = "pipe-flow";
/// The same study in quick mode (`scripts/pipe-flow.sh --quick`, what `reproduce-all.sh`
/// runs): the report falls back on it when the full study is missing.
pub const PIPE_FLOW_QUICK: &str = "pipe-flow-quick";

/// A scene's `rebound deterministic` run.
pub const DETERMINISTIC: &str = "deterministic";
/// A scene's `rebound stochastic` run.
pub const STOCHASTIC: &str = "stochastic";
/// `rebound compare` of a scene's two runs.
pub const COMPARE: &str = "compare";

/// Radenkovic & Simonin 2021, Table 1: the paper's surface.
pub const TABLE1: &str = "table1";
/// Radenkovic & Simonin 2021, Fig. 4: one surface per rms height, `h<height>`.
pub const FIG4: &str = "fig4";
/// Prefix of Fig. 4's runs (`h0.2`, …).
pub const FIG4_RUN: &str = "h";
/// Prefix of the Sec. 3 scenes (`sec3-aniso`, …).
pub const SEC3: &str = "sec3-";
/// Prefix of the Sec. 4 scenes (`sec4-glass-steel`, …).
pub const SEC4: &str = "sec4-";
/// The Sec. 4 glass-on-steel scene (the finite-size study compares with it).
pub const SEC4_GLASS_STEEL: &str = "sec4-glass-steel";
/// Prefix of the Sec. 4.2 scenes of Figs. 16 and 17 (`sec4-glass-steel-fig16`, …).
pub const SEC4_FIGS_16_17: &str = "sec4-glass-steel-fig1";

/// Hu et al. 2021, Fig. 4 (spheres).
pub const HU_FIG4: &str = "fig4";
/// Hu et al. 2021, Fig. 6 (F_max against β).
pub const HU_FIG6: &str = "fig6";
/// Hu et al. 2021, Fig. 9 (ξ against β).
pub const HU_FIG9: &str = "fig9";
/// Hu et al. 2021, Fig. 11b (F_max against U_N).
pub const HU_FIG11B: &str = "fig11b";
/// Every Hu et al. figure run, one directory each, from `configs/cases/hu-<figure>.toml`.
pub const HU2021_FIGS: [&str; 9] = [
    HU_FIG4, HU_FIG6, "fig8", HU_FIG9, "fig10", "fig10b", "fig11", HU_FIG11B, "fig12",
];

/// The scenes of Radenkovic & Simonin 2021 (directories under [`RADENKOVIC2021`]) on which
/// every stochastic variant runs against their `deterministic` run; under [`WALL_MODELS`] each
/// has a directory named without its `sec3-`/`sec4-` prefix ([`scene_name`]).
pub const WALL_MODELS_SCENES: [&str; 9] = [
    "sec3-aniso",
    "sec3-aniso-rev",
    "sec4-glass-steel-2d",
    "sec4-glass-steel-iso",
    "sec4-glass-steel",
    "sec4-glass-steel-fig16",
    "sec4-glass-steel-fig16-2d",
    "sec4-glass-steel-fig17",
    "sec4-glass-steel-fig17-2d",
];

/// The calibration benchmark's scenes (`scripts/calibrate.sh`): their case files under
/// `configs/` without `.toml`; under [`CALIBRATION`] each has a directory named like the file.
pub const CALIBRATION_SCENES: [&str; 7] = [
    "cases/aniso",
    "cases/aniso-rev",
    "cases/glass-steel",
    "cases/glass-steel-2d",
    "cases/glass-steel-iso",
    "calibration/test-5-5",
    "calibration/test-4-1",
];

/// The erosion study's walls (`scripts/erosion.sh`), `name:Δξ:Δζ` (degrees), in the order
/// the script runs them; under [`EROSION`] each has a directory named `name`. Isotropic: the
/// mean-square slope of the Sec. 3 walls, √((2.5² + 7.5²)/2) = 5.59°; 2-D: the larger Sec. 3
/// deviation along x only.
pub const EROSION_WALLS: [&str; 5] = [
    "smooth:0.0:0.0",
    "iso:5.59:5.59",
    "2d:7.5:0.0",
    "aniso:2.5:7.5",
    "aniso-rev:7.5:2.5",
];

/// An erosion wall's name ([`EROSION_WALLS`]).
pub fn erosion_wall_name(wall: &str) -> &str {
    wall.split(':').next().unwrap_or(wall)
}

/// The erosion study's incident directions β⁻ (degrees).
pub const EROSION_BETAS_DEG: [&str; 3] = ["0.0", "45.0", "90.0"];

/// A calibration scene's directory name: its case file's name ([`CALIBRATION_SCENES`]).
pub fn calibration_scene_name(case: &str) -> &str {
    case.rsplit('/').next().unwrap_or(case)
}

/// A scene's name: its directory under [`RADENKOVIC2021`] without the [`SEC3`]/[`SEC4`] prefix.
pub fn scene_name(dir: &str) -> &str {
    dir.strip_prefix(SEC3)
        .or_else(|| dir.strip_prefix(SEC4))
        .unwrap_or(dir)
}

/// Speed against error: the reference run.
pub const SPEED_REFERENCE: &str = "reference";
/// Speed against error: prefix of the deterministic runs (`det-n1000-s8`, `det-t0.1-s8`).
pub const SPEED_DETERMINISTIC: &str = "det-";
/// Speed against error: prefix of the stochastic runs (`sm-n1000`, `sm-t0.1`).
pub const SPEED_STOCHASTIC: &str = "sm-";
/// Speed against error: a run compared with the reference, inside the run's directory.
pub const VS_REFERENCE: &str = "vs-reference";

/// Calibration: the escape table `rebound calibrate` writes.
pub const CALIBRATION_TABLE: &str = "table";
/// Calibration: `deterministic` on another surface, compared with the first.
pub const CALIBRATION_NOISE: &str = "noise";
/// Calibration: `calibrated` run again with another seed ([`CALIBRATION_RESEED`]) against
/// the same reference: how far the worst cells move with the model run's own Monte Carlo noise.
pub const CALIBRATION_RESEEDED: &str = "calibrated-reseeded";
/// Calibration: the seed of that second run.
pub const CALIBRATION_RESEED: &str = "8";
/// Calibration: the runs against an ensemble of surfaces (`[deterministic] surfaces`), in
/// this directory under each scene's, laid out like the single-surface ones.
pub const CALIBRATION_ENSEMBLE: &str = "ensemble";
/// Calibration: the ensemble's surface realisations (full mode; quick mode runs two). Two
/// ensembles of 16 differed by up to 0.074° in a condition's mean α⁺, more than the goal's
/// 0.05° bias; two of 64 by at most 0.05° (2.9 GB and ~45 s per deterministic run).
pub const CALIBRATION_SURFACES: &str = "64";

/// Mirror symmetry: the triangulations run (every one the case key accepts), one directory
/// each under [`MIRROR`].
pub const MIRROR_TRIANGULATIONS: [&str; 2] = roughwall::Triangulation::NAMES;
/// Mirror symmetry: the surfaces' seeds (full mode; quick mode runs the first two).
pub const MIRROR_SEEDS: [&str; 8] = ["1", "2", "3", "4", "5", "6", "7", "8"];
/// Mirror symmetry: prefix of one surface's run (`seed1`, …).
pub const MIRROR_SEED: &str = "seed";

/// Measured walls, part 6: walls outside the calibration set, `name:Δξ:Δζ` (degrees), each
/// run with the deviations typed into `[wall]`; under [`MEASURED_WALLS`]`/`[`NOMINAL`] each
/// has a directory named `name`.
pub const NOMINAL_WALLS: [&str; 4] = ["5-5:5.0:5.0", "4-1:4.0:1.0", "3-6:3.0:6.0", "6.5-2:6.5:2.0"];
/// Measured walls: the typed-deviation runs.
pub const NOMINAL: &str = "nominal";
/// Measured walls: the deterministic ensemble built with Eq. (15) (`wall_deviations =
/// "eq15"`) and the models compared with it.
pub const NOMINAL_EQ15: &str = "eq15";
/// Measured walls, part 7: the real scans of the study, each a shipped case
/// `configs/scans/<name>.toml`; under [`MEASURED_WALLS`]`/`[`STUDY`] a directory each.
pub const STUDY_SCANS: [&str; 2] = ["x3p-2", "matrix-3"];
/// Measured walls: the study's runs.
pub const STUDY: &str = "study";
/// Measured walls: `rebound scan` of a study scan (its wall card).
pub const STUDY_CARD: &str = "scan";
/// Measured walls: `deterministic` on the scan itself, in place (the reference).
pub const STUDY_ON_SCAN: &str = "on-scan";
/// Measured walls: `deterministic` on the scan turned to its lay and mirror-tiled (the earlier
/// reference), and its comparison with [`STUDY_ON_SCAN`]: what the tiling cost.
pub const STUDY_ON_SCAN_MIRRORED: &str = "on-scan-mirrored";
/// Measured walls: `deterministic` on Gaussian (Garcia–Stoll) walls of given deviations.
pub const STUDY_GAUSSIAN: &str = "gaussian";
/// Measured walls: the noise floor of a "miss" (issue 39, part 3): one Gaussian wall of the
/// reference's block with the card's deviations and correlation area (`gaussian_control` in
/// scripts/common.sh; [`STUDY_CONTROL_ONE`]) against an ensemble of
/// [`STUDY_CONTROL_SURFACES`] such walls ([`STUDY_CONTROL_ENSEMBLE`]), and their comparison.
pub const STUDY_CONTROL: &str = "control";
/// Measured walls: the control's one wall.
pub const STUDY_CONTROL_ONE: &str = "one";
/// Measured walls: the control's ensemble.
pub const STUDY_CONTROL_ENSEMBLE: &str = "ensemble";
/// Measured walls: the walls of the control's ensemble (full mode).
pub const STUDY_CONTROL_SURFACES: &str = "64";
/// Measured walls: the runs with the wall card's deviations.
pub const STUDY_WITH_CARD: &str = "card";
/// Measured walls: the runs with the deviations of the mirror-tiled wall (what the particles
/// met on [`STUDY_ON_SCAN_MIRRORED`]).
pub const STUDY_WITH_TILED: &str = "tiled";

/// The wall's own model (issue 39, parts 3, 4 and 8): `scripts/measured-wall-model.sh`.
pub const MEASURED_WALL_MODEL: &str = "measured-wall-model";
/// Its scans and particles, `scan:D:D…` (µm; 0 the point particle): each scan a shipped case
/// `configs/scans/<scan>.toml`, each particle a directory `d<D>` under the scan's.
pub const MODEL_SCANS: [&str; 7] = [
    "x3p-2:0:50",
    "opd-1:0:50:500",
    "matrix-3:0",
    "plu-1:0:50:100:500",
    "metropro-1:0:50:100:500",
    "sample-land:0:50:100",
    "cartridge-case:0:50:100",
];
/// The wall's own model: `rebound scan --measured-wall` of a scan (its card and tables).
pub const MODEL_CARD: &str = "card";
/// The wall's own model: `deterministic` on the scan in place (the reference).
pub const MODEL_REFERENCE: &str = "reference";
/// The wall's own model: the reference again with another seed.
pub const MODEL_REFERENCE_2: &str = "reference-2";
/// The wall's own model: [`MODEL_REFERENCE`] against [`MODEL_REFERENCE_2`], the noise floor.
pub const MODEL_FLOOR: &str = "floor";
/// The wall's own model: the stochastic models run against the reference, by directory.
pub const MODEL_MODELS: [&str; 3] = ["measured-wall", "radenkovic-simonin-2021", "calibrated"];
/// The wall's own model: `deterministic` on Gaussian walls with the particle's card deviations
/// (16 surfaces, a point particle), against the reference.
pub const MODEL_GAUSSIAN: &str = "gaussian";
/// The wall's own model: the noise floor of the Gaussian walls' verdict (issue 39, part 3):
/// one Gaussian wall of the size and pixel of the block the reference bounced on, with the
/// particle's card deviations and correlation area (`gaussian_control` in scripts/common.sh;
/// [`STUDY_CONTROL_ONE`]), against an ensemble of
/// [`STUDY_CONTROL_SURFACES`] such walls ([`STUDY_CONTROL_ENSEMBLE`]), and their comparison.
pub const MODEL_CONTROL: &str = "gaussian-control";

/// Finite size: the sphere diameters (µm), one run directory each.
pub const FINITE_SIZE_DIAMETERS_UM: [&str; 4] = ["50", "100", "250", "500"];
/// Finite size: prefix of the runs of one diameter (`d50`, …).
pub const FINITE_SIZE_DIAMETER: &str = "d";
/// Finite size: `stochastic` with the deviations the sphere sees.
pub const STOCHASTIC_EFFECTIVE: &str = "stochastic-effective";
/// Finite size: `stochastic` with the wall's nominal deviations.
pub const STOCHASTIC_NOMINAL: &str = "stochastic-nominal";
/// Finite size: [`DETERMINISTIC`] against [`STOCHASTIC_EFFECTIVE`].
pub const COMPARE_EFFECTIVE: &str = "compare-effective";
/// Finite size: [`DETERMINISTIC`] against [`STOCHASTIC_NOMINAL`].
pub const COMPARE_NOMINAL: &str = "compare-nominal";
/// Finite size: prefix of the grid-convergence runs (`grid-s4`, …).
pub const FINITE_SIZE_GRID: &str = "grid-s";
/// Finite size: the effective-roughness law (`rebound surface`).
pub const FINITE_SIZE_LAW: &str = "law";

/// The names as shell variables, in the order of `scripts/paths.sh`: (variable, value; a list
/// is one space-separated word list).
pub const SHELL: [(&str, &[&str]); 77] = [
    ("REPRODUCIBILITY", &[REPRODUCIBILITY]),
    ("RADENKOVIC2021", &[RADENKOVIC2021]),
    ("HU2021", &[HU2021]),
    ("WALL_MODELS", &[WALL_MODELS]),
    ("CALIBRATION", &[CALIBRATION]),
    ("EROSION", &[EROSION]),
    ("FINITE_SIZE", &[FINITE_SIZE]),
    ("SPIN", &[SPIN]),
    ("SPEED_VS_ERROR", &[SPEED_VS_ERROR]),
    ("DETERMINISTIC", &[DETERMINISTIC]),
    ("STOCHASTIC", &[STOCHASTIC]),
    ("COMPARE", &[COMPARE]),
    ("TABLE1", &[TABLE1]),
    ("FIG4", &[FIG4]),
    ("FIG4_RUN", &[FIG4_RUN]),
    ("SEC3", &[SEC3]),
    ("SEC4", &[SEC4]),
    ("SEC4_GLASS_STEEL", &[SEC4_GLASS_STEEL]),
    ("SEC4_FIGS_16_17", &[SEC4_FIGS_16_17]),
    ("HU_FIG4", &[HU_FIG4]),
    ("HU_FIG6", &[HU_FIG6]),
    ("HU_FIG9", &[HU_FIG9]),
    ("HU_FIG11B", &[HU_FIG11B]),
    ("HU2021_FIGS", &HU2021_FIGS),
    ("WALL_MODELS_SCENES", &WALL_MODELS_SCENES),
    ("SPEED_REFERENCE", &[SPEED_REFERENCE]),
    ("SPEED_DETERMINISTIC", &[SPEED_DETERMINISTIC]),
    ("SPEED_STOCHASTIC", &[SPEED_STOCHASTIC]),
    ("VS_REFERENCE", &[VS_REFERENCE]),
    ("CALIBRATION_TABLE", &[CALIBRATION_TABLE]),
    ("CALIBRATION_NOISE", &[CALIBRATION_NOISE]),
    ("CALIBRATION_RESEEDED", &[CALIBRATION_RESEEDED]),
    ("CALIBRATION_RESEED", &[CALIBRATION_RESEED]),
    ("CALIBRATION_ENSEMBLE", &[CALIBRATION_ENSEMBLE]),
    ("CALIBRATION_SURFACES", &[CALIBRATION_SURFACES]),
    ("CALIBRATION_SCENES", &CALIBRATION_SCENES),
    ("EROSION_WALLS", &EROSION_WALLS),
    ("EROSION_BETAS_DEG", &EROSION_BETAS_DEG),
    ("FINITE_SIZE_DIAMETERS_UM", &FINITE_SIZE_DIAMETERS_UM),
    ("FINITE_SIZE_DIAMETER", &[FINITE_SIZE_DIAMETER]),
    ("STOCHASTIC_EFFECTIVE", &[STOCHASTIC_EFFECTIVE]),
    ("STOCHASTIC_NOMINAL", &[STOCHASTIC_NOMINAL]),
    ("COMPARE_EFFECTIVE", &[COMPARE_EFFECTIVE]),
    ("COMPARE_NOMINAL", &[COMPARE_NOMINAL]),
    ("FINITE_SIZE_GRID", &[FINITE_SIZE_GRID]),
    ("FINITE_SIZE_LAW", &[FINITE_SIZE_LAW]),
    ("MIRROR", &[MIRROR]),
    ("MIRROR_TRIANGULATIONS", &MIRROR_TRIANGULATIONS),
    ("MIRROR_SEEDS", &MIRROR_SEEDS),
    ("MIRROR_SEED", &[MIRROR_SEED]),
    ("MEASURED_WALLS", &[MEASURED_WALLS]),
    ("PIPE_FLOW", &[PIPE_FLOW]),
    ("PIPE_FLOW_QUICK", &[PIPE_FLOW_QUICK]),
    ("NOMINAL_WALLS", &NOMINAL_WALLS),
    ("NOMINAL", &[NOMINAL]),
    ("NOMINAL_EQ15", &[NOMINAL_EQ15]),
    ("STUDY_SCANS", &STUDY_SCANS),
    ("STUDY", &[STUDY]),
    ("STUDY_CARD", &[STUDY_CARD]),
    ("STUDY_ON_SCAN", &[STUDY_ON_SCAN]),
    ("STUDY_ON_SCAN_MIRRORED", &[STUDY_ON_SCAN_MIRRORED]),
    ("STUDY_GAUSSIAN", &[STUDY_GAUSSIAN]),
    ("STUDY_CONTROL", &[STUDY_CONTROL]),
    ("STUDY_CONTROL_ONE", &[STUDY_CONTROL_ONE]),
    ("STUDY_CONTROL_ENSEMBLE", &[STUDY_CONTROL_ENSEMBLE]),
    ("STUDY_CONTROL_SURFACES", &[STUDY_CONTROL_SURFACES]),
    ("STUDY_WITH_CARD", &[STUDY_WITH_CARD]),
    ("STUDY_WITH_TILED", &[STUDY_WITH_TILED]),
    ("MEASURED_WALL_MODEL", &[MEASURED_WALL_MODEL]),
    ("MODEL_SCANS", &MODEL_SCANS),
    ("MODEL_CARD", &[MODEL_CARD]),
    ("MODEL_REFERENCE", &[MODEL_REFERENCE]),
    ("MODEL_REFERENCE_2", &[MODEL_REFERENCE_2]),
    ("MODEL_FLOOR", &[MODEL_FLOOR]),
    ("MODEL_MODELS", &MODEL_MODELS),
    ("MODEL_GAUSSIAN", &[MODEL_GAUSSIAN]),
    ("MODEL_CONTROL", &[MODEL_CONTROL]),
];

/// The text of `scripts/paths.sh`: one `P_<NAME>=<value>` line per entry of [`SHELL`].
pub fn shell_script() -> String {
    let mut s = String::from(
        "# The layout of results/: the directory names the reproduction scripts write and\n\
         # `rebound report` reads. Generated from crates/reproduce/src/paths.rs (its test paths_sh checks\n\
         # it; `ROUGHWALL_BLESS=1 cargo test -p reproduce paths_sh` rewrites it): do not edit.\n\
         # Sourced by scripts/common.sh.\n",
    );
    for (name, value) in SHELL {
        s.push_str(&format!("P_{name}=\"{}\"\n", value.join(" ")));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    #[test]
    fn wall_model_scenes_are_sec3_or_sec4_scenes() {
        for dir in WALL_MODELS_SCENES {
            assert!(dir.starts_with(SEC3) || dir.starts_with(SEC4), "{dir}");
            assert!(
                !scene_name(dir).is_empty() && scene_name(dir) != dir,
                "{dir}"
            );
        }
        assert_eq!(scene_name("sec4-glass-steel-2d"), "glass-steel-2d");
    }

    #[test]
    fn shell_names_are_unique_and_values_are_plain_words_or_paths() {
        let mut names: Vec<&str> = SHELL.iter().map(|(n, _)| *n).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), SHELL.len());
        for (name, value) in SHELL {
            assert!(name
                .chars()
                .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_'));
            for v in value {
                assert!(
                    !v.is_empty()
                        && v.chars()
                            .all(|c| c.is_ascii_alphanumeric() || "-_./:".contains(c))
                        && !v.starts_with('/')
                        && !v.contains(".."),
                    "{name}: {v:?}"
                );
            }
        }
    }

    /// `scripts/paths.sh` (the names of the results directories, for the scripts) is what
    /// this module generates, so the scripts and `rebound report` cannot drift.
    /// After changing `crates/reproduce/src/paths.rs`, regenerate it with
    /// `ROUGHWALL_BLESS=1 cargo test -p reproduce paths_sh`.
    #[test]
    fn paths_sh_is_generated_from_the_rust_constants() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scripts/paths.sh");
        let generated = shell_script();
        if std::env::var_os("ROUGHWALL_BLESS").is_some() {
            std::fs::write(&path, &generated).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == generated,
            "scripts/paths.sh differs from crates/reproduce/src/paths.rs; regenerate: ROUGHWALL_BLESS=1 cargo test -p reproduce paths_sh"
        );
        // Every script that writes under results/ takes its directory names from it.
        let common = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scripts/common.sh"),
        )
        .unwrap();
        assert!(common.contains("source \"$ROOT/scripts/paths.sh\""));
        // A variable the scripts use is one paths.sh defines (a misspelt `$P_…` would be empty).
        let defined: std::collections::BTreeSet<String> = generated
            .lines()
            .filter_map(|l| l.split_once('=').map(|(n, _)| n.to_string()))
            .collect();
        for e in
            std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scripts")).unwrap()
        {
            let p = e.unwrap().path();
            if p.extension().is_none_or(|x| x != "sh") {
                continue;
            }
            let text = std::fs::read_to_string(&p).unwrap();
            for (i, _) in text.match_indices("$P_").chain(text.match_indices("${P_")) {
                let start = i + if text[i..].starts_with("${") { 2 } else { 1 };
                let name: String = text[start..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                assert!(
                    defined.contains(&name),
                    "{}: ${name} is not in scripts/paths.sh",
                    p.display()
                );
            }
        }
    }
}
