//! Calibration: the counts of the `calibrated` model measured on a deterministic run
//! (`rebound calibrate`): every collision of every followed history is counted with its
//! stage, its reduced incidence and rebound (in the wall's slopes, [`super::slope_space`])
//! and whether the particle then left the wall, and the wall element of every collision
//! beside a draw of the model's proposal (the shadow law in slopes) for the same direction
//! ([`super::EscapeCounts`]), and every later collision's transverse residual beside the
//! element just left's ([`super::transverse_memory`]).

use super::constants::{G_MAX, PROPOSAL_EPS};
use super::counts::EscapeCounts;
use super::grid::{Stage, X_IN_MAX};
use super::model::{left_element_memory, transverse_residual};
use super::slope_space::{proposal, reduced_slope, slope_deviations, slopes_from_normal};
use crate::angles::incident_angles;
use crate::deterministic::{
    history_observed, stream_prefix, Fate, HitInfo, ModelSetup, Realisations,
};
use crate::incidence::IncidentCondition;
use crate::rng;
use crate::wall::delta_gamma;
use nalgebra::Vector3;
use rayon::prelude::*;

/// The escape counts of histories `0..count` of every condition: the same histories (same
/// streams) as `rebound deterministic` of the same case and seed. Exact integer sums, so
/// the counts are the same for any thread count. The escape counts leave lost histories out;
/// the element, first-collision and transverse counts take every collision they saw. History `i`
/// bounces on the realisation `deterministic` gives it ([`Realisations::for_history`]).
pub fn escape_counts(
    surfaces: &Realisations<'_>,
    setup: &ModelSetup,
    conditions: &[IncidentCondition],
    count: u64,
    seed: u64,
) -> EscapeCounts {
    let mut total = EscapeCounts::default();
    // The model's coordinates: slopes ([`super::slope_space`]).
    let slopes = slope_deviations(&setup.wall);
    for (k, cond) in conditions.iter().enumerate() {
        let prefix = stream_prefix(seed, k as u64);
        // Shadow-law draws from a stream of their own (the histories' are untouched).
        let model_prefix = rng::StreamPrefix::new(seed, &[rng::domain::CALIBRATION, k as u64]);
        let counts = (0..count)
            .into_par_iter()
            .fold(
                || {
                    (
                        EscapeCounts::default(),
                        Vec::<(Vector3<f64>, Vector3<f64>, Vector3<f64>)>::new(),
                    )
                },
                |(mut counts, mut hits), i| {
                    hits.clear();
                    let tracker = surfaces.for_history(i);
                    let h = history_observed(tracker, setup, cond, &prefix, i, |hit: &HitInfo| {
                        hits.push((hit.u_in, hit.u_out, hit.normal))
                    });
                    // Every collision's stage: a later one by the element just left, seen
                    // from the new direction (its memory `q`), and its transverse residual
                    // beside the element just left's, seen from the same direction.
                    let stages: Vec<Stage> = (0..hits.len())
                        .map(|j| match j {
                            // The first by its plane's slope spread σ(β), counted along σ once.
                            0 => {
                                let beta = incident_angles(&hits[0].0).1;
                                counts.push_first(delta_gamma(&slopes, beta))
                            }
                            _ => {
                                let beta = incident_angles(&hits[j].0).1;
                                let (q, z_prev) =
                                    left_element_memory(&hits[j - 1].2, beta, &slopes);
                                let stage = Stage::later(q);
                                let z = transverse_residual(&hits[j].2, beta, &slopes);
                                counts.push_transverse(stage, z_prev, z);
                                stage
                            }
                        })
                        .collect();
                    // Every collision's element beside a draw of the model's proposal (the
                    // shadow law in slopes) for its direction.
                    let mut model_stream = model_prefix.stream(i);
                    for (j, (u_in, _, normal)) in hits.iter().enumerate() {
                        let beta = incident_angles(u_in).1;
                        let sigma = delta_gamma(&slopes, beta);
                        if sigma <= 0.0 {
                            continue;
                        }
                        let x = reduced_slope(u_in, &slopes);
                        // A rising proposal takes about x² tries, and beyond this its draws
                        // and the element (both steeper than the path) fall outside every
                        // element cell: nothing to count.
                        if x >= X_IN_MAX + G_MAX {
                            continue;
                        }
                        let g_det = slopes_from_normal(normal, beta).0 / sigma;
                        let g_model = proposal(x).sample(&mut model_stream) / PROPOSAL_EPS;
                        counts.push_element(stages[j], x, g_det, g_model);
                    }
                    if h.fate == Fate::Escaped {
                        let last = hits.len().saturating_sub(1);
                        for (j, (u_in, u_out, _)) in hits.iter().enumerate() {
                            counts.push(stages[j], u_in, u_out, &slopes, j == last);
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
