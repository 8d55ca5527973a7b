//! Issue "Hard to break": a deterministic mutation fuzzer over every shipped case.
//!
//! Every `configs/cases/*.toml` and `configs/scans/*.toml` is parsed as a TOML tree and shrunk
//! so that a valid run is quick (sweeps of ≤ 2 points per axis, 256-node surfaces,
//! `[deterministic] side_per_corr_length = 20` for the automatic surface, a scan's file as an
//! absolute path, a generated scan's wall on a 256-node grid). Then one thing at a time is
//! mutated:
//!
//! - every key (also the keys of inline tables, and the documented keys a case leaves out)
//!   gets 0, −1, ±1e308, 1e-300, 5e-324, −1e-9, NaN, ±inf, 2⁶³ − 1 (integer keys), strings
//!   (for string keys also "", a newline and near-misses such as `GLASS-STEEL`), a boolean,
//!   a table, `[]`, `[1.0]`, and for list keys a list of mixed types;
//! - the first element of every list gets NaN, ±inf, ±1e308, 0, −1, 1e-300, 5e-324, −1e-9, a
//!   string, a nested list;
//! - every key gets lists of 100 000 values (a ramp, copies of its value, mixed types) and the
//!   values at and just beyond its documented limits (`edges`) — these run on one case per
//!   command of each kind, as the cases of a kind share their keys;
//! - keys and sections are deleted or renamed to near-misses (`[particles]` → `[particle]`),
//!   a section is replaced by a value, unknown keys and sections are added;
//! - valid values that warn, stacked with errors (the error must stay the one line);
//! - command-line options (`--threads`, `--seed`, `--particles`, `--target-se`, `--shard`);
//! - 300 cases stacking 2–3 mutations.
//!
//! A SplitMix64 stream with a fixed seed picks the command of `[incidence]` cases, the
//! stacks, the sampled values and the run order: every run tries the same cases.
//!
//! Each case runs the command it is for (`[scan]` → `scan`; `[sweep]`/`[particle]` →
//! `force-sweep`; `[stats]` or a `[surface]` grid → `surface`; `[incidence]` →
//! `deterministic` or `stochastic`) with
//! `--threads 2` (and `--particles 200`), its own `--out`, under `ulimit -v` and `ulimit -f`,
//! stopped after `CPU_CAP_S` seconds of CPU time (`ulimit -t`) or `WALL_CAP` of wall time,
//! `WORKERS` cases at a time. Per case:
//!
//! - exit status 0 or 2 only: never a signal, a panic, a timeout, or another status (1 included);
//! - status 2: exactly one line on stderr (a `warning:` line before the error breaks the rule
//!   too) and nothing in `--out` (absent or empty);
//! - status 0: the expected files exist, every CSV parses (rectangular, numbers where numbers
//!   belong), no cell is NaN or infinite, and cells are empty only where docs/outputs.md says
//!   "not applicable" or "undefined" ([`empty_allowed`]); `run.toml` (and `scan`'s
//!   `wall_card.toml`) parses.
//!
//! When the same mutation (same command) comes up on several cases, the first decides for
//! the others: if it timed out, they are reported as skipped rather than burning the time cap
//! again (the others wait for it, so the outcome does not depend on timing).
//!
//! It prints the counts per outcome, the failing mutations grouped, and up to 5 examples per
//! failing category (mutation, command line, exit status, first lines of stderr); failing
//! cases are saved under `$CARGO_TARGET_TMPDIR/fuzz_cases/` (`target/tmp/`) with the command
//! that reproduces them. The test fails if any case fails.
//!
//! `FUZZ_CASES_ONLY=<substring>` runs only the cases whose description (case file, command,
//! mutation) contains it; `FUZZ_CASES_VERBOSE=1` prints one line per case.

mod common;

use common::capped::{run_capped, Limits, Ran, SIGXCPU};

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};
use toml::{Table, Value};

/// Seed of the SplitMix64 stream (commands, stacked mutations, run order).
const SEED: u64 = 0x5EED_2021_F022_CA5E;
/// Cases run at a time (each with `--threads 2`).
const WORKERS: usize = 4;
/// CPU-time cap per case, seconds (`ulimit -S -t`: SIGXCPU): 10 s of both threads of
/// `--threads 2`. CPU time rather than wall time, so that the verdict does not depend on how
/// busy the machine is (`WORKERS` cases share the cores, and I/O waits do not count): valid
/// shrunk cases take < 1 CPU-second, a valid 600 000-row force sweep ~7.
const CPU_CAP_S: u64 = 20;
/// Wall-clock cap per case, for a run that hangs without computing; SIGKILL after it.
const WALL_CAP: Duration = Duration::from_secs(60);
/// `ulimit -v` per case, kB.
const MEM_KB: u64 = 2_000_000;
/// `ulimit -f` per case (dash counts 512-byte blocks: 200 MB per file).
const FSIZE_BLOCKS: u64 = 400_000;
/// Particles per incident condition of `deterministic` and `stochastic`.
const PARTICLES: &str = "200";
/// Length of the huge lists.
const HUGE: usize = 100_000;
/// Cases that stack 2–3 mutations, on top of the single ones.
const STACKED: usize = 300;
/// Fuzz values tried per documented key that a case leaves out (drawn per case).
const ABSENT_VALUES: usize = 6;
/// At least this many mutated cases must run.
const MIN_CASES: usize = 2000;
/// Examples printed per failing category.
const EXAMPLES: usize = 5;
/// Failing cases saved per category.
const SAVED: usize = 25;

// ---------------------------------------------------------------------------------------
// Random stream

/// SplitMix64 (Steele, Lea & Flood 2014).
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            let j = self.below(i + 1);
            v.swap(i, j);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Shipped cases

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Cmd {
    Surface,
    Deterministic,
    Stochastic,
    ForceSweep,
    Scan,
}

impl Cmd {
    fn name(self) -> &'static str {
        match self {
            Cmd::Surface => "surface",
            Cmd::Deterministic => "deterministic",
            Cmd::Stochastic => "stochastic",
            Cmd::ForceSweep => "force-sweep",
            Cmd::Scan => "scan",
        }
    }

    fn tally(self) -> bool {
        matches!(self, Cmd::Deterministic | Cmd::Stochastic)
    }

    /// Files every successful run writes.
    fn expected(self) -> &'static [&'static str] {
        match self {
            Cmd::Surface => &["surface_summary.csv", "normal_angles.csv", "run.toml"],
            Cmd::Deterministic | Cmd::Stochastic => {
                &["summary.csv", "pdfs.csv", "moments.csv", "run.toml"]
            }
            Cmd::ForceSweep => &["force_sweep.csv", "run.toml"],
            Cmd::Scan => &["scan_summary.csv", "wall_card.toml", "run.toml"],
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// `[surface]` grid and `[stats]`: `surface`.
    Surface,
    /// `[incidence]`: `deterministic` and `stochastic`.
    Incidence,
    /// `[particle]`/`[sweep]`: `force-sweep`.
    Force,
    /// `[scan]`: `scan`.
    Scan,
}

/// A shipped case, shrunk.
struct Base {
    /// The case file under `configs/` (e.g. `cases/aniso.toml`).
    file: String,
    kind: Kind,
    table: Table,
    /// What the shrinking changed.
    shrink: Vec<String>,
}

/// Documented keys (docs/cases.md) with a valid sample value, per kind: the fuzzer adds the
/// ones a case leaves out.
fn documented(kind: Kind) -> Vec<(&'static str, &'static str, Value)> {
    let f = Value::Float;
    let i = Value::Integer;
    let s = |x: &str| Value::String(x.into());
    let l = |x: &[f64]| Value::Array(x.iter().map(|&v| Value::Float(v)).collect());
    let mut v = vec![("", "seed", i(7))];
    match kind {
        Kind::Incidence => v.extend([
            ("wall", "delta_xi_deg", f(2.5)),
            ("wall", "delta_zeta_deg", f(2.5)),
            ("wall", "rms_height_um", f(1.0)),
            ("wall", "corr_length_x_um", f(40.0)),
            ("wall", "corr_length_z_um", f(40.0)),
            ("wall", "length_um", f(400.0)),
            ("wall", "nodes", i(64)),
            ("incidence", "beta_deg", l(&[0.0])),
            ("incidence", "speed_mean_m_s", f(5.0)),
            ("incidence", "speed_std_m_s", f(1.0)),
            ("particles", "count", i(100)),
            ("particles", "target_se_deg", f(0.5)),
            ("particles", "diameter_um", f(500.0)),
            ("particles", "density_kg_m3", f(2500.0)),
            ("incidence", "speed_reference", s("magnitude")),
            ("incidence", "spin_rad_s", l(&[0.0, 0.0, 100.0])),
            ("erosion", "model", s("finnie")),
            ("erosion", "flow_stress_pa", f(1e9)),
            ("erosion", "psi", f(2.0)),
            ("erosion", "k", f(2.0)),
            ("collision", "model", s("sommerfeld-huber")),
            ("collision", "preset", s("glass-steel")),
            ("collision", "e_h", f(0.7)),
            ("collision", "alpha_e_deg", f(20.0)),
            ("collision", "mu_0", f(0.5)),
            ("collision", "mu_h", f(0.1)),
            ("collision", "alpha_mu_deg", f(22.0)),
            ("output", "bin_width_deg", f(1.0)),
            ("stochastic", "psi", f(2.0)),
            ("deterministic", "max_collisions", i(1000)),
            ("deterministic", "spacing_per_corr_length", f(8.0)),
            ("deterministic", "side_per_corr_length", f(20.0)),
            ("deterministic", "rms_height_um", f(1.0)),
            ("deterministic", "triangulation", s("alternating")),
        ]),
        Kind::Surface => v.extend([
            ("surface", "length_um", f(256.0)),
            ("surface", "nodes", i(256)),
            ("surface", "rms_height_um", f(0.37)),
            ("surface", "corr_length_x_um", f(12.0)),
            ("surface", "corr_length_z_um", f(4.0)),
            ("surface", "delta_xi_deg", f(2.5)),
            ("surface", "delta_zeta_deg", f(7.5)),
            ("stats", "beta_star_deg", l(&[0.0, 90.0])),
        ]),
        Kind::Scan => v.extend([
            (
                "scan",
                "file",
                s(&common::repo_root()
                    .join("tests/data/scans/x3p-2.x3p")
                    .display()
                    .to_string()),
            ),
            ("scan", "format", s("auto")),
            ("scan", "level_degree", i(2)),
            ("scan", "pixel_um", l(&[1.0, 1.0])),
            ("scan", "height_unit_um", f(1.0)),
            ("scan", "diameters_um", l(&[100.0])),
            ("surface", "length_um", f(256.0)),
            ("surface", "nodes", i(256)),
            ("surface", "rms_height_um", f(1.0)),
            ("surface", "delta_xi_deg", f(2.5)),
            ("surface", "delta_zeta_deg", f(7.5)),
        ]),
        Kind::Force => v.extend([
            ("particle", "preset", s("glass")),
            ("particle", "density_kg_m3", f(2500.0)),
            ("particle", "youngs_pa", f(64e9)),
            ("particle", "poisson", f(0.24)),
            ("particle", "diameter_um", f(2.45)),
            ("sweep", "lambda", l(&[1.5])),
            ("sweep", "beta_deg", l(&[45.0])),
            ("sweep", "u_n_m_s", l(&[0.1])),
            ("sweep", "diameter_um", l(&[2.45])),
            (
                "sweep",
                "models",
                Value::Array(vec![s("hu2021"), s("hertz-rigid"), s("hertz-dynamic")]),
            ),
        ]),
    }
    v
}

fn classify(t: &Table) -> Kind {
    if t.contains_key("scan") {
        Kind::Scan
    } else if t.contains_key("sweep") || t.contains_key("particle") {
        Kind::Force
    } else if t.contains_key("incidence") {
        Kind::Incidence
    } else if t.contains_key("stats") || t.contains_key("surface") {
        Kind::Surface
    } else {
        panic!("a shipped case of an unknown kind: {t:?}")
    }
}

fn section<'a>(t: &'a mut Table, name: &str) -> &'a mut Table {
    t.entry(name.to_string())
        .or_insert_with(|| Value::Table(Table::new()))
        .as_table_mut()
        .unwrap_or_else(|| panic!("[{name}] is not a table"))
}

