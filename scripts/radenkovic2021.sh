#!/usr/bin/env bash
# Radenkovic & Simonin 2021: Table 1, Figs. 1, 4, 6–12 (Sec. 3) and 14–17 (Sec. 4).
# Writes into $REBOUND_RESULTS/radenkovic2021/. Safe to re-run: every output is rewritten.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
R=$OUT/$P_RADENKOVIC2021
mkdir -p "$R"

# --- Table 1 and Fig. 1: the paper's surface (N = 5001, L = 5 mm) -----------------------
stage_start "Table 1, Fig. 1 (surface)"
if [ "$QUICK" = 1 ]; then
  mkdir -p "$R/cases"
  cat > "$R/cases/table1-quick.toml" <<'TOML'
name = "table1-quick"
seed = 1
[surface]
length_um = 1024.0
nodes = 1024
rms_height_um = 0.37
corr_length_x_um = 12.0
corr_length_z_um = 4.0
[stats]
beta_star_deg = [0.0, 30.0, 60.0, 90.0]
TOML
  run surface --case "$R/cases/table1-quick.toml" --out "$R/$P_TABLE1"
else
  run surface --case cases/table1.toml --out "$R/$P_TABLE1"
fi
stage_end

# --- Fig. 4: rms slope and Δξ, Δζ against h/c_L -------------------------------------------
stage_start "Fig. 4 (surface sweep)"
mkdir -p "$R/$P_FIG4/cases"
if [ "$QUICK" = 1 ]; then NODES=256; LEN=256.0; HS="0.2 0.8"; else NODES=2048; LEN=1024.0; HS="0.05 0.1 0.2 0.3 0.4 0.5 0.6 0.8 1.0"; fi
for h in $HS; do
  cat > "$R/$P_FIG4/cases/h$h.toml" <<TOML
name = "fig4-h$h"
seed = 4
[surface]
length_um = $LEN
nodes = $NODES
rms_height_um = $h
corr_length_x_um = 8.0
corr_length_z_um = 4.0
TOML
  run surface --case "$R/$P_FIG4/cases/h$h.toml" --out "$R/$P_FIG4/$P_FIG4_RUN$h"
done
stage_end

# --- Sec. 3: elastic bouncing on the two anisotropic walls (Figs. 6–12) -------------------
N3=$(particles 100000 2000)
for wall in aniso aniso-rev; do
  stage_start "Sec. 3 $wall: deterministic"
  D=$R/$P_SEC3$wall
  run deterministic --case "cases/$wall.toml" --particles "$N3" --out "$D/$P_DETERMINISTIC"
  stage_end
  stage_start "Sec. 3 $wall: stochastic + compare"
  run stochastic --case "cases/$wall.toml" --particles "$N3" --out "$D/$P_STOCHASTIC"
  run compare --a "$D/$P_DETERMINISTIC" --b "$D/$P_STOCHASTIC" --out "$D/$P_COMPARE"
  stage_end
done

# --- Sec. 4: glass on steel, Sommerfeld–Huber (Figs. 14–17) ---------------------------------
N4=$(particles 100000 2000)
for scene in glass-steel-2d glass-steel-iso glass-steel glass-steel-fig16 glass-steel-fig16-2d glass-steel-fig17 glass-steel-fig17-2d; do
  [ -f "configs/cases/$scene.toml" ] || { echo "missing configs/cases/$scene.toml" >&2; exit 1; }
  stage_start "Sec. 4 $scene"
  D=$R/$P_SEC4$scene
  run deterministic --case "cases/$scene.toml" --particles "$N4" --out "$D/$P_DETERMINISTIC"
  run stochastic --case "cases/$scene.toml" --particles "$N4" --out "$D/$P_STOCHASTIC"
  run compare --a "$D/$P_DETERMINISTIC" --b "$D/$P_STOCHASTIC" --out "$D/$P_COMPARE"
  stage_end
done

[ -n "${REBOUND_NESTED:-}" ] || print_stages "Radenkovic & Simonin 2021"
