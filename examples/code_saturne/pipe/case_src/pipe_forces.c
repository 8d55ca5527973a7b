/* The carrier flow's forces between hits, the trace and the forces' costs (pipe_forces.h). */
#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cs_headers.h"
#include "cswm_common.h"
#include "pipe_forces.h"
#include "pipe_params.h"
#include "pipe_spin.h"
#include "roughwall.h"

BEGIN_C_DECLS

static cs_real_33_t *_grad = NULL;       /* du_i/dx_j per cell (with ghosts), 1/s */
static cs_real_3_t *_vorticity = NULL;   /* per cell (with ghosts), 1/s */
static double _cost[5] = {0., 0., 0., 0., 0.};
static FILE *_trace_f = NULL;

double
pipe_now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void
pipe_forces_time(int part, double seconds)
{
  _cost[part] += seconds;
}

static int
_needed(void)
{
  const pipe_params_t *pp = pipe_params();
  return pp->phase == 2
         && (pp->saffman || pp->magnus || pp->spin || pp->trace > 0 || pp->complete_langevin);
}

void
pipe_forces_init(void)
{
  if (!_needed() || _vorticity != NULL)
    return;
  const cs_lnum_t n = cs_glob_mesh->n_cells_with_ghosts;
  cs_real_33_t *grad;
  BFT_MALLOC(_grad, n, cs_real_33_t);
  BFT_MALLOC(_vorticity, n, cs_real_3_t);
  grad = _grad;
  /* grad[c][i][j] = du_i/dx_j (cs_gradient.c); the frozen field: current = previous */
  cs_field_gradient_vector(CS_F_(vel), false, 1, grad);
  for (cs_lnum_t c = 0; c < n; c++) {
    _vorticity[c][0] = grad[c][2][1] - grad[c][1][2];
    _vorticity[c][1] = grad[c][0][2] - grad[c][2][0];
    _vorticity[c][2] = grad[c][1][0] - grad[c][0][1];
  }
  bft_printf("pipe: vorticity of the frozen flow in %d cells\n", (int)cs_glob_mesh->n_cells);
  /* From here on, the only velocity gradient the frozen run computes is condli's, every step,
     for the velocity at I' of the wall functions' boundary coefficients: nothing the
     particles see (the fluid is not solved, and the complete model reads _grad). One sweep
     instead of the iterations to convergence (5 here) saves 4.3 ms a step on 6400 cells,
     40 % of a quick run (4.6 -> 2.7 s); every hit and particle of the 46 quick runs stayed
     bit for bit the same (2026-11-29). */
  int key_cal_opt_id = cs_field_key_id("var_cal_opt");
  cs_var_cal_opt_t vcopt;
  cs_field_get_key_struct(CS_F_(vel), key_cal_opt_id, &vcopt);
  vcopt.nswrgr = 1;
  cs_field_set_key_struct(CS_F_(vel), key_cal_opt_id, &vcopt);
}

void
pipe_fluid_point(const cs_lagr_particle_set_t *p_set, cs_lnum_t p_id, rw_fluid_point *point)
{
  if (_vorticity == NULL)
    bft_error(__FILE__, __LINE__, 0, "pipe: the flow's vorticity was not computed "
              "(pipe_forces_init: cs_user_initialization not called?)");
  cs_lnum_t cell = cs_lagr_particles_get_lnum(p_set, p_id, CS_LAGR_CELL_ID);
  const cs_real_t *v = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_VELOCITY);
  const cs_real_t *us = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_VELOCITY_SEEN);
  double d = cs_lagr_particles_get_real(p_set, p_id, CS_LAGR_DIAMETER);
  double m = cs_lagr_particles_get_real(p_set, p_id, CS_LAGR_MASS);
  point->rho_f = cs_glob_fluid_properties->ro0;
  point->mu_f = cs_glob_fluid_properties->viscl0;
  point->d_p = d;
  point->rho_p = 6. * m / (3.14159265358979323846 * d * d * d);
  for (int k = 0; k < 3; k++) {
    point->slip[k] = us[k] - v[k];
    point->vorticity[k] = _vorticity[cell][k];
  }
  pipe_spin_get(cswm_get_pid(p_set, p_id), point->spin);
}

static void
_trace(const cs_lagr_particle_set_t *p_set, cs_lnum_t p_id, double taup,
       const cs_real_t gradpr[3], const rw_fluid_point *pt, const double a_s[3],
       const double a_m[3])
{
  if (_trace_f == NULL)
    _trace_f = pipe_rank_csv("trace", "step,particle_id,collision_index,x,y,z,vx,vy,vz,usx,usy,usz,taup,"
                      "gpx,gpy,gpz,wfx,wfy,wfz,wpx,wpy,wpz,asx,asy,asz,amx,amy,amz,"
                      "rho_f,mu_f,rho_p,d_p");
  const cs_real_t *x = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_COORDS);
  const cs_real_t *v = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_VELOCITY);
  const cs_real_t *us = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_VELOCITY_SEEN);
  fprintf(_trace_f, "%d,%llu,%llu", cs_glob_time_step->nt_cur, cswm_get_pid(p_set, p_id),
          cswm_get_ncoll(p_set, p_id));
  const double *cols[] = {x, v, us, NULL, gradpr, pt->vorticity, pt->spin, a_s, a_m};
  for (int c = 0; c < 9; c++) {
    if (cols[c] == NULL)
      fprintf(_trace_f, ",%.17g", taup);
    else
      fprintf(_trace_f, ",%.17g,%.17g,%.17g", cols[c][0], cols[c][1], cols[c][2]);
  }
  fprintf(_trace_f, ",%.17g,%.17g,%.17g,%.17g\n", pt->rho_f, pt->mu_f, pt->rho_p, pt->d_p);
}

