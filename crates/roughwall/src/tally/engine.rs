//! Running conditions in fixed blocks of particles: in parallel, with bounded memory,
//! optionally until a target standard error, and optionally as one shard of many.
//!
//! Particle `i` of condition `k` always belongs to block `i / BLOCK_SIZE`, whatever the
//! thread count; a worker fills one block in particle order; blocks are absorbed into
//! their condition in block order. Workers run at most a few blocks ahead of the oldest
//! unfinished one, so memory does not grow with the particle count. The stopping rule is
//! checked after each absorbed block, on the tally of that block and the blocks before it
//! (never on blocks finished out of order), so where a condition stops does not depend on
//! the threads either.

use super::condition::{BlockTally, ConditionTally, TallySpec};
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Condvar, Mutex};
use std::time::Instant;

/// What a run reports as it goes: the application draws a progress bar from it; the
/// library itself prints nothing. Every method has an empty default.
pub trait Progress: Sync {
    /// `n` more particles done.
    fn advance(&self, _n: u64) {}
    /// `n` planned particles that will not run (a condition reached its target).
    fn skip(&self, _n: u64) {}
    /// A short note on the run's state (e.g. the current standard error).
    fn note(&self, _msg: &str) {}
}

/// A run that reports nothing.
pub struct Silent;

impl Progress for Silent {}

pub use super::condition::BLOCK_SIZE;

/// Shard `index` (1-based) of `count`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// This shard's number `K`, 1-based (`1 ≤ K ≤ N`).
    pub index: u32,
    /// The number of shards `N` the case is split into.
    pub count: u32,
}

impl Shard {
    /// Parses `K/N` with `1 ≤ K ≤ N`; the error says what is allowed.
    pub fn parse(s: &str) -> std::result::Result<Shard, String> {
        let bad = || format!("`{s}` is not K/N with integers 1 ≤ K ≤ N ≤ 100000");
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let k: u32 = k.trim().parse().map_err(|_| bad())?;
        let n: u32 = n.trim().parse().map_err(|_| bad())?;
        if k == 0 || k > n || n > 100_000 {
            return Err(bad());
        }
        Ok(Shard { index: k, count: n })
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// What to run: the conditions, particles per condition, an optional target standard
/// error (degrees) and an optional shard.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The conditions to run, in case order (condition `k` is `specs[k]`).
    pub specs: Vec<TallySpec>,
    /// Particles per condition (the cap when a target is set).
    pub count: u64,
    /// Target standard error (degrees) of both the mean `α⁺` and the mean `β⁺ − β⁻`: a
    /// condition stops after the first absorbed block at which both are at or below it;
    /// `None` runs every condition to `count`.
    pub target_se_deg: Option<f64>,
    /// The shard `K/N` this run computes (`None`: every block, the whole case).
    pub shard: Option<Shard>,
}

/// How a condition's run went.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ConditionStats {
    /// Blocks absorbed.
    pub blocks: u64,
    /// Seconds the workers spent on those blocks (summed over threads).
    pub worker_seconds: f64,
    /// Under a target: whether both standard errors reached it before `count`.
    pub target_reached: Option<bool>,
}

impl Plan {
    /// Blocks of a condition when run to `count`.
    pub fn blocks_per_condition(&self) -> u64 {
        self.count.div_ceil(BLOCK_SIZE)
    }

    /// Particles `[start, end)` of block `b`.
    pub fn block_range(&self, b: u64) -> (u64, u64) {
        (b * BLOCK_SIZE, ((b + 1) * BLOCK_SIZE).min(self.count))
    }

    /// Whether block `b` of condition `k` is this run's: every block without a shard;
    /// with shard `K/N`, the blocks whose index in the case's whole list (conditions in
    /// order, blocks in order) is `K − 1` modulo `N`, so every shard gets a share of every
    /// part of the case.
    pub fn owns(&self, k: usize, b: u64) -> bool {
        match self.shard {
            None => true,
            Some(s) => {
                (k as u64 * self.blocks_per_condition() + b) % s.count as u64
                    == (s.index - 1) as u64
            }
        }
    }

    /// The blocks of condition `k` this run owns, in order.
    pub fn owned_blocks(&self, k: usize) -> Vec<u64> {
        (0..self.blocks_per_condition())
            .filter(|&b| self.owns(k, b))
            .collect()
    }

    /// Particles this run will follow at most.
    pub fn planned_particles(&self) -> u64 {
        (0..self.specs.len())
            .flat_map(|k| self.owned_blocks(k))
            .map(|b| {
                let (s, e) = self.block_range(b);
                e - s
            })
            .sum()
    }
}

