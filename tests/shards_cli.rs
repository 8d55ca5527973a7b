//! Monte Carlo at any scale through the binary: standard errors in the outputs, a target
//! standard error, `--shard K/N` and `rebound merge` giving the bytes of one process,
//! and the refusals of bad shards.

use crate::common::*;
use std::path::{Path, PathBuf};

/// Two conditions, counts that are not multiples of the 65 536-particle block, both models.
const CASE: &str = r#"name = "shards"
seed = 11
[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-5.0, -25.0]
beta_deg = [60.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16
[particles]
count = 140000
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
[deterministic]
side_per_corr_length = 20.0
"#;

fn out(dir: &Path, name: &str) -> PathBuf {
    dir.join(name)
}

/// Runs `command` in one process and as `n` shards merged; returns both output folders.
fn one_and_merged(dir: &Path, case: &Path, command: &str, n: u32) -> (PathBuf, PathBuf) {
    let one = out(dir, &format!("{command}-one"));
    rebound(&[
        command,
        "--case",
        case.to_str().unwrap(),
        "--out",
        one.to_str().unwrap(),
    ])
    .ok();
    let mut shards = Vec::new();
    // Shards in a scrambled order and with another thread count: neither may matter.
    for k in (1..=n).rev() {
        let d = out(dir, &format!("{command}-shard{k}"));
        rebound(&[
            command,
            "--case",
            case.to_str().unwrap(),
            "--shard",
            &format!("{k}/{n}"),
            "--threads",
            "1",
            "--out",
            d.to_str().unwrap(),
        ])
        .ok();
        assert!(d.join("partial.toml").is_file());
        assert!(
            !d.join("summary.csv").exists(),
            "a shard writes no final outputs"
        );
        shards.push(d);
    }
    let merged = out(dir, &format!("{command}-merged"));
    merge_shards(&merged, &shards);
    (one, merged)
}

#[test]
fn shards_merged_are_byte_identical_to_one_process_for_both_models() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", CASE);
    for command in ["stochastic", "deterministic"] {
        let (one, merged) = one_and_merged(tmp.path(), &case, command, 3);
        let a = csv_files(&one);
        assert_eq!(
            a.iter().map(|f| f.0.as_str()).collect::<Vec<_>>(),
            ["moments.csv", "pdfs.csv", "summary.csv"]
        );
        assert_eq!(a, csv_files(&merged), "{command}: merged CSVs differ");
        // The figures are drawn from the same tallies: the same bytes too.
        for f in std::fs::read_dir(&one).unwrap().filter_map(|e| e.ok()) {
            let name = f.file_name();
            if name.to_string_lossy().ends_with(".svg") {
                assert_eq!(
                    std::fs::read(f.path()).unwrap(),
                    std::fs::read(merged.join(&name)).unwrap(),
                    "{command}: {name:?}"
                );
            }
        }
        let manifest = std::fs::read_to_string(merged.join("run.toml")).unwrap();
        assert!(manifest.contains("merged_shards = 3"), "{manifest}");
    }
}

