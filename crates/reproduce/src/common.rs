//! Helpers the report's sections share: number cells, "missing run" notes, run directories.

use outputs::csv::Rows;
use roughwall::Result;
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// `x` with `digits` decimals, "–" when absent or not finite.
pub(super) fn f(x: Option<f64>, digits: usize) -> String {
    x.filter(|v| v.is_finite())
        .map_or("–".into(), |v| format!("{v:.digits$}"))
}

/// `x` as a percentage with two decimals, "–" when absent or not finite.
pub(super) fn pct(x: Option<f64>) -> String {
    x.filter(|v| v.is_finite())
        .map_or("–".into(), |v| format!("{:.2} %", 100.0 * v))
}

/// A check's verdict: "yes", "**no**", or "–" when it could not be made.
pub(super) fn yes(b: Option<bool>) -> &'static str {
    match b {
        Some(true) => "yes",
        Some(false) => "**no**",
        None => "–",
    }
}

/// The bias goal of the wall's own model (issue 39, part 4: |bias of mean α⁺| ≤ 0.05°, or
/// twice the noise floor's where that is larger); also the least bias counted as a miss
/// beyond a noise floor however small the floor.
pub(super) const GOAL_BIAS_DEG: f64 = 0.05;

/// The verdict of a difference from a reference, the largest KS distance and |bias of mean
/// α⁺| (degrees) over its directions, against a noise floor's (issue 39, part 3: a miss is
/// only what exceeds twice the floor, the bias also [`GOAL_BIAS_DEG`]), in words that follow
/// "…: " in a report line; `misses` is what would miss, with its verb ("the Gaussian
/// assumption misses").
pub(super) fn against_twice_floor(
    misses: &str,
    (ks, bias): (f64, f64),
    (floor_ks, floor_bias): (f64, f64),
) -> String {
    let ratio = |a: f64, b: f64| a / b.max(f64::MIN_POSITIVE);
    let (rk, rb) = (ratio(ks, floor_ks), ratio(bias, floor_bias));
    match (
        ks > 2.0 * floor_ks,
        bias > (2.0 * floor_bias).max(GOAL_BIAS_DEG),
    ) {
        (true, true) => format!(
            "**{misses}** this wall beyond twice that floor (KS {rk:.1}×, bias {rb:.1}× the floor)"
        ),
        (false, true) => format!(
            "within twice that floor in KS ({rk:.1}×) but **beyond it in mean α⁺** ({rb:.1}×)"
        ),
        (true, false) => format!(
            "**beyond twice that floor in KS** ({rk:.1}×), within it in mean α⁺ ({rb:.1}×)"
        ),
        (false, false) => format!(
            "within twice that floor (KS {rk:.1}×, bias {rb:.1}×): the scan cannot tell its wall from a Gaussian one"
        ),
    }
}

/// Says that a section's input `path` is missing and which script writes it (`what`).
pub(super) fn missing(md: &mut String, what: &str, path: &Path) {
    let _ = writeln!(md, "*Not run: `{}` is missing ({what}).*\n", path.display());
}

/// `path` relative to `root` (for links in `REPORT.md`).
pub(super) fn rel(path: &Path, root: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .display()
        .to_string()
}

/// Subdirectories of `dir` whose names start with `prefix`, sorted.
pub(super) fn subdirs(dir: &Path, prefix: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| {
                    p.is_dir()
                        && p.file_name()
                            .is_some_and(|n| n.to_string_lossy().starts_with(prefix))
                })
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// Rows of a deterministic or stochastic `summary.csv`.
pub(super) fn summary(dir: &Path) -> Result<Option<Rows>> {
    Rows::read(&dir.join("summary.csv"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_miss_is_what_exceeds_twice_the_floor_said_apart_in_ks_and_bias() {
        let v = |d, f| against_twice_floor("it misses", d, f);
        assert!(v((0.3, 2.0), (0.1, 0.5))
            .starts_with("**it misses** this wall beyond twice that floor (KS 3.0×, bias 4.0×"));
        assert!(v((0.15, 2.0), (0.1, 0.5)).starts_with(
            "within twice that floor in KS (1.5×) but **beyond it in mean α⁺** (4.0×)"
        ));
        assert!(v((0.3, 0.9), (0.1, 0.5))
            .starts_with("**beyond twice that floor in KS** (3.0×), within it in mean α⁺ (1.8×)"));
        assert!(
            v((0.15, 0.9), (0.1, 0.5)).starts_with("within twice that floor (KS 1.5×, bias 1.8×)")
        );
        // However small the floor, a bias within the goal's 0.05° is no miss.
        assert!(v((0.01, 0.04), (0.01, 0.001))
            .starts_with("within twice that floor (KS 1.0×, bias 40.0×)"));
    }
}
