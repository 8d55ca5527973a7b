//! The tally of one incident condition: block accumulators that a worker fills in
//! particle order, and the condition's running total that absorbs blocks.
//!
//! Integer parts (histogram counts, collision and candidate counts) are plain sums, exact
//! in any order. Floating-point parts (means and spreads) are kept per block as
//! [`Moments`] and folded in block order ([`ConditionTally::moments`]), so a run split
//! over threads, shards or machines gives the same bits as one process.

use super::histogram::{Histogram, RatioCurve};
use super::moments::{Moments, ShiftedSums};
use super::quantity::Quantity;
use super::results::{ConditionResult, ErosionSummary, Estimate, Pdf, Proportion, Summary};
use crate::incidence::IncidentCondition;
use crate::wall::{conditional_gamma_star, rotated_moments, Deviations};

/// Which model fills the tally: decides the model-specific columns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelKind {
    /// Particle histories on a surface (`rebound deterministic`).
    Deterministic,
    /// The statistical wall (`rebound stochastic`).
    Stochastic,
}

impl ModelKind {
    /// The subcommand's name.
    pub fn command(self) -> &'static str {
        match self {
            ModelKind::Deterministic => "deterministic",
            ModelKind::Stochastic => "stochastic",
        }
    }
}

/// What one followed particle history (or one accepted stochastic rebound) produced. Radians.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outcome {
    /// Final rebound angle `α⁺`.
    pub alpha_out: f64,
    /// Final transverse angle `β⁺`.
    pub beta_out: f64,
    /// `α⁺_xy` of Eq. (43) (`angles::alpha_xy_of_velocity`).
    pub alpha_out_xy: f64,
    /// Final transverse deviation `β⁺ − β⁻`, wrapped into (−π, π].
    pub dbeta: f64,
    /// Transverse deviation after the first collision (deterministic only).
    pub dbeta_first: Option<f64>,
    /// Fluctuation `ξ − π/2` of the first normal seen.
    pub xi_first: f64,
    /// Fluctuation `ζ − π/2` of the first normal seen.
    pub zeta_first: f64,
    /// `γ` of the first normal seen (Eq. 20).
    pub gamma_first: f64,
    /// `γ*` of the first normal seen (Eq. 21).
    pub gamma_star_first: f64,
    /// Number of wall collisions (deterministic only).
    pub collisions: Option<u32>,
    /// `α⁺` of the first rebound (deterministic only).
    pub alpha_first: Option<f64>,
    /// The single-collision model `tanh(ψ α⁺/Δγ(β⁺))` (Eqs. 34–35) at the first rebound
    /// (deterministic only; Fig. 12).
    pub p_single_model: Option<f64>,
    /// `|U⁺| / |U⁻|`.
    pub speed_ratio: f64,
    /// Wall erosion by this history (when the case has `[erosion]`).
    pub erosion: Option<ErosionOutcome>,
}

/// The wall volume one history removes, per unit particle mass (m³/kg).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ErosionOutcome {
    /// Deterministic: summed over every collision; stochastic: the accepted virtual wall's
    /// impact.
    pub per_mass: f64,
    /// Stochastic: summed over the rejected candidate rebounds (the repeated hits they
    /// stand for).
    pub rejected_per_mass: Option<f64>,
}

/// Number of reasons a deterministic history can be lost (`deterministic::LostReason`).
pub const LOST_REASONS: usize = 4;

/// What one condition tallies and how.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TallySpec {
    /// The incident condition `(α⁻, β⁻)` tallied.
    pub condition: IncidentCondition,
    /// Normal-angle deviations `(Δξ, Δζ)` of the wall (radians): they label the outputs and
    /// place the two `γ` slices of Fig. 11 (`Δγ` of Radenkovic & Simonin 2021, Eq. 26, at `β⁻`).
    pub deviations: Deviations,
    /// Bin width (degrees) of the angle histograms, the local impact-angle histograms and
    /// the Fig. 12 curves; the `γ*` histograms of the Fig. 11 slices use their own width.
    pub bin_width_deg: f64,
    /// Which model fills the tally: decides the model-specific columns and counters.
    pub model: ModelKind,
    /// The particle mass (kg) when the case tallies erosion; `None` without `[erosion]`.
    pub erosion_particle_mass_kg: Option<f64>,
}

