//! Progress of long runs. On an interactive terminal, a bar (never in CI). On any other
//! stderr — a batch job's log — plain lines: an estimate of the whole run once it has run for
//! a second, then a line every `--log-every` seconds (30 by default), so a log shows a run
//! is alive and when it will end. A run shorter than a second prints nothing; `--quiet`
//! silences both.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Set by [`hide`] (`--quiet`).
static HIDDEN: AtomicBool = AtomicBool::new(false);

/// Seconds between two log lines, as `f64` bits (`--log-every`; 0: none).
static LOG_EVERY_S: AtomicU64 = AtomicU64::new(f64::to_bits(30.0));

/// How long a run goes before its log gives an estimate.
const ESTIMATE_AFTER: Duration = Duration::from_secs(1);

/// No progress from now on, neither bar nor log lines (`--quiet`).
pub fn hide() {
    HIDDEN.store(true, Ordering::Relaxed);
}

/// Seconds between two progress lines on a non-terminal stderr (`--log-every`; 0: none).
pub fn set_log_every(seconds: f64) {
    LOG_EVERY_S.store(seconds.to_bits(), Ordering::Relaxed);
}

fn log_every() -> Option<Duration> {
    let s = f64::from_bits(LOG_EVERY_S.load(Ordering::Relaxed));
    (s > 0.0).then(|| Duration::from_secs_f64(s))
}

/// Progress of a Monte Carlo run counted in particles: a bar with rate, ETA and, under a
/// target standard error, the current error; or log lines.
pub struct Progress {
    bar: ProgressBar,
    log: Option<Mutex<Log>>,
}

/// What the log lines need: the run's label, its planned particles, what is done.
struct Log {
    label: String,
    total: u64,
    done: u64,
    started: Instant,
    estimated: bool,
    last_line: Instant,
    /// Time between two lines after the estimate (`None`: no lines).
    every: Option<Duration>,
    note: String,
}

impl Log {
    /// The lines due after `done` changed: the estimate once, then one per interval.
    fn lines(&mut self) -> Option<String> {
        let now = Instant::now();
        let elapsed = now.duration_since(self.started).as_secs_f64();
        let rate = self.done as f64 / elapsed.max(1e-9);
        let left = (self.total.saturating_sub(self.done)) as f64 / rate.max(1e-9);
        if !self.estimated {
            if now.duration_since(self.started) < ESTIMATE_AFTER || self.done == 0 {
                return None;
            }
            self.estimated = true;
            self.last_line = now;
            return Some(format!(
                "{}: {} particles planned, {:.0} particles/s so far: about {} in all",
                self.label,
                self.total,
                rate,
                duration(elapsed + left)
            ));
        }
        let every = self.every?;
        if now.duration_since(self.last_line) < every {
            return None;
        }
        self.last_line = now;
        let pct = 100.0 * self.done as f64 / self.total.max(1) as f64;
        let note = if self.note.is_empty() {
            String::new()
        } else {
            format!("; {}", self.note)
        };
        Some(format!(
            "{}: {}/{} particles ({pct:.1} %) after {}, about {} left{note}",
            self.label,
            self.done,
            self.total,
            duration(elapsed),
            duration(left)
        ))
    }
}

/// `s` seconds as `12 s`, `3 min 20 s` or `2 h 5 min`.
fn duration(s: f64) -> String {
    let s = s.max(0.0).round() as u64;
    match s {
        0..=99 => format!("{s} s"),
        100..=5999 => format!("{} min {} s", s / 60, s % 60),
        _ => format!("{} h {} min", s / 3600, (s % 3600) / 60),
    }
}

impl Progress {
    /// Progress over `total` particles, labelled `label`: a bar on a terminal, log lines on
    /// any other stderr, nothing under `--quiet`.
    pub fn particles(total: u64, label: &str) -> Progress {
        let hidden = HIDDEN.load(Ordering::Relaxed);
        let terminal = std::io::stderr().is_terminal();
        let bar = if !hidden && terminal && std::env::var_os("CI").is_none() {
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
        let now = Instant::now();
        let log = (!hidden && !terminal).then(|| {
            Mutex::new(Log {
                label: label.to_string(),
                total,
                done: 0,
                started: now,
                estimated: false,
                last_line: now,
                every: log_every(),
                note: String::new(),
            })
        });
        Progress { bar, log }
    }

    fn with_log(&self, f: impl FnOnce(&mut Log)) {
        if let Some(log) = &self.log {
            let mut log = log.lock().unwrap_or_else(|e| e.into_inner());
            f(&mut log);
            if let Some(line) = log.lines() {
                eprintln!("{line}");
            }
        }
    }

    /// `n` more particles done.
    pub fn advance(&self, n: u64) {
        self.bar.inc(n);
        self.with_log(|l| l.done += n);
    }

    /// `n` planned particles that will not run (a condition reached its target).
    pub fn skip(&self, n: u64) {
        if let Some(len) = self.bar.length() {
            self.bar.set_length(len.saturating_sub(n));
        }
        self.with_log(|l| l.total = l.total.saturating_sub(n));
    }

    /// A short note after the bar or the log line (e.g. the current standard error).
    pub fn note(&self, msg: &str) {
        self.bar.set_message(msg.to_string());
        if let Some(log) = &self.log {
            log.lock().unwrap_or_else(|e| e.into_inner()).note = msg.to_string();
        }
    }

    /// Removes the bar.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

impl roughwall::tally::Progress for Progress {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_read_like_a_clock() {
        assert_eq!(duration(0.4), "0 s");
        assert_eq!(duration(42.0), "42 s");
        assert_eq!(duration(200.0), "3 min 20 s");
        assert_eq!(duration(7500.0), "2 h 5 min");
    }

    #[test]
    fn a_log_estimates_once_then_writes_every_interval() {
        let every = Duration::from_secs(10);
        let start = Instant::now() - Duration::from_secs(2);
        let mut log = Log {
            label: "stochastic".into(),
            total: 1000,
            done: 100,
            started: start,
            estimated: false,
            last_line: start,
            every: Some(every),
            note: String::new(),
        };
        let first = log.lines().unwrap();
        assert!(
            first.starts_with("stochastic: 1000 particles planned"),
            "{first}"
        );
        assert!(first.ends_with("about 20 s in all"), "{first}");
        assert_eq!(log.lines(), None, "a line before its interval");
        // An interval later (the last line moved back instead of waiting for it).
        log.last_line -= every;
        log.done = 500;
        let line = log.lines().unwrap();
        assert!(
            line.starts_with("stochastic: 500/1000 particles (50.0 %) after 2 s"),
            "{line}"
        );
        assert_eq!(log.lines(), None, "two lines in one interval");
        log.every = None;
        log.last_line -= every;
        assert_eq!(log.lines(), None, "--log-every 0 writes no lines");
    }
}
