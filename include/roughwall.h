/*
 * roughwall: the stochastic rough-wall rebound model of Radenkovic & Simonin (2021) for
 * Euler-Lagrange CFD codes, one call per particle-wall hit. See docs/c-library.md.
 */

#ifndef ROUGHWALL_H
#define ROUGHWALL_H

/* Generated from crates/roughwall/src/ffi.rs by cbindgen (crates/roughwall/tests/c_header.rs checks it); do not edit. */

#include <stdint.h>
#include <stddef.h>

/*
 A rebound was computed (`rw_result.status`), or: the call succeeded.
 */
#define RW_OK 0

/*
 The particle does not move across the wall (its velocity relative to the wall is parallel
 to it, or zero): returned unchanged.
 */
#define RW_NOT_APPROACHING 1

/*
 A non-finite number, a zero-length normal, a lay direction parallel to the normal or a
 negative diameter: the particle is returned unchanged (non-finite components as 0).
 */
#define RW_INVALID_INPUT 2

/*
 A wall parameter out of its range (see the message of `rw_wall_new`), or a `threads`
 argument of `rw_rebound_batch` above `RW_MAX_THREADS`.
 */
#define RW_INVALID_PARAMETER 3

/*
 A required pointer was NULL.
 */
#define RW_NULL_POINTER 4

/*
 A bug in the library (a Rust panic, caught at the boundary); please report it. The
 outputs of the call are then unspecified (a batch may be partly written).
 */
#define RW_INTERNAL_ERROR 5

/*
 The most threads `rw_rebound_batch` accepts (more is `RW_INVALID_PARAMETER`): far above
 the cores of any node a CFD rank runs on, far below what exhausts a process's threads.
 */
#define RW_MAX_THREADS 1024

/*
 Ideally elastic, frictionless collisions (Radenkovic & Simonin 2021, Sec. 3.1).
 */
#define RW_LAW_ELASTIC 0

/*
 Sommerfeld–Huber restitution and friction (Radenkovic & Simonin 2021, Eqs. 36–42).
 */
#define RW_LAW_SOMMERFELD_HUBER 1

/*
 No preset: every Sommerfeld–Huber parameter is given.
 */
#define RW_PRESET_NONE 0

/*
 Glass beads on stainless steel (Laín & Sommerfeld 2008 fit; parameters left NaN take it).
 */
#define RW_PRESET_GLASS_STEEL 1

/*
 Radenkovic & Simonin 2021 (the default rough-wall model).
 */
#define RW_MODEL_RADENKOVIC_SIMONIN_2021 0

/*
 Sommerfeld & Huber 1999: isotropic, shadow effect, repeated hits.
 */
#define RW_MODEL_SOMMERFELD_HUBER_1999 1

/*
 The impact angle perturbed in the incident plane (OpenFOAM forks).
 */
#define RW_MODEL_GAUSSIAN_ANGLE 2

/*
 A Gaussian tilt with a uniform azimuth (LIGGGHTS-PFM).
 */
#define RW_MODEL_GAUSSIAN_TILT 3

/*
 The normal rotated by two shadow-weighted Gaussian angles (ELEXI).
 */
#define RW_MODEL_NORMAL_PERTURBATION 4

/*
 The paper's virtual walls with an escape law calibrated on the deterministic simulation,
 multiple collisions followed (`escape_table_csv`; NULL: the built-in table).
 */
#define RW_MODEL_CALIBRATED 5

/*
 An immutable wall handle, safe to share between threads.
 */
typedef struct rw_wall rw_wall;

/*
 What a wall handle is built from. Start from `rw_wall_params_default` and set fields.
 */
typedef struct {
  /*
   Standard deviations (degrees) of the wall normal's angles along the lay direction (Δξ)
   and across it (Δζ): 0 … 20 (beyond 7.5 the message holds a warning).
   */
  double delta_xi_deg;
  double delta_zeta_deg;
  /*
   `RW_LAW_ELASTIC` or `RW_LAW_SOMMERFELD_HUBER`.
   */
  int32_t law;
  /*
   `RW_PRESET_NONE` or `RW_PRESET_GLASS_STEEL` (Sommerfeld–Huber only).
   */
  int32_t preset;
  /*
   Sommerfeld–Huber (Eqs. 36–37): restitution beyond `alpha_e_deg`, (0, 1]; the angle
   (0, 90]; friction at grazing and beyond `alpha_mu_deg`, [0, 2]; the angle (0, 90].
   NaN: the preset's value.
   */
  double e_h;
  double alpha_e_deg;
  double mu_0;
  double mu_h;
  double alpha_mu_deg;
  /*
   ψ of the single-collision probability (Eq. 34), > 0; 2 in the paper.
   */
  double psi;
  /*
   Seed of every hit's random stream, with (particle id, collision index).
   */
  uint64_t seed;
  /*
   The rough-wall model: `RW_MODEL_RADENKOVIC_SIMONIN_2021` (default) …
   `RW_MODEL_NORMAL_PERTURBATION`.
   */
  int32_t model;
  /*
   The isotropic models' roughness angle Δγ (degrees, 0 … 20); NaN: `(Δξ + Δζ)/2`.
   */
  double delta_gamma_deg;
  /*
   `RW_MODEL_CALIBRATED` only: the escape table as the NUL-terminated text
   `rebound calibrate` writes (`escape_table.csv`); NULL: the built-in table. The
   handle keeps its own copy (the text may be freed after `rw_wall_new`).
   */
  const char *escape_table_csv;
} rw_wall_params;

/*
 One particle–wall hit, global axes, SI units.
 */