/// The quantities with moments, in record order (also the histogram order, but for the last).
const MOMENT_QUANTITIES: [Quantity; 15] = [
    Quantity::AlphaOut,
    Quantity::AlphaOutXy,
    Quantity::BetaOut,
    Quantity::Dbeta,
    Quantity::DbetaFirst,
    Quantity::XiFirst,
    Quantity::ZetaFirst,
    Quantity::GammaFirst,
    Quantity::GammaStarFirst,
    Quantity::AlphaFirst,
    Quantity::GammaStarGivenGamma0,
    Quantity::GammaStarGivenGammaDg,
    Quantity::SpeedRatio,
    Quantity::ErosionPerMass,
    Quantity::ErosionPerMassRejected,
];
/// Moments per block record.
pub const NM: usize = MOMENT_QUANTITIES.len();
/// Histograms per block of the moment quantities: all before the speed ratio.
const NH: usize = SPEED_RATIO;
const SPEED_RATIO: usize = 12;
const EROSION: usize = 13;
const EROSION_REJECTED: usize = 14;
/// With `[erosion]`, two more histograms follow: local impact angles of the impacts that
/// count (every deterministic collision, the accepted stochastic wall) and of rejected
/// stochastic candidates.
const IMPACT: usize = NH;
const IMPACT_REJECTED: usize = NH + 1;
const ALPHA_OUT: usize = 0;
const DBETA: usize = 3;
const ALPHA_FIRST: usize = 9;
const SLICE_0: usize = 10;

/// The two slices of `γ` of Fig. 11 (Radenkovic & Simonin 2021): centre and half-width
/// (radians), and the histogram bin width (degrees) of `γ*` in them: `Δγ/10` around 0 and
/// around `Δγ` of Eq. (26); bins of a fifth of the conditional std of Eq. (30), 0.05°–1°.
fn gamma_slices(spec: &TallySpec) -> ([(f64, f64); 2], f64) {
    let m = rotated_moments(&spec.deviations, spec.condition.beta_in);
    let dg = m.delta_gamma();
    let half = (0.1 * dg).max(1e-9);
    let (_, var) = conditional_gamma_star(&m, 0.0);
    let width = (var.max(0.0).sqrt().to_degrees() / 5.0).clamp(0.05, 1.0);
    ([(0.0, half), (dg, half)], width)
}

fn histograms(spec: &TallySpec) -> Vec<Histogram> {
    let (_, slice_width) = gamma_slices(spec);
    let mut h: Vec<Histogram> = MOMENT_QUANTITIES[..NH]
        .iter()
        .enumerate()
        .map(|(i, q)| {
            let (lo, hi) = q.range_deg();
            let w = if i >= SLICE_0 {
                slice_width
            } else {
                spec.bin_width_deg
            };
            Histogram::new(lo, hi, w)
        })
        .collect();
    if spec.erosion_particle_mass_kg.is_some() {
        for q in [
            Quantity::ImpactAngleLocal,
            Quantity::ImpactAngleLocalRejected,
        ] {
            let (lo, hi) = q.range_deg();
            h.push(Histogram::new(lo, hi, spec.bin_width_deg));
        }
    }
    h
}

/// Integer counters of a block or condition.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Counters {
    /// Histories attempted (followed or lost; stochastic: rebounds).
    pub particles: u64,
    /// Lost histories by reason (deterministic).
    pub lost: [u64; LOST_REASONS],
    /// Σ collisions over the followed histories (deterministic; lost ones not counted).
    pub collisions: u64,
    /// Σ collisions² over the followed histories (deterministic): with
    /// [`collisions`](Self::collisions), the exact spread of the collision count.
    pub collisions_sq: u128,
    /// Followed histories with exactly one collision (deterministic): the numerator of the
    /// single-collision fraction `p_single`.
    pub single: u64,
    /// Most collisions of one followed history (deterministic; 0 when none was followed).
    pub max_collisions: u32,
    /// Σ candidate walls drawn over the rebounds (stochastic: steps 2–6 of the procedure,
    /// docs/physics.md §3, including walls the particle cannot reach).
    pub tries: u64,
    /// Σ candidate rebounds computed over the rebounds (stochastic: candidates with
    /// `U⁻·n < 0`, accepted or rejected): `p_single` is rebounds over this sum.
    pub candidates: u64,
    /// Σ candidate rebounds² over the rebounds (stochastic): with
    /// [`candidates`](Self::candidates), the standard error of `p_single`.
    pub candidates_sq: u128,
    /// Rebounds that hit the guard on candidate walls and took the mean wall instead
    /// (stochastic; [`MAX_TRIES`](crate::stochastic::virtual_wall::MAX_TRIES)).
    pub capped: u64,
}

