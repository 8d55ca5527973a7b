#!/usr/bin/env bash
# Whole-process figures of "Monte Carlo at any scale" (issue 10), medians over REPS runs:
#   * stochastic, elastic (2.5°, 7.5°) wall, α⁻ = −12.5°: rebounds/s and peak RSS at 10⁷ and 10⁸;
#   * deterministic, same scene: histories/s (from run.toml) at 10⁵ and 10⁷, peak RSS against
#     the size of the surface;
#   * 4 shards run one after another plus their merge, against one process: CPU time ratio.
# Peak RSS and CPU time come from /usr/bin/time -v. Prints a Markdown table.
#
# Usage: scripts/bench-scale.sh [REPS]   (default 3; env REBOUND_BIN, CARGO_TARGET_DIR)
set -euo pipefail
cd "$(dirname "$0")/.."
REPS=${1:-3}
TARGET=${CARGO_TARGET_DIR:-target}
if [ -z "${REBOUND_BIN:-}" ]; then
  cargo build --release --quiet
  REBOUND_BIN=$TARGET/release/rebound
fi
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
. scripts/bench-lib.sh
scene_case "$W/scene.toml"
# run LABEL CMD... : one run; appends "wall_s cpu_s rss_kib" to $W/t-LABEL
run() {
  local label=$1
  shift
  measure "$W/t-$label" "$@"
}
col() { cut -d' ' -f"$2" "$W/t-$1" | median; }

for _ in $(seq "$REPS"); do
  for n in 10000000 100000000; do
    run "sm$n" "$REBOUND_BIN" stochastic --case "$W/scene.toml" --particles "$n" --out "$W/sm$n"
  done
  for n in 100000 10000000; do
    run "ds$n" "$REBOUND_BIN" deterministic --case "$W/scene.toml" --particles "$n" --out "$W/ds$n"
    grep -E '^particles_per_s' "$W/ds$n/run.toml" | awk '{print $3}' >> "$W/ds$n.rate"
  done
  # One process against four shards one after another plus the merge (CPU seconds).
  for model in stochastic deterministic; do
    n=10000000
    run "one-$model" "$REBOUND_BIN" "$model" --case "$W/scene.toml" --particles "$n" --out "$W/one-$model"
    for k in 1 2 3 4; do
      run "shard-$model" "$REBOUND_BIN" "$model" --case "$W/scene.toml" --particles "$n" --shard "$k/4" --out "$W/s$k-$model"
    done
    run "merge-$model" "$REBOUND_BIN" merge --out "$W/merged-$model" "$W"/s{1,2,3,4}-"$model"
    cmp "$W/one-$model/summary.csv" "$W/merged-$model/summary.csv"
    cmp "$W/one-$model/pdfs.csv" "$W/merged-$model/pdfs.csv"
    # CPU of this repetition's 4 shards and merge (last 5 lines).
    tail -n 4 "$W/t-shard-$model" | awk '{c += $2} END {printf "%s ", c}' >> "$W/cpu4-$model"
    tail -n 1 "$W/t-merge-$model" | awk '{print $2}' >> "$W/cpu4-$model"
    awk '{print $1 + $2}' "$W/cpu4-$model" | tail -n 1 >> "$W/cpu4sum-$model"
  done
done

grid=$(grep -E '^grid_nx' "$W/ds100000/run.toml" | awk '{print $3}')
gridz=$(grep -E '^grid_nz' "$W/ds100000/run.toml" | awk '{print $3}')
surface_mib=$(awk -v x="$grid" -v z="$gridz" 'BEGIN {printf "%.0f", x * z * 8 / 1048576}')
echo "| what (2 cores, medians of $REPS runs) | figure |"
echo "| --- | --- |"
for n in 10000000 100000000; do
  w=$(col "sm$n" 1); r=$(col "sm$n" 3)
  awk -v n="$n" -v w="$w" -v r="$r" 'BEGIN {printf "| stochastic, %.0e rebounds, whole process | %.2f s, %.1f M rebounds/s, peak RSS %.1f MiB |\n", n, w, n / w / 1e6, r / 1024}'
done
for n in 100000 10000000; do
  rate=$(median < "$W/ds$n.rate"); r=$(col "ds$n" 3)
  awk -v n="$n" -v q="$rate" -v r="$r" -v s="$surface_mib" 'BEGIN {printf "| deterministic, %.0e histories | %.2f M histories/s (run.toml), peak RSS %.0f MiB = surface %s MiB + %.0f MiB |\n", n, q / 1e6, r / 1024, s, r / 1024 - s}'
done
for model in stochastic deterministic; do
  one=$(col "one-$model" 2); four=$(median < "$W/cpu4sum-$model")
  awk -v m="$model" -v a="$one" -v b="$four" 'BEGIN {printf "| %s: 4 shards one after another + merge, against one process (CPU s) | %.2f s against %.2f s: %+.1f %% |\n", m, b, a, 100 * (b / a - 1)}'
done
