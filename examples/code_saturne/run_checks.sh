#!/usr/bin/env bash
# The code_saturne checks of the roughwall C library (run by tests/real_systems/code_saturne.rs):
#  (a) a smooth elastic roughwall wall gives the trajectories of code_saturne's built-in
#      CS_LAGR_REBOUND bit for bit (compare_traj.py: same particles, steps and cells; every
#      position, velocity and restart point identical as printed with %.17g). roughwall
#      computes a smooth elastic rebound as code_saturne does, u - (2 (u.n)) n in global
#      axes with the same operations in the same order. TOL > 0 (environment) would accept
#      max |a - b| <= TOL instead, for experiments only;
#  (b) the Sec. 4 glass-steel wall: the run's wall hits, for the comparison with
#      `rebound stochastic` that the Rust test makes.
# Needs code_saturne 6.0.x (Debian's 6.0.2), gcc and gfortran: scripts/install-deps.sh installs them.
# Usage: run_checks.sh WORKDIR   Prints "CHECK (a): PASS" and "HITS (b): <dir>" on success.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=${1:?usage: run_checks.sh WORKDIR}
mkdir -p "$work"
for c in code_saturne gcc gfortran python3; do
  command -v "$c" >/dev/null 2>&1 || { echo "run_checks.sh: $c not found: run scripts/install-deps.sh" >&2; exit 1; }
done
case "$(dpkg-query -W -f='${Version}' code-saturne 2>/dev/null)" in
  6.0.*) ;;
  *) echo "run_checks.sh: code_saturne 6.0.x needed (the wall hook is written for 6.0): run scripts/install-deps.sh" >&2; exit 1 ;;
esac
export USER=${USER:-root}
t0=$(date +%s.%N)
declare -A resu
for mode in builtin user; do
  resu[$mode]=$("$here/setup_case.sh" smooth "$mode" "$work/a-$mode")
  "$work/a-$mode/run.sh" > "$work/a-$mode.log" 2>&1 || { tail -30 "$work/a-$mode.log" >&2; exit 1; }
done
python3 "$here/compare_traj.py" "${resu[builtin]}" "${resu[user]}" --tol "${TOL:-0}" --hits "${resu[user]}"
resu_c=$("$here/setup_case.sh" rough user "$work/c")
"$work/c/run.sh" > "$work/c.log" 2>&1 || { tail -30 "$work/c.log" >&2; exit 1; }
python3 "$here/compare_traj.py" "${resu[user]}" "$resu_c" --rough
t1=$(date +%s.%N)
resu_b=$("$here/setup_case.sh" glass-steel user "$work/b")
"$work/b/run.sh" > "$work/b.log" 2>&1 || { tail -30 "$work/b.log" >&2; exit 1; }
t2=$(date +%s.%N)
grep -h "roughwall" "$resu_b"/listing 2>/dev/null | head -1 || true
echo "HITS (b): $resu_b"
awk -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN {printf "times: check (a) %.1f s, run (b) %.1f s\n", b - a, c - b}'