/// The run's blocks in the order they are handed out: condition by condition, or, under a
/// target, round-robin over the conditions (so that all of them approach their stopping
/// points together and few blocks past one are computed in vain). Either way each
/// condition's blocks come in block order.
fn work_list(plan: &Plan) -> Vec<(usize, u64)> {
    let owned: Vec<Vec<u64>> = (0..plan.specs.len())
        .map(|k| plan.owned_blocks(k))
        .collect();
    if plan.target_se_deg.is_none() {
        return owned
            .iter()
            .enumerate()
            .flat_map(|(k, bs)| bs.iter().map(move |&b| (k, b)))
            .collect();
    }
    let longest = owned.iter().map(Vec::len).max().unwrap_or(0);
    (0..longest)
        .flat_map(|j| {
            owned
                .iter()
                .enumerate()
                .filter_map(move |(k, bs)| bs.get(j).map(|&b| (k, b)))
        })
        .collect()
}

/// What the workers share: the tallies, and the blocks finished out of order.
struct Shared {
    tallies: Vec<(ConditionTally, ConditionStats)>,
    /// Finished blocks waiting for the ones before them: work-list index → block.
    waiting: BTreeMap<usize, Finished>,
    /// Work-list index of the next block to absorb.
    absorbed: usize,
}

/// A finished block (`None`: skipped, its condition had already reached its target).
type Finished = (usize, Option<(BlockTally, f64)>);

impl Shared {
    /// Absorbs every finished block that is next in line; checks the stopping rule after
    /// each, on the tally of that block and the blocks before it (all absorbed in block
    /// order, none finished out of order).
    fn absorb_ready(&mut self, plan: &Plan, done: &[AtomicBool], progress: &dyn Progress) {
        while let Some((k, finished)) = self.waiting.remove(&self.absorbed) {
            self.absorbed += 1;
            let (tally, stats) = &mut self.tallies[k];
            let Some((block, secs)) = finished else {
                continue;
            };
            let (start, end) = plan.block_range(block.block());
            if stats.target_reached == Some(true) {
                continue; // computed past the stopping point: discarded (already skipped)
            }
            tally.absorb(block);
            stats.blocks += 1;
            stats.worker_seconds += secs;
            progress.advance(end - start);
            let (Some(target), Some((se_a, se_b))) = (plan.target_se_deg, tally.running_se())
            else {
                continue;
            };
            progress.note(&format!(
                "α⁻ = {}°, β⁻ = {}°: SE {se_a:.3}°, {se_b:.3}° → {target}°",
                crate::format::fmt_num(tally.spec.condition.alpha_in_deg()),
                crate::format::fmt_num(tally.spec.condition.beta_in_deg()),
            ));
            if se_a <= target && se_b <= target {
                stats.target_reached = Some(true);
                done[k].store(true, Ordering::Relaxed);
                let remaining: u64 = plan
                    .owned_blocks(k)
                    .into_iter()
                    .filter(|&b| b > tally.blocks().last().copied().unwrap_or(0))
                    .map(|b| {
                        let (s, e) = plan.block_range(b);
                        e - s
                    })
                    .sum();
                progress.skip(remaining);
            }
        }
    }
}

/// Runs the plan. `fill(k, start, end, block)` tallies particles `start..end` of
/// condition `k` into `block`, in particle order. Returns each condition's tally and
/// statistics, in condition order.
///
/// Every thread of the pool pulls the next block of the work list, fills it, and absorbs
/// whatever blocks are next in line; a thread that would run more than a few blocks ahead
/// of the oldest unfinished one waits, so memory stays bounded without a barrier between
/// groups of blocks.
pub fn run<F>(
    plan: &Plan,
    progress: &dyn Progress,
    fill: F,
) -> Vec<(ConditionTally, ConditionStats)>
where
    F: Fn(usize, u64, u64, &mut BlockTally) + Sync,
{
    let items = work_list(plan);
    let threads = rayon::current_num_threads().max(1);
    let window = (4 * threads).clamp(2, 256);
    let next = AtomicUsize::new(0);
    let done: Vec<AtomicBool> = plan.specs.iter().map(|_| AtomicBool::new(false)).collect();
    let shared = Mutex::new(Shared {
        tallies: plan
            .specs
            .iter()
            .map(|s| {
                (
                    ConditionTally::new(*s),
                    ConditionStats {
                        target_reached: plan.target_se_deg.map(|_| false),
                        ..Default::default()
                    },
                )
            })
            .collect(),
        waiting: BTreeMap::new(),
        absorbed: 0,
    });
    let ahead = Condvar::new();
    let lock = || shared.lock().unwrap_or_else(|e| e.into_inner());
    let worker = || loop {
        let i = next.fetch_add(1, Ordering::Relaxed);
        let Some(&(k, b)) = items.get(i) else { break };
        {
            let mut st = lock();
            while i >= st.absorbed + window {
                st = ahead.wait(st).unwrap_or_else(|e| e.into_inner());
            }
        }
        let finished = (!done[k].load(Ordering::Relaxed)).then(|| {
            let t0 = Instant::now();
            let mut block = BlockTally::new(&plan.specs[k], b);
            let (start, end) = plan.block_range(b);
            fill(k, start, end, &mut block);
            (block, t0.elapsed().as_secs_f64())
        });
        let mut st = lock();
        st.waiting.insert(i, (k, finished));
        st.absorb_ready(plan, &done, progress);
        drop(st);
        ahead.notify_all();
    };
    rayon::scope(|s| {
        for _ in 0..threads {
            s.spawn(|_| worker());
        }
    });
    shared
        .into_inner()
        .unwrap_or_else(|e| e.into_inner())
        .tallies
}

