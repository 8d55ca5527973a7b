//! Issue 42, "Hostile scans": valid but extreme files a user, an instrument export, a unit
//! mistake or a script can produce, through every command that reads a scan.
//!
//! The classes: extreme magnitudes (heights of 1e±300 m and ±1e308, a height offset of 1e300 m,
//! pixels and extents of 1e±300 m, a 1e308 m side in a binary header), pixel aspect ratios up to
//! 1e9 both ways, strips (2 × 100 000 points of 1 m × 1 µm, 2 × 2²² and 2²² × 2 points), a
//! Gwyddion export 8192 columns wide (its first row is longer than the detection window), and
//! special files (a FIFO, `/dev/zero`, `/proc/self/pagemap` read as SUR, which reports size 0
//! and never ends).
//!
//! Each file runs `rebound scan --scan F`, `rebound scan --scan F --diameter-um 100` and
//! `rebound deterministic --surface F --particles 200` (special files through a case's
//! `[scan] file` as well), one thread, under `ulimit -v` ([`MEM_KB`]) and a CPU-time limit of
//! [`CPU_CAP_S`] seconds (the bound: every reproducer ends within 10 s). Every run
//! must end with exit status 0 or 2: never a signal, a panic, a timeout or an abort.
//! - Status 2: exactly one line on stderr, an `error:` naming the file (or the case key that
//!   names it), and nothing in `--out`.
//! - Status 0: every CSV and TOML file written holds no NaN or infinity, and `run.toml` (and
//!   `wall_card.toml`) parse.
//!
//! The Python package's `read_scan` and `wall_card` get the same files in
//! `crates/roughwall-py/tests` (run by `tests/real_systems/python.rs`).

mod common;

use common::capped::{run_capped, Limits};

use std::path::{Path, PathBuf};
use std::time::Duration;

/// `ulimit -v` per run, kB: 3 GiB. A strip that once held a result per row (gigabytes) or
/// a mirror-tiled wall of 392 GB must be refused by the memory budget, not abort.
const MEM_KB: u64 = 3 << 20;
/// CPU seconds per run (one thread): the bound of 10 s.
const CPU_CAP_S: u64 = 10;
/// Wall-clock cap per run (a run blocked on I/O uses no CPU).
const WALL_CAP: Duration = Duration::from_secs(60);
/// The limits of every run (files up to 200 MB).
const LIMITS: Limits = Limits {
    mem_kb: MEM_KB,
    fsize_blocks: 400_000,
    cpu_s: CPU_CAP_S,
    wall: WALL_CAP,
};

/// A Gwyddion text export: `width` and `height` are the header's lengths with their units.
fn gwyddion(path: &Path, width: &str, height: &str, rows: &[Vec<f64>]) {
    let mut s = format!("# Channel: Z\n# Width: {width}\n# Height: {height}\n# Value units: m\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{v:e}")).collect();
        s.push_str(&cells.join(" "));
        s.push('\n');
    }
    std::fs::write(path, s).unwrap();
}

/// A Gwyddion Simple Field: `nx × ny` f32 heights (m), sides `x_real`, `y_real` (m).
fn gsf(path: &Path, nx: usize, ny: usize, x_real: f64, y_real: f64, h: impl Fn(usize) -> f32) {
    let mut head = format!(
        "Gwyddion Simple Field 1.0\nXRes = {nx}\nYRes = {ny}\nXReal = {x_real:e}\nYReal = {y_real:e}\nXYUnits = m\nZUnits = m\n"
    )
    .into_bytes();
    head.resize(head.len() + 4 - head.len() % 4, 0);
    for i in 0..nx * ny {
        head.extend_from_slice(&h(i).to_le_bytes());
    }
    std::fs::write(path, head).unwrap();
}

/// Rough heights (m) of amplitude `a` at point `i`: a few incommensurate waves.
fn rough(i: usize, a: f64) -> f64 {
    let x = i as f64;
    a * ((0.37 * x).sin() + 0.6 * (1.91 * x).cos() + 0.3 * (5.3 * x).sin())
}

fn grid(nx: usize, ny: usize, h: impl Fn(usize) -> f64) -> Vec<Vec<f64>> {
    (0..ny)
        .map(|iy| (0..nx).map(|ix| h(iy * nx + ix)).collect())
        .collect()
}

