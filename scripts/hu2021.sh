#!/usr/bin/env bash
# Hu et al.: Figs. 4, 6, 8–12 and the Eq. (8) comparison with the physical models.
# Writes into $REBOUND_RESULTS/hu2021/. Safe to re-run.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
H=$OUT/hu2021
mkdir -p "$H"
for fig in hu-fig4 hu-fig6 hu-fig8 hu-fig9 hu-fig10 hu-fig10b hu-fig11 hu-fig11b hu-fig12; do
  stage_start "$fig"
  run force-sweep --case "cases/$fig.toml" --out "$H/${fig#hu-}"
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "Hu et al."
