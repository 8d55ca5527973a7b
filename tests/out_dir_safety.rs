//! Output directories are written as a whole (issue "Hard to break", items 8–10): every
//! output path is checked before computing, a failed, killed (`kill -9`) or concurrent run
//! never leaves `--out` mixed, and a previous result is never damaged.
use crate::common::{rebound, rebound_in, write_case, Run, TestCommand};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const SURFACE: &str = r#"name = "small"
seed = 3
[surface]
length_um = 256.0
nodes = 256
rms_height_um = 0.37
corr_length_x_um = 12.0
corr_length_z_um = 4.0
[stats]
beta_star_deg = [0.0, 30.0, 60.0, 90.0]
"#;

/// A stochastic case of `count` particles per condition (4 conditions).
fn stochastic_case(name: &str, count: u64) -> String {
    format!(
        "name = \"{name}\"\nseed = 1\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n\
         [incidence]\nalpha_deg = [-12.5, -32.5]\nbeta_deg = [0.0, 60.0]\n[particles]\ncount = {count}\n"
    )
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every entry below `dir` (relative path → bytes of a file, or a marker for anything
/// else), hidden entries included. With `timeless`, the `run.toml` lines holding timings
/// are left out.
fn snapshot(dir: &Path, timeless: bool) -> BTreeMap<PathBuf, Vec<u8>> {
    fn walk(root: &Path, dir: &Path, timeless: bool, out: &mut BTreeMap<PathBuf, Vec<u8>>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let e = e.unwrap();
            let p = e.path();
            let rel = p.strip_prefix(root).unwrap().to_path_buf();
            let ft = std::fs::symlink_metadata(&p).unwrap().file_type();
            if ft.is_dir() {
                out.insert(rel, b"<dir>".to_vec());
                walk(root, &p, timeless, out);
            } else if ft.is_file() {
                let mut bytes = std::fs::read(&p).unwrap();
                if timeless && rel == Path::new("run.toml") {
                    bytes = String::from_utf8(bytes)
                        .unwrap()
                        .lines()
                        .filter(|l| {
                            !(l.contains("_s =")
                                || l.contains("seconds")
                                || l.contains("per_s")
                                || l.contains("wall_time"))
                        })
                        .collect::<Vec<_>>()
                        .join("\n")
                        .into_bytes();
                }
                out.insert(rel, bytes);
            } else {
                out.insert(rel, b"<other>".to_vec());
            }
        }
    }
    let mut out = BTreeMap::new();
    walk(dir, dir, timeless, &mut out);
    out
}

/// The names in a directory.
fn names(dir: &Path) -> BTreeSet<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

fn surface(case: &Path, out: &Path, seed: &str, extra: &[&str]) -> Run {
    let mut args = vec![
        "surface",
        "--case",
        s(case),
        "--out",
        s(out),
        "--seed",
        seed,
    ];
    args.extend_from_slice(extra);
    rebound(&args)
}

fn stochastic(case: &Path, out: &Path, seed: &str) -> Run {
    rebound(&[
        "stochastic",
        "--case",
        s(case),
        "--out",
        s(out),
        "--seed",
        seed,
    ])
}

#[test]
fn a_run_refused_on_a_bad_heights_path_leaves_the_previous_result_byte_identical() {
    let tmp = tempfile::tempdir().unwrap();
    let case = write_case(tmp.path(), "s.toml", SURFACE);
    let d = tmp.path().join("D");
    surface(&case, &d, "1", &[]).ok();
    let before = snapshot(&d, false);
    let around = names(tmp.path());
    let hd = tmp.path().join("hd");
    std::fs::create_dir(&hd).unwrap();
    surface(&case, &d, "2", &["--heights", s(&hd)]).refused("--heights");
    assert_eq!(snapshot(&d, false), before, "D changed");
    let mut expect = around.clone();
    expect.insert("hd".into());
    assert_eq!(names(tmp.path()), expect);
    assert!(names(&hd).is_empty());
}

#[test]
fn heights_that_are_not_regular_files_or_clash_with_outputs_are_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let case = write_case(t, "s.toml", SURFACE);
    let target = write_case(t, "target.txt", "keep me\n");
    std::fs::create_dir(t.join("hd")).unwrap();
    let fifo = t.join("fifo");
    let st = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(st.success(), "mkfifo");
    let link = t.join("link");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let old = t.join("old");
    surface(&case, &old, "1", &[]).ok();
    let old_before = snapshot(&old, false);
    let fresh = t.join("fresh");
    let cases: Vec<(PathBuf, &Path)> = vec![
        (t.join("hd"), &fresh),
        (fifo.clone(), &fresh),
        (link.clone(), &fresh),
        (PathBuf::from("/dev/null"), &fresh),
        (fresh.join("run.toml"), &fresh),
        (fresh.join("surface_summary.csv"), &fresh),
        (fresh.clone(), &fresh),
        (old.join("run.toml"), &old),
        (old.join("normal_angles.csv"), &old),
        (t.join(".old.lock"), &old),
    ];
    let around = names(t);
    for (heights, out) in cases {
        let r = surface(&case, out, "2", &["--heights", s(&heights)]);
        r.refused("--heights");
        assert!(r.stderr.contains(s(&heights)), "{}", r.stderr);
        assert_eq!(names(t), around, "--heights {}", heights.display());
        assert!(!fresh.exists());
        assert_eq!(snapshot(&old, false), old_before);
    }
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::symlink_metadata(&fifo)
        .unwrap()
        .file_type()
        .is_fifo());
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep me\n");
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    assert!(names(&t.join("hd")).is_empty());

    // Allowed: a new file outside `--out`, and a new name inside it (moved with the swap).
    let h_out = t.join("h.rbhf");
    surface(&case, &fresh, "2", &["--heights", s(&h_out)]).ok();
    assert!(h_out.is_file());
    let h_in = old.join("sub/h.rbhf");
    surface(&case, &old, "2", &["--heights", s(&h_in)]).ok();
    assert_eq!(
        std::fs::read(&h_in).unwrap(),
        std::fs::read(&h_out).unwrap()
    );
    assert_eq!(
        snapshot(&old, false).get(Path::new("surface_summary.csv")),
        snapshot(&fresh, false).get(Path::new("surface_summary.csv"))
    );

    // A height file inside `--out` is not the input of a run that replaces `--out`.
    let h_top = fresh.join("h.rbhf");
    surface(&case, &fresh, "2", &["--heights", s(&h_top)]).ok();
    let before = snapshot(&fresh, false);
    rebound(&[
        "deterministic",
        "--surface",
        s(&h_top),
        "--particles",
        "100",
        "--out",
        s(&fresh),
    ])
    .refused("--surface");
    assert_eq!(snapshot(&fresh, false), before);
}

