#!/usr/bin/env bash
# The wall's own model (issue 39, parts 3, 4 and 8): for each real scan and particle of
# $P_MODEL_SCANS (scan:D:D…, D in µm, 0 the point particle; each scan a shipped case
# configs/scans/<scan>.toml), `rebound scan --measured-wall` builds the measured-wall tables;
# `deterministic` bounces on the scan itself in place (the reference) twice, with two seeds (the
# noise floor: what two independent references differ by); and the measured-wall model, the
# paper's model and the calibrated model, the last two with the card's deviations for that
# particle, and `deterministic` on 16 Gaussian walls with those deviations, run at incident
# directions between the table's grid points (configs/scans/own-model.toml). Every run is
# compared with the first reference, every run of a particle with PDFs in the same bins, a
# tenth of its rebound angle's spread or finer (bin_width_for, common.sh), so that the KS
# distances are those of the laws. The Gaussian walls' verdict has a noise floor of its own:
# one Gaussian wall of the reference's block size against $P_STUDY_CONTROL_SURFACES such walls. Writes
# $REBOUND_RESULTS/measured-wall-model/; `rebound report` turns it into a REPORT.md section.
# REBOUND_MODEL_SCANS (in place of $P_MODEL_SCANS) and REBOUND_MODEL_HISTORIES (histories per
# table direction) may be set to study a subset or another table resolution.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[ -n "${REBOUND_NESTED:-}" ] || : > "$STAGE_LOG"
M=$OUT/$P_MEASURED_WALL_MODEL
mkdir -p "$M/cases"
N=$(particles 200000 2000)
# The tables' histories per incident direction: the default, or the least in quick mode.
HISTORIES=${REBOUND_MODEL_HISTORIES:-$([ "$QUICK" = 1 ] && echo 1024 || echo 17711)}
GAUSS_SURFACES=$(particles 16 2)

