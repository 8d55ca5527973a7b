#!/usr/bin/env bash
# Finite spheres (issue 11): the Sec. 4 glass-on-steel scene with the particle as a sphere
# of diameter D = 50, 100, 250, 500 µm. For each D: `deterministic` with the centre on the
# dilated surface, `stochastic` with the deviations that sphere sees
# (`effective_for_diameter`), and `stochastic` with the wall's nominal deviations; both
# compared with the deterministic run. Writes $REBOUND_RESULTS/finite-size/d<D>/...;
# `rebound report` aggregates them (finite_size.csv, REPORT.md section).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
F=$OUT/$P_FINITE_SIZE
mkdir -p "$F/cases"
N=$(particles 100000 2000)
for d in $P_FINITE_SIZE_DIAMETERS_UM; do
  stage_start "Finite size D = $d um"
  sphere="$F/cases/d$d.toml"
  sed -e "s/^name = .*/name = \"finite-size-d$d\"/" -e "s/^diameter_um = .*/diameter_um = $d.0/" \
      configs/cases/glass-steel-sphere.toml > "$sphere"
  nominal="$F/cases/d$d-nominal.toml"
  sed -e "s/^effective_for_diameter = true$/effective_for_diameter = false/" "$sphere" > "$nominal"
  grep -q "diameter_um = $d.0" "$sphere" && grep -q "effective_for_diameter = false" "$nominal" \
    || { echo "finite-size.sh: could not write the cases" >&2; exit 1; }
  D=$F/$P_FINITE_SIZE_DIAMETER$d
  run deterministic --case "$sphere" --particles "$N" --out "$D/$P_DETERMINISTIC"
  run stochastic --case "$sphere" --particles "$N" --out "$D/$P_STOCHASTIC_EFFECTIVE"
  run stochastic --case "$nominal" --particles "$N" --out "$D/$P_STOCHASTIC_NOMINAL"
  run compare --a "$D/$P_DETERMINISTIC" --b "$D/$P_STOCHASTIC_EFFECTIVE" --out "$D/$P_COMPARE_EFFECTIVE"
  run compare --a "$D/$P_DETERMINISTIC" --b "$D/$P_STOCHASTIC_NOMINAL" --out "$D/$P_COMPARE_NOMINAL"
  stage_end
done
# Grid convergence of the sphere's centre surface (its kinks): D = 100 µm at three spacings.
stage_start "Finite size: grid convergence"
for spc in 4 8 16; do
  c="$F/cases/grid-s$spc.toml"
  sed -e "s/^name = .*/name = \"finite-size-grid-s$spc\"/" -e "s/^diameter_um = .*/diameter_um = 100.0/" \
      -e "s/^contact = \"sphere\"$/contact = \"sphere\"\nspacing_per_corr_length = $spc.0\nside_per_corr_length = 40.0/" \
      configs/cases/glass-steel-sphere.toml > "$c"
  grep -q "spacing_per_corr_length = $spc.0" "$c" || { echo "finite-size.sh: could not write $c" >&2; exit 1; }
  run deterministic --case "$c" --particles "$N" --out "$F/$P_FINITE_SIZE_GRID$spc"
done
stage_end

# The effective-roughness curve over three decades of D on a Table 1-like surface.
stage_start "Effective roughness law"
if [ "$QUICK" = 1 ]; then NODES=512; LEN=512.0; DS="5.0, 50.0, 500.0"; else NODES=2048; LEN=2048.0; DS="1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0"; fi
cat > "$F/cases/law.toml" <<TOML
name = "effective-roughness-law"
seed = 1
[surface]
length_um = $LEN
nodes = $NODES
rms_height_um = 0.37
corr_length_x_um = 12.0
corr_length_z_um = 4.0
[stats]
diameter_um = [$DS]
TOML
run surface --case "$F/cases/law.toml" --out "$F/$P_FINITE_SIZE_LAW"
stage_end
[ -n "${REBOUND_NESTED:-}" ] || print_stages "finite size"
