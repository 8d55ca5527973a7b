//! The C ABI of the wall model (`libroughwall`, header `include/roughwall.h`, generated from
//! this file by cbindgen and checked by `tests/c_header.rs`): a wall handle, one call per
//! particle–wall hit, a batch call in struct-of-arrays form, and a version query.
//!
//! Every entry point returns a status and never unwinds into the host: a panic (a bug)
//! becomes `RW_INTERNAL_ERROR`. Null pointers, non-finite numbers, a zero normal, a lay
//! direction parallel to the normal and a negative diameter are statuses, never NaN
//! outputs. A single call allocates nothing and starts no thread; only the batch call
//! starts threads, and only when asked to.
#![allow(non_camel_case_types)]

use crate::collision::CollisionParams;
use crate::wall_model::{Hit, HitOutcome, HitStatus, WallModel, WallParams};
use std::ffi::c_char;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// A rebound was computed (`rw_result.status`), or: the call succeeded.
pub const RW_OK: i32 = 0;
/// The particle does not move across the wall (its velocity relative to the wall is parallel
/// to it, or zero): returned unchanged.
pub const RW_NOT_APPROACHING: i32 = 1;
/// A non-finite number, a zero-length normal, a lay direction parallel to the normal or a
/// negative diameter: the particle is returned unchanged (non-finite components as 0).
pub const RW_INVALID_INPUT: i32 = 2;
/// A wall parameter out of its range (see the message of `rw_wall_new`), or a `threads`
/// argument of `rw_rebound_batch` above `RW_MAX_THREADS`.
pub const RW_INVALID_PARAMETER: i32 = 3;
/// A required pointer was NULL.
pub const RW_NULL_POINTER: i32 = 4;
/// A bug in the library (a Rust panic, caught at the boundary); please report it. The
/// outputs of the call are then unspecified (a batch may be partly written).
pub const RW_INTERNAL_ERROR: i32 = 5;

/// The most threads `rw_rebound_batch` accepts (more is `RW_INVALID_PARAMETER`): far above
/// the cores of any node a CFD rank runs on, far below what exhausts a process's threads.
pub const RW_MAX_THREADS: i32 = 1024;

/// Ideally elastic, frictionless collisions (Radenkovic & Simonin 2021, Sec. 3.1).
pub const RW_LAW_ELASTIC: i32 = 0;
/// Sommerfeld–Huber restitution and friction (Radenkovic & Simonin 2021, Eqs. 36–42).
pub const RW_LAW_SOMMERFELD_HUBER: i32 = 1;
/// No preset: every Sommerfeld–Huber parameter is given.
pub const RW_PRESET_NONE: i32 = 0;
/// Glass beads on stainless steel (Laín & Sommerfeld 2008 fit; parameters left NaN take it).
pub const RW_PRESET_GLASS_STEEL: i32 = 1;

/// Radenkovic & Simonin 2021 (the default rough-wall model).
pub const RW_MODEL_RADENKOVIC_SIMONIN_2021: i32 = 0;
/// Sommerfeld & Huber 1999: isotropic, shadow effect, repeated hits.
pub const RW_MODEL_SOMMERFELD_HUBER_1999: i32 = 1;
/// The impact angle perturbed in the incident plane (OpenFOAM forks).
pub const RW_MODEL_GAUSSIAN_ANGLE: i32 = 2;
/// A Gaussian tilt with a uniform azimuth (LIGGGHTS-PFM).
pub const RW_MODEL_GAUSSIAN_TILT: i32 = 3;
/// The normal rotated by two shadow-weighted Gaussian angles (ELEXI).
pub const RW_MODEL_NORMAL_PERTURBATION: i32 = 4;
/// The paper's virtual walls with an escape law calibrated on the deterministic simulation,
/// multiple collisions followed (`escape_table_csv`; NULL: the built-in table).
pub const RW_MODEL_CALIBRATED: i32 = 5;
/// The rebound law measured on the wall itself (a scan's in-place deterministic reference),
/// from the table `rebound scan --measured-wall` writes (`wall_table_text`, required).
pub const RW_MODEL_MEASURED_WALL: i32 = 6;

/// What a wall handle is built from. Start from `rw_wall_params_default` and set fields.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct rw_wall_params {
    /// Δξ: standard deviation (degrees) of the wall normal's angle along the lay direction
    /// (Radenkovic & Simonin 2021, Eq. 15): 0 … 20 (beyond 7.5 the message holds a warning).
    pub delta_xi_deg: f64,
    /// Δζ: standard deviation (degrees) of the wall normal's angle across the lay direction
    /// (Radenkovic & Simonin 2021, Eq. 15): 0 … 20, 0 for 2-D roughness (beyond 7.5 the
    /// message holds a warning).
    pub delta_zeta_deg: f64,
    /// `RW_LAW_ELASTIC` or `RW_LAW_SOMMERFELD_HUBER`.
    pub law: i32,
    /// `RW_PRESET_NONE` or `RW_PRESET_GLASS_STEEL` (Sommerfeld–Huber only).
    pub preset: i32,
    /// Sommerfeld–Huber `e_h`: the restitution coefficient at impact angles beyond
    /// `alpha_e_deg` (Radenkovic & Simonin 2021, Eq. 36), in (0, 1]. NaN: the preset's value;
    /// must be NaN with `RW_LAW_ELASTIC`.
    pub e_h: f64,
    /// Sommerfeld–Huber `α_e` (degrees): the impact angle up to which the restitution
    /// coefficient falls linearly from 1 to `e_h` (Radenkovic & Simonin 2021, Eq. 36), in
    /// (0, 90]. NaN: the preset's value; must be NaN with `RW_LAW_ELASTIC`.
    pub alpha_e_deg: f64,
    /// Sommerfeld–Huber `μ_0`: the friction coefficient at grazing incidence (impact angle 0;
    /// Radenkovic & Simonin 2021, Eq. 37 as corrected), in [0, 2]. NaN: the preset's value;
    /// must be NaN with `RW_LAW_ELASTIC`.
    pub mu_0: f64,
    /// Sommerfeld–Huber `μ_h`: the friction coefficient at impact angles beyond
    /// `alpha_mu_deg` (Radenkovic & Simonin 2021, Eq. 37 as corrected), in [0, 2]. NaN: the
    /// preset's value; must be NaN with `RW_LAW_ELASTIC`.
    pub mu_h: f64,
    /// Sommerfeld–Huber `α_μ` (degrees): the impact angle up to which the friction
    /// coefficient goes linearly from `mu_0` to `mu_h` (Radenkovic & Simonin 2021, Eq. 37 as
    /// corrected), in (0, 90]. NaN: the preset's value; must be NaN with `RW_LAW_ELASTIC`.
    pub alpha_mu_deg: f64,
    /// ψ of the single-collision probability (Eq. 34), in [0.01, 100]; 2 in the paper.
    pub psi: f64,
    /// Seed of every hit's random stream, with (particle id, collision index).
    pub seed: u64,
    /// The rough-wall model: `RW_MODEL_RADENKOVIC_SIMONIN_2021` (default) …
    /// `RW_MODEL_CALIBRATED`.
    pub model: i32,
    /// The isotropic models' roughness angle Δγ (degrees, 0 … 20); NaN: `(Δξ + Δζ)/2`.
    pub delta_gamma_deg: f64,
    /// `RW_MODEL_CALIBRATED` only: the escape table as the NUL-terminated text
    /// `rebound calibrate` writes (`escape_table.csv`); NULL: the built-in table. The
    /// handle keeps its own copy (the text may be freed after `rw_wall_new`). A process keeps
    /// each distinct table for its life, at most 16 besides the built-in one (about 1.4 MB
    /// each): a 17th is `RW_INVALID_PARAMETER`.
    pub escape_table_csv: *const std::os::raw::c_char,
    /// `RW_MODEL_MEASURED_WALL` only, and required there: the wall's table as the
    /// NUL-terminated text `rebound scan --measured-wall` writes (`measured_wall_*.txt`,
    /// named by the wall card's row). The handle keeps its own copy; a process keeps each
    /// distinct table for its life, at most 16 (4–18 MB each). The deviations are then
    /// the table's (`delta_xi_deg`, `delta_zeta_deg` are not used), and the sign of
    /// `rw_hit.lay` matters: a measured wall need not be its own mirror image.
    pub wall_table_text: *const std::os::raw::c_char,
}

