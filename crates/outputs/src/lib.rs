//! The files `rebound` writes and its reproduction report reads back, shared by the
//! application (`rebound`) and the report (`crates/reproduce`, binary `rebound-report`):
//!
//! * [`write_atomic`], [`write_atomic_with`]: a file appears whole or not at all;
//! * [`csv`]: CSV tables with a fixed header ([`CsvTable`]) and the one reader of the
//!   tool's own outputs by column name ([`Rows`]);
//! * [`plot`]: the SVG line-plot renderer ([`Plot`], [`Series`], [`Kind`], [`plot_svg`],
//!   [`plot_grid_svg`]), the one place besides the application's figures that imports
//!   `plotters`.
//!
//! It depends on no physics: `roughwall` only for its error type, so that a failed write
//! carries the same message and exit code as every other error of the tool.

mod atomic;
pub mod csv;
pub mod plot;

pub use atomic::{write_atomic, write_atomic_with};
pub use csv::{CsvTable, Rows};
pub use plot::{plot_grid_svg, plot_svg, Kind, Plot, Series};