impl Counters {
    fn add(&mut self, o: &Counters) {
        self.particles += o.particles;
        for (a, b) in self.lost.iter_mut().zip(&o.lost) {
            *a += b;
        }
        self.collisions += o.collisions;
        self.collisions_sq += o.collisions_sq;
        self.single += o.single;
        self.max_collisions = self.max_collisions.max(o.max_collisions);
        self.tries += o.tries;
        self.candidates += o.candidates;
        self.candidates_sq += o.candidates_sq;
        self.capped += o.capped;
    }

    /// Histories lost for any reason.
    pub fn lost_total(&self) -> u64 {
        self.lost.iter().sum()
    }
}

/// One block's moments, kept so that blocks can be folded in order later.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlockRecord {
    /// The block's index within its condition (particles `block · BLOCK_SIZE` onwards).
    pub block: u64,
    /// The block's moments of each quantity in record order (angles in degrees), [`NM`] of
    /// them.
    pub moments: [Moments; NM],
}

/// The accumulators one worker fills for one block of particles, in particle order.
#[derive(Clone, Debug)]
pub struct BlockTally {
    block: u64,
    sums: [ShiftedSums; NM],
    hists: Vec<Histogram>,
    /// Fig. 12 curves (deterministic): by the final `α⁺` (from 0°) and by the first `α⁺`.
    p_out: Option<RatioCurve>,
    p_first: Option<RatioCurve>,
    slices: [(f64, f64); 2],
    counters: Counters,
}

fn ratio_curves(spec: &TallySpec) -> (Option<RatioCurve>, Option<RatioCurve>) {
    match spec.model {
        ModelKind::Deterministic => (
            Some(RatioCurve::new(0.0, 90.0, spec.bin_width_deg, 0.0)),
            Some(RatioCurve::new(
                -90.0,
                90.0,
                spec.bin_width_deg,
                f64::NEG_INFINITY,
            )),
        ),
        ModelKind::Stochastic => (None, None),
    }
}

impl BlockTally {
    /// Empty accumulators for block `block` of a condition.
    pub fn new(spec: &TallySpec, block: u64) -> BlockTally {
        let (p_out, p_first) = ratio_curves(spec);
        BlockTally {
            block,
            sums: [ShiftedSums::default(); NM],
            hists: histograms(spec),
            p_out,
            p_first,
            slices: gamma_slices(spec).0,
            counters: Counters::default(),
        }
    }

    /// The block's index within its condition.
    pub fn block(&self) -> u64 {
        self.block
    }

    #[inline]
    fn angle(&mut self, i: usize, rad: f64) {
        let deg = rad.to_degrees();
        self.sums[i].push(deg);
        self.hists[i].push(deg);
    }

