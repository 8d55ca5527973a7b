#!/usr/bin/env bash
# Reading and characterising a measured scan (issue 29, part 8): `rebound scan` on a
# 4096² X3P scan (float64, 128 MiB of heights) against SurfaceTopography reading the same
# file, levelling it by its plane and computing Sq and Sdq (scripts/st_characterise.py), in
# alternating pairs, with peak memory from /usr/bin/time -v. Prints the performance-table
# row: the median of the pairs' wall-time ratios, both median wall times (and rebound's CPU
# time, user + system), rebound's peak RSS against the field's bytes and the reference's, and
# the machine.
#
# Usage: scripts/bench-scan.sh [PAIRS]   (default 5; env REBOUND_VENV, CARGO_TARGET_DIR)
# SurfaceTopography comes from the project's virtual environment (scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/bench-lib.sh
PAIRS=${1:-5}
N=${BENCH_SCAN_N:-4096}
TARGET=${CARGO_TARGET_DIR:-target}
PYTHON=$(numpy_python)
"$PYTHON" -c "import SurfaceTopography" 2> /dev/null ||
    { echo "SurfaceTopography not found in ${REBOUND_VENV:-.venv}: run scripts/install-deps.sh" >&2; exit 1; }
OUT=$TARGET/bench-scan
rm -rf "$OUT"
mkdir -p "$OUT"
cargo build --release --quiet
REBOUND=$TARGET/release/rebound
SCAN=$OUT/scan-$N.x3p
"$PYTHON" scripts/st_characterise.py --make "$SCAN" "$N" 2> /dev/null

for i in $(seq "$PAIRS"); do
    measure "$OUT/st" "$PYTHON" scripts/st_characterise.py "$SCAN"
    measure "$OUT/rebound" "$REBOUND" scan --scan "$SCAN" --out "$OUT/out-$i"
    rm -rf "$OUT/out-$i"
done
paste -d' ' "$OUT/st" "$OUT/rebound" | awk '{print $1 / $4}' > "$OUT/ratio"
w_st=$(cut -d' ' -f1 "$OUT/st" | median)
w_rb=$(cut -d' ' -f1 "$OUT/rebound" | median)
cpu_rb=$(cut -d' ' -f2 "$OUT/rebound" | median)
rss=$(cut -d' ' -f3 "$OUT/rebound" | median)
rss_st=$(cut -d' ' -f3 "$OUT/st" | median)
field_mib=$(awk -v n="$N" 'BEGIN {print n * n * 8 / 1048576}')
printf '| `scan`, %s² X3P: read, level, characterise, write, against SurfaceTopography (read, level, Sq, Sdq) | **%.1f×** faster | %.2f s (%.2f s CPU) against %.2f s; %.0f MiB peak (%.1f× the field'"'"'s %.0f MiB) against %.0f MiB | ≤ 2 s, ≤ 3× the field |\n' \
    "$N" "$(median < "$OUT/ratio")" "$w_rb" "$cpu_rb" "$w_st" "$(awk -v r="$rss" 'BEGIN {print r / 1024}')" \
    "$(awk -v r="$rss" -v f="$field_mib" 'BEGIN {print r / 1024 / f}')" "$field_mib" \
    "$(awk -v r="$rss_st" 'BEGIN {print r / 1024}')"
echo "(median of $PAIRS alternating pairs; $(machine))"