#[test]
fn summary_has_standard_errors_that_match_the_spread() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", CASE);
    let o = out(tmp.path(), "o");
    rebound(&[
        "stochastic",
        "--case",
        case.to_str().unwrap(),
        "--out",
        o.to_str().unwrap(),
    ])
    .ok();
    let s = Csv::read(&o.join("summary.csv"));
    // The first version's 20 columns keep their places; standard errors come after.
    assert_eq!(s.header[19], "lost");
    assert_eq!(s.header[20], "se_mean_alpha_out_deg");
    for row in &s.rows {
        let n = s.num(row, "particles");
        assert_eq!(n, 140_000.0);
        for q in ["alpha_out", "dbeta", "gamma", "gamma_star"] {
            let sd = s.num(row, &format!("std_{q}_deg"));
            let se = s.num(row, &format!("se_mean_{q}_deg"));
            assert!(
                (se - sd / n.sqrt()).abs() <= 1e-6 * se.max(1e-12),
                "{q}: {se} vs {sd}"
            );
        }
        // p_single = accepted / candidates, its error from the spread of candidates.
        let p = s.num(row, "p_single");
        let se = s.num(row, "se_p_single");
        assert!(p > 0.5 && p <= 1.0 && se > 0.0 && se < 0.01, "{p} ± {se}");
        for na in ["se_mean_dbeta_first_deg", "se_mean_collisions"] {
            assert_eq!(
                s.cell(row, na),
                "",
                "{na} does not apply to the stochastic model"
            );
        }
    }
    // Every PDF bin of a density has its binomial error; model curves have none.
    let p = Csv::read(&o.join("pdfs.csv"));
    assert_eq!(p.header.last().map(String::as_str), Some("se"));
    for row in &p.rows {
        let q = p.cell(row, "quantity");
        let se = p.cell(row, "se");
        if q == "gamma_model" {
            assert_eq!(se, "", "{row:?}");
        } else {
            let v = p.num(row, "value");
            let w = p.num(row, "bin_hi") - p.num(row, "bin_lo");
            let se: f64 = se.parse().unwrap();
            let n = if q.starts_with("gamma_star_given") {
                0.0
            } else {
                140_000.0
            };
            if n > 0.0 {
                let pb = v * w;
                assert!(
                    (se - (pb * (1.0 - pb) / n).sqrt() / w).abs() <= 1e-6 * se.max(1e-9),
                    "{row:?}"
                );
            }
        }
    }
    let m = Csv::read(&o.join("moments.csv"));
    assert_eq!(
        m.header,
        [
            "alpha_in_deg",
            "beta_in_deg",
            "quantity",
            "n",
            "mean",
            "std",
            "se",
            "se_histories"
        ]
    );
    // One surface (the stochastic model): the error of independent values.
    for row in &m.rows {
        assert_eq!(m.cell(row, "se"), m.cell(row, "se_histories"), "{row:?}");
    }
    assert!(m
        .rows
        .iter()
        .any(|r| m.cell(r, "quantity") == "speed_ratio"));
}

#[test]
fn a_target_error_stops_at_whole_blocks_and_is_recorded() {
    let tmp = Dir::new();
    let case = write_case(
        tmp.path(),
        "c.toml",
        &CASE.replace("count = 140000", "count = 2000000"),
    );
    let mut rows = Vec::new();
    for threads in ["1", "2"] {
        let o = out(tmp.path(), &format!("t{threads}"));
        rebound(&[
            "stochastic",
            "--case",
            case.to_str().unwrap(),
            "--target-se",
            "0.02",
            "--threads",
            threads,
            "--out",
            o.to_str().unwrap(),
        ])
        .ok();
        rows.push(csv_files(&o));
        let s = Csv::read(&o.join("summary.csv"));
        for row in &s.rows {
            let n = s.num(row, "particles") as u64;
            assert!(n.is_multiple_of(65_536) && n < 2_000_000, "{n}");
            assert!(s.num(row, "se_mean_alpha_out_deg") <= 0.02);
            assert!(s.num(row, "se_mean_dbeta_deg") <= 0.02);
        }
        let manifest = std::fs::read_to_string(o.join("run.toml")).unwrap();
        for key in [
            "target_se_deg = 0.02",
            "target_reached = true",
            "blocks = ",
            "se_mean_alpha_out_deg = ",
        ] {
            assert!(manifest.contains(key), "run.toml lacks {key}");
        }
    }
    assert_eq!(
        rows[0], rows[1],
        "the stopping point depends on the thread count"
    );
    // The case key does the same as the flag.
    let keyed = write_case(
        tmp.path(),
        "k.toml",
        &CASE.replace("count = 140000", "count = 2000000\ntarget_se_deg = 0.02"),
    );
    let o = out(tmp.path(), "keyed");
    rebound(&[
        "stochastic",
        "--case",
        keyed.to_str().unwrap(),
        "--out",
        o.to_str().unwrap(),
    ])
    .ok();
    assert_eq!(csv_files(&o), rows[0]);
}

