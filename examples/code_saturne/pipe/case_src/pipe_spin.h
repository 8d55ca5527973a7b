#ifndef PIPE_SPIN_H
#define PIPE_SPIN_H
/* The particles' spin in the pipe-flow study (pipe.params `spin` 1). code_saturne 6.0 has no
 * particle angular velocity, and 6.0.2 cannot give a particle a second user variable (the
 * injection writes past the attribute table: ../../case_src/cswm_common.h), so the spin is
 * not a particle attribute: it is a table of n_particles spins indexed by the particle's
 * stable id (the one user variable), held identical on every rank.
 *   - A wall hit hands the table's spin to roughwall and writes back what it returns.
 *   - At the end of each step (pipe_spin_step, collective): the spins of the hits made on
 *     any rank reach every rank (the hit with the highest collision index wins); then the
 *     rank that owns each particle relaxes its spin over the step in the fluid of its cell
 *     (roughwall's rw_spin_relax: rotational drag, Dennis et al. 1980), and the relaxed
 *     spins reach every rank. Each spin thus depends on its particle's history only, not
 *     on the ranks: 1 and 2 ranks give the same hits (tests/real_systems/pipe_flow.rs).
 * A run starts with every particle at rest (spin 0). With `spin` 0 every hit gets spin 0
 * and its result is discarded (code_saturne's own behaviour).                          */

#include "cs_defs.h"
#include "cs_headers.h"

/* The spin of particle `pid` (0 when `spin` is off). */
void pipe_spin_get(unsigned long long pid, double spin[3]);

/* The spin particle `pid` leaves its hit number `cidx` with (no-op when `spin` is off). */
void pipe_spin_after_hit(unsigned long long pid, unsigned long long cidx,
                         const double spin[3]);

/* End of step: exchange the hits' spins, relax every local particle's over dt, exchange. */
void pipe_spin_step(const cs_lagr_particle_set_t *p_set, double dt);

#endif
