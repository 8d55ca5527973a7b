/* Particle ids at injection (../case_src/cswm_ids.h) and, at the end of each step, the
 * spins' exchange and relaxation (pipe_spin.h), the per-step tallies of the pipe-flow
 * study (pipe_tally.c), the test scene `kick`; particles.csv and forces_cost.csv at the
 * last step.                                                                            */
#include "cs_defs.h"

#include <math.h>

#include "cs_headers.h"
#include "cswm_common.h"
#include "cswm_ids.h"
#include "pipe_forces.h"
#include "pipe_params.h"
#include "pipe_spin.h"
#include "pipe_tally.h"

BEGIN_C_DECLS

void pipe_flush_hits(void);

/* The test scene `kick`: every particle thrown towards the wall, `speed` added to its
   velocity along the outward radius (steep hits, where friction lets a sphere roll). */
static void
_kick(cs_lagr_particle_set_t *p_set, double speed)
{
  for (cs_lnum_t p_id = 0; p_id < p_set->n_particles; p_id++) {
    const cs_real_t *x = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_COORDS);
    cs_real_t *v = cs_lagr_particles_attr(p_set, p_id, CS_LAGR_VELOCITY);
    double r = sqrt(x[1] * x[1] + x[2] * x[2]);
    if (r > 0.) {
      v[1] += speed * x[1] / r;
      v[2] += speed * x[2] / r;
    }
  }
}

void
cs_user_lagr_in(cs_lagr_particle_set_t         *particles,
                const cs_lagr_injection_set_t  *zis,
                const cs_lnum_t                 particle_range[2],
                const cs_lnum_t                 particle_face_id[],
                const cs_real_t                 visc_length[])
{
  CS_UNUSED(zis); CS_UNUSED(particle_face_id); CS_UNUSED(visc_length);
  cswm_assign_ids(particles, particle_range);
}

void
cs_user_lagr_extra_operations(const cs_real_t  dt[])
{
  const pipe_params_t *pp = pipe_params();
  const cs_time_step_t *ts = cs_glob_time_step;
  if (pp->phase == 2)
    pipe_spin_step(cs_glob_lagr_particle_set, dt[0]);
  if (pp->phase == 2 && pp->kick != 0. && ts->nt_cur == ts->nt_prev + 1)
    _kick(cs_glob_lagr_particle_set, pp->kick);
  if (pipe_in_window())
    pipe_tally_sample(cs_glob_lagr_particle_set);
  pipe_flush_hits();
  pipe_forces_step_end(cs_glob_lagr_particle_set);
  if (pp->phase == 2 && ts->nt_cur == ts->nt_max) {
    pipe_tally_write();
    pipe_forces_cost_write();
  }
}

END_C_DECLS
