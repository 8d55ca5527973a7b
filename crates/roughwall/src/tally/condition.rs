//! The tally of one incident condition: block accumulators that a worker fills in
//! particle order, and the condition's running total that absorbs blocks.
//!
//! Integer parts (histogram counts, collision and candidate counts) are plain sums, exact
//! in any order. Floating-point parts (means and spreads) are kept per block as
//! [`Moments`] and folded in block order ([`ConditionTally::moments`]), so a run split
//! over threads, shards or machines gives the same bits as one process.

use super::histogram::{Histogram, RatioCurve};
use super::moments::{ensemble_se, Moments, ShiftedSums};
use super::quantity::Quantity;
use super::results::{ConditionResult, ErosionSummary, Estimate, Pdf, Proportion, Summary};
use crate::incidence::IncidentCondition;
use crate::wall::{conditional_gamma_star, rotated_moments, Deviations};

/// Particles per block: the unit of work, of reproducibility and of the stopping rule
/// (block `b` of a condition holds its particles `b · BLOCK_SIZE` onwards).
pub const BLOCK_SIZE: u64 = 1 << 16;

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
pub const LOST_REASONS: usize = 5;

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
    /// Surface realisations the histories are spread over (`[deterministic] surfaces`;
    /// history `i` on realisation `realisation_of``(i, N)`): 1 for one surface and for the
    /// stochastic model. With more than one, the standard error of every mean includes the
    /// spread between realisations (`ensemble_se`).
    pub realisations: u32,
}

impl TallySpec {
    /// The same tally over `n` surface realisations (0 is taken as 1).
    pub fn with_realisations(self, n: u32) -> TallySpec {
        TallySpec {
            realisations: n.max(1),
            ..self
        }
    }

    /// Whether means are tallied per realisation too (more than one).
    fn clustered(&self) -> bool {
        self.realisations > 1
    }
}

/// The realisation history `history` of a condition bounces on, of `realisations`:
/// `history mod N`. Depends on the history alone, so every block samples every realisation
/// and a run is the same for any thread count or shard split.
#[inline]
pub fn realisation_of(history: u64, realisations: u32) -> usize {
    (history % realisations.max(1) as u64) as usize
}

/// The integer tallies of one surface realisation, for the ensemble standard errors of
/// `p_single` and the mean collision count (deterministic, more than one realisation).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RealisationCounts {
    /// Histories followed on this realisation.
    pub followed: u64,
    /// Of them, histories with exactly one collision.
    pub single: u64,
    /// Σ collisions over them.
    pub collisions: u64,
}

