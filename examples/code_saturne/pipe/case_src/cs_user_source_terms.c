/* The streamwise-periodic pipe is driven by a uniform axial pressure gradient G (a momentum
 * source, N/m3) that holds the bulk velocity at pipe.params' u_bulk: a proportional-integral
 * controller on the volume-averaged axial velocity, which in a periodic section is the bulk
 * velocity. It starts from Blasius' friction factor (Blasius 1913), G = f/D rho U^2/2 with
 * f = 0.3164 Re^-1/4; once the flow is steady G is the wall's friction, 4 tau_w / D.
 * Gains: a weak proportional part (50 steps) and an integral part of 10 steps bring the bulk
 * velocity within 1e-4 of its target in 600 steps of 1 ms on the study mesh (a proportional
 * part of 10 steps held an offset of 0.13 % for thousands of steps).
 * Called for the fluid run only: the particle runs freeze the carrier phase.            */
#include "cs_defs.h"

#include <math.h>
#include <stdio.h>

#include "cs_headers.h"
#include "pipe_forces.h"
#include "pipe_params.h"

BEGIN_C_DECLS

static double _g_int = -1.;   /* integral part of G; < 0 until initialised */

/* The wall cells' centres in wall units, y+ = y u_tau / nu, with the mean friction velocity
   u_tau = (G D / 4 rho)^1/2 of the driving gradient G (in a steady periodic pipe G D / 4 is
   the mean wall shear stress): the near-wall resolution the dispersion sees. */
static void
_first_cell_yplus(double g, double rho, double mu)
{
  const cs_mesh_t *m = cs_glob_mesh;
  const cs_mesh_quantities_t *mq = cs_glob_mesh_quantities;
  const double u_tau = sqrt(fabs(g) * pipe_params()->diameter_pipe / (4. * rho));
  double lo = 1e300, hi = 0., s[2] = {0., 0.};
  for (cs_lnum_t f = 0; f < m->n_b_faces; f++) {
    const cs_real_t *n = mq->b_face_normal + 3 * f;
    const cs_real_t *c = mq->cell_cen + 3 * m->b_face_cells[f];
    const cs_real_t *o = mq->b_face_cog + 3 * f;
    double y = fabs((c[0] - o[0]) * n[0] + (c[1] - o[1]) * n[1] + (c[2] - o[2]) * n[2])
               / mq->b_face_surf[f];
    double yp = y * u_tau * rho / mu;
    lo = fmin(lo, yp);
    hi = fmax(hi, yp);
    s[0] += yp;
    s[1] += 1.;
  }
  cs_parall_min(1, CS_DOUBLE, &lo);
  cs_parall_max(1, CS_DOUBLE, &hi);
  cs_parall_sum(2, CS_DOUBLE, s);
  bft_printf("pipe: first-cell y+ min %.3g mean %.3g max %.3g (u_tau %.4g m/s)\n", lo,
             s[0] / s[1], hi, u_tau);
}

void
cs_user_source_terms(cs_domain_t  *domain,
                     int           f_id,
                     cs_real_t    *st_exp,
                     cs_real_t    *st_imp)
{
  CS_UNUSED(domain); CS_UNUSED(st_imp);
  if (f_id != CS_F_(vel)->id)
    return;

  const pipe_params_t *pp = pipe_params();
  const cs_lnum_t n_cells = cs_glob_mesh->n_cells;
  const cs_real_t *vol = cs_glob_mesh_quantities->cell_vol;
  const cs_real_3_t *vel = (const cs_real_3_t *)CS_F_(vel)->val;
  const double rho = cs_glob_fluid_properties->ro0;
  const double mu = cs_glob_fluid_properties->viscl0;

  double s[2] = {0., 0.};
  for (cs_lnum_t i = 0; i < n_cells; i++) {
    s[0] += vel[i][0] * vol[i];
    s[1] += vol[i];
  }
  cs_parall_sum(2, CS_DOUBLE, s);
  const double u_b = s[0] / s[1];

  if (_g_int < 0.) {
    double re = rho * pp->u_bulk * pp->diameter_pipe / mu;
    _g_int = 0.3164 * pow(re, -0.25) / pp->diameter_pipe * 0.5 * rho * pp->u_bulk * pp->u_bulk;
  }
  const double err = pp->u_bulk - u_b;
  const double tau_p = 50. * pp->dt, tau_i = 10. * pp->dt;
  _g_int += rho * err * pp->dt / tau_i;
  const double g = _g_int + rho * err / tau_p;

  cs_real_3_t *_st_exp = (cs_real_3_t *)st_exp;
  for (cs_lnum_t i = 0; i < n_cells; i++)
    _st_exp[i][0] += vol[i] * g;

  if (cs_glob_time_step->nt_cur % 20 == 0 || cs_glob_time_step->nt_cur == cs_glob_time_step->nt_max)
    bft_printf("pipe: step %d bulk velocity %.6g m/s (target %.6g), pressure gradient %.6g Pa/m\n",
               cs_glob_time_step->nt_cur, u_b, pp->u_bulk, g);
  if (cs_glob_time_step->nt_cur == cs_glob_time_step->nt_max)
    _first_cell_yplus(g, rho, mu);
}

/* A uniform axial velocity at the start of the fluid run (k and epsilon from uref, almax). */
void
cs_user_initialization(cs_domain_t  *domain)
{
  CS_UNUSED(domain);
  pipe_forces_init();   /* a particle run: the frozen flow's vorticity (lift, spin) */
  if (cs_glob_time_step->nt_prev > 0)
    return;
  cs_real_3_t *vel = (cs_real_3_t *)CS_F_(vel)->val;
  for (cs_lnum_t i = 0; i < cs_glob_mesh->n_cells_with_ghosts; i++) {
    vel[i][0] = pipe_params()->u_bulk;
    vel[i][1] = 0.;
    vel[i][2] = 0.;
  }
}

END_C_DECLS
