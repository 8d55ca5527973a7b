#!/usr/bin/env bash
# Every test: installs what the tests against real systems need (scripts/install-deps.sh),
# then runs the hermetic tests of both crates (unit, integration and documentation tests,
# nothing but the Rust toolchain needed) and the tests against real systems (code_saturne,
# OpenFOAM, pysand, Slurm, gfortran). This is the README's test command and what CI runs.
#
# Usage: scripts/test-all.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# CI builds from nothing, where the incremental cache is only work (a cold build of the tests:
# Cargo.toml, [profile.test]).
export CARGO_INCREMENTAL=0
t0=$(date +%s)
scripts/install-deps.sh
t1=$(date +%s)
cargo test --workspace
t2=$(date +%s)
cargo test --test real_systems
t3=$(date +%s)
echo "test-all: install $((t1 - t0)) s, hermetic tests $((t2 - t1)) s, real systems $((t3 - t2)) s"
