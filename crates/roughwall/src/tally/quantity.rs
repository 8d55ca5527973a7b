//! The quantities a run tallies, by name: one enum instead of strings looked up by position.

/// A tallied quantity. Angles are in degrees in every output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Quantity {
    /// Final rebound angle `α⁺`.
    AlphaOut,
    /// `α⁺_xy = arctan(tan α⁺ / cos β⁺)` (Radenkovic & Simonin 2021, Eq. 43).
    AlphaOutXy,
    /// Final transverse angle `β⁺`.
    BetaOut,
    /// Final transverse deviation `β⁺ − β⁻`.
    Dbeta,
    /// Transverse deviation after the first collision (deterministic).
    DbetaFirst,
    /// `ξ − 90°` of the first normal seen.
    XiFirst,
    /// `ζ − 90°` of the first normal seen.
    ZetaFirst,
    /// `γ` of the first normal seen (Eq. 20).
    GammaFirst,
    /// `γ*` of the first normal seen (Eq. 21).
    GammaStarFirst,
    /// Angle `α⁺` of the first rebound (deterministic).
    AlphaFirst,
    /// `γ*` of the first normal seen, for `γ` within `0.1 Δγ` of 0 (Fig. 11).
    GammaStarGivenGamma0,
    /// `γ*` of the first normal seen, for `γ` within `0.1 Δγ` of `Δγ` (Fig. 11).
    GammaStarGivenGammaDg,
    /// `|U⁺| / |U⁻|` (moments only).
    SpeedRatio,
    /// Collisions per history (deterministic; moments only).
    Collisions,
    /// Fraction of single-collision histories per bin of the final `α⁺` (deterministic).
    PSingleGivenAlphaOut,
    /// Fraction of single-collision histories per bin of the first rebound's `α⁺` (Fig. 12).
    PSingleGivenAlphaFirst,
    /// `tanh(ψ α⁺/Δγ(β⁺))` (Eqs. 34–35) averaged per bin of the first rebound's `α⁺` (Fig. 12).
    PSingleModel,
    /// The analytic `P_eff(γ | α⁻)` (Eqs. 31–33) at the `gamma_first` bin centres (stochastic).
    GammaModel,
    /// Impact angle to the local wall element (facet hit, or accepted virtual wall) of every
    /// impact that counts for erosion.
    ImpactAngleLocal,
    /// Impact angle to the local wall element of rejected stochastic candidates.
    ImpactAngleLocalRejected,
    /// Wall volume removed per unit particle mass by one history (m³/kg; moments only).
    ErosionPerMass,
    /// What the rejected stochastic candidates of one rebound would remove (m³/kg; moments only).
    ErosionPerMassRejected,
}

impl Quantity {
    /// Every quantity, in the order `pdfs.csv` and `moments.csv` list them.
    pub const ALL: [Quantity; 22] = [
        Quantity::AlphaOut,
        Quantity::AlphaOutXy,
        Quantity::BetaOut,
        Quantity::Dbeta,
        Quantity::DbetaFirst,
        Quantity::XiFirst,
        Quantity::ZetaFirst,
        Quantity::GammaFirst,
        Quantity::GammaStarFirst,
        Quantity::PSingleGivenAlphaOut,
        Quantity::PSingleGivenAlphaFirst,
        Quantity::PSingleModel,
        Quantity::AlphaFirst,
        Quantity::GammaModel,
        Quantity::GammaStarGivenGamma0,
        Quantity::GammaStarGivenGammaDg,
        Quantity::SpeedRatio,
        Quantity::Collisions,
        Quantity::ImpactAngleLocal,
        Quantity::ImpactAngleLocalRejected,
        Quantity::ErosionPerMass,
        Quantity::ErosionPerMassRejected,
    ];

    /// The name used in the CSV files.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::AlphaOut => "alpha_out",
            Quantity::AlphaOutXy => "alpha_out_xy",
            Quantity::BetaOut => "beta_out",
            Quantity::Dbeta => "dbeta",
            Quantity::DbetaFirst => "dbeta_first",
            Quantity::XiFirst => "xi_first",
            Quantity::ZetaFirst => "zeta_first",
            Quantity::GammaFirst => "gamma_first",
            Quantity::GammaStarFirst => "gamma_star_first",
            Quantity::AlphaFirst => "alpha_first",
            Quantity::GammaStarGivenGamma0 => "gamma_star_given_gamma_0",
            Quantity::GammaStarGivenGammaDg => "gamma_star_given_gamma_dg",
            Quantity::SpeedRatio => "speed_ratio",
            Quantity::Collisions => "collisions",
            Quantity::PSingleGivenAlphaOut => "p_single_given_alpha_out",
            Quantity::PSingleGivenAlphaFirst => "p_single_given_alpha_first",
            Quantity::PSingleModel => "p_single_model",
            Quantity::GammaModel => "gamma_model",
            Quantity::ImpactAngleLocal => "impact_angle_local",
            Quantity::ImpactAngleLocalRejected => "impact_angle_local_rejected",
            Quantity::ErosionPerMass => "erosion_per_mass",
            Quantity::ErosionPerMassRejected => "erosion_per_mass_rejected",
        }
    }

    /// The quantity of a CSV name.
    pub fn from_name(name: &str) -> Option<Quantity> {
        Quantity::ALL.into_iter().find(|q| q.name() == name)
    }

    /// Whether `pdfs.csv` holds a probability density of it (compared by `rebound compare`),
    /// rather than a probability per bin (`p_single_*`).
    pub fn is_density(self) -> bool {
        !matches!(
            self,
            Quantity::PSingleGivenAlphaOut
                | Quantity::PSingleGivenAlphaFirst
                | Quantity::PSingleModel
                | Quantity::SpeedRatio
                | Quantity::Collisions
                | Quantity::ErosionPerMass
                | Quantity::ErosionPerMassRejected
        )
    }

    /// Whether it is a wall-erosion volume (m³/kg) rather than an angle or a ratio.
    pub fn is_erosion(self) -> bool {
        matches!(
            self,
            Quantity::ErosionPerMass | Quantity::ErosionPerMassRejected
        )
    }

    /// Histogram range (degrees) of an angle quantity.
    pub fn range_deg(self) -> (f64, f64) {
        match self {
            Quantity::BetaOut | Quantity::Dbeta | Quantity::DbetaFirst => (-180.0, 180.0),
            Quantity::ImpactAngleLocal | Quantity::ImpactAngleLocalRejected => (0.0, 90.0),
            _ => (-90.0, 90.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_are_unique() {
        for q in Quantity::ALL {
            assert_eq!(Quantity::from_name(q.name()), Some(q));
        }
        let mut names: Vec<&str> = Quantity::ALL.iter().map(|q| q.name()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), Quantity::ALL.len());
        assert_eq!(Quantity::from_name("nope"), None);
    }
}
