#!/usr/bin/env bash
# Erosion against the nominal impact angle (issue 12): glass on steel, Finnie's law, |U| =
# 20 m/s, for a smooth wall, isotropic roughness, 2-D roughness and both anisotropic walls
# of Radenkovic & Simonin 2021, Sec. 3, at β⁻ = 0°, 45° and 90°, from `deterministic` and
# `stochastic`. The base case is configs/cases/erosion-glass-steel.toml; each wall gets a
# copy with its deviations. Writes $REBOUND_RESULTS/erosion/<wall>/{deterministic,stochastic}/;
# `rebound report` aggregates them (erosion.csv, erosion.svg, REPORT.md section).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
E=$OUT/$P_EROSION
mkdir -p "$E/cases"
N=$(particles 100000 1000)
if [ "$QUICK" = 1 ]; then
  ALPHAS="-1.0, -5.0, -17.0, -45.0, -90.0"
else
  ALPHAS="-1.0, -2.0, -3.0, -5.0, -7.5, -10.0, -12.5, -15.0, -17.5, -20.0, -25.0, -30.0, -35.0, -40.0, -45.0, -50.0, -60.0, -70.0, -80.0, -90.0"
fi
# The walls, name:Δξ:Δζ (degrees), and the directions β⁻: crates/reproduce/src/paths.rs (paths.sh).
BETAS=$(echo "$P_EROSION_BETAS_DEG" | sed 's/ /, /g')
for w in $P_EROSION_WALLS; do
  IFS=: read -r name dxi dze <<< "$w"
  case_file="$E/cases/$name.toml"
  sed -e "s/^name = .*/name = \"erosion-$name\"/" \
      -e "s/^delta_xi_deg = .*/delta_xi_deg = $dxi/" \
      -e "s/^delta_zeta_deg = .*/delta_zeta_deg = $dze/" \
      -e "s/^alpha_deg = .*/alpha_deg = [$ALPHAS]/" \
      -e "s/^beta_deg = .*/beta_deg = [$BETAS]/" \
      configs/cases/erosion-glass-steel.toml > "$case_file"
  grep -q "delta_xi_deg = $dxi" "$case_file" || { echo "erosion.sh: could not write $case_file" >&2; exit 1; }
  stage_start "Erosion $name: deterministic + stochastic"
  run deterministic --case "$case_file" --particles "$N" --out "$E/$name/$P_DETERMINISTIC"
  run stochastic --case "$case_file" --particles "$N" --out "$E/$name/$P_STOCHASTIC"
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "erosion"
