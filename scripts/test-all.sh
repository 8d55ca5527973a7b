#!/usr/bin/env bash
# Every test: installs what the tests against real systems need (scripts/install-deps.sh),
# then runs the hermetic tests of both crates (unit, integration and documentation tests,
# nothing but the Rust toolchain needed) and the tests against real systems (code_saturne,
# OpenFOAM, pysand, Slurm, gfortran). This is the README's test command and what CI runs.
#
# CI has 20 minutes on 2 cores, so the stages overlap where one alone leaves a core idle:
#   1. the install (downloads and dpkg: little CPU) runs beside the build of both suites;
#   2. the two suites run at once: the hermetic one ends on the reproduction script, one
#      process at a time, and the real systems wait on daemons, MPI start-up and downloads.
# One after another the stages kept 1.79 of 2 cores busy, overlapped 1.91: 758 s → 713 s from
# a fresh clone (docs/design-notes.md, "CI's time, second pass"). The hermetic suite's output
# streams; the real systems' is printed when both have finished.
#
# Usage: scripts/test-all.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# CI builds from nothing, where the incremental cache is only work (a cold build of the tests:
# Cargo.toml, [profile.test]).
export CARGO_INCREMENTAL=0
logs=$(mktemp -d)
install_pid=""
real_pid=""
finish() {
  # A half-done install is left to finish (never kill dpkg); the real-system suite started
  # in its own process group goes with everything it started.
  [ -z "$real_pid" ] || kill -TERM -- "-$real_pid" 2>/dev/null || true
  [ -z "$install_pid" ] || wait "$install_pid" 2>/dev/null || true
  rm -rf "$logs"
}
trap finish EXIT

t0=$(date +%s)
scripts/install-deps.sh > "$logs/install" 2>&1 &
install_pid=$!
cargo test --workspace --no-run
cargo test --test real_systems --no-run
t1=$(date +%s)
install_rc=0
wait "$install_pid" || install_rc=$?
install_pid=""
cat "$logs/install"
if [ "$install_rc" -ne 0 ]; then
  echo "test-all: scripts/install-deps.sh failed (exit $install_rc)" >&2
  exit 1
fi
t2=$(date +%s)

setsid -w cargo test --test real_systems > "$logs/real" 2>&1 &
real_pid=$!
hermetic_rc=0
cargo test --workspace || hermetic_rc=$?
t3=$(date +%s)
real_rc=0
wait "$real_pid" || real_rc=$?
real_pid=""
t4=$(date +%s)
echo "=== the tests against real systems (cargo test --test real_systems)"
cat "$logs/real"
echo "test-all: build $((t1 - t0)) s (the install beside it, $((t2 - t0)) s to both), hermetic tests $((t3 - t2)) s, real systems $((t4 - t2)) s (at the same time), $((t4 - t0)) s in all"
if [ "$hermetic_rc" -ne 0 ] || [ "$real_rc" -ne 0 ]; then
  echo "test-all: failed: hermetic tests exit $hermetic_rc, real systems exit $real_rc" >&2
  exit 1
fi
