//! `rebound deterministic`: particle-centre bouncing on a generated anisotropic
//! rough wall (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5 and 4; docs/physics.md §5).
pub(crate) mod in_place;
pub(crate) mod patch;
pub(crate) mod scene;
pub(crate) mod trace;

pub use in_place::{in_place_wall, InPlaceWall, ScanReference};
pub use patch::{Margins, Patch, LEFT_PATCH_BOUND, MARGIN_FLIGHTS, MAX_MARGIN_SHARE};
pub use scene::{
    build_surfaces, choose_surface, generate_surface, realisation_seed, realisations,
    surface_from_field, BuiltSurface, SceneOptions, SphereDilation, SurfacePlan, WallDeviations,
};
pub use trace::{Fate, History, HitInfo, LostReason, Tracker, DEFAULT_MAX_COLLISIONS};

use crate::angles::{
    alpha_xy_of_velocity, gamma_from_normal, incident_angles, wrap_pi, xi_zeta_of_normal,
};
use crate::collision::CollisionLaw;
use crate::erosion::ErosionSetup;
use crate::incidence::{draw_speed, IncidentCondition, SpeedLaw, SpinLaw};
use crate::rng;
use crate::tally::{
    condition::realisation_of, Bin, BlockTally, ConditionResult, ConditionTally, ErosionOutcome,
    ModelKind, Outcome, Quantity, TallySpec, BLOCK_SIZE,
};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;
use rayon::prelude::*;

/// Everything a deterministic run needs besides the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelSetup {
    /// The collision law applied at every triangle hit, in that triangle's frame (ideal elastic or
    /// Sommerfeld–Huber; Radenkovic & Simonin 2021, Eqs. 36–42, docs/physics.md §2).
    pub law: CollisionLaw,
    /// Sphere diameter (m), for the spin terms of Sommerfeld–Huber.
    pub diameter_m: f64,
    /// The law of the incident speed (m/s): horizontal speed or `|U⁻|`, drawn per history.
    pub speed: SpeedLaw,
    /// The deviations the wall is meant to have: labels the outputs and gives `Δγ(β⁺)` of
    /// the Fig. 12 model curve.
    pub wall: Deviations,
    /// ψ of Eq. (34), for the Fig. 12 model curve.
    pub psi: f64,
    /// The erosion law, when the case tallies erosion.
    pub erosion: Option<ErosionSetup>,
    /// Incident spin (default zero).
    pub spin: SpinLaw,
}

/// The surface realisations a run bounces on (`[deterministic] surfaces`): history `i` of
/// every condition on realisation `i mod N`. The assignment depends on the history alone, so
/// a run is the same for any thread count, shard split or target standard error, and every
/// block samples every realisation. One realisation is the run on a single surface.
pub struct Realisations<'a> {
    trackers: Vec<Tracker<'a>>,
}

impl<'a> Realisations<'a> {
    /// At least one tracker; they must share the periods the histories start over.
    pub fn new(trackers: Vec<Tracker<'a>>) -> crate::error::Result<Self> {
        let Some(first) = trackers.first() else {
            return Err(crate::error::Error::Internal(
                "no surface realisation".into(),
            ));
        };
        let periods = first.periods();
        if trackers.iter().any(|t| t.periods() != periods) {
            return Err(crate::error::Error::Internal(
                "surface realisations of different periods".into(),
            ));
        }
        Ok(Realisations { trackers })
    }

    /// The realisation history `i` bounces on.
    #[inline]
    pub fn for_history(&self, i: u64) -> &Tracker<'a> {
        &self.trackers[realisation_of(i, self.trackers.len() as u32)]
    }

    /// How many realisations.
    pub fn len(&self) -> usize {
        self.trackers.len()
    }

    /// Never true ([`Realisations::new`] refuses none).
    pub fn is_empty(&self) -> bool {
        self.trackers.is_empty()
    }
}

impl<'a> From<Tracker<'a>> for Realisations<'a> {
    fn from(t: Tracker<'a>) -> Self {
        Realisations { trackers: vec![t] }
    }
}

