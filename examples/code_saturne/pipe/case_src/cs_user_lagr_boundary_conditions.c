/* The pipe wall of the pipe-flow study: every particle-wall hit goes to roughwall
 * (CS_LAGR_BC_USER), with the lay direction of the face it hits:
 *   wall 0 smooth, wall 1 isotropic: the pipe axis (any direction off the normal would do);
 *   wall 2 (a drawn or rolled tube): the pipe axis x;
 *   wall 3 (lay around the circumference): axis x face normal, the tangent of the
 *          circumference at the hit.
 * as any host passes it: the library builds the wall frame from the normal and the lay.
 * The key of the hit's random stream is (particle id, collision index), the id the
 * particle carries between ranks and through restarts (../case_src/cswm_ids.h). The hit
 * takes the particle's spin from, and gives the rebound's spin back to, the spin table
 * (pipe_spin.h; spin 0 when pipe.params `spin` is 0).
 * In the sampling window every rebound (status RW_OK) is counted (pipe_tally.c) and, with
 * log_hits, every hit is written to hits_rank<r>.csv: impact point, impact angle (to the
 * mean wall, and to the wall element the library drew: rw_element_impact_angle), angle to
 * the lay, speeds before and after, status; and the hit's vectors in full (velocity and
 * spin before and after, the face normal) for the test that replays it in the library.
 * The rest of the step after a hit follows the
 * rebound velocity.
 * PINNED TO code_saturne 6.0.x (../case_src/cswm_wall_hit.h).                           */

#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_headers.h"
#include "cs_lagr_tracking.h"
#include "cswm_common.h"
#include "cswm_wall_hit.h"
#include "pipe_params.h"
#include "pipe_spin.h"
#include "pipe_tally.h"
#include "roughwall.h"
#include "cswm_wall.h"

BEGIN_C_DECLS

void
cs_user_lagr_boundary_conditions(const int  bc_type[])
{
  CS_UNUSED(bc_type);
  cs_lagr_zone_data_t *lagr_bcs = cs_lagr_get_boundary_conditions();
  int n_zones = cs_boundary_zone_n_zones();
  for (int z_id = 0; z_id < n_zones; z_id++)
    lagr_bcs->zone_type[z_id] = CS_LAGR_BC_USER;
}

static rw_wall *_wall = NULL;
static FILE *_hits_f = NULL;

static const rw_wall *
_the_wall(void)
{
  if (_wall == NULL) {
    const pipe_params_t *pp = pipe_params();
    rw_wall_params p;
    char what[32];
    rw_wall_params_default(&p);
    p.delta_xi_deg = pp->delta_xi_deg;
    p.delta_zeta_deg = pp->delta_zeta_deg;
    p.law = pp->law;
    p.preset = pp->preset;
    p.model = pp->model;
    p.seed = pp->seed;
    snprintf(what, sizeof what, "pipe wall %d", pp->wall);
    _wall = cswm_wall_new(&p, what);
  }
  return _wall;
}

/* The lay direction at a hit (global axes), from the face normal. */
static void
_lay(const cs_real_t n[3], double lay[3])
{
  if (pipe_params()->wall == 3) {
    /* x x n = (0, -n_z, n_y): the tangent of the circumference */
    lay[0] = 0.; lay[1] = -n[2]; lay[2] = n[1];
  }
  else {
    lay[0] = 1.; lay[1] = 0.; lay[2] = 0.;
  }
}

static double
_deg(double rad)
{
  return rad * 180. / 3.14159265358979323846;
}

static void
_log_hit(unsigned long long pid, unsigned long long cidx, const cs_real_t xi[3],
         const cs_real_t n[3], const double lay[3], const rw_hit *hit, const rw_result *res)
{
  const double *u_in = hit->velocity, *u_out = res->velocity;
  if (_hits_f == NULL)
    _hits_f = pipe_rank_csv("hits", "particle_id,collision_index,step,y,z,alpha_in_deg,lay_angle_deg,"
                     "speed_in,speed_out,alpha_out_deg,deflection_deg,status,candidate_walls,"
                     "alpha_element_deg,ux_in,uy_in,uz_in,wx_in,wy_in,wz_in,ux_out,uy_out,"
                     "uz_out,wx_out,wy_out,wz_out,nx,ny,nz,diameter");
  double s_in = cs_math_3_norm(u_in), s_out = cs_math_3_norm(u_out);
  double un_in = fabs(cs_math_3_dot_product(u_in, n));
  double un_out = fabs(cs_math_3_dot_product(u_out, n));
  /* the angle between the incident plane (normal, incident velocity) and the lay: between
     the tangential incident velocity and the lay's projection on the wall, folded to 0-90 */
  double ut[3], lt[3];
  double dn = cs_math_3_dot_product(u_in, n), ln = cs_math_3_dot_product(lay, n);
  for (int k = 0; k < 3; k++) {
    ut[k] = u_in[k] - dn * n[k];
    lt[k] = lay[k] - ln * n[k];
  }
  double c = fabs(cs_math_3_dot_product(ut, lt))
             / (cs_math_3_norm(ut) * cs_math_3_norm(lt) + 1e-300);
  /* the deflection out of the incident plane: the angle between the tangential velocities
     before and after the hit */
  double uo[3], don = cs_math_3_dot_product(u_out, n);
  for (int k = 0; k < 3; k++)
    uo[k] = u_out[k] - don * n[k];
  double cd = cs_math_3_dot_product(ut, uo)
              / (cs_math_3_norm(ut) * cs_math_3_norm(uo) + 1e-300);
  fprintf(_hits_f, "%llu,%llu,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%u,%.17g",
          pid, cidx, cs_glob_time_step->nt_cur, xi[1], xi[2],
          _deg(asin(fmin(1., un_in / s_in))), _deg(acos(fmin(1., c))), s_in, s_out,
          _deg(asin(fmin(1., un_out / s_out))), _deg(acos(fmax(-1., fmin(1., cd)))),
          res->status, res->candidate_walls, _deg(rw_element_impact_angle(hit, res)));
  const double *vec[5] = {hit->velocity, hit->spin, res->velocity, res->spin, n};
  for (int v = 0; v < 5; v++)
    fprintf(_hits_f, ",%.17g,%.17g,%.17g", vec[v][0], vec[v][1], vec[v][2]);
  fprintf(_hits_f, ",%.17g\n", hit->diameter);
}

