#!/usr/bin/env bash
# The README's performance table, measured in one run on this machine. Absolute times move
# from machine to machine, so each row's figure is a ratio against a reference measured in
# the same run (alternating pairs, the median of the pairs' ratios), with the absolute
# figures, the date and the CPU beside it. Prints the table's rows as Markdown.
#
#   1. `stochastic` against `deterministic` on one scene (the elastic (2.5°, 7.5°) wall,
#      α⁻ = −12.5°, 10⁷ particles each): rebounds/s over histories/s, both from run.toml
#      (surface generation excluded); the stochastic run's peak RSS.
#   2. `deterministic` at 10⁷ against 10⁵ histories on that scene: the rate ratio.
#   3. `rebound surface` on the Table 1 surface against the NumPy rsgeng2D port (wall time).
#   4. One `rw_rebound` call against the same rebound through the Rust API, and
#   5. `rw_rebound_batch` on 2 threads against 1: from `cargo bench -p roughwall --bench
#      c_library`'s summary (its own alternating rounds).
#
# Usage: scripts/bench-readme.sh [REPS]   (default 5; env REBOUND_VENV, CARGO_TARGET_DIR)
# Needs NumPy in the project's virtual environment (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/bench-lib.sh
REPS=${1:-5}
PYTHON=$(numpy_python)
cargo build --release --quiet
REBOUND=${CARGO_TARGET_DIR:-target}/release/rebound
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
scene_case "$W/scene.toml"

# rate KEY DIR: the `KEY = value` of DIR/run.toml
rate() { awk -v k="$1" '$1 == k {print $3}' "$2/run.toml"; }

echo "measuring ($REPS alternating pairs per row; a few minutes)..." >&2
for _ in $(seq "$REPS"); do
  measure "$W/sm" "$REBOUND" stochastic --case "$W/scene.toml" --particles 10000000 --out "$W/sm-out"
  measure "$W/ds" "$REBOUND" deterministic --case "$W/scene.toml" --particles 10000000 --out "$W/ds-out"
  measure "$W/ds5" "$REBOUND" deterministic --case "$W/scene.toml" --particles 100000 --out "$W/ds5-out"
  s=$(rate rebounds_per_s "$W/sm-out"); d=$(rate particles_per_s "$W/ds-out"); d5=$(rate particles_per_s "$W/ds5-out")
  echo "$s $d $d5" >> "$W/rates"
  rm -rf "$W"/sm-out "$W"/ds-out "$W"/ds5-out
  measure "$W/np" "$PYTHON" scripts/rsgeng2d_numpy.py 5001 5000 0.37 12 4 1
  measure "$W/sf" "$REBOUND" surface --case cases/table1.toml --out "$W/sf-out"
  rm -rf "$W/sf-out"
done
cargo bench -p roughwall --bench c_library -- summary-only > "$W/c_library.txt" 2> "$W/c_library.err" ||
  { cat "$W/c_library.err" >&2; exit 1; }

col() { awk -v c="$2" '{print $c}' "$1" | median; }
sm_rate=$(col "$W/rates" 1); ds_rate=$(col "$W/rates" 2); ds5_rate=$(col "$W/rates" 3)
sm_ratio=$(awk '{print $1 / $2}' "$W/rates" | median)
scale_ratio=$(awk '{print $2 / $3}' "$W/rates" | median)
sm_rss=$(col "$W/sm" 3)
np_wall=$(col "$W/np" 1); sf_wall=$(col "$W/sf" 1); sf_rss=$(col "$W/sf" 3)
np_ratio=$(paste -d' ' "$W/np" "$W/sf" | awk '{print $1 / $4}' | median)
c_line=$(grep -m1 'C/Rust' "$W/c_library.txt")
rust_ns=$(sed -E 's/.*Rust WallModel::rebound ([0-9.]+) ns.*/\1/' <<< "$c_line")
c_ns=$(sed -E 's/.*C rw_rebound ([0-9.]+) ns.*/\1/' <<< "$c_line")
c_ratio=$(sed -E 's/.*C\/Rust ([0-9.]+).*/\1/' <<< "$c_line")
b1=$(sed -nE 's/^rw_rebound_batch, 1 thread\(s\): ([0-9.]+) M.*/\1/p' "$W/c_library.txt")
b2=$(sed -nE 's/^rw_rebound_batch, 2 thread\(s\): ([0-9.]+) M.*/\1/p' "$W/c_library.txt")

echo "| what | ratio, same run | absolute, this run | target |"
echo "| --- | --- | --- | --- |"
awk -v r="$sm_ratio" -v s="$sm_rate" -v d="$ds_rate" -v m="$sm_rss" 'BEGIN {printf "| `stochastic` against `deterministic`, elastic (2.5°, 7.5°) wall, 10⁷ each | **%.1f×** the rate | %.1f M rebounds/s against %.2f M histories/s; %.1f MiB peak | ≥ 5 M/s, ≤ 100 MiB |\n", r, s / 1e6, d / 1e6, m / 1024}'
awk -v r="$scale_ratio" -v a="$ds5_rate" -v b="$ds_rate" 'BEGIN {printf "| `deterministic`, 10⁷ against 10⁵ histories, same scene | **%.2f×** the rate | %.2f → %.2f M histories/s | ≥ 1× |\n", r, a / 1e6, b / 1e6}'
awk -v r="$np_ratio" -v a="$sf_wall" -v b="$np_wall" -v m="$sf_rss" 'BEGIN {printf "| `surface`, Table 1 (5001² nodes), against NumPy `rsgeng2D` | **%.1f×** faster | %.2f s against %.2f s; %.0f MiB peak | ≥ 10× |\n", r, a, b, m / 1024}'
awk -v r="$c_ratio" -v c="$c_ns" -v u="$rust_ns" 'BEGIN {printf "| C library: one `rw_rebound` call against the Rust call | **%.2f×** the time | %.0f ns against %.0f ns | ≤ 1.1× |\n", r, c, u}'
awk -v a="$b1" -v b="$b2" 'BEGIN {printf "| C library: `rw_rebound_batch`, 2 threads against 1 | **%.2f×** the rate | %.1f M rebounds/s against %.1f M/s | ≥ 5 M/s on 2 threads |\n", b / a, b, a}'
echo
echo "Measured $(machine); medians of $REPS alternating pairs (the C rows: the bench's own rounds)."