/// History `i` of condition `cond` (index `cond_index` in the case): its start `(x, z)`
/// (uniform over the period) and horizontal speed come from its own stream
/// `rng::stream(seed, &[DETERMINISTIC, cond_index, i])`, so it does not depend on the
/// thread or shard that runs it. Incident spin is zero (Radenkovic & Simonin 2021, Sec. 4).
pub fn history(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cond: &IncidentCondition,
    cond_index: u64,
    i: u64,
    seed: u64,
) -> History {
    history_at(tracker, setup, cond, &stream_prefix(seed, cond_index), i)
}

/// The part of a history's stream key shared by a condition: `(seed, DETERMINISTIC, k)`.
pub(crate) fn stream_prefix(seed: u64, cond_index: u64) -> rng::StreamPrefix {
    rng::StreamPrefix::new(seed, &[rng::domain::DETERMINISTIC, cond_index])
}

#[inline]
fn history_at(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cond: &IncidentCondition,
    prefix: &rng::StreamPrefix,
    i: u64,
) -> History {
    history_observed(tracker, setup, cond, prefix, i, |_| {})
}

/// [`history_at`] reporting every collision to `observe`.
#[inline]
pub(crate) fn history_observed(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cond: &IncidentCondition,
    prefix: &rng::StreamPrefix,
    i: u64,
    observe: impl FnMut(&HitInfo),
) -> History {
    let mut r = prefix.stream(i);
    // The same draws, in the same order, on a periodic wall and on a patch.
    let (mut a, mut b) = (r.gen::<f64>(), r.gen::<f64>());
    if tracker.patch().is_some() {
        (a, b) = in_sub_patch(i, (a, b));
    }
    history_entered(tracker, setup, cond, (a, b), &mut r, observe)
}

/// Sub-patches of a measured patch's entry region, per side: a scan is one realisation, and
/// the spread between its parts is what its reference's standard error must include (issue
/// 39, part 3), as that between surfaces does for `surfaces = N`. The lay's uncertainty is
/// measured on as many ([`crate::scan::PATCHES_PER_SIDE`]).
pub const SUB_PATCHES_PER_SIDE: u64 = crate::scan::PATCHES_PER_SIDE as u64;

/// The clusters of an in-place run: its sub-patches ([`SUB_PATCHES_PER_SIDE`]²), taken as the
/// tally's realisations ([`crate::tally::realisation_of`]: history `i` in sub-patch `i mod 16`).
pub const SUB_PATCHES: u32 = (SUB_PATCHES_PER_SIDE * SUB_PATCHES_PER_SIDE) as u32;

/// History `i`'s uniform entry numbers `(a, b)` moved into its sub-patch `i mod 16` of the
/// entry region (row-major along `a`): uniform over that sub-patch, and the 16 together
/// uniform over the region.
#[inline]
fn in_sub_patch(i: u64, (a, b): (f64, f64)) -> (f64, f64) {
    let k = i % SUB_PATCHES as u64;
    let side = SUB_PATCHES_PER_SIDE as f64;
    let (kx, kz) = (
        (k % SUB_PATCHES_PER_SIDE) as f64,
        (k / SUB_PATCHES_PER_SIDE) as f64,
    );
    ((kx + a) / side, (kz + b) / side)
}

/// The history that enters at the uniform numbers `(a, b)` in `[0, 1)²` (over the period of
/// a periodic wall, over the inner region of a patch), drawing its speed and spin from `r`.
#[inline]
pub(crate) fn history_entered<R: Rng + ?Sized>(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cond: &IncidentCondition,
    (a, b): (f64, f64),
    r: &mut R,
    observe: impl FnMut(&HitInfo),
) -> History {
    Entry::draw(tracker, setup, cond, r).history(tracker, setup, (a, b), observe)
}

/// What a history takes from its condition before it enters: its incident velocity and spin
/// (in the walk's axes) and, on a patch, the entry region's margins. A history draws its own
/// ([`history_entered`]); the histories of a condition whose speed and spin have no spread
/// share one (a measured-wall table's build), which saves their trigonometry.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Entry {
    u: Vector3<f64>,
    w: Vector3<f64>,
    margins: Option<Margins>,
}