/// The hostile files, written into `dir`: (name, path).
fn hostile_files(dir: &Path) -> Vec<(&'static str, PathBuf)> {
    let mut out = Vec::new();
    let mut add = |name: &'static str, file: &str| {
        let p = dir.join(file);
        out.push((name, p.clone()));
        p
    };
    // Magnitudes.
    let mut last = grid(4, 3, |_| 0.0);
    last[2][2] = 3e299;
    last[2][3] = 3e300;
    gwyddion(
        &add("3e300 heights", "huge-heights.txt"),
        "4 um",
        "3 um",
        &last,
    );
    // Gwyddion text exports: (name, file, width, height, nx, ny, height of point i in m).
    type Height = fn(usize) -> f64;
    let exports: [(&'static str, &str, &str, &str, usize, usize, Height); 11] = [
        (
            "1e303 m side",
            "huge-side.txt",
            "2 um",
            "1e303 m",
            2,
            2,
            |i| rough(i, 1e-6),
        ),
        (
            "±1e308 heights",
            "max-heights.txt",
            "3 um",
            "3 um",
            3,
            3,
            |i| {
                if i % 2 == 0 {
                    1e308
                } else {
                    -1e308
                }
            },
        ),
        ("1e307 heights", "1e307.txt", "3 um", "3 um", 3, 3, |i| {
            if i % 3 == 0 {
                1e307
            } else {
                -1e307
            }
        }),
        ("offset 1e300 m", "offset.txt", "8 um", "8 um", 8, 8, |i| {
            1e300 + rough(i, 1e-6)
        }),
        (
            "1e300 m pixels",
            "huge-pixels.txt",
            "8e300 m",
            "8e300 m",
            8,
            8,
            |i| rough(i, 1e-6),
        ),
        (
            "1e-300 m heights",
            "tiny-heights.txt",
            "8 um",
            "8 um",
            8,
            8,
            |i| rough(i, 1e-300),
        ),
        (
            "1e-300 m pixels",
            "tiny-pixels.txt",
            "8e-300 m",
            "8e-300 m",
            8,
            8,
            |i| rough(i, 1e-6),
        ),
        // Aspect ratios of 1e9 both ways.
        (
            "1 m × 1 nm pixel",
            "aspect-1e9.txt",
            "8 m",
            "8 nm",
            8,
            8,
            |i| rough(i, 1e-9),
        ),
        (
            "1 nm × 1 m pixel",
            "aspect-1e-9.txt",
            "8 nm",
            "8 m",
            8,
            8,
            |i| rough(i, 1e-9),
        ),
        // A strip of very unequal pixels.
        (
            "2 × 100000 strip, 1 m × 1 µm",
            "strip-aspect.txt",
            "2 m",
            "0.1 m",
            2,
            100_000,
            |i| rough(i, 1e-6),
        ),
        // A Gwyddion export 8192 columns wide.
        (
            "8192 columns",
            "wide-export.txt",
            "8192 um",
            "6 um",
            8192,
            6,
            |i| rough(i, 1e-6) + 1.234_567_89e-9,
        ),
    ];
    for (name, file, width, height, nx, ny, h) in exports {
        gwyddion(&add(name, file), width, height, &grid(nx, ny, h));
    }
    gsf(
        &add("GSF side 1e308 m", "huge-side.gsf"),
        4,
        4,
        4e-6,
        1e308,
        |i| rough(i, 1e-6) as f32,
    );
    // Strips a few points wide or high.
    gsf(
        &add("2 × 2^22 strip", "tall.gsf"),
        2,
        1 << 22,
        2e-6,
        4.194304,
        |i| rough(i, 1e-6) as f32,
    );
    gsf(
        &add("2^22 × 2 strip", "wide.gsf"),
        1 << 22,
        2,
        4.194304,
        2e-6,
        |i| rough(i, 1e-6) as f32,
    );
    // Special files.
    let fifo = add("FIFO", "scan.fifo");
    let c = std::ffi::CString::new(fifo.to_str().unwrap()).unwrap();
    // SAFETY: a valid NUL-terminated path; mkfifo only creates a file.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0, "mkfifo");
    out.push(("/dev/zero", PathBuf::from("/dev/zero")));
    out
}

/// Files under `dir` (recursively).
fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(rd) = std::fs::read_dir(dir) {
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                out.extend(files_under(&p));
            } else {
                out.push(p);
            }
        }
    }
    out
}

