#!/usr/bin/env bash
# Which rough-wall model to trust: every stochastic variant (`[stochastic] model`) against
# `deterministic` on every Sec. 3 and Sec. 4 scene of Radenkovic & Simonin 2021. Reuses the
# deterministic runs of scripts/radenkovic2021.sh when the same reproduce-all.sh made them
# (same case, particles and directory; run_once), runs them otherwise,
# runs each variant with the same particles per condition and compares. Writes
# $REBOUND_RESULTS/wall-models/<scene>/<variant>/{stochastic,compare}/; `rebound report`
# aggregates them into wall_models.csv and a REPORT.md table.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
W=$OUT/$P_WALL_MODELS
R=$OUT/$P_RADENKOVIC2021
mkdir -p "$W/cases"
N=$(particles 100000 2000)
VARIANTS="radenkovic-simonin-2021 sommerfeld-huber-1999 gaussian-angle gaussian-tilt normal-perturbation calibrated measured-wall"
# The scenes are directories under $R (sec3-aniso, …); a scene's name drops the prefix.
for sdir in $P_WALL_MODELS_SCENES; do
  scene=${sdir#"$P_SEC3"}
  scene=${scene#"$P_SEC4"}
  det="$R/$sdir/$P_DETERMINISTIC"
  stage_start "Wall models $scene"
  run_once deterministic --case "cases/$scene.toml" --particles "$N" --out "$det"
  for v in $VARIANTS; do
    # The measured-wall model is one measured wall's: scripts/measured-wall-model.sh runs it
    # on the real scans, against the reference on each.
    [ "$v" != measured-wall ] || continue
    case_file="$W/cases/$scene-$v.toml"
    variant_case "cases/$scene.toml" "$v" > "$case_file"
    grep -q "model = \"$v\"" "$case_file" || { echo "wall-models.sh: could not write $case_file" >&2; exit 1; }
    run stochastic --case "$case_file" --particles "$N" --out "$W/$scene/$v/$P_STOCHASTIC"
    run compare --a "$det" --b "$W/$scene/$v/$P_STOCHASTIC" --out "$W/$scene/$v/$P_COMPARE"
  done
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "wall models"
