#!/usr/bin/env bash
# Times `rebound surface` on the Table 1 surface (N = 5001, generation + statistics +
# outputs) beside a NumPy port of Bergström's rsgeng2D (generation only) on the same
# machine, with peak memory from /usr/bin/time -v. Prints a Markdown table of medians.
#
# Usage: scripts/bench-surface-numpy.sh [REPS]   (default 5; env REBOUND_VENV, CARGO_TARGET_DIR)
# NumPy comes from the project's virtual environment (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
REPS=${1:-5}
TARGET=${CARGO_TARGET_DIR:-target}
VENV=${REBOUND_VENV:-.venv}
OUT=$TARGET/bench-surface
mkdir -p "$OUT"

"$VENV/bin/python" -c "import numpy" 2>/dev/null ||
    { echo "numpy not found in $VENV: run scripts/install-deps.sh" >&2; exit 1; }
cargo build --release --quiet
REBOUND=$TARGET/release/rebound

# time_it LABEL CMD... : appends "wall_s rss_kb" per run to $OUT/LABEL.txt
time_it() {
    local label=$1
    shift
    : >"$OUT/$label.txt"
    for _ in $(seq "$REPS"); do
        /usr/bin/time -v "$@" >"$OUT/$label.log" 2>"$OUT/$label.time" || {
            cat "$OUT/$label.log" "$OUT/$label.time" >&2
            exit 1
        }
        awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; w = s}
                    /Maximum resident set size/ {r = $2}
                    END {print w, r}' "$OUT/$label.time" >>"$OUT/$label.txt"
    done
}

median() { sort -n | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

time_it numpy "$VENV/bin/python" scripts/rsgeng2d_numpy.py 5001 5000 0.37 12 4 1
time_it rebound "$REBOUND" surface --case cases/table1.toml --out "$OUT/table1"

echo "| program (N = 5001, 2 cores) | median wall time (s) | median peak RSS (MiB) | runs |"
echo "| --- | --- | --- | --- |"
for label in numpy rebound; do
    w=$(cut -d' ' -f1 "$OUT/$label.txt" | median)
    r=$(cut -d' ' -f2 "$OUT/$label.txt" | median)
    name=$([ "$label" = numpy ] && echo "NumPy rsgeng2D port (generation only)" || echo "rebound surface --case cases/table1.toml (generation + Table 1 statistics + outputs)")
    printf '| %s | %.2f | %.0f | %s |\n' "$name" "$w" "$(awk -v r="$r" 'BEGIN {print r / 1024}')" "$REPS"
done
