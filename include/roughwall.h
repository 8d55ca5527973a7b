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
 The rebound law measured on the wall itself (a scan's in-place deterministic reference),
 from the table `rebound scan --measured-wall` writes (`wall_table_text`, required).
 */
#define RW_MODEL_MEASURED_WALL 6

/*
 An immutable wall handle, safe to share between threads.
 */
typedef struct rw_wall rw_wall;

/*
 What a wall handle is built from. Start from `rw_wall_params_default` and set fields.
 */
typedef struct {
  /*
   Δξ: standard deviation (degrees) of the wall normal's angle along the lay direction
   (Radenkovic & Simonin 2021, Eq. 15): 0 … 20 (beyond 7.5 the message holds a warning).
   */
  double delta_xi_deg;
  /*
   Δζ: standard deviation (degrees) of the wall normal's angle across the lay direction
   (Radenkovic & Simonin 2021, Eq. 15): 0 … 20, 0 for 2-D roughness (beyond 7.5 the
   message holds a warning).
   */
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
   Sommerfeld–Huber `e_h`: the restitution coefficient at impact angles beyond
   `alpha_e_deg` (Radenkovic & Simonin 2021, Eq. 36), in (0, 1]. NaN: the preset's value;
   must be NaN with `RW_LAW_ELASTIC`.
   */
  double e_h;
  /*
   Sommerfeld–Huber `α_e` (degrees): the impact angle up to which the restitution
   coefficient falls linearly from 1 to `e_h` (Radenkovic & Simonin 2021, Eq. 36), in
   (0, 90]. NaN: the preset's value; must be NaN with `RW_LAW_ELASTIC`.
   */
  double alpha_e_deg;
  /*
   Sommerfeld–Huber `μ_0`: the friction coefficient at grazing incidence (impact angle 0;
   Radenkovic & Simonin 2021, Eq. 37 as corrected), in [0, 2]. NaN: the preset's value;
   must be NaN with `RW_LAW_ELASTIC`.
   */
  double mu_0;
  /*
   Sommerfeld–Huber `μ_h`: the friction coefficient at impact angles beyond
   `alpha_mu_deg` (Radenkovic & Simonin 2021, Eq. 37 as corrected), in [0, 2]. NaN: the
   preset's value; must be NaN with `RW_LAW_ELASTIC`.
   */
  double mu_h;
  /*
   Sommerfeld–Huber `α_μ` (degrees): the impact angle up to which the friction
   coefficient goes linearly from `mu_0` to `mu_h` (Radenkovic & Simonin 2021, Eq. 37 as
   corrected), in (0, 90]. NaN: the preset's value; must be NaN with `RW_LAW_ELASTIC`.
   */
  double alpha_mu_deg;
  /*
   ψ of the single-collision probability (Eq. 34), in [0.01, 100]; 2 in the paper.
   */
  double psi;
  /*
   Seed of every hit's random stream, with (particle id, collision index).
   */
  uint64_t seed;
  /*
   The rough-wall model: `RW_MODEL_RADENKOVIC_SIMONIN_2021` (default) …
   `RW_MODEL_CALIBRATED`.
   */
  int32_t model;
  /*
   The isotropic models' roughness angle Δγ (degrees, 0 … 20); NaN: `(Δξ + Δζ)/2`.
   */
  double delta_gamma_deg;
  /*
   `RW_MODEL_CALIBRATED` only: the escape table as the NUL-terminated text
   `rebound calibrate` writes (`escape_table.csv`); NULL: the built-in table. The
   handle keeps its own copy (the text may be freed after `rw_wall_new`). A process keeps
   each distinct table for its life, at most 16 besides the built-in one (about 1.4 MB
   each): a 17th is `RW_INVALID_PARAMETER`.
   */
  const char *escape_table_csv;
  /*
   `RW_MODEL_MEASURED_WALL` only, and required there: the wall's table as the
   NUL-terminated text `rebound scan --measured-wall` writes (`measured_wall_*.txt`,
   named by the wall card's row). The handle keeps its own copy; a process keeps each
   distinct table for its life, at most 16 (4–18 MB each). The deviations are then
   the table's (`delta_xi_deg`, `delta_zeta_deg` are not used), and the sign of
   `rw_hit.lay` matters: a measured wall need not be its own mirror image.
   */
  const char *wall_table_text;
} rw_wall_params;

/*
 One particle–wall hit, global axes, SI units.
 */
typedef struct {
  /*
   Particle velocity (m/s, global axes) before the hit, not relative to the wall.
   */
  double velocity[3];
  /*
   Particle angular velocity (rad/s, global axes) before the hit.
   */
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
   The first part of the key of the hit's random stream (with the wall's `seed` and
   `collision_index`): the particle's identifier. The same key gives the same rebound on
   any rank, so use an identifier that is unique and does not change across ranks.
   */
  uint64_t particle_id;
  /*
   The second part of the stream's key: the index of this hit among the particle's wall
   hits (e.g. a per-particle counter), so that successive hits draw different walls.
   */
  uint64_t collision_index;
} rw_hit;