#[test]
fn bad_shards_targets_and_merges_are_one_line_errors_and_write_nothing() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", CASE);
    let c = case.to_str().unwrap();
    let never = out(tmp.path(), "never");
    let nv = never.to_str().unwrap();
    for (args, needle) in [
        (
            vec!["stochastic", "--case", c, "--shard", "0/4", "--out", nv],
            "--shard",
        ),
        (
            vec!["stochastic", "--case", c, "--shard", "5/4", "--out", nv],
            "--shard",
        ),
        (
            vec!["deterministic", "--case", c, "--shard", "x", "--out", nv],
            "--shard",
        ),
        (
            vec!["stochastic", "--case", c, "--target-se", "0", "--out", nv],
            "--target-se",
        ),
        (
            vec!["stochastic", "--case", c, "--target-se", "-1", "--out", nv],
            "--target-se",
        ),
        (
            vec!["stochastic", "--case", c, "--target-se", "nan", "--out", nv],
            "--target-se",
        ),
        (
            vec![
                "stochastic",
                "--case",
                c,
                "--target-se",
                "0.1",
                "--shard",
                "1/2",
                "--out",
                nv,
            ],
            "--shard",
        ),
        (vec!["merge", "--out", nv], "SHARD_DIR"),
    ] {
        rebound(&args).refused(needle);
        assert!(!never.exists(), "{args:?} wrote output");
    }
    let bad_key = write_case(
        tmp.path(),
        "b.toml",
        &CASE.replace("count = 140000", "target_se_deg = -0.5"),
    );
    rebound(&[
        "stochastic",
        "--case",
        bad_key.to_str().unwrap(),
        "--out",
        nv,
    ])
    .refused("particles.target_se_deg");

    // Four shards of one run, and shards that do not belong to it.
    let shard = |k: u32, n: u32, seed: &str, name: &str| {
        let d = out(tmp.path(), name);
        rebound(&[
            "stochastic",
            "--case",
            c,
            "--seed",
            seed,
            "--shard",
            &format!("{k}/{n}"),
            "--out",
            d.to_str().unwrap(),
        ])
        .ok();
        d.display().to_string()
    };
    let s: Vec<String> = (1..=4)
        .map(|k| shard(k, 4, "11", &format!("s{k}")))
        .collect();
    let other_seed = shard(4, 4, "12", "seed12");
    let other_n = shard(3, 3, "11", "of3");
    let det = out(tmp.path(), "det4");
    rebound(&[
        "deterministic",
        "--case",
        c,
        "--shard",
        "4/4",
        "--out",
        det.to_str().unwrap(),
    ])
    .ok();
    let other_case = write_case(
        tmp.path(),
        "d.toml",
        &CASE.replace("seed = 11", "seed = 11\n# edited"),
    );
    let edited = out(tmp.path(), "edited4");
    rebound(&[
        "stochastic",
        "--case",
        other_case.to_str().unwrap(),
        "--seed",
        "11",
        "--shard",
        "4/4",
        "--out",
        edited.to_str().unwrap(),
    ])
    .ok();
    let text = std::fs::read_to_string(Path::new(&s[3]).join("partial.toml")).unwrap();
    let truncated = out(tmp.path(), "truncated.toml");
    std::fs::write(&truncated, &text[..text.len() / 2]).unwrap();
    let corrupt = out(tmp.path(), "corrupt.toml");
    std::fs::write(&corrupt, text.replacen("capped = 0", "capped = 1", 1)).unwrap();
    let merge = |last: &str, needle: &str| {
        let args = ["merge", "--out", nv, &s[0], &s[1], &s[2], last];
        rebound(&args).refused(needle);
        assert!(!never.exists(), "{needle}: output written");
    };
    merge(&other_seed, "seed");
    merge(&other_n, "number of shards");
    merge(&det.display().to_string(), "command");
    merge(&edited.display().to_string(), "case");
    merge(&s[2], "twice");
    merge(truncated.to_str().unwrap(), "truncated");
    merge(corrupt.to_str().unwrap(), "corrupt");
    rebound(&["merge", "--out", nv, &s[0], &s[1], &s[2]]).refused("missing");
    // The four together do merge.
    rebound(&["merge", "--out", nv, &s[0], &s[1], &s[2], &s[3]]).ok();
    assert!(never.join("summary.csv").is_file());
}

/// The `version = "…"` line of a partial tally: its build identity.
fn partial_version(text: &str) -> String {
    text.lines()
        .find_map(|l| l.strip_prefix("version = \""))
        .and_then(|v| v.strip_suffix('"'))
        .expect("a version line")
        .to_string()
}