/* The lifts as an external acceleration (m/s2), held over the step: code_saturne adds it
   to gravity and the pressure gradient (cs_lagr_sde.c, 6.0.2). fextla comes zeroed. */
void
cs_user_lagr_ef(cs_real_t            dt_p,
                const cs_real_t      taup[],
                const cs_real_3_t    tlag[],
                const cs_real_3_t    piil[],
                const cs_real_33_t   bx[],
                const cs_real_t      tsfext[],
                const cs_real_33_t   vagaus[],
                const cs_real_3_t    gradpr[],
                const cs_real_33_t   gradvf[],
                cs_real_t            rho_p[],
                cs_real_3_t          fextla[])
{
  CS_UNUSED(dt_p); CS_UNUSED(tlag); CS_UNUSED(piil); CS_UNUSED(bx); CS_UNUSED(tsfext);
  CS_UNUSED(vagaus); CS_UNUSED(gradvf); CS_UNUSED(rho_p);
  const pipe_params_t *pp = pipe_params();
  if (pp->phase != 2)
    return;
  if (pp->complete_langevin) {
    /* A frozen run computes the velocity gradient of the complete model once, at its
       start, and only if it starts at or after modcpl; but a run that does not read
       statistics must start them after its start (cs_lagr.c, cs_lagr_lec.c, 6.0.2). So the
       gradient the model will read from the step after the first on is given here. */
    static int given = 0;
    cs_lagr_extra_module_t *extra = cs_glob_lagr_extra_module;
    if (!given) {
      if (extra->grad_vel == NULL || _grad == NULL)
        bft_error(__FILE__, __LINE__, 0, "pipe: the complete model's velocity gradient "
                  "is not allocated (modcpl = 0?)");
      memcpy(extra->grad_vel, _grad,
             (size_t)cs_glob_mesh->n_cells_with_ghosts * sizeof(cs_real_33_t));
      given = 1;
    }
  }
  if (!(pp->saffman || pp->magnus || pp->trace > 0))
    return;
  const cs_lagr_particle_set_t *p_set = cs_lagr_get_particle_set();
  double t0 = pipe_now(), t_trace = 0.;
  for (cs_lnum_t ip = 0; ip < p_set->n_particles; ip++) {
    cs_lnum_t cell = cs_lagr_particles_get_lnum(p_set, ip, CS_LAGR_CELL_ID);
    if (cell < 0)
      continue;
    rw_fluid_point pt;
    pipe_fluid_point(p_set, ip, &pt);
    double a_s[3] = {0., 0., 0.}, a_m[3] = {0., 0., 0.};
    int s = RW_OK;
    if (pp->saffman)
      s = rw_saffman_mei_lift(&pt, a_s);
    if (s == RW_OK && pp->magnus)
      s = rw_magnus_lift(&pt, a_m);
    if (s != RW_OK)
      bft_error(__FILE__, __LINE__, 0, "roughwall: lift: %s (particle %llu)",
                rw_status_string(s), cswm_get_pid(p_set, ip));
    for (int k = 0; k < 3; k++)
      fextla[ip][k] = a_s[k] + a_m[k];
    if (cswm_get_pid(p_set, ip) < (unsigned long long)pp->trace) {
      double t = pipe_now();
      _trace(p_set, ip, taup[ip], gradpr[cell], &pt, a_s, a_m);
      t_trace += pipe_now() - t;   /* a test's output, not the forces' cost */
    }
  }
  _cost[0] += pipe_now() - t0 - t_trace;
}

void
pipe_forces_step_end(const cs_lagr_particle_set_t *p_set)
{
  static double last = -1.;
  double now = pipe_now();
  if (last >= 0.)
    _cost[4] += now - last;
  last = now;
  _cost[3] += (double)p_set->n_particles;
  if (_trace_f != NULL)
    fflush(_trace_f);
}

void
pipe_forces_cost_write(void)
{
#if defined(HAVE_MPI)
  if (cs_glob_n_ranks > 1)
    MPI_Allreduce(MPI_IN_PLACE, _cost, 5, MPI_DOUBLE, MPI_SUM, cs_glob_mpi_comm);
#endif
  if (cs_glob_rank_id > 0)
    return;
  FILE *f = fopen("forces_cost.csv", "w");
  if (f == NULL)
    bft_error(__FILE__, __LINE__, 0, "pipe: cannot write forces_cost.csv");
  fprintf(f, "particle_steps,lift_s,spin_relax_s,spin_exchange_s,step_s\n");
  fprintf(f, "%.17g,%.9g,%.9g,%.9g,%.9g\n", _cost[3], _cost[0], _cost[1], _cost[2], _cost[4]);
  fclose(f);
}

END_C_DECLS
