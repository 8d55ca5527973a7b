//! `rebound stochastic`: the stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.6, Fig. 13; docs/physics.md §3) for every incident condition of the case, on the
//! case's wall or a wall card's (`--wall-card`).

use crate::case::{builtin, stochastic::prepare};
use crate::cli::StochasticArgs;
use crate::commands::{apply_wall_card, begin_out, context, warn, Summary};
use crate::output::out_dir::{check_distinct, check_out};
use crate::runner;
use crate::writers::stochastic::finish;
use roughwall::error::Result;
use roughwall::stochastic::simulate::fill_block;
use roughwall::tally::engine::ConditionStats;
use roughwall::tally::ConditionTally;

/// Runs the subcommand.
pub fn run(args: &StochasticArgs) -> Result<Summary> {
    let mut ctx = context(&args.common, "stochastic", builtin::STOCHASTIC)?;
    let card = apply_wall_card(&mut ctx, args.wall_card.as_deref(), "stochastic")?;
    let o = args.tally.overrides();
    let mut p = prepare(&ctx.case, &o, ctx.seed)?;
    warn(std::mem::take(&mut p.warnings));
    if let Some(card) = card {
        p.notes.insert("wall_card".into(), toml::Value::Table(card));
    }
    let plan = runner::plan(
        p.specs.clone(),
        p.scene.count as u64,
        p.scene.target_se_deg,
        o.shard,
    )?;
    // What shards must agree on (a shard's partial tally records it).
    let identity = plan
        .shard
        .map(|_| {
            let (text, origin) = (&ctx.case_text, &ctx.case_origin);
            runner::identity("stochastic", text, origin, ctx.seed, &o, None)
        })
        .transpose()?;
    // Every input is checked: lock and stage the output directory (a shard's own directory
    // for a shard run), then compute.
    let target = match plan.shard {
        Some(shard) => ctx.shard_dir(args.common.out.as_deref(), shard),
        None => ctx.out_dir.clone(),
    };
    if let Some(card) = &args.wall_card {
        // `--out` is replaced as a whole: it must not hold the card the run reads.
        check_out(&target, "--out")?;
        check_distinct(&target, "--out", &[("--wall-card", card)])?;
    }
    let out = begin_out(&target)?;
    let t0 = std::time::Instant::now();
    let (setup, conditions, seed) = (&p.setup, &p.scene.conditions, ctx.seed);
    let done = runner::execute(&plan, "stochastic", |k, start, end, block| {
        fill_block(setup, &conditions[k], k as u64, seed, (start, end), block)
    });
    let seconds = t0.elapsed().as_secs_f64();
    let (tallies, stats): (Vec<ConditionTally>, Vec<ConditionStats>) = done.into_iter().unzip();
    let summary = Summary::monte_carlo(plan.shard, &tallies, "rebounds", &target);
    if let Some(identity) = &identity {
        runner::write_partial(out.path(), identity, &plan, p.notes, tallies, seconds)?;
    } else {
        let manifest = ctx.manifest;
        warn(finish(
            out.path(),
            manifest,
            &p,
            &tallies,
            Some(&stats),
            seconds,
        )?);
    }
    out.commit()?;
    Ok(summary)
}
