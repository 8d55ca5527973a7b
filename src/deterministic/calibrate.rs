//! The escape law of the `calibrated` stochastic model, measured on a deterministic run
//! (`rebound calibrate`): every collision of every followed history is counted with its
//! stage, its reduced incident and rebound angles and whether the particle then left the
//! wall ([`crate::stochastic::escape_table`]).

use super::{history_observed, stream_prefix, Fate, HitInfo, ModelSetup, Tracker};
use crate::incidence::IncidentCondition;
use crate::stochastic::escape_table::{EscapeCounts, Stage};
use nalgebra::Vector3;
use rayon::prelude::*;

/// The escape counts of histories `0..count` of every condition: the same histories (same
/// streams) as `rebound deterministic` of the same case and seed. Exact integer sums, so
/// the counts are the same for any thread count. Lost histories are not counted.
pub fn escape_counts(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    conditions: &[IncidentCondition],
    count: u64,
    seed: u64,
) -> EscapeCounts {
    let mut total = EscapeCounts::default();
    for (k, cond) in conditions.iter().enumerate() {
        let prefix = stream_prefix(seed, k as u64);
        let counts = (0..count)
            .into_par_iter()
            .fold(
                || {
                    (
                        EscapeCounts::default(),
                        Vec::<(Vector3<f64>, Vector3<f64>)>::new(),
                    )
                },
                |(mut counts, mut hits), i| {
                    hits.clear();
                    let h = history_observed(tracker, setup, cond, &prefix, i, |hit: &HitInfo| {
                        hits.push((hit.u_in, hit.u_out))
                    });
                    if h.fate == Fate::Escaped {
                        let last = hits.len().saturating_sub(1);
                        for (j, (u_in, u_out)) in hits.iter().enumerate() {
                            let stage = if j == 0 { Stage::First } else { Stage::Later };
                            counts.push(stage, u_in, u_out, &setup.wall, j == last);
                        }
                    }
                    (counts, hits)
                },
            )
            .map(|(c, _)| c)
            .reduce(EscapeCounts::default, |mut a, b| {
                a.add(&b);
                a
            });
        total.add(&counts);
    }
    total
}
