# Sourced by scripts/pipe-flow.sh (the study) and run_checks.sh (the tests' coarse version):
# the steps of a pipe-flow study in code_saturne, each one run_phase.sh run. The caller sets
#   PIPE_EX     this directory          WORK   the study directory (runs, params, study.tsv)
#   D L UB      pipe diameter (m), section length (m), bulk velocity (m/s)
#   RHO         particle density        NPART  particles per diameter
#   DT_FLUID NT_FLUID   the fluid run's time step (s) and steps
#   DT NP T_DEV         the particle runs' time step, steps, and start of their sampling window
#   JOBS        particle runs at once
#   WALLS       name:code:delta_xi:delta_zeta ... (codes: 0 smooth, 1 isotropic, 2 lay along
#               the axis, 3 lay around the circumference)
# and calls: study_init; setup (setup_pipe.sh); fluid STUDY; inject STUDY D_UM;
# particles_run ... (queues); run_all.

model_code() { case $1 in paper) echo 0 ;; sh1999) echo 1 ;; calibrated) echo 5 ;; *) echo "unknown model $1" >&2; return 1 ;; esac; }
steps() { awk -v t="$1" -v dt="$DT" 'BEGIN { printf "%d", t / dt + 0.5 }'; }

study_init() {
  WORK=${WORK%/}
  # one run at a time per study directory: a second one would delete the first one's runs
  mkdir -p "$(dirname "$WORK")"
  exec 9> "$WORK.lock"
  flock -n 9 || { echo "pipe-flow: $WORK is in use by another run (lock $WORK.lock)" >&2; exit 1; }
  # never delete a directory that is not a previous study (or empty)
  if [ -d "$WORK" ] && [ ! -f "$WORK/study.tsv" ] && [ -n "$(ls -A "$WORK")" ]; then
    echo "pipe-flow: $WORK holds files that are not a pipe-flow study; give a new or empty directory" >&2
    exit 1
  fi
  rm -rf "$WORK"
  mkdir -p "$WORK/runs" "$WORK/params"
  printf 'name\tkind\tdiameter_um\twall\tmodel\tdir\n' > "$WORK/study.tsv"
  RUNS=()
}

