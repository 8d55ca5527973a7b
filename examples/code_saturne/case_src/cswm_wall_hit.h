#ifndef CSWM_WALL_HIT_H
#define CSWM_WALL_HIT_H
/* The parts of a CS_LAGR_BC_USER wall hit that are code_saturne's, shared by every case whose
 * wall hook calls roughwall (case_src/ and pipe/case_src/). They do what the built-in
 * CS_LAGR_REBOUND branch of _boundary_treatment() (cs_lagr_tracking.c, 6.0.2) does, in the
 * same operations and order, so that a smooth elastic roughwall wall gives the built-in
 * trajectories bit for bit (check (a) of run_checks.sh):
 *   cswm_hit_begin:  1. restart point  start_coords = I + 1e-2 (cell_center - I)
 *                    2. end point      x -= 2 ((x - I).n) n  (the remaining displacement)
 *   (the host then sets the velocity: roughwall's rebound)
 *   cswm_hit_end:    4. velocity seen  us -= 2 (us.n) n
 *                    5. event flag |= CS_EVENT_REBOUND, state CS_LAGR_PART_TO_SYNC
 * Also checks that the replica of the private tracking record (cswm_common.h) matches.
 * PINNED TO code_saturne 6.0.x.                                                           */

#include "cswm_common.h"

static inline void
cswm_hit_begin(cs_lagr_particle_set_t  *particles,
               cs_lnum_t                p_id,
               const cs_real_t          face_norm[3],
               const cs_real_t          c_intersect[3],
               cs_real_t                t_intersect)
{
  const cs_real_t bc_epsilon = 1.e-2;  /* the built-in rebound's constant */

  const cs_lagr_attribute_map_t *p_am = particles->p_am;
  unsigned char *particle = particles->p_buffer + p_am->extents * p_id;
  _cs60_tracking_info_t *p_info = (_cs60_tracking_info_t *)particle;
  cs_real_t *particle_coord = cs_lagr_particle_attr(particle, p_am, CS_LAGR_COORDS);

  /* Layout guard (6.0.x private struct): the record starts with the tracking info, and
     c_intersect is what the tracker computed from start_coords: I = (x - start) t + start. */

  if (p_am->lb < sizeof(_cs60_tracking_info_t))
    bft_error(__FILE__, __LINE__, 0,
              "cswm: particle lower bound %d < replica tracking info size %d: "
              "code_saturne version is not 6.0.x?",
              (int)p_am->lb, (int)sizeof(_cs60_tracking_info_t));
  for (int k = 0; k < 3; k++) {
    cs_real_t d = particle_coord[k] - p_info->start_coords[k];
    cs_real_t ik = d*t_intersect + p_info->start_coords[k];
    if (fabs(ik - c_intersect[k]) > 1e-9 * (1. + fabs(c_intersect[k])))
      bft_error(__FILE__, __LINE__, 0,
                "cswm: tracking info layout mismatch (start_coords does not "
                "reproduce c_intersect): the hook is pinned to code_saturne 6.0.x");
  }

  cs_lnum_t cell_id = cs_lagr_particle_get_lnum(particle, p_am, CS_LAGR_CELL_ID);
  const cs_real_t *cell_cen = cs_glob_mesh_quantities->cell_cen + 3*cell_id;

  /* 1. Reset the tracking restart point (private start_coords) */

  for (int k = 0; k < 3; k++) {
    cs_real_t vect_cen = (cell_cen[k] - c_intersect[k]);
    p_info->start_coords[k] = c_intersect[k] + bc_epsilon * vect_cen;
  }

  /* 2. Reflect the remaining displacement (new end point) */

  cs_real_t disp[3];
  for (int k = 0; k < 3; k++)
    disp[k] = particle_coord[k] - c_intersect[k];

  cs_real_t tmp = 2. * cs_math_3_dot_product(disp, face_norm);
  for (int k = 0; k < 3; k++)
    particle_coord[k] -= tmp * face_norm[k];
}

static inline void
cswm_hit_end(cs_lagr_particle_set_t    *particles,
             cs_lnum_t                  p_id,
             const cs_real_t            face_norm[3],
             int                       *event_flag,
             cs_lagr_tracking_state_t  *tracking_state)
{
  cs_real_t *particle_velocity_seen
    = cs_lagr_particles_attr(particles, p_id, CS_LAGR_VELOCITY_SEEN);

  /* 4. Velocity seen: reflected as in the built-in rebound */

  cs_real_t tmp = 2. * cs_math_3_dot_product(particle_velocity_seen, face_norm);
  for (int k = 0; k < 3; k++)
    particle_velocity_seen[k] -= tmp * face_norm[k];

  /* 5. Event flag and state */

  *event_flag = *event_flag | CS_EVENT_REBOUND;
  *tracking_state = CS_LAGR_PART_TO_SYNC;
}

#endif /* CSWM_WALL_HIT_H */
