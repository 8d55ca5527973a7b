//! `rebound-report`: writes `REPORT.md` and the aggregated tables and figures under
//! `--results` (see the library's documentation). `rebound report` runs this binary.
//!
//! Unlike `rebound`'s run commands, it does not replace a directory as a whole: it adds a few
//! files (`REPORT.md`, `fig4.csv`/`.svg`, `speed_vs_error.csv`/`.svg`, …) to a results tree
//! that the runs own, so each file is written on its own, atomically.

use clap::error::ErrorKind;
use clap::Parser;
use roughwall::Error;
use std::path::PathBuf;
use std::time::Instant;

/// Write results/REPORT.md (ours beside the papers' numbers) from the reproduction outputs.
#[derive(Parser, Debug)]
#[command(
    name = "rebound report",
    version,
    after_help = "Example: rebound report --results results"
)]
struct Args {
    /// Root of the reproduction outputs (as written by scripts/reproduce-all.sh).
    #[arg(long, value_name = "DIR", default_value = "results")]
    results: PathBuf,
    /// Print nothing on success (errors are still printed).
    #[arg(long)]
    quiet: bool,
}

fn main() {
    let args = match Args::try_parse() {
        Ok(a) => a,
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => {
            e.exit()
        }
        Err(e) => {
            // One line, like every other input error of the tool: clap's message without its
            // usage hints.
            let rendered = e.render().to_string();
            let line: Vec<&str> = rendered
                .lines()
                .take_while(|l| !l.trim().is_empty())
                .map(str::trim)
                .collect();
            eprintln!("{}", line.join(" "));
            std::process::exit(2);
        }
    };
    let t0 = Instant::now();
    let result = if args.results.is_dir() {
        reproduce::write_report(&args.results)
    } else {
        Err(Error::invalid(
            "--results",
            args.results.display(),
            "an existing directory written by scripts/reproduce-all.sh",
        ))
    };
    match result {
        Ok(()) if args.quiet => {}
        Ok(()) => eprintln!(
            "report: read {} in {:.2} s; wrote {}",
            args.results.display(),
            t0.elapsed().as_secs_f64(),
            args.results.join("REPORT.md").display()
        ),
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(e.exit_code());
        }
    }
}
