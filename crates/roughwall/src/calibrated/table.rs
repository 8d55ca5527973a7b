//! The calibrated table read by the model: built from a calibration's counts (sparse
//! cells filled from their neighbours), the escape probability `P(escape | stage, x_in,
//! x_out)`, the element correction `w(stage, x_in, s)` with its rejection bound, the first
//! stage of a collision by the roughness of its plane, and the transverse memory. Its file
//! form (reader and writer) is [`super::table_file`].

use super::constants::*;
use super::counts::EscapeCounts;
use super::grid::*;
use super::transverse_memory::TransverseMemory;

/// A calibrated escape law: the counts it came from and the probability of every cell
/// (sparse cells filled, see [`EscapeTable::from_counts`]).
#[derive(Clone, Debug, PartialEq)]
pub struct EscapeTable {
    pub(super) counts: EscapeCounts,
    pub(super) p: Vec<f64>,
    /// Element correction: the ratio of the deterministic elements' law to the shadow law
    /// per `(stage, x_in, s)` cell (sparse cells: see [`EscapeTable::from_counts`]), and its
    /// largest value per `x_in` row (the rejection bound).
    pub(super) weight: Vec<f64>,
    pub(super) row_max: Vec<f64>,
    /// Where each `(slice, x_in bin)` row's values belong along `x_in`: the row's mean
    /// `x_in` ([`row_positions`]), for the escape and the element table.
    pub(super) escape_pos: Vec<f64>,
    pub(super) element_pos: Vec<f64>,
    /// Where each first stage's values belong along `Δγ` (degrees, increasing).
    pub(super) first_pos: Vec<f64>,
    /// The later stages' transverse memory.
    pub(super) memory: TransverseMemory,
    /// Where the table came from (the `# source:` line of its file).
    pub source: String,
}

/// Where one collision reads the element table ([`EscapeTable::element_read`]): the first
/// cells of its two rows along `x_in` and the upper row's weight, its `x_in` clamped to the
/// axis, and the rejection bound over both rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElementRead {
    pub(super) lo: usize,
    pub(super) hi: usize,
    pub(super) ti: f64,
    pub(super) x_in: f64,
    /// An upper bound of the weight over every `g` (at least 1).
    pub bound: f64,
}

/// The ratio `d/m` of a row's counts at cell `j`, pooled over the narrowest window
/// `j−k..=j+k` (clipped to the row) that holds [`ELEMENT_MIN_COUNT`] model draws; `None`
/// when the whole row holds fewer.
pub(super) fn window_ratio(d: &[u64], m: &[u64], j: usize) -> Option<f64> {
    window_ratio_within(d, m, j, usize::MAX)
}

/// `window_ratio` with the window's half-width at most `max_k` cells.
pub(super) fn window_ratio_within(d: &[u64], m: &[u64], j: usize, max_k: usize) -> Option<f64> {
    let (mut sd, mut sm) = (d[j], m[j]);
    let mut k = 0;
    while sm < ELEMENT_MIN_COUNT {
        k += 1;
        if k > max_k || (k > j && j + k >= m.len()) {
            return None;
        }
        for i in [j.checked_sub(k), Some(j + k).filter(|&i| i < m.len())]
            .into_iter()
            .flatten()
        {
            sd += d[i];
            sm += m[i];
        }
    }
    Some(sd as f64 / sm as f64)
}

/// The weight of a sparse later-stage element cell `c` from its own stage: the ratio over the
/// narrowest window of at most [`SAME_STAGE_S_CELLS`] cells each side along `s`, first in
/// its own row, then in the rows within 1, 2, … [`SAME_STAGE_ROWS`] bins along `x_in` pooled;
/// `None` when none holds [`ELEMENT_MIN_COUNT`] draws. Pooling along `x_in` within the stage
/// keeps the memory that pooling the stages loses: at α⁻ = −32.5°, β⁻ = 90° on the Sec. 3
/// wall the deterministic next element has a mean `γ/Δγ` of 1.07, 1.50 and 2.00 after `q` in
/// `[−3, −2.5)`, `[−2.5, −2)` and `[−2, −1.5)` (docs/design-notes.md, "Multiple collisions
/// followed").
pub(super) fn same_stage_ratio(deterministic: &[u64], model: &[u64], c: usize) -> Option<f64> {
    const K: usize = SAME_STAGE_S_CELLS;
    let plane = X_IN_BINS * G_BINS;
    let (slice, i_in, j) = (c / plane, (c % plane) / G_BINS, c % G_BINS);
    // Only the cells within K of j can enter the window: pool those alone.
    let (lo, hi) = (j.saturating_sub(K), (j + K).min(G_BINS - 1));
    let (mut d, mut m) = ([0u64; 2 * K + 1], [0u64; 2 * K + 1]);
    let n = hi - lo + 1;
    for r in 0..=SAME_STAGE_ROWS {
        // Row i_in itself, then the two rows r bins away.
        let rows = match r {
            0 => [Some(i_in), None],
            _ => [
                i_in.checked_sub(r),
                Some(i_in + r).filter(|&i| i < X_IN_BINS),
            ],
        };
        for i in rows.into_iter().flatten() {
            let b = slice * plane + i * G_BINS;
            for g in lo..=hi {
                d[g - lo] += deterministic[b + g];
                m[g - lo] += model[b + g];
            }
        }
        if let Some(w) = window_ratio_within(&d[..n], &m[..n], j - lo, K) {
            return Some(w);
        }
    }
    None
}