/// One particle–wall hit, global axes, SI units.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct rw_hit {
    /// Particle velocity (m/s, global axes) before the hit, not relative to the wall.
    pub velocity: [f64; 3],
    /// Particle angular velocity (rad/s, global axes) before the hit.
    pub spin: [f64; 3],
    /// Face normal, either orientation, any non-zero length (one of unit length to
    /// round-off is used as given, as the host's own rebound uses it).
    pub normal: [f64; 3],
    /// The wall's lay direction (that of Δξ), projected onto the wall plane.
    pub lay: [f64; 3],
    /// Velocity of the wall (m/s).
    pub wall_velocity: [f64; 3],
    /// Particle diameter (m), ≥ 0.
    pub diameter: f64,
    /// The first part of the key of the hit's random stream (with the wall's `seed` and
    /// `collision_index`): the particle's identifier. The same key gives the same rebound on
    /// any rank, so use an identifier that is unique and does not change across ranks.
    pub particle_id: u64,
    /// The second part of the stream's key: the index of this hit among the particle's wall
    /// hits (e.g. a per-particle counter), so that successive hits draw different walls.
    pub collision_index: u64,
}

/// The rebound of a hit.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct rw_result {
    /// Rebound velocity (m/s, global axes, wall velocity added back). When the particle is
    /// returned unchanged (`status` not `RW_OK`): its incident velocity, non-finite
    /// components as 0.
    pub velocity: [f64; 3],
    /// Rebound angular velocity (rad/s, global axes). When the particle is returned
    /// unchanged: its incident angular velocity, non-finite components as 0.
    pub spin: [f64; 3],
    /// Inclination γ (rad) of the virtual wall element that produced the rebound, in the
    /// incident plane (Radenkovic & Simonin 2021, Eq. 20); 0 for a smooth wall or a particle
    /// returned unchanged.
    pub gamma: f64,
    /// Inclination γ* (rad) of that wall element normal to the incident plane (Radenkovic &
    /// Simonin 2021, Eq. 21); 0 for a smooth wall or a particle returned unchanged.
    pub gamma_star: f64,
    /// Candidate walls drawn (≥ 1 for a rebound).
    pub candidate_walls: u32,
    /// `RW_OK`, `RW_NOT_APPROACHING` or `RW_INVALID_INPUT`.
    pub status: i32,
}

/// `n` hits in struct-of-arrays form. Inputs marked "may be NULL" default to zero. Output
/// arrays may be the input arrays (in-place update); those marked "may be NULL" are not
/// written.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct rw_batch {
    /// Number of hits: every array that is not NULL holds `n` elements. With `n` = 0
    /// nothing is read or written and the arrays may all be NULL.
    pub n: usize,
    /// x components of the particle velocities (m/s, global axes, before the hit, not
    /// relative to the wall), as `rw_hit.velocity[0]`; required.
    pub ux: *const f64,
    /// y components of the particle velocities (m/s, global axes); required.
    pub uy: *const f64,
    /// z components of the particle velocities (m/s, global axes); required.
    pub uz: *const f64,
    /// x components of the particle angular velocities (rad/s, global axes), as
    /// `rw_hit.spin[0]`; may be NULL (then 0).
    pub wx: *const f64,
    /// y components of the particle angular velocities (rad/s, global axes); may be NULL
    /// (then 0).
    pub wy: *const f64,
    /// z components of the particle angular velocities (rad/s, global axes); may be NULL
    /// (then 0).
    pub wz: *const f64,
    /// x components of the face normals (either orientation, any non-zero length), as
    /// `rw_hit.normal[0]`; required.
    pub nx: *const f64,
    /// y components of the face normals (either orientation, any non-zero length);
    /// required.
    pub ny: *const f64,
    /// z components of the face normals (either orientation, any non-zero length);
    /// required.
    pub nz: *const f64,
    /// x components of the lay directions (that of Δξ, projected onto the wall plane), as
    /// `rw_hit.lay[0]`; required.
    pub lx: *const f64,
    /// y components of the lay directions (that of Δξ, projected onto the wall plane);
    /// required.
    pub ly: *const f64,
    /// z components of the lay directions (that of Δξ, projected onto the wall plane);
    /// required.
    pub lz: *const f64,
    /// x components of the wall velocities (m/s, global axes), as `rw_hit.wall_velocity[0]`;
    /// may be NULL (then 0).
    pub vx: *const f64,
    /// y components of the wall velocities (m/s, global axes); may be NULL (then 0).
    pub vy: *const f64,
    /// z components of the wall velocities (m/s, global axes); may be NULL (then 0).
    pub vz: *const f64,
    /// Diameters (m).
    pub diameter: *const f64,
    /// First parts of the random streams' keys, the particle identifiers, as
    /// `rw_hit.particle_id`; required.
    pub particle_id: *const u64,
    /// Second parts of the random streams' keys, the hit indices, as
    /// `rw_hit.collision_index`; required.
    pub collision_index: *const u64,
    /// x components of the rebound velocities (m/s, global axes), as `rw_result.velocity[0]`;
    /// required (may be `ux`, for an in-place update).
    pub out_ux: *mut f64,
    /// y components of the rebound velocities (m/s, global axes); required (may be `uy`).
    pub out_uy: *mut f64,
    /// z components of the rebound velocities (m/s, global axes); required (may be `uz`).
    pub out_uz: *mut f64,
    /// x components of the rebound angular velocities (rad/s, global axes), as
    /// `rw_result.spin[0]`; may be NULL (not written).
    pub out_wx: *mut f64,
    /// y components of the rebound angular velocities (rad/s, global axes); may be NULL
    /// (not written).
    pub out_wy: *mut f64,
    /// z components of the rebound angular velocities (rad/s, global axes); may be NULL
    /// (not written).
    pub out_wz: *mut f64,
    /// γ (rad), as `rw_result.gamma`; may be NULL (not written).
    pub out_gamma: *mut f64,
    /// γ* (rad), as `rw_result.gamma_star`; may be NULL (not written).
    pub out_gamma_star: *mut f64,
    /// Candidate walls drawn, as `rw_result.candidate_walls`; may be NULL (not written).
    pub out_candidate_walls: *mut u32,
    /// Status of each hit.
    pub out_status: *mut i32,
}

/// An immutable wall handle, safe to share between threads.
pub struct rw_wall {
    model: WallModel,
}

/// Runs `f`, turning a panic into `RW_INTERNAL_ERROR`.
fn guarded(f: impl FnOnce() -> i32) -> i32 {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(RW_INTERNAL_ERROR)
}

/// Unit tests only (never in the library): a hit with this particle id, or a wall with this
/// seed, panics inside the entry point, standing in for a bug, to check that the panic is
/// caught at the boundary.
#[cfg(test)]
const FORCED_PANIC_KEY: u64 = 0xdead_beef_0bad_f00d;

/// The rebound of one hit: what `rw_rebound` and every hit of `rw_rebound_batch` run.
fn rebound_one(model: &WallModel, hit: &Hit) -> HitOutcome {
    #[cfg(test)]
    assert_ne!(
        hit.particle_id, FORCED_PANIC_KEY,
        "a panic forced by a test"
    );
    model.rebound(hit)
}

/// Copies `msg` into the caller's buffer, NUL-terminated, cut at a character boundary.
///
/// # Safety
/// `buf` is NULL or points to `len` writable bytes.
unsafe fn write_message(buf: *mut c_char, len: usize, msg: &str) {
    if buf.is_null() || len == 0 {
        return;
    }
    let mut end = msg.len().min(len - 1);
    while !msg.is_char_boundary(end) {
        end -= 1;
    }
    std::ptr::copy_nonoverlapping(msg.as_ptr(), buf.cast::<u8>(), end);
    *buf.add(end) = 0;
}

/// Fills `params` with the defaults: a smooth elastic wall (Δξ = Δζ = 0), no preset,
/// Sommerfeld–Huber parameters NaN (taken from the preset), ψ = 2, seed 0.
///
/// # Safety
/// `params` is NULL or points to a writable `rw_wall_params`.
#[no_mangle]
pub unsafe extern "C" fn rw_wall_params_default(params: *mut rw_wall_params) -> i32 {
    if params.is_null() {
        return RW_NULL_POINTER;
    }
    guarded(|| {
        params.write(rw_wall_params {
            delta_xi_deg: 0.0,
            delta_zeta_deg: 0.0,
            law: RW_LAW_ELASTIC,
            preset: RW_PRESET_NONE,
            e_h: f64::NAN,
            alpha_e_deg: f64::NAN,
            mu_0: f64::NAN,
            mu_h: f64::NAN,
            alpha_mu_deg: f64::NAN,
            psi: 2.0,
            seed: 0,
            model: RW_MODEL_RADENKOVIC_SIMONIN_2021,
            delta_gamma_deg: f64::NAN,
            escape_table_csv: std::ptr::null(),
            wall_table_text: std::ptr::null(),
        });
        RW_OK
    })
}

