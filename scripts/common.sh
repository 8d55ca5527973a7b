# Sourced by the reproduction scripts: where the binary and the results are, the
# reduced mode, and a `run` that prints each command before running it.
#
#   REBOUND_RESULTS  output root (default: results, under the repository)
#   REBOUND_BIN      the rebound binary (default: build target/release/rebound once)
#   REBOUND_QUICK=1  reduced mode: few particles, small surfaces (used by the tests)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# The names of the directories under results/ (the P_… variables), shared with `rebound report`.
source "$ROOT/scripts/paths.sh"
# Relative by default (every script runs from the root): the case files and manifests the
# results hold then name repository paths, and a clone can rerun them.
OUT=${REBOUND_RESULTS:-results}
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

# bin_width_for XI ZE: the PDFs' bin width (degrees) for a wall of deviations XI, ZE: a fifth
# of the smaller, down to 1, 2 or 5 × 10^k, within [0.01, 1]. The rebound angle's spread is
# about twice the deviation, so a bin is at most a tenth of it and a KS distance between two
# runs' PDFs is that of their laws; with the default 1° bins a smooth wall's α⁺ (spread
# 0.14–0.45° on plu-1 and metropro-1) falls in one or two bins, and the KS distance says only
# how its mass splits across a bin edge.
bin_width_for() {
  awk -v xi="$1" -v ze="$2" 'BEGIN {
    w = (xi < ze ? xi : ze) / 5; if (w >= 1) { print 1; exit }
    e = 10 ^ int(log(w) / log(10) - (w < 1 ? 1 : 0)); m = w / e
    n = (m >= 5 ? 5 : (m >= 2 ? 2 : 1)) * e
    if (n < 0.01) n = 0.01
    printf "%g\n", n }'
}

# gaussian_control CARD_DIR REF D XI ZE DIRECTIONS NAME CASES OUT [BIN]: the noise floor of a
# verdict on the Gaussian assumption for a scan (issue 39, part 3). The scan is one
# realisation, so even a Gaussian wall would differ from a Gaussian ensemble: one Gaussian
# wall (seed 2022) of the size and pixel of the block the in-place reference REF bounced on
# (its run.toml), with deviations XI, ZE (the card's for particles of D µm, 0 the point) and
# the correlation area `rebound scan` measured for that particle (wall_card_diameters.csv of
# CARD_DIR: its part of the scan over its correlation areas, so that the block holds as many
# as the scan's; rms height from Eq. 15), against an ensemble of $P_STUDY_CONTROL_SURFACES such
# walls (seed 2021; fewer in quick mode), at DIRECTIONS' incident directions, and their
# comparison, $N particles a direction (the calling study's), with PDFs in bins of BIN
# degrees when given. Cases go to
# CASES/NAME-{one,ensemble}.toml, runs under OUT.
gaussian_control() {
  local card_dir=$1 ref=$2 d=$3 xi=$4 ze=$5 directions=$6 name=$7 cases=$8 out=$9 bin=${10:-}
  local size area h surfaces
  surfaces=$(particles "$P_STUDY_CONTROL_SURFACES" 4)
  # The size of the block the reference bounced on, as a square of the same area. Not its
  # entry region (the part of the block particles enter over, [scan] entry_region_um): a
  # Gaussian wall that small is smaller than one correlation length for a sphere's centre
  # surface (sample-land, 100 µm: 74 µm against 163 × 100 µm) and comes out flat.
  size=$(awk -F' = ' '
    /^\[/{sec=$0}
    sec=="[surface_choice]" && $1=="grid_nx"{nx=$2+0} sec=="[surface_choice]" && $1=="grid_nz"{nz=$2+0}
    sec=="[surface_choice]" && $1=="spacing_x_um"{px=$2+0} sec=="[surface_choice]" && $1=="spacing_z_um"{pz=$2+0}
    END { if (nx > 2 && nz > 2) { L = sqrt(nx*px*nz*pz); printf "%.6g %d\n", L, int(L / sqrt(px*pz) + 0.5) } }' "$ref/run.toml")
  area=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    NR == 2 { printf "%.9g\n", $col["nx"] * $col["dx_um"] * $col["ny"] * $col["dy_um"] }' "$card_dir/scan_summary.csv")
  h=$(awk -F, -v d="$d" -v area="$area" -v xi="$xi" -v ze="$ze" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    $1 + 0 == d + 0 && $col["correlation_areas"] > 0 {
      a = $col["exact_fraction"] * area / $col["correlation_areas"]; r = 3.141592653589793 / 180
      printf "%.6g\n", sqrt(a * xi * r * ze * r / 2); exit }' "$card_dir/wall_card_diameters.csv")
  [ -n "$size" ] && [ -n "$h" ] || { echo "gaussian_control: no block size in $ref/run.toml or correlation area for $d µm in $card_dir" >&2; exit 1; }
  local which tag n_surf seed cc
  for which in "$P_STUDY_CONTROL_ONE:1:2022" "$P_STUDY_CONTROL_ENSEMBLE:$surfaces:2021"; do
    IFS=: read -r tag n_surf seed <<< "$which"
    cc="$cases/$name-$tag.toml"
    { sed -e "s/^name = .*/name = \"$name-$tag\"/" -e "s/^seed = .*/seed = $seed/" "$directions"
      printf '\n[surface]\nlength_um = %s\nnodes = %s\nrms_height_um = %s\ndelta_xi_deg = %s\ndelta_zeta_deg = %s\n\n[deterministic]\nsurfaces = %s\n' \
        "${size% *}" "${size#* }" "$h" "$xi" "$ze" "$n_surf"
      [ -z "$bin" ] || printf '\n[output]\nbin_width_deg = %s\n' "$bin"; } > "$cc"
    grep -q "^surfaces = $n_surf\$" "$cc" || { echo "gaussian_control: could not write $cc" >&2; exit 1; }
    run deterministic --case "$cc" --particles "$N" --out "$out/$tag/$P_DETERMINISTIC"
  done
  run compare --a "$out/$P_STUDY_CONTROL_ENSEMBLE/$P_DETERMINISTIC" \
    --b "$out/$P_STUDY_CONTROL_ONE/$P_DETERMINISTIC" --out "$out/$P_COMPARE"
}