#[test]
fn compare_and_merge_never_write_over_the_runs_they_read() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let case = write_case(t, "c.toml", &stochastic_case("cmp", 4000));
    let (a, b) = (t.join("A"), t.join("B"));
    stochastic(&case, &a, "1").ok();
    stochastic(&case, &b, "2").ok();
    let (sa, sb) = (snapshot(&a, false), snapshot(&b, false));
    let link = t.join("link-to-a");
    std::os::unix::fs::symlink(&a, &link).unwrap();
    let around = names(t);
    for out in [
        a.clone(),
        PathBuf::from(format!("{}/", a.display())),
        a.join("."),
        t.join("B/../A"),
        link.clone(),
        b.clone(),
    ] {
        let r = rebound(&["compare", "--a", s(&a), "--b", s(&b), "--out", s(&out)]);
        r.refused("--out");
        assert_eq!(snapshot(&a, false), sa);
        assert_eq!(snapshot(&b, false), sb);
        assert_eq!(names(t), around);
    }
    // A shard's directory is not a merge's `--out` either.
    let shard = |k: &str, dir: &Path| {
        rebound(&[
            "stochastic",
            "--case",
            s(&case),
            "--shard",
            k,
            "--out",
            s(dir),
        ])
        .ok();
    };
    let (s1, s2) = (t.join("s1"), t.join("s2"));
    shard("1/2", &s1);
    shard("2/2", &s2);
    let before = snapshot(&s1, false);
    rebound(&["merge", "--out", s(&s1), s(&s1), s(&s2)]).refused("--out");
    assert_eq!(snapshot(&s1, false), before);
    // A fine `--out`.
    let cmp = t.join("cmp");
    rebound(&["compare", "--a", s(&a), "--b", s(&b), "--out", s(&cmp)]).ok();
    assert!(cmp.join("comparison.csv").is_file());
}