fn num(v: &Value) -> Option<f64> {
    match v {
        Value::Float(f) => Some(*f),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// Shrinks a shipped case so that its valid runs take a fraction of a second (`dir`: the case
/// file's directory, against which a scan's relative file is read).
fn shrink(kind: Kind, t: &mut Table, dir: &Path) -> Vec<String> {
    let mut notes = Vec::new();
    match kind {
        Kind::Scan => {
            // The mutated case is written elsewhere: its scan file becomes absolute.
            let file = section(t, "scan")
                .get("file")
                .and_then(Value::as_str)
                .map(String::from);
            if let Some(f) = file {
                let abs = dir.join(&f).display().to_string();
                section(t, "scan").insert("file".into(), Value::String(abs));
                notes.push(format!("scan.file = {f} from configs/scans/"));
            } else if let Some(Value::Table(mut w)) = t.remove("wall") {
                // The generated wall, on a 256-node grid instead of the automatic 2400-node
                // one: spacing c_L,min / 4, side 64 c_L,min (h = 1 µm, Eq. 15).
                let d_max = ["delta_xi_deg", "delta_zeta_deg"]
                    .iter()
                    .filter_map(|k| w.get(*k).and_then(num))
                    .fold(0.0, f64::max);
                let c_min = 2f64.sqrt() / d_max.to_radians();
                let l = 256.0 * c_min / 4.0;
                w.insert("length_um".into(), Value::Float(l));
                w.insert("nodes".into(), Value::Integer(256));
                w.insert("rms_height_um".into(), Value::Float(1.0));
                t.insert("surface".into(), Value::Table(w));
                notes.push(format!(
                    "[wall] → [surface] with nodes = 256, rms_height_um = 1, length_um = {l}"
                ));
            }
        }
        Kind::Incidence => {
            section(t, "deterministic").insert("side_per_corr_length".into(), Value::Float(20.0));
            notes.push("deterministic.side_per_corr_length = 20".into());
            if t.get("surface").is_some_and(|s| s.get("nodes").is_some()) {
                notes.extend(shrink(Kind::Surface, t, dir));
            }
        }
        Kind::Surface => {
            let s = section(t, "surface");
            let c_min = ["corr_length_x_um", "corr_length_z_um"]
                .iter()
                .filter_map(|k| s.get(*k).and_then(num))
                .fold(f64::INFINITY, f64::min);
            s.insert("nodes".into(), Value::Integer(256));
            notes.push("surface.nodes = 256".into());
            if c_min.is_finite() {
                // Spacing c_L,min / 4 (≤ c_L/2 as required), side 64 c_L,min.
                let l = 256.0 * c_min / 4.0;
                s.insert("length_um".into(), Value::Float(l));
                notes.push(format!("surface.length_um = {l}"));
            }
        }
        Kind::Force => {
            let s = section(t, "sweep");
            for (k, v) in s.iter_mut() {
                match v {
                    Value::Array(a) if a.len() > 2 && k != "models" => {
                        a.truncate(2);
                        notes.push(format!("sweep.{k}: first 2 values"));
                    }
                    Value::Table(r)
                        if r.get("points").and_then(Value::as_integer).unwrap_or(0) > 2 =>
                    {
                        r.insert("points".into(), Value::Integer(2));
                        notes.push(format!("sweep.{k}.points = 2"));
                    }
                    Value::Table(r) if r.contains_key("step") => {
                        let (a, b) = (
                            r.get("start").and_then(num).unwrap_or(0.0),
                            r.get("stop").and_then(num).unwrap_or(0.0),
                        );
                        let step = r.get("step").and_then(num).unwrap_or(1.0);
                        if step > 0.0 && (b - a) / step > 1.0 {
                            r.insert("step".into(), Value::Float(b - a));
                            notes.push(format!("sweep.{k}.step = {}", b - a));
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    notes
}

/// The folders of `configs/` whose cases are fuzzed.
const CASE_DIRS: [&str; 2] = ["cases", "scans"];

fn load_bases() -> Vec<Base> {
    let mut files: Vec<(&str, PathBuf)> = Vec::new();
    for sub in CASE_DIRS {
        let dir = common::repo_root().join("configs").join(sub);
        files.extend(
            std::fs::read_dir(&dir)
                .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .map(|p| (sub, p)),
        );
    }
    files.sort();
    files
        .into_iter()
        .map(|(sub, p)| {
            let text = std::fs::read_to_string(&p).unwrap();
            let mut table: Table =
                toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            let kind = classify(&table);
            let shrink = shrink(kind, &mut table, p.parent().unwrap());
            Base {
                file: format!("{sub}/{}", p.file_name().unwrap().to_string_lossy()),
                kind,
                table,
                shrink,
            }
        })
        .collect()
}

// ---------------------------------------------------------------------------------------
// Mutations

/// A value put in place of a key (or a list element).
#[derive(Clone, Debug)]
enum Val {
    Int(i64),
    Float(f64),
    Str(String),
    Bool,
    EmptyList,
    /// `[1.0]`.
    OneList,
    /// `{ fuzz = 1 }`.
    Table,
    /// `[1.0, "fuzz", true, [1.0], { fuzz = 1 }]`.
    Mixed,
    /// `HUGE` numbers `0, 0.001, 0.002, …`.
    HugeRamp,
    /// `HUGE` copies of the key's (first) number or string.
    HugeConst,
    /// `HUGE` values alternating number and string.
    HugeMixed,
    /// A documented key's valid sample value.
    Exact(Value),
}

impl Val {
    fn describe(&self) -> String {
        match self {
            Val::Int(i) => i.to_string(),
            Val::Float(f) => common::toml_number(*f),
            Val::Str(s) => format!("{s:?}"),
            Val::Bool => "true".into(),
            Val::EmptyList => "[]".into(),
            Val::OneList => "[1.0]".into(),
            Val::Table => "{ fuzz = 1 }".into(),
            Val::Mixed => "[1.0, \"fuzz\", true, [1.0], { fuzz = 1 }]".into(),
            Val::HugeRamp => format!("[{HUGE} numbers 0, 0.001, 0.002, …]"),
            Val::HugeConst => format!("[{HUGE} copies of the current value]"),
            Val::HugeMixed => format!("[{HUGE} values 1.0, \"fuzz\", 1.0, …]"),
            Val::Exact(v) => v.to_string(),
        }
    }

    fn huge(&self) -> bool {
        matches!(self, Val::HugeRamp | Val::HugeConst | Val::HugeMixed)
    }

    fn make(&self, current: Option<&Value>) -> Value {
        let one = || {
            let mut t = Table::new();
            t.insert("fuzz".into(), Value::Integer(1));
            Value::Table(t)
        };
        match self {
            Val::Int(i) => Value::Integer(*i),
            Val::Float(f) => Value::Float(*f),
            Val::Str(s) => Value::String(s.clone()),
            Val::Bool => Value::Boolean(true),
            Val::Exact(v) => v.clone(),
            Val::EmptyList => Value::Array(vec![]),
            Val::OneList => Value::Array(vec![Value::Float(1.0)]),
            Val::Table => one(),
            Val::Mixed => Value::Array(vec![
                Value::Float(1.0),
                Value::String("fuzz".into()),
                Value::Boolean(true),
                Value::Array(vec![Value::Float(1.0)]),
                one(),
            ]),
            Val::HugeRamp => {
                Value::Array((0..HUGE).map(|i| Value::Float(i as f64 * 1e-3)).collect())
            }
            Val::HugeConst => {
                let first = match current {
                    Some(Value::Array(a)) => a.first().cloned(),
                    Some(v @ (Value::Float(_) | Value::Integer(_) | Value::String(_))) => {
                        Some(v.clone())
                    }
                    _ => None,
                }
                .filter(|v| !matches!(v, Value::Array(_) | Value::Table(_)))
                .unwrap_or(Value::Float(1.0));
                Value::Array(vec![first; HUGE])
            }
            Val::HugeMixed => Value::Array(
                (0..HUGE)
                    .map(|i| {
                        if i % 2 == 0 {
                            Value::Float(1.0)
                        } else {
                            Value::String("fuzz".into())
                        }
                    })
                    .collect(),
            ),
        }
    }
}

#[derive(Clone, Copy, PartialEq)]
enum VKind {
    Int,
    Float,
    Str,
    List,
    /// An inline table (a `{start, stop, step}` or `{log_start, log_stop, points}` range).
    Range,
    Other,
}

fn vkind(v: &Value) -> VKind {
    match v {
        Value::Integer(_) => VKind::Int,
        Value::Float(_) => VKind::Float,
        Value::String(_) => VKind::Str,
        Value::Array(_) => VKind::List,
        Value::Table(_) => VKind::Range,
        _ => VKind::Other,
    }
}

fn near_miss_strings(s: &str) -> Vec<String> {
    let mut v = vec![s.to_uppercase()];
    if s.contains('-') {
        v.push(s.replace('-', "_"));
    } else if s.contains('_') {
        v.push(s.replace('_', "-"));
    } else {
        v.push(format!("{s}s"));
    }
    v.push(format!("{s} "));
    v.retain(|x| x != s);
    v
}

/// The values every key gets.
fn value_set(current: &Value) -> Vec<Val> {
    let k = vkind(current);
    let mut v = if k == VKind::Int {
        vec![Val::Int(0), Val::Int(-1), Val::Int(i64::MAX)]
    } else {
        vec![Val::Float(0.0), Val::Float(-1.0)]
    };
    v.extend([
        Val::Float(1e308),
        Val::Float(-1e308),
        Val::Float(1e-300),
        Val::Float(5e-324),
        Val::Float(-1e-9),
        Val::Float(f64::NAN),
        Val::Float(f64::INFINITY),
        Val::Float(f64::NEG_INFINITY),
        Val::Str("fuzz".into()),
        Val::Bool,
        Val::EmptyList,
        Val::OneList,
        Val::Table,
    ]);
    if let Value::String(s) = current {
        v.push(Val::Str(String::new()));
        v.push(Val::Str("line one\nline two".into()));
        v.extend(near_miss_strings(s).into_iter().map(Val::Str));
    }
    if matches!(k, VKind::List | VKind::Range) {
        v.push(Val::Mixed);
    }
    v
}

/// The huge values a key gets: lists of `HUGE` numbers, and for list keys of mixed types.
fn huge_set(current: &Value) -> Vec<Val> {
    if matches!(vkind(current), VKind::List | VKind::Range) {
        vec![Val::HugeRamp, Val::HugeConst, Val::HugeMixed]
    } else {
        vec![Val::HugeConst]
    }
}

/// The values the first element of a list gets.
fn element_set(first: &Value) -> Vec<Val> {
    match first {
        Value::String(s) => {
            let mut v = vec![Val::Str(String::new()), Val::Str("fuzz".into())];
            v.extend(near_miss_strings(s).into_iter().map(Val::Str));
            v.extend([Val::Float(0.0), Val::OneList]);
            v
        }
        _ => vec![
            Val::Float(0.0),
            Val::Float(-1.0),
            Val::Float(1e308),
            Val::Float(-1e308),
            Val::Float(1e-300),
            Val::Float(5e-324),
            Val::Float(-1e-9),
            Val::Float(f64::NAN),
            Val::Float(f64::INFINITY),
            Val::Float(f64::NEG_INFINITY),
            Val::Int(i64::MAX),
            Val::Str("fuzz".into()),
            Val::OneList,
        ],
    }
}

fn near_miss_names(k: &str) -> Vec<String> {
    let mut v = Vec::new();
    match k.strip_suffix('s') {
        Some(stem) if !stem.is_empty() => v.push(stem.to_string()),
        _ => v.push(format!("{k}s")),
    }
    let mut c = k.chars();
    if let Some(f) = c.next() {
        v.push(f.to_uppercase().collect::<String>() + c.as_str());
    }
    v.retain(|x| x != k);
    v
}

#[derive(Clone, Debug)]
enum Mutation {
    /// The shrunk shipped case as it is.
    None,
    Set(Vec<String>, Val),
    SetElem(Vec<String>, usize, Val),
    Delete(Vec<String>),
    Rename(Vec<String>, String),
    /// An unknown key in the table at the path (top level for an empty path).
    AddUnknown(Vec<String>),
    AddUnknownSection,
    /// Command-line options replacing the defaults (`--threads 2`, `--particles 200`).
    Args(Vec<String>),
    Stack(Vec<Mutation>),
}

fn dotted(p: &[String]) -> String {
    if p.is_empty() {
        "<top level>".into()
    } else {
        p.join(".")
    }
}

/// The table at `path` (created when missing); `None` when something on the way is not a table.
fn table_at<'a>(t: &'a mut Table, path: &[String]) -> Option<&'a mut Table> {
    let mut cur = t;
    for k in path {
        cur = cur
            .entry(k.clone())
            .or_insert_with(|| Value::Table(Table::new()))
            .as_table_mut()?;
    }
    Some(cur)
}

impl Mutation {
    fn describe(&self) -> String {
        match self {
            Mutation::None => "(shipped case, shrunk, unmutated)".into(),
            Mutation::Set(p, v) => format!("{} = {}", dotted(p), v.describe()),
            Mutation::SetElem(p, i, v) => format!("{}[{i}] = {}", dotted(p), v.describe()),
            Mutation::Delete(p) if p.len() == 1 => format!("delete [{}]", p[0]),
            Mutation::Delete(p) => format!("delete {}", dotted(p)),
            Mutation::Rename(p, to) if p.len() == 1 => format!("rename [{}] → [{to}]", p[0]),
            Mutation::Rename(p, to) => format!("rename {} → {to}", dotted(p)),
            Mutation::AddUnknown(p) => format!("add unknown key {}.fuzz_unknown = 1", dotted(p)),
            Mutation::AddUnknownSection => "add unknown section [fuzz_unknown]".into(),
            Mutation::Args(a) => format!("options {}", a.join(" ")),
            Mutation::Stack(m) => m
                .iter()
                .map(Mutation::describe)
                .collect::<Vec<_>>()
                .join(" + "),
        }
    }

    fn args(&self) -> Option<&[String]> {
        match self {
            Mutation::Args(a) => Some(a),
            _ => None,
        }
    }

    /// Applies the mutation; a stacked one skips the parts whose path no longer exists.
    fn apply(&self, t: &mut Table) {
        match self {
            Mutation::None | Mutation::Args(_) => {}
            Mutation::Set(p, v) => {
                let (last, parent) = p.split_last().unwrap();
                if let Some(tab) = table_at(t, parent) {
                    let val = v.make(tab.get(last));
                    tab.insert(last.clone(), val);
                }
            }
            Mutation::SetElem(p, i, v) => {
                let (last, parent) = p.split_last().unwrap();
                if let Some(Value::Array(a)) = table_at(t, parent).and_then(|x| x.get_mut(last)) {
                    if *i < a.len() {
                        let val = v.make(Some(&a[*i]));
                        a[*i] = val;
                    }
                }
            }
            Mutation::Delete(p) => {
                let (last, parent) = p.split_last().unwrap();
                if let Some(tab) = table_at(t, parent) {
                    tab.remove(last);
                }
            }
            Mutation::Rename(p, to) => {
                let (last, parent) = p.split_last().unwrap();
                if let Some(tab) = table_at(t, parent) {
                    if let Some(v) = tab.remove(last) {
                        tab.insert(to.clone(), v);
                    }
                }
            }
            Mutation::AddUnknown(p) => {
                if let Some(tab) = table_at(t, p) {
                    tab.insert("fuzz_unknown".into(), Value::Integer(1));
                }
            }
            Mutation::AddUnknownSection => {
                let mut s = Table::new();
                s.insert("x".into(), Value::Integer(1));
                t.insert("fuzz_unknown".into(), Value::Table(s));
            }
            Mutation::Stack(m) => m.iter().for_each(|m| m.apply(t)),
        }
    }
}

/// Values at and just beyond the documented limits of a key (docs/cases.md), and in the
/// warning zones: for a list key, values of its first element. Some are valid and heavy (a
/// 10⁶-point sweep, a 10 000-correlation-length surface): they run on one case per command.
fn edges(path: &[String]) -> Vec<f64> {
    let sec = path.first().map_or("", String::as_str);
    let key = path.last().map_or("", String::as_str);
    let v: &[f64] = match (sec, key) {
        ("wall" | "surface", "delta_xi_deg" | "delta_zeta_deg") => &[7.5, 7.6, 20.0, 20.000001],
        ("wall" | "surface", "rms_height_um") => &[1e-12, 1e6],
        ("wall" | "surface", "corr_length_x_um" | "corr_length_z_um") => &[1e-9, 1e9],
        ("wall" | "surface", "length_um") => &[1e-3, 100.0, 1e9],
        ("wall" | "surface", "nodes") => &[15.0, 16.0, 40000.0, 40001.0],
        ("incidence", "alpha_deg") => &[-90.0, -89.999999, -90.000001, -1e-300],
        ("incidence", "beta_deg") => &[180.0, -180.0, 180.000001],
        ("incidence", "speed_mean_m_s" | "speed_std_m_s") => &[1e-9, 1e9],
        ("particles", "count") => &[1.0, 100000000.0, 100000001.0],
        ("particles", "target_se_deg") => &[1e-9, 1e9],
        ("particles", "diameter_um") => &[1e-9, 1e300],
        ("collision", "e_h") => &[1.0, 1.0000001, 1e-300],
        ("collision", "alpha_e_deg" | "alpha_mu_deg") => &[90.0, 90.000001, 1e-300],
        ("collision", "mu_0" | "mu_h") => &[2.0, 2.000001],
        ("output", "bin_width_deg") => &[0.01, 0.00999, 10.0, 10.000001],
        ("stochastic", "psi") => &[1e-9, 1e300],
        ("particles", "density_kg_m3") => &[10.0, 9.99, 3e4, 3.0001e4],
        ("erosion", "flow_stress_pa") => &[1e3, 999.0, 1e13, 1e300, -1e9],
        ("erosion", "psi" | "k") => &[1e-3, 1e-300, 1e3, 1e300, 0.0],
        ("deterministic", "max_collisions") => &[1.0, 1000000.0, 1000001.0],
        ("deterministic", "spacing_per_corr_length") => &[1.0, 64.0, 64.000001],
        ("deterministic", "side_per_corr_length") => &[1.0, 10000.0, 10000.000001],
        ("deterministic", "rms_height_um") => &[1e-300, 1e300, 1e-6, 1e6, 1.000001e6],
        ("stats", "beta_star_deg") => &[180.0, -180.0, 180.000001],
        ("particle", "poisson") => &[0.5, 0.500001, -0.999999, -1.0],
        ("particle", "density_kg_m3" | "youngs_pa" | "diameter_um") => &[1e-9, 1e300],
        ("sweep", "lambda") => &[1.0, 0.999999, 1e300],
        ("sweep", "beta_deg") => &[90.0, 90.000001],
        ("sweep", "u_n_m_s") => &[1e-9, 1e300],
        ("sweep", "diameter_um") => &[1e-9, 1e300],
        ("sweep", "points") => &[1.0, 1000000.0, 1000001.0],
        ("sweep", "step") => &[1e-9, 1e-4],
        ("sweep", "log_start" | "log_stop") => &[-300.0, 300.0, 308.3],
        ("sweep", "start" | "stop") => &[-1e-9, 90.000001],
        ("scan", "level_degree") => &[0.0, 1.0, 3.0, 4.0],
        ("scan", "pixel_um" | "height_unit_um") => &[1e-6, 0.99e-6, 1e6, 1.01e6],
        ("scan", "diameters_um") => &[1e-3, 0.99e-3, 1e6, 1.01e6, 0.0],
        _ => &[],
    };
    v.to_vec()
}

/// Every single mutation of a (shrunk) case, each with a flag: `true` for the huge lists,
/// which run on one case of the kind per command only (the cases of a kind have the same
/// keys; parsing 10⁵ values costs ~0.3 s, and a huge valid sweep runs into the time cap).
fn single_mutations(base: &Base, rng: &mut SplitMix64) -> Vec<(Mutation, bool)> {
    let mut out = Vec::new();
    let key = |p: &[&str]| p.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    // Keys present, sections first-level, inline tables (ranges) both as a value and by key.
    fn leaves(t: &Table, prefix: &[String], out: &mut Vec<(Vec<String>, Value)>) {
        for (k, v) in t {
            let mut p = prefix.to_vec();
            p.push(k.clone());
            match v {
                Value::Table(sub) if prefix.is_empty() => leaves(sub, &p, out),
                Value::Table(sub) => {
                    out.push((p.clone(), v.clone()));
                    leaves(sub, &p, out);
                }
                _ => out.push((p, v.clone())),
            }
        }
    }
    let mut present = Vec::new();
    leaves(&base.table, &[], &mut present);
    for (p, v) in &present {
        for val in value_set(v) {
            out.push((Mutation::Set(p.clone(), val), false));
        }
        for val in huge_set(v) {
            out.push((Mutation::Set(p.clone(), val), true));
        }
        out.push((Mutation::Delete(p.clone()), false));
        for n in near_miss_names(p.last().unwrap()) {
            out.push((Mutation::Rename(p.clone(), n), false));
        }
        if let Value::Array(a) = v {
            if let Some(first) = a.first() {
                for val in element_set(first) {
                    out.push((Mutation::SetElem(p.clone(), 0, val), false));
                }
            }
        }
        out.extend(edge_mutations(p, v));
    }
    // Documented keys the case leaves out: the valid sample, a few fuzz values drawn from the
    // set (every value over the cases of a kind), the huge lists.
    for (sec, k, sample) in documented(base.kind) {
        let p = if sec.is_empty() {
            key(&[k])
        } else {
            key(&[sec, k])
        };
        if present.iter().any(|(q, _)| *q == p) {
            continue;
        }
        out.push((Mutation::Set(p.clone(), Val::Exact(sample.clone())), false));
        let mut vals = value_set(&sample);
        rng.shuffle(&mut vals);
        for val in vals.into_iter().take(ABSENT_VALUES) {
            out.push((Mutation::Set(p.clone(), val), false));
        }
        for val in huge_set(&sample) {
            out.push((Mutation::Set(p.clone(), val), true));
        }
        out.extend(edge_mutations(&p, &sample));
    }
    // Sections: delete, near-miss names, an unknown key, replaced by a value.
    for (s, v) in &base.table {
        if !v.is_table() {
            continue;
        }
        let p = vec![s.clone()];
        out.push((Mutation::Delete(p.clone()), false));
        for n in near_miss_names(s) {
            out.push((Mutation::Rename(p.clone(), n), false));
        }
        out.push((Mutation::AddUnknown(p.clone()), false));
        out.push((Mutation::Set(p.clone(), Val::Int(0)), false));
        out.push((Mutation::Set(p, Val::EmptyList), false));
    }
    out.push((Mutation::AddUnknown(vec![]), false));
    out.push((Mutation::AddUnknownSection, false));
    out
}

/// The `edges` of a key as mutations (of its first element for a list), typed like the key.
fn edge_mutations(p: &[String], current: &Value) -> Vec<(Mutation, bool)> {
    let typed = |x: f64, like: &Value| match like {
        Value::Integer(_) if x.fract() == 0.0 => Val::Int(x as i64),
        _ => Val::Float(x),
    };
    edges(p)
        .into_iter()
        .map(|x| match current {
            Value::Array(a) if !a.is_empty() => {
                (Mutation::SetElem(p.to_vec(), 0, typed(x, &a[0])), true)
            }
            _ => (Mutation::Set(p.to_vec(), typed(x, current)), true),
        })
        .collect()
}

/// Warnings followed by an error: the error must still be the only line on stderr. Each
/// warning mutation (valid on its own) is stacked with each error mutation; `None` runs it
/// with either command.
fn warning_probes(base: &Base) -> Vec<(Mutation, Option<Cmd>)> {
    let k = |s: &str| s.split('.').map(String::from).collect::<Vec<_>>();
    let set = |p: &str, v: Val| Mutation::Set(k(p), v);
    let mut warnings: Vec<(Mutation, Option<Cmd>)> = Vec::new();
    let mut errors: Vec<Mutation> = Vec::new();
    match base.kind {
        Kind::Incidence => {
            // Δζ beyond the low-roughness approximation: a warning from both commands.
            warnings.push((set("wall.delta_zeta_deg", Val::Float(10.0)), None));
            // A wall given as a surface: `stochastic` says it converts it.
            warnings.push((
                Mutation::Stack(vec![
                    Mutation::Delete(k("wall.delta_xi_deg")),
                    Mutation::Delete(k("wall.delta_zeta_deg")),
                    set("wall.rms_height_um", Val::Float(1.0)),
                    set("wall.corr_length_x_um", Val::Float(40.0)),
                    set("wall.corr_length_z_um", Val::Float(20.0)),
                ]),
                Some(Cmd::Stochastic),
            ));
            errors.extend([
                set("output.bin_width_deg", Val::Float(0.0)),
                set("stochastic.psi", Val::Float(0.0)),
                set("incidence.alpha_deg", Val::EmptyList),
                set("incidence.speed_std_m_s", Val::Float(-1.0)),
                set("particles.diameter_um", Val::Float(0.0)),
                set("collision.model", Val::Str("fuzz".into())),
                set("deterministic.max_collisions", Val::Int(0)),
                set("particles.target_se_deg", Val::Float(-1.0)),
            ]);
        }
        Kind::Surface => {
            // L < 20 c_L.
            warnings.push((set("surface.length_um", Val::Float(100.0)), None));
            warnings.push((set("surface.delta_zeta_deg", Val::Float(10.0)), None));
            errors.extend([
                set("stats.beta_star_deg", Val::EmptyList),
                set("stats.beta_star_deg", Val::OneList),
                Mutation::SetElem(k("stats.beta_star_deg"), 0, Val::Float(200.0)),
            ]);
        }
        Kind::Scan => {
            // A wall beside a scan file, or a generated wall beyond Eq. 6: a warning.
            warnings.push((set("surface.delta_zeta_deg", Val::Float(10.0)), None));
            errors.extend([
                set("scan.level_degree", Val::Int(0)),
                set("scan.format", Val::Str("fuzz".into())),
                set("scan.pixel_um", Val::OneList),
            ]);
        }
        Kind::Force => {}
    }
    let mut out = Vec::new();
    for (w, c) in &warnings {
        // A `delta_zeta_deg` warning needs the key; a surface with both Δζ and c_L,z errs.
        let mut muts = vec![w.clone()];
        if let Mutation::Set(p, _) = w {
            if p.last().is_some_and(|l| l == "delta_zeta_deg") && base.kind == Kind::Surface {
                muts.insert(0, Mutation::Delete(k("surface.corr_length_z_um")));
            }
        }
        out.push((Mutation::Stack(muts.clone()), *c));
        for e in &errors {
            let mut m = muts.clone();
            m.push(e.clone());
            out.push((Mutation::Stack(m), *c));
        }
    }
    out
}

/// Command-line mutations (run on one case per command).
fn option_mutations(cmd: Cmd) -> Vec<Mutation> {
    let a = |v: &[&str]| Mutation::Args(v.iter().map(|s| s.to_string()).collect());
    let mut v = vec![
        a(&["--threads", "0"]),
        a(&["--threads", "1"]),
        a(&["--threads", "-1"]),
        a(&["--threads", "two"]),
        a(&["--seed", "18446744073709551615"]),
        a(&["--seed", "18446744073709551616"]),
        a(&["--seed", "-1"]),
        a(&["--fuzz-unknown-option"]),
    ];
    // The thread pool is built before the subcommand runs: one command each is enough.
    match cmd {
        Cmd::Stochastic => v.push(a(&["--threads", "100000"])),
        Cmd::Surface => v.push(a(&["--threads", "18446744073709551615"])),
        Cmd::Scan => v.extend([
            a(&["--scan", "/nonexistent/fuzz.x3p"]),
            a(&["--scan", ""]),
            a(&["--scan", "/dev/null"]),
            a(&["--scan", "/"]),
            a(&["--scan"]),
        ]),
        _ => {}
    }
    if cmd.tally() {
        v.extend([
            a(&["--particles", "0"]),
            a(&["--particles", "1"]),
            a(&["--particles", "100000001"]),
            a(&["--particles", "18446744073709551615"]),
            a(&["--particles", "-1"]),
            a(&["--target-se", "0"]),
            a(&["--target-se", "-1"]),
            a(&["--target-se", "nan"]),
            a(&["--target-se", "inf"]),
            a(&["--target-se", "1e-300"]),
            a(&["--shard", "0/4"]),
            a(&["--shard", "5/4"]),
            a(&["--shard", "1/18446744073709551615"]),
        ]);
    }
    v
}

// ---------------------------------------------------------------------------------------
// Jobs

struct Job {
    id: usize,
    base: usize,
    cmd: Cmd,
    mutation: Mutation,
    /// Same mutation and command on another case: one timeout is enough for all of them.
    signature: String,
    /// Huge lists and edge values: run first.
    heavy: bool,
}

fn build_jobs(bases: &[Base], rng: &mut SplitMix64) -> Vec<Job> {
    let mut jobs = Vec::new();
    let push = |base: usize, cmd: Cmd, mutation: Mutation, heavy: bool, jobs: &mut Vec<Job>| {
        // A huge list that timed out on a key stands for every huge list on that key.
        let signature = match &mutation {
            Mutation::Set(p, v) | Mutation::SetElem(p, _, v) if v.huge() => {
                format!("{} {} = <huge list>", cmd.name(), dotted(p))
            }
            m => format!("{} {}", cmd.name(), m.describe()),
        };
        jobs.push(Job {
            id: 0,
            base,
            cmd,
            mutation,
            signature,
            heavy,
        });
    };
    let cmds = |kind: Kind| -> &'static [Cmd] {
        match kind {
            Kind::Surface => &[Cmd::Surface],
            Kind::Incidence => &[Cmd::Deterministic, Cmd::Stochastic],
            Kind::Force => &[Cmd::ForceSweep],
            Kind::Scan => &[Cmd::Scan],
        }
    };
    let mut optioned = BTreeSet::new();
    let mut singles: Vec<Vec<Mutation>> = Vec::new();
    // Mutations that run on one case of their kind: (kind, mutation) → candidate cases.
    let mut once: BTreeMap<(String, String), Vec<(usize, Mutation)>> = BTreeMap::new();
    for (bi, b) in bases.iter().enumerate() {
        let muts = single_mutations(b, rng);
        for &c in cmds(b.kind) {
            push(bi, c, Mutation::None, false, &mut jobs);
            if optioned.insert(c) {
                for m in option_mutations(c) {
                    push(bi, c, m, false, &mut jobs);
                }
            }
        }
        for (m, c) in warning_probes(b) {
            let cs = cmds(b.kind);
            let c = c.unwrap_or_else(|| cs[rng.below(cs.len())]);
            push(bi, c, m, false, &mut jobs);
        }
        for (m, dedupe) in &muts {
            if *dedupe {
                once.entry((format!("{:?}", b.kind), m.describe()))
                    .or_default()
                    .push((bi, m.clone()));
                continue;
            }
            let cs = cmds(b.kind);
            let c = cs[rng.below(cs.len())];
            push(bi, c, m.clone(), false, &mut jobs);
        }
        singles.push(muts.into_iter().filter(|m| !m.1).map(|m| m.0).collect());
    }
    // One case per command of the kind (drawn).
    for (_, cands) in once {
        for &c in cmds(bases[cands[0].0].kind) {
            let (bi, m) = cands[rng.below(cands.len())].clone();
            push(bi, c, m, true, &mut jobs);
        }
    }
    // Stacked: 2–3 mutations of one case (no huge lists or edges: a timeout stays attributable).
    for _ in 0..STACKED {
        let bi = rng.below(bases.len());
        let pool: Vec<&Mutation> = singles[bi].iter().collect();
        let n = 2 + rng.below(2);
        let stack: Vec<Mutation> = (0..n)
            .map(|_| pool[rng.below(pool.len())].clone())
            .collect();
        let cs = cmds(bases[bi].kind);
        let c = cs[rng.below(cs.len())];
        push(bi, c, Mutation::Stack(stack), false, &mut jobs);
    }
    // Run order: huge lists and edges first (the slow ones), the rest shuffled.
    rng.shuffle(&mut jobs);
    jobs.sort_by_key(|j| !j.heavy);
    for (i, j) in jobs.iter_mut().enumerate() {
        j.id = i;
    }
    jobs
}

// ---------------------------------------------------------------------------------------
// Running one case

/// The limits of every case run.
const LIMITS: Limits = Limits {
    mem_kb: MEM_KB,
    fsize_blocks: FSIZE_BLOCKS,
    cpu_s: CPU_CAP_S,
    wall: WALL_CAP,
};

fn signal_name(s: i32) -> String {
    let n = match s {
        4 => "SIGILL",
        6 => "SIGABRT",
        7 => "SIGBUS",
        8 => "SIGFPE",
        9 => "SIGKILL",
        11 => "SIGSEGV",
        24 => "SIGXCPU",
        25 => "SIGXFSZ",
        _ => "",
    };
    format!("signal {s} {n}")
}

/// Columns of `summary.csv` that the stochastic model leaves empty (docs/outputs.md).
const STOCHASTIC_NA: [&str; 7] = [
    "mean_dbeta_first_deg",
    "std_dbeta_first_deg",
    "mean_collisions",
    "max_collisions",
    "lost",
    "se_mean_dbeta_first_deg",
    "se_mean_collisions",
];

/// Columns of `summary.csv` that the deterministic model leaves empty (docs/outputs.md):
/// the rejected candidates' erosion, which only the stochastic model has.
const DETERMINISTIC_NA: [&str; 2] = ["erosion_per_mass_rejected", "se_erosion_per_mass_rejected"];

/// Text columns; every other column holds numbers.
const TEXT_COLUMNS: [&str; 5] = ["model", "quantity", "file", "format", "note"];

/// Columns of `scan_summary.csv` that hold the lay's statistics (all empty without a lay).
const SCAN_LAY: [&str; 10] = [
    "lay_deg",
    "delta_xi_deg",
    "delta_zeta_deg",
    "rho_xi_zeta",
    "skewness_xi",
    "skewness_zeta",
    "kurtosis_xi",
    "kurtosis_zeta",
    "delta_scan_x_deg",
    "delta_scan_y_deg",
];

/// Whether a cell is a number within `tiny` of 0.
fn near_zero(cell: &str, tiny: f64) -> bool {
    cell.parse::<f64>().is_ok_and(|x| x.abs() <= tiny)
}

/// Where `scan_summary.csv` may leave a cell empty (docs/outputs.md, "undefined"): `file` of a
/// generated wall; Ssk and Sku of a scan levelled flat (Sq at round-off); the three Sdq
/// together (no point with both forward neighbours); every lay column without a lay; the
/// direction, correlation, skewness and kurtosis of an angle without spread.
fn scan_empty_allowed(col: &str, row: &dyn Fn(&str) -> String) -> bool {
    let flat = |c: &str| near_zero(&row(c), 1e-9);
    match col {
        "file" => row("format") == "generated",
        "ssk" | "sku" => flat("sq_um"),
        "sdq" | "sdq_x" | "sdq_y" => row("sdq").is_empty(),
        _ if SCAN_LAY.contains(&col) && SCAN_LAY.iter().all(|c| row(c).is_empty()) => true,
        "lay_deg" => flat("delta_xi_deg") && flat("delta_zeta_deg"),
        "rho_xi_zeta" => flat("delta_xi_deg") || flat("delta_zeta_deg"),
        "skewness_xi" | "kurtosis_xi" => flat("delta_xi_deg"),
        "skewness_zeta" | "kurtosis_zeta" => flat("delta_zeta_deg"),
        // The autocorrelation need not fall to 1/e within a quarter of a small scan.
        "corr_length_along_um" | "corr_length_across_um" => true,
        _ => false,
    }
}

/// Where docs/outputs.md allows an empty cell ("not applicable to this model"):
/// - `summary.csv` of `stochastic`: the collision and first-rebound columns (`STOCHASTIC_NA`);
///   `deterministic`'s: the rejected candidates' erosion columns (`DETERMINISTIC_NA`);
/// - `pdfs.csv`: `se` of the model curves `gamma_model` and `p_single_model` only;
/// - `force_sweep.csv`: `contact_time_s` for `hu2021` and for U_N = 0 only;
/// - `scan_summary.csv`: what is undefined for the scan ([`scan_empty_allowed`]);
/// - `effective_roughness.csv`: `d_over_cl_*` and `delta_*_ratio` along an axis without
///   roughness;
/// - `wall_card_diameters.csv`: the deviations of a sphere with nothing exact, the error with
///   no correlation area, a note where there is none, the resolution check of a row without
///   deviations or too small a scan;
/// - a standard deviation or standard error of a single value ("undefined for this run"):
///   `std`, `se`, `se_histories` of a `moments.csv` row with `n = 1`, `std_*`, `se_*` of a `summary.csv` row
///   with one particle;
/// - `moments.csv`, `accuracy.csv`, `dynamic_convergence.csv`, `surface_summary.csv`,
///   `normal_angles.csv` and any other CSV: nowhere else.
fn empty_allowed(cmd: Cmd, file: &str, col: &str, row: &dyn Fn(&str) -> String) -> bool {
    let spread = col.starts_with("std_") || col.starts_with("se_");
    match file {
        "moments.csv" => matches!(col, "std" | "se" | "se_histories") && row("n") == "1",
        "summary.csv" if spread && row("particles") == "1" => true,
        "summary.csv" => match cmd {
            Cmd::Stochastic => STOCHASTIC_NA.contains(&col),
            Cmd::Deterministic => DETERMINISTIC_NA.contains(&col),
            _ => false,
        },
        "pdfs.csv" => {
            col == "se" && matches!(row("quantity").as_str(), "gamma_model" | "p_single_model")
        }
        "force_sweep.csv" => {
            col == "contact_time_s"
                && (row("model") == "hu2021" || row("u_n_m_s").parse::<f64>() == Ok(0.0))
        }
        "scan_summary.csv" => scan_empty_allowed(col, row),
        // An axis without roughness (2-D surfaces): c_L = ∞ and Δ = 0 along it, so D/c_L and
        // Δ_eff/Δ are not defined there.
        "effective_roughness.csv" => match col {
            "d_over_cl_x" | "delta_xi_ratio" => near_zero(&row("delta_xi_eff_deg"), 0.0),
            "d_over_cl_z" | "delta_zeta_ratio" => near_zero(&row("delta_zeta_eff_deg"), 0.0),
            _ => false,
        },
        // No exact triangle of a sphere's centre surface: no deviations, no error; no note
        // where the scan serves the diameter.
        "wall_card_diameters.csv" => match col {
            "delta_xi_deg" | "delta_zeta_deg" => row("note").starts_with("too small: no triangle"),
            "delta_rel_se" => near_zero(&row("correlation_areas"), 0.0),
            // The resolution check needs the deviations at twice the pixel: none without the
            // row's own, and possibly none where the scan is already too small for the row.
            "delta_xi_deg_2x_pixel"
            | "delta_zeta_deg_2x_pixel"
            | "change_xi_2x_pixel"
            | "change_zeta_2x_pixel" => {
                row("delta_xi_deg").is_empty() || row("note").contains("too small")
            }
            "note" => true,
            _ => false,
        },
        _ => false,
    }
}

fn non_finite_text(c: &str) -> bool {
    let l = c.trim().trim_start_matches(['+', '-']).to_ascii_lowercase();
    l == "nan" || l == "inf" || l == "infinity"
}

type Findings = Vec<(String, String)>;

fn check_csv(cmd: Cmd, file: &str, path: &Path, f: &mut Findings) {
    let mut r = match csv::ReaderBuilder::new().flexible(false).from_path(path) {
        Ok(r) => r,
        Err(e) => return f.push(("output: CSV does not parse".into(), format!("{file}: {e}"))),
    };
    let header: Vec<String> = match r.headers() {
        Ok(h) => h.iter().map(String::from).collect(),
        Err(e) => return f.push(("output: CSV does not parse".into(), format!("{file}: {e}"))),
    };
    if header.is_empty() || header.iter().any(|h| h.trim().is_empty()) {
        f.push((
            "output: CSV does not parse".into(),
            format!("{file}: header {header:?}"),
        ));
        return;
    }
    // (category, column) → (count, first row)
    let mut bad: BTreeMap<(&str, String), (usize, usize, String)> = BTreeMap::new();
    let mut rows = 0;
    for (ri, rec) in r.records().enumerate() {
        let rec = match rec {
            Ok(r) => r,
            Err(e) => {
                f.push(("output: CSV does not parse".into(), format!("{file}: {e}")));
                return;
            }
        };
        rows += 1;
        let get = |name: &str| -> String {
            header
                .iter()
                .position(|h| h == name)
                .and_then(|i| rec.get(i))
                .unwrap_or("")
                .to_string()
        };
        for (ci, cell) in rec.iter().enumerate() {
            let col = header[ci].as_str();
            let cat = if cell.trim().is_empty() {
                if empty_allowed(cmd, file, col, &get) {
                    continue;
                }
                "output: empty cell"
            } else if non_finite_text(cell) {
                "output: NaN/inf cell"
            } else if TEXT_COLUMNS.contains(&col) {
                continue;
            } else {
                match cell.trim().parse::<f64>() {
                    Ok(x) if x.is_finite() => continue,
                    Ok(_) => "output: NaN/inf cell",
                    Err(_) => "output: not a number",
                }
            };
            let e = bad
                .entry((cat, col.to_string()))
                .or_insert((0, ri + 1, cell.to_string()));
            e.0 += 1;
        }
    }
    for ((cat, col), (n, first, cell)) in bad {
        f.push((
            cat.to_string(),
            format!("{file}: column {col}: {n} of {rows} rows (first: row {first}, {cell:?})"),
        ));
    }
    let must_have_rows = [
        "summary.csv",
        "force_sweep.csv",
        "surface_summary.csv",
        "normal_angles.csv",
        "scan_summary.csv",
    ];
    if rows == 0 && must_have_rows.contains(&file) {
        f.push(("output: empty table".into(), format!("{file}: no rows")));
    }
}

fn check_success(cmd: Cmd, out: &Path) -> Findings {
    let mut f = Findings::new();
    for e in cmd.expected() {
        if !out.join(e).is_file() {
            f.push(("output: missing file".into(), format!("{e} not written")));
        }
    }
    let mut names: Vec<String> = std::fs::read_dir(out)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    for n in &names {
        let p = out.join(n);
        if n.starts_with('.') || n.ends_with(".tmp") {
            f.push(("output: temporary file left".into(), n.clone()));
        } else if n.ends_with(".csv") {
            check_csv(cmd, n, &p, &mut f);
        } else if n == "run.toml" || n == "wall_card.toml" {
            let ok = std::fs::read_to_string(&p)
                .ok()
                .and_then(|t| t.parse::<Table>().ok())
                .is_some();
            if !ok {
                f.push((format!("output: {n} does not parse"), n.clone()));
            }
        }
    }
    f
}

fn out_is_empty(out: &Path) -> bool {
    match std::fs::read_dir(out) {
        Err(_) => true,
        Ok(mut d) => d.next().is_none(),
    }
}

/// The verdict on one run: ok, refused, or the failures found.
fn judge(cmd: Cmd, ran: &Ran, out: &Path) -> Result<&'static str, Findings> {
    let mut f = Findings::new();
    let lines: Vec<&str> = ran.stderr.trim_end().lines().collect();
    if ran.timed_out {
        let cat = if ran.signal == Some(SIGXCPU) {
            format!("timeout (over {CPU_CAP_S} s of CPU time, SIGXCPU)")
        } else {
            format!(
                "timeout (over {} s of wall time, killed)",
                WALL_CAP.as_secs()
            )
        };
        f.push((cat, String::new()));
        return Err(f);
    }
    if ran.stderr.contains("panicked") {
        f.push(("panic".into(), String::new()));
    }
    match (ran.code, ran.signal) {
        (_, Some(s)) => f.push((signal_name(s), String::new())),
        (Some(0), _) => f.extend(check_success(cmd, out)),
        (Some(2), _) => {
            if lines.len() != 1 || lines[0].trim().is_empty() {
                let cat = if lines.iter().any(|l| l.starts_with("warning:")) {
                    "error: warning line(s) before the error"
                } else if lines.is_empty() {
                    "error: no message on stderr"
                } else {
                    "error: several lines on stderr"
                };
                f.push((cat.into(), format!("{} lines", lines.len())));
            }
            if !out_is_empty(out) {
                f.push(("error: wrote into --out".into(), String::new()));
            }
        }
        (Some(101), _) if !f.is_empty() => {}
        (Some(1), _) => f.push(("exit status 1 (I/O error)".into(), String::new())),
        (Some(c), _) => f.push((format!("exit status {c}"), String::new())),
        (None, None) => f.push(("no exit status".into(), String::new())),
    }
    if !f.is_empty() {
        return Err(f);
    }
    Ok(if ran.code == Some(0) { "ok" } else { "refused" })
}

// ---------------------------------------------------------------------------------------
// The test

/// Records on drop that job `index` finished (and whether it timed out), and wakes the
/// jobs waiting for it.
struct Done<'a> {
    index: usize,
    timed_out: bool,
    done: &'a Mutex<BTreeMap<usize, bool>>,
    cv: &'a std::sync::Condvar,
}

impl Drop for Done<'_> {
    fn drop(&mut self) {
        if let Ok(mut d) = self.done.lock() {
            d.insert(self.index, self.timed_out);
        }
        self.cv.notify_all();
    }
}

struct Record {
    job: usize,
    /// "ok", "refused", "skipped", or the first failing category.
    outcome: String,
    findings: Findings,
    status: String,
    stderr_head: String,
    seconds: f64,
    command: String,
    /// The case file given to `--case` (deleted after the run; `saved` keeps a copy).
    case_path: String,
    saved: Option<PathBuf>,
}

fn shorten(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n).collect::<String>() + "…"
    }
}

