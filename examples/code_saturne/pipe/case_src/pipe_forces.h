#ifndef PIPE_FORCES_H
#define PIPE_FORCES_H
/* What the carrier flow does to a particle of the pipe-flow study between wall hits, beyond
 * code_saturne's drag, gravity and pressure gradient (docs/pipe-flow.md, "Physics"):
 *   - the Saffman-Mei shear lift and the Magnus lift (pipe.params `saffman`, `magnus`),
 *     roughwall's rw_saffman_mei_lift and rw_magnus_lift, as an external acceleration
 *     through code_saturne's cs_user_lagr_ef (held over the step like gravity);
 *   - the particle's spin (pipe.params `spin`): pipe_spin.h.
 * The frozen carrier flow's vorticity (curl of the velocity, per cell) is computed once, at
 * the start of a particle run (pipe_forces_init, collective).
 * With pipe.params `trace` N > 0 every step writes the state of particles 0 ... N-1 where
 * they are (trace_rank<r>.csv), for the test that integrates their equation of motion
 * independently (tests/real_systems/pipe_flow.rs).
 * The time spent in these forces is timed (pipe_forces_cost_write: forces_cost.csv).
 * PINNED TO code_saturne 6.0.x.                                                          */

#include "cs_defs.h"
#include "cs_headers.h"
#include "roughwall.h"

/* Computes the vorticity of the frozen flow (every rank; a no-op unless phase 2 with a
   force or the spin on). */
void pipe_forces_init(void);

/* The carrier fluid and particle p_id of the local set where it is (slip: velocity seen
   minus particle velocity; vorticity of its cell; spin from pipe_spin). */
void pipe_fluid_point(const cs_lagr_particle_set_t *p_set, cs_lnum_t p_id,
                      rw_fluid_point *point);

/* Adds `seconds` of work to one of the timed parts (0 lift, 1 spin relaxation, 2 spin
   exchange between ranks) and counts particle steps (part 3). */
void pipe_forces_time(int part, double seconds);

/* Monotonic wall time (s). */
double pipe_now(void);

/* End of each step: counts its particle steps, times the step, flushes the trace. */
void pipe_forces_step_end(const cs_lagr_particle_set_t *p_set);

/* Writes forces_cost.csv (particle steps; seconds of lift, spin relaxation, spin exchange
   and whole steps from the second on, all summed over ranks) on rank 0 (sums over ranks; call on every rank, last step). */
void pipe_forces_cost_write(void);

#endif
