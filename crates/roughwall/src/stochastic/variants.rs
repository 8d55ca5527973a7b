//! The rough-wall models CFD codes ship, beside Radenkovic & Simonin 2021, so that each can
//! be measured against the deterministic simulation on the same wall (issue "which
//! rough-wall model to trust"). Every variant draws a virtual wall normal from the
//! incident state and hands it to the same collision law; they differ in how the normal is
//! drawn and in what happens when the rebound does not leave the wall.
//!
//! | variant | virtual wall | shadow effect | a rebound into the wall |
//! | --- | --- | --- | --- |
//! | `radenkovic-simonin-2021` | `γ`, `γ*` of the anisotropic wall (Eqs. 26, 29–33) | yes (Eqs. 31–33) | rejected with prob. `1 − tanh(ψα⁺/Δγ)` or when `α⁺ ≤ 0`, redrawn for the same incident particle (Eq. 34) |
//! | `sommerfeld-huber-1999` | isotropic: `γ` from the shadow law with `Δγ`, `γ* ~ N(0, Δγ)` | yes | hits the wall again (a new virtual wall for the new velocity) |
//! | `gaussian-angle` | `α₁ = max(α + Δγ N(0,1), 0)`: a tilt in the incident plane only | no | hits again |
//! | `gaussian-tilt` | tilt `δ = \|Δγ N(0,1)\|`, azimuth uniform in `[0, π)` towards the particle | no | hits again |
//! | `normal-perturbation` | rotation by `θ₁` about `n × t`, then by `θ₂` about `n`, both from the shadow-weighted Gaussian | yes | hits again |
//! | `calibrated` | as `radenkovic-simonin-2021`, in the wall's slopes, corrected by the calibrated table | yes (Eq. 31 in slopes, continued to rising particles) | leaves with the calibrated probability of [`crate::calibrated`], otherwise hits the wall again with the rebound velocity |
//!
//! Sources:
//! * Sommerfeld & Huber, Int. J. Multiphase Flow 25 (1999) 1457–1489: the shadow-effect
//!   law of the roughness angle seen by a particle (as Radenkovic & Simonin 2021, Eq. 31,
//!   write it) for an isotropic wall; a particle that does not return to the flow meets
//!   a new virtual wall (Sommerfeld & Zivkovic 1992, as Radenkovic & Simonin 2021, Sec. 1,
//!   describe it).
//! * OpenFOAM forks' rough-wall patch interaction: the impact angle perturbed as
//!   `alpha1 = max(alpha + gamma*N(0,1), 0)` (as the issue quotes it; no public source was
//!   found to read, so the formula is implemented as quoted: a tilt of the wall in the
//!   incident plane, no transverse roughness, no shadow effect).
//! * LIGGGHTS-PFM (`ParticulateFlow/LIGGGHTS-PFM`, `src/fix_roughness.cpp` l. 193–211,
//!   `src/surface_model_roughness.h` l. 144–213): `deltaGamma = σ N(0,1)` redrawn while
//!   `γ/2 + deltaGamma < 0` with `γ` clamped to `≤ 0` (so a half-normal tilt for an
//!   approaching particle), azimuth `ψ = π U[0,1)`, tilted normal
//!   `n' = cos δ n + sin δ (sin ψ n₁ + cos ψ n₂)`, `n₁` opposite the tangential velocity,
//!   `n₂ = n × n₁`.
//! * ELEXI (`flexi-framework/elexi`, `src/particles/boundary/particle_boundary_condition.f90`
//!   l. 855–937, `Part-Boundary[$]-RoughWall`): the normal rotated by `θ₁` about
//!   `n × t` and then by `θ₂` about the original normal, each angle drawn by rejection from
//!   `sin(α + θ)/sin α · N(θ; 0, σ)` (the shadow-weighted Gaussian). ELEXI's code uses `σ`
//!   as the standard deviation in the exponent and as the variance in the prefactor, and
//!   accepts against an unscaled uniform; here the intended law is sampled exactly.
//!
//! The isotropic variants take one roughness angle `Δγ`: `[stochastic] delta_gamma_deg`, or
//! by default the mean of the wall's two deviations `(Δξ + Δζ)/2`.

