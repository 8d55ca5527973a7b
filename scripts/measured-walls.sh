#!/usr/bin/env bash
# Your own wall (issue 29), two studies; `rebound report` turns them into a REPORT.md section.
#  1. Typed deviations (part 6). On four walls the escape table was not calibrated on
#     ($P_NOMINAL_WALLS, name:Δξ:Δζ), the deviations as a user types them into [wall]:
#     `deterministic` on an ensemble of $P_CALIBRATION_SURFACES surfaces built with the default
#     `wall_deviations = "normal-angles"` (its triangles have the typed deviations) and on one
#     built with Eq. (15) (`"eq15"`, as the papers build theirs: 0.3–2.1 % less), and both
#     stochastic models with the typed deviations against each.
#  2. Real scans (part 7), $P_STUDY_SCANS (configs/scans/<name>.toml): `rebound scan` writes
#     the wall card; `deterministic` bounces on the scan itself in place (the reference,
#     issue 39 part 1), on the scan turned to its lay and mirror-tiled (the earlier reference,
#     $P_STUDY_ON_SCAN_MIRRORED/, compared with the in-place one: what the tiling cost) and on
#     Gaussian walls (16 surfaces); both stochastic models run. The Gaussian walls and the
#     models get the card's deviations ($P_STUDY_WITH_CARD/) and those of the tiled wall
#     ($P_STUDY_WITH_TILED/). Every run is compared with the in-place one.
# The cases are configs/calibration/test-5-5.toml (part 1) and configs/scans/study.toml
# (part 2) with the deviations replaced. Writes $REBOUND_RESULTS/measured-walls/.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
M=$OUT/$P_MEASURED_WALLS
mkdir -p "$M/cases"
MODELS="radenkovic-simonin-2021 calibrated"

