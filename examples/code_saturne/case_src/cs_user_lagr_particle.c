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

BEGIN_C_DECLS

/* Next global particle id (same value on all ranks). On the first call it
   is initialised to 1 + the max id of particles already present (e.g. read
   from a Lagrangian restart, where the user variable is restored with the
   particles; restart itself is untested here). */

static unsigned long long _next_gid = 0;
static int _gid_init = 0;

/*----------------------------------------------------------------------------
 * Assign globally unique, rank-independent-in-meaning particle ids to newly
 * injected particles: ids are consecutive in (injection call, rank, local
 * injection order). cs_user_lagr_in is called collectively (on every rank,
 * for every zone/set injected at this step, possibly with an empty range),
 * so the MPI_Exscan/Allreduce below are safe.
 *----------------------------------------------------------------------------*/

void
cs_user_lagr_in(cs_lagr_particle_set_t         *particles,
                const cs_lagr_injection_set_t  *zis,
                const cs_lnum_t                 particle_range[2],
                const cs_lnum_t                 particle_face_id[],
                const cs_real_t                 visc_length[])
{
  CS_UNUSED(zis); CS_UNUSED(particle_face_id); CS_UNUSED(visc_length);

  if (!_gid_init) {
    unsigned long long next = 0;
    for (cs_lnum_t p_id = 0; p_id < particle_range[0]; p_id++) {
      unsigned long long pid = cswm_get_pid(particles, p_id);
      if (pid + 1 > next)
        next = pid + 1;
    }
#if defined(HAVE_MPI)
    if (cs_glob_n_ranks > 1)
      MPI_Allreduce(MPI_IN_PLACE, &next, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX,
                    cs_glob_mpi_comm);
#endif
    _next_gid = next;
    _gid_init = 1;
  }

  unsigned long long n_loc = particle_range[1] - particle_range[0];
  unsigned long long shift = 0, n_tot = n_loc;

#if defined(HAVE_MPI)
  if (cs_glob_n_ranks > 1) {
    MPI_Exscan(&n_loc, &shift, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM,
               cs_glob_mpi_comm);
    if (cs_glob_rank_id == 0)
      shift = 0;   /* MPI_Exscan leaves rank 0's result undefined */
    MPI_Allreduce(&n_loc, &n_tot, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM,
                  cs_glob_mpi_comm);
  }
#endif

  for (cs_lnum_t p_id = particle_range[0]; p_id < particle_range[1]; p_id++)
    cswm_set_key(particles, p_id,
                 _next_gid + shift + (unsigned long long)(p_id - particle_range[0]),
                 0);

  _next_gid += n_tot;
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