fn wall_params(p: &rw_wall_params) -> Result<WallParams, String> {
    let given = |x: f64| (!x.is_nan()).then_some(x);
    let model_name = usize::try_from(p.model)
        .ok()
        .and_then(|i| crate::models::AnyModel::NAMES.get(i).copied())
        .ok_or_else(|| {
            let names = crate::models::AnyModel::NAMES;
            let constant =
                |name: &str| format!("RW_MODEL_{}", name.to_uppercase().replace('-', "_"));
            format!(
                "invalid `model` = {}: allowed {} (0) to {} ({})",
                p.model,
                constant(names[0]),
                constant(names[names.len() - 1]),
                names.len() - 1
            )
        })?;
    let model = match p.law {
        RW_LAW_ELASTIC => "elastic",
        RW_LAW_SOMMERFELD_HUBER => "sommerfeld-huber",
        other => {
            return Err(format!(
                "invalid `law` = {other}: allowed RW_LAW_ELASTIC (0) or RW_LAW_SOMMERFELD_HUBER (1)"
            ))
        }
    };
    let preset = match p.preset {
        RW_PRESET_NONE => None,
        RW_PRESET_GLASS_STEEL => Some("glass-steel".to_string()),
        other => {
            return Err(format!(
            "invalid `preset` = {other}: allowed RW_PRESET_NONE (0) or RW_PRESET_GLASS_STEEL (1)"
        ))
        }
    };
    Ok(WallParams {
        delta_xi_deg: p.delta_xi_deg,
        delta_zeta_deg: p.delta_zeta_deg,
        collision: CollisionParams {
            model: Some(model.into()),
            preset,
            e_h: given(p.e_h),
            alpha_e_deg: given(p.alpha_e_deg),
            mu_0: given(p.mu_0),
            mu_h: given(p.mu_h),
            alpha_mu_deg: given(p.alpha_mu_deg),
        },
        psi: Some(p.psi),
        seed: p.seed,
        model: Some(model_name.into()),
        delta_gamma_deg: given(p.delta_gamma_deg),
        escape_table: if p.escape_table_csv.is_null() {
            None
        } else {
            // SAFETY: a non-NULL `escape_table_csv` is a NUL-terminated string (header).
            let text = unsafe { std::ffi::CStr::from_ptr(p.escape_table_csv) };
            Some(
                text.to_str()
                    .map_err(|_| "`stochastic.escape_table`: not UTF-8 text".to_string())?
                    .to_string(),
            )
        },
        wall_table: if p.wall_table_text.is_null() {
            None
        } else {
            // SAFETY: a non-NULL `wall_table_text` is a NUL-terminated string (header).
            let text = unsafe { std::ffi::CStr::from_ptr(p.wall_table_text) };
            Some(
                text.to_str()
                    .map_err(|_| "`stochastic.wall_table`: not UTF-8 text".to_string())?
                    .to_string(),
            )
        },
    })
}

/// Builds a wall handle into `*wall`. On `RW_INVALID_PARAMETER`, `message` (if not NULL)
/// holds one line naming the parameter, its value and what is allowed, and `*wall` is NULL;
/// on `RW_OK` it holds the warnings, if any ("" otherwise). Free the handle with
/// `rw_wall_free`.
///
/// # Safety
/// `params` and `wall` are NULL or valid; `message` is NULL or points to `message_len`
/// writable bytes.
#[no_mangle]
pub unsafe extern "C" fn rw_wall_new(
    params: *const rw_wall_params,
    wall: *mut *mut rw_wall,
    message: *mut c_char,
    message_len: usize,
) -> i32 {
    if params.is_null() || wall.is_null() {
        write_message(
            message,
            message_len,
            "a NULL pointer was passed to rw_wall_new",
        );
        return RW_NULL_POINTER;
    }
    guarded(|| {
        wall.write(std::ptr::null_mut());
        #[cfg(test)]
        assert_ne!((*params).seed, FORCED_PANIC_KEY, "a panic forced by a test");
        let built =
            wall_params(&*params).and_then(|p| WallModel::new(&p).map_err(|e| e.to_string()));
        match built {
            Ok((model, warnings)) => {
                write_message(message, message_len, &warnings.join("; "));
                wall.write(Box::into_raw(Box::new(rw_wall { model })));
                RW_OK
            }
            Err(msg) => {
                write_message(message, message_len, &msg);
                RW_INVALID_PARAMETER
            }
        }
    })
}

/// Frees a wall handle (NULL is allowed).
///
/// # Safety
/// `wall` is NULL or a handle from `rw_wall_new` not freed before.
#[no_mangle]
pub unsafe extern "C" fn rw_wall_free(wall: *mut rw_wall) {
    if !wall.is_null() {
        let _ = catch_unwind(AssertUnwindSafe(|| drop(Box::from_raw(wall))));
    }
}

fn result_of(o: &HitOutcome) -> rw_result {
    rw_result {
        velocity: o.velocity,
        spin: o.spin,
        gamma: o.gamma,
        gamma_star: o.gamma_star,
        candidate_walls: o.candidate_walls,
        status: o.status as i32,
    }
}

fn hit_of(h: &rw_hit) -> Hit {
    Hit {
        velocity: h.velocity,
        spin: h.spin,
        normal: h.normal,
        lay: h.lay,
        wall_velocity: h.wall_velocity,
        diameter_m: h.diameter,
        particle_id: h.particle_id,
        collision_index: h.collision_index,
    }
}

/// The rebound of one hit, into `*result`. Returns the hit's status (also in
/// `result->status`): `RW_OK` (a rebound), `RW_NOT_APPROACHING` or `RW_INVALID_INPUT` (the
/// particle is returned unchanged), or `RW_NULL_POINTER` (nothing written). Allocates
/// nothing, starts no thread.
///
/// # Safety
/// `wall` is NULL or a live handle; `hit` is NULL or valid; `result` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn rw_rebound(
    wall: *const rw_wall,
    hit: *const rw_hit,
    result: *mut rw_result,
) -> i32 {
    if wall.is_null() || hit.is_null() || result.is_null() {
        return RW_NULL_POINTER;
    }
    guarded(|| {
        let r = result_of(&rebound_one(&(*wall).model, &hit_of(&*hit)));
        result.write(r);
        r.status
    })
}

/// Impact angle (rad, 0 to π/2) of `hit`'s incident velocity (relative to the wall) on the
/// wall element that produced `result`: the facet the particle struck, whose angle erosion
/// laws (Finnie, Oka, DNV) take, rather than the mean wall's. It follows from
/// `result->gamma`, `result->gamma_star` and the incident direction in the wall's frame of
/// `hit->normal` and `hit->lay` (Radenkovic & Simonin 2021, Eqs. 10, 20–23). On a smooth
/// wall it is the angle to the wall. 0 when `result->status` is not `RW_OK` or a pointer is
/// NULL. Allocates nothing; never NaN.
///
/// # Safety
/// `hit` and `result` are NULL or valid.
#[no_mangle]
pub unsafe extern "C" fn rw_element_impact_angle(
    hit: *const rw_hit,
    result: *const rw_result,
) -> f64 {
    if hit.is_null() || result.is_null() {
        return 0.0;
    }
    let (h, r) = (hit_of(&*hit), *result);
    if r.status != RW_OK {
        return 0.0;
    }
    catch_unwind(AssertUnwindSafe(|| {
        crate::wall_model::element_impact_angle(&h, r.gamma, r.gamma_star)
    }))
    .unwrap_or(0.0)
}

/// The carrier fluid and a particle where the particle is, for the between-hit laws
/// `rw_saffman_mei_lift`, `rw_magnus_lift` and `rw_spin_relax` (global axes, SI units;
/// `roughwall::carrier`).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct rw_fluid_point {
    /// Fluid density (kg/m³, > 0).
    pub rho_f: f64,
    /// Fluid dynamic viscosity (Pa s, > 0).
    pub mu_f: f64,
    /// Particle density (kg/m³, > 0).
    pub rho_p: f64,
    /// Particle diameter (m, > 0).
    pub d_p: f64,
    /// The fluid's velocity as the particle sees it minus the particle's (m/s).
    pub slip: [f64; 3],
    /// The fluid's vorticity, the curl of its velocity (1/s): the fluid turns at half of it.
    pub vorticity: [f64; 3],
    /// The particle's angular velocity (rad/s).
    pub spin: [f64; 3],
}