impl Entry {
    /// The entry of condition `cond`, its speed and spin drawn from `r` (nothing is drawn
    /// for a law without spread).
    #[inline]
    pub(crate) fn draw<R: Rng + ?Sized>(
        tracker: &Tracker<'_>,
        setup: &ModelSetup,
        cond: &IncidentCondition,
        r: &mut R,
    ) -> Entry {
        let mut r = r;
        let u_h = draw_speed(&setup.speed, &mut r);
        let u = setup.speed.velocity(cond.alpha_in, cond.beta_in, u_h);
        let w = setup.spin.draw(&mut r);
        match tracker.patch() {
            None => Entry {
                u,
                w,
                margins: None,
            },
            Some(patch) => {
                // On a measured patch the incident direction is turned by the lay, not the wall.
                let (u, w) = (patch.to_field(&u), patch.to_field(&w));
                Entry {
                    u,
                    w,
                    margins: Some(patch.margins(cond.alpha_in, &u)),
                }
            }
        }
    }

    /// Where the uniform numbers `(a, b)` enter, in the walk's axes.
    #[inline]
    pub(crate) fn start(&self, tracker: &Tracker<'_>, (a, b): (f64, f64)) -> (f64, f64) {
        match (tracker.patch(), &self.margins) {
            (Some(patch), Some(m)) => patch.start_in(m, a, b),
            _ => {
                let (lx, lz) = tracker.periods();
                (a * lx, b * lz)
            }
        }
    }

    /// The incident velocity in the walk's axes.
    pub(crate) fn velocity(&self) -> Vector3<f64> {
        self.u
    }

    /// The history that enters at `(a, b)`.
    #[inline]
    pub(crate) fn history(
        &self,
        tracker: &Tracker<'_>,
        setup: &ModelSetup,
        (a, b): (f64, f64),
        observe: impl FnMut(&HitInfo),
    ) -> History {
        let collide = |u, w, n| setup.law.collide(u, w, n, setup.diameter_m);
        let (x, z) = self.start(tracker, (a, b));
        let Some(patch) = tracker.patch() else {
            return tracker.trace_observed(x, z, self.u, self.w, collide, observe);
        };
        let mut observe = observe;
        let h = tracker.trace_observed(x, z, self.u, self.w, collide, |hit| {
            observe(&hit.to_models(patch))
        });
        h.to_models(patch)
    }
}

/// The tallied record of a followed history (`None` for a lost one).
///
/// `xi_first`, `zeta_first` are `ξ − 90°`, `ζ − 90°` of the first normal seen,
/// `γ`, `γ*` from Radenkovic & Simonin 2021, Eqs. (20)–(21) (docs/physics.md §2) with the
/// incident `β⁻`; the deviations are wrapped into (−180°, 180°]. The first rebound's
/// `α⁺` and the model `P(n = 1)` of Eq. (34) at its `(α⁺, β⁺)` feed Fig. 12.
pub fn outcome(h: &History, beta_in: f64, wall: &Deviations, psi: f64) -> Option<Outcome> {
    if h.fate != Fate::Escaped {
        return None;
    }
    let (alpha_out, beta_out) = incident_angles(&h.velocity);
    let (alpha_first, beta_first) = incident_angles(&h.first_velocity);
    let (xi, zeta) = xi_zeta_of_normal(&h.first_normal);
    let (gamma, gamma_star) = gamma_from_normal(&h.first_normal, beta_in);
    let s_in = h.incident.norm();
    Some(Outcome {
        alpha_out,
        beta_out,
        alpha_out_xy: alpha_xy_of_velocity(&h.velocity),
        dbeta: wrap_pi(beta_out - beta_in),
        dbeta_first: Some(wrap_pi(beta_first - beta_in)),
        xi_first: xi,
        zeta_first: zeta,
        gamma_first: gamma,
        gamma_star_first: gamma_star,
        collisions: Some(h.collisions),
        alpha_first: Some(alpha_first),
        p_single_model: Some(p_single_model(wall, psi, alpha_first, beta_first)),
        speed_ratio: if s_in > 0.0 {
            h.velocity.norm() / s_in
        } else {
            1.0
        },
        erosion: None,
    })
}

