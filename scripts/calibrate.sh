#!/usr/bin/env bash
# A model within the deterministic noise? (issue "which rough-wall model to trust", part 3)
#  1. `rebound calibrate` on configs/calibration/aniso.toml regenerates the escape table the
#     library ships (crates/roughwall/src/calibrated/aniso-escape.csv) and checks it is byte-identical.
#  2. On every scene below, `deterministic` and then the stochastic model twice — the paper's
#     (`radenkovic-simonin-2021`) and `calibrated` — both run with the deviations MEASURED on
#     the deterministic surface (its run.toml), so that the comparison isolates the model from
#     the surface's discretisation (the generated surfaces have 1-3 % less slope than nominal).
#     Two walls the table was not calibrated on: (5°, 5°) and (4°, 1°). The deterministic
#     run's own noise: the same scene on another surface (seed 7) against the first. The
#     model run's own noise: `calibrated` again with seed $P_CALIBRATION_RESEED.
#  3. The same against an ensemble: `deterministic` with `[deterministic] surfaces =
#     $P_CALIBRATION_SURFACES` (the histories spread over that many surfaces), its noise another
#     ensemble (seed 7), the models with the deviations measured over the ensemble. One
#     100-c_L surface has quirks of its own (another surface moves mean α⁺ by up to 0.2°); a
#     statistical wall model stands for the ensemble, and the goal is judged against it. Two
#     ensembles of 16 surfaces still differed by up to 0.074° (more than the goal's bias
#     bound), two of 64 by at most 0.05°.
# Writes $REBOUND_RESULTS/calibration/; `rebound report` turns it into a REPORT.md section.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
C=$OUT/$P_CALIBRATION
mkdir -p "$C/cases"
stage_start "Calibration: escape table"
if [ "$QUICK" = 1 ]; then
  # Two surface realisations instead of the shipped table's 16 (memory and time).
  quick="$C/cases/calibration-quick.toml"
  sed "s/^surfaces = .*/surfaces = 2/" configs/calibration/aniso.toml > "$quick"
  grep -q "^surfaces = 2\$" "$quick" || { echo "calibrate.sh: could not write $quick" >&2; exit 1; }
  run calibrate --case "$quick" --particles 2000 --out "$C/$P_CALIBRATION_TABLE"
else
  run calibrate --case calibration/aniso.toml --out "$C/$P_CALIBRATION_TABLE"
  if cmp -s "$C/$P_CALIBRATION_TABLE/escape_table.csv" crates/roughwall/src/calibrated/aniso-escape.csv; then
    echo "shipped table: byte-identical" > "$C/$P_CALIBRATION_TABLE/shipped.txt"
  else
    echo "shipped table: DIFFERENT from crates/roughwall/src/calibrated/aniso-escape.csv" > "$C/$P_CALIBRATION_TABLE/shipped.txt"
  fi
  cat "$C/$P_CALIBRATION_TABLE/shipped.txt"
fi
stage_end
N=$(particles 1000000 2000)
SURFACES=$(particles "$P_CALIBRATION_SURFACES" 2)
# benchmark CASE DIR TAG: `deterministic` on CASE, its noise (seed 7) and both models against
# it, under DIR; TAG names the generated stochastic cases.
benchmark() {
  local s=$1 d=$2 tag=$3
  local det="$d/$P_DETERMINISTIC"
  run deterministic --case "$s" --particles "$N" --out "$det"
  # The deterministic run's own noise: the same scene on other surfaces (another seed),
  # compared with the first; a model is within the noise when it is no farther than this.
  run deterministic --case "$s" --particles "$N" --seed 7 --out "$d/$P_CALIBRATION_NOISE/$P_DETERMINISTIC"
  run compare --a "$det" --b "$d/$P_CALIBRATION_NOISE/$P_DETERMINISTIC" --out "$d/$P_CALIBRATION_NOISE/$P_COMPARE"
  local xi ze
  xi=$(awk -F' = ' '/^measured_delta_xi_deg/{print $2; exit}' "$det/run.toml")
  ze=$(awk -F' = ' '/^measured_delta_zeta_deg/{print $2; exit}' "$det/run.toml")
  [ -n "$xi" ] && [ -n "$ze" ] || { echo "calibrate.sh: no measured deviations in $det/run.toml" >&2; exit 1; }
  for v in radenkovic-simonin-2021 calibrated; do
    local case_file="$C/cases/$tag-$v.toml"
    # The scene with the measured deviations and the model; the rest of the case unchanged.
    variant_case "$s" "$v" "$xi" "$ze" > "$case_file"
    grep -q "^delta_xi_deg = $xi\$" "$case_file" && grep -q "^model = \"$v\"" "$case_file" \
      || { echo "calibrate.sh: could not write $case_file" >&2; exit 1; }
    run stochastic --case "$case_file" --particles "$N" --out "$d/$v/$P_STOCHASTIC"
    run compare --a "$det" --b "$d/$v/$P_STOCHASTIC" --out "$d/$v/$P_COMPARE"
  done
  # The model run's own noise: `calibrated` again with another seed, against the same
  # reference (the worst cells of a 10⁶-particle run move by a few hundredths of a degree).
  local re="$d/$P_CALIBRATION_RESEEDED"
  run stochastic --case "$C/cases/$tag-calibrated.toml" --particles "$N" --seed "$P_CALIBRATION_RESEED" --out "$re/$P_STOCHASTIC"
  run compare --a "$det" --b "$re/$P_STOCHASTIC" --out "$re/$P_COMPARE"
}
for s in $P_CALIBRATION_SCENES; do
  scene=$(basename "$s")
  stage_start "Calibration: $scene"
  benchmark "$s.toml" "$C/$scene" "$scene"
  stage_end
  stage_start "Calibration: $scene, $SURFACES surfaces"
  # The scene with `[deterministic] surfaces`; the rest unchanged.
  ens="$C/cases/$scene-$P_CALIBRATION_ENSEMBLE.toml"
  sed "s/^\[deterministic\]\$/[deterministic]\nsurfaces = $SURFACES/" "configs/$s.toml" > "$ens"
  grep -q "^surfaces = $SURFACES\$" "$ens" || { echo "calibrate.sh: could not write $ens" >&2; exit 1; }
  benchmark "$ens" "$C/$scene/$P_CALIBRATION_ENSEMBLE" "$scene-$P_CALIBRATION_ENSEMBLE"
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "calibration"
