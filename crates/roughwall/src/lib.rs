//! `roughwall`: particles bouncing off anisotropic rough walls.
//!
//! The physics of the `rebound` tool as a library: anisotropic Gaussian rough surfaces
//! (Radenkovic & Simonin 2021, Sec. 2), particles bouncing on them deterministically
//! (Sec. 3.1–3.3), the stochastic wall model that stands for those statistics (Sec. 3.4–3.6)
//! and the models CFD codes ship beside it, a calibrated model, collision laws
//! (Sommerfeld–Huber, Eqs. 36–42), erosion laws, and the peak elastic force of spheroids
//! hitting a wall (Hu et al. 2021). It is also the C library `libroughwall` a CFD code calls
//! once per particle–wall hit ([`ffi`], header `include/roughwall.h`). Conventions (frames,
//! signs, units) are those of `docs/physics.md`; every physics function cites its paper and
//! equation.
//!
//! Reproducible by construction: every particle draws from its own random stream keyed by
//! `(seed, indices)` ([`rng`]), and tallies are merged in a fixed block order
//! ([`tally::run`]), so results do not depend on the thread count or on a split into
//! shards. Nothing here prints, reads a case file or draws a figure: the `rebound`
//! application does that.
//!
//! # Where to start
//!
//! The types most callers need are at the top (`roughwall::WallModel`,
//! `roughwall::CollisionLaw`, `roughwall::Deviations`, …); everything else is one level down,
//! in the module of its family (`roughwall::tally::BlockTally`). No file's module is public,
//! so the files can move without breaking a caller.
//!
//! | to … | use |
//! | --- | --- |
//! | rebound one particle off a wall from a CFD code (any frame, moving wall, keyed stream) | [`WallModel`], or [`ffi`] from C and Fortran |
//! | draw one rebound in the wall's frame | [`rebound`] (the paper's model), [`models::rebound_with`] (any model of [`models`]) |
//! | add a rough-wall model | [`RoughWallModel`], [`NamedModel`] ([`models`] lists the models) |
//! | generate a rough surface and measure it | [`surface::generate()`], [`surface::surface_stats`], [`surface::measured_deviations`] |
//! | read a measured wall's parameters off a scan | [`ScanField`], [`scan::characterise`] |
//! | follow particles on a surface | [`Tracker`], [`deterministic::run_condition`] |
//! | run many particles into tallies with standard errors | [`tally::run`] with [`models::fill_block`] or [`deterministic::fill_block`] |
//! | the calibrated model and its table | [`calibrated`] |
//! | erosion at an impact | [`ErosionModel`] |
//! | carry a particle's spin between hits; the shear and rotational lifts | [`carrier`] |
//! | peak elastic force of a sphere or spheroid | [`force::Model::evaluate`] |
//! | the library's one-line errors and range checks, for a caller's own keys | [`Error`], [`check`] |
//!
//! # Examples
//!
//! A CFD code's wall hit: the Sec. 4 glass–steel wall, a hit keyed by particle id and
//! collision index, so that it rebounds the same on any rank or thread.
//!
//! ```
//! use roughwall::collision::CollisionParams;
//! use roughwall::wall_model::{Hit, HitStatus, WallModel, WallParams};
//!
//! let (wall, warnings) = WallModel::new(&WallParams {
//!     delta_xi_deg: 3.8,
//!     delta_zeta_deg: 7.5,
//!     collision: CollisionParams {
//!         model: Some("sommerfeld-huber".into()),
//!         preset: Some("glass-steel".into()),
//!         ..Default::default()
//!     },
//!     seed: 2021,
//!     ..Default::default()
//! })
//! .expect("valid parameters");
//! assert!(warnings.is_empty());
//! let hit = Hit {
//!     velocity: [5.0, -1.5, 0.5],
//!     spin: [0.0; 3],
//!     normal: [0.0, 1.0, 0.0],
//!     lay: [1.0, 0.0, 0.0],
//!     wall_velocity: [0.0; 3],
//!     diameter_m: 500e-6,
//!     particle_id: 42,
//!     collision_index: 0,
//! };
//! let out = wall.rebound(&hit);
//! assert_eq!(out.status, HitStatus::Rebound);
//! assert!(out.velocity[1] > 0.0); // it leaves the wall
//! assert_eq!(wall.rebound(&hit), out); // the same key gives the same rebound
//! ```
//!
//! A bad parameter is a one-line error naming the key, the value and what is allowed:
//!
//! ```
//! use roughwall::wall_model::{WallModel, WallParams};
//!
//! let err = WallModel::new(&WallParams { delta_xi_deg: 25.0, ..Default::default() }).unwrap_err();
//! assert_eq!(err.to_string(), "invalid `wall.delta_xi_deg` = 25: allowed 0 to 20 degrees");
//! ```
//!
//! A Garcia–Stoll surface (Radenkovic & Simonin 2021, Eqs. 1–2) and the normal-angle
//! deviations it has, against `√2 h/c_L` of Eq. (15):
//!
//! ```
//! use roughwall::surface::{generate, measured_deviations, SurfaceSpec};
//!
//! let spec = SurfaceSpec {
//!     length_m: 512e-6,
//!     nodes: 512,
//!     rms_height_m: 0.37e-6,
//!     corr_length_x_m: Some(12e-6),
//!     corr_length_z_m: Some(4e-6),
//! };
//! let field = generate(&spec, 1);
//! let measured = measured_deviations(&field);
//! let nominal = roughwall::wall::deviation_from_surface(0.37e-6, 4e-6);
//! assert!((measured.delta_zeta / nominal - 1.0).abs() < 0.1);
//! ```
//!
//! Particles bouncing on that surface, deterministically: an ideally elastic bounce keeps
//! the speed (`docs/physics.md` §5).
//!
//! ```
//! use roughwall::collision::CollisionLaw;
//! use roughwall::deterministic::{history, ModelSetup, Tracker};
//! use roughwall::incidence::{IncidentCondition, SpeedLaw};
//! use roughwall::surface::{generate, SurfaceSpec};
//! use roughwall::wall::Deviations;
//!
//! let spec = SurfaceSpec {
//!     length_m: 256e-6,
//!     nodes: 256,
//!     rms_height_m: 0.37e-6,
//!     corr_length_x_m: Some(12e-6),
//!     corr_length_z_m: Some(4e-6),
//! };
//! let field = generate(&spec, 7);
//! let tracker = Tracker::new(&field, 1000).unwrap();
//! let setup = ModelSetup {
//!     law: CollisionLaw::Elastic,
//!     diameter_m: 500e-6,
//!     speed: SpeedLaw::horizontal(1.0, 0.0),
//!     wall: Deviations { delta_xi: 2.5f64.to_radians(), delta_zeta: 7.5f64.to_radians() },
//!     psi: 2.0,
//!     erosion: None,
//!     spin: Default::default(),
//! };
//! let cond = IncidentCondition::from_degrees(-12.5, 30.0);
//! for i in 0..100 {
//!     let h = history(&tracker, &setup, &cond, 0, i, 2021);
//!     assert!((h.velocity.norm() - h.incident.norm()).abs() < 1e-9);
//! }
//! ```
//!
//! The peak elastic force of a glass prolate spheroid (λ = 2) hitting a wall standing on its
//! tip (β = 90°, the major axis normal to the wall), by Hu et al. 2021's fit (Eqs. 7–8) and
//! by the rigid-spheroid Hertz model; the particle and `U_N` are those of Hu et al. 2021,
//! Fig. 6 (type I glass of Table 1, `D` = 2.45 µm, the captions' 64 GPa: docs/physics.md §7):
//!
//! ```
//! use roughwall::force::{Impact, Model, Particle};
//!
//! let glass = Particle { density: 2500.0, youngs: 64e9, poisson: 0.24, diameter: 2.45e-6 };
//! let impact = Impact::from_deg(2.0, 90.0, 0.0457).unwrap();
//! let fit = Model::Hu2021.evaluate(&glass, &impact).unwrap().f_max;
//! let hertz = Model::HertzRigid.evaluate(&glass, &impact).unwrap().f_max;
//! assert!(fit > 0.0 && (hertz / fit - 1.0).abs() < 0.2);
//! ```
#![deny(missing_docs)]
#![warn(unnameable_types)]
pub mod angles;
pub mod calibrated;
pub mod carrier;
pub mod check;
pub mod collision;
pub mod deterministic;
pub mod erosion;
pub mod error;
pub mod ffi;
pub mod force;
pub mod format;
pub mod gaussian_cost;
pub mod incidence;
pub mod measured_wall;
pub mod memory;
pub mod models;
pub mod parameters;
pub mod rng;
pub mod scan;
pub mod stochastic;
pub mod surface;
pub mod tally;
pub mod wall;
pub mod wall_model;
pub mod warning;

// The front door: what most callers need, at the top. Everything else is one level down, in
// the module of its family (`roughwall::tally::BlockTally`); no file's module is public.
pub use collision::{CollisionLaw, CollisionParams, ShParams};
pub use deterministic::Tracker;
pub use erosion::{ErosionModel, ErosionSetup};
pub use error::{Error, Result};
pub use incidence::{IncidentCondition, SpeedLaw, SpinLaw};
pub use models::{AnyModel, ModelParams, NamedModel, RoughWallModel};
pub use scan::ScanField;
pub use stochastic::rebound;
pub use surface::{HeightField, SurfaceSpec, Triangulation};
pub use wall::Deviations;
pub use wall_model::{Hit, HitOutcome, HitStatus, WallModel, WallParams};
pub use warning::Warning;