/// What is wrong with a finished run's outputs, if anything.
fn check_outputs(out: &Path) -> Option<String> {
    let files = files_under(out);
    if !files.iter().any(|f| f.ends_with("run.toml")) {
        return Some("no run.toml".into());
    }
    for f in files {
        let ext = f.extension().and_then(|e| e.to_str()).unwrap_or("");
        if ext != "csv" && ext != "toml" {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        if ext == "toml" {
            if let Err(e) = text.parse::<toml::Table>() {
                return Some(format!("{name} does not parse: {e}"));
            }
        }
        // A number token that is NaN or infinite (words such as "infinite" in notes are text).
        let bad = text
            .split([',', '\n', '=', '[', ']', ' '])
            .map(str::trim)
            .find(|t| {
                let t = t.trim_start_matches(['-', '+']).to_ascii_lowercase();
                t == "nan" || t == "inf" || t == "infinity"
            });
        if let Some(t) = bad {
            return Some(format!("{name} holds `{t}`"));
        }
    }
    None
}

#[test]
fn hostile_scans_end_cleanly_in_every_command() {
    let dir = tempfile::tempdir().unwrap();
    let files = hostile_files(dir.path());
    // `/proc/self/pagemap` as SUR: a regular file that reports size 0 and never ends; read
    // through a case, as a user would name a file of any extension.
    let case = dir.path().join("pagemap.toml");
    std::fs::write(
        &case,
        "name = \"pagemap\"\n[scan]\nfile = \"/proc/self/pagemap\"\nformat = \"sur\"\n",
    )
    .unwrap();
    let mut runs: Vec<(String, Vec<String>)> = Vec::new();
    for (name, path) in &files {
        let p = path.display().to_string();
        runs.push((
            format!("{name}: scan"),
            vec!["scan".into(), "--scan".into(), p.clone()],
        ));
        runs.push((
            format!("{name}: scan --diameter-um 100"),
            vec![
                "scan".into(),
                "--scan".into(),
                p.clone(),
                "--diameter-um".into(),
                "100".into(),
            ],
        ));
        runs.push((
            format!("{name}: deterministic --surface"),
            vec![
                "deterministic".into(),
                "--surface".into(),
                p.clone(),
                "--particles".into(),
                "200".into(),
            ],
        ));
    }
    runs.push((
        "/proc/self/pagemap as SUR: scan".into(),
        vec!["scan".into(), "--case".into(), case.display().to_string()],
    ));
    let mut failures = Vec::new();
    let mut slowest = (0.0, String::new());
    for (k, (what, mut args)) in runs.into_iter().enumerate() {
        let out = dir.path().join(format!("out{k}"));
        args.extend([
            "--threads".into(),
            "1".into(),
            "--quiet".into(),
            "--out".into(),
            out.display().to_string(),
        ]);
        let ran = run_capped(common::rebound_bin(), &args, dir.path(), LIMITS);
        if ran.seconds > slowest.0 {
            slowest = (ran.seconds, what.clone());
        }
        let lines: Vec<&str> = ran.stderr.trim().lines().collect();
        let problem = if ran.timed_out {
            Some(format!(
                "over {CPU_CAP_S} s of CPU or {} s of wall time",
                WALL_CAP.as_secs()
            ))
        } else if let Some(sig) = ran.signal {
            Some(format!("killed by signal {sig}"))
        } else {
            match ran.code {
                Some(0) => check_outputs(&out),
                Some(2) if lines.len() != 1 => Some(format!("{} lines on stderr", lines.len())),
                Some(2) if !lines[0].starts_with("error: ") => Some("no `error:` line".into()),
                Some(2) if !files_under(&out).is_empty() => {
                    Some("a refused run left files in --out".into())
                }
                Some(2) => {
                    // The one line names the file (or the case that names it).
                    let named =
                        files
                            .iter()
                            .chain([("case", case.clone())].iter())
                            .any(|(_, p)| {
                                lines[0].contains(&*p.file_name().unwrap().to_string_lossy())
                            })
                            || lines[0].contains("pagemap");
                    (!named).then(|| "the message names no file".to_string())
                }
                other => Some(format!("exit status {other:?}")),
            }
        };
        if let Some(p) = problem {
            failures.push(format!(
                "{what}: {p} ({:.1} s)\n    rebound {}\n    {}",
                ran.seconds,
                args.join(" "),
                ran.stderr
                    .lines()
                    .take(3)
                    .collect::<Vec<_>>()
                    .join("\n    ")
            ));
        }
    }
    eprintln!("slowest run: {:.1} s ({})", slowest.0, slowest.1);
    assert!(
        failures.is_empty(),
        "{} hostile runs failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
