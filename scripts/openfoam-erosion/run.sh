#!/usr/bin/env bash
# OpenFOAM v1912 (Debian package `openfoam`) reference for Finnie erosion on a
# smooth wall.  Usage: scripts/openfoam-erosion/run.sh OUT.csv
# Needs Debian's openfoam (scripts/install-deps.sh). Runs case/ twice (erosionParameters A: K=2,
# and B: K=1.5) in a temporary directory, writes one CSV row per wall impact.
set -euo pipefail

die() { echo "openfoam-erosion/run.sh: $*" >&2; exit 1; }

[ $# -eq 1 ] || die "usage: run.sh OUT.csv"
out=$1
case "$out" in /*) ;; *) out="$PWD/$out" ;; esac
[ -d "$(dirname "$out")" ] || die "output directory $(dirname "$out") does not exist"

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
[ -d "$here/case/system" ] || die "case directory $here/case not found"
command -v python3 >/dev/null || die "python3 not found"

# ---- Debian's OpenFOAM (scripts/install-deps.sh installs it) ----------------
status=$(dpkg-query -W -f='${Status}' openfoam 2>/dev/null || true)
[ "$status" = "install ok installed" ] || die "Debian's openfoam is not installed: run scripts/install-deps.sh"
version=$(dpkg-query -W -f='${Version}' openfoam)
case "$version" in
    1912.*) ;;
    *) echo "openfoam-erosion: warning: reference made with OpenFOAM 1912, found $version" >&2 ;;
esac
for exe in blockMesh icoUncoupledKinematicParcelFoam; do
    [ -x "/usr/bin/$exe" ] || die "/usr/bin/$exe missing (package openfoam $version)"
done
# Debian's etc/bashrc cannot be sourced (bin/foamEtcFile missing); the
# binaries only need WM_PROJECT_DIR to find etc/controlDict.
export WM_PROJECT_DIR=/usr/share/openfoam
export LC_ALL=C

# ---- run --------------------------------------------------------------------
tmp=$(mktemp -d "${TMPDIR:-/tmp}/openfoam-erosion.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

foam() {  # foam RUNDIR APP
    # subshell + 2>/dev/null: keep bash's "Aborted" job notice off the terminal
    if ! ( "/usr/bin/$2" -case "$1" > "$1/log.$2" 2>&1; exit $? ) 2>/dev/null; then
        # the FOAM FATAL message text, joined onto one line
        msg=$(awk '/FOAM FATAL/ {on=1; next}
                   on && /From function|FOAM exiting|FOAM aborting/ {exit}
                   on && NF {sub(/^ +/, ""); printf "%s%s", sep, $0; sep=" "}' \
              "$1/log.$2" || true)
        die "$2 failed in variant $(basename "$1"): ${msg:-$(tail -n1 "$1/log.$2")}"
    fi
}

for variant in A B; do
    run="$tmp/$variant"
    cp -r "$here/case" "$run"
    if [ "$variant" = B ]; then
        cp "$run/constant/erosionParameters.B" "$run/constant/erosionParameters"
    fi
    foam "$run" blockMesh
    foam "$run" icoUncoupledKinematicParcelFoam
done

# extract.py prints its own one-line error and exits 1 on failure
python3 "$here/extract.py" "$out" "$tmp/A" "$tmp/B" || exit 1