#[test]
fn case_names_that_leave_results_are_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let cwd = t.join("w/x");
    std::fs::create_dir_all(&cwd).unwrap();
    let abs = std::env::temp_dir().join(format!("roughwall-abs-{}", std::process::id()));
    for name in [
        "../../ESC".to_string(),
        abs.display().to_string(),
        "..".into(),
        "a\\\\b".into(),
    ] {
        let case = write_case(&cwd, "c.toml", &stochastic_case(&name, 2000));
        let before_t = names(t);
        let before_cwd = names(&cwd);
        for cmd in ["stochastic", "surface", "deterministic"] {
            let r = rebound_in(&cwd, &[cmd, "--case", s(&case)]);
            r.refused("`name`");
            assert_eq!(names(t), before_t, "{cmd} {name}");
            assert_eq!(names(&cwd), before_cwd, "{cmd} {name}");
            assert!(!abs.exists(), "{cmd} wrote {}", abs.display());
            assert!(!t.join("ESC").exists() && !t.join("w/ESC").exists());
        }
    }
    // A plain name goes under results/.
    let case = write_case(&cwd, "c.toml", &stochastic_case("plain", 2000));
    rebound_in(&cwd, &["stochastic", "--case", s(&case)]).ok();
    assert!(cwd.join("results/plain/stochastic/summary.csv").is_file());
}

#[test]
fn an_out_that_is_a_file_or_a_foreign_directory_is_refused_and_untouched() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let case = write_case(t, "s.toml", SURFACE);
    let file = write_case(t, "file.txt", "mine\n");
    let link = t.join("link");
    std::os::unix::fs::symlink(&file, &link).unwrap();
    let fifo = t.join("fifo");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let foreign = t.join("foreign");
    std::fs::create_dir(&foreign).unwrap();
    write_case(&foreign, "notes.txt", "my notes\n");
    let sub_foreign = t.join("sub-foreign");
    std::fs::create_dir_all(sub_foreign.join("data")).unwrap();
    write_case(&sub_foreign.join("data"), "x.bin", "x");
    let before = snapshot(t, false);
    for (out, needle) in [
        (&file, "--out"),
        (&link, "--out"),
        (&fifo, "--out"),
        (&foreign, "not a rebound output"),
        (&sub_foreign, "not a rebound output"),
    ] {
        surface(&case, out, "1", &[]).refused(needle);
        assert_eq!(snapshot(t, false), before, "{}", out.display());
    }
    // An existing empty directory is fine.
    let empty = t.join("empty");
    std::fs::create_dir(&empty).unwrap();
    surface(&case, &empty, "1", &[]).ok();
    assert!(empty.join("run.toml").is_file());
}

#[test]
fn default_shard_directories_survive_the_merge_into_their_parent() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let case = write_case(t, "c.toml", &stochastic_case("dflt", 4000));
    for k in ["1/2", "2/2"] {
        rebound_in(t, &["stochastic", "--case", s(&case), "--shard", k]).ok();
    }
    let parent = t.join("results/dflt/stochastic");
    let shards = [parent.join("shard-1-of-2"), parent.join("shard-2-of-2")];
    let before: Vec<_> = shards.iter().map(|d| snapshot(d, false)).collect();
    rebound_in(t, &["merge", s(&shards[0]), s(&shards[1])]).ok();
    assert!(parent.join("summary.csv").is_file());
    let after: Vec<_> = shards.iter().map(|d| snapshot(d, false)).collect();
    assert_eq!(after, before);
    // Merging again replaces the result and keeps the shards.
    rebound_in(t, &["merge", s(&shards[0]), s(&shards[1])]).ok();
    let after: Vec<_> = shards.iter().map(|d| snapshot(d, false)).collect();
    assert_eq!(after, before);
}

