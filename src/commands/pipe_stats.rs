//! `rebound pipe-stats --study DIR --out DIR`: the statistics of a pipe-flow study
//! (`crate::pipe_flow` reads and computes; this writes the tables, figures and `run.toml`).

use crate::cli::PipeStatsArgs;
use crate::commands::{begin_out, counted, Summary};
use crate::output::{out_dir, write_atomic};
use crate::pipe_flow::{read, sums, tables};
use roughwall::erosion::{AngleDependency, Dnv, ErosionModel, Finnie, OkaInput};
use roughwall::{Error, Result};

/// Finnie's law for the erosion tallies: a steel wall (flow stress 1 GPa) with OpenFOAM's
/// ψ = K = 2, as in `configs/cases/erosion-glass-steel.toml`.
pub const FINNIE: Finnie = Finnie {
    flow_stress_pa: 1e9,
    psi: 2.0,
    k: 2.0,
};

/// DNV RP-O501's carbon steel (K = 2·10⁻⁹ (m/s)^−2.6, n = 2.6, 7800 kg/m³, ductile), as
/// pysand's `material_dict['carbon_steel']` and `[erosion] model = "dnv"`'s defaults.
pub const DNV: Dnv = Dnv {
    k: 2e-9,
    n: 2.6,
    target_density_kg_m3: 7800.0,
    angle_dependency: AngleDependency::Ductile,
};

/// Oka's Vickers hardness of the wall (GPa). An assumed value, not a measured one: 1.8 GPa
/// (about 180 HV) stands for an annealed austenitic stainless steel pipe; the study names no
/// steel grade. Oka's angle function sharpens with hardness (Oka, Okamura & Yoshida 2005,
/// Eq. 2: n1 = 0.71 Hv^0.14, n2 = 2.4 Hv^−0.94), so a harder wall moves its ratios.
pub const OKA_HARDNESS_GPA: f64 = 1.8;

/// The erosion laws of the tallies, in the order of `pipe_flow::sums::LAWS`: Finnie, Oka
/// (Oka & Yoshida 2005, SiO₂ constants for the glass beads, [`OKA_HARDNESS_GPA`]), DNV.
pub fn erosion_laws() -> [ErosionModel; 3] {
    let oka = OkaInput {
        hardness_gpa: OKA_HARDNESS_GPA,
        ..Default::default()
    }
    .resolve();
    [
        ErosionModel::Finnie(FINNIE),
        ErosionModel::Oka(oka),
        ErosionModel::Dnv(DNV),
    ]
}

/// Runs the subcommand.
pub fn run(args: &PipeStatsArgs) -> Result<Summary> {
    out_dir::check_out(&args.out, "--out")?;
    out_dir::check_distinct(&args.out, "--out", &[("--study", args.study.as_path())])?;
    let runs = read::study(&args.study)?;
    let laws = erosion_laws();
    let analysed: Vec<tables::Analysed> = runs
        .iter()
        .map(|run| tables::Analysed {
            run,
            sums: sums::sums(run, &laws),
        })
        .collect();
    let hits: usize = runs.iter().map(|r| r.hits.len()).sum();
    let particles: usize = runs.iter().map(|r| r.particles.len()).sum();
    let staged = begin_out(&args.out)?;
    let dir = staged.path();
    tables::summary(&analysed).write(&dir.join("summary.csv"))?;
    tables::profiles(&analysed).write(&dir.join("profiles.csv"))?;
    tables::distributions(&analysed).write(&dir.join("distributions.csv"))?;
    tables::comparisons(&analysed).write(&dir.join("comparisons.csv"))?;
    tables::sensitivity(&analysed).write(&dir.join("sensitivity.csv"))?;
    if analysed.iter().any(|a| a.run.cost.is_some()) {
        tables::costs(&analysed).write(&dir.join("costs.csv"))?;
    }
    let figures = crate::figures::pipe_flow::write(dir, &analysed)?;
    let mut run = toml::Table::new();
    run.insert("command".into(), "pipe-stats".into());
    run.insert("version".into(), crate::BUILD_VERSION.into());
    run.insert("study".into(), args.study.display().to_string().into());
    run.insert("runs".into(), toml::Value::Integer(runs.len() as i64));
    run.insert("hits".into(), toml::Value::Integer(hits as i64));
    run.insert(
        "finnie".into(),
        format!(
            "flow stress {} Pa, psi {}, K {}",
            FINNIE.flow_stress_pa, FINNIE.psi, FINNIE.k
        )
        .into(),
    );
    run.insert(
        "oka".into(),
        format!("hardness {OKA_HARDNESS_GPA} GPa, SiO2 particle constants (Oka & Yoshida 2005)")
            .into(),
    );
    run.insert(
        "dnv".into(),
        format!(
            "K {} (m/s)^-n, n {}, target density {} kg/m3, ductile",
            DNV.k, DNV.n, DNV.target_density_kg_m3
        )
        .into(),
    );
    let mut root = toml::Table::new();
    root.insert("run".into(), toml::Value::Table(run));
    // The study's own records (mesh, fluid convergence), as the script wrote them.
    for (key, file) in [
        ("mesh_coarse", "mesh-coarse.txt"),
        ("mesh_fine", "mesh-fine.txt"),
        ("mesh_nearwall", "mesh-nearwall.txt"),
        ("fluid", "fluid.txt"),
    ] {
        if let Ok(text) = std::fs::read_to_string(args.study.join(file)) {
            root.insert(key.into(), text.trim().to_string().into());
        }
    }
    root.insert(
        "figures".into(),
        toml::Value::Array(figures.into_iter().map(toml::Value::String).collect()),
    );
    let text =
        toml::to_string_pretty(&root).map_err(|e| Error::Internal(format!("run.toml: {e}")))?;
    write_atomic(&dir.join("run.toml"), text.as_bytes())?;
    staged.commit()?;
    Ok(Summary {
        work: format!(
            "{}, {} particles, {} wall hits",
            counted(runs.len(), "run"),
            particles,
            hits
        ),
        rate: None,
        wrote: args.out.clone(),
    })
}
