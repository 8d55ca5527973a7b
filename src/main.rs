//! The `rebound` binary: parse, dispatch, report errors. The physics lives in the library.

use clap::Parser;

fn main() {
    let cli = rebound::cli::Cli::parse();
    if let Err(e) = rebound::cli::run(cli) {
        eprintln!("error: {e}");
        std::process::exit(e.exit_code());
    }
}
