//! The dispatcher ([`run`]: a parsed command line in a thread pool of its size, warnings
//! printed after success) and one module per subcommand: context → resolve → run → write,
//! each step a library call.

pub mod calibrate;
pub mod compare;
pub mod deterministic;
pub mod force_sweep;
pub mod merge;
mod monte_carlo;
pub mod pipe_stats;
pub mod report;
pub mod scan;
pub mod stochastic;
pub mod surface;

use crate::case::Warning;
use crate::cli::{Cli, Command, CommonArgs};
use crate::output::OutputDir;
use crate::run_context::Context;
use roughwall::tally::{ConditionTally, Shard};
use roughwall::{Error, Result};
use std::path::{Path, PathBuf};

/// What a successful command tells its user on stderr (unless `--quiet`): what it did, how
/// fast, and what it wrote where.
pub struct Summary {
    /// What was done, e.g. `12 conditions, 1 200 000 particles`.
    pub work: String,
    /// Items done and their name, for a rate (e.g. `(1_200_000, "rebounds")`).
    pub rate: Option<(u64, &'static str)>,
    /// The output directory written (its files are listed).
    pub wrote: PathBuf,
}

impl Summary {
    /// A Monte Carlo run (or one shard of it) written to `dir`: its conditions and particles
    /// (`unit`: rebounds or histories), with a rate.
    pub fn monte_carlo(
        shard: Option<Shard>,
        tallies: &[ConditionTally],
        unit: &'static str,
        dir: &Path,
    ) -> Summary {
        let particles = tallies.iter().map(|t| t.counters.particles).sum();
        let conditions = tallies.len();
        let shard = match shard {
            Some(s) => format!("shard {}/{}: ", s.index, s.count),
            None => String::new(),
        };
        Summary {
            work: format!(
                "{shard}{}, {} {unit}",
                counted(conditions, "condition"),
                grouped(particles)
            ),
            rate: Some((particles, unit)),
            wrote: dir.to_path_buf(),
        }
    }

    /// The summary line of `command` that took `seconds`.
    pub fn line(&self, command: &str, seconds: f64) -> String {
        let rate = match self.rate {
            Some((n, unit)) if seconds > 0.0 && n > 0 => {
                format!(" ({} {unit}/s)", per_second(n as f64 / seconds))
            }
            _ => String::new(),
        };
        let wrote = format!("{}/ ({})", self.wrote.display(), listing(&self.wrote));
        format!(
            "{command}: {} in {:.2} s{rate}; wrote {wrote}",
            self.work, seconds
        )
    }
}

/// `n word` or `n words`.
pub fn counted(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}

/// `1234567` as `1 234 567`.
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(' ');
        }
        out.push(c);
    }
    out
}

/// A rate in the largest unit that keeps it at or above 1: `2.31 M`, `850 k`.
fn per_second(x: f64) -> String {
    if x >= 1e6 {
        format!("{:.2} M", x / 1e6)
    } else if x >= 1e3 {
        format!("{:.1} k", x / 1e3)
    } else {
        format!("{x:.1}")
    }
}

/// The files of an output directory: tables and manifests by name, figures counted.
fn listing(dir: &Path) -> String {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    let figures = names.iter().filter(|n| n.ends_with(".svg")).count();
    let mut shown: Vec<String> = names.into_iter().filter(|n| !n.ends_with(".svg")).collect();
    if figures > 0 {
        shown.push(counted(figures, "SVG figure"));
    }
    shown.join(", ")
}

/// The run context of `--case`, `--seed` and `--out` (threads: the pool the command runs in).
/// Warns about the case's sections that `command` does not read (`case::sections`).
pub fn context(common: &CommonArgs, command: &str, default_toml: &str) -> Result<Context> {
    let ctx = Context::new(
        common.case.as_deref(),
        common.seed,
        common.out.clone(),
        command,
        default_toml,
    )?;
    warn(crate::case::sections::unread(&ctx.case, command));
    Ok(ctx)
}