    /// Tallies one followed particle.
    pub fn push(&mut self, o: &Outcome) {
        self.counters.particles += 1;
        self.angle(ALPHA_OUT, o.alpha_out);
        self.angle(1, o.alpha_out_xy);
        self.angle(2, o.beta_out);
        self.angle(DBETA, o.dbeta);
        if let Some(d) = o.dbeta_first {
            self.angle(4, d);
        }
        self.angle(5, o.xi_first);
        self.angle(6, o.zeta_first);
        self.angle(7, o.gamma_first);
        self.angle(8, o.gamma_star_first);
        if let Some(a) = o.alpha_first {
            self.angle(ALPHA_FIRST, a);
        }
        let slices = self.slices;
        for (k, &(centre, half)) in slices.iter().enumerate() {
            if (o.gamma_first - centre).abs() <= half {
                self.angle(SLICE_0 + k, o.gamma_star_first);
            }
        }
        self.sums[SPEED_RATIO].push(o.speed_ratio);
        if let Some(e) = o.erosion {
            self.sums[EROSION].push(e.per_mass);
            if let Some(r) = e.rejected_per_mass {
                self.sums[EROSION_REJECTED].push(r);
            }
        }
        if let Some(c) = o.collisions {
            let k = &mut self.counters;
            k.collisions += c as u64;
            k.collisions_sq += (c as u128) * (c as u128);
            k.single += (c == 1) as u64;
            k.max_collisions = k.max_collisions.max(c);
            if let Some(p) = &mut self.p_out {
                p.push(o.alpha_out.to_degrees(), c == 1, None);
            }
            if let (Some(p), Some(a)) = (&mut self.p_first, o.alpha_first) {
                p.push(a.to_degrees(), c == 1, o.p_single_model);
            }
        }
    }

    /// Tallies the local impact angle `alpha` (rad, to the wall element hit) of one impact:
    /// one that counts (`rejected = false`) or a rejected stochastic candidate. Only with
    /// `[erosion]`; call it for followed histories only, before [`BlockTally::push`].
    #[inline]
    pub fn push_impact(&mut self, alpha: f64, rejected: bool) {
        let i = if rejected { IMPACT_REJECTED } else { IMPACT };
        if let Some(h) = self.hists.get_mut(i) {
            h.push(alpha.to_degrees());
        }
    }

    /// Counts a history that could not be followed (deterministic; `reason` indexes
    /// `deterministic::LostReason`).
    pub fn push_lost(&mut self, reason: usize) {
        self.counters.particles += 1;
        self.counters.lost[reason.min(LOST_REASONS - 1)] += 1;
    }

    /// Counts the candidate walls of one stochastic rebound (call with [`BlockTally::push`]).
    pub fn push_candidates(&mut self, tries: u32, candidates: u32, capped: bool) {
        let k = &mut self.counters;
        k.tries += tries as u64;
        k.candidates += candidates as u64;
        k.candidates_sq += (candidates as u128) * (candidates as u128);
        k.capped += capped as u64;
    }
}

/// The running tally of one condition.
#[derive(Clone, Debug)]
pub struct ConditionTally {
    /// What this condition tallies and how.
    pub spec: TallySpec,
    hists: Vec<Histogram>,
    p_out: Option<RatioCurve>,
    p_first: Option<RatioCurve>,
    /// Integer counters summed over the blocks absorbed and tallies added.
    pub counters: Counters,
    records: Vec<BlockRecord>,
    /// Moments of the records absorbed so far, folded in absorption order.
    running: [Moments; NM],
}

impl ConditionTally {
    /// An empty tally.
    pub fn new(spec: TallySpec) -> ConditionTally {
        let (p_out, p_first) = ratio_curves(&spec);
        ConditionTally {
            hists: histograms(&spec),
            spec,
            p_out,
            p_first,
            counters: Counters::default(),
            records: Vec::new(),
            running: [Moments::default(); NM],
        }
    }

    /// Adds a finished block. The engine absorbs blocks in block order, so the running
    /// moments equal [`ConditionTally::moments`].
    pub fn absorb(&mut self, b: BlockTally) {
        for (a, h) in self.hists.iter_mut().zip(&b.hists) {
            a.add(h);
        }
        if let (Some(a), Some(h)) = (&mut self.p_out, &b.p_out) {
            a.add(h);
        }
        if let (Some(a), Some(h)) = (&mut self.p_first, &b.p_first) {
            a.add(h);
        }
        self.counters.add(&b.counters);
        let record = BlockRecord {
            block: b.block,
            moments: b.sums.map(|s| s.moments()),
        };
        for (r, m) in self.running.iter_mut().zip(&record.moments) {
            r.merge(m);
        }
        self.records.push(record);
    }

