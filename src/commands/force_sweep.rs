//! `rebound force-sweep`: peak elastic force of spheres and prolate spheroids over a sweep of
//! models × D × λ × β × U_N (Hu et al. 2021; physics notes §7).
//!
//! Outputs in `--out`:
//! - `force_sweep.csv` — one row per point, columns [`HEADER`];
//! - `accuracy.csv` — whenever `hu2021` and another model are both in the sweep: mean and max
//!   relative deviation of every other model from `hu2021` over the sweep's β values, per (D, λ, U_N);
//! - `dynamic_convergence.csv` — whenever `hertz-dynamic` is in the sweep: relative error of the
//!   peak force and contact time against a fine reference for several steps per contact
//!   (deterministic); the matching wall times per impact go to `run.toml`
//!   (`[[dynamic_convergence]]`), so that every CSV is byte-identical between runs;
//! - SVG figures ([`crate::figures::force_sweep`]): `fmax_vs_beta.svg` (Fig. 6), `xi_vs_beta.svg` (Fig. 9) when β varies,
//!   `fmax_vs_un.svg` (Figs. 8, 10–12; one panel per (λ, β), at most 12) when U_N varies, and always `sphere_check.svg` (Fig. 4);
//! - `run.toml`.
//!
//! `--out` is written as a whole (staging directory, lock, swap: [`crate::output::out_dir`]).
use crate::case::{Case, ParticleSection, SweepSection};
use crate::cli::ForceSweepArgs;
use crate::commands::Context;
use crate::error::{Error, Result};
use crate::figures;
use crate::force::report::{self, Accuracy, Convergence};
use crate::force::sweep::{Row, Sweep};
use crate::force::{hertz_dynamic, material, Impact, Model, Particle};
use crate::output::{fmt_num, fmt_opt, CsvTable, OutputDir};

/// The columns of `force_sweep.csv` (issue 5).
pub const HEADER: [&str; 11] = [
    "model",
    "lambda",
    "beta_deg",
    "u_n_m_s",
    "diameter_um",
    "density_kg_m3",
    "youngs_pa",
    "poisson",
    "f_max_n",
    "xi",
    "contact_time_s",
];

/// The columns of `accuracy.csv`.
pub const ACCURACY_HEADER: [&str; 10] = [
    "model",
    "lambda",
    "diameter_um",
    "u_n_m_s",
    "points",
    "beta_min_deg",
    "beta_max_deg",
    "mean_rel_dev",
    "max_rel_dev",
    "beta_at_max_deg",
];

/// The columns of `dynamic_convergence.csv`.
pub const CONVERGENCE_HEADER: [&str; 9] = [
    "lambda",
    "beta_deg",
    "u_n_m_s",
    "diameter_um",
    "steps_per_contact",
    "steps",
    "reference_steps_per_contact",
    "rel_err_f_max",
    "rel_err_contact_time",
];

/// Without `--case`: Hu et al. 2021, Fig. 6.
pub const DEFAULT_CASE: &str = include_str!("../../configs/cases/hu-fig6.toml");

/// Fig. 6 values used for any `[particle]` property a case leaves out (no preset).
const FIG6: Particle = Particle {
    density: 2500.0,
    youngs: 64e9,
    poisson: 0.24,
    diameter: 2.45e-6,
};