impl From<rw_fluid_point> for crate::carrier::FluidPoint {
    fn from(p: rw_fluid_point) -> Self {
        Self {
            rho_f: p.rho_f,
            mu_f: p.mu_f,
            rho_p: p.rho_p,
            d_p: p.d_p,
            slip: p.slip,
            vorticity: p.vorticity,
            spin: p.spin,
        }
    }
}

/// Writes `law(point)` into `out` when `point` is valid; zeros and a status otherwise.
///
/// # Safety
/// `point` and `out` are NULL or valid.
unsafe fn carrier_call(
    point: *const rw_fluid_point,
    out: *mut f64,
    law: impl Fn(&crate::carrier::FluidPoint) -> [f64; 3],
    otherwise: impl Fn(&crate::carrier::FluidPoint) -> [f64; 3],
) -> i32 {
    if point.is_null() || out.is_null() {
        return RW_NULL_POINTER;
    }
    let p = crate::carrier::FluidPoint::from(*point);
    let (status, v) = if p.is_valid() {
        match catch_unwind(AssertUnwindSafe(|| law(&p))) {
            Ok(v) if v.iter().all(|x| x.is_finite()) => (RW_OK, v),
            Ok(_) => (RW_INVALID_INPUT, otherwise(&p)),
            Err(_) => (RW_INTERNAL_ERROR, otherwise(&p)),
        }
    } else {
        (RW_INVALID_INPUT, otherwise(&p))
    };
    std::ptr::copy_nonoverlapping(v.as_ptr(), out, 3);
    status
}

/// The Saffman–Mei shear-lift acceleration (m/s², force over the particle's mass) on the
/// particle of `point`, into `acceleration[0..3]`: Saffman's lift with Mei's (1992)
/// finite-Reynolds correction (`roughwall::carrier`; docs/physics.md §8a). A CFD
/// code adds it to gravity in its particle equation. `RW_OK`; `RW_INVALID_INPUT` (zeros
/// written) for a non-finite number or a non-positive property; `RW_NULL_POINTER`.
///
/// # Safety
/// `point` is NULL or valid; `acceleration` is NULL or holds 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn rw_saffman_mei_lift(
    point: *const rw_fluid_point,
    acceleration: *mut f64,
) -> i32 {
    carrier_call(
        point,
        acceleration,
        crate::carrier::saffman_mei_lift,
        |_| [0.0; 3],
    )
}

/// The Magnus (rotational) lift acceleration (m/s²) on the particle of `point`, spinning at
/// `point->spin` relative to the fluid's rotation, into `acceleration[0..3]`, with
/// Oesterlé & Bui Dinh's (1998) coefficient (docs/physics.md §8a). Statuses
/// as `rw_saffman_mei_lift`.
///
/// # Safety
/// `point` is NULL or valid; `acceleration` is NULL or holds 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn rw_magnus_lift(
    point: *const rw_fluid_point,
    acceleration: *mut f64,
) -> i32 {
    carrier_call(point, acceleration, crate::carrier::magnus_lift, |_| {
        [0.0; 3]
    })
}

/// The particle's angular velocity (rad/s) after `dt` seconds in the fluid of `point`,
/// into `spin[0..3]` (which may be `point->spin`): the rotational drag of Dennis, Singh &
/// Ingham (1980) relaxes it towards the fluid's rotation (docs/physics.md §8a), at the rate
/// of the start of the step (exact in the Stokes regime). Carry
/// `rw_result.spin` with this between hits and give it back in the next `rw_hit.spin`.
/// `RW_INVALID_INPUT` (the spin written back unchanged, non-finite components as 0) for a
/// non-finite number, a non-positive property or a negative `dt`.
///
/// # Safety
/// `point` is NULL or valid; `spin` is NULL or holds 3 doubles.
#[no_mangle]
pub unsafe extern "C" fn rw_spin_relax(
    point: *const rw_fluid_point,
    dt: f64,
    spin: *mut f64,
) -> i32 {
    let unchanged =
        |p: &crate::carrier::FluidPoint| p.spin.map(|x| if x.is_finite() { x } else { 0.0 });
    if dt.is_finite() && dt >= 0.0 {
        carrier_call(
            point,
            spin,
            |p| crate::carrier::relaxed_spin(p, dt),
            unchanged,
        )
    } else {
        carrier_call(point, spin, unchanged, unchanged).max(RW_INVALID_INPUT)
    }
}

/// Raw pointers of a batch, shareable between the threads of one call: each thread touches
/// only its own indices.
#[derive(Clone, Copy)]
struct Batch(rw_batch);
unsafe impl Send for Batch {}
unsafe impl Sync for Batch {}

impl Batch {
    /// Hit `i`.
    ///
    /// # Safety
    /// The required arrays hold `n` elements; `i < n`.
    unsafe fn hit(&self, i: usize) -> Hit {
        let b = &self.0;
        let opt = |p: *const f64| if p.is_null() { 0.0 } else { p.add(i).read() };
        Hit {
            velocity: [b.ux.add(i).read(), b.uy.add(i).read(), b.uz.add(i).read()],
            spin: [opt(b.wx), opt(b.wy), opt(b.wz)],
            normal: [b.nx.add(i).read(), b.ny.add(i).read(), b.nz.add(i).read()],
            lay: [b.lx.add(i).read(), b.ly.add(i).read(), b.lz.add(i).read()],
            wall_velocity: [opt(b.vx), opt(b.vy), opt(b.vz)],
            diameter_m: b.diameter.add(i).read(),
            particle_id: b.particle_id.add(i).read(),
            collision_index: b.collision_index.add(i).read(),
        }
    }

    /// Writes the outcome of hit `i`.
    ///
    /// # Safety
    /// As [`Batch::hit`], for the output arrays.
    unsafe fn put(&self, i: usize, o: &HitOutcome) {
        let b = &self.0;
        let put = |p: *mut f64, v: f64| {
            if !p.is_null() {
                p.add(i).write(v)
            }
        };
        b.out_ux.add(i).write(o.velocity[0]);
        b.out_uy.add(i).write(o.velocity[1]);
        b.out_uz.add(i).write(o.velocity[2]);
        put(b.out_wx, o.spin[0]);
        put(b.out_wy, o.spin[1]);
        put(b.out_wz, o.spin[2]);
        put(b.out_gamma, o.gamma);
        put(b.out_gamma_star, o.gamma_star);
        if !b.out_candidate_walls.is_null() {
            b.out_candidate_walls.add(i).write(o.candidate_walls);
        }
        b.out_status.add(i).write(o.status as i32);
    }

    fn required_present(&self) -> bool {
        let b = &self.0;
        let inputs = [
            b.ux, b.uy, b.uz, b.nx, b.ny, b.nz, b.lx, b.ly, b.lz, b.diameter,
        ];
        let outputs = [b.out_ux, b.out_uy, b.out_uz];
        inputs.iter().all(|p| !p.is_null())
            && outputs.iter().all(|p| !p.is_null())
            && !b.particle_id.is_null()
            && !b.collision_index.is_null()
            && !b.out_status.is_null()
    }
}