#[test]
fn shards_of_another_build_are_refused_naming_the_shard_and_both_versions() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", CASE);
    let shard = |k: u32| {
        let d = out(tmp.path(), &format!("s{k}"));
        run_case("stochastic", &case, &d, &["--shard", &format!("{k}/2")]);
        d
    };
    let (s1, s2) = (shard(1), shard(2));

    // The build identity: the package version and a digest of the sources, the same in
    // `--version`, in the partial tally and in the merged `run.toml`.
    let file = s2.join("partial.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let this = partial_version(&text);
    let (package, digest) = this.split_once("+src.").expect("VERSION+src.DIGEST");
    assert_eq!(package, env!("CARGO_PKG_VERSION"));
    assert!(
        digest.len() == 16 && digest.bytes().all(|b| b.is_ascii_hexdigit()),
        "{this}"
    );
    let shown = rebound(&["--version"]).ok().stdout;
    assert_eq!(shown.trim(), format!("rebound {this}"));
    let together = out(tmp.path(), "together");
    rebound(&[
        "merge",
        "--out",
        together.to_str().unwrap(),
        s1.to_str().unwrap(),
        s2.to_str().unwrap(),
    ])
    .ok();
    let manifest = std::fs::read_to_string(together.join("run.toml")).unwrap();
    assert!(
        manifest.contains(&format!("version = \"{this}\"")),
        "{manifest}"
    );

    // The same package version from other sources: only the digest differs, and the file
    // stays valid (its checksum recomputed: `# sha256 ` and the SHA-256 of the body).
    let other_digest = if digest == "0123456789abcdef" {
        "fedcba9876543210"
    } else {
        "0123456789abcdef"
    };
    let other = format!("{package}+src.{other_digest}");
    let body = &text[..text.trim_end().rfind('\n').unwrap() + 1];
    assert_eq!(sealed(body), text);
    let needle = format!("version = \"{this}\"\n");
    assert_eq!(body.matches(&needle).count(), 1);
    let rewritten = body.replacen(&needle, &format!("version = \"{other}\"\n"), 1);
    std::fs::write(&file, sealed(&rewritten)).unwrap();

    let never = out(tmp.path(), "never");
    let run = rebound(&[
        "merge",
        "--out",
        never.to_str().unwrap(),
        s1.to_str().unwrap(),
        s2.to_str().unwrap(),
    ]);
    run.refused(&file.display().to_string());
    run.refused(&format!(
        "written by rebound {other}, this is rebound {this}"
    ));
    assert!(!never.exists(), "a refused merge wrote output");
}

