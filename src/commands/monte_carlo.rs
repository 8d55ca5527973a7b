//! The skeleton of the Monte Carlo commands (`deterministic`, `stochastic`): plan → identity
//! → target → begin → execute → partial tally (one shard of many) or final outputs → commit.
//! A command brings only what is its own: its scene, how a block of particles is filled and
//! how its outputs are written.

use crate::case::Warning;
use crate::commands::{begin_out, warn, Summary};
use crate::partial::RunIdentity;
use crate::run_context::Context;
use crate::runner::{self, TallyOverrides};
use roughwall::tally::ConditionStats;
use roughwall::tally::{BlockTally, ConditionTally, Plan, Shard, TallySpec};
use roughwall::Result;
use std::path::{Path, PathBuf};

/// A planned Monte Carlo run whose inputs are all checked: where it writes and what a shard
/// of it must agree on.
pub struct MonteCarlo {
    /// The subcommand (`deterministic`, `stochastic`): the progress label and the identity.
    command: &'static str,
    /// What one particle is called in the summary line (`histories`, `rebounds`).
    unit: &'static str,
    plan: Plan,
    /// What shards must agree on; `Some` for a shard run (a shard's partial tally records it).
    identity: Option<RunIdentity>,
    target: PathBuf,
}

/// What a command's scene gives the skeleton.
pub struct Scene<'a> {
    /// One tally spec per incident condition.
    pub specs: Vec<TallySpec>,
    /// Particles per condition.
    pub count: u64,
    /// Target standard error (degrees), if any.
    pub target_se_deg: Option<f64>,
    /// The height file or scan the run reads (part of a shard's identity).
    pub surface_file: Option<&'a Path>,
}

impl MonteCarlo {
    /// Plans the run of `scene` with the command line's `overrides`; `out` is `--out` (a
    /// shard writes into its own directory under it).
    pub fn plan(
        ctx: &Context,
        out: Option<&Path>,
        command: &'static str,
        unit: &'static str,
        scene: Scene,
        overrides: &TallyOverrides,
    ) -> Result<MonteCarlo> {
        let plan = runner::plan(
            scene.specs,
            scene.count,
            scene.target_se_deg,
            overrides.shard,
        )?;
        let identity = plan
            .shard
            .map(|_| {
                let (text, origin) = (&ctx.case_text, &ctx.case_origin);
                runner::identity(
                    command,
                    text,
                    origin,
                    ctx.seed,
                    overrides,
                    scene.surface_file,
                )
            })
            .transpose()?;
        let target = match plan.shard {
            Some(shard) => ctx.shard_dir(out, shard),
            None => ctx.out_dir.clone(),
        };
        Ok(MonteCarlo {
            command,
            unit,
            plan,
            identity,
            target,
        })
    }

    /// The directory the run writes (`--out`, or a shard's own directory).
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// The shard this run is, when it is one of many (it then writes a partial tally).
    pub fn shard(&self) -> Option<Shard> {
        self.plan.shard
    }

    /// Locks and stages the output directory, runs every condition
    /// (`fill(k, start, end, block)` tallies particles `start..end` of condition `k`), then
    /// writes a shard's partial tally (with `notes`, and `setup_seconds` added to the run's
    /// time) or, for a whole run, the outputs through `finish(dir, tallies, stats, seconds)`,
    /// whose warnings are printed; commits the directory.
    pub fn run<F, W>(
        self,
        notes: &toml::Table,
        setup_seconds: f64,
        fill: F,
        finish: W,
    ) -> Result<Summary>
    where
        F: Fn(usize, u64, u64, &mut BlockTally) + Sync,
        W: FnOnce(&Path, &[ConditionTally], &[ConditionStats], f64) -> Result<Vec<Warning>>,
    {
        let out = begin_out(&self.target)?;
        let t0 = std::time::Instant::now();
        let done = runner::execute(&self.plan, self.command, fill);
        let seconds = t0.elapsed().as_secs_f64();
        let (tallies, stats): (Vec<ConditionTally>, Vec<ConditionStats>) = done.into_iter().unzip();
        let summary = Summary::monte_carlo(self.plan.shard, &tallies, self.unit, &self.target);
        match &self.identity {
            Some(identity) => {
                let total_s = seconds + setup_seconds;
                runner::write_partial(
                    out.path(),
                    identity,
                    &self.plan,
                    notes.clone(),
                    tallies,
                    total_s,
                )?;
            }
            None => warn(finish(out.path(), &tallies, &stats, seconds)?),
        }
        out.commit()?;
        Ok(summary)
    }
}
