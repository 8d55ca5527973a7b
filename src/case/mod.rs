//! TOML case files: the schema (`schema`), loading with one-line errors (`load`), the
//! check helpers every section uses (`check`, OpenMC's checkvalue as the model), and one file
//! per section family with its validated SI view: `wall` (`[surface]`, `[wall]`, `[stats]`),
//! `scene` (`[incidence]`, `[particles]`, `[output]`), `collision`, `stochastic` (and `[stochastic]`),
//! `deterministic` (and `[deterministic]`), `erosion`, `force` (`[impactor]`, `[sweep]`),
//! `scan` (`[scan]`, and the scan it names, read), `values` (sweep ranges), `wall_card` (the
//! wall of a `wall_card.toml`, `--wall-card`). `sections` says which command reads which
//! section; `builtin` holds each command's built-in case.

pub mod builtin;
pub mod collision;
pub mod deterministic;
pub mod erosion;
pub mod force;
pub mod load;
pub mod scan;
pub mod scene;
pub mod schema;
pub mod sections;
pub mod stochastic;
pub mod values;
pub mod wall;
pub mod wall_card;

pub use load::{load_text, parse, DEFAULT_SEED};
pub use roughwall::Warning;
pub use scene::Scene;
pub use schema::*;
pub use wall::WallSource;