    /// Adds another tally of the same condition (a shard's): integers add, block records
    /// join the list. Fails (with the clashing block) if a block is in both.
    pub fn add(&mut self, other: &ConditionTally) -> std::result::Result<(), u64> {
        for r in &other.records {
            if self.records.iter().any(|s| s.block == r.block) {
                return Err(r.block);
            }
        }
        for (a, h) in self.hists.iter_mut().zip(&other.hists) {
            a.add(h);
        }
        if let (Some(a), Some(h)) = (&mut self.p_out, &other.p_out) {
            a.add(h);
        }
        if let (Some(a), Some(h)) = (&mut self.p_first, &other.p_first) {
            a.add(h);
        }
        self.counters.add(&other.counters);
        self.records.extend_from_slice(&other.records);
        self.records.sort_by_key(|r| r.block);
        self.running = self.moments();
        Ok(())
    }

    /// Block indices absorbed, in order.
    pub fn blocks(&self) -> Vec<u64> {
        let mut b: Vec<u64> = self.records.iter().map(|r| r.block).collect();
        b.sort_unstable();
        b
    }

    /// The moments of every quantity, folded over the blocks in block order.
    pub fn moments(&self) -> [Moments; NM] {
        let mut sorted: Vec<&BlockRecord> = self.records.iter().collect();
        sorted.sort_by_key(|r| r.block);
        let mut m = [Moments::default(); NM];
        for r in sorted {
            for (a, b) in m.iter_mut().zip(&r.moments) {
                a.merge(b);
            }
        }
        m
    }

    /// Standard errors (degrees) of the running mean `α⁺` and mean `β⁺ − β⁻`, the
    /// quantities the stopping rule watches; `None` before two particles were followed.
    pub fn running_se(&self) -> Option<(f64, f64)> {
        Some((self.running[ALPHA_OUT].se()?, self.running[DBETA].se()?))
    }

    /// Histories followed so far.
    pub fn followed(&self) -> u64 {
        self.running[ALPHA_OUT].n
    }

    /// The condition's summary, PDFs and moments.
    pub fn result(&self) -> ConditionResult {
        let moments = self.moments();
        let est = |q: Quantity| -> Option<Estimate> {
            let i = MOMENT_QUANTITIES.iter().position(|&m| m == q)?;
            Estimate::of(&moments[i])
        };
        let k = &self.counters;
        let followed = moments[ALPHA_OUT].n;
        let (p_single, collisions, max_collisions, lost) = match self.spec.model {
            ModelKind::Deterministic => (
                (followed > 0).then(|| Proportion::binomial(k.single, followed)),
                Estimate::of_counts(followed, k.collisions as u128, k.collisions_sq),
                (followed > 0).then_some(k.max_collisions),
                Some(k.lost_total()),
            ),
            ModelKind::Stochastic => (
                (k.candidates > 0).then(|| {
                    Proportion::per_trials(followed, k.candidates as u128, k.candidates_sq)
                }),
                None,
                None,
                None,
            ),
        };
        let summary = Summary {
            condition: self.spec.condition,
            deviations: self.spec.deviations,
            particles: followed,
            alpha_out: est(Quantity::AlphaOut),
            dbeta: est(Quantity::Dbeta),
            dbeta_first: est(Quantity::DbetaFirst),
            gamma: est(Quantity::GammaFirst),
            gamma_star: est(Quantity::GammaStarFirst),
            p_single,
            collisions,
            max_collisions,
            speed_ratio: est(Quantity::SpeedRatio),
            lost,
            erosion: self.spec.erosion_particle_mass_kg.map(|mass| {
                let per_mass = est(Quantity::ErosionPerMass);
                ErosionSummary {
                    per_mass,
                    per_particle: per_mass.map(|e| e.scaled(mass)),
                    impacts: match self.spec.model {
                        ModelKind::Deterministic => collisions,
                        ModelKind::Stochastic => {
                            Estimate::of_counts(followed, k.candidates as u128, k.candidates_sq)
                        }
                    },
                    rejected_per_mass: est(Quantity::ErosionPerMassRejected),
                }
            }),
        };
        // Densities in the order of earlier versions of `pdfs.csv`, then the Fig. 12 curves,
        // then the quantities added since (first rebound angle, Fig. 11 slices).
        let mut pdfs: Vec<Pdf> = Vec::new();
        let density = |i: usize| {
            (self.hists[i].total() > 0)
                .then(|| Pdf::new(MOMENT_QUANTITIES[i], self.hists[i].density()))
        };
        pdfs.extend((0..ALPHA_FIRST).filter_map(density));
        if followed > 0 {
            if let Some(p) = &self.p_out {
                pdfs.push(Pdf::new(Quantity::PSingleGivenAlphaOut, p.fraction()));
            }
            if let Some(p) = &self.p_first {
                pdfs.push(Pdf::new(Quantity::PSingleGivenAlphaFirst, p.fraction()));
                pdfs.push(Pdf::new(Quantity::PSingleModel, p.model_mean()));
            }
        }
        pdfs.extend((ALPHA_FIRST..NH).filter_map(density));
        for (i, q) in [
            (IMPACT, Quantity::ImpactAngleLocal),
            (IMPACT_REJECTED, Quantity::ImpactAngleLocalRejected),
        ] {
            if let Some(h) = self.hists.get(i).filter(|h| h.total() > 0) {
                pdfs.push(Pdf::new(q, h.density()));
            }
        }
        let mut estimates: Vec<(Quantity, Estimate)> = MOMENT_QUANTITIES
            .iter()
            .zip(&moments)
            .filter_map(|(q, m)| Estimate::of(m).map(|e| (*q, e)))
            .collect();
        if let Some(c) = summary.collisions {
            estimates.push((Quantity::Collisions, c));
        }
        ConditionResult {
            summary,
            pdfs,
            estimates,
        }
    }

