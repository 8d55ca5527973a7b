//! Running a case's incident conditions through a model, and ending the run either with
//! the final outputs or, for one shard of many, with a partial tally that `merge` turns
//! into exactly the outputs one process would have written.
//!
//! Shared by `deterministic`, `stochastic` and `merge`; the models only say how to fill a
//! block of particles (`deterministic::fill_block`, `models::simulate::fill_block`).

use crate::partial::{Partial, PartialFile, RunIdentity, PARTIAL_FILE};
use crate::progress::Progress;
use roughwall::tally::{self, ConditionStats};
use roughwall::tally::{BlockTally, ConditionTally, Plan, Shard, TallySpec};
use roughwall::{Error, Result};
use sha2::Digest;
use std::path::{Path, PathBuf};

/// What the command line adds to a case for a tally run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TallyOverrides {
    /// `--particles N`.
    pub particles: Option<u64>,
    /// `--target-se DEG`.
    pub target_se: Option<f64>,
    /// `--shard K/N`.
    pub shard: Option<Shard>,
}

/// The identity of a run (what every shard must agree on).
pub fn identity(
    command: &str,
    case_text: &str,
    case_origin: &str,
    seed: u64,
    overrides: &TallyOverrides,
    surface_file: Option<&Path>,
) -> Result<RunIdentity> {
    let (surface_file, surface_sha256) = match surface_file {
        Some(p) => {
            let bad =
                |e: std::io::Error| Error::Input(format!("--surface file `{}`: {e}", p.display()));
            // Streamed: a height file may be larger than the memory the run may use.
            let mut file = std::fs::File::open(p).map_err(bad)?;
            let mut hasher = sha2::Sha256::new();
            std::io::copy(&mut file, &mut hasher).map_err(bad)?;
            let digest: String = hasher
                .finalize()
                .iter()
                .map(|b| format!("{b:02x}"))
                .collect();
            (Some(p.display().to_string()), Some(digest))
        }
        None => (None, None),
    };
    Ok(RunIdentity {
        command: command.into(),
        case_text: case_text.into(),
        case_origin: case_origin.into(),
        seed: seed.to_string(),
        particles: overrides.particles.map(|n| n.to_string()),
        target_se: overrides.target_se.map(|t| t.to_string()),
        surface_file,
        surface_sha256,
    })
}

/// The seed and overrides a run identity records.
pub fn overrides_of(id: &RunIdentity) -> Result<(u64, TallyOverrides)> {
    let bad = |what: &str| Error::Input(format!("partial tally: malformed {what}"));
    let seed = id.seed.parse().map_err(|_| bad("seed"))?;
    let particles = id
        .particles
        .as_deref()
        .map(|s| s.parse().map_err(|_| bad("particle count")))
        .transpose()?;
    let target_se = id
        .target_se
        .as_deref()
        .map(|s| s.parse().map_err(|_| bad("target")))
        .transpose()?;
    Ok((
        seed,
        TallyOverrides {
            particles,
            target_se,
            shard: None,
        },
    ))
}

/// The plan of a run: `count` particles per condition, an optional target standard error
/// and an optional shard. A target and a shard exclude each other: where a condition
/// stops depends on the tally of all its earlier blocks, which no single shard has.
pub fn plan(
    specs: Vec<TallySpec>,
    count: u64,
    target_se_deg: Option<f64>,
    shard: Option<Shard>,
) -> Result<Plan> {
    if let (Some(t), Some(s)) = (target_se_deg, shard) {
        return Err(Error::Input(format!(
            "`--shard {s}` cannot be used with a target standard error ({t}°): where a condition stops depends on all its earlier blocks; give a fixed count (`[particles] count` or --particles) to run shards"
        )));
    }
    Ok(Plan {
        specs,
        count,
        target_se_deg,
        shard,
    })
}

/// Runs the plan with a progress bar labelled `label`; `fill(k, start, end, block)`
/// tallies particles `start..end` of condition `k`.
pub fn execute<F>(plan: &Plan, label: &str, fill: F) -> Vec<(ConditionTally, ConditionStats)>
where
    F: Fn(usize, u64, u64, &mut BlockTally) + Sync,
{
    let progress = Progress::particles(plan.planned_particles(), label);
    let out = tally::run(plan, &progress, fill);
    progress.finish();
    out
}

/// Writes a shard's partial tally into `dir`; returns its path.
pub fn write_partial(
    dir: &Path,
    identity: &RunIdentity,
    plan: &Plan,
    manifest: toml::Table,
    tallies: Vec<ConditionTally>,
    seconds: f64,
) -> Result<PathBuf> {
    let shard = plan
        .shard
        .ok_or_else(|| Error::Internal("a partial tally without a shard".into()))?;
    crate::output::prepare_out_dir(dir)?;
    let path = dir.join(PARTIAL_FILE);
    Partial {
        identity: identity.clone(),
        shard,
        particles_per_condition: plan.count,
        seconds,
        manifest,
        tallies,
    }
    .write(&path)?;
    Ok(path)
}

