//! Running the binary as an adversarial user's run is judged: under an address-space limit,
//! a file-size limit and a CPU-time limit (`ulimit`, so the verdict does not depend on how
//! busy the machine is), with a wall-clock cap for a run that blocks without computing.
//! Shared by the fuzz tests (`tests/fuzz_cases.rs`, `tests/fuzz_scans.rs`).

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The signal of a soft CPU-time limit.
pub const SIGXCPU: i32 = 24;

/// The limits of one run.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// `ulimit -v`, kB.
    pub mem_kb: u64,
    /// `ulimit -f` (dash counts 512-byte blocks).
    pub fsize_blocks: u64,
    /// `ulimit -S -t`, seconds of CPU time (SIGXCPU); a hard limit 5 s above it kills.
    pub cpu_s: u64,
    /// Wall-clock cap; SIGKILL after it.
    pub wall: Duration,
}

/// How a capped run ended.
pub struct Ran {
    /// Exit status, or `None` for a signal.
    pub code: Option<i32>,
    pub signal: Option<i32>,
    /// Over the CPU or the wall-clock cap.
    pub timed_out: bool,
    /// Its stderr (at most 1 MiB).
    pub stderr: String,
    pub seconds: f64,
}

/// Runs `bin args` in `dir` under `limits`, stdin and stdout closed, stderr kept.
pub fn run_capped(bin: &Path, args: &[String], dir: &Path, limits: Limits) -> Ran {
    let err_path = dir.join("stderr.txt");
    let err = std::fs::File::create(&err_path).unwrap();
    // Soft CPU limit first (SIGXCPU), then a hard one above it (SIGKILL if SIGXCPU is ignored).
    let script = format!(
        "ulimit -v {} && ulimit -f {} && ulimit -S -t {} && ulimit -H -t {} && exec \"$0\" \"$@\"",
        limits.mem_kb,
        limits.fsize_blocks,
        limits.cpu_s,
        limits.cpu_s + 5
    );
    let t0 = Instant::now();
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(bin)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(err)
        .spawn()
        .expect("spawn sh");
    let mut timed_out = false;
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if t0.elapsed() > limits.wall {
            timed_out = true;
            // SIGKILL to the process we started (sh exec'd into the binary: same pid).
            let _ = child.kill();
            break child.wait().expect("wait");
        }
        let e = t0.elapsed();
        std::thread::sleep(if e < Duration::from_millis(50) {
            Duration::from_millis(1)
        } else {
            Duration::from_millis(10)
        });
    };
    let seconds = t0.elapsed().as_secs_f64();
    use std::os::unix::process::ExitStatusExt;
    let timed_out = timed_out || status.signal() == Some(SIGXCPU);
    let bytes = std::fs::read(&err_path).unwrap_or_default();
    let stderr = String::from_utf8_lossy(&bytes[..bytes.len().min(1 << 20)]).into_owned();
    Ran {
        code: status.code(),
        signal: status.signal(),
        timed_out,
        stderr,
        seconds,
    }
}
