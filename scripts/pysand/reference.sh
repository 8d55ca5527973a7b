#!/usr/bin/env bash
# Reference values of Equinor's pysand DNV RP-O501 erosion function, for the Rust check of
# `[erosion] model = "dnv"` (tests/real_systems/erosion_references.rs).
# Usage: scripts/pysand/reference.sh OUTDIR   (the committed copy is tests/data/)
# Runs pysand (pinned) from the project's virtual environment, which scripts/install-deps.sh
# makes: $REBOUND_VENV, default <repo>/.venv. Writes OUTDIR/dnv_pysand.csv and
# OUTDIR/dnv_pysand_F.csv.
set -euo pipefail
die() { echo "pysand/reference.sh: $*" >&2; exit 1; }
[ $# -eq 1 ] || die "usage: reference.sh OUTDIR"
[ -d "$1" ] || die "output directory $1 does not exist"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="${REBOUND_VENV:-$root/.venv}"
version="2.0.0"
have="$("$venv/bin/python" -c 'import importlib.metadata as m; print(m.version("pysand"))' 2>/dev/null || true)"
[ "$have" = "$version" ] || die "pysand $version not found in $venv (found: ${have:-none}): run scripts/install-deps.sh"
exec "$venv/bin/python" "$here/reference.py" "$1"
