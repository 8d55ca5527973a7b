#!/usr/bin/env bash
# How much accuracy does each second buy? Deterministic runs at several particle counts and
# grid spacings against a high-resolution reference, and the stochastic model on the same
# scene. `rebound report` turns these runs into speed_vs_error.csv and its figure.
# Writes into $REBOUND_RESULTS/speed-vs-error/. Safe to re-run.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
S=$OUT/$P_SPEED_VS_ERROR
mkdir -p "$S/cases"

case_file() { # spacing_per_corr_length -> case path
  local f="$S/cases/spacing$1.toml"
  cat > "$f" <<TOML
name = "speed-vs-error"
seed = 7
[wall]
delta_xi_deg = 2.5
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-12.5]
beta_deg = [0.0, 60.0]
[particles]
count = 10000
[deterministic]
spacing_per_corr_length = $1
wall_deviations = "eq15"
[output]
bin_width_deg = 0.5
TOML
  echo "$f"
}

if [ "$QUICK" = 1 ]; then REF_N=4000; REF_S=8; COUNTS="1000 2000"; SPACINGS="4 8"; TARGETS="0.2"; CAP=200000
else REF_N=1000000; REF_S=16; COUNTS="1000 10000 100000 1000000"; SPACINGS="4 8 16"; TARGETS="0.1 0.05 0.02 0.01"; CAP=10000000; fi

stage_start "speed-vs-error: reference"
run deterministic --case "$(case_file $REF_S)" --particles "$REF_N" --seed 99 --out "$S/$P_SPEED_REFERENCE"
stage_end

stage_start "speed-vs-error: particle counts"
for n in $COUNTS; do
  run deterministic --case "$(case_file 8)" --particles "$n" --out "$S/${P_SPEED_DETERMINISTIC}n$n-s8"
  run compare --a "$S/$P_SPEED_REFERENCE" --b "$S/${P_SPEED_DETERMINISTIC}n$n-s8" --out "$S/${P_SPEED_DETERMINISTIC}n$n-s8/$P_VS_REFERENCE" --label-a REF --label-b DS
done
stage_end

stage_start "speed-vs-error: grid spacings"
for s in $SPACINGS; do
  n=$(particles 100000 2000)
  # At spacing 8 the particle-count stage above may have made this run already.
  run_once deterministic --case "$(case_file "$s")" --particles "$n" --out "$S/${P_SPEED_DETERMINISTIC}n$n-s$s"
  run_once compare --a "$S/$P_SPEED_REFERENCE" --b "$S/${P_SPEED_DETERMINISTIC}n$n-s$s" --out "$S/${P_SPEED_DETERMINISTIC}n$n-s$s/$P_VS_REFERENCE" --label-a REF --label-b DS
done
stage_end

stage_start "speed-vs-error: stochastic model"
for n in $COUNTS; do
  run stochastic --case "$(case_file 8)" --particles "$n" --out "$S/${P_SPEED_STOCHASTIC}n$n"
  run compare --a "$S/$P_SPEED_REFERENCE" --b "$S/${P_SPEED_STOCHASTIC}n$n" --out "$S/${P_SPEED_STOCHASTIC}n$n/$P_VS_REFERENCE" --label-a REF --label-b SM
done
stage_end

# "How many particles do I need?" as a setting: run whole blocks until the standard errors of
# mean α⁺ and mean β⁺ − β⁻ reach the target (at most CAP particles per condition).
stage_start "speed-vs-error: target standard errors"
for t in $TARGETS; do
  run deterministic --case "$(case_file 8)" --target-se "$t" --particles "$CAP" --out "$S/${P_SPEED_DETERMINISTIC}t$t-s8"
  run compare --a "$S/$P_SPEED_REFERENCE" --b "$S/${P_SPEED_DETERMINISTIC}t$t-s8" --out "$S/${P_SPEED_DETERMINISTIC}t$t-s8/$P_VS_REFERENCE" --label-a REF --label-b DS
  run stochastic --case "$(case_file 8)" --target-se "$t" --particles "$CAP" --out "$S/${P_SPEED_STOCHASTIC}t$t"
  run compare --a "$S/$P_SPEED_REFERENCE" --b "$S/${P_SPEED_STOCHASTIC}t$t" --out "$S/${P_SPEED_STOCHASTIC}t$t/$P_VS_REFERENCE" --label-a REF --label-b SM
done
stage_end
[ -n "${REBOUND_NESTED:-}" ] || print_stages "speed vs error"