/// The position of every `(slice, x_in bin)` row: its counts' mean `x_in` (`sums` in
/// [`X_SUM_UNIT`]s over `counts` values) when it has at least `min` of them, else the bin's
/// centre. A mean lies in its bin, so positions increase along a slice.
pub(super) fn row_positions(sums: &[i64], counts: &[u64], min: u64) -> Vec<f64> {
    let per_row = counts.len() / ROWS;
    (0..ROWS)
        .map(|r| {
            let n: u64 = counts[r * per_row..(r + 1) * per_row].iter().sum();
            if n >= min.max(1) {
                sums[r] as f64 * X_SUM_UNIT / n as f64
            } else {
                centre_in(r % X_IN_BINS)
            }
        })
        .collect()
}

/// The position of every first stage along `Δγ` (degrees): its first collisions' mean
/// `Δγ(β)`, or for a stage without any a point inside its bin (its values are then the
/// first stages' pooled ones).
pub(super) fn first_positions(sums: &[i64], counts: &[u64]) -> Vec<f64> {
    (0..FIRST_STAGES)
        .map(|k| {
            if counts[k] > 0 {
                // Inside its bin even if every sum was rounded up onto the upper edge, so
                // that the positions increase.
                let (lo, hi) = first_edges(k);
                let mean = sums[k] as f64 * DG_SUM_UNIT / counts[k] as f64;
                mean.max(lo).min(hi - DG_SUM_UNIT)
            } else {
                match first_edges(k) {
                    (lo, hi) if hi.is_finite() => 0.5 * (lo + hi),
                    (lo, _) => lo + 1.0,
                }
            }
        })
        .collect()
}

/// Rows `(lo, hi)` of a slice and the weight of `hi` for a linear read at `x_in` between the
/// rows' positions `pos` (the slice's [`X_IN_BINS`] positions; clamped at the ends).
#[inline]
pub(super) fn rows_at(x_in: f64, pos: &[f64]) -> (usize, usize, f64) {
    let i = bin_in(x_in);
    let (lo, hi) = if x_in >= pos[i] {
        (i, (i + 1).min(X_IN_BINS - 1))
    } else {
        (i.saturating_sub(1), i)
    };
    let span = pos[hi] - pos[lo];
    if span > 0.0 {
        (lo, hi, ((x_in - pos[lo]) / span).clamp(0.0, 1.0))
    } else {
        (lo, hi, 0.0)
    }
}

/// The counts `v` of `stages` added cell by cell: one stage's plane of `plane` cells.
pub(super) fn pooled_stages(v: &[u64], plane: usize, stages: std::ops::Range<usize>) -> Vec<u64> {
    (0..plane)
        .map(|c| stages.clone().map(|k| v[k * plane + c]).sum())
        .collect()
}

/// Two tables of counts `(a, b)` pooled over each kind of stage: `[first, later]`, each the
/// pair of pooled planes (the fallback of a sparse cell).
pub(super) fn pooled_by_kind(a: &[u64], b: &[u64], plane: usize) -> [(Vec<u64>, Vec<u64>); 2] {
    [0..FIRST_STAGES, FIRST_STAGES..SLICES].map(|stages| {
        (
            pooled_stages(a, plane, stages.clone()),
            pooled_stages(b, plane, stages),
        )
    })
}