# card_value CARD D KEY: KEY of the card's [wall] (D = 0) or of its [[diameter]] row of D µm.
card_value() {
  awk -v d="$2" -v key="$3" '
    /^\[/ { sec = $0; row = 0 }
    sec == "[[diameter]]" && /^diameter_um = / { row = ($3 + 0 == d + 0) }
    ((d + 0 == 0 && sec == "[wall]") || (d + 0 > 0 && sec == "[[diameter]]" && row)) && $1 == key {
      v = $3; gsub(/"/, "", v); print v; exit
    }
  ' "$1"
}

# own_case D XI ZE NAME [STOCHASTIC_LINES]: the scan's directions ($DIRECTIONS:
# configs/scans/own-model-<scan>.toml where a scan needs its own, else own-model.toml) for
# particles of D µm
# with [wall] XI, ZE and `name = NAME`; then the [stochastic] lines, or, without them (the
# reference), the scan's levelling and a sphere's contact when D > 0 (its diameter goes into
# [particles]: with_d).
own_case() {
  local d=$1 xi=$2 ze=$3 name=$4 st=${5:-}
  sed "s/^name = .*/name = \"$name\"/" "$DIRECTIONS"
  printf '\n[wall]\ndelta_xi_deg = %s\ndelta_zeta_deg = %s\n\n[output]\nbin_width_deg = %s\n' "$xi" "$ze" "$BIN"
  if [ -n "$st" ]; then
    printf '\n[stochastic]\n%b' "$st"
  else
    # The reference levels the scan as its card did, and enters over the one region the
    # particle's table was built on (the card's measured_wall_entry_alpha_deg).
    printf '\n[deterministic]\nscan_level_degree = %s\n' "$DEGREE"
    [ -z "$ENTRY" ] || printf 'entry_alpha_deg = %s\n' "$ENTRY"
    [ "$d" = 0 ] || printf 'contact = "sphere"\n'
  fi
}

for entry in ${REBOUND_MODEL_SCANS:-$P_MODEL_SCANS}; do
  s=${entry%%:*}
  ds=${entry#*:}
  stage_start "Measured-wall model: $s"
  DIRECTIONS=configs/scans/own-model.toml
  [ ! -f "configs/scans/own-model-$s.toml" ] || DIRECTIONS="configs/scans/own-model-$s.toml"
  DEGREE=$(awk -F' = ' '/^level_degree = /{print $2 + 0; exit}' "configs/scans/$s.toml")
  DEGREE=${DEGREE:-1}
  file=$(awk -F' = ' '/^file = /{gsub(/"/, "", $2); split($2,a," "); print a[1]; exit}' "configs/scans/$s.toml")
  spheres=$(echo "$ds" | tr ':' '\n' | awk '$1 + 0 > 0' | paste -sd, -)
  diameters=()
  [ -z "$spheres" ] || diameters=(--diameter-um "$spheres")
  card_dir="$M/$s/$P_MODEL_CARD"
  run scan --case "scans/$s.toml" --measured-wall --measured-wall-histories "$HISTORIES" \
    "${diameters[@]}" --out "$card_dir"
  card="$card_dir/wall_card.toml"
  for d in ${ds//:/ }; do
    p="$M/$s/d$d"
    xi=$(card_value "$card" "$d" delta_xi_deg)
    ze=$(card_value "$card" "$d" delta_zeta_deg)
    table=$(card_value "$card" "$d" measured_wall_table)
    # A particle without a table enters as the point particle's table did.
    ENTRY=$(card_value "$card" "$d" measured_wall_entry_alpha_deg)
    [ -n "$ENTRY" ] || ENTRY=$(card_value "$card" 0 measured_wall_entry_alpha_deg)
    [ -n "$xi" ] && [ -n "$ze" ] || { echo "measured-wall-model.sh: no deviations for $d µm in $card" >&2; exit 1; }
    # Every run of this particle bins its PDFs alike, finely enough for its spread (common.sh).
    BIN=$(bin_width_for "$xi" "$ze")
    particles_line=""
    [ "$d" = 0 ] || particles_line="diameter_um = $d"
    with_d() { if [ -n "$particles_line" ]; then sed "/^\[particles\]/a $particles_line"; else cat; fi; }
    cd_="$M/cases/$s-d$d-reference.toml"
    own_case "$d" "$xi" "$ze" "$s-d$d-reference" | with_d > "$cd_"
    ref="$p/$P_MODEL_REFERENCE/$P_DETERMINISTIC"
    run deterministic --case "$cd_" --surface "configs/scans/$file" --particles "$N" --out "$ref"
    # The noise floor: the same reference with another seed, against the first.
    run deterministic --case "$cd_" --surface "configs/scans/$file" --particles "$N" --seed 2022 \
      --out "$p/$P_MODEL_REFERENCE_2/$P_DETERMINISTIC"
    run compare --a "$ref" --b "$p/$P_MODEL_REFERENCE_2/$P_DETERMINISTIC" --out "$p/$P_MODEL_FLOOR/$P_COMPARE"
    # Gaussian walls with this particle's card deviations (a point particle on them: the
    # deviations are those the particle sees), against the reference.
    cg="$M/cases/$s-d$d-$P_MODEL_GAUSSIAN.toml"
    { sed "s/^name = .*/name = \"$s-d$d-$P_MODEL_GAUSSIAN\"/" "$DIRECTIONS"
      printf '\n[wall]\ndelta_xi_deg = %s\ndelta_zeta_deg = %s\n\n[output]\nbin_width_deg = %s\n\n[deterministic]\nsurfaces = %s\n' \
        "$xi" "$ze" "$BIN" "$GAUSS_SURFACES"; } > "$cg"
    run deterministic --case "$cg" --particles "$N" --out "$p/$P_MODEL_GAUSSIAN/$P_DETERMINISTIC"
    run compare --a "$ref" --b "$p/$P_MODEL_GAUSSIAN/$P_DETERMINISTIC" --out "$p/$P_MODEL_GAUSSIAN/$P_COMPARE"
    # The noise floor of that verdict (part 3; common.sh).
    gaussian_control "$card_dir" "$ref" "$d" "$xi" "$ze" "$DIRECTIONS" "$s-d$d-$P_MODEL_CONTROL" \
      "$M/cases" "$p/$P_MODEL_CONTROL" "$BIN"
    for v in $P_MODEL_MODELS; do
      st="model = \"$v\"\n"
      if [ "$v" = measured-wall ]; then
        [ -n "$table" ] || { echo "measured-wall-model.sh: $card names no table for $d µm: $(card_value "$card" "$d" measured_wall_note)" >&2; continue; }
        st+="wall_table = \"$card_dir/$table\"\n"
      fi
      cv="$M/cases/$s-d$d-$v.toml"
      own_case "$d" "$xi" "$ze" "$s-d$d-$v" "$st" | with_d > "$cv"
      run stochastic --case "$cv" --particles "$N" --out "$p/$v/$P_STOCHASTIC"
      run compare --a "$ref" --b "$p/$v/$P_STOCHASTIC" --out "$p/$v/$P_COMPARE"
    done
  done
  stage_end
done
[ -n "${REBOUND_NESTED:-}" ] || print_stages "measured-wall model"