/// Shards read back and merged.
pub struct Merged {
    pub identity: RunIdentity,
    pub shards: u32,
    /// The manifest tables of the first shard (the same in every shard but for timings).
    pub manifest: toml::Table,
    /// Seconds each shard took, in shard order.
    pub seconds: Vec<f64>,
    /// The merged tallies, in condition order.
    pub tallies: Vec<ConditionTally>,
}

/// Reads the partial tallies `inputs` (files or shard directories), checks they are the
/// shards of one run, all present once, and merges them. `specs(identity)` gives the
/// case's tally specifications (from the case text the shards carry). Every problem is a
/// one-line input error naming the shard.
pub fn merge<S>(inputs: &[PathBuf], specs: S) -> Result<Merged>
where
    S: Fn(&RunIdentity) -> Result<(Vec<TallySpec>, u64)>,
{
    if inputs.is_empty() {
        return Err(Error::invalid(
            "SHARD_DIR",
            "none",
            "one or more shard directories (or partial.toml files) written with --shard K/N",
        ));
    }
    let files: Vec<PartialFile> = inputs
        .iter()
        .map(|p| PartialFile::read(p))
        .collect::<Result<_>>()?;
    let first = &files[0];
    let digest = first.identity.digest();
    for f in &files[1..] {
        let clash = |what: &str| {
            Error::Input(format!(
                "shard `{}`: {what} differs from shard `{}`: not shards of one run",
                f.path, first.path
            ))
        };
        if f.identity.command != first.identity.command {
            return Err(clash("the command"));
        }
        if f.identity.seed != first.identity.seed {
            return Err(clash("the seed"));
        }
        if f.identity.digest() != digest {
            return Err(clash("the case (or an override)"));
        }
        if f.shard.count != first.shard.count {
            return Err(clash("the number of shards"));
        }
        if f.particles_per_condition != first.particles_per_condition {
            return Err(clash("the particle count"));
        }
    }
    let (specs, count) = specs(&first.identity)?;
    if count != first.particles_per_condition {
        return Err(Error::Input(format!(
            "shard `{}`: {} particles per condition, its case says {count}",
            first.path, first.particles_per_condition
        )));
    }
    let n = first.shard.count;
    let whole = Plan {
        specs: specs.clone(),
        count,
        target_se_deg: None,
        shard: None,
    };
    let mut order: Vec<usize> = (0..files.len()).collect();
    order.sort_by_key(|&i| files[i].shard.index);
    let identity = first.identity.clone();
    let mut manifest = toml::Table::new();
    let mut seconds = Vec::new();
    let mut merged: Vec<ConditionTally> = specs.iter().map(|s| ConditionTally::new(*s)).collect();
    let mut seen_shards: Vec<u32> = Vec::new();
    let mut files: Vec<Option<PartialFile>> = files.into_iter().map(Some).collect();
    for i in order {
        let Some(f) = files[i].take() else { continue };
        let name = f.path.clone();
        if seen_shards.contains(&f.shard.index) {
            return Err(Error::Input(format!(
                "shard `{name}`: shard {} is given twice (overlapping blocks)",
                f.shard
            )));
        }
        seen_shards.push(f.shard.index);
        let shard = f.shard;
        let part = f.restore(&specs)?;
        let own = Plan {
            shard: Some(shard),
            ..whole.clone()
        };
        for (k, (m, t)) in merged.iter_mut().zip(&part.tallies).enumerate() {
            if t.blocks() != own.owned_blocks(k) {
                return Err(Error::Input(format!(
                    "shard `{name}`: its blocks of condition {} are not those of shard {shard}",
                    k + 1
                )));
            }
            m.add(t).map_err(|b| {
                Error::Input(format!(
                    "shard `{name}`: block {b} of condition {} is also in another shard (overlapping blocks)",
                    k + 1
                ))
            })?;
        }
        if manifest.is_empty() {
            manifest = part.manifest;
        }
        seconds.push(part.seconds);
    }
    if let Some(missing) = (1..=n).find(|k| !seen_shards.contains(k)) {
        return Err(Error::Input(format!(
            "shard {missing}/{n} is missing: its blocks are not in any of the {} inputs (missing blocks)",
            inputs.len()
        )));
    }
    Ok(Merged {
        identity,
        shards: n,
        manifest,
        seconds,
        tallies: merged,
    })
}