/// The escape probabilities of every cell. A cell with fewer than [`MIN_COUNT`] collisions
/// takes the value of the nearest cell along `x_in` (same stage and `x_out`) that has enough;
/// a column with none takes the pooled counts of its kind of stage, first or later (nearest
/// along `x_in`; a later column then the first stages' pooled value); a column no run saw
/// trapped is 1 (the rebound is steep enough).
pub(super) fn escape_probabilities(collisions: &[u64], escaped: &[u64]) -> Vec<f64> {
    let plane = X_IN_BINS * X_OUT_BINS;
    let mut p = vec![f64::NAN; SLICES * plane];
    let [(first_c, first_e), (pooled_c, pooled_e)] = pooled_by_kind(collisions, escaped, plane);
    for stage in 0..SLICES {
        for i_out in 0..X_OUT_BINS {
            // Nearest populated bin along x_in, the lower one first on a tie.
            let nearest = |c: &[u64], e: &[u64], i_in: usize, k: usize| {
                let own = |i: usize| {
                    let j = k + i * X_OUT_BINS + i_out;
                    (c[j] >= MIN_COUNT).then(|| e[j] as f64 / c[j] as f64)
                };
                (0..X_IN_BINS).find_map(|d| {
                    let lo = i_in.checked_sub(d).and_then(own);
                    let hi = (i_in + d < X_IN_BINS).then(|| own(i_in + d)).flatten();
                    lo.or(hi)
                })
            };
            for i_in in 0..X_IN_BINS {
                let at = i_in * X_OUT_BINS + i_out;
                p[stage * plane + at] = match nearest(collisions, escaped, i_in, stage * plane) {
                    Some(v) => v,
                    None if stage < FIRST_STAGES => {
                        nearest(&first_c, &first_e, i_in, 0).unwrap_or(f64::NAN)
                    }
                    None => nearest(&pooled_c, &pooled_e, i_in, 0)
                        .or_else(|| nearest(&first_c, &first_e, i_in, 0))
                        .unwrap_or(f64::NAN),
                };
            }
        }
    }
    p.into_iter()
        .map(|v| if v.is_nan() { 1.0 } else { v })
        .collect()
}

/// The element weights of every cell. An element cell with fewer than [`ELEMENT_MIN_COUNT`]
/// draws takes, for a later stage, the ratio pooled nearby in its own stage
/// (`same_stage_ratio`); else the ratio over the narrowest window that has enough
/// (`window_ratio`) in the pooled row of its kind of stage (first or later); a row without
/// enough draws keeps the shadow law (1).
pub(super) fn element_weights(deterministic: &[u64], model: &[u64]) -> Vec<f64> {
    // The shadow law's tails are where cells are sparse, and there the deterministic
    // surface has fewer steep elements than the shadow law (the ratio falls to ~0.3 five Δγ
    // out): a sparse cell must not fall back to 1.
    let plane = X_IN_BINS * G_BINS;
    let [(first_d, first_m), (later_d, later_m)] = pooled_by_kind(deterministic, model, plane);
    (0..SLICES * plane)
        .map(|c| {
            let (d, m, base) = if model[c] >= ELEMENT_MIN_COUNT {
                (deterministic, model, c - c % G_BINS)
            } else if c < FIRST_STAGES * plane {
                (&first_d[..], &first_m[..], c % plane - c % G_BINS)
            } else if let Some(w) = same_stage_ratio(deterministic, model, c) {
                return w;
            } else {
                (&later_d[..], &later_m[..], c % plane - c % G_BINS)
            };
            window_ratio(&d[base..base + G_BINS], &m[base..base + G_BINS], c % G_BINS)
                .unwrap_or(1.0)
        })
        .collect()
}

impl EscapeTable {
    /// The table of `counts` (`escape_probabilities`, `element_weights`).
    pub fn from_counts(counts: EscapeCounts, source: &str) -> EscapeTable {
        let p = escape_probabilities(&counts.collisions, &counts.escaped);
        let weight = element_weights(&counts.element_deterministic, &counts.element_model);
        let row_max = weight
            .chunks(G_BINS)
            .map(|r| r.iter().copied().fold(0.0, f64::max))
            .collect();
        let escape_pos = row_positions(&counts.escape_x_sum, &counts.collisions, MIN_COUNT);
        let element_pos = row_positions(
            &counts.element_x_sum,
            &counts.element_model,
            ELEMENT_MIN_COUNT,
        );
        let first_pos = first_positions(&counts.first_dg_sum, &counts.first_count);
        let memory = TransverseMemory::from_counts(&counts.transverse);
        EscapeTable {
            counts,
            p,
            weight,
            row_max,
            escape_pos,
            element_pos,
            first_pos,
            memory,
            source: source.to_string(),
        }
    }

    /// The element weight `w(stage, x_in, s)` of an element of reduced inclination
    /// `g = γ/Δγ(β)`, read at `s = g − x_in` (bilinear between the rows' positions along
    /// `x_in` and the cell centres along `s`, 1 outside the `s` range): the calibrated model
    /// accepts a shadow-law draw with `w / bound(x_in)`.
    #[inline]
    pub fn element_weight(&self, stage: Stage, x_in: f64, g: f64) -> f64 {
        self.weight_at(&self.element_read(stage, x_in), g)
    }

    /// An upper bound of [`Self::element_weight`] at `x_in` (over every `g`; at least 1,
    /// the weight outside the range).
    #[inline]
    pub fn element_bound(&self, stage: Stage, x_in: f64) -> f64 {
        self.element_read(stage, x_in).bound
    }