# params FILE PHASE NT [KEY VALUE ...]: a pipe.params file (a later key overrides an earlier).
params() {
  local f=$1 phase=$2 nt=$3
  shift 3
  {
    printf 'phase %s\nnt %s\ndiameter_pipe %s\nlength %s\nu_bulk %s\n' "$phase" "$nt" "$D" "$L" "$UB"
    while [ $# -gt 0 ]; do printf '%s %s\n' "$1" "$2"; shift 2; done
  } > "$f"
}

# fluid STUDY: the converged RANS flow of STUDY on 2 ranks; fails unless the pressure
# gradient changed by less than 0.2 % over the last 100 steps and the bulk velocity is
# within 0.1 % of UB. Writes STUDY/fluid/converged.txt (with the first cells' y+).
fluid() {
  local s=$1 name
  name=$(basename "$s")
  params "$WORK/params/fluid-$name.params" 0 "$NT_FLUID" dt "$DT_FLUID"
  "$PIPE_EX/run_phase.sh" "$s/build" "$s/fluid" - 2 "$WORK/params/fluid-$name.params" "fluid $name"
  grep -h "pipe: step" "$s/fluid/run_solver.log" | awk -v ub="$UB" -v name="$name" '
    { u[NR] = $6; g[NR] = $(NF - 1) }
    END {
      n = NR; if (n < 6) { print "pipe-flow: fluid " name ": too few steps logged" > "/dev/stderr"; exit 1 }
      dg = (g[n] - g[n - 5]) / g[n]; du = (u[n] - ub) / ub
      printf "fluid %s: bulk velocity %.5g m/s, pressure gradient %.5g Pa/m (change over the last 100 steps %.2g)\n", name, u[n], g[n], dg
      if (dg < 0) dg = -dg; if (du < 0) du = -du
      if (dg > 2e-3 || du > 1e-3) { print "pipe-flow: fluid " name " has not converged: see its run_solver.log" > "/dev/stderr"; exit 1 }
    }' > "$s/fluid/converged.txt"
  grep -h "pipe: first-cell y+" "$s/fluid/run_solver.log" | tail -1 | sed "s/^pipe:/fluid $name:/" \
    >> "$s/fluid/converged.txt"
  sed 's/^/  /' "$s/fluid/converged.txt"
}

# inject STUDY D_UM: NPART particles of diameter D_UM put into the converged flow (one rank:
# the particle runs restart from them, on any number of ranks).
inject() {
  local s=$1 d=$2
  local f=$WORK/params/inject-$(basename "$s")-$d.params
  params "$f" 1 $((NT_FLUID + 1)) dt "$DT" n_particles "$NPART" \
    d_p "$(awk -v d="$d" 'BEGIN { print d * 1e-6 }')" rho_p "$RHO" dispersion 1
  "$PIPE_EX/run_phase.sh" "$s/build" "$s/inject-$d" "$s/fluid/checkpoint" 1 "$f" "inject $(basename "$s") $d um"
}

# particles_run NAME KIND STUDY D_UM WALL MODEL [KEY VALUE ...]: queues one wall's run (a
# line of study.tsv and its params file; run_all runs them). KEY VALUE pairs override the
# params (e.g. law 0 dispersion 0 t_sample 0.9 np 2000); `nprocs N` sets its MPI ranks (1).
# The physics by default: the Sec. 4 collision law, code_saturne's Langevin dispersion (its
# complete model where COMPLETE_LANGEVIN=1, the simplified one otherwise), the spin carried
# between hits, the Saffman-Mei and the Magnus lift.
particles_run() {
  local name=$1 kind=$2 s=$3 d=$4 wall=$5 model=$6
  shift 6
  local code="" xi ze w wn np=$NP nprocs=1 extra=() mc
  for w in $WALLS; do
    IFS=: read -r wn code xi ze <<< "$w"
    [ "$wn" = "$wall" ] && break
    code=""
  done
  [ -n "$code" ] || { echo "pipe-flow: unknown wall $wall" >&2; exit 1; }
  mc=$(model_code "$model") || exit 1
  while [ $# -gt 0 ]; do
    case $1 in np) np=$2 ;; nprocs) nprocs=$2 ;; *) extra+=("$1" "$2") ;; esac
    shift 2
  done
  params "$WORK/params/$name.params" 2 $((NT_FLUID + 1 + np)) dt "$DT" wall "$code" \
    delta_xi_deg "$xi" delta_zeta_deg "$ze" model "$mc" law 1 preset 1 \
    nt_restart $((NT_FLUID + 1)) seed 2021 n_particles "$NPART" d_p "$(awk -v d="$d" 'BEGIN { print d * 1e-6 }')" \
    rho_p "$RHO" dispersion 1 complete_langevin "${COMPLETE_LANGEVIN:-0}" spin 1 saffman 1 \
    magnus 1 t_sample "$T_DEV" n_bins 20 log_hits 1 \
    mesh_sides "$(awk '$1 == "NC" { print 4 * $2 }' "$s/mesh.txt")" "${extra[@]}"
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$kind" "$d" "$wall" "$model" "runs/$name" >> "$WORK/study.tsv"
  RUNS+=("$s|$name|$d|$nprocs")
}

# run_all: the queued particle runs, JOBS at a time; stops at the first failure (and on
# INT or TERM, stopping the runs under way).
run_all() {
  local n=${#RUNS[@]} k=0 failed=0 t0 s name d np pid
  local -a pids=()
  t0=$(date +%s)
  echo "  $n particle runs, $JOBS at a time, $NPART particles x $NP steps each"
  export PIPE_TTY_PROGRESS
  PIPE_TTY_PROGRESS=$([ "$JOBS" = 1 ] && echo 1 || echo 0)
  trap 'kill -TERM "${pids[@]}" 2>/dev/null; wait; echo "pipe-flow: stopped" >&2; exit 130' INT TERM
  for r in "${RUNS[@]}"; do
    IFS='|' read -r s name d np <<< "$r"
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || failed=1; done
    [ "$failed" = 0 ] || break
    k=$((k + 1))
    echo "  [$k/$n] $name ($(($(date +%s) - t0)) s)"
    "$PIPE_EX/run_phase.sh" "$s/build" "$WORK/runs/$name" "$s/inject-$d/checkpoint" "$np" \
      "$WORK/params/$name.params" "$name" &
    pids+=("$!")
  done
  # every run's own status (wait -n above may have missed one that ended meanwhile)
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
  trap - INT TERM
  [ "$failed" = 0 ] || { echo "pipe-flow: a particle run failed (above)" >&2; return 1; }
  echo "  particle runs done in $(($(date +%s) - t0)) s"
}