/// Runs the subcommand.
pub fn run(args: &ForceSweepArgs) -> Result<()> {
    let mut ctx = Context::new(&args.common, "force-sweep", DEFAULT_CASE)?;
    let (material, sweep) = resolve(&ctx.case)?;
    let out = OutputDir::begin(&ctx.out_dir, "--out")?;
    let rows = sweep.rows(&material)?;
    let dir = out.path().to_path_buf();
    rows_table(&rows).write(&dir.join("force_sweep.csv"))?;

    let acc = report::accuracy(&rows);
    if !acc.is_empty() {
        accuracy_table(&acc).write(&dir.join("accuracy.csv"))?;
    }
    if sweep.models.contains(&Model::HertzDynamic) {
        let conv = convergence_runs(&material, &sweep);
        if !conv.is_empty() {
            let (table, timing) = convergence_outputs(&conv);
            table.write(&dir.join("dynamic_convergence.csv"))?;
            ctx.manifest.set("dynamic_convergence", timing);
        }
    }
    figures::force_sweep::write(&dir, &ctx.case.name, &rows, &sweep, &material)?;

    let mut info = toml::Table::new();
    info.insert("density_kg_m3".into(), material.density.into());
    info.insert("youngs_pa".into(), material.youngs.into());
    info.insert("poisson".into(), material.poisson.into());
    info.insert("rows".into(), toml::Value::Integer(rows.len() as i64));
    info.insert(
        "dynamic_steps_per_contact".into(),
        toml::Value::Integer(hertz_dynamic::Options::default().steps_per_contact as i64),
    );
    info.insert(
        "diameter".into(),
        "volume-equivalent (Hu et al. 2021, Table 1): a = (D/2) λ^(-1/3), b = λ a".into(),
    );
    ctx.manifest.set("force", toml::Value::Table(info));
    ctx.manifest.write(&dir)?;
    let dir = out.commit()?;
    eprintln!(
        "force-sweep: {} rows → {}",
        rows.len(),
        dir.join("force_sweep.csv").display()
    );
    Ok(())
}

/// The particle material (ρ, E, σ; diameter as the default D) and the sweep of a case.
///
/// `[particle]`: `preset` (Hu et al. 2021, Table 1) with any property overriding it; without a
/// preset, missing properties take Fig. 6's values (ρ = 2500 kg/m³, E = 64 GPa, σ = 0.24,
/// D = 2.45 µm). `[sweep]`: missing keys take Fig. 6's sweep; `diameter_um` may be swept here
/// or given once in `[particle]`, not both.
pub fn resolve(case: &Case) -> Result<(Particle, Sweep)> {
    let ps: ParticleSection = case.particle.clone().unwrap_or_default();
    let mut p = match &ps.preset {
        Some(name) => {
            let m = material::preset(name)?;
            Particle {
                density: m.density,
                youngs: m.youngs,
                poisson: m.poisson,
                diameter: m.diameter_um * 1e-6,
            }
        }
        None => FIG6,
    };
    if let Some(v) = ps.density_kg_m3 {
        p.density = v;
    }
    if let Some(v) = ps.youngs_pa {
        p.youngs = v;
    }
    if let Some(v) = ps.poisson {
        p.poisson = v;
    }
    if let Some(v) = ps.diameter_um {
        p.diameter = v * 1e-6;
    }
    p.validate()?;

    let ss: SweepSection = case.sweep.clone().unwrap_or_default();
    let fig6 = Sweep::fig6();
    let models = match &ss.models {
        Some(names) => names
            .iter()
            .map(|n| Model::from_name(n))
            .collect::<Result<Vec<_>>>()?,
        None => fig6.models.clone(),
    };
    let lambdas = match &ss.lambda {
        Some(v) => v.expand("sweep.lambda")?,
        None => fig6.lambdas.clone(),
    };
    let betas_deg = match &ss.beta_deg {
        Some(v) => v.expand("sweep.beta_deg")?,
        None => fig6.betas_deg.clone(),
    };
    let u_ns = match &ss.u_n_m_s {
        Some(v) => v.expand("sweep.u_n_m_s")?,
        None => fig6.u_ns.clone(),
    };
    let diameters = match &ss.diameter_um {
        Some(_) if ps.diameter_um.is_some() => {
            return Err(Error::Input(
                "give `diameter_um` in [particle] or in [sweep], not both".into(),
            ))
        }
        Some(v) => v
            .expand("sweep.diameter_um")?
            .into_iter()
            .map(|d| d * 1e-6)
            .collect(),
        None => vec![p.diameter],
    };
    let sweep = Sweep {
        models,
        lambdas,
        betas_deg,
        u_ns,
        diameters,
    };
    sweep.validate()?;
    for &d in &sweep.diameters {
        Particle { diameter: d, ..p }.validate()?;
    }
    Ok((p, sweep))
}

