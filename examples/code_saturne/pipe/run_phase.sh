#!/usr/bin/env bash
# run_phase.sh BUILD RUN RESTART NPROCS PARAMS LABEL: one run of the pipe-flow study with the
# solver of setup_pipe.sh (BUILD), in the new directory RUN, restarting from RESTART (a
# checkpoint directory, or - for none), on NPROCS MPI ranks, with the parameter file PARAMS
# (copied to RUN/pipe.params). It runs in RUN.part and becomes RUN only when it succeeded: a
# failed or killed run never leaves a RUN that looks finished. A failure ends with one line
# naming LABEL and the solver's log. On a terminal it shows the time step it is at (unless
# PIPE_TTY_PROGRESS=0, as when runs go in parallel); otherwise it prints a line every 30 s.
set -euo pipefail
usage="usage: run_phase.sh BUILD RUN RESTART NPROCS PARAMS LABEL"
build=${1:?$usage} run=${2:?$usage} restart=${3:?$usage} nprocs=${4:?$usage}
params=${5:?$usage} label=${6:?$usage}
export USER=${USER:-root} OMP_NUM_THREADS=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Idle ranks give their core away instead of spinning: with more ranks than cores (two
# 2-rank runs at once on 2 cores, as the tests do) spinning ranks slowed a 400-step fluid run
# from 12 s to 10 min.
export OMPI_MCA_mpi_yield_when_idle=1
part=$run.part
rm -rf "$part" "$run"
mkdir -p "$part"
cp "$build/cs_solver" "$build/mesh_input" "$part/"
cp "$params" "$part/pipe.params"
if [ "$restart" != - ]; then
  [ -d "$restart" ] || { echo "pipe-flow: case $label: no restart directory $restart" >&2; exit 1; }
  ln -s "$(cd "$restart" && pwd)" "$part/restart"
fi
phase=$(awk '$1 == "phase" {print $2}' "$params")
nt=$(awk '$1 == "nt" {print $2}' "$params")

# the step the solver is at: the fluid run logs "pipe: step", the particle runs lagrangian.log
step_now() {
  local s=""
  if [ -f "$part/lagrangian.log" ]; then s=$(tail -1 "$part/lagrangian.log" | awk '{print $1}'); fi
  if [ -z "$s" ] || [ "${s:0:1}" = "#" ]; then
    s=$(grep -h "pipe: step" "$part/run_solver.log" 2>/dev/null | tail -1 | awk '{print $3}')
  fi
  echo "${s:-0}"
}

cd "$part"
if [ "$nprocs" -gt 1 ]; then
  mpiexec -n "$nprocs" ./cs_solver --mpi > run.out 2>&1 &
else
  ./cs_solver > run.out 2>&1 &
fi
pid=$!
trap 'kill "$pid" 2>/dev/null || true' INT TERM
t0=$(date +%s) last=$t0
tty=0
[ -t 2 ] && [ "${PIPE_TTY_PROGRESS:-1}" = 1 ] && tty=1
while kill -0 "$pid" 2>/dev/null; do
  sleep 1
  now=$(date +%s)
  if [ "$tty" = 1 ]; then
    printf '\r  %s: step %s of %s (%d s)   ' "$label" "$(step_now)" "$nt" $((now - t0)) >&2
  elif [ $((now - last)) -ge 30 ]; then
    echo "  $label: step $(step_now) of $nt ($((now - t0)) s)" >&2
    last=$now
  fi
done
rc=0
wait "$pid" || rc=$?
trap - INT TERM
[ "$tty" = 1 ] && printf '\r\033[K' >&2
cd - >/dev/null
ok=1
[ "$rc" -eq 0 ] || ok=0
[ -e "$part/error" ] && ok=0
[ "$phase" = 2 ] && [ ! -f "$part/particles.csv" ] && ok=0
[ -d "$part/checkpoint" ] || ok=0
if [ "$ok" != 1 ]; then
  echo "pipe-flow: case $label failed (exit $rc): see $part/run_solver.log and $part/error" >&2
  exit 1
fi
mv "$part" "$run"
