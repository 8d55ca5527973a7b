//! Tallies shared by `deterministic` and `stochastic`: per incident condition, streaming
//! accumulators in fixed blocks of particles (the way OpenMC keeps its tallies), so memory
//! does not grow with the particle count and the outputs are byte-identical for any
//! thread count and any split into shards.
//!
//! * `moments`: `(n, mean, M2)` per block, merged in block order (Chan et al. 1979).
//! * `histogram`: integer histograms and per-bin ratio curves, exact under any merge.
//! * `condition`: what a worker fills for one block, and the condition's running tally.
//! * `engine`: runs the blocks in parallel, to a target standard error, or as one shard.
//! * `results`, `quantity`: typed results (the application writes them as CSV).
//! * `distance`: Kolmogorov–Smirnov and L1 distances between binned densities.
pub(crate) mod condition;
pub(crate) mod distance;
pub(crate) mod engine;
pub(crate) mod histogram;
pub(crate) mod moments;
pub(crate) mod quantity;
pub(crate) mod results;

pub use condition::{
    BlockRecord, Counters, RealisationCounts, TallyParts, TallyPartsMut, LOST_REASONS, NM,
};
pub use condition::{BlockTally, ConditionTally, ErosionOutcome, ModelKind, Outcome, TallySpec};
pub use distance::{distances, ks_samples, BinnedPdf};
pub use engine::{run, ConditionStats, Progress, Silent};
pub use engine::{Plan, Shard, BLOCK_SIZE};
pub use histogram::Bin;
pub use histogram::{Histogram, RatioCurve};
pub use moments::{Moments, ShiftedSums};
pub use quantity::Quantity;
pub use results::{ConditionResult, ErosionSummary, Estimate, Pdf, Proportion, Summary};
