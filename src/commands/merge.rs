//! `rebound merge --out DIR SHARD_DIR...`: the partial tallies of `--shard K/N` runs
//! become the outputs of one run, byte for byte (see `crate::runner::merge`).

use crate::case::{deterministic, stochastic};
use crate::cli::MergeArgs;
use crate::commands::{begin_out, warn, Summary};
use crate::output::out_dir::{check_distinct, check_out};
use crate::partial::RunIdentity;
use crate::run_context::Context;
use crate::runner::{self, overrides_of};
use crate::writers;
use roughwall::{Error, Result};
use std::path::PathBuf;

/// The context of the run the shards came from.
fn context(id: &RunIdentity, out: Option<PathBuf>) -> Result<Context> {
    let (seed, _) = overrides_of(id)?;
    Context::from_text(
        id.case_text.clone(),
        id.case_origin.clone(),
        Some(seed),
        out,
        &id.command,
    )
}

/// Runs the subcommand.
pub fn run(args: &MergeArgs) -> Result<Summary> {
    let inputs: Vec<(&str, &std::path::Path)> = args
        .inputs
        .iter()
        .map(|p| ("SHARD_DIR", p.as_path()))
        .collect();
    if let Some(out) = &args.out {
        // Output paths first (the default `--out` needs the shards' case).
        check_out(out, "--out")?;
        check_distinct(out, "--out", &inputs)?;
    }
    let merged = runner::merge(&args.inputs, |id| {
        let ctx = context(id, args.out.clone())?;
        let (_, o) = overrides_of(id)?;
        match id.command.as_str() {
            "stochastic" => {
                let p = stochastic::prepare(&ctx.case, &o, ctx.seed)?;
                warn(p.warnings);
                Ok((p.specs, p.scene.count as u64))
            }
            "deterministic" => {
                let surface = id.surface_file.as_deref().map(std::path::Path::new);
                let p = deterministic::prepare(&ctx.case, &o, surface)?;
                warn(p.warnings);
                Ok((p.specs, p.scene.count as u64))
            }
            other => Err(Error::Input(format!(
                "partial tally of an unknown command `{other}`"
            ))),
        }
    })?;
    let id = &merged.identity;
    let ctx = context(id, args.out.clone())?;
    let (_, o) = overrides_of(id)?;
    // The merged outputs replace `--out` as a whole: it must not be one of the shards read.
    check_distinct(&ctx.out_dir, "--out", &inputs)?;
    let out = begin_out(&ctx.out_dir)?;
    let mut manifest = ctx.manifest;
    manifest.set_run("merged_shards", toml::Value::Integer(merged.shards as i64));
    manifest.set_run(
        "shard_seconds",
        toml::Value::Array(
            merged
                .seconds
                .iter()
                .map(|&s| toml::Value::Float(s))
                .collect(),
        ),
    );
    let seconds: f64 = merged.seconds.iter().sum();
    let unit = if id.command == "stochastic" {
        "rebounds"
    } else {
        "histories"
    };
    let mut summary = Summary::monte_carlo(None, &merged.tallies, unit, &ctx.out_dir);
    // Merging takes no Monte Carlo time: the shards' rate is their own.
    summary.rate = None;
    summary.work = format!(
        "{} shards of {}: {}",
        merged.shards, id.command, summary.work
    );
    match id.command.as_str() {
        "stochastic" => {
            let mut p = stochastic::prepare(&ctx.case, &o, ctx.seed)?;
            warn(std::mem::take(&mut p.warnings));
            p.notes = merged.manifest;
            let tallies = &merged.tallies;
            let fin = writers::stochastic::finish(out.path(), manifest, &p, tallies, None, seconds);
            warn(fin?);
        }
        _ => {
            let surface = id.surface_file.as_deref().map(std::path::Path::new);
            let mut p = deterministic::prepare(&ctx.case, &o, surface)?;
            warn(std::mem::take(&mut p.warnings));
            p.notes = merged.manifest;
            let tallies = &merged.tallies;
            let fin =
                writers::deterministic::finish(out.path(), manifest, &p, tallies, None, seconds);
            warn(fin?);
        }
    }
    let dir = out.commit()?;
    summary.wrote = dir;
    Ok(summary)
}
