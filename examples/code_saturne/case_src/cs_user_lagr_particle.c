/* Particle ids at injection, and per-time-step particle state output.
 *
 * traj_rank<r>.csv (run directory): one row per particle still in the domain
 * at the end of each Lagrangian time step:
 *   step,time,particle_id,n_coll,cell_id,x,y,z,u,v,w,sx,sy,sz
 * (sx,sy,sz: the private tracking restart point start_coords, read through
 *  the 6.0.x replica struct; after a wall hit it is the restart point set by
 *  the rebound treatment, otherwise the particle position at step start)
 * values printed with %.17g (round-trip exact). Rows are in particle-buffer
 * order; compare after sorting by (step, particle_id) (compare_traj.py).   */

#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cs_headers.h"
#include "cswm_common.h"
#include "cswm_ids.h"

BEGIN_C_DECLS

/* Ids of newly injected particles: cswm_ids.h. */

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

/*----------------------------------------------------------------------------
 * End of each Lagrangian time step: dump particle states.
 *----------------------------------------------------------------------------*/

static FILE *_traj_f = NULL;

void
cs_user_lagr_extra_operations(const cs_real_t  dt[])
{
  CS_UNUSED(dt);

  const cs_lagr_particle_set_t *p_set = cs_glob_lagr_particle_set;

  if (!CSWM_TRAJECTORIES) {
    cswm_flush_hits();
    return;
  }

  if (_traj_f == NULL) {
    char name[64];
    snprintf(name, 63, "traj_rank%04d.csv",
             cs_glob_rank_id < 0 ? 0 : cs_glob_rank_id);
    _traj_f = fopen(name, "w");
    if (_traj_f == NULL)
      bft_error(__FILE__, __LINE__, 0, "cannot open %s", name);
    fprintf(_traj_f, "step,time,particle_id,n_coll,cell_id,x,y,z,u,v,w,"
            "sx,sy,sz\n");
  }

  const int nt = cs_glob_time_step->nt_cur;
  const double t = cs_glob_time_step->t_cur;

  for (cs_lnum_t p_id = 0; p_id < p_set->n_particles; p_id++) {
    const cs_real_t *x
      = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_COORDS);
    const cs_real_t *u
      = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_VELOCITY);
    cs_lnum_t c_id = cs_lagr_particles_get_lnum(p_set, p_id, CS_LAGR_CELL_ID);
    const _cs60_tracking_info_t *ti
      = (const _cs60_tracking_info_t *)(  p_set->p_buffer
                                        + p_set->p_am->extents*p_id);
    fprintf(_traj_f,
            "%d,%.17g,%llu,%llu,%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
            "%.17g,%.17g,%.17g\n",
            nt, t, cswm_get_pid(p_set, p_id), cswm_get_ncoll(p_set, p_id),
            (long)c_id, x[0], x[1], x[2], u[0], u[1], u[2],
            ti->start_coords[0], ti->start_coords[1], ti->start_coords[2]);
  }
  fflush(_traj_f);
  cswm_flush_hits();
}

END_C_DECLS
