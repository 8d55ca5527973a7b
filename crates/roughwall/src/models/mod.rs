//! The rough-wall models: Radenkovic & Simonin 2021, the models CFD codes ship and the
//! calibrated model, each one type implementing [`RoughWallModel`], so that each can be
//! measured against the deterministic simulation on the same wall. Every model draws a
//! virtual wall normal from the incident state and hands it to the same collision law; they
//! differ in how the normal is drawn and in what happens when the rebound does not leave the
//! wall.
//!
//! | model | virtual wall | shadow effect | a rebound into the wall |
//! | --- | --- | --- | --- |
//! | `radenkovic-simonin-2021` | `γ`, `γ*` of the anisotropic wall (Eqs. 26, 29–33) | yes (Eqs. 31–33) | rejected with prob. `1 − tanh(ψα⁺/Δγ)` or when `α⁺ ≤ 0`, redrawn for the same incident particle (Eq. 34) |
//! | `sommerfeld-huber-1999` | isotropic: `γ` from the shadow law with `Δγ`, `γ* ~ N(0, Δγ)` | yes | hits the wall again (a new virtual wall for the new velocity) |
//! | `gaussian-angle` | `α₁ = max(α + Δγ N(0,1), 0)`: a tilt in the incident plane only | no | hits again |
//! | `gaussian-tilt` | tilt `δ = \|Δγ N(0,1)\|`, azimuth uniform in `[0, π)` towards the particle | no | hits again |
//! | `normal-perturbation` | rotation by `θ₁` about `n × t`, then by `θ₂` about `n`, both from the shadow-weighted Gaussian | yes | hits again |
//! | `calibrated` | as `radenkovic-simonin-2021`, in the wall's slopes, corrected by the calibrated table | yes (Eq. 31 in slopes, continued to rising particles) | leaves with the calibrated probability of [`crate::calibrated`], otherwise hits the wall again with the rebound velocity |
//! | `measured-wall` | the effective element `(γ, γ*)` of the deterministic reference on the wall itself, from its table ([`crate::measured_wall`]) | measured (in the table) | hits again (only with a law that is not elastic) |
//!
//! Each model's file cites its source.
//!
//! The isotropic models take one roughness angle `Δγ`: `[stochastic] delta_gamma_deg`, or
//! by default the mean of the wall's two deviations `(Δξ + Δζ)/2`.
//!
//! This module sits above the models it lists: [`crate::stochastic`] (the paper's model and
//! what all share) and [`crate::calibrated`] are below it and know nothing of the others.
//!
//! * `rough_wall_model`: the traits, [`RoughWallModel`] (a model rebounds particles) and
//!   [`NamedModel`] (a case file names it; it checks its own parameters), and [`ModelParams`].
//! * one file per model: `radenkovic_simonin_2021`, `sommerfeld_huber_1999`,
//!   `gaussian_angle`, `gaussian_tilt`, `normal_perturbation` (with what the four
//!   isotropic ones share, `isotropic`), `calibrated` and `measured_wall`;
//! * `registry`: the list of the models, and [`AnyModel`], the dispatch between them;
//! * `rebound`: one rebound from any model, the trivial cases ruled out alike;
//! * `simulate`: many rebounds of one incident condition, parallel and reproducible.
//!
//! Adding a model: its file here implementing [`RoughWallModel`] and [`NamedModel`], its
//! `mod` line below and its line in `registry`'s list, a test, and its row in the table
//! above and in `docs/cases.md` (CONTRIBUTING.md).

pub(crate) mod calibrated;
pub(crate) mod gaussian_angle;
pub(crate) mod gaussian_tilt;
pub(crate) mod isotropic;
pub(crate) mod measured_wall;
pub(crate) mod normal_perturbation;
pub(crate) mod params;
pub(crate) mod radenkovic_simonin_2021;
pub(crate) mod rebound;
pub(crate) mod registry;
pub(crate) mod rough_wall_model;
pub(crate) mod simulate;
pub(crate) mod sommerfeld_huber_1999;

pub use calibrated::Calibrated;
pub use gaussian_angle::{GaussianAngle, GaussianAngleWall};
pub use gaussian_tilt::{GaussianTilt, GaussianTiltWall};
pub use isotropic::{Isotropic, IsotropicDraw, IsotropicIncidence};
pub use measured_wall::{rebound_off_table, MeasuredWall};
pub use normal_perturbation::{NormalPerturbation, NormalPerturbationWall};
pub use params::{refuse_delta_gamma, refuse_escape_table, refuse_wall_table};
pub use radenkovic_simonin_2021::RadenkovicSimonin2021;
pub use rebound::{rebound_from_observed, rebound_with};
pub use registry::{AnyIncidence, AnyModel};
pub use rough_wall_model::{ModelParams, NamedModel, RoughWallModel};
pub use simulate::{fill_block, gamma_model_curve, outcome, rebound_of, tally_spec, ModelSetup};
pub use sommerfeld_huber_1999::{SommerfeldHuber1999, SommerfeldHuberWall};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wall::Deviations;

    #[test]
    fn names_round_trip() {
        for &name in AnyModel::NAMES {
            // The measured-wall model has no default: its table is the wall's.
            if name == MeasuredWall::NAME {
                let e = AnyModel::with_defaults(name).unwrap_err().to_string();
                assert!(e.contains("needs `stochastic.wall_table`"), "{e}");
                let table = || Ok(crate::measured_wall::small_table());
                let params = ModelParams {
                    wall_table: Some(&table),
                    ..Default::default()
                };
                assert_eq!(AnyModel::named(Some(name), &params).unwrap().name(), name);
                continue;
            }
            assert_eq!(AnyModel::with_defaults(name).unwrap().name(), name);
        }
        assert!(AnyModel::with_defaults("konan").is_err());
        let w = Deviations {
            delta_xi: 0.02,
            delta_zeta: 0.06,
        };
        assert!((AnyModel::default().roughness_angle(&w) - 0.04).abs() < 1e-15);
    }
}