/// A small deterministic pseudo-random sequence (xorshift64*).
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn clock_seed() -> u64 {
    let n = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .unwrap()
        .as_nanos() as u64;
    (n ^ (u64::from(std::process::id()) << 32)) | 1
}

fn spawn_stochastic(case: &Path, out: &Path, seed: &str, stderr: Stdio) -> std::process::Child {
    TestCommand::new()
        .args([
            "stochastic",
            "--case",
            s(case),
            "--out",
            s(out),
            "--seed",
            seed,
        ])
        .cmd()
        .stdout(Stdio::null())
        .stderr(stderr)
        .spawn()
        .unwrap()
}

#[test]
fn kill_9_at_any_moment_leaves_the_old_or_the_new_result() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let case = write_case(t, "k.toml", &stochastic_case("kill", 800_000));
    let refs = t.join("refs");
    std::fs::create_dir(&refs).unwrap();
    let seeds = ["1", "2"];
    let mut reference = Vec::new();
    let mut took = Vec::new();
    for seed in seeds {
        let r = refs.join(seed);
        let t0 = Instant::now();
        stochastic(&case, &r, seed).ok();
        took.push(t0.elapsed().as_secs_f64());
        reference.push(snapshot(&r, true));
    }
    assert_ne!(reference[0], reference[1]);
    let mut run_s = took.iter().sum::<f64>() / took.len() as f64;
    let work = t.join("work");
    std::fs::create_dir(&work).unwrap();
    let d = work.join("D");
    stochastic(&case, &d, "1").ok();
    let mut holds = 0;
    let seed = clock_seed();
    let mut rng = Rng(seed);
    let (mut unchanged, mut replaced) = (0, 0);
    for trial in 0..32 {
        let next = 1 - holds;
        // Half the delays anywhere in the run, half in its last quarter (the writing).
        let f = if trial % 2 == 0 {
            1.1 * rng.unit()
        } else {
            0.75 + 0.35 * rng.unit()
        };
        let mut child = spawn_stochastic(&case, &d, seeds[next], Stdio::null());
        let t0 = Instant::now();
        let deadline = Duration::from_secs_f64(f * run_s);
        let status = loop {
            if let Some(st) = child.try_wait().unwrap() {
                // It finished first: follow the machine's current speed.
                run_s = 0.5 * run_s + 0.5 * t0.elapsed().as_secs_f64();
                break st;
            }
            if t0.elapsed() >= deadline {
                let _ = child.kill();
                break child.wait().unwrap();
            }
            std::thread::sleep(Duration::from_millis(2));
        };
        let now = snapshot(&d, true);
        let which = reference.iter().position(|r| *r == now);
        assert!(
            which.is_some(),
            "trial {trial} (seed {seed:#x}, delay {f:.2} of a run of {run_s:.3} s, {status}): D is neither result: {:?}",
            now.keys().collect::<Vec<_>>()
        );
        let which = which.unwrap();
        if which == holds {
            unchanged += 1;
        } else {
            replaced += 1;
        }
        holds = which;
        for n in names(&work) {
            assert!(
                n == "D" || n == ".D.lock" || n.starts_with(".D.staging-"),
                "trial {trial}: stray {n} beside D"
            );
        }
    }
    eprintln!(
        "kill -9: 32 trials (rng seed {seed:#x}, run {run_s:.3} s): {unchanged} left the old result, {replaced} the new one"
    );
    assert!(unchanged > 0, "no kill landed before the swap");
    // The next run removes what the killed runs left.
    stochastic(&case, &d, seeds[1 - holds]).ok();
    assert_eq!(snapshot(&d, true), reference[1 - holds]);
    assert_eq!(
        names(&work),
        BTreeSet::from(["D".to_string(), ".D.lock".to_string()])
    );
}

