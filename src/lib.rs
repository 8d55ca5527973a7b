//! `rebound`: particles bouncing off anisotropic rough walls.
//!
//! The modules follow the pipeline of a run: `case` (schema, checks in `case::check`, what
//! each command resolves from a case: `case::deterministic`, `case::stochastic`,
//! `case::force`, returning warnings (`warning`) instead of printing them) → `run_context`
//! (case, seed, threads, output folder) → wall (`surface` generated, `deterministic::scene`
//! planning it, or the statistical `wall`) → incident particles (`incidence`, `angles`) →
//! `collision` law → `tally` (`runner` drives the blocks; `tally::schema` names the columns
//! of the tables) → `writers` (each command's tables, figures and `run.toml`:
//! `writers::deterministic`, `writers::stochastic`, `writers::surface`; `force::tables`),
//! built on the primitives of `output` (number formatting, CSV tables, atomic files and
//! output folders, the manifest) and on `figures`. `compare` reads two runs and computes
//! their distances. The physics modules (`collision`, `wall`, `surface`, `deterministic`,
//! `stochastic`, `tally`, `force`, `erosion`) do not import `case`. `rng` gives every
//! particle its own random stream.
//!
//! The modules import each other without cycles, low → high: `error`, `rng`, `warning`,
//! `output` → geometry and physics, `tally` → `runner` → `case` → `compare`, `figures` →
//! `writers`, `report`. The command line (`cli`, `commands`) belongs to the
//! `rebound` binary (`src/main.rs`), not to this library.
pub mod angles;
pub mod case;
pub mod collision;
pub mod compare;
pub mod deterministic;
pub mod erosion;
pub mod error;
pub mod ffi;
pub mod figures;
pub mod force;
pub mod incidence;
pub mod memory;
pub mod output;
pub mod progress;
pub mod report;
pub mod rng;
pub mod run_context;
pub mod runner;
pub mod stochastic;
pub mod surface;
pub mod tally;
pub mod wall;
pub mod wall_model;
pub mod warning;
pub mod writers;

/// This build's identity: the package version, `+src.`, and a 64-bit FNV-1a digest (16 hex
/// digits) of every `src/**/*.rs` file, `Cargo.toml` and `Cargo.lock` (`build.rs`), e.g.
/// `0.1.0+src.0123456789abcdef`. The package version alone is the same for every commit; this
/// changes whenever the code that produces results does. Partial tallies record it and
/// `rebound merge` refuses shards of another build; `run.toml` records it as `version`.
pub const BUILD_VERSION: &str = concat!(
    env!("CARGO_PKG_VERSION"),
    "+src.",
    env!("ROUGHWALL_SOURCE_DIGEST")
);
