#!/usr/bin/env bash
# Times `rebound surface` on the Table 1 surface (N = 5001, generation + statistics +
# outputs) against a NumPy port of Bergström's rsgeng2D (generation only) on the same
# machine, in alternating pairs, with peak memory from /usr/bin/time -v. Prints a Markdown
# table of medians and the median of the pairs' ratios.
#
# Usage: scripts/bench-surface-numpy.sh [REPS]   (default 5; env REBOUND_VENV, CARGO_TARGET_DIR)
# NumPy comes from the project's virtual environment (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/bench-lib.sh
REPS=${1:-5}
TARGET=${CARGO_TARGET_DIR:-target}
PYTHON=$(numpy_python)
OUT=$TARGET/bench-surface
rm -rf "$OUT"
mkdir -p "$OUT"
cargo build --release --quiet
REBOUND=$TARGET/release/rebound

for _ in $(seq "$REPS"); do
    measure "$OUT/numpy" "$PYTHON" scripts/rsgeng2d_numpy.py 5001 5000 0.37 12 4 1
    measure "$OUT/rebound" "$REBOUND" surface --case cases/table1.toml --out "$OUT/table1"
    rm -rf "$OUT/table1"
done
paste -d' ' "$OUT/numpy" "$OUT/rebound" | awk '{print $1 / $4}' > "$OUT/ratio"

echo "| program (N = 5001, $(nproc) cores) | median wall time (s) | median peak RSS (MiB) | runs |"
echo "| --- | --- | --- | --- |"
for label in numpy rebound; do
    w=$(cut -d' ' -f1 "$OUT/$label" | median)
    r=$(cut -d' ' -f3 "$OUT/$label" | median)
    name=$([ "$label" = numpy ] && echo "NumPy rsgeng2D port (generation only)" || echo "rebound surface --case cases/table1.toml (generation + Table 1 statistics + outputs)")
    printf '| %s | %.2f | %.0f | %s |\n' "$name" "$w" "$(awk -v r="$r" 'BEGIN {print r / 1024}')" "$REPS"
done
printf '\nNumPy / rebound wall time: %.1fx (median of %s alternating pairs; %s)\n' "$(median < "$OUT/ratio")" "$REPS" "$(machine)"