#[test]
fn every_mutated_case_exits_cleanly() {
    let t0 = Instant::now();
    let bin = common::rebound_bin().to_path_buf();
    let bases = load_bases();
    assert!(!bases.is_empty(), "no shipped cases under configs/");
    assert!(
        bases.iter().any(|b| b.kind == Kind::Scan),
        "no scan case under configs/scans"
    );
    let mut rng = SplitMix64(SEED);
    let mut jobs = build_jobs(&bases, &mut rng);
    let only = std::env::var("FUZZ_CASES_ONLY").ok();
    if let Some(o) = &only {
        jobs.retain(|j| {
            format!(
                "{} {} {}",
                bases[j.base].file,
                j.cmd.name(),
                j.mutation.describe()
            )
            .contains(o)
        });
    }
    let total = jobs.len();
    let verbose = std::env::var_os("FUZZ_CASES_VERBOSE").is_some();
    if only.is_none() {
        assert!(total >= MIN_CASES, "only {total} cases");
    }

    let tmp = tempfile::Builder::new()
        .prefix("fuzz_cases.")
        .tempdir()
        .expect("temporary directory");
    let saved_dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz_cases");
    let _ = std::fs::remove_dir_all(&saved_dir);
    std::fs::create_dir_all(&saved_dir).unwrap();

    let next = AtomicUsize::new(0);
    let records: Mutex<Vec<Record>> = Mutex::new(Vec::new());
    // The first job of each signature (in run order) decides for the others: if it times
    // out they are skipped. The others wait for it, so the outcome does not depend on timing.
    let mut first: BTreeMap<&str, usize> = BTreeMap::new();
    for (i, j) in jobs.iter().enumerate() {
        first.entry(j.signature.as_str()).or_insert(i);
    }
    let done: Mutex<BTreeMap<usize, bool>> = Mutex::new(BTreeMap::new());
    let done_cv = std::sync::Condvar::new();
    let saved_per_cat: Mutex<BTreeMap<String, usize>> = Mutex::new(BTreeMap::new());

    std::thread::scope(|s| {
        for _ in 0..WORKERS {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= jobs.len() {
                    break;
                }
                let job = &jobs[i];
                let base = &bases[job.base];
                let rep = first[job.signature.as_str()];
                let skip = rep != i && {
                    let mut d = done.lock().unwrap();
                    loop {
                        match d.get(&rep) {
                            Some(&t) => break t,
                            None => d = done_cv.wait(d).unwrap(),
                        }
                    }
                };
                // Marks the job done even if this thread panics, so no one waits forever.
                let mut guard = Done {
                    index: i,
                    timed_out: false,
                    done: &done,
                    cv: &done_cv,
                };
                let dir = tmp.path().join(format!("{:05}", job.id));
                std::fs::create_dir_all(&dir).unwrap();
                let case_path = dir.join("case.toml");
                let out = dir.join("out");
                let mut args: Vec<String> = vec![
                    job.cmd.name().into(),
                    "--case".into(),
                    case_path.display().to_string(),
                    "--out".into(),
                    out.display().to_string(),
                ];
                // The defaults, unless the mutation gives the option itself.
                let given = job.mutation.args().unwrap_or(&[]);
                if !given.iter().any(|a| a == "--threads") {
                    args.extend(["--threads".into(), "2".into()]);
                }
                if job.cmd.tally() && !given.iter().any(|a| a == "--particles") {
                    args.extend(["--particles".into(), PARTICLES.into()]);
                }
                args.extend(given.iter().cloned());
                let command = format!("rebound {}", args.join(" "));
                if skip {
                    records.lock().unwrap().push(Record {
                        job: job.id,
                        outcome: "skipped".into(),
                        findings: vec![],
                        status: "not run: the same mutation timed out on another case".into(),
                        stderr_head: String::new(),
                        seconds: 0.0,
                        command,
                        case_path: case_path.display().to_string(),
                        saved: None,
                    });
                    let _ = std::fs::remove_dir_all(&dir);
                    continue;
                }
                let mut table = base.table.clone();
                job.mutation.apply(&mut table);
                let text = toml::to_string(&table).expect("serialize the mutated case");
                std::fs::write(&case_path, &text).unwrap();
                let ran = run_capped(&bin, &args, &dir, LIMITS);
                guard.timed_out = ran.timed_out;
                drop(guard);
                let verdict = judge(job.cmd, &ran, &out);
                let status = if ran.timed_out {
                    format!(
                        "killed after {:.1} s ({})",
                        ran.seconds,
                        ran.signal.map_or("?".into(), signal_name)
                    )
                } else if let Some(sig) = ran.signal {
                    signal_name(sig)
                } else {
                    format!("exit {}", ran.code.unwrap_or(-1))
                };
                let stderr_head = ran
                    .stderr
                    .lines()
                    .take(3)
                    .map(|l| shorten(l, 300))
                    .collect::<Vec<_>>()
                    .join("\n");
                let (outcome, findings) = match verdict {
                    Ok(o) => (o.to_string(), vec![]),
                    Err(f) => (f[0].0.clone(), f),
                };
                let mut saved = None;
                if !findings.is_empty() {
                    let mut per = saved_per_cat.lock().unwrap();
                    let n = per.entry(outcome.clone()).or_insert(0);
                    if *n < SAVED {
                        *n += 1;
                        let p = saved_dir.join(format!("{:05}.toml", job.id));
                        let header = format!(
                            "# fuzz_cases case {}: {} (from configs/{}, shrunk: {})\n\
                             # run: rebound {} --case {} --out OUT {}\n\
                             # ({}; under ulimit -v {MEM_KB})\n",
                            job.id,
                            job.mutation.describe(),
                            base.file,
                            base.shrink.join(", "),
                            job.cmd.name(),
                            p.display(),
                            args[5..].join(" "),
                            status,
                        );
                        std::fs::write(&p, header + &text).unwrap();
                        saved = Some(p);
                    }
                }
                if verbose {
                    eprintln!(
                        "#{:05} {:<26} {:<13} {:>6.2} s  {:<10} {}",
                        job.id,
                        base.file,
                        job.cmd.name(),
                        ran.seconds,
                        shorten(&outcome, 10),
                        shorten(&job.mutation.describe(), 120)
                    );
                }
                records.lock().unwrap().push(Record {
                    job: job.id,
                    outcome,
                    findings,
                    status,
                    stderr_head,
                    seconds: ran.seconds,
                    command,
                    case_path: case_path.display().to_string(),
                    saved,
                });
                let _ = std::fs::remove_dir_all(&dir);
            });
        }
    });

    // ------------------------------------------------------------------ summary
    let mut records = records.into_inner().unwrap();
    records.sort_by_key(|r| r.job);
    let by_id: BTreeMap<usize, &Job> = jobs.iter().map(|j| (j.id, j)).collect();
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    for r in &records {
        *counts.entry(r.outcome.clone()).or_default() += 1;
    }
    let failed: Vec<&Record> = records
        .iter()
        .filter(|r| !matches!(r.outcome.as_str(), "ok" | "refused" | "skipped"))
        .collect();
    let mut rep = String::new();
    let ran = records.iter().filter(|r| r.outcome != "skipped").count();
    let slowest = records
        .iter()
        .filter(|r| r.outcome == "ok" || r.outcome == "refused")
        .map(|r| r.seconds)
        .fold(0.0, f64::max);
    writeln!(
        rep,
        "\nfuzz_cases: {total} cases from {} shipped cases (seed {SEED:#x}), {ran} run, {:.1} s \
         with {WORKERS} workers; slowest passing case {slowest:.2} s",
        bases.len(),
        t0.elapsed().as_secs_f64()
    )
    .unwrap();
    for (o, n) in &counts {
        let what = match o.as_str() {
            "ok" => "ok (exit 0, outputs valid)",
            "refused" => "refused (exit 2, one line, nothing written)",
            "skipped" => "skipped (same mutation already timed out on another case)",
            other => other,
        };
        let tag = if matches!(o.as_str(), "ok" | "refused" | "skipped") {
            "  "
        } else {
            "✗ "
        };
        writeln!(rep, "  {tag}{what}: {n}").unwrap();
    }
    if !failed.is_empty() {
        // Grouped: category × mutation (over all cases and commands).
        let mut groups: BTreeMap<(String, String), BTreeSet<String>> = BTreeMap::new();
        for r in &failed {
            let j = by_id[&r.job];
            let detail: BTreeSet<String> = r.findings.iter().map(|f| f.0.clone()).collect();
            let key = (
                detail.into_iter().collect::<Vec<_>>().join(" & "),
                format!(
                    "{:<13} {}",
                    j.cmd.name(),
                    shorten(&j.mutation.describe(), 140)
                ),
            );
            groups
                .entry(key)
                .or_default()
                .insert(bases[j.base].file.clone());
        }
        writeln!(
            rep,
            "\nfailing mutations ({} groups: categories | command mutation | cases):",
            groups.len()
        )
        .unwrap();
        for ((cat, m), files) in &groups {
            let fl: Vec<&str> = files.iter().map(|s| s.trim_end_matches(".toml")).collect();
            writeln!(rep, "  [{cat}] {m} | {}", shorten(&fl.join(","), 120)).unwrap();
        }
        let mut cats: BTreeMap<&str, Vec<&Record>> = BTreeMap::new();
        for r in &failed {
            cats.entry(r.outcome.as_str()).or_default().push(r);
        }
        for (cat, rs) in &cats {
            writeln!(rep, "\n== {cat}: {} cases ==", rs.len()).unwrap();
            for r in rs.iter().take(EXAMPLES) {
                let j = by_id[&r.job];
                let b = &bases[j.base];
                writeln!(
                    rep,
                    "  #{} configs/{} [{}] {}",
                    r.job,
                    b.file,
                    j.cmd.name(),
                    shorten(&j.mutation.describe(), 300)
                )
                .unwrap();
                // The command line with the saved copy of the case (the run's own is gone).
                let command = match &r.saved {
                    Some(p) => r.command.replace(&r.case_path, &p.display().to_string()),
                    None => r.command.clone(),
                };
                writeln!(rep, "    {command}  →  {} ({:.2} s)", r.status, r.seconds).unwrap();
                for (c, d) in &r.findings {
                    if !d.is_empty() {
                        writeln!(rep, "    {c}: {}", shorten(d, 300)).unwrap();
                    }
                }
                for l in r.stderr_head.lines() {
                    writeln!(rep, "    stderr| {l}").unwrap();
                }
                if let Some(p) = &r.saved {
                    writeln!(rep, "    saved: {}", p.display()).unwrap();
                }
            }
        }
        writeln!(
            rep,
            "\n(failing cases saved with their command lines under {})",
            saved_dir.display()
        )
        .unwrap();
    }
    println!("{rep}");
    assert!(
        failed.is_empty(),
        "{} of {ran} mutated cases failed (summary above)",
        failed.len()
    );
}

