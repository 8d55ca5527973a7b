//! `rebound stochastic`: the stochastic rebound model of Radenkovic & Simonin 2021
//! (Sec. 3.6, Fig. 13; docs/physics.md §3) for every incident condition of the case, on the
//! case's wall or a wall card's (`--wall-card`).

use crate::case::wall_card::CardWall;
use crate::case::{builtin, stochastic::prepare};
use crate::cli::StochasticArgs;
use crate::commands::monte_carlo::{MonteCarlo, Scene};
use crate::commands::{apply_wall_card, context, warn, Summary};
use crate::output::out_dir::{check_distinct, check_out};
use crate::writers::stochastic::finish;
use roughwall::models::fill_block;
use roughwall::Result;

/// Runs the subcommand.
pub fn run(args: &StochasticArgs) -> Result<Summary> {
    let mut ctx = context(&args.common, "stochastic", builtin::STOCHASTIC)?;
    let card = apply_wall_card(
        &mut ctx,
        args.wall_card.as_deref(),
        "stochastic",
        match args.wall_card_point {
            true => CardWall::Point,
            false => CardWall::OfTheParticles,
        },
    )?;
    let o = args.tally.overrides();
    let mut p = prepare(&ctx.case, &o, ctx.seed)?;
    warn(std::mem::take(&mut p.warnings));
    if let Some(card) = card {
        p.notes.insert("wall_card".into(), toml::Value::Table(card));
    }
    let scene = Scene {
        specs: p.specs.clone(),
        count: p.scene.count as u64,
        target_se_deg: p.scene.target_se_deg,
        surface_file: None,
    };
    let out = args.common.out.as_deref();
    let mc = MonteCarlo::plan(&ctx, out, "stochastic", "rebounds", scene, &o)?;
    if let Some(card) = &args.wall_card {
        // `--out` is replaced as a whole: it must not hold the card the run reads.
        check_out(mc.target(), "--out")?;
        check_distinct(mc.target(), "--out", &[("--wall-card", card)])?;
    }
    // Every input is checked: lock and stage the output directory, then compute.
    let (setup, conditions, seed) = (&p.setup, &p.scene.conditions, ctx.seed);
    let manifest = ctx.manifest;
    mc.run(
        &p.notes,
        0.0,
        |k, start, end, block| {
            fill_block(setup, &conditions[k], k as u64, seed, (start, end), block)
        },
        |dir, tallies, stats, seconds| finish(dir, manifest, &p, tallies, Some(stats), seconds),
    )
}