# with_wall SRC XI ZE NAME [KEY=VALUE ...]: the case SRC with [wall] deviations XI, ZE (the
# section added when SRC has none), `name = NAME`, no `wall_deviations` pin, and each
# KEY = VALUE put into [deterministic]; on stdout.
with_wall() {
  local src=$1 xi=$2 ze=$3 name=$4
  shift 4
  awk -v xi="$xi" -v ze="$ze" -v name="$name" -v extra="$*" '
    /^\[/ { sec = $0 }
    /^name = / { print "name = \"" name "\""; next }
    /^wall_deviations = / { next }
    sec == "[wall]" && /^delta_xi_deg/ { print "delta_xi_deg = " xi; wall = 1; next }
    sec == "[wall]" && /^delta_zeta_deg/ { print "delta_zeta_deg = " ze; next }
    { print }
    $0 == "[deterministic]" { det = 1; n = split(extra, kv, " "); for (i = 1; i <= n; i++) { sub("=", " = ", kv[i]); print kv[i] } }
    END {
      if (!wall) printf "\n[wall]\ndelta_xi_deg = %s\ndelta_zeta_deg = %s\n", xi, ze
      if (!det && extra != "") { print "\n[deterministic]"; n = split(extra, kv, " "); for (i = 1; i <= n; i++) { sub("=", " = ", kv[i]); print kv[i] } }
    }
  ' "configs/$src"
}

# models DET CASE DIR [COMPARE_NAME]: both stochastic models on CASE, each compared with DET.
models() {
  local det=$1 case_file=$2 dir=$3
  for v in $MODELS; do
    variant_case "$case_file" "$v" > "${case_file%.toml}-$v.toml"
    grep -q "^model = \"$v\"" "${case_file%.toml}-$v.toml" || { echo "measured-walls.sh: could not write ${case_file%.toml}-$v.toml" >&2; exit 1; }
    # One stochastic run serves both ensembles of a nominal wall: the second call reuses it.
    run_once stochastic --case "${case_file%.toml}-$v.toml" --particles "$N" --out "$dir/$v/$P_STOCHASTIC"
    run compare --a "$det" --b "$dir/$v/$P_STOCHASTIC" --out "$dir/$v/${4:-$P_COMPARE}"
  done
}

# --- 1. Typed deviations on walls outside the calibration set -------------------------------
N=$(particles 1000000 2000)
SURFACES=$(particles "$P_CALIBRATION_SURFACES" 2)
for w in $P_NOMINAL_WALLS; do
  IFS=: read -r name xi ze <<< "$w"
  d="$M/$P_NOMINAL/$name"
  stage_start "Measured walls: typed ($xi°, $ze°), $SURFACES surfaces"
  c="$M/cases/nominal-$name.toml"
  with_wall calibration/test-5-5.toml "$xi" "$ze" "nominal-$name" "surfaces=$SURFACES" > "$c"
  c15="$M/cases/nominal-$name-eq15.toml"
  with_wall calibration/test-5-5.toml "$xi" "$ze" "nominal-$name-eq15" "surfaces=$SURFACES" 'wall_deviations="eq15"' > "$c15"
  grep -q "^delta_zeta_deg = $ze\$" "$c" && grep -q '^wall_deviations = "eq15"$' "$c15" \
    || { echo "measured-walls.sh: could not write $c, $c15" >&2; exit 1; }
  run deterministic --case "$c" --particles "$N" --out "$d/$P_DETERMINISTIC"
  run deterministic --case "$c15" --particles "$N" --out "$d/$P_NOMINAL_EQ15/$P_DETERMINISTIC"
  # The stochastic runs read only [wall]: one run each, compared with both ensembles.
  models "$d/$P_DETERMINISTIC" "$c" "$d"
  models "$d/$P_NOMINAL_EQ15/$P_DETERMINISTIC" "$c" "$d" "$P_NOMINAL_EQ15-$P_COMPARE"
  stage_end
done

# --- 2. Real scans: on the scan, on Gaussian walls, and the models with the card --------------
N=$(particles 200000 2000)
GAUSS_SURFACES=$(particles 16 2)
for s in $P_STUDY_SCANS; do
  d="$M/$P_STUDY/$s"
  stage_start "Measured walls: scan $s"
  run scan --case "scans/$s.toml" --out "$d/$P_STUDY_CARD"
  card="$d/$P_STUDY_CARD/wall_card.toml"
  xi=$(awk -F' = ' '/^\[/{sec=$0} sec=="[wall]" && /^delta_xi_deg/{split($2,a," "); print a[1]; exit}' "$card")
  ze=$(awk -F' = ' '/^\[/{sec=$0} sec=="[wall]" && /^delta_zeta_deg/{split($2,a," "); print a[1]; exit}' "$card")
  [ -n "$xi" ] && [ -n "$ze" ] || { echo "measured-walls.sh: no [wall] in $card" >&2; exit 1; }
  file=$(awk -F' = ' '/^file = /{gsub(/"/, "", $2); split($2,a," "); print a[1]; exit}' "configs/scans/$s.toml")
  det="$d/$P_STUDY_ON_SCAN/$P_DETERMINISTIC"
  c="$M/cases/study-$s.toml"
  with_wall scans/study.toml "$xi" "$ze" "study-$s" > "$c"
  grep -q "^delta_xi_deg = $xi\$" "$c" || { echo "measured-walls.sh: could not write $c" >&2; exit 1; }
  run deterministic --case "$c" --surface "configs/scans/$file" --particles "$N" --out "$det"
  # The earlier reference: the same scan turned to its lay, resampled and mirror-tiled.
  detm="$d/$P_STUDY_ON_SCAN_MIRRORED/$P_DETERMINISTIC"
  cm="$M/cases/study-$s-mirrored.toml"
  with_wall scans/study.toml "$xi" "$ze" "study-$s-mirrored" 'scan_wall="mirrored"' > "$cm"
  grep -q '^scan_wall = "mirrored"$' "$cm" || { echo "measured-walls.sh: could not write $cm" >&2; exit 1; }
  run deterministic --case "$cm" --surface "configs/scans/$file" --particles "$N" --out "$detm"
  run compare --a "$det" --b "$detm" --out "$d/$P_STUDY_ON_SCAN_MIRRORED/$P_COMPARE"
  # Two sets of deviations: the card's (the scan's own triangles, what a user has and what the
  # in-place reference meets) and those of the mirror-tiled wall (resampled along the lay, a
  # little smoother): the second shows what the tiled reference's deviations did.
  txi=$(awk -F' = ' '/^measured_delta_xi_deg/{print $2; exit}' "$detm/run.toml")
  tze=$(awk -F' = ' '/^measured_delta_zeta_deg/{print $2; exit}' "$detm/run.toml")
  [ -n "$txi" ] && [ -n "$tze" ] || { echo "measured-walls.sh: no measured deviations in $detm/run.toml" >&2; exit 1; }
  # The noise floor of a "miss" (issue 39, part 3; common.sh).
  gaussian_control "$d/$P_STUDY_CARD" "$det" 0 "$xi" "$ze" configs/scans/study.toml \
    "study-$s-control" "$M/cases" "$d/$P_STUDY_CONTROL"
  for which in "$P_STUDY_WITH_CARD:$xi:$ze" "$P_STUDY_WITH_TILED:$txi:$tze"; do
    IFS=: read -r tag wxi wze <<< "$which"
    cw="$M/cases/study-$s-$tag.toml"
    with_wall scans/study.toml "$wxi" "$wze" "study-$s-$tag" > "$cw"
    cg="$M/cases/study-$s-$tag-gaussian.toml"
    with_wall scans/study.toml "$wxi" "$wze" "study-$s-$tag-gaussian" "surfaces=$GAUSS_SURFACES" > "$cg"
    grep -q "^delta_xi_deg = $wxi\$" "$cw" && grep -q "^surfaces = $GAUSS_SURFACES\$" "$cg" \
      || { echo "measured-walls.sh: could not write $cw, $cg" >&2; exit 1; }
    run deterministic --case "$cg" --particles "$N" --out "$d/$tag/$P_STUDY_GAUSSIAN/$P_DETERMINISTIC"
    run compare --a "$det" --b "$d/$tag/$P_STUDY_GAUSSIAN/$P_DETERMINISTIC" --out "$d/$tag/$P_STUDY_GAUSSIAN/$P_COMPARE"
    models "$det" "$cw" "$d/$tag"
  done
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "measured walls"
