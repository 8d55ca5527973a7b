//! The tables of `rebound force-sweep` (Hu et al. 2021; docs/physics.md §7):
//! `force_sweep.csv`, `accuracy.csv`, `dynamic_convergence.csv` and the `[force]` and
//! `[[dynamic_convergence]]` tables of `run.toml`.

use crate::output::{fmt_num, fmt_opt, CsvTable};
use roughwall::force::{self, Accuracy, Convergence};
use roughwall::force::{hertz_dynamic, Impact, Particle};
use roughwall::force::{Row, Sweep};

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

/// Least wall time over which each step count of `dynamic_convergence` is timed (repeats of one
/// impact): 2 ms is 8–340 repeats of impacts of 5.9–267 µs (8–1024 steps, Fig. 9's glass
/// spheroid, 2026-11-30), enough for the per-run figure in `run.toml`; at 20 ms a sweep with
/// `hertz-dynamic` spent up to 0.54 s timing itself (9 step counts × 3 λ).
const TIMING_S: f64 = 0.002;

/// Representative impacts of the speed-versus-error table: for (up to) the first three λ of
/// the sweep, the sweep's β closest to 45°, its first positive U_N and first D.
pub fn convergence_runs(
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
            let c = force::convergence(
                &p,
                &imp,
                &force::CONVERGENCE_STEPS,
                force::REFERENCE_STEPS,
                TIMING_S,
            );
            (imp, p, c)
        })
        .collect()
}

/// `dynamic_convergence.csv` (deterministic) and the `[[dynamic_convergence]]` tables of
/// `run.toml` (with the wall times).
pub fn convergence_outputs(
    conv: &[(Impact, Particle, Vec<Convergence>)],
) -> (CsvTable, toml::Value) {
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
                force::REFERENCE_STEPS.to_string(),
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

/// The `[force]` table of `run.toml`: the material, the row count and the conventions.
pub fn manifest_table(material: &Particle, rows: usize) -> toml::Value {
    let mut info = toml::Table::new();
    info.insert("density_kg_m3".into(), material.density.into());
    info.insert("youngs_pa".into(), material.youngs.into());
    info.insert("poisson".into(), material.poisson.into());
    info.insert("rows".into(), toml::Value::Integer(rows as i64));
    info.insert(
        "dynamic_steps_per_contact".into(),
        toml::Value::Integer(hertz_dynamic::Options::default().steps_per_contact as i64),
    );
    info.insert(
        "diameter".into(),
        "volume-equivalent (Hu et al. 2021, Table 1): a = (D/2) λ^(-1/3), b = λ a".into(),
    );
    toml::Value::Table(info)
}