/// Histories traced in parallel before they are tallied in order (bounded memory).
const CHUNK: u64 = 4096;

/// Tallies histories `start..end` of a condition into `block`, in particle order.
///
/// Histories are traced in parallel in chunks of `CHUNK` (4096) and tallied in particle order, so
/// that a run with fewer blocks than threads (a few thousand particles) still uses every
/// thread, and the tally is the same for any thread count.
pub fn fill_block(
    surfaces: &Realisations<'_>,
    setup: &ModelSetup,
    cond: &IncidentCondition,
    cond_index: u64,
    seed: u64,
    (start, end): (u64, u64),
    block: &mut BlockTally,
) {
    let prefix = stream_prefix(seed, cond_index);
    if let Some(erosion) = &setup.erosion {
        return fill_block_eroding(surfaces, setup, erosion, cond, &prefix, (start, end), block);
    }
    let mut lo = start;
    while lo < end {
        let hi = (lo + CHUNK).min(end);
        let fates: Vec<Result<Outcome, LostReason>> = (lo..hi)
            .into_par_iter()
            .map(|i| {
                let h = history_at(surfaces.for_history(i), setup, cond, &prefix, i);
                match h.fate {
                    Fate::Lost(r) => Err(r),
                    Fate::Escaped => {
                        outcome(&h, cond.beta_in, &setup.wall, setup.psi).ok_or(LostReason::Stopped)
                    }
                }
            })
            .collect();
        for f in &fates {
            match f {
                Ok(o) => block.push(o),
                Err(r) => block.push_lost(*r as usize),
            }
        }
        lo = hi;
    }
}

/// The histories of a chunk traced by one task of [`fill_block_eroding`], in particle order:
/// each history's fate, and the local impact angles of all of them in one buffer.
#[derive(Default)]
struct ErodedChunk {
    fates: Vec<Result<Outcome, LostReason>>,
    /// End of each history's impact angles in `angles`.
    ends: Vec<usize>,
    angles: Vec<f64>,
}

/// [`fill_block`] with erosion: every collision of a history adds the volume its local
/// impact removes (at the collision's own angle to the facet hit and speed), and its local
/// impact angle to the `impact_angle_local` PDF (for followed histories only).
fn fill_block_eroding(
    surfaces: &Realisations<'_>,
    setup: &ModelSetup,
    erosion: &ErosionSetup,
    cond: &IncidentCondition,
    prefix: &rng::StreamPrefix,
    (start, end): (u64, u64),
    block: &mut BlockTally,
) {
    let mut lo = start;
    while lo < end {
        let hi = (lo + CHUNK).min(end);
        // Folds keep contiguous runs of particles in order, one buffer per task rather
        // than one allocation per history.
        let parts: Vec<ErodedChunk> = (lo..hi)
            .into_par_iter()
            .fold(ErodedChunk::default, |mut part, i| {
                let mut per_mass = 0.0;
                let angles = &mut part.angles;
                let tracker = surfaces.for_history(i);
                let h = history_observed(tracker, setup, cond, prefix, i, |hit| {
                    let (a, v) = erosion.impact(&hit.u_in, hit.u_in.norm(), &hit.normal);
                    per_mass += v;
                    angles.push(a.alpha);
                });
                part.ends.push(part.angles.len());
                part.fates.push(match h.fate {
                    Fate::Lost(r) => Err(r),
                    Fate::Escaped => outcome(&h, cond.beta_in, &setup.wall, setup.psi)
                        .map(|o| Outcome {
                            erosion: Some(ErosionOutcome {
                                per_mass,
                                rejected_per_mass: None,
                            }),
                            ..o
                        })
                        .ok_or(LostReason::Stopped),
                });
                part
            })
            .collect();
        for part in &parts {
            let mut from = 0;
            for (f, &to) in part.fates.iter().zip(&part.ends) {
                match f {
                    Ok(o) => {
                        for &a in &part.angles[from..to] {
                            block.push_impact(a, false);
                        }
                        block.push(o);
                    }
                    Err(r) => block.push_lost(*r as usize),
                }
                from = to;
            }
        }
        lo = hi;
    }
}

