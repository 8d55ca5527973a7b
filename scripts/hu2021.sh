#!/usr/bin/env bash
# Hu et al.: Figs. 4, 6, 8–12 and the Eq. (8) comparison with the physical models.
# Writes into $REBOUND_RESULTS/hu2021/. Safe to re-run.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
H=$OUT/$P_HU2021
mkdir -p "$H"
# One run per figure, from configs/cases/hu-<figure>.toml.
for fig in $P_HU2021_FIGS; do
  stage_start "hu-$fig"
  run force-sweep --case "cases/hu-$fig.toml" --out "$H/$fig"
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "Hu et al."