/// The rebounds of `batch->n` hits (each exactly as `rw_rebound` gives it, whatever the
/// thread count), per-hit statuses in `batch->out_status`: bad hits get their status
/// (`RW_INVALID_INPUT`, …) and finite outputs, the others are rebounded. `threads` ≤ 1
/// runs in the calling thread; 2 … `RW_MAX_THREADS` splits the hits over that many
/// threads (at most one per hit), started and joined in this call (a thread the system
/// refuses to start leaves its share to the calling thread). Returns `RW_OK`;
/// `RW_NULL_POINTER` when `wall`, `batch` or a required array is NULL, and
/// `RW_INVALID_PARAMETER` when `threads` > `RW_MAX_THREADS`: then nothing is written.
///
/// # Safety
/// `wall` is NULL or a live handle; `batch` is NULL or valid, with every non-NULL array
/// holding `n` elements.
#[no_mangle]
pub unsafe extern "C" fn rw_rebound_batch(
    wall: *const rw_wall,
    batch: *const rw_batch,
    threads: i32,
) -> i32 {
    if wall.is_null() || batch.is_null() {
        return RW_NULL_POINTER;
    }
    let b = Batch(*batch);
    if b.0.n > 0 && !b.required_present() {
        return RW_NULL_POINTER;
    }
    if threads > RW_MAX_THREADS {
        return RW_INVALID_PARAMETER;
    }
    let model = (*wall).model;
    guarded(|| {
        let n = b.0.n;
        let run = |lo: usize, hi: usize| {
            for i in lo..hi {
                b.put(i, &rebound_one(&model, &b.hit(i)));
            }
        };
        let t = (threads.max(1) as usize).min(n.max(1));
        if t == 1 {
            run(0, n);
        } else {
            let chunk = n.div_ceil(t);
            std::thread::scope(|s| {
                let mut started = Vec::with_capacity(t);
                for k in 0..t {
                    let (lo, hi) = (k * chunk, ((k + 1) * chunk).min(n));
                    if lo >= hi {
                        continue;
                    }
                    let run = &run;
                    match std::thread::Builder::new().spawn_scoped(s, move || run(lo, hi)) {
                        Ok(thread) => started.push(thread),
                        // No thread to be had (a limit of the system): this share runs here.
                        Err(_) => run(lo, hi),
                    }
                }
                // Joined, not only waited for (as the scope's end would): the threads have
                // exited when the call returns. A panic in one is re-raised here.
                for thread in started {
                    if let Err(panic) = thread.join() {
                        std::panic::resume_unwind(panic);
                    }
                }
            });
        }
        RW_OK
    })
}

/// The library's version, e.g. "0.1.0" (a static string).
#[no_mangle]
pub extern "C" fn rw_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

/// A short description of a status code (a static string).
#[no_mangle]
pub extern "C" fn rw_status_string(status: i32) -> *const c_char {
    let s: &'static str = match status {
        RW_OK => "ok\0",
        RW_NOT_APPROACHING => "the particle does not move across the wall\0",
        RW_INVALID_INPUT => "invalid input: non-finite number, zero normal, lay parallel to the normal or negative diameter\0",
        RW_INVALID_PARAMETER => "invalid wall parameter\0",
        RW_NULL_POINTER => "a required pointer is NULL\0",
        RW_INTERNAL_ERROR => "internal error in roughwall (please report)\0",
        _ => "unknown status\0",
    };
    s.as_ptr().cast()
}

const _: () = {
    // The C status codes are the wall model's.
    assert!(HitStatus::Rebound as i32 == RW_OK);
    assert!(HitStatus::NotApproaching as i32 == RW_NOT_APPROACHING);
    assert!(HitStatus::InvalidInput as i32 == RW_INVALID_INPUT);
};

#[cfg(test)]
mod tests {
    use super::*;

    fn params() -> rw_wall_params {
        let mut p = std::mem::MaybeUninit::<rw_wall_params>::uninit();
        assert_eq!(unsafe { rw_wall_params_default(p.as_mut_ptr()) }, RW_OK);
        let mut p = unsafe { p.assume_init() };
        p.delta_xi_deg = 3.8;
        p.delta_zeta_deg = 7.5;
        p.law = RW_LAW_SOMMERFELD_HUBER;
        p.preset = RW_PRESET_GLASS_STEEL;
        p.seed = 3;
        p
    }

    fn wall(p: &rw_wall_params) -> (i32, *mut rw_wall, String) {
        let mut w = std::ptr::null_mut();
        let mut msg = [0 as c_char; 256];
        let s = unsafe { rw_wall_new(p, &mut w, msg.as_mut_ptr(), msg.len()) };
        let text = unsafe { std::ffi::CStr::from_ptr(msg.as_ptr()) }
            .to_string_lossy()
            .into_owned();
        (s, w, text)
    }

    fn hit(i: u64) -> rw_hit {
        rw_hit {
            velocity: [5.0 + 0.01 * i as f64, -1.5, -2.0],
            spin: [0.0; 3],
            normal: [0.0, -1.0, 0.0],
            lay: [1.0, 0.0, 0.0],
            wall_velocity: [0.0; 3],
            diameter: 500e-6,
            particle_id: i,
            collision_index: 0,
        }
    }

    #[test]
    fn the_c_call_is_the_rust_call() {
        let (s, w, msg) = wall(&params());
        assert_eq!((s, msg.as_str()), (RW_OK, ""));
        let model = unsafe { &*w }.model;
        for i in 0..100 {
            let h = hit(i);
            let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
            let status = unsafe { rw_rebound(w, &h, r.as_mut_ptr()) };
            let r = unsafe { r.assume_init() };
            let o = model.rebound(&hit_of(&h));
            assert_eq!(status, RW_OK);
            assert_eq!(r.velocity.map(f64::to_bits), o.velocity.map(f64::to_bits));
            assert_eq!((r.gamma, r.candidate_walls), (o.gamma, o.candidate_walls));
        }
        unsafe { rw_wall_free(w) };
    }

    /// On an ideally elastic wall the rebound is the mirror image of the incident velocity in
    /// the element struck, so that element's impact angle is half the turn of the velocity:
    /// `sin α = |u⁺ − u⁻| / (2|u|)`, whatever the host's normal orientation and the lay.
    /// A smooth wall gives the angle to the wall; no rebound or a NULL pointer gives 0.
    #[test]
    fn the_element_impact_angle_is_half_the_turn_of_an_elastic_rebound() {
        let mut p = params();
        p.law = RW_LAW_ELASTIC;
        p.preset = RW_PRESET_NONE;
        let (s, w, _) = wall(&p);
        assert_eq!(s, RW_OK);
        let mut tilted = 0;
        for i in 0..500 {
            let mut h = hit(i);
            h.lay = [(i as f64).cos(), 0.3, (i as f64).sin()];
            if i % 2 == 1 {
                h.normal = [0.0, 2.0, 0.0];
            }
            let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
            assert_eq!(unsafe { rw_rebound(w, &h, r.as_mut_ptr()) }, RW_OK);
            let r = unsafe { r.assume_init() };
            let a = unsafe { rw_element_impact_angle(&h, &r) };
            let (u_in, u_out) = (
                nalgebra::Vector3::from(h.velocity),
                nalgebra::Vector3::from(r.velocity),
            );
            let expect = ((u_out - u_in).norm() / (2.0 * u_in.norm())).asin();
            assert!((a - expect).abs() < 1e-9, "{i}: {a} vs {expect}");
            let mean_wall = (1.5 / u_in.norm()).asin();
            tilted += usize::from((a - mean_wall).abs() > 1e-3);
        }
        // The rough wall's elements are not the mean wall.
        assert!(tilted > 400, "{tilted}");
        unsafe { rw_wall_free(w) };
        // A smooth wall: the angle to the wall.
        let (s, w, _) = wall(&{
            let mut p = p;
            p.delta_xi_deg = 0.0;
            p.delta_zeta_deg = 0.0;
            p
        });
        assert_eq!(s, RW_OK);
        let h = hit(1);
        let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
        assert_eq!(unsafe { rw_rebound(w, &h, r.as_mut_ptr()) }, RW_OK);
        let mut r = unsafe { r.assume_init() };
        let u = nalgebra::Vector3::from(h.velocity);
        let a = unsafe { rw_element_impact_angle(&h, &r) };
        assert!((a - (1.5 / u.norm()).asin()).abs() < 1e-15);
        assert_eq!(
            unsafe { rw_element_impact_angle(std::ptr::null(), &r) },
            0.0
        );
        r.status = RW_NOT_APPROACHING;
        assert_eq!(unsafe { rw_element_impact_angle(&h, &r) }, 0.0);
        unsafe { rw_wall_free(w) };
    }