/// A partial tally's text: `body` and its checksum line, as `docs/scale.md` describes it.
fn sealed(body: &str) -> String {
    use sha2::Digest;
    let hex: String = sha2::Sha256::digest(body.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    format!("{body}# sha256 {hex}\n")
}

/// An edited tally whose checksum was recomputed must still add up: a NaN mean, a particle
/// count that disagrees with the records, or a histogram that does not hold its records'
/// values is refused naming the shard; the untouched shards merge.
#[test]
fn an_edited_tally_with_a_recomputed_checksum_is_refused() {
    let tmp = Dir::new();
    let case = write_case(tmp.path(), "c.toml", CASE);
    let shards: Vec<PathBuf> = (1..=2)
        .map(|k| {
            let d = out(tmp.path(), &format!("s{k}"));
            run_case("stochastic", &case, &d, &["--shard", &format!("{k}/2")]);
            d
        })
        .collect();
    let file = shards[1].join("partial.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let body = &text[..text.trim_end().rfind('\n').unwrap() + 1];
    let merge = |name: &str| {
        let o = out(tmp.path(), name);
        let r = rebound(&[
            "merge",
            "--out",
            o.to_str().unwrap(),
            shards[0].to_str().unwrap(),
            shards[1].to_str().unwrap(),
        ]);
        (r, o)
    };
    let (r, _) = merge("fine");
    assert_eq!(r.code, 0, "{}", r.stderr);
    // The first record's first mean (α⁺ of the first block), as bits: NaN.
    let records = body.find("records = [\"").unwrap() + "records = [\"".len();
    let fields: Vec<&str> = body[records..].split(' ').take(3).collect();
    let nan = body.replacen(
        &format!("{} {} {}", fields[0], fields[1], fields[2]),
        &format!("{} {} 7ff8000000000000", fields[0], fields[1]),
        1,
    );
    // The first condition's particle count, one more.
    let line = body
        .lines()
        .find(|l| l.starts_with("particles = ") && !l.contains('"'))
        .unwrap();
    let n: u64 = line["particles = ".len()..].parse().unwrap();
    let more = body.replacen(line, &format!("particles = {}", n + 1), 1);
    // The first histogram's first count (after its first bin's index), one more: it no
    // longer holds its records' values.
    let hist = body.find("histograms = [[").unwrap() + "histograms = [[".len();
    let index: &str = body[hist..].split(", ").next().unwrap();
    let at = hist + index.len() + ", ".len();
    let first: &str = body[at..].split(',').next().unwrap();
    let count: u64 = first.parse().unwrap();
    let binned = format!("{}{}{}", &body[..at], count + 1, &body[at + first.len()..]);
    // More single-collision histories than histories followed.
    let single = body.replacen("\nsingle = 0\n", &format!("\nsingle = {}\n", n + 1), 1);
    for (edited, needle) in [
        (nan, "impossible moments"),
        (more, "but its records follow"),
        (binned, "histogram 0 holds"),
        (single, "single-collision histories of"),
    ] {
        assert_ne!(edited, body);
        std::fs::write(&file, sealed(&edited)).unwrap();
        let (r, o) = merge("never");
        r.refused("an edited or corrupted tally");
        r.refused(needle);
        r.refused(&file.display().to_string());
        assert!(!o.exists(), "a refused merge wrote output");
    }
}

/// With several surface realisations the partial tally carries each realisation's moments
/// and counts (for the ensemble standard errors); an edited one must add up too: a
/// realisation's count of values that no longer sums to its block's, or integer tallies
/// that no longer sum to the condition's, is refused naming the shard.
#[test]
fn an_edited_realisation_tally_is_refused() {
    let tmp = Dir::new();
    let case = write_case(
        tmp.path(),
        "c.toml",
        "name = \"t\"\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n[incidence]\n\
         alpha_deg = [-12.5]\nbeta_deg = [0.0]\n[particles]\ncount = 2000\n[collision]\n\
         model = \"elastic\"\n[deterministic]\nside_per_corr_length = 10.0\nsurfaces = 2\n",
    );
    let shard = out(tmp.path(), "s1");
    run_case("deterministic", &case, &shard, &["--shard", "1/1"]);
    let file = shard.join("partial.toml");
    let text = std::fs::read_to_string(&file).unwrap();
    let body = &text[..text.trim_end().rfind('\n').unwrap() + 1];
    let merge = || {
        let o = out(tmp.path(), "merged");
        (
            rebound(&[
                "merge",
                "--out",
                o.to_str().unwrap(),
                shard.to_str().unwrap(),
            ]),
            o,
        )
    };
    let (r, o) = merge();
    assert_eq!(r.code, 0, "{}", r.stderr);
    std::fs::remove_dir_all(&o).unwrap();
    // The record's first per-realisation triple follows the block index and 15 triples.
    let start = body.find("records = [\"").unwrap() + "records = [\"".len();
    let tokens: Vec<&str> = body[start..].split(' ').take(47).collect();
    let prefix = tokens[..46].join(" ");
    let n: u64 = tokens[46].parse().unwrap();
    let moved = body.replacen(
        &format!("{prefix} {n} "),
        &format!("{prefix} {} ", n + 1),
        1,
    );
    // The first realisation's followed histories, one more.
    let at = body.find("realisation_counts = [[").unwrap() + "realisation_counts = [[".len();
    let followed: &str = body[at..].split(',').next().unwrap();
    let counts = format!(
        "{}{}{}",
        &body[..at],
        followed.parse::<u64>().unwrap() + 1,
        &body[at + followed.len()..]
    );
    for (edited, needle) in [
        (moved, "its realisations"),
        (counts, "its realisations follow"),
    ] {
        assert_ne!(edited, body);
        std::fs::write(&file, sealed(&edited)).unwrap();
        let (r, o) = merge();
        r.refused("an edited or corrupted tally");
        r.refused(needle);
        assert!(!o.exists(), "a refused merge wrote output");
    }
}
