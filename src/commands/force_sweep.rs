//! `rebound force-sweep`: peak elastic force of spheres and prolate spheroids over a sweep of
//! models × D × λ × β × U_N (Hu et al. 2021; docs/physics.md §7).
//!
//! Outputs in `--out`:
//! - `force_sweep.csv` — one row per point, columns `crate::writers::force_sweep::HEADER`;
//! - `accuracy.csv` — whenever `hu2021` and another model are both in the sweep: mean and max
//!   relative deviation of every other model from `hu2021` over the sweep's β values, per (D, λ, U_N);
//! - `dynamic_convergence.csv` — whenever `hertz-dynamic` is in the sweep: relative error of the
//!   peak force and contact time against a fine reference for several steps per contact
//!   (deterministic); the matching wall times per impact go to `run.toml`
//!   (`[[dynamic_convergence]]`), so that every CSV is byte-identical between runs;
//! - SVG figures: `fmax_vs_beta.svg` (Fig. 6), `xi_vs_beta.svg` (Fig. 9) when β varies,
//!   `fmax_vs_un.svg` (Figs. 8, 10–12; one panel per (λ, β), at most 12) when U_N varies, and always `sphere_check.svg` (Fig. 4);
//! - `run.toml`.
//!
//! `--out` is written as a whole (staging directory, lock, swap: `crate::output::out_dir`).
use crate::case::{builtin, force::resolve};
use crate::cli::ForceSweepArgs;
use crate::commands::{begin_out, context, grouped, Summary};
use crate::figures;
use crate::writers::force_sweep::{
    accuracy_table, convergence_outputs, convergence_runs, manifest_table, rows_table,
};
use roughwall::force;
use roughwall::force::Model;
use roughwall::Result;

/// Runs the subcommand.
pub fn run(args: &ForceSweepArgs) -> Result<Summary> {
    let mut ctx = context(&args.common, "force-sweep", builtin::FORCE_SWEEP)?;
    let (material, sweep) = resolve(&ctx.case)?;
    let out = begin_out(&ctx.out_dir)?;
    let rows = sweep.rows(&material)?;
    let dir = out.path().to_path_buf();
    rows_table(&rows).write(&dir.join("force_sweep.csv"))?;

    let acc = force::accuracy(&rows);
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

    ctx.manifest
        .set("force", manifest_table(&material, rows.len()));
    ctx.manifest.write(&dir)?;
    let dir = out.commit()?;
    Ok(Summary {
        work: format!("{} sweep points", grouped(rows.len() as u64)),
        rate: Some((rows.len() as u64, "points")),
        wrote: dir,
    })
}