use super::cfd_models::CfdModel;
use crate::calibrated::EscapeTable;
use crate::check::within;
use crate::error::{Error, Result};
use crate::wall::{Deviations, MAX_DEVIATION_DEG};

/// ψ of Eq. (34): the paper uses 2 (Konan et al. 1.5); below 0.01 almost every candidate
/// rebound is rejected (hundreds of redraws per rebound), above 100 none is.
pub const PSI_RANGE: (f64, f64) = (0.01, 100.0);

/// ψ of Eq. (34) when none is given: Radenkovic & Simonin 2021's 2 (Sec. 3.5, Fig. 12;
/// docs/physics.md §3 step 6).
pub const PSI_PAPER: f64 = 2.0;

/// ψ of Eq. (34) under the key `stochastic.psi`, checked against [`PSI_RANGE`].
pub fn checked_psi(psi: f64) -> Result<f64> {
    let (lo, hi) = PSI_RANGE;
    within(
        "stochastic.psi",
        psi,
        lo,
        hi,
        "",
        "below, almost every candidate rebound is redrawn; above, none is; the paper uses 2",
    )
}

/// Which rough-wall model draws the virtual walls.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum VariantKind {
    /// Radenkovic & Simonin 2021 (the default).
    #[default]
    RadenkovicSimonin2021,
    /// Sommerfeld & Huber 1999: isotropic, shadow effect, repeated hits.
    SommerfeldHuber1999,
    /// OpenFOAM forks: the impact angle perturbed in the incident plane.
    GaussianAngle,
    /// LIGGGHTS-PFM: a Gaussian tilt with a uniform azimuth.
    GaussianTilt,
    /// ELEXI: the normal rotated by two shadow-weighted Gaussian angles.
    NormalPerturbation,
    /// The paper's virtual walls with an escape law calibrated on a deterministic run, and
    /// multiple collisions followed (`rebound calibrate`).
    Calibrated,
}

impl VariantKind {
    /// Every variant, in the benchmark's order.
    pub const ALL: [VariantKind; 6] = [
        VariantKind::RadenkovicSimonin2021,
        VariantKind::SommerfeldHuber1999,
        VariantKind::GaussianAngle,
        VariantKind::GaussianTilt,
        VariantKind::NormalPerturbation,
        VariantKind::Calibrated,
    ];

    /// The name in case files (`[stochastic] model`).
    pub fn name(self) -> &'static str {
        match self {
            VariantKind::RadenkovicSimonin2021 => "radenkovic-simonin-2021",
            VariantKind::SommerfeldHuber1999 => "sommerfeld-huber-1999",
            VariantKind::GaussianAngle => "gaussian-angle",
            VariantKind::GaussianTilt => "gaussian-tilt",
            VariantKind::NormalPerturbation => "normal-perturbation",
            VariantKind::Calibrated => "calibrated",
        }
    }

    /// Whether the virtual walls are those of the anisotropic wall (Eqs. 26, 29–33) rather
    /// than of one isotropic roughness angle.
    pub fn anisotropic(self) -> bool {
        matches!(
            self,
            VariantKind::RadenkovicSimonin2021 | VariantKind::Calibrated
        )
    }

    /// The variant of a case-file name.
    pub fn from_name(name: &str) -> Option<VariantKind> {
        VariantKind::ALL.into_iter().find(|v| v.name() == name)
    }

    /// The model of the variants CFD codes ship (`None` for the paper's and `calibrated`).
    pub fn cfd_model(self) -> Option<CfdModel> {
        match self {
            VariantKind::RadenkovicSimonin2021 | VariantKind::Calibrated => None,
            VariantKind::SommerfeldHuber1999 => Some(CfdModel::SommerfeldHuber1999),
            VariantKind::GaussianAngle => Some(CfdModel::GaussianAngle),
            VariantKind::GaussianTilt => Some(CfdModel::GaussianTilt),
            VariantKind::NormalPerturbation => Some(CfdModel::NormalPerturbation),
        }
    }
}

