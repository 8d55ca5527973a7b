#!/usr/bin/env bash
# Installs everything the tests against real systems and the reference benchmarks need, and
# is the only script of this repository that installs anything. Idempotent: when every
# package is there it changes nothing (no apt-get update either).
#
#   Debian packages (apt-get, after apt-get update, as root or through sudo):
#     gfortran                      the Fortran example of the C library
#     code-saturne (6.0.x)          the C library at every wall hit of a real CFD code
#     gmsh                          the mesh of the pipe-flow study (examples/code_saturne/pipe)
#     openfoam (v1912)              Finnie erosion reference (particleErosion)
#     slurmctld slurmd slurm-client munge iproute2 util-linux
#                                   shards on a local Slurm cluster
#   Python packages (pip, into the virtual environment $REBOUND_VENV, default <repo>/.venv):
#     pysand==2.0.0                 DNV RP-O501 erosion reference
#     numpy                         the NumPy rsgeng2D of scripts/bench-surface-numpy.sh
#     surfacetopography==1.27.1     the reference reader of the instrument scans that
#                                   crates/topography reads (tests/real_systems/surfacetopography.rs)
#     maturin==1.16.0               builds the Python package's wheel (crates/roughwall-py;
#                                   tests/real_systems/python.rs, scripts/bench-python.sh)
#     pytest==9.2.0                 runs the Python package's tests (crates/roughwall-py/tests)
#     matplotlib==3.11.2            the figure of examples/python/channel.py
#
# The Rust toolchain (cargo, rustc) and a C compiler are assumed: `cargo test --workspace`
# needs nothing else.
#
# Usage: scripts/install-deps.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
say() { echo "install-deps: $*" >&2; }
die() { echo "install-deps: $*" >&2; exit 1; }

apt_packages=(gfortran code-saturne gmsh openfoam slurmctld slurmd slurm-client munge iproute2 util-linux)
pip_packages=("pysand==2.0.0" numpy "surfacetopography==1.27.1" "maturin==1.16.0" "pytest==9.2.0" "matplotlib==3.11.2")
venv=${REBOUND_VENV:-$root/.venv}

# ---- Debian packages --------------------------------------------------------------------
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for p in "${apt_packages[@]}"; do installed "$p" || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  command -v apt-get >/dev/null || die "apt-get not found: install ${missing[*]} by hand"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || die "need root (or sudo) to install ${missing[*]}"
    sudo=sudo
  fi
  say "installing ${missing[*]}"
  # Keep the packages' maintainer scripts from starting munge and Slurm as services: the
  # Slurm test starts its own daemons on 127.0.0.1 and stops them by their process ids.
  prc=/usr/sbin/policy-rc.d
  backup=""
  if [ -e "$prc" ] || [ -L "$prc" ]; then
    backup=$($sudo mktemp /usr/sbin/.policy-rc.d.install-deps.XXXXXX)
    $sudo cp -a "$prc" "$backup"
  fi
  restore() {
    if [ -n "$backup" ]; then $sudo mv -f "$backup" "$prc"; else $sudo rm -f "$prc"; fi
  }
  trap restore EXIT
  printf '#!/bin/sh\nexit 101\n' | $sudo tee "$prc" >/dev/null
  $sudo chmod 755 "$prc"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends \
    -o Dpkg::Options::=--force-confdef -o Dpkg::Options::=--force-confold "${missing[@]}"
  restore
  trap - EXIT
else
  say "Debian packages already installed: ${apt_packages[*]}"
fi
ver=$(dpkg-query -W -f='${Version}' code-saturne)
case "$ver" in
  6.0.*) ;;
  *) die "code-saturne $ver is not 6.0.x: the wall hook of examples/code_saturne is written for 6.0" ;;
esac

# ---- Python packages ----------------------------------------------------------------------
command -v python3 >/dev/null || die "python3 not found"
if [ ! -x "$venv/bin/python" ]; then
  say "creating the virtual environment $venv"
  python3 -m venv "$venv"
fi
need=()
for spec in "${pip_packages[@]}"; do
  name=${spec%%==*}
  want=${spec#*==}; [ "$want" = "$spec" ] && want=""
  have=$("$venv/bin/python" -c "import importlib.metadata as m; print(m.version('$name'))" 2>/dev/null || true)
  if [ -z "$have" ] || { [ -n "$want" ] && [ "$have" != "$want" ]; }; then need+=("$spec"); fi
done
if [ ${#need[@]} -gt 0 ]; then
  say "pip install ${need[*]} into $venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check "${need[@]}"
else
  say "Python packages already installed in $venv: ${pip_packages[*]}"
fi
say "done"
