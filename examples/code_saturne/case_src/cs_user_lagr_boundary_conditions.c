/* Particle boundary conditions, injection, and the CS_LAGR_BC_USER wall hook that hands
 * every particle-wall hit to the roughwall C library (rw_rebound, include/roughwall.h).
 *
 * PINNED TO code_saturne 6.0.x: the hook writes into the private per-particle tracking
 * record of cs_lagr_tracking.c (see _cs60_tracking_info_t in cswm_common.h).
 *
 * CSWM_USER_MODE == 0: the walls are CS_LAGR_REBOUND (built in); the hook is never called.
 * CSWM_USER_MODE == 1: the walls are CS_LAGR_BC_USER; every hit goes through
 *                      cs_lagr_user_boundary_interaction() below, which calls rw_rebound()
 *                      and logs the hit to wall_hits_rank<r>.csv in the run directory.
 *
 * Scenes (cswm_common.h, set by setup_case.sh):
 *   CSWM_SCENE 1: two sets of 50 particles aimed at the walls at an angle (check (a));
 *   CSWM_SCENE 2: CSWM_N_INJECT particles at 5 m/s towards the floor y = 0 at 15 degrees
 *                 below the horizontal, in the x-y plane (check (b)).                     */

#include "cs_defs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_headers.h"
#include "cs_lagr_tracking.h"
#include "cswm_common.h"
#include "cswm_wall_hit.h"

#if CSWM_USER_MODE
#include "roughwall.h"
#include "cswm_wall.h"
#endif

BEGIN_C_DECLS

/*----------------------------------------------------------------------------
 * Boundary zone types and injection
 *----------------------------------------------------------------------------*/

void
cs_user_lagr_boundary_conditions(const int  bc_type[])
{
  CS_UNUSED(bc_type);

  cs_lagr_zone_data_t *lagr_bcs = cs_lagr_get_boundary_conditions();

  int n_zones = cs_boundary_zone_n_zones();
  for (int z_id = 0; z_id < n_zones; z_id++)
    lagr_bcs->zone_type[z_id] = CS_LAGR_REBOUND;

  const cs_zone_t *z_in  = cs_boundary_zone_by_name("inlet");
  const cs_zone_t *z_out = cs_boundary_zone_by_name("outlet");
  const cs_zone_t *z_w   = cs_boundary_zone_by_name("wall");

  lagr_bcs->zone_type[z_in->id]  = CS_LAGR_INLET;
  lagr_bcs->zone_type[z_out->id] = CS_LAGR_OUTLET;
#if CSWM_USER_MODE
  lagr_bcs->zone_type[z_w->id]   = CS_LAGR_BC_USER;
#else
  lagr_bcs->zone_type[z_w->id]   = CS_LAGR_REBOUND;
#endif

  /* Very heavy 1 mm particles (rho_p = 1e5 kg/m3) in air at rest: relaxation time ~50 s,
     so drag only shortens the velocity by ~1e-4 over the run and never turns it; the
     trajectories are straight lines between wall hits. Injected once, at the first step. */

#if CSWM_SCENE == 2
  const int n_sets = 1;
  const double t15 = tan(15.0 * 3.14159265358979323846 / 180.0);
  const cs_real_t vel[1][3] = {{5.0, -5.0 * t15, 0.0}};
#else
  const int n_sets = 2;
  const cs_real_t vel[2][3] = {{0.5,  1.0,  0.7},
                               {0.6, -0.9, -0.5}};
#endif

  for (int set_id = 0; set_id < n_sets; set_id++) {
    cs_lagr_injection_set_t *zis
      = cs_lagr_get_injection_set(lagr_bcs, z_in->id, set_id);

    zis->n_inject = CSWM_N_INJECT;
    zis->injection_frequency = 0;        /* only at the first time step */

    zis->velocity_profile = 1;           /* imposed velocity vector */
    for (int k = 0; k < 3; k++)
      zis->velocity[k] = vel[set_id][k];

    zis->stat_weight = 1.0;
    zis->flow_rate = 0.0;
    zis->diameter = 1.0e-3;
    zis->diameter_variance = 0.0;
    zis->density = 1.0e5;
  }
}

/*----------------------------------------------------------------------------
 * The wall (CS_LAGR_BC_USER): one roughwall handle, built at the first hit from the
 * scene's parameters (-D flags of setup_case.sh) and shared by every hit.
 *----------------------------------------------------------------------------*/

#if CSWM_USER_MODE

static rw_wall *_wall = NULL;
static FILE *_hits_f = NULL;
static unsigned long long _n_hits = 0;

static const rw_wall *
_the_wall(void)
{
  if (_wall == NULL) {
    rw_wall_params p;
    rw_wall_params_default(&p);
    p.delta_xi_deg = CSWM_DELTA_XI_DEG;
    p.delta_zeta_deg = CSWM_DELTA_ZETA_DEG;
    p.law = CSWM_LAW;
    p.preset = CSWM_PRESET;
    p.seed = CSWM_SEED;
    _wall = cswm_wall_new(&p, "wall");
  }
  return _wall;
}