#[test]
fn concurrent_runs_on_one_out_leave_one_complete_result() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let case = write_case(t, "c.toml", &stochastic_case("conc", 150_000));
    let seeds = ["1", "2"];
    let reference: Vec<_> = seeds
        .iter()
        .map(|seed| {
            let r = t.join(format!("ref{seed}"));
            stochastic(&case, &r, seed).ok();
            snapshot(&r, true)
        })
        .collect();
    let work = t.join("work");
    std::fs::create_dir(&work).unwrap();
    let d = work.join("D");
    let mut refused = 0;
    for trial in 0..10 {
        let children: Vec<_> = seeds
            .iter()
            .map(|seed| spawn_stochastic(&case, &d, seed, Stdio::piped()))
            .collect();
        let mut ok = 0;
        for c in children {
            let o = c.wait_with_output().unwrap();
            let err = String::from_utf8_lossy(&o.stderr);
            match o.status.code() {
                Some(0) => ok += 1,
                Some(2) => {
                    refused += 1;
                    let lines: Vec<&str> = err.trim().lines().collect();
                    assert_eq!(lines.len(), 1, "trial {trial}: {err}");
                    assert!(
                        lines[0].contains("another rebound run is writing")
                            && lines[0].contains(".D.lock"),
                        "trial {trial}: {err}"
                    );
                }
                other => panic!("trial {trial}: exit {other:?}: {err}"),
            }
        }
        assert!(ok >= 1, "trial {trial}: no run succeeded");
        let now = snapshot(&d, true);
        assert!(
            reference.contains(&now),
            "trial {trial}: D is not one complete result"
        );
        assert_eq!(
            names(&work),
            BTreeSet::from(["D".to_string(), ".D.lock".to_string()])
        );
    }
    eprintln!("concurrency: 10 trials, {refused} runs refused by the lock");
}

/// A run stopped by SIGTERM, SIGINT or SIGHUP (a batch system's cancel or time limit, Ctrl-C)
/// removes its staging directory and exits with 128 + the signal: `--out` keeps its old
/// result and nothing hidden is left beside it.
#[test]
fn a_signal_leaves_the_old_result_and_no_staging_directory() {
    let tmp = tempfile::tempdir().unwrap();
    let t = tmp.path();
    let small = write_case(t, "small.toml", &stochastic_case("sig", 2_000));
    let long = write_case(t, "long.toml", &stochastic_case("sig", 50_000_000));
    let work = t.join("work");
    std::fs::create_dir(&work).unwrap();
    let d = work.join("D");
    stochastic(&small, &d, "1").ok();
    let before = snapshot(&d, false);
    for (sig, name) in [(15, "TERM"), (2, "INT"), (1, "HUP")] {
        let mut child = spawn_stochastic(&long, &d, "2", Stdio::null());
        // Until the run is computing into its staging directory.
        let t0 = Instant::now();
        while !names(&work).iter().any(|n| n.starts_with(".D.staging-")) {
            assert!(
                t0.elapsed() < Duration::from_secs(30),
                "no staging directory"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        std::thread::sleep(Duration::from_millis(100));
        let sent = std::process::Command::new("kill")
            .args([&format!("-{name}"), &child.id().to_string()])
            .status()
            .unwrap();
        assert!(sent.success());
        let status = child.wait().unwrap();
        assert_eq!(status.code(), Some(128 + sig), "SIG{name}: {status}");
        assert_eq!(snapshot(&d, false), before, "SIG{name} changed D");
        assert_eq!(
            names(&work),
            BTreeSet::from(["D".to_string(), ".D.lock".to_string()]),
            "SIG{name} left something beside D"
        );
    }
}