/// A variant with its one roughness angle (the isotropic ones) or its escape table (the
/// calibrated one).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Variant {
    /// Which rough-wall model ([`VariantKind`]).
    pub kind: VariantKind,
    /// `Δγ` (rad) of the isotropic variants; `None`: `(Δξ + Δζ)/2` of the wall.
    pub delta_gamma: Option<f64>,
    /// The escape law of `calibrated` (`None`: the built-in table). Interned
    /// ([`EscapeTable::intern`]), so the variant stays a small `Copy` value.
    pub escape: Option<&'static EscapeTable>,
}

impl Variant {
    /// Radenkovic & Simonin 2021.
    pub const PAPER: Variant = Variant {
        kind: VariantKind::RadenkovicSimonin2021,
        delta_gamma: None,
        escape: None,
    };

    /// The calibrated model with `table` (`None`: the built-in one).
    pub fn calibrated(table: Option<&'static EscapeTable>) -> Variant {
        Variant {
            kind: VariantKind::Calibrated,
            delta_gamma: None,
            escape: table,
        }
    }

    /// The variant named `model` (`[stochastic] model`; the paper's when `None`) with the
    /// isotropic variants' roughness angle `delta_gamma_deg`, checked: one-line errors naming
    /// `stochastic.model` or `stochastic.delta_gamma_deg`. The escape table is the built-in
    /// one ([`Variant::with_escape_table`] gives another).
    pub fn checked(model: Option<&str>, delta_gamma_deg: Option<f64>) -> Result<Variant> {
        let kind = match model {
            None => VariantKind::RadenkovicSimonin2021,
            Some(name) => VariantKind::from_name(name).ok_or_else(|| {
                let names: Vec<String> = VariantKind::ALL
                    .iter()
                    .map(|v| format!("\"{}\"", v.name()))
                    .collect();
                Error::invalid(
                    "stochastic.model",
                    format!("\"{name}\""),
                    &format!("one of {}", names.join(", ")),
                )
            })?,
        };
        let delta_gamma = match delta_gamma_deg {
            None => None,
            Some(_) if kind.anisotropic() => {
                return Err(Error::Input(format!(
                    "`stochastic.delta_gamma_deg` applies to the isotropic variants only; model = \"{}\" takes its Δγ from the wall (Eq. 26)",
                    kind.name()
                )))
            }
            Some(d) => Some(
                within(
                    "stochastic.delta_gamma_deg",
                    d,
                    0.0,
                    MAX_DEVIATION_DEG,
                    " degrees",
                    "a roughness angle within the wall models' range",
                )?
                .to_radians(),
            ),
        };
        Ok(Variant {
            kind,
            delta_gamma,
            escape: None,
        })
    }

    /// Whether this variant takes an escape table (`stochastic.escape_table`): only
    /// `calibrated` does; the error names the key and the model.
    pub fn check_takes_escape_table(&self) -> Result<()> {
        if self.kind == VariantKind::Calibrated {
            Ok(())
        } else {
            Err(Error::Input(format!(
                "`stochastic.escape_table` applies to model = \"calibrated\" only (model = \"{}\")",
                self.kind.name()
            )))
        }
    }

    /// This variant with the escape table `table` ([`Variant::check_takes_escape_table`]
    /// first).
    pub fn with_escape_table(self, table: &'static EscapeTable) -> Result<Variant> {
        self.check_takes_escape_table()?;
        Ok(Variant {
            escape: Some(table),
            ..self
        })
    }

    /// The escape table of the calibrated model.
    pub fn escape_table(&self) -> &'static EscapeTable {
        self.escape.unwrap_or_else(EscapeTable::builtin)
    }

    /// The roughness angle an isotropic variant uses on `wall` (rad).
    pub fn delta_gamma_on(&self, wall: &Deviations) -> f64 {
        self.delta_gamma
            .unwrap_or(0.5 * (wall.delta_xi + wall.delta_zeta))
    }

    /// Whether the variant is the paper's model.
    pub fn is_paper(&self) -> bool {
        self.kind == VariantKind::RadenkovicSimonin2021
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for v in VariantKind::ALL {
            assert_eq!(VariantKind::from_name(v.name()), Some(v));
        }
        assert_eq!(VariantKind::from_name("konan"), None);
        let w = Deviations {
            delta_xi: 0.02,
            delta_zeta: 0.06,
        };
        assert!((Variant::default().delta_gamma_on(&w) - 0.04).abs() < 1e-15);
    }
}