    /// Where a collision of `stage` at `x_in` reads the element table: found once per
    /// collision, read once per shadow-law proposal ([`Self::weight_at`]).
    #[inline]
    pub fn element_read(&self, stage: Stage, x_in: f64) -> ElementRead {
        let x_in = if x_in.is_nan() { 0.0 } else { x_in };
        let row = stage.0 * X_IN_BINS;
        let (i0, i1, ti) = rows_at(x_in, &self.element_pos[row..row + X_IN_BINS]);
        ElementRead {
            lo: (row + i0) * G_BINS,
            hi: (row + i1) * G_BINS,
            ti,
            x_in: x_in.clamp(X_IN_MIN, X_IN_MAX),
            bound: self.row_max[row + i0].max(self.row_max[row + i1]).max(1.0),
        }
    }

    /// [`Self::element_weight`] of an element of reduced inclination `g` where `read` says.
    #[inline]
    pub fn weight_at(&self, read: &ElementRead, g: f64) -> f64 {
        let s = g - read.x_in;
        if s.is_nan() || !(G_MIN..G_MAX).contains(&s) {
            return 1.0;
        }
        let (g0, g1, tg) = axis(s, G_MIN, DG, G_BINS);
        let w = &self.weight;
        let lo = w[read.lo + g0] + (w[read.lo + g1] - w[read.lo + g0]) * tg;
        let hi = w[read.hi + g0] + (w[read.hi + g1] - w[read.hi + g0]) * tg;
        lo + (hi - lo) * read.ti
    }

    /// The counts the table came from.
    pub fn counts(&self) -> &EscapeCounts {
        &self.counts
    }

    /// The first stage of a collision in an incident plane of roughness angle `delta_gamma`
    /// (radians), given a uniform draw `u` in `[0, 1)`: of the two first stages whose
    /// positions along `Δγ` bracket it, the upper one with probability `t` (the linear
    /// weight between them; clamped at the ends). The particle's first collision then
    /// follows the mixture `(1 − t)·law(lo) + t·law(hi)` exactly, at the cost of one table
    /// read: on the deterministic surface the law at one reduced angle still depends on the
    /// roughness angle itself (docs/design-notes.md).
    #[inline]
    pub fn first_stage(&self, delta_gamma: f64, u: f64) -> Stage {
        let d = delta_gamma.to_degrees();
        let pos = &self.first_pos;
        let k = pos[1..FIRST_STAGES - 1].partition_point(|&p| p <= d);
        let t = (d - pos[k]) / (pos[k + 1] - pos[k]);
        // (A NaN `t` compares false: the lower stage.)
        Stage(if u < t { k + 1 } else { k })
    }

    /// The residual of the transverse inclination of a later collision's element after an
    /// element of residual `z_prev`, from a standard normal draw `n`
    /// (`super::transverse_memory`); a first collision has no memory: `n`.
    #[inline]
    pub fn transverse_residual(&self, stage: Stage, z_prev: f64, n: f64) -> f64 {
        match stage.later_index() {
            Some(k) => self.memory.residual(k, z_prev, n),
            None => n,
        }
    }

    /// The transverse memory's slope of a later stage (0 for a first one).
    pub fn transverse_slope(&self, stage: Stage) -> f64 {
        stage.later_index().map_or(0.0, |k| self.memory.slope(k))
    }

    /// The probability of cell `(stage, i_in, i_out)`.
    pub fn cell_p(&self, stage: Stage, i_in: usize, i_out: usize) -> f64 {
        self.p[cell(stage, i_in, i_out)]
    }

    /// The probability that a particle leaves the wall after a collision of `stage` from
    /// reduced incident angle `x_in` with reduced rebound angle `x_out` (bilinear between
    /// the rows' positions along `x_in` and the bin centres along `x_out`, clamped at the
    /// edges; 1 beyond `x_out =` `X_OUT_MAX`, 0 for `x_out ≤ 0`).
    #[inline]
    pub fn p_escape(&self, stage: Stage, x_in: f64, x_out: f64) -> f64 {
        if x_out.is_nan() || x_out <= 0.0 {
            return 0.0;
        }
        if x_out >= X_OUT_MAX {
            return 1.0;
        }
        // A direction with no roughness in its plane has no reduced angle (0/0).
        let x_in = if x_in.is_nan() { 0.0 } else { x_in };
        let row = stage.0 * X_IN_BINS;
        let (i0, i1, ti) = rows_at(x_in, &self.escape_pos[row..row + X_IN_BINS]);
        let (o0, o1, to) = axis(x_out, 0.0, DX_OUT, X_OUT_BINS);
        let at = |i, o| self.p[cell(stage, i, o)];
        let lo = at(i0, o0) + (at(i0, o1) - at(i0, o0)) * to;
        let hi = at(i1, o0) + (at(i1, o1) - at(i1, o0)) * to;
        lo + (hi - lo) * ti
    }
}
