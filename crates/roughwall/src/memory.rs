//! What the process may still allocate, checked before every large allocation so that a
//! case too big for the machine ends with a one-line error instead of an abort.
//!
//! The bound is the least of: the address-space limit (`RLIMIT_AS`, e.g. `ulimit -v`) minus
//! what the process already maps; the cgroup's memory limit minus its usage (containers,
//! Slurm jobs); and the machine's `MemAvailable`. All three come from `/proc` and `/sys`, so
//! on a system without them nothing is checked.

use crate::error::{Error, Result};
use std::fmt::Display;

fn read(path: &str) -> Option<String> {
    std::fs::read_to_string(path).ok()
}

/// A `/proc` line `Key:   N kB` in bytes.
fn kb_field(text: &str, key: &str) -> Option<u64> {
    let line = text.lines().find(|l| l.starts_with(key))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb.saturating_mul(1024))
}

/// `RLIMIT_AS` (soft) minus the current virtual size; `None` when unlimited or unknown.
fn address_space_left() -> Option<u64> {
    let limits = read("/proc/self/limits")?;
    let line = limits
        .lines()
        .find(|l| l.starts_with("Max address space"))?;
    let soft = line.split_whitespace().nth(3)?;
    let limit: u64 = soft.parse().ok()?; // "unlimited" does not parse
    let used = kb_field(&read("/proc/self/status")?, "VmSize:")?;
    Some(limit.saturating_sub(used))
}

/// The cgroup (v2, else v1) memory limit minus the cgroup's usage.
fn cgroup_left() -> Option<u64> {
    let cgroup = read("/proc/self/cgroup")?;
    // v2: a line "0::/path".
    if let Some(path) = cgroup.lines().find_map(|l| l.strip_prefix("0::")) {
        let dir = format!("/sys/fs/cgroup{}", path.trim_end());
        let max =
            read(&format!("{dir}/memory.max")).or_else(|| read("/sys/fs/cgroup/memory.max"))?;
        let limit: u64 = max.trim().parse().ok()?; // "max" does not parse
        let used: u64 = read(&format!("{dir}/memory.current"))
            .or_else(|| read("/sys/fs/cgroup/memory.current"))
            .and_then(|s| s.trim().parse().ok())
            .unwrap_or(0);
        return Some(limit.saturating_sub(used));
    }
    let limit: u64 = read("/sys/fs/cgroup/memory/memory.limit_in_bytes")?
        .trim()
        .parse()
        .ok()?;
    if limit >= 1 << 60 {
        return None; // v1 writes a huge number for "no limit"
    }
    let used: u64 = read("/sys/fs/cgroup/memory/memory.usage_in_bytes")
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(0);
    Some(limit.saturating_sub(used))
}

/// Bytes the process may still allocate, `None` if nothing bounds it that we can read.
pub fn available_bytes() -> Option<u64> {
    let mem_available = read("/proc/meminfo").and_then(|t| kb_field(&t, "MemAvailable:"));
    [address_space_left(), cgroup_left(), mem_available]
        .into_iter()
        .flatten()
        .min()
}

/// Bytes as people read them.
pub fn human(bytes: u64) -> String {
    let b = bytes as f64;
    if b >= (1u64 << 30) as f64 {
        format!("{:.1} GiB", b / (1u64 << 30) as f64)
    } else {
        format!("{:.0} MiB", (b / (1u64 << 20) as f64).ceil())
    }
}

/// What every refusal of [`require`] allows, after `allowed `: a caller that must tell a
/// size refused for memory from another bad value (the Python bindings raise `MemoryError`)
/// looks for it.
pub const FITS_IN_MEMORY: &str = "a size that fits in memory";

/// Refuses with a one-line input error naming `key = value` when `bytes` (what `what`
/// needs) exceed what the process may allocate.
pub fn require(key: &str, value: impl Display, bytes: u64, what: &str) -> Result<()> {
    match available_bytes() {
        Some(avail) if bytes > avail => Err(Error::invalid(
            key,
            value,
            &format!(
                "{FITS_IN_MEMORY}: {what} needs {}, the process may use {} (the least of the address-space limit, the cgroup limit and the free memory)",
                human(bytes),
                human(avail)
            ),
        )),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_machine_has_some_memory_and_absurd_requests_are_refused() {
        let a = available_bytes().expect("Linux /proc");
        assert!(a > 1 << 20);
        let e = require("surface.nodes", 40000, u64::MAX, "a 40000² grid").unwrap_err();
        let m = e.to_string();
        assert!(
            m.contains("surface.nodes") && m.contains("40000") && !m.contains('\n'),
            "{m}"
        );
        assert!(m.contains(&format!("allowed {FITS_IN_MEMORY}:")), "{m}");
        assert!(require("surface.nodes", 16, 1024, "a tiny grid").is_ok());
        assert_eq!(human(3 << 30), "3.0 GiB");
    }
}
