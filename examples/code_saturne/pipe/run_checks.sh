#!/usr/bin/env bash
# run_checks.sh WORK: the coarse pipe-flow study the tests run (tests/real_systems/pipe_flow.rs),
# in about 20 s: a coarse mesh (6 x 6 cells per quarter and ring, 10 along the axis), 500
# fluid steps, 300 particles of 150 um, 0.05 s before a 0.1 s window:
#   main:        smooth, isotropic (5.95 deg), lay along the axis and around the circumference,
#                (3.8, 7.5) deg, the paper's model, 1 rank, code_saturne's dispersion on, no
#                spin or lift;
#   ranks:       the isotropic wall on 2 ranks (dispersion on, no spin or lift);
#   nodisp-1, nodisp-2: the isotropic wall without dispersion, on 1 and 2 ranks, with the
#                Sec. 4 collision law, spin and both lifts (the spin table across ranks);
#   forces:      the smooth wall, Sec. 4 law, spin and lifts, no dispersion, particles 0-19
#                traced every step (their equation of motion, integrated by the test);
#   kick:        the same, every particle thrown at the wall at 40 m/s after the first step
#                (steep hits: the rolling branch of the collision law).
# Then `rebound pipe-stats` (REBOUND_BIN) into WORK/stats. Prints "STUDY: <dir>".
set -euo pipefail
PIPE_EX=$(cd "$(dirname "$0")" && pwd)
WORK=${1:?usage: run_checks.sh WORK}
REBOUND_BIN=${REBOUND_BIN:?REBOUND_BIN: the rebound binary}
source "$PIPE_EX/study_lib.sh"
D=0.05 L=0.2 UB=20 RHO=2500 NPART=300
DT_FLUID=0.001 NT_FLUID=500 DT=0.0005 T_DEV=0.05 JOBS=2
NP=$(steps 0.15)
WALLS="smooth:0:0:0 iso:1:5.95:5.95 axial:2:3.8:7.5 circ:3:3.8:7.5"
study_init
"$PIPE_EX/setup_pipe.sh" "$WORK/coarse" 6 6 1.1 10 > /dev/null
fluid "$WORK/coarse"
inject "$WORK/coarse" 150
OFF="spin 0 saffman 0 magnus 0"
for w in smooth iso axial circ; do
  # shellcheck disable=SC2086 # OFF is a list of arguments
  particles_run "150um-$w-paper" main "$WORK/coarse" 150 "$w" paper law 0 preset 0 $OFF
done
# shellcheck disable=SC2086
particles_run 150um-iso-paper-2ranks ranks "$WORK/coarse" 150 iso paper law 0 preset 0 $OFF nprocs 2
particles_run 150um-iso-paper-nodisp-1 nodisp-1 "$WORK/coarse" 150 iso paper dispersion 0
particles_run 150um-iso-paper-nodisp-2 nodisp-2 "$WORK/coarse" 150 iso paper dispersion 0 nprocs 2
particles_run 150um-smooth-paper-forces forces "$WORK/coarse" 150 smooth paper dispersion 0 trace 20
particles_run 150um-smooth-paper-kick kick "$WORK/coarse" 150 smooth paper dispersion 0 kick 40 \
  t_sample 0
run_all
"$REBOUND_BIN" pipe-stats --study "$WORK" --out "$WORK/stats"
echo "STUDY: $WORK"