/// The harness itself: what it flags and what it lets through, on made-up runs.
#[test]
fn the_judge_flags_what_the_issue_forbids() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let ran = |code: Option<i32>, signal: Option<i32>, stderr: &str| Ran {
        code,
        signal,
        timed_out: signal == Some(SIGXCPU),
        stderr: stderr.into(),
        seconds: 0.0,
    };
    let cats = |r: Result<&'static str, Findings>| -> Vec<String> {
        match r {
            Ok(o) => vec![o.to_string()],
            Err(f) => f.into_iter().map(|x| x.0).collect(),
        }
    };
    // Refusals.
    let c = Cmd::Stochastic;
    assert_eq!(
        cats(judge(c, &ran(Some(2), None, "error: x\n"), &out)),
        ["refused"]
    );
    let two = cats(judge(
        c,
        &ran(Some(2), None, "warning: w\nerror: x\n"),
        &out,
    ));
    assert_eq!(two, ["error: warning line(s) before the error"]);
    let two = cats(judge(c, &ran(Some(2), None, "error: a\nb\n"), &out));
    assert_eq!(two, ["error: several lines on stderr"]);
    assert_eq!(
        cats(judge(c, &ran(Some(2), None, ""), &out)),
        ["error: no message on stderr"]
    );
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("summary.csv"), "a\n").unwrap();
    assert_eq!(
        cats(judge(c, &ran(Some(2), None, "error: x\n"), &out)),
        ["error: wrote into --out"]
    );
    // Crashes.
    assert_eq!(
        cats(judge(c, &ran(None, Some(11), ""), &out)),
        ["signal 11 SIGSEGV"]
    );
    assert_eq!(
        cats(judge(c, &ran(None, Some(SIGXCPU), ""), &out))[0],
        format!("timeout (over {CPU_CAP_S} s of CPU time, SIGXCPU)")
    );
    assert_eq!(
        cats(judge(
            c,
            &ran(Some(101), None, "thread 'main' panicked at x"),
            &out
        )),
        ["panic"]
    );
    assert_eq!(
        cats(judge(c, &ran(Some(1), None, "error: I/O error: x"), &out)),
        ["exit status 1 (I/O error)"]
    );
    assert_eq!(
        cats(judge(c, &ran(Some(3), None, "error: x"), &out)),
        ["exit status 3"]
    );

    // Successes: the empty-cell rules.
    let write = |name: &str, text: &str| std::fs::write(out.join(name), text).unwrap();
    let reset = || {
        let _ = std::fs::remove_dir_all(&out);
        std::fs::create_dir_all(&out).unwrap();
        std::fs::write(out.join("run.toml"), "[run]\ncommand = \"x\"\n").unwrap();
    };
    let na = STOCHASTIC_NA.join(",");
    let blanks = ",".repeat(STOCHASTIC_NA.len() - 1);
    reset();
    write(
        "summary.csv",
        &format!("alpha_in_deg,{na},p_single\n-5,{blanks},0.5\n"),
    );
    write(
        "pdfs.csv",
        "alpha_in_deg,quantity,value,se\n-5,gamma_model,0.1,\n-5,alpha_out,0.2,0.01\n",
    );
    write("moments.csv", "quantity,n,mean\nalpha_out,3,1.5\n");
    assert_eq!(cats(judge(c, &ran(Some(0), None, ""), &out)), ["ok"]);
    // The same summary is not fine for `deterministic`, nor an empty `se` of a density.
    let d = cats(judge(Cmd::Deterministic, &ran(Some(0), None, ""), &out));
    assert_eq!(d, vec!["output: empty cell"; STOCHASTIC_NA.len()]);
    write(
        "pdfs.csv",
        "alpha_in_deg,quantity,value,se\n-5,alpha_out,0.2,\n",
    );
    assert_eq!(
        cats(judge(c, &ran(Some(0), None, ""), &out)),
        ["output: empty cell"]
    );
    write(
        "pdfs.csv",
        "alpha_in_deg,quantity,value,se\n-5,alpha_out,NaN,0.1\n",
    );
    assert_eq!(
        cats(judge(c, &ran(Some(0), None, ""), &out)),
        ["output: NaN/inf cell"]
    );
    write(
        "pdfs.csv",
        "alpha_in_deg,quantity,value,se\n-5,alpha_out,-inf,0.1\n",
    );
    assert_eq!(
        cats(judge(c, &ran(Some(0), None, ""), &out)),
        ["output: NaN/inf cell"]
    );
    write(
        "pdfs.csv",
        "alpha_in_deg,quantity,value,se\n-5,alpha_out,0.2\n",
    );
    assert_eq!(
        cats(judge(c, &ran(Some(0), None, ""), &out)),
        ["output: CSV does not parse"]
    );
    // A spread of one value is empty; of two values it must be a number.
    write(
        "pdfs.csv",
        "alpha_in_deg,quantity,value,se\n-5,alpha_out,0.2,0.01\n",
    );
    write(
        "moments.csv",
        "quantity,n,mean,std,se\nalpha_out,1,1.5,,\ndbeta,2,1.5,,\n",
    );
    assert_eq!(
        cats(judge(c, &ran(Some(0), None, ""), &out)),
        ["output: empty cell", "output: empty cell"]
    );
    std::fs::remove_file(out.join("moments.csv")).unwrap();
    write("pdfs.csv", "alpha_in_deg,quantity,value,se\n");
    assert_eq!(
        cats(judge(c, &ran(Some(0), None, ""), &out)),
        ["output: missing file"]
    );

    // force_sweep.csv: contact time empty for hu2021 and U_N = 0 only.
    reset();
    let head = "model,u_n_m_s,f_max_n,contact_time_s\n";
    write(
        "force_sweep.csv",
        &format!("{head}hu2021,0.1,1e-6,\nhertz-rigid,0,0,\nhertz-rigid,0.1,1e-6,2e-9\n"),
    );
    let f = Cmd::ForceSweep;
    assert_eq!(
        cats(judge(f, &ran(Some(0), None, "force-sweep: 3 rows"), &out)),
        ["ok"]
    );
    write("force_sweep.csv", &format!("{head}hertz-rigid,1e-300,0,\n"));
    assert_eq!(
        cats(judge(f, &ran(Some(0), None, ""), &out)),
        ["output: empty cell"]
    );
    write("force_sweep.csv", head);
    assert_eq!(
        cats(judge(f, &ran(Some(0), None, ""), &out)),
        ["output: empty table"]
    );

    // scan_summary.csv: empty where undefined only; the wall card must parse.
    reset();
    let s = Cmd::Scan;
    let head = "file,format,sq_um,ssk,sku,sdq,sdq_x,sdq_y,lay_deg,delta_xi_deg,delta_zeta_deg,rho_xi_zeta,skewness_xi,kurtosis_xi,skewness_zeta,kurtosis_zeta\n";
    write("wall_card.toml", "notes = []\n[wall]\ndelta_xi_deg = 2.5\n");
    write(
        "scan_summary.csv",
        &format!("{head},generated,1,0.1,3,0.2,0.1,0.1,0.5,2.5,7.5,0.01,0.1,3,0.1,3\n"),
    );
    assert_eq!(cats(judge(s, &ran(Some(0), None, ""), &out)), ["ok"]);
    // A plane: no shape, no lay direction; a scan without a lay or gradients.
    write(
        "scan_summary.csv",
        &format!("{head}a.x3p,x3p,0,,,0,0,0,,0,0,,,,,\nb.x3p,x3p,1,0.1,3,,,,,,,,,,,\n"),
    );
    assert_eq!(cats(judge(s, &ran(Some(0), None, ""), &out)), ["ok"]);
    // A file name is never empty for a file, a deviation never while the other is there,
    // a shape never for an angle with spread (or without a known spread).
    write(
        "scan_summary.csv",
        &format!("{head},x3p,1,0.1,3,0.2,0.1,0.1,0.5,,7.5,0.01,,3,0.1,3\n"),
    );
    assert_eq!(
        cats(judge(s, &ran(Some(0), None, ""), &out)),
        [
            "output: empty cell",
            "output: empty cell",
            "output: empty cell"
        ]
    );
    write(
        "scan_summary.csv",
        &format!("{head}a.x3p,x3p,1,0.1,3,0.2,0.1,0.1,0.5,2.5,7.5,0.01,0.1,3,,3\n"),
    );
    assert_eq!(
        cats(judge(s, &ran(Some(0), None, ""), &out)),
        ["output: empty cell"]
    );
    write(
        "scan_summary.csv",
        &format!("{head}a.x3p,x3p,1,0.1,3,0.2,0.1,0.1,0.5,2.5,7.5,0.01,0.1,3,0.1,3\n"),
    );
    write("wall_card.toml", "[wall\n");
    assert_eq!(
        cats(judge(s, &ran(Some(0), None, ""), &out)),
        ["output: wall_card.toml does not parse"]
    );
}

/// The same seed gives the same cases, in the same order.
#[test]
fn the_cases_are_the_same_on_every_run() {
    let bases = load_bases();
    let list = |seed| -> Vec<String> {
        build_jobs(&bases, &mut SplitMix64(seed))
            .iter()
            .map(|j| {
                format!(
                    "{} {} {}",
                    bases[j.base].file,
                    j.cmd.name(),
                    j.mutation.describe()
                )
            })
            .collect()
    };
    let a = list(SEED);
    assert!(a.len() >= MIN_CASES);
    assert_eq!(a, list(SEED));
    assert_ne!(a, list(SEED + 1));
}
