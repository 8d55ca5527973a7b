//! Partial tallies: what `--shard K/N` writes instead of final outputs, and what
//! `rebound merge` reads back.
//!
//! A partial tally is a TOML file that describes itself: format version, build identity
//! ([`crate::BUILD_VERSION`]: the tool version and a digest of its sources),
//! the command, the case text with every override, the seed, the shard, a digest of all
//! of these, and per condition the integer tallies plus one record of moments per block
//! (floats as exact bit patterns). Its last line is a SHA-256 of everything before it, so
//! a truncated or altered file is refused rather than merged.

use roughwall::tally::Moments;
use roughwall::tally::{
    BlockRecord, ConditionTally, Counters, RealisationCounts, TallySpec, LOST_REASONS, NM,
};
use roughwall::tally::{Shard, BLOCK_SIZE};
use roughwall::{Error, Result};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::path::Path;

pub use crate::output::out_dir::PARTIAL_FILE;
pub use crate::output::sha256_hex;
const FORMAT: &str = "rebound partial tally";
/// Version 2: block records and integer tallies per surface realisation.
const FORMAT_VERSION: i64 = 2;
const CHECKSUM_PREFIX: &str = "# sha256 ";

/// A partial tally's text: `body` followed by its checksum line (`# sha256 ` and the SHA-256
/// of `body`), as [`Partial::write`] writes it and [`PartialFile::read`] checks it.
pub fn sealed(body: &str) -> String {
    format!("{body}{CHECKSUM_PREFIX}{}\n", sha256_hex(body.as_bytes()))
}

/// Everything that makes two runs the same run: shards must agree on all of it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunIdentity {
    /// `deterministic` or `stochastic`.
    pub command: String,
    /// The case file's text as read (the built-in case's text without `--case`).
    pub case_text: String,
    /// Where the case came from (for messages only; not part of the digest).
    pub case_origin: String,
    /// The seed of every stream (`--seed` or the case's), as decimal text.
    pub seed: String,
    /// `--particles`, when given.
    pub particles: Option<String>,
    /// `--target-se`, when given.
    pub target_se: Option<String>,
    /// A height file read with `--surface` and its SHA-256 (deterministic).
    pub surface_file: Option<String>,
    pub surface_sha256: Option<String>,
}