    /// Parts for a partial tally file.
    pub fn parts(&self) -> TallyParts<'_> {
        TallyParts {
            hists: &self.hists,
            p_out: self.p_out.as_ref(),
            p_first: self.p_first.as_ref(),
            counters: &self.counters,
            records: &self.records,
        }
    }

    /// Mutable parts, to restore a partial tally file into an empty tally.
    pub fn parts_mut(&mut self) -> TallyPartsMut<'_> {
        TallyPartsMut {
            hists: &mut self.hists,
            p_out: self.p_out.as_mut(),
            p_first: self.p_first.as_mut(),
            counters: &mut self.counters,
            records: &mut self.records,
        }
    }

    /// Recomputes the running moments after restoring records.
    pub fn refold(&mut self) {
        self.records.sort_by_key(|r| r.block);
        self.running = self.moments();
    }
}

/// The state of a [`ConditionTally`], borrowed to write a partial tally file
/// ([`ConditionTally::parts`]).
pub struct TallyParts<'a> {
    /// The histograms (degrees): the angle quantities in record order, then, with
    /// `[erosion]`, the local impact angles that count and those of rejected candidates.
    pub hists: &'a [Histogram],
    /// Fig. 12 curve by the final `α⁺` (deterministic; `None` for the stochastic model).
    pub p_out: Option<&'a RatioCurve>,
    /// Fig. 12 curve by the first rebound's `α⁺`, with the model `P(n = 1)` (deterministic;
    /// `None` for the stochastic model).
    pub p_first: Option<&'a RatioCurve>,
    /// The integer counters.
    pub counters: &'a Counters,
    /// The block records absorbed, each block's moments.
    pub records: &'a [BlockRecord],
}

