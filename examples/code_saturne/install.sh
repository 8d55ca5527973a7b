#!/bin/bash
# install.sh: install code_saturne 6.0.x (Debian bookworm: 6.0.2-2) and the
# compilers it needs for user sources, via apt, only when missing.
# Idempotent: a second run does nothing (no apt-get update either).
# The check and the install run under the lock every test of this repository takes
# around apt-get (/tmp/roughwall-apt.lock, see ensure_tools in tests/common/mod.rs), so
# that two of them never run dpkg at the same time.
set -euo pipefail

lock=/tmp/roughwall-apt.lock
touch "$lock" 2>/dev/null || true   # flock needs the file, not write access to it
exec 9<"$lock"
flock 9

need=()
dpkg-query -W -f='${Status}' code-saturne 2>/dev/null | grep -q "install ok installed" || need+=(code-saturne)
command -v gcc      >/dev/null 2>&1 || need+=(gcc)
command -v gfortran >/dev/null 2>&1 || need+=(gfortran)
command -v python3  >/dev/null 2>&1 || need+=(python3)

if [ ${#need[@]} -gt 0 ]; then
  echo "install.sh: installing ${need[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${need[@]}"
else
  echo "install.sh: code-saturne, gcc, gfortran, python3 already present"
fi

flock -u 9
exec 9>&-

ver="$(dpkg-query -W -f='${Version}' code-saturne)"
case "$ver" in
  6.0.*) echo "install.sh: code-saturne $ver OK" ;;
  *) echo "install.sh: WARNING code-saturne $ver is not 6.0.x; the wall hook is pinned to 6.0.x" >&2; exit 1 ;;
esac
