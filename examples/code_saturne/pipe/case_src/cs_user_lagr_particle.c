/* Particle ids at injection (../case_src/cswm_ids.h) and the per-step tallies of the
 * pipe-flow study (pipe_tally.c); particles.csv at the last step.                      */
#include "cs_defs.h"

#include "cs_headers.h"
#include "cswm_common.h"
#include "cswm_ids.h"
#include "pipe_params.h"
#include "pipe_tally.h"

BEGIN_C_DECLS

void pipe_flush_hits(void);

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
  CS_UNUSED(dt);
  if (pipe_in_window())
    pipe_tally_sample(cs_glob_lagr_particle_set);
  pipe_flush_hits();
  const cs_time_step_t *ts = cs_glob_time_step;
  if (pipe_params()->phase == 2 && ts->nt_cur == ts->nt_max)
    pipe_tally_write();
}

END_C_DECLS
