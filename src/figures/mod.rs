//! SVG figures: the one place that talks to `plotters`. Every writer takes data already
//! computed (tallies, rows, statistics) and a directory or path; figures are rendered into
//! a string and written atomically like every other output. Physics modules never import
//! this module; commands and the report call it.
//!
//! * [`plot`]: the line-plot renderer ([`Plot`], [`Series`], [`Kind`], [`plot_svg`],
//!   [`plot_grid_svg`]).
//! * [`sweeps`]: the mean and std of `β⁺ − β⁻` against the incident angles (Figs. 16–17),
//!   shared by `deterministic`, `stochastic` and `compare`.
//! * One module per command: [`surface`] (height map, normal-angle PDFs, effective
//!   roughness), [`deterministic`], [`stochastic`], [`compare`] (overlays of two runs),
//!   [`force_sweep`], [`scan`] (a measured wall's height map and slope-angle PDFs),
//!   [`pipe_flow`] (`pipe-stats`: profiles, wall hits and erosion in a pipe).
//! * [`png`]: the small indexed-colour PNG the height map embeds.
//!
//! A new figure of a command goes into that command's module, built from [`Plot`]s; the
//! shared helpers below give panel titles and histogram outlines.

pub mod compare;
pub mod deterministic;
pub mod force_sweep;
pub mod pipe_flow;
pub mod png;
pub mod scan;
pub mod stochastic;
pub mod surface;
pub mod sweeps;

pub use outputs::{plot, plot_grid_svg, plot_svg, Kind, Plot, Series};
pub use sweeps::{dbeta_sweeps, sweep_plots, sweep_series, SweepPoint};

use roughwall::incidence::fmt_key;
use roughwall::tally::Bin;
use roughwall::IncidentCondition;
use std::fmt::Display;

/// The panel title of an incident condition given by its angles as written (degrees).
pub fn title(alpha_in: impl Display, beta_in: impl Display) -> String {
    format!("α⁻ = {alpha_in}°, β⁻ = {beta_in}°")
}

/// The panel title of an incident condition.
pub fn condition_title(c: &IncidentCondition) -> String {
    title(fmt_key(c.alpha_in_deg()), fmt_key(c.beta_in_deg()))
}

/// `(bin centre, value)` of every bin `(lo, hi, value)`: what a `Step` series draws as a
/// histogram outline.
pub fn bin_centres(bins: impl IntoIterator<Item = (f64, f64, f64)>) -> Vec<(f64, f64)> {
    bins.into_iter()
        .map(|(lo, hi, v)| (0.5 * (lo + hi), v))
        .collect()
}

/// `(bin centre, value)` points of a PDF, for a `Step` series.
pub fn bins_to_points(bins: &[Bin]) -> Vec<(f64, f64)> {
    bin_centres(bins.iter().map(|b| (b.lo, b.hi, b.value)))
}
