#!/usr/bin/env bash
# The Python package against the C library (docs/performance.md, issue 32): Wall.rebound on
# 10^6 hits against rw_rebound_batch on the same hits, both on 2 threads, measured in one run
# (crates/roughwall-py/bench/bench_rebound.py). Builds the C library (cargo build --release
# -p roughwall) and the wheel (maturin), installs the wheel into the virtual environment
# $REBOUND_VENV (default <repo>/.venv); installs nothing else: maturin and NumPy come from
# scripts/install-deps.sh.
#
# Usage: scripts/bench-python.sh   (BENCH_HITS, BENCH_THREADS, BENCH_ROUNDS override 10^6, 2, 7)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
venv=${REBOUND_VENV:-$root/.venv}
for t in python maturin; do
  [ -x "$venv/bin/$t" ] || { echo "bench-python: $venv/bin/$t not found: run scripts/install-deps.sh" >&2; exit 1; }
done
cd "$root"
cargo build --release -j 2 -p roughwall >&2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
(cd crates/roughwall-py && PATH="$venv/bin:$PATH" CARGO_BUILD_JOBS=2 \
  "$venv/bin/maturin" build --release --out "$out" --interpreter "$venv/bin/python" >&2)
"$venv/bin/python" -m pip install --quiet --force-reinstall --no-deps "$out"/*.whl
ROUGHWALL_CLIB="$root/target/release/libroughwall.so" "$venv/bin/python" crates/roughwall-py/bench/bench_rebound.py
