/* The particles' spin table (pipe_spin.h). */
#include "cs_defs.h"

#include <stdlib.h>
#include <string.h>

#include "cs_headers.h"
#include "cswm_common.h"
#include "pipe_forces.h"
#include "pipe_params.h"
#include "pipe_spin.h"
#include "roughwall.h"

BEGIN_C_DECLS

static double *_spin = NULL;          /* 3 n: the spins, the same on every rank */
static long long *_stamp = NULL;      /* n: 2 + collision index of this step's last hit here */
static double *_buf = NULL;           /* 3 n: exchange buffer */
static long long *_mine = NULL;       /* n: this rank's stamps, during the exchange */

static void
_alloc(void)
{
  if (_spin != NULL)
    return;
  size_t n = (size_t)pipe_params()->n_particles;
  _spin = calloc(3 * n + 1, sizeof(double));
  _buf = calloc(3 * n + 1, sizeof(double));
  _stamp = calloc(n + 1, sizeof(long long));
  _mine = calloc(n + 1, sizeof(long long));
  if (_spin == NULL || _buf == NULL || _stamp == NULL || _mine == NULL)
    bft_error(__FILE__, __LINE__, 0, "pipe: cannot allocate the spins of %zu particles", n);
}

static size_t
_index(unsigned long long pid)
{
  if (pid >= (unsigned long long)pipe_params()->n_particles)
    bft_error(__FILE__, __LINE__, 0, "pipe: particle id %llu beyond n_particles %d", pid,
              pipe_params()->n_particles);
  return (size_t)pid;
}

void
pipe_spin_get(unsigned long long pid, double spin[3])
{
  if (!pipe_params()->spin) {
    spin[0] = spin[1] = spin[2] = 0.;
    return;
  }
  _alloc();
  memcpy(spin, _spin + 3 * _index(pid), 3 * sizeof(double));
}

void
pipe_spin_after_hit(unsigned long long pid, unsigned long long cidx, const double spin[3])
{
  if (!pipe_params()->spin)
    return;
  _alloc();
  size_t i = _index(pid);
  memcpy(_spin + 3 * i, spin, 3 * sizeof(double));
  _stamp[i] = 2 + (long long)cidx;
}

void
pipe_spin_step(const cs_lagr_particle_set_t *p_set, double dt)
{
  const pipe_params_t *pp = pipe_params();
  if (!pp->spin)
    return;
  _alloc();
  const size_t n = (size_t)pp->n_particles;
  double t0 = pipe_now();

  /* 1. The hits of this step: each particle's spin from the rank of its last hit (the
        highest collision index; one rank has it), unchanged where no rank saw a hit. */
#if defined(HAVE_MPI)
  if (cs_glob_n_ranks > 1) {
    long long *mine = _mine;
    memcpy(mine, _stamp, n * sizeof(long long));
    MPI_Allreduce(MPI_IN_PLACE, _stamp, (int)n, MPI_LONG_LONG, MPI_MAX, cs_glob_mpi_comm);
    for (size_t i = 0; i < n; i++)
      for (int k = 0; k < 3; k++)
        _buf[3 * i + k] = (_stamp[i] > 0 && mine[i] == _stamp[i]) ? _spin[3 * i + k] : 0.;
    MPI_Allreduce(MPI_IN_PLACE, _buf, (int)(3 * n), MPI_DOUBLE, MPI_SUM, cs_glob_mpi_comm);
    for (size_t i = 0; i < n; i++)
      if (_stamp[i] > 0)
        memcpy(_spin + 3 * i, _buf + 3 * i, 3 * sizeof(double));
  }
#endif
  memset(_stamp, 0, n * sizeof(long long));
  double t1 = pipe_now();

  /* 2. Relaxation in the fluid, by the rank that owns the particle. */
  int multi = cs_glob_n_ranks > 1;
  if (multi)
    memset(_buf, 0, 3 * n * sizeof(double));
  for (cs_lnum_t p_id = 0; p_id < p_set->n_particles; p_id++) {
    if (cs_lagr_particles_get_lnum(p_set, p_id, CS_LAGR_CELL_ID) < 0)
      continue;
    size_t i = _index(cswm_get_pid(p_set, p_id));
    rw_fluid_point point;
    pipe_fluid_point(p_set, p_id, &point);
    double *out = multi ? _buf + 3 * i : _spin + 3 * i;
    int s = rw_spin_relax(&point, dt, out);
    if (s != RW_OK)
      bft_error(__FILE__, __LINE__, 0, "roughwall: rw_spin_relax: %s (particle %zu)",
                rw_status_string(s), i);
  }
  double t2 = pipe_now();

  /* 3. The relaxed spins reach every rank (one owner per particle: a sum of one value). */
#if defined(HAVE_MPI)
  if (multi) {
    MPI_Allreduce(MPI_IN_PLACE, _buf, (int)(3 * n), MPI_DOUBLE, MPI_SUM, cs_glob_mpi_comm);
    memcpy(_spin, _buf, 3 * n * sizeof(double));
  }
#endif
  pipe_forces_time(1, t2 - t1);
  pipe_forces_time(2, (t1 - t0) + (pipe_now() - t2));
}

END_C_DECLS