    #[test]
    fn every_rough_wall_model_is_part_of_the_handle() {
        let mut first = Vec::new();
        use crate::models::RoughWallModel;
        for (i, name) in crate::models::AnyModel::NAMES.iter().enumerate() {
            let mut p = params();
            p.model = i as i32;
            let table =
                std::ffi::CString::new(crate::measured_wall::small_table().to_text()).unwrap();
            if i as i32 == RW_MODEL_MEASURED_WALL {
                p.wall_table_text = table.as_ptr();
            } else if !crate::models::AnyModel::with_defaults(name)
                .unwrap()
                .anisotropic()
            {
                p.delta_gamma_deg = 4.0;
            }
            let (s, w, msg) = wall(&p);
            assert_eq!((s, msg.as_str()), (RW_OK, ""), "{name}");
            let handle = unsafe { &*w }.model;
            assert_eq!(handle.model.name(), *name);
            // Twenty hits: two models may agree on one hit (e.g. the paper's and the
            // calibrated one when both accept the first wall element), not on all.
            let bits: Vec<[u64; 3]> = (0..20)
                .map(|i| {
                    let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
                    assert_eq!(unsafe { rw_rebound(w, &hit(i), r.as_mut_ptr()) }, RW_OK);
                    unsafe { r.assume_init() }.velocity.map(f64::to_bits)
                })
                .collect();
            first.push(bits);
            unsafe { rw_wall_free(w) };
        }
        let n = first.len();
        first.sort();
        first.dedup();
        assert_eq!(first.len(), n, "two models gave the same rebound");
        // The calibrated model's table travels with the handle, as text: the built-in
        // table's text is the NULL default; a bad text is a one-line refusal.
        let rebound_with = |table: Option<&std::ffi::CString>| {
            let mut p = params();
            p.model = RW_MODEL_CALIBRATED;
            p.escape_table_csv = table.map_or(std::ptr::null(), |t| t.as_ptr());
            let (s, w, msg) = wall(&p);
            if s != RW_OK {
                return Err(msg);
            }
            let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
            assert_eq!(unsafe { rw_rebound(w, &hit(3), r.as_mut_ptr()) }, RW_OK);
            unsafe { rw_wall_free(w) };
            Ok(unsafe { r.assume_init() }.velocity.map(f64::to_bits))
        };
        let builtin = std::ffi::CString::new(crate::calibrated::BUILTIN).unwrap();
        assert_eq!(rebound_with(None), rebound_with(Some(&builtin)));
        let bad = std::ffi::CString::new("alpha,beta\n").unwrap();
        let msg = rebound_with(Some(&bad)).unwrap_err();
        assert!(
            msg.contains("stochastic.escape_table") && !msg.contains('\n'),
            "{msg}"
        );
        // The measured-wall model needs its table; a bad one is a one-line refusal naming
        // the key.
        for (text, expect) in [
            (None, "needs `stochastic.wall_table`"),
            (
                Some("# roughwall measured-wall table v4\nsource = x\n"),
                "stochastic.wall_table",
            ),
            (Some("alpha,beta\n"), "not a measured-wall table"),
        ] {
            let mut p = params();
            p.model = RW_MODEL_MEASURED_WALL;
            let t = text.map(|t| std::ffi::CString::new(t).unwrap());
            p.wall_table_text = t.as_ref().map_or(std::ptr::null(), |t| t.as_ptr());
            let (s, w, msg) = wall(&p);
            assert_eq!(s, RW_INVALID_PARAMETER);
            assert!(w.is_null());
            assert!(msg.contains(expect) && !msg.contains('\n'), "{msg}");
        }
        for (model, dg, key) in [
            (9, f64::NAN, "model"),
            (2, -1.0, "delta_gamma_deg"),
            (0, 3.0, "delta_gamma_deg"),
        ] {
            let mut p = params();
            p.model = model;
            p.delta_gamma_deg = dg;
            let (s, w, msg) = wall(&p);
            assert_eq!(s, RW_INVALID_PARAMETER, "{msg}");
            assert!(
                w.is_null() && msg.contains(key) && !msg.contains('\n'),
                "{msg}"
            );
        }
    }

    #[test]
    fn bad_parameters_and_null_pointers_are_statuses_with_one_line() {
        let mut p = params();
        p.e_h = 1.5;
        let (s, w, msg) = wall(&p);
        assert_eq!(s, RW_INVALID_PARAMETER);
        assert!(w.is_null());
        assert!(
            msg.contains("collision.e_h") && !msg.contains('\n'),
            "{msg}"
        );
        let mut p = params();
        p.law = 7;
        assert!(wall(&p).2.contains("law"));
        let mut p = params();
        p.delta_zeta_deg = 12.0;
        let (s, w, msg) = wall(&p);
        assert_eq!(s, RW_OK);
        assert!(msg.contains("low-roughness"), "{msg}");
        let h = hit(0);
        let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
        unsafe {
            assert_eq!(
                rw_rebound(std::ptr::null(), &h, r.as_mut_ptr()),
                RW_NULL_POINTER
            );
            assert_eq!(
                rw_rebound(w, std::ptr::null(), r.as_mut_ptr()),
                RW_NULL_POINTER
            );
            assert_eq!(rw_rebound(w, &h, std::ptr::null_mut()), RW_NULL_POINTER);
            assert_eq!(
                rw_wall_params_default(std::ptr::null_mut()),
                RW_NULL_POINTER
            );
            let mut out = std::ptr::null_mut();
            assert_eq!(
                rw_wall_new(std::ptr::null(), &mut out, std::ptr::null_mut(), 0),
                RW_NULL_POINTER
            );
            assert_eq!(rw_rebound_batch(w, std::ptr::null(), 2), RW_NULL_POINTER);
            rw_wall_free(w);
            rw_wall_free(std::ptr::null_mut());
        }
        // A message buffer too small is cut, still NUL-terminated, at a character boundary.
        let mut buf = [1 as c_char; 5];
        unsafe { write_message(buf.as_mut_ptr(), buf.len(), "Δξ = −1") };
        let cut = unsafe { std::ffi::CStr::from_ptr(buf.as_ptr()) };
        assert!(std::str::from_utf8(cut.to_bytes()).is_ok());
    }

    #[test]
    fn the_batch_gives_the_single_calls_for_any_thread_count_and_in_place() {
        let (_, w, _) = wall(&params());
        let n = 1001;
        let hits: Vec<rw_hit> = (0..n as u64).map(hit).collect();
        let col = |f: &dyn Fn(&rw_hit) -> f64| hits.iter().map(f).collect::<Vec<f64>>();
        let (ux, uy, uz) = (
            col(&|h| h.velocity[0]),
            col(&|h| h.velocity[1]),
            col(&|h| h.velocity[2]),
        );
        let (nx, ny, nz) = (
            col(&|h| h.normal[0]),
            col(&|h| h.normal[1]),
            col(&|h| h.normal[2]),
        );
        let (lx, ly, lz) = (col(&|h| h.lay[0]), col(&|h| h.lay[1]), col(&|h| h.lay[2]));
        let d = col(&|h| h.diameter);
        let pid: Vec<u64> = hits.iter().map(|h| h.particle_id).collect();
        let cid = vec![0u64; n];
        let single: Vec<rw_result> = hits
            .iter()
            .map(|h| {
                let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
                unsafe { rw_rebound(w, h, r.as_mut_ptr()) };
                unsafe { r.assume_init() }
            })
            .collect();
        for threads in [1, 2, 3] {
            // In place: the velocity arrays are also the outputs.
            let (mut ox, mut oy, mut oz) = (ux.clone(), uy.clone(), uz.clone());
            let mut status = vec![-1i32; n];
            let mut gamma = vec![0.0; n];
            let b = rw_batch {
                n,
                ux: ox.as_ptr(),
                uy: oy.as_ptr(),
                uz: oz.as_ptr(),
                wx: std::ptr::null(),
                wy: std::ptr::null(),
                wz: std::ptr::null(),
                nx: nx.as_ptr(),
                ny: ny.as_ptr(),
                nz: nz.as_ptr(),
                lx: lx.as_ptr(),
                ly: ly.as_ptr(),
                lz: lz.as_ptr(),
                vx: std::ptr::null(),
                vy: std::ptr::null(),
                vz: std::ptr::null(),
                diameter: d.as_ptr(),
                particle_id: pid.as_ptr(),
                collision_index: cid.as_ptr(),
                out_ux: ox.as_mut_ptr(),
                out_uy: oy.as_mut_ptr(),
                out_uz: oz.as_mut_ptr(),
                out_wx: std::ptr::null_mut(),
                out_wy: std::ptr::null_mut(),
                out_wz: std::ptr::null_mut(),
                out_gamma: gamma.as_mut_ptr(),
                out_gamma_star: std::ptr::null_mut(),
                out_candidate_walls: std::ptr::null_mut(),
                out_status: status.as_mut_ptr(),
            };
            assert_eq!(unsafe { rw_rebound_batch(w, &b, threads) }, RW_OK);
            for i in 0..n {
                assert_eq!(status[i], single[i].status);
                assert_eq!([ox[i], oy[i], oz[i]], single[i].velocity, "{threads} {i}");
                assert_eq!(gamma[i], single[i].gamma);
            }
        }
        unsafe { rw_wall_free(w) };
    }