/// The tally specification of a condition of this model, on one surface (more:
/// [`TallySpec::with_realisations`]).
pub fn tally_spec(
    wall: &Deviations,
    cond: IncidentCondition,
    bin_width_deg: f64,
    erosion: Option<&ErosionSetup>,
) -> TallySpec {
    TallySpec {
        condition: cond,
        deviations: *wall,
        bin_width_deg,
        model: ModelKind::Deterministic,
        erosion_particle_mass_kg: erosion.map(|e| e.particle_mass_kg),
        realisations: 1,
    }
}

/// Counts of lost histories by reason.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LostCounts {
    /// Histories that hit the cap on collisions per particle ([`LostReason::CollisionCap`]).
    pub collision_cap: u64,
    /// Histories whose centre was found below the lowest node, a leak through the surface
    /// ([`LostReason::BelowSurface`]).
    pub below_surface: u64,
    /// Histories whose cell walk exceeded its step budget, a near-horizontal flight
    /// ([`LostReason::StepBudget`]).
    pub step_budget: u64,
    /// Histories for which the collision law returned a zero or non-finite velocity
    /// ([`LostReason::Stopped`]).
    pub stopped: u64,
    /// Histories whose flight left a measured patch ([`LostReason::LeftPatch`]).
    pub left_patch: u64,
}

impl LostCounts {
    /// From the tally's counts, indexed by `LostReason as usize`.
    pub fn from_tally(lost: &[u64; crate::tally::condition::LOST_REASONS]) -> LostCounts {
        LostCounts {
            collision_cap: lost[LostReason::CollisionCap as usize],
            below_surface: lost[LostReason::BelowSurface as usize],
            step_budget: lost[LostReason::StepBudget as usize],
            stopped: lost[LostReason::Stopped as usize],
            left_patch: lost[LostReason::LeftPatch as usize],
        }
    }

    /// All lost histories, whatever the reason.
    pub fn total(&self) -> u64 {
        self.collision_cap + self.below_surface + self.step_budget + self.stopped + self.left_patch
    }

    fn add(&mut self, r: LostReason) {
        match r {
            LostReason::CollisionCap => self.collision_cap += 1,
            LostReason::BelowSurface => self.below_surface += 1,
            LostReason::StepBudget => self.step_budget += 1,
            LostReason::Stopped => self.stopped += 1,
            LostReason::LeftPatch => self.left_patch += 1,
        }
    }

    /// `"N hit the cap …, M …"` for warnings; empty when nothing was lost.
    pub fn describe(&self) -> String {
        [
            (self.collision_cap, LostReason::CollisionCap),
            (self.below_surface, LostReason::BelowSurface),
            (self.step_budget, LostReason::StepBudget),
            (self.stopped, LostReason::Stopped),
            (self.left_patch, LostReason::LeftPatch),
        ]
        .iter()
        .filter(|(n, _)| *n > 0)
        .map(|(n, r)| format!("{n} {}", r.describe()))
        .collect::<Vec<_>>()
        .join(", ")
    }
}

/// Every history of one condition, kept in memory: for tests and small studies that look
/// at single histories. Runs of any size go through `tally::engine` instead.
#[derive(Clone, Debug)]
pub struct ConditionRun {
    /// The incident condition `(α⁻, β⁻)` the histories were shot at.
    pub condition: IncidentCondition,
    /// The run's parameters (collision law, diameter, speed law, wall, `ψ`, erosion, spin).
    pub setup: ModelSetup,
    /// Outcomes of the followed histories, in particle order.
    pub outcomes: Vec<Outcome>,
    /// The fate of every history, in particle order.
    fates: Vec<Fate>,
    /// Lost histories by reason (they have no entry in [`outcomes`](Self::outcomes)).
    pub lost: LostCounts,
}

/// Radenkovic & Simonin 2021, Eq. (34) with Δγ(β⁺) of Eq. (35), at rebound angles
/// `(α⁺, β⁺)`: the stochastic model's own implementation, so both models use one formula.
pub fn p_single_model(dev: &Deviations, psi: f64, alpha_out: f64, beta_out: f64) -> f64 {
    let u = crate::angles::velocity_from_angles(1.0, alpha_out, beta_out);
    crate::stochastic::single_collision_probability(&u, alpha_out, dev, psi)
}