/// `force_sweep.csv`.
pub fn rows_table(rows: &[Row]) -> CsvTable {
    let mut t = CsvTable::new(&HEADER);
    for r in rows {
        t.push(vec![
            r.model.name().to_string(),
            fmt_num(r.lambda),
            fmt_num(r.beta_deg),
            fmt_num(r.u_n),
            fmt_num(r.particle.diameter * 1e6),
            fmt_num(r.particle.density),
            fmt_num(r.particle.youngs),
            fmt_num(r.particle.poisson),
            fmt_num(r.result.f_max),
            fmt_num(r.result.xi),
            fmt_opt(r.result.contact_time),
        ]);
    }
    t
}

/// `accuracy.csv`.
pub fn accuracy_table(acc: &[Accuracy]) -> CsvTable {
    let mut t = CsvTable::new(&ACCURACY_HEADER);
    for a in acc {
        t.push(vec![
            a.model.name().to_string(),
            fmt_num(a.lambda),
            fmt_num(a.diameter * 1e6),
            fmt_num(a.u_n),
            a.points.to_string(),
            fmt_num(a.beta_range_deg.0),
            fmt_num(a.beta_range_deg.1),
            fmt_num(a.mean_rel_dev),
            fmt_num(a.max_rel_dev),
            fmt_num(a.beta_at_max_deg),
        ]);
    }
    t
}

/// Representative impacts of the speed-versus-error table: for (up to) the first three λ of
/// the sweep, the sweep's β closest to 45°, its first positive U_N and first D.
fn convergence_runs(
    material: &Particle,
    sweep: &Sweep,
) -> Vec<(Impact, Particle, Vec<Convergence>)> {
    let Some(&u_n) = sweep.u_ns.iter().find(|&&u| u > 0.0) else {
        return Vec::new();
    };
    let beta = sweep
        .betas_deg
        .iter()
        .copied()
        .min_by(|a, b| (a - 45.0).abs().total_cmp(&(b - 45.0).abs()))
        .unwrap_or(45.0);
    let p = Particle {
        diameter: sweep.diameters[0],
        ..*material
    };
    let mut seen: Vec<f64> = Vec::new();
    for &l in &sweep.lambdas {
        if !seen.contains(&l) && seen.len() < 3 {
            seen.push(l);
        }
    }
    seen.into_iter()
        .filter_map(|lambda| Impact::from_deg(lambda, beta, u_n).ok())
        .map(|imp| {
            let c = report::convergence(
                &p,
                &imp,
                &report::CONVERGENCE_STEPS,
                report::REFERENCE_STEPS,
                0.02,
            );
            (imp, p, c)
        })
        .collect()
}

/// `dynamic_convergence.csv` (deterministic) and the `[[dynamic_convergence]]` tables of
/// `run.toml` (with the wall times).
fn convergence_outputs(conv: &[(Impact, Particle, Vec<Convergence>)]) -> (CsvTable, toml::Value) {
    let mut t = CsvTable::new(&CONVERGENCE_HEADER);
    let mut timing = Vec::new();
    for (imp, p, rows) in conv {
        for c in rows {
            t.push(vec![
                fmt_num(imp.lambda),
                fmt_num(imp.beta.to_degrees()),
                fmt_num(imp.u_n),
                fmt_num(p.diameter * 1e6),
                c.steps_per_contact.to_string(),
                c.steps.to_string(),
                report::REFERENCE_STEPS.to_string(),
                fmt_num(c.rel_err_f_max),
                fmt_num(c.rel_err_contact_time),
            ]);
            let mut e = toml::Table::new();
            e.insert("lambda".into(), imp.lambda.into());
            e.insert("beta_deg".into(), imp.beta.to_degrees().into());
            e.insert("u_n_m_s".into(), imp.u_n.into());
            e.insert("diameter_um".into(), (p.diameter * 1e6).into());
            e.insert(
                "steps_per_contact".into(),
                (c.steps_per_contact as i64).into(),
            );
            e.insert("rel_err_f_max".into(), c.rel_err_f_max.into());
            e.insert("time_per_impact_s".into(), c.time_per_impact_s.into());
            timing.push(toml::Value::Table(e));
        }
    }
    (t, toml::Value::Array(timing))
}