    /// The columns of a batch (inputs and outputs), owned; outputs start at sentinels.
    struct Columns {
        input: Vec<Vec<f64>>,
        pid: Vec<u64>,
        cid: Vec<u64>,
        out: Vec<Vec<f64>>,
        walls: Vec<u32>,
        status: Vec<i32>,
    }

    const SENTINEL: f64 = -12345.0;

    impl Columns {
        fn new(hits: &[rw_hit]) -> Columns {
            let col = |f: &dyn Fn(&rw_hit) -> f64| hits.iter().map(f).collect::<Vec<f64>>();
            let input = vec![
                col(&|h| h.velocity[0]),
                col(&|h| h.velocity[1]),
                col(&|h| h.velocity[2]),
                col(&|h| h.spin[0]),
                col(&|h| h.spin[1]),
                col(&|h| h.spin[2]),
                col(&|h| h.normal[0]),
                col(&|h| h.normal[1]),
                col(&|h| h.normal[2]),
                col(&|h| h.lay[0]),
                col(&|h| h.lay[1]),
                col(&|h| h.lay[2]),
                col(&|h| h.wall_velocity[0]),
                col(&|h| h.wall_velocity[1]),
                col(&|h| h.wall_velocity[2]),
                col(&|h| h.diameter),
            ];
            let n = hits.len();
            Columns {
                input,
                pid: hits.iter().map(|h| h.particle_id).collect(),
                cid: hits.iter().map(|h| h.collision_index).collect(),
                out: vec![vec![SENTINEL; n]; 8],
                walls: vec![u32::MAX; n],
                status: vec![-1; n],
            }
        }

        /// Every array given.
        fn batch(&mut self) -> rw_batch {
            let i = |k: usize| self.input[k].as_ptr();
            let (o, rest) = self.out.split_at_mut(4);
            let (o2, o3) = rest.split_at_mut(2);
            let [ux, uy, uz, wx] = o else { unreachable!() };
            let [wy, wz] = o2 else { unreachable!() };
            let [g, gs] = o3 else { unreachable!() };
            rw_batch {
                n: self.pid.len(),
                ux: i(0),
                uy: i(1),
                uz: i(2),
                wx: i(3),
                wy: i(4),
                wz: i(5),
                nx: i(6),
                ny: i(7),
                nz: i(8),
                lx: i(9),
                ly: i(10),
                lz: i(11),
                vx: i(12),
                vy: i(13),
                vz: i(14),
                diameter: i(15),
                particle_id: self.pid.as_ptr(),
                collision_index: self.cid.as_ptr(),
                out_ux: ux.as_mut_ptr(),
                out_uy: uy.as_mut_ptr(),
                out_uz: uz.as_mut_ptr(),
                out_wx: wx.as_mut_ptr(),
                out_wy: wy.as_mut_ptr(),
                out_wz: wz.as_mut_ptr(),
                out_gamma: g.as_mut_ptr(),
                out_gamma_star: gs.as_mut_ptr(),
                out_candidate_walls: self.walls.as_mut_ptr(),
                out_status: self.status.as_mut_ptr(),
            }
        }

        fn untouched(&self) -> bool {
            self.out.iter().flatten().all(|&x| x == SENTINEL)
                && self.walls.iter().all(|&x| x == u32::MAX)
                && self.status.iter().all(|&x| x == -1)
        }

        /// Output `i` as an `rw_result`.
        fn result(&self, i: usize) -> rw_result {
            let o = |k: usize| self.out[k][i];
            rw_result {
                velocity: [o(0), o(1), o(2)],
                spin: [o(3), o(4), o(5)],
                gamma: o(6),
                gamma_star: o(7),
                candidate_walls: self.walls[i],
                status: self.status[i],
            }
        }
    }

    fn single(w: *const rw_wall, h: &rw_hit) -> (i32, rw_result) {
        let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
        let s = unsafe { rw_rebound(w, h, r.as_mut_ptr()) };
        (s, unsafe { r.assume_init() })
    }

    fn same(a: &rw_result, b: &rw_result) -> bool {
        let bits = |r: &rw_result| {
            let mut v: Vec<u64> = r
                .velocity
                .iter()
                .chain(&r.spin)
                .map(|x| x.to_bits())
                .collect();
            v.extend([r.gamma.to_bits(), r.gamma_star.to_bits()]);
            (v, r.candidate_walls, r.status)
        };
        bits(a) == bits(b)
    }

