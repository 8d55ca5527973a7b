#!/usr/bin/env bash
# What mirrored tiling costs a measured scan (issue 29, part 4): generated Sec. 3 walls,
# particles on each periodic wall against particles on a window of it taken as a scan and
# mirror-tiled (crates/roughwall/examples/scan_tiling.rs). Writes
# $REBOUND_RESULTS/measured-walls/scan_tiling.csv; docs/models.md quotes it.
#   SURFACES (default 32) walls, HISTORIES (default 100000) per condition and wall.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${REBOUND_RESULTS:-$root/results}/measured-walls
mkdir -p "$out"
cd "$root"
cargo build --release --quiet -p roughwall --example scan_tiling
./target/release/examples/scan_tiling "${SURFACES:-32}" "${HISTORIES:-100000}" "$out/scan_tiling.csv.tmp"
mv "$out/scan_tiling.csv.tmp" "$out/scan_tiling.csv"
cat "$out/scan_tiling.csv"