typedef struct {
  /*
   Particle velocity (m/s) and angular velocity (rad/s).
   */
  double velocity[3];
  double spin[3];
  /*
   Face normal, either orientation, any non-zero length (one of unit length to
   round-off is used as given, as the host's own rebound uses it).
   */
  double normal[3];
  /*
   The wall's lay direction (that of Δξ), projected onto the wall plane.
   */
  double lay[3];
  /*
   Velocity of the wall (m/s).
   */
  double wall_velocity[3];
  /*
   Particle diameter (m), ≥ 0.
   */
  double diameter;
  /*
   The key of the hit's random stream: the same key gives the same rebound on any rank.
   */
  uint64_t particle_id;
  uint64_t collision_index;
} rw_hit;

/*
 The rebound of a hit.
 */
typedef struct {
  /*
   Rebound velocity (m/s, wall velocity added back) and angular velocity (rad/s).
   */
  double velocity[3];
  double spin[3];
  /*
   Inclinations γ, γ* (rad) of the virtual wall element that produced the rebound.
   */
  double gamma;
  double gamma_star;
  /*
   Candidate walls drawn (≥ 1 for a rebound).
   */
  uint32_t candidate_walls;
  /*
   `RW_OK`, `RW_NOT_APPROACHING` or `RW_INVALID_INPUT`.
   */
  int32_t status;
} rw_result;

/*
 `n` hits in struct-of-arrays form. Inputs marked "may be NULL" default to zero. Output
 arrays may be the input arrays (in-place update); those marked "may be NULL" are not
 written.
 */
typedef struct {
  size_t n;
  /*
   Velocities (m/s).
   */
  const double *ux;
  const double *uy;
  const double *uz;
  /*
   Angular velocities (rad/s); may be NULL.
   */
  const double *wx;
  const double *wy;
  const double *wz;
  /*
   Face normals, either orientation.
   */
  const double *nx;
  const double *ny;
  const double *nz;
  /*
   Lay directions.
   */
  const double *lx;
  const double *ly;
  const double *lz;
  /*
   Wall velocities (m/s); may be NULL.
   */
  const double *vx;
  const double *vy;
  const double *vz;
  /*
   Diameters (m).
   */
  const double *diameter;
  /*
   Keys of the random streams.
   */
  const uint64_t *particle_id;
  const uint64_t *collision_index;
  /*
   Rebound velocities.
   */
  double *out_ux;
  double *out_uy;
  double *out_uz;
  /*
   Rebound angular velocities; may be NULL.
   */
  double *out_wx;
  double *out_wy;
  double *out_wz;
  /*
   γ, γ* and candidate walls; may be NULL.
   */
  double *out_gamma;
  double *out_gamma_star;
  uint32_t *out_candidate_walls;
  /*
   Status of each hit.
   */
  int32_t *out_status;
} rw_batch;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

/*
 Fills `params` with the defaults: a smooth elastic wall (Δξ = Δζ = 0), no preset,
 Sommerfeld–Huber parameters NaN (taken from the preset), ψ = 2, seed 0.

 # Safety
 `params` is NULL or points to a writable `rw_wall_params`.
 */
int32_t rw_wall_params_default(rw_wall_params *params);

/*
 Builds a wall handle into `*wall`. On `RW_INVALID_PARAMETER`, `message` (if not NULL)
 holds one line naming the parameter, its value and what is allowed, and `*wall` is NULL;
 on `RW_OK` it holds the warnings, if any ("" otherwise). Free the handle with
 `rw_wall_free`.

 # Safety
 `params` and `wall` are NULL or valid; `message` is NULL or points to `message_len`
 writable bytes.
 */
int32_t rw_wall_new(const rw_wall_params *params, rw_wall **wall, char *message, size_t message_len);

/*
 Frees a wall handle (NULL is allowed).

 # Safety
 `wall` is NULL or a handle from `rw_wall_new` not freed before.
 */
void rw_wall_free(rw_wall *wall);

/*
 The rebound of one hit, into `*result`. Returns the hit's status (also in
 `result->status`): `RW_OK` (a rebound), `RW_NOT_APPROACHING` or `RW_INVALID_INPUT` (the
 particle is returned unchanged), or `RW_NULL_POINTER` (nothing written). Allocates
 nothing, starts no thread.

 # Safety
 `wall` is NULL or a live handle; `hit` is NULL or valid; `result` is NULL or writable.
 */
int32_t rw_rebound(const rw_wall *wall, const rw_hit *hit, rw_result *result);

/*
 The rebounds of `batch->n` hits (each exactly as `rw_rebound` gives it, whatever the
 thread count), per-hit statuses in `batch->out_status`: bad hits get their status
 (`RW_INVALID_INPUT`, …) and finite outputs, the others are rebounded. `threads` ≤ 1
 runs in the calling thread; 2 … `RW_MAX_THREADS` splits the hits over that many
 threads (at most one per hit), started and joined in this call (a thread the system
 refuses to start leaves its share to the calling thread). Returns `RW_OK`;
 `RW_NULL_POINTER` when `wall`, `batch` or a required array is NULL, and
 `RW_INVALID_PARAMETER` when `threads` > `RW_MAX_THREADS`: then nothing is written.

 # Safety
 `wall` is NULL or a live handle; `batch` is NULL or valid, with every non-NULL array
 holding `n` elements.
 */
int32_t rw_rebound_batch(const rw_wall *wall, const rw_batch *batch, int32_t threads);

/*
 The library's version, e.g. "0.1.0" (a static string).
 */
const char *rw_version(void);

/*
 A short description of a status code (a static string).
 */
const char *rw_status_string(int32_t status);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* ROUGHWALL_H */
