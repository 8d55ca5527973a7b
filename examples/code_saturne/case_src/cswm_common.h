#ifndef CSWM_COMMON_H
#define CSWM_COMMON_H

#include <math.h>
/* Shared helpers of the roughwall hook case (code_saturne 6.0.x ONLY).
 *
 * Run parameters: overridable with -D... in the compile flags
 * (setup_case.sh writes them into DATA/cs_user_scripts.py).             */

#ifndef CSWM_DT
#define CSWM_DT 0.005            /* time step (s) */
#endif
#ifndef CSWM_NT_MAX
#define CSWM_NT_MAX 60           /* number of time steps */
#endif
#ifndef CSWM_N_INJECT
#define CSWM_N_INJECT 50         /* particles per injection set */
#endif
#ifndef CSWM_NAMED_GROUPS
#define CSWM_NAMED_GROUPS 0      /* 1 if the mesh has named groups (Gmsh 4.1) */
#endif
#ifndef CSWM_USER_MODE
#define CSWM_USER_MODE 0         /* 0: walls CS_LAGR_REBOUND, 1: CS_LAGR_BC_USER */
#endif
#ifndef CSWM_SCENE
#define CSWM_SCENE 1             /* 1: particles aimed at every wall; 2: at the floor */
#endif
#ifndef CSWM_TRAJECTORIES
#define CSWM_TRAJECTORIES 1      /* write traj_rank<r>.csv every step */
#endif

/* The rough wall (roughwall's rw_wall_params) and its lay direction (global axes). */
#ifndef CSWM_DELTA_XI_DEG
#define CSWM_DELTA_XI_DEG 0.0
#endif
#ifndef CSWM_DELTA_ZETA_DEG
#define CSWM_DELTA_ZETA_DEG 0.0
#endif
#ifndef CSWM_LAW
#define CSWM_LAW 0               /* RW_LAW_ELASTIC */
#endif
#ifndef CSWM_PRESET
#define CSWM_PRESET 0            /* RW_PRESET_NONE */
#endif
#ifndef CSWM_SEED
#define CSWM_SEED 2021
#endif
#ifndef CSWM_LAY_X
#define CSWM_LAY_X 1.0
#endif
#ifndef CSWM_LAY_Y
#define CSWM_LAY_Y 0.0
#endif
#ifndef CSWM_LAY_Z
#define CSWM_LAY_Z 0.0
#endif

/* ---------------------------------------------------------------------
 * Stable particle id + per-particle collision counter.
 *
 * code_saturne 6.0 has NO global particle id attribute.  We add ONE user
 * particle variable (CS_LAGR_USER, a cs_real_t that is part of the particle
 * record and therefore migrates with the particle between MPI ranks and is
 * written to Lagrangian restart files).  It packs
 *     key = particle_id + 2^32 * collision_count
 * which is exact in a double while key < 2^53 (particle_id < 2^32,
 * collision_count < 2^21).
 *
 * Why not two user variables?  6.0.2 initialises user variables at
 * injection with  cs_lagr_particle_set_real(..., CS_LAGR_USER + i, 0.0)
 * (cs_lagr_injection.c, _init_particles): for i >= 1 this indexes past the
 * attribute table (CS_LAGR_USER + 1 == CS_LAGR_N_ATTRIBUTES) and writes
 * 8 zero bytes at a bogus displacement (heap corruption).  Keep
 * n_user_variables == 1.
 * --------------------------------------------------------------------- */

#define CSWM_ID_RANGE 4294967296.0   /* 2^32 */

static inline unsigned long long
cswm_get_pid(const cs_lagr_particle_set_t *p_set, cs_lnum_t p_id)
{
  const cs_real_t *u = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_USER);
  double c = floor(u[0] / CSWM_ID_RANGE);
  return (unsigned long long)(u[0] - c*CSWM_ID_RANGE);
}

static inline unsigned long long
cswm_get_ncoll(const cs_lagr_particle_set_t *p_set, cs_lnum_t p_id)
{
  const cs_real_t *u = cs_lagr_particles_attr_const(p_set, p_id, CS_LAGR_USER);
  return (unsigned long long)floor(u[0] / CSWM_ID_RANGE);
}

static inline void
cswm_set_key(cs_lagr_particle_set_t *p_set, cs_lnum_t p_id,
             unsigned long long pid, unsigned long long ncoll)
{
  cs_real_t *u = cs_lagr_particles_attr(p_set, p_id, CS_LAGR_USER);
  u[0] = (double)pid + CSWM_ID_RANGE * (double)ncoll;
}

/*----------------------------------------------------------------------------
 * Minimal replica of the private struct at the start of every particle
 * record in code_saturne 6.0.x (src/lagr/cs_lagr_tracking.c, lines 136-145
 * in 6.0.2):
 *
 *   typedef struct {
 *     cs_real_t  start_coords[3];       starting coordinates for next
 *                                       displacement  (= tracking restart
 *                                       point)
 *     cs_lnum_t  last_face_num;         last face number encountered
 *     cs_lagr_tracking_state_t  state;  current state
 *   } cs_lagr_tracking_info_t;
 *
 * It is mapped at offset 0 of each particle ("p_buffer + extents*p_id"),
 * before the attributes (p_am->lb = aligned sizeof of this struct).
 * Only start_coords is written here.
 *----------------------------------------------------------------------------*/

typedef struct {
  cs_real_t                 start_coords[3];
  cs_lnum_t                 last_face_num;
  cs_lagr_tracking_state_t  state;
} _cs60_tracking_info_t;

/* The Lagrangian options every roughwall case shares (cs_user_lagr_model): transport only
 * (no heat or mass transfer, deposition, resuspension, clogging, DLVO, Brownian motion,
 * statistical classes), no diffusion or Poisson correction, and the one user particle
 * variable that holds the packed (particle id, collision count) key above (do NOT use more
 * than 1 in 6.0.2). The coupling mode, time scheme and dispersion are the case's.     */
static inline void
cswm_lagr_transport_only(void)
{
  cs_glob_lagr_time_scheme->idiffl = 0;
  cs_glob_lagr_time_scheme->modcpl = 0;
  cs_glob_lagr_time_scheme->ilapoi = 0;          /* no Poisson correction */

  cs_glob_lagr_model->physical_model = 0;        /* transport only */
  cs_glob_lagr_model->deposition = 0;
  cs_glob_lagr_model->resuspension = 0;
  cs_glob_lagr_model->roughness = 0;
  cs_glob_lagr_model->clogging = 0;
  cs_glob_lagr_model->dlvo = 0;
  cs_glob_lagr_model->n_stat_classes = 0;
  cs_glob_lagr_brownian->lamvbr = 0;

  cs_lagr_set_n_user_variables(1);
}

/* flush the wall-hit log (defined in cs_user_lagr_boundary_conditions.c) */
void cswm_flush_hits(void);

#endif /* CSWM_COMMON_H */