/*
 The rebound of a hit.
 */
typedef struct {
  /*
   Rebound velocity (m/s, global axes, wall velocity added back). When the particle is
   returned unchanged (`status` not `RW_OK`): its incident velocity, non-finite
   components as 0.
   */
  double velocity[3];
  /*
   Rebound angular velocity (rad/s, global axes). When the particle is returned
   unchanged: its incident angular velocity, non-finite components as 0.
   */
  double spin[3];
  /*
   Inclination γ (rad) of the virtual wall element that produced the rebound, in the
   incident plane (Radenkovic & Simonin 2021, Eq. 20); 0 for a smooth wall or a particle
   returned unchanged.
   */
  double gamma;
  /*
   Inclination γ* (rad) of that wall element normal to the incident plane (Radenkovic &
   Simonin 2021, Eq. 21); 0 for a smooth wall or a particle returned unchanged.
   */
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
 The carrier fluid and a particle where the particle is, for the between-hit laws
 `rw_saffman_mei_lift`, `rw_magnus_lift` and `rw_spin_relax` (global axes, SI units;
 `roughwall::carrier`).
 */
typedef struct {
  /*
   Fluid density (kg/m³, > 0).
   */
  double rho_f;
  /*
   Fluid dynamic viscosity (Pa s, > 0).
   */
  double mu_f;
  /*
   Particle density (kg/m³, > 0).
   */
  double rho_p;
  /*
   Particle diameter (m, > 0).
   */
  double d_p;
  /*
   The fluid's velocity as the particle sees it minus the particle's (m/s).
   */
  double slip[3];
  /*
   The fluid's vorticity, the curl of its velocity (1/s): the fluid turns at half of it.
   */
  double vorticity[3];
  /*
   The particle's angular velocity (rad/s).
   */
  double spin[3];
} rw_fluid_point;

/*
 `n` hits in struct-of-arrays form. Inputs marked "may be NULL" default to zero. Output
 arrays may be the input arrays (in-place update); those marked "may be NULL" are not
 written.
 */
typedef struct {
  /*
   Number of hits: every array that is not NULL holds `n` elements. With `n` = 0
   nothing is read or written and the arrays may all be NULL.
   */
  size_t n;
  /*
   x components of the particle velocities (m/s, global axes, before the hit, not
   relative to the wall), as `rw_hit.velocity[0]`; required.
   */
  const double *ux;
  /*
   y components of the particle velocities (m/s, global axes); required.
   */
  const double *uy;
  /*
   z components of the particle velocities (m/s, global axes); required.
   */
  const double *uz;
  /*
   x components of the particle angular velocities (rad/s, global axes), as
   `rw_hit.spin[0]`; may be NULL (then 0).
   */
  const double *wx;
  /*
   y components of the particle angular velocities (rad/s, global axes); may be NULL
   (then 0).
   */
  const double *wy;
  /*
   z components of the particle angular velocities (rad/s, global axes); may be NULL
   (then 0).
   */
  const double *wz;
  /*
   x components of the face normals (either orientation, any non-zero length), as
   `rw_hit.normal[0]`; required.
   */
  const double *nx;
  /*
   y components of the face normals (either orientation, any non-zero length);
   required.
   */
  const double *ny;
  /*
   z components of the face normals (either orientation, any non-zero length);
   required.
   */
  const double *nz;
  /*
   x components of the lay directions (that of Δξ, projected onto the wall plane), as
   `rw_hit.lay[0]`; required.
   */
  const double *lx;
  /*
   y components of the lay directions (that of Δξ, projected onto the wall plane);
   required.
   */
  const double *ly;
  /*
   z components of the lay directions (that of Δξ, projected onto the wall plane);
   required.
   */
  const double *lz;
  /*
   x components of the wall velocities (m/s, global axes), as `rw_hit.wall_velocity[0]`;
   may be NULL (then 0).
   */
  const double *vx;
  /*
   y components of the wall velocities (m/s, global axes); may be NULL (then 0).
   */
  const double *vy;
  /*
   z components of the wall velocities (m/s, global axes); may be NULL (then 0).
   */
  const double *vz;
  /*
   Diameters (m).
   */
  const double *diameter;
  /*
   First parts of the random streams' keys, the particle identifiers, as
   `rw_hit.particle_id`; required.
   */
  const uint64_t *particle_id;
  /*
   Second parts of the random streams' keys, the hit indices, as
   `rw_hit.collision_index`; required.
   */
  const uint64_t *collision_index;
  /*
   x components of the rebound velocities (m/s, global axes), as `rw_result.velocity[0]`;
   required (may be `ux`, for an in-place update).
   */
  double *out_ux;
  /*
   y components of the rebound velocities (m/s, global axes); required (may be `uy`).
   */
  double *out_uy;
  /*
   z components of the rebound velocities (m/s, global axes); required (may be `uz`).
   */
  double *out_uz;
  /*
   x components of the rebound angular velocities (rad/s, global axes), as
   `rw_result.spin[0]`; may be NULL (not written).
   */
  double *out_wx;
  /*
   y components of the rebound angular velocities (rad/s, global axes); may be NULL
   (not written).
   */
  double *out_wy;
  /*
   z components of the rebound angular velocities (rad/s, global axes); may be NULL
   (not written).
   */
  double *out_wz;
  /*
   γ (rad), as `rw_result.gamma`; may be NULL (not written).
   */
  double *out_gamma;
  /*
   γ* (rad), as `rw_result.gamma_star`; may be NULL (not written).
   */
  double *out_gamma_star;
  /*
   Candidate walls drawn, as `rw_result.candidate_walls`; may be NULL (not written).
   */
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
 Impact angle (rad, 0 to π/2) of `hit`'s incident velocity (relative to the wall) on the
 wall element that produced `result`: the facet the particle struck, whose angle erosion
 laws (Finnie, Oka, DNV) take, rather than the mean wall's. It follows from
 `result->gamma`, `result->gamma_star` and the incident direction in the wall's frame of
 `hit->normal` and `hit->lay` (Radenkovic & Simonin 2021, Eqs. 10, 20–23). On a smooth
 wall it is the angle to the wall. 0 when `result->status` is not `RW_OK` or a pointer is
 NULL. Allocates nothing; never NaN.

 # Safety
 `hit` and `result` are NULL or valid.
 */
double rw_element_impact_angle(const rw_hit *hit, const rw_result *result);

/*
 The Saffman–Mei shear-lift acceleration (m/s², force over the particle's mass) on the
 particle of `point`, into `acceleration[0..3]`: Saffman's lift with Mei's (1992)
 finite-Reynolds correction (`roughwall::carrier`; docs/physics.md §8a). A CFD
 code adds it to gravity in its particle equation. `RW_OK`; `RW_INVALID_INPUT` (zeros
 written) for a non-finite number or a non-positive property; `RW_NULL_POINTER`.

 # Safety
 `point` is NULL or valid; `acceleration` is NULL or holds 3 doubles.
 */
int32_t rw_saffman_mei_lift(const rw_fluid_point *point, double *acceleration);

/*
 The Magnus (rotational) lift acceleration (m/s²) on the particle of `point`, spinning at
 `point->spin` relative to the fluid's rotation, into `acceleration[0..3]`, with
 Oesterlé & Bui Dinh's (1998) coefficient (docs/physics.md §8a). Statuses
 as `rw_saffman_mei_lift`.

 # Safety
 `point` is NULL or valid; `acceleration` is NULL or holds 3 doubles.
 */
int32_t rw_magnus_lift(const rw_fluid_point *point, double *acceleration);

/*
 The particle's angular velocity (rad/s) after `dt` seconds in the fluid of `point`,
 into `spin[0..3]` (which may be `point->spin`): the rotational drag of Dennis, Singh &
 Ingham (1980) relaxes it towards the fluid's rotation (docs/physics.md §8a), at the rate
 of the start of the step (exact in the Stokes regime). Carry
 `rw_result.spin` with this between hits and give it back in the next `rw_hit.spin`.
 `RW_INVALID_INPUT` (the spin written back unchanged, non-finite components as 0) for a
 non-finite number, a non-positive property or a negative `dt`.

 # Safety
 `point` is NULL or valid; `spin` is NULL or holds 3 doubles.
 */
int32_t rw_spin_relax(const rw_fluid_point *point, double dt, double *spin);

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
