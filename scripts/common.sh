# Sourced by the reproduction scripts: where the binary and the results are, the
# reduced mode, and a `run` that prints each command before running it.
#
#   REBOUND_RESULTS  output root (default: <repo>/results)
#   REBOUND_BIN      the rebound binary (default: build target/release/rebound once)
#   REBOUND_QUICK=1  reduced mode: few particles, small surfaces (used by the tests)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# The names of the directories under results/ (the P_… variables), shared with `rebound report`.
source "$ROOT/scripts/paths.sh"
OUT=${REBOUND_RESULTS:-$ROOT/results}
QUICK=${REBOUND_QUICK:-0}
if [ -z "${REBOUND_BIN:-}" ]; then
  if [ -z "${REBOUND_BUILT:-}" ]; then
    (cd "$ROOT" && cargo build --release --quiet)
    export REBOUND_BUILT=1
  fi
  REBOUND_BIN=$ROOT/target/release/rebound
fi
export REBOUND_BIN REBOUND_RESULTS=$OUT REBOUND_QUICK=$QUICK
# Shipped cases are found under configs/ from the repository root.
cd "$ROOT"

# Every run of this reproduction is logged, one command line each, so that a later stage can
# reuse a run an earlier stage of the *same* invocation made (run_once), never a directory that
# merely exists: a clone holds tables whose PDFs git does not keep. The log is emptied when a
# top-level script starts (reproduce-all.sh, or a per-paper script run on its own).
RUN_LOG=${REBOUND_RUN_LOG:-$OUT/.runs-this-reproduction}
export REBOUND_RUN_LOG=$RUN_LOG
mkdir -p "$OUT"
[ -n "${REBOUND_NESTED:-}" ] || : > "$RUN_LOG"

run() {
  echo "+ rebound $*"
  "$REBOUND_BIN" "$@"
  printf '%s\n' "$*" >> "$RUN_LOG"
}

# run_once ARGS...: `run ARGS...` unless this very command already ran in this reproduction
# (same subcommand, case, particles, seed and --out), whose outputs are then complete and current.
run_once() {
  if grep -qxF -- "$*" "$RUN_LOG"; then
    echo "= rebound $* (already run by this reproduction)"
  else
    run "$@"
  fi
}

# Particle counts: full mode, reduced mode.
particles() { if [ "$QUICK" = 1 ]; then echo "$2"; else echo "$1"; fi; }

# Stage timings accumulate in one file so that reproduce-all.sh can print them all at the end.
STAGE_LOG=${REBOUND_STAGE_LOG:-$OUT/.stage-times}
export REBOUND_STAGE_LOG=$STAGE_LOG
stage_start() { STAGE_NAME=$1; STAGE_T0=$(date +%s.%N); echo "== $1"; }
stage_end() {
  local t1; t1=$(date +%s.%N)
  printf '%-44s %8.1f s\n' "$STAGE_NAME" "$(awk -v a="$t1" -v b="$STAGE_T0" 'BEGIN{print a-b}')" >> "$STAGE_LOG"
}
print_stages() {
  echo "== time per stage ($1)"
  cat "$STAGE_LOG"
}

# variant_case SRC MODEL [XI ZE]: the case file SRC (under configs/, else as given) with `[stochastic] model =
# MODEL` (the section added when the case has none, an existing `model` replaced) and, when XI
# and ZE are given, `[wall]` deviations XI and ZE (degrees); the rest unchanged, on stdout.
variant_case() {
  awk -v m="$2" -v xi="${3:-}" -v ze="${4:-}" '
    /^\[/ { sec = $0 }
    xi != "" && sec == "[wall]" && /^delta_xi_deg/ { print "delta_xi_deg = " xi; next }
    ze != "" && sec == "[wall]" && /^delta_zeta_deg/ { print "delta_zeta_deg = " ze; next }
    sec == "[stochastic]" && /^model/ { next }
    { print }
    $0 == "[stochastic]" { print "model = \"" m "\""; seen = 1 }
    END { if (!seen) printf "\n[stochastic]\nmodel = \"%s\"\n", m }
  ' "$(if [ -f "configs/$1" ]; then echo "configs/$1"; else echo "$1"; fi)"
}
