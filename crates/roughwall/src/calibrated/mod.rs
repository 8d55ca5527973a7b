//! The `calibrated` wall model: Radenkovic & Simonin 2021's virtual walls with what their
//! Eq. (34) leaves out measured on a deterministic run instead (`rebound calibrate`), and a
//! trapped particle followed from hit to hit.
//!
//! Eq. (34) gives the single-collision probability as `tanh(ψ α⁺/Δγ(β⁺))` whatever the
//! incidence. The deterministic simulation says otherwise (`results/REPORT.md`, "A model
//! within the deterministic noise? The calibrated escape law"): at grazing incidence a particle
//! hits near the asperity tops and escapes more easily, and after a first collision it
//! starts low, in a valley. So the model tabulates, per collision *stage* (the first, by the
//! roughness of its incident plane: [`Stage::first`]; or a later one of the same history,
//! remembering the element the particle has just left: [`Stage::later`]):
//! * the probability that the particle leaves the wall after the collision, by its reduced
//!   incidence `x_in = tan α/σ(β)` and rebound `x_out = tan α⁺/σ(β⁺)`;
//! * a correction of the first element's law (the paper's shadow law in slopes) by the
//!   ratio of the deterministic elements' law to it;
//! * the memory of the element's transverse inclination across successive hits
//!   (`transverse_memory`).
//!
//! Everything works in the wall's *slopes* (`slope_space`): `σ(β)` is the slope spread
//! along the direction `β` (Eq. 35 with slopes for angles), because in those units a point
//! particle's first element has one law for every wall.
//!
//! The files follow the model's life: `constants` (every chosen number, with how it was
//! chosen) and `grid` (the table's fixed axes and stages); `calibrate` counts a
//! deterministic run into `counts`; `table` turns the counts into the law the model
//! reads, and `table_file` writes and reads it (with the built-in table); `model` is the
//! rebound. The other models do not depend on anything here.

pub(crate) mod calibrate;
pub(crate) mod constants;
pub(crate) mod counts;
pub(crate) mod grid;
pub(crate) mod model;
pub(crate) mod slope_space;
pub(crate) mod table;
pub(crate) mod table_file;
pub(crate) mod transverse_memory;

#[cfg(test)]
mod tests;

pub use calibrate::escape_counts;
pub use constants::X_OUT_BINS;
pub use counts::EscapeCounts;
pub use grid::Stage;
pub use grid::{FIRST_STAGES, X_IN_BINS};
pub use model::{left_element_memory, rebound, transverse_residual, CalibratedIncidence};
pub use slope_space::slope_deviations;
pub use slope_space::slopes_from_normal;
pub use table::{ElementRead, EscapeTable};
pub use table_file::MAX_DISTINCT_TABLES;
pub use table_file::{BUILTIN, MAGIC};
pub use transverse_memory::TransverseCounts;
