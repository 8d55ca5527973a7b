#!/usr/bin/env bash
# Reference values of Equinor's pysand DNV RP-O501 erosion function, for the Rust check of
# `[erosion] model = "dnv"` (tests/erosion_references.rs).
# Usage: scripts/pysand/reference.sh OUTDIR   (the committed copy is tests/data/)
# Installs pysand (pinned) in a virtual environment when missing: $PYSAND_VENV, default
# target/pysand-venv. Writes OUTDIR/dnv_pysand.csv and OUTDIR/dnv_pysand_F.csv.
set -euo pipefail
die() { echo "pysand/reference.sh: $*" >&2; exit 1; }
[ $# -eq 1 ] || die "usage: reference.sh OUTDIR"
[ -d "$1" ] || die "output directory $1 does not exist"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="${PYSAND_VENV:-$root/target/pysand-venv}"
version="2.0.0"
command -v python3 >/dev/null || die "python3 not found"
# One installer at a time (parallel tests share the venv).
mkdir -p "$(dirname "$venv")"
exec 9>"$venv.lock"
flock 9
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv" || die "python3 -m venv $venv failed"
fi
have="$("$venv/bin/python" -c 'import importlib.metadata as m; print(m.version("pysand"))' 2>/dev/null || true)"
if [ "$have" != "$version" ]; then
    log="$(mktemp)"
    if ! "$venv/bin/pip" install --quiet --disable-pip-version-check "pysand==$version" >"$log" 2>&1; then
        msg="$(tail -n1 "$log")"; rm -f "$log"
        die "pip install pysand==$version failed: $msg"
    fi
    rm -f "$log"
fi
flock -u 9
exec "$venv/bin/python" "$here/reference.py" "$1"