#[cfg(test)]
mod tests {
    use super::super::condition::{ModelKind, Outcome};
    use super::*;
    use crate::incidence::IncidentCondition;
    use crate::wall::Deviations;

    fn plan(count: u64, target: Option<f64>, shard: Option<Shard>) -> Plan {
        let spec = |a: f64| TallySpec {
            condition: IncidentCondition::from_degrees(a, 0.0),
            deviations: Deviations {
                delta_xi: 0.05,
                delta_zeta: 0.1,
            },
            bin_width_deg: 1.0,
            model: ModelKind::Stochastic,
            erosion_particle_mass_kg: None,
            realisations: 1,
        };
        Plan {
            specs: vec![spec(-10.0), spec(-20.0)],
            count,
            target_se_deg: target,
            shard,
        }
    }

    /// A fake model: α⁺ of particle i is a hash of (k, i), spread over ±30°.
    fn fill(k: usize, start: u64, end: u64, b: &mut BlockTally) {
        for i in start..end {
            let h = crate::rng::splitmix64(i ^ ((k as u64) << 40));
            let x = (h >> 11) as f64 / (1u64 << 53) as f64;
            b.push(&Outcome {
                alpha_out: (x - 0.5) * 1.0,
                dbeta: (0.5 - x) * 0.5,
                speed_ratio: 1.0,
                ..Default::default()
            });
        }
    }

    fn results(p: &Plan, threads: usize) -> Vec<crate::tally::ConditionResult> {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| run(p, &Silent, fill))
            .into_iter()
            .map(|(t, _)| t.result())
            .collect()
    }

    #[test]
    fn any_thread_count_and_any_shard_split_give_the_same_tally() {
        let p = plan(3 * BLOCK_SIZE + 123, None, None);
        let one = results(&p, 1);
        assert_eq!(one, results(&p, 3));
        let mut merged: Vec<ConditionTally> = Vec::new();
        for index in 1..=4 {
            let shard = plan(3 * BLOCK_SIZE + 123, None, Some(Shard { index, count: 4 }));
            let parts = run(&shard, &Silent, fill);
            if merged.is_empty() {
                merged = parts.into_iter().map(|p| p.0).collect();
            } else {
                for (m, (t, _)) in merged.iter_mut().zip(parts) {
                    m.add(&t).unwrap();
                }
            }
        }
        let merged: Vec<_> = merged.iter().map(|t| t.result()).collect();
        assert_eq!(merged, one);
        assert_eq!(one[0].summary.particles, 3 * BLOCK_SIZE + 123);
    }

    #[test]
    fn a_target_stops_at_the_same_block_for_any_thread_count() {
        // α⁺ spread ≈ 16.5°: SE after b blocks ≈ 16.5/√(65536 b) → 0.045° needs 3 blocks.
        let p = plan(40 * BLOCK_SIZE, Some(0.045), None);
        let a = results(&p, 1);
        let b = results(&p, 2);
        assert_eq!(a, b);
        let n = a[0].summary.particles;
        assert!(n.is_multiple_of(BLOCK_SIZE) && n < 10 * BLOCK_SIZE, "{n}");
        assert!(a[0].summary.alpha_out.unwrap().se.unwrap() <= 0.045);
        // Stopping one block earlier would have missed the target.
        let shorter = plan(n - BLOCK_SIZE, None, None);
        let s = results(&shorter, 1);
        let se = s[0]
            .summary
            .alpha_out
            .unwrap()
            .se
            .unwrap()
            .max(s[0].summary.dbeta.unwrap().se.unwrap());
        assert!(se > 0.045, "{se}");
    }

    #[test]
    fn shards_parse_and_partition_the_blocks() {
        assert_eq!(Shard::parse("2/4"), Ok(Shard { index: 2, count: 4 }));
        for bad in ["0/4", "5/4", "x", "1/0", "-1/2", "1/"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
        let base = plan(5 * BLOCK_SIZE, None, None);
        for k in 0..2 {
            let mut seen: Vec<u64> = Vec::new();
            for index in 1..=3 {
                let p = Plan {
                    shard: Some(Shard { index, count: 3 }),
                    ..base.clone()
                };
                seen.extend(p.owned_blocks(k));
            }
            seen.sort_unstable();
            assert_eq!(seen, base.owned_blocks(k));
        }
    }
}
