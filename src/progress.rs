//! Progress bars for long runs: shown on an interactive terminal only, never in CI
//! or when stderr is piped (so logs and tests stay clean).

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};

/// Set by [`hide`] (`--quiet`).
static HIDDEN: AtomicBool = AtomicBool::new(false);

/// No progress bar from now on, even on a terminal (`--quiet`).
pub fn hide() {
    HIDDEN.store(true, Ordering::Relaxed);
}

/// Whether progress should be drawn: stderr is a terminal, `CI` is not set, and not hidden.
fn visible() -> bool {
    !HIDDEN.load(Ordering::Relaxed)
        && std::io::stderr().is_terminal()
        && std::env::var_os("CI").is_none()
}

/// Progress of a Monte Carlo run counted in particles: rate, ETA and, under a target
/// standard error, the current error.
pub struct Progress {
    bar: ProgressBar,
}

impl Progress {
    /// A bar over `total` particles, labelled `label` (hidden when not on a terminal).
    pub fn particles(total: u64, label: &str) -> Progress {
        let bar = if visible() {
            let pb = ProgressBar::new(total);
            pb.set_style(
                ProgressStyle::with_template(
                    "{prefix} [{bar:30}] {human_pos}/{human_len} particles, {per_sec}, ETA {eta} {msg}",
                )
                .unwrap_or_else(|_| ProgressStyle::default_bar())
                .progress_chars("=> "),
            );
            pb.set_prefix(label.to_string());
            pb
        } else {
            ProgressBar::hidden()
        };
        Progress { bar }
    }

    /// `n` more particles done.
    pub fn advance(&self, n: u64) {
        self.bar.inc(n);
    }

    /// `n` planned particles that will not run (a condition reached its target).
    pub fn skip(&self, n: u64) {
        if let Some(len) = self.bar.length() {
            self.bar.set_length(len.saturating_sub(n));
        }
    }

    /// A short note after the bar (e.g. the current standard error).
    pub fn note(&self, msg: &str) {
        self.bar.set_message(msg.to_string());
    }

    /// Removes the bar.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

impl roughwall::tally::engine::Progress for Progress {
    fn advance(&self, n: u64) {
        Progress::advance(self, n)
    }

    fn skip(&self, n: u64) {
        Progress::skip(self, n)
    }

    fn note(&self, msg: &str) {
        Progress::note(self, msg)
    }
}
