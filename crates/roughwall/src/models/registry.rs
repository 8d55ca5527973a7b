//! The list of the rough-wall models that case files, the C library and Python name, and the
//! dispatch between them: [`AnyModel`] is one of them with its parameters, and implements
//! [`RoughWallModel`] by handing each call to the model it holds. The list's order is the
//! benchmark's and the C library's model index (`rw_wall_params.model`): append, never
//! reorder.

use super::calibrated::Calibrated;
use super::gaussian_angle::GaussianAngle;
use super::gaussian_tilt::GaussianTilt;
use super::measured_wall::MeasuredWall;
use super::normal_perturbation::NormalPerturbation;
use super::radenkovic_simonin_2021::RadenkovicSimonin2021;
use super::rough_wall_model::{ModelParams, NamedModel, RoughWallModel};
use super::sommerfeld_huber_1999::SommerfeldHuber1999;
use crate::calibrated::EscapeTable;
use crate::error::{Error, Result};
use crate::stochastic::{Contact, Rebound};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::Rng;

/// Writes [`AnyModel`], its incidence [`AnyIncidence`] and the dispatch from the list of
/// model types: one enum arm per model, named after its type.
macro_rules! registry {
    ($($model:ident),+ $(,)?) => {
        /// One of the registered rough-wall models, with its parameters (`[stochastic] model`
        /// and the keys it takes). The default is Radenkovic & Simonin 2021.
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub enum AnyModel {
            $(
                #[doc = concat!("[`", stringify!($model), "`].")]
                $model($model),
            )+
        }

        /// What the model an [`AnyModel`] holds precomputes for one incident direction,
        /// with the model.
        #[derive(Clone, Copy, Debug)]
        pub enum AnyIncidence {
            $(
                #[doc = concat!("[`", stringify!($model), "`].")]
                $model($model, <$model as RoughWallModel>::Incidence),
            )+
        }

        impl AnyModel {
            /// The registered models' names, in the list's order.
            pub const NAMES: &'static [&'static str] = &[$(<$model as NamedModel>::NAME),+];

            /// The model named `name` with `params`, `None` for a name not in the list.
            fn build(name: &str, params: &ModelParams) -> Option<Result<AnyModel>> {
                $(
                    if name == <$model as NamedModel>::NAME {
                        return Some(<$model as NamedModel>::from_params(params).map(AnyModel::$model));
                    }
                )+
                None
            }
        }

        impl RoughWallModel for AnyModel {
            type Incidence = AnyIncidence;

            fn name(&self) -> &'static str {
                match self {
                    $(AnyModel::$model(m) => m.name(),)+
                }
            }

            fn anisotropic(&self) -> bool {
                match self {
                    $(AnyModel::$model(m) => m.anisotropic(),)+
                }
            }

            fn roughness_angle(&self, wall: &Deviations) -> f64 {
                match self {
                    $(AnyModel::$model(m) => m.roughness_angle(wall),)+
                }
            }

            fn wall(&self, given: &Deviations) -> Deviations {
                match self {
                    $(AnyModel::$model(m) => m.wall(given),)+
                }
            }

            fn incidence(&self, alpha: f64, beta: f64, wall: &Deviations) -> AnyIncidence {
                match self {
                    $(AnyModel::$model(m) => AnyIncidence::$model(*m, m.incidence(alpha, beta, wall)),)+
                }
            }

            #[inline]
            fn rebound_drawn<R: Rng + ?Sized>(
                &self,
                inc: &AnyIncidence,
                u_in: Vector3<f64>,
                omega_in: Vector3<f64>,
                contact: &Contact,
                rng: &mut R,
                observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
            ) -> Rebound {
                match inc {
                    $(AnyIncidence::$model(m, inc) => m.rebound_drawn(inc, u_in, omega_in, contact, rng, observe),)+
                }
            }
        }
    };
}

// The registered models: one line each.
registry! {
    RadenkovicSimonin2021,
    SommerfeldHuber1999,
    GaussianAngle,
    GaussianTilt,
    NormalPerturbation,
    Calibrated,
    MeasuredWall,
}

impl Default for AnyModel {
    fn default() -> AnyModel {
        AnyModel::PAPER
    }
}

impl AnyModel {
    /// Radenkovic & Simonin 2021.
    pub const PAPER: AnyModel = AnyModel::RadenkovicSimonin2021(RadenkovicSimonin2021);

    /// The model named `model` (`[stochastic] model`; the paper's when `None`) with `params`,
    /// checked by the model: one-line errors naming `stochastic.model` or the key at fault.
    pub fn named(model: Option<&str>, params: &ModelParams) -> Result<AnyModel> {
        let name = model.unwrap_or(RadenkovicSimonin2021::NAME);
        AnyModel::build(name, params).unwrap_or_else(|| {
            let names: Vec<String> = AnyModel::NAMES.iter().map(|n| format!("\"{n}\"")).collect();
            Err(Error::invalid(
                "stochastic.model",
                format!("\"{name}\""),
                &format!("one of {}", names.join(", ")),
            ))
        })
    }

    /// The model named `name` with no parameters given (each takes its defaults).
    pub fn with_defaults(name: &str) -> Result<AnyModel> {
        AnyModel::named(Some(name), &ModelParams::default())
    }

    /// The calibrated model with `table` (`None`: the built-in one).
    pub fn calibrated(table: Option<&'static EscapeTable>) -> AnyModel {
        AnyModel::Calibrated(Calibrated { escape: table })
    }

    /// Whether this is the paper's model.
    pub fn is_paper(&self) -> bool {
        matches!(self, AnyModel::RadenkovicSimonin2021(_))
    }
}
