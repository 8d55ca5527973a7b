//! The statistics of the pipe-flow study (`rebound pipe-stats`, `scripts/pipe-flow.sh`):
//! code_saturne runs of glass beads in a horizontal pipe whose wall hook calls roughwall
//! (`examples/code_saturne/pipe/`) become concentration and velocity profiles, collision
//! frequencies, impact-angle and lay-angle distributions and Finnie erosion around the
//! circumference, each with a standard error, and the differences between walls.
//!
//! * [`read`]: the study's runs (`study.tsv`, each run's `pipe.params`, `particles.csv`,
//!   `hits_rank*.csv`).
//! * [`section`]: the mesh's cross-section, whose slab and strip areas normalise the
//!   concentration.
//! * [`sums`]: one run's batch sums (particles in 20 batches by id).
//! * [`jackknife`]: a statistic and its standard error from batch sums (delete-one-batch).
//! * [`stats`]: the study's quantities.
//! * [`tables`]: the CSV tables.

pub mod jackknife;
pub mod read;
pub mod section;
pub mod stats;
pub mod sums;
pub mod tables;
