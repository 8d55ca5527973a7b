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

/// Whether a difference from a reference, the largest KS distance and |bias of mean α⁺|
/// (degrees) over its directions, exceeds twice a noise floor's (issue 39, part 3: a miss is
/// only what exceeds the floor), the bias also [`FLOOR_BIAS_MIN_DEG`]: (KS beyond, bias beyond).
pub(super) fn beyond_twice_floor(
    ks: f64,
    bias: f64,
    floor_ks: f64,
    floor_bias: f64,
) -> (bool, bool) {
    (
        ks > 2.0 * floor_ks,
        bias > (2.0 * floor_bias).max(FLOOR_BIAS_MIN_DEG),
    )
}

/// The least bias (degrees) counted as a miss however small the floor: issue 39's goal.
pub(super) const FLOOR_BIAS_MIN_DEG: f64 = 0.05;

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