/// Runs `count` histories of one condition in parallel and keeps them all (see
/// [`ConditionRun`]); the same histories as a tallied run of the same seed on one surface
/// (`[deterministic] surfaces = 1`).
pub fn run_condition(
    tracker: &Tracker<'_>,
    setup: &ModelSetup,
    cond: IncidentCondition,
    cond_index: u64,
    count: usize,
    seed: u64,
) -> ConditionRun {
    let histories: Vec<History> = (0..count as u64)
        .into_par_iter()
        .map(|i| history(tracker, setup, &cond, cond_index, i, seed))
        .collect();
    let mut lost = LostCounts::default();
    let mut outcomes = Vec::with_capacity(histories.len());
    for h in &histories {
        if let Fate::Lost(r) = h.fate {
            lost.add(r);
        }
        outcomes.extend(outcome(h, cond.beta_in, &setup.wall, setup.psi));
    }
    let fates = histories.iter().map(|h| h.fate).collect();
    ConditionRun {
        condition: cond,
        setup: *setup,
        outcomes,
        fates,
        lost,
    }
}

impl ConditionRun {
    /// The tally of these histories, exactly as a tallied run of the same seed gives it.
    pub fn tally(&self, bin_width_deg: f64) -> ConditionResult {
        let spec = tally_spec(&self.setup.wall, self.condition, bin_width_deg, None);
        let mut t = ConditionTally::new(spec);
        let mut next = self.outcomes.iter();
        for (b, chunk) in self.fates.chunks(BLOCK_SIZE as usize).enumerate() {
            let mut block = BlockTally::new(&spec, b as u64);
            for fate in chunk {
                match fate {
                    Fate::Lost(r) => block.push_lost(*r as usize),
                    Fate::Escaped => {
                        if let Some(o) = next.next() {
                            block.push(o);
                        }
                    }
                }
            }
            t.absorb(block);
        }
        t.result()
    }

    /// The Fig. 12 curves (Radenkovic & Simonin 2021, Eq. 34–35): `P(n = 1)` per bin of
    /// the *first* rebound angle `α⁺` — the probability the stochastic procedure
    /// (Fig. 13, step 6) uses to accept a rebound — and the model averaged over the
    /// bin's particles at their own first-rebound `(α⁺, β⁺)`.
    pub fn fig12_curves(&self, bin_width_deg: f64) -> (Vec<Bin>, Vec<Bin>) {
        let r = self.tally(bin_width_deg);
        (
            r.pdf(Quantity::PSingleGivenAlphaFirst)
                .unwrap_or_default()
                .to_vec(),
            r.pdf(Quantity::PSingleModel).unwrap_or_default().to_vec(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_history_enters_its_own_sub_patch_and_together_they_cover_the_region() {
        let side = SUB_PATCHES_PER_SIDE as f64;
        let mut counts = [0u32; SUB_PATCHES as usize];
        for i in 0..SUB_PATCHES as u64 * 64 {
            // Corners and middle of the unit square: each lands inside sub-patch `i mod 16`.
            for (a, b) in [(0.0, 0.0), (0.5, 0.5), (0.999_999, 0.999_999)] {
                let (x, z) = in_sub_patch(i, (a, b));
                let k = (i % SUB_PATCHES as u64) as usize;
                let (kx, kz) = ((x * side).floor() as usize, (z * side).floor() as usize);
                assert_eq!(kz * SUB_PATCHES_PER_SIDE as usize + kx, k, "{i} {a} {b}");
                assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&z));
            }
            counts[(i % SUB_PATCHES as u64) as usize] += 1;
        }
        // The tally's clusters are the sub-patches: history `i` is in realisation `i mod 16`.
        for i in 0..100u64 {
            assert_eq!(
                crate::tally::condition::realisation_of(i, SUB_PATCHES) as u64,
                i % SUB_PATCHES as u64
            );
        }
        assert!(counts.iter().all(|&c| c == 64));
    }
}
