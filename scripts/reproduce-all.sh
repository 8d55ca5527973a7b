#!/usr/bin/env bash
# Regenerates every reproducible table and figure of the three papers into results/,
# then writes results/REPORT.md. Stops at the first failure; safe to re-run.
#   REBOUND_QUICK=1 scripts/reproduce-all.sh   # reduced mode (minutes → seconds)
# The pipe-flow study runs in its quick mode (scripts/pipe-flow.sh --quick, about a minute, into
# pipe-flow-quick/; the full study is scripts/pipe-flow.sh, into pipe-flow/). It needs
# code_saturne and gmsh (scripts/install-deps.sh); REBOUND_WITHOUT_CFD=1 leaves it out (the
# hermetic tests do, needing nothing beyond the Rust toolchain).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
export REBOUND_NESTED=1
: > "$STAGE_LOG"
: > "$RUN_LOG"
T0=$(date +%s)
# Fingerprints of the CSVs already there, to check afterwards that the same seeds give the
# same bytes. speed_vs_error.csv holds wall times and pipe-flow's costs.csv CPU times, so they
# are left out of the check.
BEFORE=$(mktemp)
trap 'rm -f "$BEFORE"' EXIT
(cd "$OUT" && find . -name '*.csv' ! -name 'speed_vs_error.csv' ! -name 'costs.csv' -print0 | sort -z | xargs -0 -r sha256sum) > "$BEFORE"
# The mode the files before were made in: the `mode:` line of the last check (unknown without
# one, e.g. results written before the line existed).
PREVIOUS_MODE=$(awk '/^mode: /{print $2; exit}' "$OUT/$P_REPRODUCIBILITY" 2>/dev/null || true)
PREVIOUS_MODE=${PREVIOUS_MODE:-unknown}
for part in radenkovic2021 wall-models calibrate measured-walls measured-wall-model mirror hu2021 erosion finite-size spin speed-vs-error; do
  echo "=== scripts/$part.sh"
  bash "$ROOT/scripts/$part.sh"
done
if [ "${REBOUND_WITHOUT_CFD:-0}" = 1 ]; then
  echo "=== scripts/pipe-flow.sh --quick: left out (REBOUND_WITHOUT_CFD=1)"
else
  echo "=== scripts/pipe-flow.sh --quick"
  bash "$ROOT/scripts/pipe-flow.sh" --quick
fi
# The report writes aggregate CSVs (fig4.csv, erosion.csv, wall_models.csv, …): write them before
# the check so that it covers them too, then once more so that REPORT.md quotes the check.
echo "=== report (its tables)"
run report --results "$OUT"
MODE=$([ "$QUICK" = 1 ] && echo quick || echo full)
if [ -s "$BEFORE" ]; then
  (cd "$OUT" && sha256sum --quiet -c "$BEFORE" 2>/dev/null) > "$OUT/.changed" || true
  total=$(wc -l < "$BEFORE")
  changed=$(grep -c ': FAILED' "$OUT/.changed" || true)
  # A difference is explained only when the files before were made in the other mode (other
  # particle counts and surfaces); anything else is listed as unexplained.
  if [ "$PREVIOUS_MODE" = unknown ]; then
    why="unexplained: the mode of the files before is not recorded"
  elif [ "$PREVIOUS_MODE" != "$MODE" ]; then
    why="explained: the files before were made in ${PREVIOUS_MODE} mode, this run in $MODE mode"
  else
    why="unexplained: same mode ($MODE), same seeds"
  fi
  {
    echo "mode: $MODE"
    echo "CSV files present before this run: $total (speed_vs_error.csv and costs.csv excluded: they hold wall and CPU times)"
    echo "byte-identical after re-running with the same seeds: $((total - changed))"
    echo "different: $changed"
    [ "$changed" = 0 ] || echo "  ($why)"
    sed 's/^/  /' "$OUT/.changed"
  } > "$OUT/$P_REPRODUCIBILITY"
  rm -f "$OUT/.changed"
  cat "$OUT/$P_REPRODUCIBILITY"
else
  { echo "mode: $MODE"; echo "CSV files present before this run: 0"; } > "$OUT/$P_REPRODUCIBILITY"
fi
echo "=== report"
run report --results "$OUT"
T1=$(date +%s)
print_stages "all"
echo "total: $((T1 - T0)) s"