    /// Hits a C host could hand over by mistake, each with its expected status.
    fn bad_hits() -> Vec<(&'static str, rw_hit, i32)> {
        let h = rw_hit {
            spin: [10.0, -20.0, 30.0],
            ..hit(7)
        };
        let (inf, nan) = (f64::INFINITY, f64::NAN);
        vec![
            (
                "inf velocity",
                rw_hit {
                    velocity: [5.0, -inf, 0.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "NaN velocity",
                rw_hit {
                    velocity: [nan, -1.0, 0.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "inf spin",
                rw_hit {
                    spin: [0.0, 0.0, -inf],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "inf normal",
                rw_hit {
                    normal: [0.0, -inf, 0.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "NaN normal",
                rw_hit {
                    normal: [0.0, -1.0, nan],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "zero normal",
                rw_hit {
                    normal: [0.0; 3],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "NaN lay",
                rw_hit {
                    lay: [nan, 0.0, 0.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "inf lay",
                rw_hit {
                    lay: [inf, 0.0, 1.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "lay along the normal",
                rw_hit {
                    lay: [0.0, 3.0, 0.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            ("zero lay", rw_hit { lay: [0.0; 3], ..h }, RW_INVALID_INPUT),
            (
                "inf wall velocity",
                rw_hit {
                    wall_velocity: [inf, 0.0, 0.0],
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "inf diameter",
                rw_hit { diameter: inf, ..h },
                RW_INVALID_INPUT,
            ),
            (
                "NaN diameter",
                rw_hit { diameter: nan, ..h },
                RW_INVALID_INPUT,
            ),
            (
                "negative diameter",
                rw_hit {
                    diameter: -1e-6,
                    ..h
                },
                RW_INVALID_INPUT,
            ),
            (
                "along the wall",
                rw_hit {
                    velocity: [3.0, 0.0, 1.0],
                    ..h
                },
                RW_NOT_APPROACHING,
            ),
        ]
    }

    #[test]
    fn every_bad_input_is_its_status_with_finite_outputs() {
        let (_, w, _) = wall(&params());
        for (what, h, want) in bad_hits() {
            let (s, r) = single(w, &h);
            assert_eq!((s, r.status), (want, want), "{what}");
            assert!(
                r.velocity.iter().chain(&r.spin).all(|x| x.is_finite()),
                "{what}: {r:?}"
            );
            assert_eq!(
                (r.gamma, r.gamma_star, r.candidate_walls),
                (0.0, 0.0, 0),
                "{what}"
            );
            // Returned unchanged, a non-finite component as 0.
            let clean = |v: [f64; 3]| v.map(|x| if x.is_finite() { x } else { 0.0 });
            assert_eq!(r.velocity, clean(h.velocity), "{what}");
            assert_eq!(r.spin, clean(h.spin), "{what}");
        }
        unsafe { rw_wall_free(w) };
    }

    #[test]
    fn a_batch_with_bad_hits_rebounds_the_good_ones_and_flags_the_bad_ones() {
        let (_, w, _) = wall(&params());
        let bad = bad_hits();
        // Good and bad hits interleaved: the bad ones at every third place.
        let mut hits = Vec::new();
        let mut expect = Vec::new();
        for i in 0..3 * bad.len() {
            if i % 3 == 1 {
                hits.push(bad[i / 3].1);
                expect.push(bad[i / 3].2);
            } else {
                hits.push(rw_hit {
                    spin: [5.0, 0.0, -3.0],
                    ..hit(100 + i as u64)
                });
                expect.push(RW_OK);
            }
        }
        for threads in [1, 2, 4] {
            let mut c = Columns::new(&hits);
            let b = c.batch();
            assert_eq!(unsafe { rw_rebound_batch(w, &b, threads) }, RW_OK);
            for (i, h) in hits.iter().enumerate() {
                let r = c.result(i);
                assert_eq!(r.status, expect[i], "{threads} threads, hit {i}");
                assert!(r.velocity.iter().chain(&r.spin).all(|x| x.is_finite()));
                assert!(
                    same(&r, &single(w, h).1),
                    "{threads} threads, hit {i}: {r:?}"
                );
                if expect[i] == RW_OK {
                    assert!(r.candidate_walls >= 1 && r.velocity[1] > 0.0, "{r:?}");
                }
            }
        }
        unsafe { rw_wall_free(w) };
    }

    #[test]
    fn a_batch_with_a_null_required_array_is_refused_and_nothing_is_written() {
        let (_, w, _) = wall(&params());
        let hits: Vec<rw_hit> = (0..8).map(hit).collect();
        type Clear = fn(&mut rw_batch);
        let required: [(&str, Clear); 16] = [
            ("ux", |b| b.ux = std::ptr::null()),
            ("uy", |b| b.uy = std::ptr::null()),
            ("uz", |b| b.uz = std::ptr::null()),
            ("nx", |b| b.nx = std::ptr::null()),
            ("ny", |b| b.ny = std::ptr::null()),
            ("nz", |b| b.nz = std::ptr::null()),
            ("lx", |b| b.lx = std::ptr::null()),
            ("ly", |b| b.ly = std::ptr::null()),
            ("lz", |b| b.lz = std::ptr::null()),
            ("diameter", |b| b.diameter = std::ptr::null()),
            ("particle_id", |b| b.particle_id = std::ptr::null()),
            ("collision_index", |b| b.collision_index = std::ptr::null()),
            ("out_ux", |b| b.out_ux = std::ptr::null_mut()),
            ("out_uy", |b| b.out_uy = std::ptr::null_mut()),
            ("out_uz", |b| b.out_uz = std::ptr::null_mut()),
            ("out_status", |b| b.out_status = std::ptr::null_mut()),
        ];
        for (name, clear) in required {
            for threads in [1, 3] {
                let mut c = Columns::new(&hits);
                let mut b = c.batch();
                clear(&mut b);
                assert_eq!(
                    unsafe { rw_rebound_batch(w, &b, threads) },
                    RW_NULL_POINTER,
                    "{name}"
                );
                assert!(c.untouched(), "{name}: written");
            }
        }
        // The optional arrays may be NULL: spin and wall velocity default to 0.
        let mut c = Columns::new(&hits);
        let mut b = c.batch();
        (b.wx, b.wy, b.wz, b.vx, b.vy, b.vz) = (
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
            std::ptr::null(),
        );
        (b.out_wx, b.out_gamma, b.out_candidate_walls) = (
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
        );
        assert_eq!(unsafe { rw_rebound_batch(w, &b, 2) }, RW_OK);
        assert!(c.status.iter().all(|&s| s == RW_OK));
        assert!(c.out[3].iter().all(|&x| x == SENTINEL) && c.out[4].iter().all(|&x| x != SENTINEL));
        // NULL wall: refused, nothing written.
        let mut c = Columns::new(&hits);
        let b = c.batch();
        assert_eq!(
            unsafe { rw_rebound_batch(std::ptr::null(), &b, 1) },
            RW_NULL_POINTER
        );
        assert!(c.untouched());
        unsafe { rw_wall_free(w) };
    }

    #[test]
    fn more_threads_than_the_maximum_are_refused_before_anything_is_written() {
        let (_, w, _) = wall(&params());
        let hits: Vec<rw_hit> = (0..100).map(hit).collect();
        for threads in [RW_MAX_THREADS + 1, 1 << 20, i32::MAX] {
            let mut c = Columns::new(&hits);
            let b = c.batch();
            assert_eq!(
                unsafe { rw_rebound_batch(w, &b, threads) },
                RW_INVALID_PARAMETER,
                "{threads}"
            );
            assert!(c.untouched(), "{threads}: written");
        }
        // Up to the maximum (here one thread per hit), and 0 or negative (the calling
        // thread): every hit as the single call gives it.
        for threads in [RW_MAX_THREADS, 0, -5] {
            let mut c = Columns::new(&hits);
            let b = c.batch();
            assert_eq!(
                unsafe { rw_rebound_batch(w, &b, threads) },
                RW_OK,
                "{threads}"
            );
            for (i, h) in hits.iter().enumerate() {
                assert!(same(&c.result(i), &single(w, h).1), "{threads}: {i}");
            }
        }
        unsafe { rw_wall_free(w) };
    }

    #[test]
    fn a_panic_inside_an_entry_point_is_rw_internal_error() {
        let (_, w, _) = wall(&params());
        let bug = rw_hit {
            particle_id: FORCED_PANIC_KEY,
            ..hit(1)
        };
        let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
        assert_eq!(
            unsafe { rw_rebound(w, &bug, r.as_mut_ptr()) },
            RW_INTERNAL_ERROR
        );
        let hits: Vec<rw_hit> = (0..50)
            .map(|i| if i == 37 { bug } else { hit(i) })
            .collect();
        for threads in [1, 4] {
            let mut c = Columns::new(&hits);
            let b = c.batch();
            assert_eq!(
                unsafe { rw_rebound_batch(w, &b, threads) },
                RW_INTERNAL_ERROR,
                "{threads}"
            );
        }
        let mut p = params();
        p.seed = FORCED_PANIC_KEY;
        let (s, handle, _) = wall(&p);
        assert_eq!(s, RW_INTERNAL_ERROR);
        assert!(handle.is_null());
        // The library goes on working after a caught panic.
        assert_eq!(single(w, &hit(1)).0, RW_OK);
        unsafe { rw_wall_free(w) };
    }

    #[test]
    fn version_and_status_strings_are_c_strings() {
        let v = unsafe { std::ffi::CStr::from_ptr(rw_version()) };
        assert_eq!(v.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
        for s in 0..7 {
            let t = unsafe { std::ffi::CStr::from_ptr(rw_status_string(s)) };
            assert!(!t.to_bytes().is_empty());
        }
    }

    #[test]
    fn carrier_laws_are_the_librarys_and_refuse_bad_points() {
        let point = rw_fluid_point {
            rho_f: 1.205,
            mu_f: 1.82e-5,
            rho_p: 2500.0,
            d_p: 150e-6,
            slip: [0.4, -0.1, 0.05],
            vorticity: [10.0, -30.0, -1500.0],
            spin: [200.0, 0.0, 900.0],
        };
        let p = crate::carrier::FluidPoint::from(point);
        let mut a = [7.0; 3];
        assert_eq!(
            unsafe { rw_saffman_mei_lift(&point, a.as_mut_ptr()) },
            RW_OK
        );
        assert_eq!(a, crate::carrier::saffman_mei_lift(&p));
        assert_eq!(unsafe { rw_magnus_lift(&point, a.as_mut_ptr()) }, RW_OK);
        assert_eq!(a, crate::carrier::magnus_lift(&p));
        // in place: the spin array may be the point's own
        let mut q = point;
        let s = unsafe { rw_spin_relax(&q, 5e-4, q.spin.as_mut_ptr()) };
        assert_eq!(s, RW_OK);
        assert_eq!(q.spin, crate::carrier::relaxed_spin(&p, 5e-4));
        // bad points: a status, zeros (lifts) or the spin unchanged, never NaN
        let bad = rw_fluid_point {
            mu_f: -1.0,
            ..point
        };
        assert_eq!(
            unsafe { rw_magnus_lift(&bad, a.as_mut_ptr()) },
            RW_INVALID_INPUT
        );
        assert_eq!(a, [0.0; 3]);
        let nan = rw_fluid_point {
            spin: [f64::NAN, 1.0, 2.0],
            ..point
        };
        let mut w = [9.0; 3];
        let s = unsafe { rw_spin_relax(&nan, 1e-3, w.as_mut_ptr()) };
        assert_eq!((s, w), (RW_INVALID_INPUT, [0.0, 1.0, 2.0]));
        let s = unsafe { rw_spin_relax(&point, -1e-3, w.as_mut_ptr()) };
        assert_eq!((s, w), (RW_INVALID_INPUT, point.spin));
        let s = unsafe { rw_spin_relax(&point, f64::NAN, w.as_mut_ptr()) };
        assert_eq!(s, RW_INVALID_INPUT);
        assert_eq!(
            unsafe { rw_saffman_mei_lift(std::ptr::null(), a.as_mut_ptr()) },
            RW_NULL_POINTER
        );
        assert_eq!(
            unsafe { rw_spin_relax(&point, 1e-3, std::ptr::null_mut()) },
            RW_NULL_POINTER
        );
    }
}