static void
_open_hits_file(void)
{
  char name[64];
  snprintf(name, 63, "wall_hits_rank%04d.csv", cs_glob_rank_id < 0 ? 0 : cs_glob_rank_id);
  _hits_f = fopen(name, "w");
  if (_hits_f == NULL)
    bft_error(__FILE__, __LINE__, 0, "cannot open %s", name);
  fprintf(_hits_f,
          "step,particle_id,collision_index,face_id,b_zone_id,t_intersect,"
          "xi,yi,zi,u_in_x,u_in_y,u_in_z,n_x,n_y,n_z,"
          "n_dot_outward,u_out_x,u_out_y,u_out_z,status,gamma,gamma_star,candidate_walls,"
          "diameter\n");
}

#endif

/*----------------------------------------------------------------------------
 * Wall hook (CS_LAGR_BC_USER), called from _boundary_treatment() (cs_lagr_tracking.c)
 * with face_norm the unit normal of the crossed face (sub-triangle; it points into the
 * domain here, but roughwall accepts either orientation), c_intersect the hit point, the
 * particle coordinates at the end of the current (sub)displacement, beyond the wall.
 *
 * Does what the built-in CS_LAGR_REBOUND branch does, with the velocity from roughwall:
 *   1. restart point  start_coords = I + 1e-2 (cell_center - I)
 *   2. end point      x -= 2 ((x - I).n) n   (the remaining displacement reflected)
 *   3. velocity       rw_rebound(): the rough wall's rebound (built-in: u -= 2 (u.n) n)
 *   4. velocity seen  us -= 2 (us.n) n
 *   5. event flag |= CS_EVENT_REBOUND, state stays CS_LAGR_PART_TO_SYNC
 * The key of the hit's random stream is (particle id, collision index): the same hit
 * gives the same rebound whatever the number of MPI ranks.
 *----------------------------------------------------------------------------*/

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
#if CSWM_USER_MODE

  cs_real_t *particle_velocity
    = cs_lagr_particles_attr(particles, p_id, CS_LAGR_VELOCITY);
  const cs_real_t diameter
    = cs_lagr_particles_get_real(particles, p_id, CS_LAGR_DIAMETER);

  /* 1.-2. Restart point and remaining displacement, as built in */

  cswm_hit_begin(particles, p_id, face_norm, c_intersect, t_intersect);

  /* 3. Rebound velocity from the rough-wall model */

  unsigned long long pid = cswm_get_pid(particles, p_id);
  unsigned long long cidx = cswm_get_ncoll(particles, p_id);

  rw_hit hit = {
    .velocity = {particle_velocity[0], particle_velocity[1], particle_velocity[2]},
    .spin = {0., 0., 0.},                      /* no particle rotation in this case */
    .normal = {face_norm[0], face_norm[1], face_norm[2]},
    .lay = {CSWM_LAY_X, CSWM_LAY_Y, CSWM_LAY_Z},
    .wall_velocity = {0., 0., 0.},
    .diameter = diameter,
    .particle_id = pid,
    .collision_index = cidx,
  };
  rw_result res;
  int status = rw_rebound(_the_wall(), &hit, &res);
  if (status != RW_OK && status != RW_NOT_APPROACHING)
    bft_error(__FILE__, __LINE__, 0,
              "roughwall: %s (particle %llu, collision %llu)",
              rw_status_string(status), pid, cidx);

  for (int k = 0; k < 3; k++)
    particle_velocity[k] = res.velocity[k];

  cswm_set_key(particles, p_id, pid, cidx + 1);

  /* 4.-5. Velocity seen, event flag and state, as built in */

  cswm_hit_end(particles, p_id, face_norm, event_flag, tracking_state);

  /* Log the hit; n_dot_outward = face_norm . (unit outward b_face_normal). */

  const cs_real_t *bfn = cs_glob_mesh_quantities->b_face_normal + 3*face_id;
  cs_real_t bfn_norm = cs_math_3_norm(bfn);
  cs_real_t n_dot_out = cs_math_3_dot_product(face_norm, bfn) / bfn_norm;

  if (_hits_f == NULL)
    _open_hits_file();
  fprintf(_hits_f,
          "%d,%llu,%llu,%ld,%d,%.17g,%.17g,%.17g,%.17g,"
          "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%.17g,%u,"
          "%.17g\n",
          cs_glob_time_step->nt_cur, pid, cidx, (long)face_id, b_zone_id,
          t_intersect, c_intersect[0], c_intersect[1], c_intersect[2],
          hit.velocity[0], hit.velocity[1], hit.velocity[2],
          face_norm[0], face_norm[1], face_norm[2], n_dot_out,
          res.velocity[0], res.velocity[1], res.velocity[2], status,
          res.gamma, res.gamma_star, res.candidate_walls, diameter);
  _n_hits++;
  if (_n_hits % 256 == 0)
    fflush(_hits_f);

#else

  /* built-in mode: never called (walls are CS_LAGR_REBOUND) */
  CS_UNUSED(particles); CS_UNUSED(p_id); CS_UNUSED(face_id);
  CS_UNUSED(face_norm); CS_UNUSED(c_intersect); CS_UNUSED(t_intersect);
  CS_UNUSED(b_zone_id); CS_UNUSED(event_flag); CS_UNUSED(tracking_state);
  bft_error(__FILE__, __LINE__, 0,
            "cswm: CS_LAGR_BC_USER hook called in built-in mode");

#endif
}

/* Flush the hit log (called from cs_user_lagr_extra_operations) */

void
cswm_flush_hits(void)
{
#if CSWM_USER_MODE
  if (_hits_f != NULL)
    fflush(_hits_f);
#endif
}

END_C_DECLS
