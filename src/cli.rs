//! Command-line interface (clap): parses arguments and dispatches to `commands`.

use crate::runner::TallyOverrides;
use clap::{Args, Parser, Subcommand};
use roughwall::tally::Shard;
use std::path::PathBuf;

/// Particles bouncing off anisotropic rough walls: surfaces, deterministic bouncing,
/// a stochastic wall model, and the peak elastic force of spheroids.
#[derive(Parser, Debug)]
#[command(name = "rebound", version = crate::BUILD_VERSION, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// No summary on success and no progress bar or log lines (warnings and errors are still
    /// printed).
    #[arg(long, short = 'q', global = true)]
    pub quiet: bool,
    /// When stderr is not a terminal (a batch job's log): after an estimate of the whole run,
    /// a progress line every SECONDS (0: none).
    #[arg(long, global = true, value_name = "SECONDS", default_value_t = 30.0)]
    pub log_every: f64,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Generate a Garcia–Stoll anisotropic Gaussian surface and its normal-angle statistics (Table 1).
    #[command(
        after_help = "Example: rebound surface --case cases/table1.toml --heights /tmp/table1.rbhf"
    )]
    Surface(SurfaceArgs),
    /// Track particle centres bouncing on a generated surface (Figs. 6–9, 12).
    #[command(
        after_help = "Example: rebound deterministic --case cases/aniso.toml --particles 100000"
    )]
    Deterministic(DeterministicArgs),
    /// Run the stochastic rough-wall rebound model (Fig. 13) on the same scenes.
    #[command(
        after_help = "Example: rebound stochastic --case cases/glass-steel.toml --target-se 0.02"
    )]
    Stochastic(StochasticArgs),
    /// Peak elastic force of spheres and prolate spheroids hitting a wall (Hu et al.).
    #[command(name = "force-sweep")]
    #[command(after_help = "Example: rebound force-sweep --case cases/hu-fig6.toml")]
    ForceSweep(ForceSweepArgs),
    /// Compare the PDFs of two runs (e.g. deterministic vs stochastic).
    #[command(
        after_help = "Example: rebound compare --a results/aniso/deterministic --b results/aniso/stochastic --out results/aniso/compare"
    )]
    Compare(CompareArgs),
    /// Write results/REPORT.md (ours beside the papers' numbers) from the reproduction outputs.
    #[command(after_help = "Example: rebound report --results results")]
    Report(ReportArgs),
    /// Merge the partial tallies of `--shard K/N` runs into the outputs of one run.
    #[command(
        after_help = "Example: rebound merge --out results/gs/merged results/gs/shard-1 results/gs/shard-2"
    )]
    Merge(MergeArgs),
    /// Measure the escape table of the `calibrated` stochastic model on a deterministic run.
    #[command(
        after_help = "Example: rebound calibrate --case calibration/aniso.toml --out /tmp/cal"
    )]
    Calibrate(CalibrateArgs),
    /// Characterise a measured wall (a scan file) and write its wall card: the deviations
    /// and lay the models take.
    #[command(
        after_help = "Example: rebound scan --scan wall.x3p --out results/wall/scan --diameter-um 100,500\n   then: rebound stochastic --wall-card results/wall/scan/wall_card.toml"
    )]
    Scan(ScanArgs),
    /// Statistics of a pipe-flow study (code_saturne runs whose wall hook calls roughwall,
    /// written by scripts/pipe-flow.sh): profiles, collision frequency, impact angles,
    /// erosion, and the differences between walls, with standard errors.
    #[command(
        name = "pipe-stats",
        after_help = "Example: rebound pipe-stats --study target/pipe-flow --out results/pipe-flow"
    )]
    PipeStats(PipeStatsArgs),
}

/// Options every simulation subcommand takes.
#[derive(Args, Debug, Clone, Default)]
pub struct CommonArgs {
    /// Case file (TOML). Looked up as given, then under configs/ (e.g. `cases/aniso.toml`).
    /// Without it the subcommand runs its built-in default case.
    #[arg(long, value_name = "FILE")]
    pub case: Option<PathBuf>,
    /// Output directory [default: results/CASE_NAME/SUBCOMMAND/, the case's `name`].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Seed of every random stream; overrides the case's `seed`.
    #[arg(long, value_name = "N")]
    pub seed: Option<u64>,
    /// Worker threads [default: all cores]. Outputs are identical for any value.
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
}

#[derive(Args, Debug, Clone, Default)]
pub struct SurfaceArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Also save the height field (little-endian f32 with a small header; see README) to FILE.
    #[arg(long, value_name = "FILE")]
    pub heights: Option<PathBuf>,
}

/// Options of the Monte Carlo subcommands (`deterministic`, `stochastic`).
#[derive(Args, Debug, Clone, Default)]
pub struct TallyArgs {
    /// Particles per incident condition; overrides `[particles] count` (the cap under a target).
    #[arg(long, value_name = "N")]
    pub particles: Option<u64>,
    /// Run whole blocks of particles until the standard errors of mean α⁺ and mean β⁺ − β⁻
    /// are at most DEG degrees (or the count is reached); overrides `[particles] target_se_deg`.
    #[arg(long, value_name = "DEG", value_parser = parse_target_se, allow_negative_numbers = true)]
    pub target_se: Option<f64>,
    /// Run only shard K of N (1 ≤ K ≤ N) and write a partial tally (`partial.toml`) instead
    /// of outputs; `rebound merge` turns the N partial tallies into the outputs of one run.
    #[arg(long, value_name = "K/N", value_parser = Shard::parse)]
    pub shard: Option<Shard>,
}

impl TallyArgs {
    pub fn overrides(&self) -> TallyOverrides {
        TallyOverrides {
            particles: self.particles,
            target_se: self.target_se,
            shard: self.shard,
        }
    }
}