impl RunIdentity {
    /// A digest of everything but `case_origin`, and of the build identity.
    pub fn digest(&self) -> String {
        let mut h = Sha256::new();
        for part in [
            crate::BUILD_VERSION,
            &self.command,
            &self.case_text,
            &self.seed,
            self.particles.as_deref().unwrap_or("-"),
            self.target_se.as_deref().unwrap_or("-"),
            self.surface_sha256.as_deref().unwrap_or("-"),
        ] {
            h.update((part.len() as u64).to_le_bytes());
            h.update(part.as_bytes());
        }
        h.finalize().iter().map(|b| format!("{b:02x}")).collect()
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileHead {
    format: String,
    format_version: i64,
    version: String,
    case_digest: String,
    shard: String,
    block_size: i64,
    particles_per_condition: i64,
    seconds: f64,
    identity: RunIdentity,
    /// The command's manifest tables (surface choice, notes), without timings.
    manifest: toml::Table,
    conditions: Vec<ConditionFile>,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ConditionFile {
    alpha_in_deg: f64,
    beta_in_deg: f64,
    blocks: Vec<i64>,
    particles: i64,
    lost: Vec<i64>,
    collisions: i64,
    collisions_sq: String,
    single: i64,
    max_collisions: i64,
    tries: i64,
    candidates: i64,
    candidates_sq: String,
    capped: i64,
    /// Per histogram: first occupied bin, then the counts up to the last occupied one.
    histograms: Vec<Vec<i64>>,
    /// Fig. 12 curves (deterministic): totals, hits and fixed-point model sums.
    curves: Vec<CurveFile>,
    /// Per block: index, then `n mean m2` per quantity (floats as hex bit patterns), then
    /// the same per surface realisation (with `[deterministic] surfaces` > 1).
    records: Vec<String>,
    /// Per surface realisation (with `[deterministic] surfaces` > 1): followed histories,
    /// single-collision ones, Σ collisions.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    realisation_counts: Vec<Vec<i64>>,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct CurveFile {
    total: Vec<i64>,
    hits: Vec<i64>,
    model: Vec<String>,
}

/// A shard's partial tally.
#[derive(Clone, Debug)]
pub struct Partial {
    pub identity: RunIdentity,
    pub shard: Shard,
    pub particles_per_condition: u64,
    pub seconds: f64,
    pub manifest: toml::Table,
    pub tallies: Vec<ConditionTally>,
}

fn record_text(r: &BlockRecord) -> String {
    let mut s = r.block.to_string();
    for m in r.moments.iter().chain(r.by_realisation.iter().flatten()) {
        s.push_str(&format!(
            " {} {:x} {:x}",
            m.n,
            m.mean.to_bits(),
            m.m2.to_bits()
        ));
    }
    s
}

/// A block record of a tally over `realisations` surface realisations (one: no
/// per-realisation moments).
fn parse_record(s: &str, realisations: u32) -> Option<BlockRecord> {
    let mut it = s.split_ascii_whitespace();
    let block = it.next()?.parse().ok()?;
    let mut read = || -> Option<[Moments; NM]> {
        let mut moments = [Moments::default(); NM];
        for m in moments.iter_mut() {
            m.n = it.next()?.parse().ok()?;
            m.mean = f64::from_bits(u64::from_str_radix(it.next()?, 16).ok()?);
            m.m2 = f64::from_bits(u64::from_str_radix(it.next()?, 16).ok()?);
        }
        Some(moments)
    };
    let moments = read()?;
    let per = if realisations > 1 { realisations } else { 0 };
    let by_realisation = (0..per).map(|_| read()).collect::<Option<Vec<_>>>()?;
    it.next().is_none().then_some(BlockRecord {
        block,
        moments,
        by_realisation,
    })
}

fn int(x: u64) -> i64 {
    i64::try_from(x).unwrap_or(i64::MAX)
}

impl Partial {
    /// Writes the partial tally to `path` (atomically) with its checksum line.
    pub fn write(&self, path: &Path) -> Result<()> {
        let conditions = self
            .tallies
            .iter()
            .map(|t| {
                let p = t.parts();
                let c: &Counters = p.counters;
                let curve = |r: &roughwall::tally::RatioCurve| {
                    let (total, hits, model) = r.parts();
                    CurveFile {
                        total: total.iter().map(|&x| int(x)).collect(),
                        hits: hits.iter().map(|&x| int(x)).collect(),
                        model: model.iter().map(|x| x.to_string()).collect(),
                    }
                };
                ConditionFile {
                    alpha_in_deg: t.spec.condition.alpha_in_deg(),
                    beta_in_deg: t.spec.condition.beta_in_deg(),
                    blocks: t.blocks().into_iter().map(int).collect(),
                    particles: int(c.particles),
                    lost: c.lost.iter().map(|&x| int(x)).collect(),
                    collisions: int(c.collisions),
                    collisions_sq: c.collisions_sq.to_string(),
                    single: int(c.single),
                    max_collisions: c.max_collisions as i64,
                    tries: int(c.tries),
                    candidates: int(c.candidates),
                    candidates_sq: c.candidates_sq.to_string(),
                    capped: int(c.capped),
                    histograms: p
                        .hists
                        .iter()
                        .map(|h| {
                            let (first, counts) = h.occupied();
                            std::iter::once(first as i64)
                                .chain(counts.iter().map(|&x| int(x)))
                                .collect()
                        })
                        .collect(),
                    curves: p.p_out.into_iter().chain(p.p_first).map(curve).collect(),
                    records: p.records.iter().map(record_text).collect(),
                    realisation_counts: p
                        .realisation_counts
                        .iter()
                        .map(|c| vec![int(c.followed), int(c.single), int(c.collisions)])
                        .collect(),
                }
            })
            .collect();
        let head = FileHead {
            format: FORMAT.into(),
            format_version: FORMAT_VERSION,
            version: crate::BUILD_VERSION.into(),
            case_digest: self.identity.digest(),
            shard: self.shard.to_string(),
            block_size: BLOCK_SIZE as i64,
            particles_per_condition: int(self.particles_per_condition),
            seconds: self.seconds,
            identity: self.identity.clone(),
            manifest: self.manifest.clone(),
            conditions,
        };
        let body =
            toml::to_string(&head).map_err(|e| Error::Io(format!("{}: {e}", path.display())))?;
        crate::output::write_atomic(path, sealed(&body).as_bytes())
    }
}

/// A partial tally read from disk, checked, before its conditions are restored.
pub struct PartialFile {
    pub path: String,
    pub identity: RunIdentity,
    pub shard: Shard,
    pub particles_per_condition: u64,
    pub seconds: f64,
    pub manifest: toml::Table,
    conditions: Vec<ConditionFile>,
}

impl PartialFile {
    /// Reads and checks `path` (a partial tally, or a directory holding one). Every problem
    /// is a one-line input error naming the file.
    pub fn read(path: &Path) -> Result<PartialFile> {
        let file = if path.is_dir() {
            path.join(PARTIAL_FILE)
        } else {
            path.to_path_buf()
        };
        let name = file.display().to_string();
        let bad = |what: &str| Error::Input(format!("shard `{name}`: {what}"));
        let bytes = std::fs::read(&file).map_err(|e| bad(&format!("cannot be read ({e})")))?;
        let text =
            std::str::from_utf8(&bytes).map_err(|_| bad("not a partial tally (not UTF-8 text)"))?;
        let body_end = text
            .trim_end_matches('\n')
            .rfind('\n')
            .map(|i| i + 1)
            .unwrap_or(0);
        let (body, last) = text.split_at(body_end);
        let Some(sum) = last.trim_end().strip_prefix(CHECKSUM_PREFIX) else {
            return Err(bad(
                "truncated or not a partial tally (no checksum line at the end)",
            ));
        };
        if sum != sha256_hex(body.as_bytes()) {
            return Err(bad("corrupt: its checksum does not match its content"));
        }
        let head: FileHead = toml::from_str(body).map_err(|e| {
            bad(&format!(
                "not a partial tally ({})",
                e.message().replace('\n', " ")
            ))
        })?;
        if head.format != FORMAT || head.format_version != FORMAT_VERSION {
            return Err(bad(&format!(
                "format `{}` version {}, this tool reads `{FORMAT}` version {FORMAT_VERSION}",
                head.format, head.format_version
            )));
        }
        if head.version != crate::BUILD_VERSION {
            return Err(bad(&format!(
                "written by rebound {}, this is rebound {} (another build): rerun the shard with this build",
                head.version,
                crate::BUILD_VERSION
            )));
        }
        if head.block_size != BLOCK_SIZE as i64 {
            return Err(bad("written with another block size"));
        }
        if head.case_digest != head.identity.digest() {
            return Err(bad(
                "its case digest does not match its case: the file was edited",
            ));
        }
        let shard = Shard::parse(&head.shard).map_err(|e| bad(&format!("shard {e}")))?;
        let particles_per_condition = u64::try_from(head.particles_per_condition)
            .map_err(|_| bad("negative particle count"))?;
        Ok(PartialFile {
            path: name,
            identity: head.identity,
            shard,
            particles_per_condition,
            seconds: head.seconds,
            manifest: head.manifest,
            conditions: head.conditions,
        })
    }

    /// Restores the condition tallies for the case's `specs` (in condition order).
    pub fn restore(self, specs: &[TallySpec]) -> Result<Partial> {
        let name = self.path.clone();
        let bad = |what: &str| Error::Input(format!("shard `{name}`: {what}"));
        if self.conditions.len() != specs.len() {
            return Err(bad(&format!(
                "{} conditions, the case has {}",
                self.conditions.len(),
                specs.len()
            )));
        }
        let u = |x: i64| u64::try_from(x).map_err(|_| bad("negative count"));
        let u128_of = |s: &str| s.parse::<u128>().map_err(|_| bad("malformed integer"));
        let mut tallies = Vec::with_capacity(specs.len());
        for (c, spec) in self.conditions.into_iter().zip(specs) {
            let mut t = ConditionTally::new(*spec);
            {
                let p = t.parts_mut();
                if c.lost.len() != LOST_REASONS || c.histograms.len() != p.hists.len() {
                    return Err(bad("malformed condition"));
                }
                let k = p.counters;
                k.particles = u(c.particles)?;
                for (a, &b) in k.lost.iter_mut().zip(&c.lost) {
                    *a = u(b)?;
                }
                k.collisions = u(c.collisions)?;
                k.collisions_sq = u128_of(&c.collisions_sq)?;
                k.single = u(c.single)?;
                k.max_collisions =
                    u32::try_from(c.max_collisions).map_err(|_| bad("malformed count"))?;
                k.tries = u(c.tries)?;
                k.candidates = u(c.candidates)?;
                k.candidates_sq = u128_of(&c.candidates_sq)?;
                k.capped = u(c.capped)?;
                for (h, stored) in p.hists.iter_mut().zip(&c.histograms) {
                    let counts: Vec<u64> = stored
                        .iter()
                        .skip(1)
                        .map(|&x| u(x))
                        .collect::<Result<_>>()?;
                    let first = stored.first().map_or(Ok(0), |&x| u(x))? as usize;
                    if !h.restore(first, &counts) {
                        return Err(bad("histogram does not fit the case's bins"));
                    }
                }
                let curves: Vec<&mut roughwall::tally::RatioCurve> =
                    p.p_out.into_iter().chain(p.p_first).collect();
                if curves.len() != c.curves.len() {
                    return Err(bad("malformed curves"));
                }
                for (r, stored) in curves.into_iter().zip(&c.curves) {
                    let total = stored.total.iter().map(|&x| u(x)).collect::<Result<_>>()?;
                    let hits = stored.hits.iter().map(|&x| u(x)).collect::<Result<_>>()?;
                    let model = stored
                        .model
                        .iter()
                        .map(|s| u128_of(s))
                        .collect::<Result<_>>()?;
                    if !r.restore(total, hits, model) {
                        return Err(bad("curve does not fit the case's bins"));
                    }
                }
                for s in &c.records {
                    p.records.push(
                        parse_record(s, spec.realisations)
                            .ok_or_else(|| bad("malformed block record"))?,
                    );
                }
                if c.realisation_counts.len() != p.realisation_counts.len() {
                    return Err(bad(&format!(
                        "integer tallies of {} surface realisations, the case has {}",
                        c.realisation_counts.len(),
                        spec.realisations
                    )));
                }
                for (a, stored) in p.realisation_counts.iter_mut().zip(&c.realisation_counts) {
                    let [followed, single, collisions] = stored[..] else {
                        return Err(bad("malformed realisation tally"));
                    };
                    *a = RealisationCounts {
                        followed: u(followed)?,
                        single: u(single)?,
                        collisions: u(collisions)?,
                    };
                }
            }
            let listed: Vec<u64> = c.blocks.iter().map(|&b| u(b)).collect::<Result<_>>()?;
            t.refold();
            if t.blocks() != listed {
                return Err(bad("its block list does not match its block records"));
            }
            // The checksum guards against accidents; an edited tally with a recomputed
            // checksum must still add up.
            consistent(&t).map_err(|m| {
                bad(&format!(
                    "condition α⁻ = {}°, β⁻ = {}°: {m} (an edited or corrupted tally)",
                    spec.condition.alpha_in_deg(),
                    spec.condition.beta_in_deg()
                ))
            })?;
            tallies.push(t);
        }
        Ok(Partial {
            identity: self.identity,
            shard: self.shard,
            particles_per_condition: self.particles_per_condition,
            seconds: self.seconds,
            manifest: self.manifest,
            tallies,
        })
    }
}

/// Whether a restored tally adds up: every block record's moments finite with `0 ≤ n ≤ block
/// size` and `M2 ≥ 0`, and per realisation counts that add up to the block's; the particles
/// counted equal the records' followed ones plus the lost; each angle histogram holds as many
/// values as the records of its quantity; single-collision histories at most the followed
/// ones; the per-realisation integer tallies add up to the condition's.
fn consistent(t: &ConditionTally) -> std::result::Result<(), String> {
    let p = t.parts();
    for r in p.records {
        for m in std::iter::once(&r.moments).chain(&r.by_realisation) {
            for (q, m) in m.iter().enumerate() {
                if m.n > BLOCK_SIZE || !m.mean.is_finite() || !m.m2.is_finite() || m.m2 < 0.0 {
                    return Err(format!(
                        "block {} has impossible moments for quantity {q} (n {}, mean {}, M2 {})",
                        r.block, m.n, m.mean, m.m2
                    ));
                }
            }
        }
        if !r.by_realisation.is_empty() {
            for q in 0..NM {
                let sum: u64 = r.by_realisation.iter().map(|m| m[q].n).sum();
                if sum != r.moments[q].n {
                    return Err(format!(
                        "block {} counts {} values of quantity {q}, its realisations {sum}",
                        r.block, r.moments[q].n
                    ));
                }
            }
        }
    }
    let n = |q: usize| -> u64 { p.records.iter().map(|r| r.moments[q].n).sum() };
    let followed = n(0);
    let lost: u64 = p.counters.lost.iter().sum();
    if followed + lost != p.counters.particles {
        return Err(format!(
            "{} particles, but its records follow {followed} and lose {lost}",
            p.counters.particles
        ));
    }
    for (q, h) in p.hists.iter().enumerate().take(NM) {
        let sum: u64 = h.occupied().1.iter().sum();
        if sum != h.total() || (q < ANGLE_HISTOGRAMS && h.total() != n(q)) {
            return Err(format!(
                "histogram {q} holds {} values, its records {}",
                h.total(),
                n(q)
            ));
        }
    }
    if p.counters.single > followed {
        return Err(format!(
            "{} single-collision histories of {followed} followed",
            p.counters.single
        ));
    }
    if !p.realisation_counts.is_empty() {
        let sum =
            |f: fn(&RealisationCounts) -> u64| -> u64 { p.realisation_counts.iter().map(f).sum() };
        let (f, s, c) = (
            sum(|c| c.followed),
            sum(|c| c.single),
            sum(|c| c.collisions),
        );
        let k = p.counters;
        if f != followed || s != k.single || c != k.collisions {
            return Err(format!(
                "its realisations follow {f} histories with {s} single and {c} collisions, the condition {followed}, {} and {}",
                k.single, k.collisions
            ));
        }
    }
    Ok(())
}

/// The histograms filled with their moment quantity, value for value (the angles; the impact
/// histograms after them have no moments).
const ANGLE_HISTOGRAMS: usize = 12;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn records_round_trip_exactly() {
        let mut moments = [Moments::default(); NM];
        moments[0] = Moments {
            n: 7,
            mean: -0.1 + 1e-17,
            m2: 3.25e-300,
        };
        moments[3] = Moments {
            n: 1,
            mean: -0.0,
            m2: 0.0,
        };
        let r = BlockRecord {
            block: 42,
            moments,
            by_realisation: vec![moments, [Moments::default(); NM]],
        };
        let back = parse_record(&record_text(&r), 2).unwrap();
        assert_eq!(back.by_realisation.len(), 2);
        assert_eq!(
            back.by_realisation[0][0].mean.to_bits(),
            moments[0].mean.to_bits()
        );
        assert!(parse_record(&record_text(&r), 1).is_none());
        assert!(parse_record(&record_text(&r), 3).is_none());
        assert_eq!(back.block, 42);
        for (a, b) in back.moments.iter().zip(&r.moments) {
            assert_eq!(
                (a.n, a.mean.to_bits(), a.m2.to_bits()),
                (b.n, b.mean.to_bits(), b.m2.to_bits())
            );
        }
        assert!(parse_record("1 2 3", 1).is_none());
        assert!(parse_record(&(record_text(&r) + " 9"), 2).is_none());
    }
}