/// `--wall-card FILE` (`card`): the card's wall in place of the case's
/// (`crate::case::wall_card`), printed as a warning when the case had its own; returns the
/// `[wall_card]` table of `run.toml`.
pub fn apply_wall_card(
    ctx: &mut Context,
    card: Option<&Path>,
    command: &str,
    taking: crate::case::wall_card::CardWall,
) -> Result<Option<toml::Table>> {
    let Some(path) = card else {
        return Ok(None);
    };
    let card = crate::case::wall_card::WallCard::read(path)?;
    let mut case = ctx.case.clone();
    let applied = card.apply(&mut case, command, taking)?;
    ctx.set_case(case, command)?;
    warn(applied.warnings);
    Ok(Some(applied.manifest))
}

/// Begins writing `--out` at `dir` ([`OutputDir::begin`]) and hands its warnings on.
pub fn begin_out(dir: &Path) -> Result<OutputDir> {
    let mut out = OutputDir::begin(dir, "--out")?;
    warn(out.take_warnings());
    Ok(out)
}

thread_local! {
    /// The warnings of the command running on this thread, in order.
    static WARNINGS: std::cell::RefCell<Vec<Warning>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// Keeps the warnings the library returned: [`run`] prints them, in order, once the
/// command has succeeded (an error is always the one line a failed run prints).
pub fn warn(warnings: impl IntoIterator<Item = Warning>) {
    WARNINGS.with(|list| list.borrow_mut().extend(warnings));
}

/// The warnings kept on this thread so far (emptied).
pub fn take_warnings() -> Vec<Warning> {
    WARNINGS.with(|list| std::mem::take(&mut *list.borrow_mut()))
}

/// Runs a parsed command inside a rayon pool of the requested size.
pub fn run(cli: Cli) -> Result<()> {
    let threads = match &cli.command {
        Command::Surface(a) => a.common.threads,
        Command::Deterministic(a) => a.common.threads,
        Command::Stochastic(a) => a.common.threads,
        Command::ForceSweep(a) => a.common.threads,
        Command::Merge(a) => a.threads,
        Command::Calibrate(a) => a.common.threads,
        Command::Scan(a) => a.common.threads,
        Command::Compare(_) | Command::Report(_) | Command::PipeStats(_) => None,
    };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    // More threads than a few per core only cost memory (a stack each) and scheduling.
    let max_threads = (8 * cores).max(8);
    let threads = match threads {
        Some(n) if n == 0 || n > max_threads => {
            return Err(Error::invalid(
                "--threads",
                n,
                &format!("1 to {max_threads} (8 per core, {cores} cores here)"),
            ))
        }
        Some(n) => n,
        None => cores,
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Error::Io(format!("thread pool: {e}")))?;
    if !(cli.log_every.is_finite() && cli.log_every >= 0.0) {
        return Err(Error::invalid(
            "--log-every",
            cli.log_every,
            "a number of seconds ≥ 0 (0: no log lines)",
        ));
    }
    crate::progress::set_log_every(cli.log_every);
    if cli.quiet {
        crate::progress::hide();
    }
    let t0 = std::time::Instant::now();
    // Warnings are printed once the command has succeeded, so that an error is always the
    // one line a failed run prints. `install` runs the command on a pool thread: its
    // warnings are kept there.
    let (result, warnings) = pool.install(|| (dispatch(&cli), take_warnings()));
    let summary = result?;
    for w in warnings {
        eprintln!("warning: {w}");
    }
    if !cli.quiet {
        eprintln!(
            "{}",
            summary.line(cli.command.name(), t0.elapsed().as_secs_f64())
        );
    }
    Ok(())
}

fn dispatch(cli: &Cli) -> Result<Summary> {
    match &cli.command {
        Command::Surface(a) => surface::run(a),
        Command::Deterministic(a) => deterministic::run(a),
        Command::Stochastic(a) => stochastic::run(a),
        Command::ForceSweep(a) => force_sweep::run(a),
        Command::Compare(a) => compare::run(a),
        Command::Report(a) => Err(report::run(a, cli.quiet)),
        Command::Merge(a) => merge::run(a),
        Command::Calibrate(a) => calibrate::run(a),
        Command::Scan(a) => scan::run(a),
        Command::PipeStats(a) => pipe_stats::run(a),
    }
}