fn parse_target_se(s: &str) -> std::result::Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v > 0.0 && v.is_finite() => Ok(v),
        _ => Err(format!(
            "`{s}` is not allowed: a positive standard error in degrees"
        )),
    }
}

#[derive(Args, Debug, Clone, Default)]
pub struct DeterministicArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Reuse a height field saved by `rebound surface --heights FILE` instead of generating one.
    #[arg(long, value_name = "FILE")]
    pub surface: Option<PathBuf>,
    /// The wall of a wall_card.toml written by `rebound scan`: its [wall] deviations (and
    /// Sq as the rms height) replace the case's [wall].
    #[arg(long, value_name = "FILE")]
    pub wall_card: Option<PathBuf>,
    #[command(flatten)]
    pub tally: TallyArgs,
}

#[derive(Args, Debug, Clone, Default)]
pub struct StochasticArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// The wall of a wall_card.toml written by `rebound scan`, replacing the case's [wall]:
    /// its [[diameter]] row of [particles] diameter_um when it has rows, else its [wall].
    #[arg(long, value_name = "FILE")]
    pub wall_card: Option<PathBuf>,
    /// With --wall-card: take the card's [wall], the point particle's deviations (and
    /// measured-wall table), even when the card has [[diameter]] rows.
    #[arg(long, requires = "wall_card")]
    pub wall_card_point: bool,
    #[command(flatten)]
    pub tally: TallyArgs,
}

#[derive(Args, Debug, Clone, Default)]
pub struct CalibrateArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Histories per incident condition; overrides `[particles] count`.
    #[arg(long, value_name = "N")]
    pub particles: Option<u64>,
}

#[derive(Args, Debug, Clone, Default)]
pub struct MergeArgs {
    /// Output directory [default: results/CASE_NAME/SUBCOMMAND/, the case's `name`].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Worker threads for the figures [default: all cores].
    #[arg(long, value_name = "N")]
    pub threads: Option<usize>,
    /// The shards' output directories (or their partial.toml files), all N of one run.
    #[arg(value_name = "SHARD_DIR")]
    pub inputs: Vec<PathBuf>,
}

#[derive(Args, Debug, Clone, Default)]
pub struct ForceSweepArgs {
    #[command(flatten)]
    pub common: CommonArgs,
}

#[derive(Args, Debug, Clone, Default)]
pub struct ScanArgs {
    #[command(flatten)]
    pub common: CommonArgs,
    /// The scan file (X3P, SUR, GSF, Gwyddion text, MetroPro, OPD, PLU, …); overrides the
    /// case's `[scan] file`. Without `--case`, the run is named after the file.
    #[arg(long, value_name = "FILE")]
    pub scan: Option<PathBuf>,
    /// Particle diameter (µm) whose deviations the wall card gives (the sphere's centre
    /// surface on the scan); repeat it or give a comma list. Overrides the case's `[scan]
    /// diameters_um`.
    #[arg(
        long = "diameter-um",
        value_name = "UM",
        value_delimiter = ',',
        allow_negative_numbers = true
    )]
    pub diameter_um: Vec<f64>,
    /// Also build the wall's own stochastic model: the measured-wall table of the point
    /// particle and of each diameter (the rebound law of the deterministic reference on the
    /// scan itself; about 15 s each on a 4096² scan), named by the card for `[stochastic]
    /// model = "measured-wall"`. Overrides the case's `[scan] measured_wall`.
    #[arg(long = "measured-wall")]
    pub measured_wall: bool,
    /// Histories per incident direction of each measured-wall table (1024 … 1000000);
    /// overrides the case's `[scan] measured_wall_histories` [default: 17711].
    #[arg(long = "measured-wall-histories", value_name = "N")]
    pub measured_wall_histories: Option<i64>,
}

#[derive(Args, Debug, Clone, Default)]
pub struct CompareArgs {
    /// First run's output directory (e.g. a deterministic run: "DS").
    #[arg(long, value_name = "DIR")]
    pub a: PathBuf,
    /// Second run's output directory (e.g. a stochastic run: "SM").
    #[arg(long, value_name = "DIR")]
    pub b: PathBuf,
    /// Where to write comparison.csv and the overlay figures.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Label of run A in figures.
    #[arg(long, default_value = "DS")]
    pub label_a: String,
    /// Label of run B in figures.
    #[arg(long, default_value = "SM")]
    pub label_b: String,
}

#[derive(Args, Debug, Clone)]
pub struct PipeStatsArgs {
    /// The study directory scripts/pipe-flow.sh wrote (its study.tsv lists the runs).
    #[arg(long, value_name = "DIR")]
    pub study: PathBuf,
    /// Where to write the tables and figures (replaced as a whole).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

#[derive(Args, Debug, Clone)]
pub struct ReportArgs {
    /// Root of the reproduction outputs (as written by scripts/reproduce-all.sh).
    #[arg(long, value_name = "DIR", default_value = "results")]
    pub results: PathBuf,
}

impl Command {
    /// The subcommand's name on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            Command::Surface(_) => "surface",
            Command::Deterministic(_) => "deterministic",
            Command::Stochastic(_) => "stochastic",
            Command::ForceSweep(_) => "force-sweep",
            Command::Compare(_) => "compare",
            Command::Report(_) => "report",
            Command::Merge(_) => "merge",
            Command::Calibrate(_) => "calibrate",
            Command::Scan(_) => "scan",
            Command::PipeStats(_) => "pipe-stats",
        }
    }
}

/// The first paragraph of a clap error, on one line (clap adds usage lines after it).
pub fn one_line(rendered: &str) -> String {
    rendered
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect::<Vec<_>>()
        .join(" ")
}