/// The state of a [`ConditionTally`], borrowed mutably to restore a partial tally file into
/// an empty tally ([`ConditionTally::parts_mut`]; call [`ConditionTally::refold`] after).
pub struct TallyPartsMut<'a> {
    /// The histograms, laid out as in [`TallyParts::hists`].
    pub hists: &'a mut Vec<Histogram>,
    /// Fig. 12 curve by the final `α⁺` (deterministic; `None` for the stochastic model).
    pub p_out: Option<&'a mut RatioCurve>,
    /// Fig. 12 curve by the first rebound's `α⁺` (deterministic; `None` for the stochastic
    /// model).
    pub p_first: Option<&'a mut RatioCurve>,
    /// The integer counters.
    pub counters: &'a mut Counters,
    /// The block records.
    pub records: &'a mut Vec<BlockRecord>,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(model: ModelKind) -> TallySpec {
        TallySpec {
            condition: IncidentCondition::from_degrees(-11.5, 0.0),
            deviations: Deviations {
                delta_xi: 0.04,
                delta_zeta: 0.13,
            },
            bin_width_deg: 1.0,
            model,
            erosion_particle_mass_kg: None,
        }
    }

    fn outcome(i: u64) -> Outcome {
        let a = 0.01 + 0.5 * ((i * 7919 % 1000) as f64 / 1000.0);
        Outcome {
            alpha_out: a,
            beta_out: 0.1,
            dbeta: 0.1 - 0.2 * (i % 3) as f64,
            dbeta_first: Some(0.05),
            collisions: Some(1 + (i % 2) as u32),
            alpha_first: Some(a * 0.9),
            p_single_model: Some(0.5),
            speed_ratio: 1.0,
            ..Default::default()
        }
    }

    fn tally(spec: TallySpec, blocks: &[(u64, std::ops::Range<u64>)]) -> ConditionTally {
        let mut t = ConditionTally::new(spec);
        for (b, range) in blocks {
            let mut bt = BlockTally::new(&spec, *b);
            for i in range.clone() {
                bt.push(&outcome(i));
            }
            t.absorb(bt);
        }
        t
    }

    #[test]
    fn shards_merged_give_the_same_bits_as_one_pass() {
        let s = spec(ModelKind::Deterministic);
        let all = tally(s, &[(0, 0..300), (1, 300..600), (2, 600..1000)]);
        let odd = tally(s, &[(1, 300..600)]);
        let mut even = tally(s, &[(0, 0..300), (2, 600..1000)]);
        even.add(&odd).unwrap();
        assert_eq!(even.result(), all.result());
        assert_eq!(even.blocks(), vec![0, 1, 2]);
        assert_eq!(even.add(&odd), Err(1));
    }

    #[test]
    fn deterministic_summary_has_counts_and_standard_errors() {
        let t = tally(spec(ModelKind::Deterministic), &[(0, 0..1000)]);
        let r = t.result();
        let s = &r.summary;
        assert_eq!(s.particles, 1000);
        let p = s.p_single.unwrap();
        assert_eq!(p.value, 0.5);
        assert!((p.se.unwrap() - (0.25f64 / 1000.0).sqrt()).abs() < 1e-15);
        let c = s.collisions.unwrap();
        assert_eq!(c.mean, 1.5);
        assert!((c.std.unwrap() - (250.0f64 / 999.0).sqrt()).abs() < 1e-12);
        assert_eq!(s.max_collisions, Some(2));
        assert_eq!(s.lost, Some(0));
        let a = s.alpha_out.unwrap();
        assert!((a.se.unwrap() - a.std.unwrap() / 1000f64.sqrt()).abs() < 1e-15);
        for pdf in r.pdfs.iter().filter(|p| p.quantity.is_density()) {
            let integral: f64 = pdf.bins.iter().map(|b| b.value * (b.hi - b.lo)).sum();
            assert!((integral - 1.0).abs() < 1e-12, "{:?}", pdf.quantity);
        }
        assert!(r.pdf(Quantity::PSingleModel).is_some());
        assert!(r.pdf(Quantity::AlphaFirst).is_some());
    }

    #[test]
    fn stochastic_p_single_is_accepted_over_candidates() {
        let s = spec(ModelKind::Stochastic);
        let mut b = BlockTally::new(&s, 0);
        for i in 0..100 {
            let mut o = outcome(i);
            o.dbeta_first = None;
            o.collisions = None;
            o.alpha_first = None;
            b.push(&o);
            b.push_candidates(2, 1 + (i % 2) as u32, false);
        }
        let mut t = ConditionTally::new(s);
        t.absorb(b);
        let r = t.result();
        let p = r.summary.p_single.unwrap();
        assert!((p.value - 100.0 / 150.0).abs() < 1e-15);
        // Delta method: p² sd(c)/√n with sd(c) of 50 ones and 50 twos.
        let sd = (25.0f64 / 99.0).sqrt();
        assert!((p.se.unwrap() - p.value * p.value * sd / 10.0).abs() < 1e-15);
        assert_eq!(r.summary.lost, None);
        assert!(r.summary.collisions.is_none() && r.summary.dbeta_first.is_none());
        assert!(r.pdf(Quantity::PSingleGivenAlphaOut).is_none());
        assert_eq!(t.counters.tries, 200);
    }
}
