#!/usr/bin/env bash
# Incident spin (issue 11): mean rebound angle and mean transverse deviation against the
# incident angular velocity, topspin/backspin (ω_z) and sidespin (ω_x), for the Sec. 4 glass-
# on-steel scene (α⁻ = −15°, β⁻ = 0°, 500 µm beads), from `deterministic` and `stochastic`.
# Writes $REBOUND_RESULTS/spin/<axis><value>/{deterministic,stochastic}/; `rebound report`
# aggregates them (spin.csv, spin.svg, REPORT.md section).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
S=$OUT/$P_SPIN
mkdir -p "$S/cases"
N=$(particles 50000 1000)
if [ "$QUICK" = 1 ]; then VALUES="-20000 0 20000"; else VALUES="-40000 -20000 -10000 -5000 0 5000 10000 20000 40000"; fi
stage_start "Spin"
for axis in z x; do
  for w in $VALUES; do
    if [ "$axis" = z ]; then spin="[0.0, 0.0, $w.0]"; else spin="[$w.0, 0.0, 0.0]"; fi
    c="$S/cases/$axis$w.toml"
    cat > "$c" <<TOML
name = "spin-$axis$w"
seed = 2021
[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-15.0]
beta_deg = [0.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16
spin_rad_s = $spin
[particles]
count = $N
diameter_um = 500.0
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
[deterministic]
wall_deviations = "eq15"
TOML
    run deterministic --case "$c" --out "$S/$axis$w/$P_DETERMINISTIC"
    run stochastic --case "$c" --out "$S/$axis$w/$P_STOCHASTIC"
  done
done
stage_end
[ -n "${REBOUND_NESTED:-}" ] || print_stages "spin"