impl RealisationCounts {
    fn add(&mut self, o: &RealisationCounts) {
        self.followed += o.followed;
        self.single += o.single;
        self.collisions += o.collisions;
    }
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
#[derive(Clone, Debug, PartialEq)]
pub struct BlockRecord {
    /// The block's index within its condition (particles `block · BLOCK_SIZE` onwards).
    pub block: u64,
    /// The block's moments of each quantity in record order (angles in degrees), [`NM`] of
    /// them.
    pub moments: [Moments; NM],
    /// The same per surface realisation, in realisation order (empty on one surface).
    pub by_realisation: Vec<[Moments; NM]>,
}

/// The accumulators one worker fills for one block of particles, in particle order.
#[derive(Clone, Debug)]
pub struct BlockTally {
    block: u64,
    sums: [ShiftedSums; NM],
    /// Per realisation (empty on one surface): the sums of each quantity, and counts.
    by_realisation: Vec<[ShiftedSums; NM]>,
    realisation_counts: Vec<RealisationCounts>,
    realisations: u32,
    /// The index of the next history pushed: histories arrive in order from the block's
    /// first, `block · BLOCK_SIZE`, followed or lost.
    next_history: u64,
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
        let per = if spec.clustered() {
            spec.realisations as usize
        } else {
            0
        };
        BlockTally {
            block,
            sums: [ShiftedSums::default(); NM],
            by_realisation: vec![[ShiftedSums::default(); NM]; per],
            realisation_counts: vec![RealisationCounts::default(); per],
            realisations: spec.realisations,
            next_history: block * BLOCK_SIZE,
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

    /// The realisation of the next history, `None` on one surface; advances to the next.
    #[inline]
    fn next_realisation(&mut self) -> Option<usize> {
        let i = self.next_history;
        self.next_history += 1;
        (!self.by_realisation.is_empty()).then(|| realisation_of(i, self.realisations))
    }

    #[inline]
    fn value(&mut self, r: Option<usize>, i: usize, x: f64) {
        self.sums[i].push(x);
        if let Some(r) = r {
            self.by_realisation[r][i].push(x);
        }
    }

    #[inline]
    fn angle(&mut self, r: Option<usize>, i: usize, rad: f64) {
        let deg = rad.to_degrees();
        self.value(r, i, deg);
        self.hists[i].push(deg);
    }

    /// Tallies one followed particle.
    pub fn push(&mut self, o: &Outcome) {
        let r = self.next_realisation();
        self.counters.particles += 1;
        self.angle(r, ALPHA_OUT, o.alpha_out);
        self.angle(r, 1, o.alpha_out_xy);
        self.angle(r, 2, o.beta_out);
        self.angle(r, DBETA, o.dbeta);
        if let Some(d) = o.dbeta_first {
            self.angle(r, 4, d);
        }
        self.angle(r, 5, o.xi_first);
        self.angle(r, 6, o.zeta_first);
        self.angle(r, 7, o.gamma_first);
        self.angle(r, 8, o.gamma_star_first);
        if let Some(a) = o.alpha_first {
            self.angle(r, ALPHA_FIRST, a);
        }
        let slices = self.slices;
        for (k, &(centre, half)) in slices.iter().enumerate() {
            if (o.gamma_first - centre).abs() <= half {
                self.angle(r, SLICE_0 + k, o.gamma_star_first);
            }
        }
        self.value(r, SPEED_RATIO, o.speed_ratio);
        if let Some(e) = o.erosion {
            self.value(r, EROSION, e.per_mass);
            if let Some(x) = e.rejected_per_mass {
                self.value(r, EROSION_REJECTED, x);
            }
        }
        if let Some(c) = o.collisions {
            if let Some(r) = r {
                let rc = &mut self.realisation_counts[r];
                rc.followed += 1;
                rc.single += (c == 1) as u64;
                rc.collisions += c as u64;
            }
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
        self.next_realisation();
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
    /// Integer tallies per realisation (empty on one surface), summed.
    realisation_counts: Vec<RealisationCounts>,
    /// Moments of the records absorbed so far, folded in absorption order.
    running: [Moments; NM],
    /// The same per realisation (empty on one surface).
    running_by_realisation: Vec<[Moments; NM]>,
}

impl ConditionTally {
    /// An empty tally.
    pub fn new(spec: TallySpec) -> ConditionTally {
        let (p_out, p_first) = ratio_curves(&spec);
        let per = if spec.clustered() {
            spec.realisations as usize
        } else {
            0
        };
        ConditionTally {
            hists: histograms(&spec),
            spec,
            p_out,
            p_first,
            counters: Counters::default(),
            records: Vec::new(),
            realisation_counts: vec![RealisationCounts::default(); per],
            running: [Moments::default(); NM],
            running_by_realisation: vec![[Moments::default(); NM]; per],
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
        for (a, c) in self
            .realisation_counts
            .iter_mut()
            .zip(&b.realisation_counts)
        {
            a.add(c);
        }
        let record = BlockRecord {
            block: b.block,
            moments: b.sums.map(|s| s.moments()),
            by_realisation: b
                .by_realisation
                .iter()
                .map(|sums| sums.map(|s| s.moments()))
                .collect(),
        };
        fold(&mut self.running, &record.moments);
        for (run, m) in self
            .running_by_realisation
            .iter_mut()
            .zip(&record.by_realisation)
        {
            fold(run, m);
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
        for (a, c) in self
            .realisation_counts
            .iter_mut()
            .zip(&other.realisation_counts)
        {
            a.add(c);
        }
        self.records.extend_from_slice(&other.records);
        self.refold();
        Ok(())
    }

    /// Block indices absorbed, in order.
    pub fn blocks(&self) -> Vec<u64> {
        let mut b: Vec<u64> = self.records.iter().map(|r| r.block).collect();
        b.sort_unstable();
        b
    }

    fn sorted_records(&self) -> Vec<&BlockRecord> {
        let mut sorted: Vec<&BlockRecord> = self.records.iter().collect();
        sorted.sort_by_key(|r| r.block);
        sorted
    }

    /// The moments of every quantity, folded over the blocks in block order.
    pub fn moments(&self) -> [Moments; NM] {
        let mut m = [Moments::default(); NM];
        for r in self.sorted_records() {
            fold(&mut m, &r.moments);
        }
        m
    }

    /// The moments of every quantity on each surface realisation, folded over the blocks
    /// in block order (empty on one surface).
    pub fn moments_by_realisation(&self) -> Vec<[Moments; NM]> {
        let mut m = vec![[Moments::default(); NM]; self.running_by_realisation.len()];
        for r in self.sorted_records() {
            for (a, b) in m.iter_mut().zip(&r.by_realisation) {
                fold(a, b);
            }
        }
        m
    }

    /// Standard errors (degrees) of the running mean `α⁺` and mean `β⁺ − β⁻`, the
    /// quantities the stopping rule watches, with the spread between surface realisations
    /// (`ensemble_se`); `None` before two particles were followed.
    pub fn running_se(&self) -> Option<(f64, f64)> {
        let se = |i: usize| quantity_se(&self.running, &self.running_by_realisation, i);
        Some((se(ALPHA_OUT)?, se(DBETA)?))
    }

    /// Histories followed so far.
    pub fn followed(&self) -> u64 {
        self.running[ALPHA_OUT].n
    }

    /// The condition's summary, PDFs and moments.
    pub fn result(&self) -> ConditionResult {
        let moments = self.moments();
        let by_realisation = self.moments_by_realisation();
        let estimate = |i: usize| -> Option<Estimate> {
            Some(Estimate::of(&moments[i])?.with_se(quantity_se(&moments, &by_realisation, i)))
        };
        let est = |q: Quantity| -> Option<Estimate> {
            estimate(MOMENT_QUANTITIES.iter().position(|&m| m == q)?)
        };
        let k = &self.counters;
        let followed = moments[ALPHA_OUT].n;
        // The integer tallies' ensemble errors: each realisation's fraction or mean count.
        let counts_se = |value: f64, se: Option<f64>, of: fn(&RealisationCounts) -> u64| {
            ensemble_se(
                followed,
                value,
                se,
                self.realisation_counts
                    .iter()
                    .map(|c| (c.followed, of(c) as f64 / c.followed.max(1) as f64)),
            )
        };
        let (p_single, collisions, max_collisions, lost) = match self.spec.model {
            ModelKind::Deterministic => (
                (followed > 0).then(|| {
                    let p = Proportion::binomial(k.single, followed);
                    Proportion {
                        se: counts_se(p.value, p.se, |c| c.single),
                        ..p
                    }
                }),
                Estimate::of_counts(followed, k.collisions as u128, k.collisions_sq)
                    .map(|e| e.with_se(counts_se(e.mean, e.se, |c| c.collisions))),
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
            .enumerate()
            .filter_map(|(i, q)| estimate(i).map(|e| (*q, e)))
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
            realisation_counts: &self.realisation_counts,
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
            realisation_counts: &mut self.realisation_counts,
        }
    }

    /// Recomputes the running moments after restoring records.
    pub fn refold(&mut self) {
        self.records.sort_by_key(|r| r.block);
        self.running = self.moments();
        self.running_by_realisation = self.moments_by_realisation();
    }
}

/// Folds one block's moments into running moments (Chan et al. 1979, Eq. 2.1b).
fn fold(running: &mut [Moments; NM], block: &[Moments; NM]) {
    for (a, b) in running.iter_mut().zip(block) {
        a.merge(b);
    }
}

/// The standard error of the mean of quantity `i`: the histories' own, or with more than
/// one realisation the ensemble error ([`ensemble_se`]).
fn quantity_se(total: &[Moments; NM], by_realisation: &[[Moments; NM]], i: usize) -> Option<f64> {
    let m = &total[i];
    ensemble_se(
        m.n,
        m.mean,
        m.se(),
        by_realisation.iter().map(|r| (r[i].n, r[i].mean)),
    )
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
    /// The integer tallies per realisation (empty on one surface).
    pub realisation_counts: &'a [RealisationCounts],
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
    /// The integer tallies per realisation, one per realisation of the spec (empty on one
    /// surface).
    pub realisation_counts: &'a mut Vec<RealisationCounts>,
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
            realisations: 1,
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

    /// Two realisations whose histories differ (even histories: α⁺ of `outcome`, odd ones
    /// 10° more, and one collision more): every mean's standard error is the spread of the
    /// two realisation means, the stopping rule watches the same error, and shards still
    /// merge to the same bits.
    #[test]
    fn realisations_that_differ_widen_every_standard_error() {
        let s = spec(ModelKind::Deterministic).with_realisations(2);
        let shifted = |i: u64| {
            let mut o = outcome(i);
            if i % 2 == 1 {
                o.alpha_out += 10f64.to_radians();
                o.collisions = o.collisions.map(|c| c + 1);
            }
            o
        };
        let run = |blocks: &[u64]| {
            let mut t = ConditionTally::new(s);
            for &b in blocks {
                let mut bt = BlockTally::new(&s, b);
                let first = b * BLOCK_SIZE;
                for i in first..first + 1000 {
                    if i % 97 == 0 {
                        bt.push_lost(0);
                    } else {
                        bt.push(&shifted(i));
                    }
                }
                t.absorb(bt);
            }
            t
        };
        let all = run(&[0, 1]);
        let r = all.result();
        let a = r.summary.alpha_out.unwrap();
        // Two realisations 10° apart with equal shares: G/(G−1) Σ (1/2)² (±5°)² = 25 deg².
        assert!((a.se.unwrap() - 5.0).abs() < 0.1, "{a:?}");
        assert!(a.se_histories.unwrap() < 0.25, "{a:?}");
        assert_eq!(all.running_se().unwrap().0, a.se.unwrap());
        let c = r.summary.collisions.unwrap();
        assert!(c.se.unwrap() > 0.45 && c.se.unwrap() > 5.0 * c.se_histories.unwrap());
        // A quantity the realisations share keeps (about) its own error.
        let g = r.summary.gamma.unwrap();
        assert_eq!(g.se, g.se_histories);
        let mut odd = run(&[1]);
        odd.add(&run(&[0])).unwrap();
        assert_eq!(odd.result(), r);
        // One realisation: the error of independent values, as before.
        let one = tally(spec(ModelKind::Deterministic), &[(0, 0..1000)]).result();
        let e = one.summary.alpha_out.unwrap();
        assert_eq!(e.se, e.se_histories);
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
