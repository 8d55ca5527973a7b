#!/usr/bin/env bash
# Mirror symmetry of the deterministic wall (beyond the papers): the isotropic (5°, 5°) wall of
# configs/cases/mirror-5-5.toml at β⁻ = ±30°, ±45°, ±60° on several surfaces (seeds), once per
# `[deterministic] triangulation`. A mirror-symmetric wall gives the same statistics at +b
# and −b; `rebound report` tabulates the differences over the surfaces.
# Writes $REBOUND_RESULTS/mirror/<triangulation>/seed<s>/.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
M=$OUT/$P_MIRROR
mkdir -p "$M/cases"
N=$(particles 200000 2000)
# Reduced mode: the first two surfaces (a standard error needs two).
if [ "$QUICK" = 1 ]; then SEEDS=$(echo $P_MIRROR_SEEDS | cut -d' ' -f1-2); else SEEDS=$P_MIRROR_SEEDS; fi
for tri in $P_MIRROR_TRIANGULATIONS; do
  stage_start "Mirror symmetry: $tri"
  c="$M/cases/$tri.toml"
  # The shipped case with the triangulation set; the rest unchanged.
  sed "s/^\[deterministic\]\$/[deterministic]\ntriangulation = \"$tri\"/" "$ROOT/configs/cases/mirror-5-5.toml" > "$c"
  grep -q "^triangulation = \"$tri\"\$" "$c" || { echo "mirror.sh: could not write $c" >&2; exit 1; }
  for s in $SEEDS; do
    run deterministic --case "$c" --seed "$s" --particles "$N" --out "$M/$tri/$P_MIRROR_SEED$s"
  done
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "mirror"
