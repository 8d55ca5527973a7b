#ifndef CSWM_IDS_H
#define CSWM_IDS_H
/* Stable particle ids for the wall model's keys, shared by every case whose wall hook calls
 * roughwall (case_src/ and pipe/case_src/): cswm_assign_ids() is what cs_user_lagr_in()
 * calls for each range of newly injected particles. The id is stored in the particle's one
 * user variable (cswm_common.h), so it migrates with the particle between MPI ranks and is
 * written to, and read back from, Lagrangian restart files.
 * PINNED TO code_saturne 6.0.x.                                                           */

#include "cswm_common.h"

/* Next global particle id (same value on all ranks). On the first call it
   is initialised to 1 + the max id of particles already present (e.g. read
   from a Lagrangian restart, where the user variable is restored with the
   particles: the pipe study, pipe/, restarts from its injection run). */

static unsigned long long _cswm_next_gid = 0;
static int _cswm_gid_init = 0;

/*----------------------------------------------------------------------------
 * Assign globally unique, rank-independent-in-meaning particle ids to newly
 * injected particles: ids are consecutive in (injection call, rank, local
 * injection order). cs_user_lagr_in is called collectively (on every rank,
 * for every zone/set injected at this step, possibly with an empty range),
 * so the MPI_Exscan/Allreduce below are safe.
 *----------------------------------------------------------------------------*/

static inline void
cswm_assign_ids(cs_lagr_particle_set_t  *particles,
                const cs_lnum_t          particle_range[2])
{
  if (!_cswm_gid_init) {
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
    _cswm_next_gid = next;
    _cswm_gid_init = 1;
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
                 _cswm_next_gid + shift + (unsigned long long)(p_id - particle_range[0]),
                 0);

  _cswm_next_gid += n_tot;
}

#endif /* CSWM_IDS_H */