void
cs_lagr_user_boundary_interaction(cs_lagr_particle_set_t    *particles,
                                  cs_lnum_t                  p_id,
                                  cs_lnum_t                  face_id,
                                  const cs_real_t            face_norm[3],
                                  const cs_real_t            c_intersect[3],
                                  cs_real_t                  t_intersect,
                                  int                        b_zone_id,
                                  int                       *event_flag,
                                  cs_lagr_tracking_state_t  *tracking_state)
{
  CS_UNUSED(face_id); CS_UNUSED(b_zone_id);

  cs_real_t *particle_velocity = cs_lagr_particles_attr(particles, p_id, CS_LAGR_VELOCITY);
  const cs_real_t diameter = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_DIAMETER);

  cswm_hit_begin(particles, p_id, face_norm, c_intersect, t_intersect);

  unsigned long long pid = cswm_get_pid(particles, p_id);
  unsigned long long cidx = cswm_get_ncoll(particles, p_id);
  double lay[3];
  _lay(face_norm, lay);

  double spin[3];
  pipe_spin_get(pid, spin);                    /* code_saturne 6.0 tracks no particle spin */
  rw_hit hit = {
    .velocity = {particle_velocity[0], particle_velocity[1], particle_velocity[2]},
    .spin = {spin[0], spin[1], spin[2]},
    .normal = {face_norm[0], face_norm[1], face_norm[2]},
    .lay = {lay[0], lay[1], lay[2]},
    .wall_velocity = {0., 0., 0.},
    .diameter = diameter,
    .particle_id = pid,
    .collision_index = cidx,
  };
  rw_result res;
  int status = rw_rebound(_the_wall(), &hit, &res);
  if (status != RW_OK && status != RW_NOT_APPROACHING)
    bft_error(__FILE__, __LINE__, 0, "roughwall: %s (particle %llu, collision %llu)",
              rw_status_string(status), pid, cidx);

  for (int k = 0; k < 3; k++)
    particle_velocity[k] = res.velocity[k];
  if (status == RW_OK)
    pipe_spin_after_hit(pid, cidx, res.spin);
  cswm_set_key(particles, p_id, pid, cidx + 1);

  /* The rest of the step goes along the rebound velocity, not the specular reflection that
     cswm_hit_begin made (built in, and right for a smooth wall only): the particle covers
     the remaining path length |x - I| in the time tau = |x - I| / |u_in| at u_out. */
  if (status == RW_OK) {
    cs_real_t *particle_coord = cs_lagr_particles_attr(particles, p_id, CS_LAGR_COORDS);
    cs_real_t rem[3];
    for (int k = 0; k < 3; k++)
      rem[k] = particle_coord[k] - c_intersect[k];
    double speed_in = cs_math_3_norm(hit.velocity);
    double tau = speed_in > 0. ? cs_math_3_norm(rem) / speed_in : 0.;
    for (int k = 0; k < 3; k++)
      particle_coord[k] = c_intersect[k] + tau * res.velocity[k];
  }

  cswm_hit_end(particles, p_id, face_norm, event_flag, tracking_state);

  if (pipe_in_window()) {
    if (status == RW_OK)
      pipe_tally_hit(pid);
    if (pipe_params()->log_hits)
      _log_hit(pid, cidx, c_intersect, face_norm, lay, &hit, &res);
  }
}

/* Flush the hit log (end of each step; cs_user_lagr_particle.c) */
void pipe_flush_hits(void);

void
pipe_flush_hits(void)
{
  if (_hits_f != NULL)
    fflush(_hits_f);
}

END_C_DECLS
