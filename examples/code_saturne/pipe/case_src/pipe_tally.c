/* The per-particle tallies of the pipe-flow study (pipe_tally.h). */
#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_headers.h"
#include "cswm_common.h"
#include "pipe_params.h"
#include "pipe_tally.h"

BEGIN_C_DECLS

static double *_rows = NULL;  /* n_particles rows of _width doubles */
static int _width = 0;

static double *
_row(unsigned long long pid)
{
  const pipe_params_t *pp = pipe_params();
  if (_rows == NULL) {
    _width = 4 + 8 * pp->n_bins;
    _rows = calloc((size_t)pp->n_particles * (size_t)_width, sizeof(double));
    if (_rows == NULL)
      bft_error(__FILE__, __LINE__, 0, "pipe: cannot allocate the tallies of %d particles",
                pp->n_particles);
  }
  if (pid >= (unsigned long long)pp->n_particles)
    bft_error(__FILE__, __LINE__, 0, "pipe: particle id %llu beyond n_particles %d", pid,
              pp->n_particles);
  return _rows + (size_t)pid * (size_t)_width;
}

int
pipe_in_window(void)
{
  const pipe_params_t *pp = pipe_params();
  const cs_time_step_t *ts = cs_glob_time_step;
  double t_run = (ts->nt_cur - ts->nt_prev) * pp->dt;
  return pp->phase == 2 && t_run > pp->t_sample + 0.5 * pp->dt;
}

static int
_bin(double c, double r, int nb)
{
  int b = (int)floor((c + r) / (2. * r) * nb);
  return b < 0 ? 0 : (b >= nb ? nb - 1 : b);
}

void
pipe_tally_sample(const cs_lagr_particle_set_t *p_set)
{
  const pipe_params_t *pp = pipe_params();
  const int nb = pp->n_bins;
  const double r = 0.5 * pp->diameter_pipe;
  for (cs_lnum_t p_id = 0; p_id < p_set->n_particles; p_id++) {
    if (cs_lagr_particles_get_lnum(p_set, p_id, CS_LAGR_CELL_ID) < 0)
      continue;
    const cs_real_t *x = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_COORDS);
    const cs_real_t *u = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_VELOCITY);
    double *row = _row(cswm_get_pid(p_set, p_id));
    double rad = sqrt(x[1] * x[1] + x[2] * x[2]);
    double ur = rad > 0. ? (u[1] * x[1] + u[2] * x[2]) / rad : 0.;
    int by = _bin(x[1], r, nb), bz = _bin(x[2], r, nb);
    row[0] += 1.;
    row[1] += u[0] * pp->dt;
    row[3] += x[1];
    row[4 + by] += 1.;
    row[4 + nb + bz] += 1.;
    row[4 + 2 * nb + by] += u[0];
    row[4 + 3 * nb + by] += u[0] * u[0];
    row[4 + 4 * nb + by] += ur;
    row[4 + 5 * nb + by] += ur * ur;
    /* the strips along the two diameters, a fifth of R either side */
    if (fabs(x[2]) < 0.2 * r)
      row[4 + 6 * nb + by] += 1.;
    if (fabs(x[1]) < 0.2 * r)
      row[4 + 7 * nb + bz] += 1.;
  }
}

void
pipe_tally_hit(unsigned long long pid)
{
  _row(pid)[2] += 1.;
}

void
pipe_tally_write(void)
{
  const pipe_params_t *pp = pipe_params();
  _row(0);  /* allocate on ranks that saw no particle */
  size_t n = (size_t)pp->n_particles * (size_t)_width;
#if defined(HAVE_MPI)
  if (cs_glob_n_ranks > 1)
    MPI_Allreduce(MPI_IN_PLACE, _rows, (int)n, MPI_DOUBLE, MPI_SUM, cs_glob_mpi_comm);
#endif
  if (cs_glob_rank_id <= 0) {
    FILE *f = fopen("particles.csv", "w");
    if (f == NULL)
      bft_error(__FILE__, __LINE__, 0, "pipe: cannot write particles.csv");
    const char *names[8] = {"cy", "cz", "ux", "ux2", "ur", "ur2", "sy", "sz"};
    fprintf(f, "particle_id,n,dist,hits,sum_y");
    for (int g = 0; g < 8; g++)
      for (int b = 0; b < pp->n_bins; b++)
        fprintf(f, ",%s_%d", names[g], b);
    fprintf(f, "\n");
    for (int p = 0; p < pp->n_particles; p++) {
      const double *row = _rows + (size_t)p * (size_t)_width;
      fprintf(f, "%d", p);
      for (int k = 0; k < _width; k++)
        fprintf(f, ",%.17g", row[k]);
      fprintf(f, "\n");
    }
    fclose(f);
  }
  (void)n;
}

END_C_DECLS
