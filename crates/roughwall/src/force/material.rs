//! Particle material presets of Hu et al. 2021, Table 1.
use crate::error::{Error, Result};

/// A material preset: density (kg/m³), Young's modulus (Pa), Poisson's ratio, and the
/// volume-equivalent diameter used by Hu et al. for it (µm, the first listed in Table 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Preset {
    /// Name used in case files.
    pub name: &'static str,
    /// ρ_p (kg/m³).
    pub density: f64,
    /// E_p (Pa).
    pub youngs: f64,
    /// σ_p.
    pub poisson: f64,
    /// D_p (µm).
    pub diameter_um: f64,
}

/// Hu et al. 2021, Table 1. Note: Table 1 gives E = 63 GPa for glass (type I) while every figure
/// caption (Figs. 3, 6–9, 11, 12) says 64 GPa; the `hu-fig*` cases override `youngs_pa = 64e9`
/// (docs/physics.md §7).
pub const PRESETS: [Preset; 4] = [
    Preset {
        name: "e-glass-sphere",
        density: 2560.0,
        youngs: 80e9,
        poisson: 0.22,
        diameter_um: 2.45,
    },
    Preset {
        name: "glass",
        density: 2500.0,
        youngs: 63e9,
        poisson: 0.24,
        diameter_um: 2.45,
    },
    Preset {
        name: "copper",
        density: 8960.0,
        youngs: 115e9,
        poisson: 0.35,
        diameter_um: 2.45,
    },
    Preset {
        name: "iron",
        density: 7690.0,
        youngs: 203e9,
        poisson: 0.29,
        diameter_um: 2.45,
    },
];

/// Looks a preset up by name; unknown names are a one-line `Error::Input` naming `key`.
pub fn preset(key: &str, name: &str) -> Result<Preset> {
    PRESETS
        .iter()
        .copied()
        .find(|p| p.name == name)
        .ok_or_else(|| Error::invalid(key, name, "e-glass-sphere, glass, copper, iron"))
}

#[cfg(test)]
mod tests {
    #[test]
    fn presets_resolve_and_unknown_is_one_line_error() {
        assert_eq!(
            super::preset("impactor.preset", "copper").unwrap().youngs,
            115e9
        );
        let e = super::preset("impactor.preset", "steel")
            .unwrap_err()
            .to_string();
        assert!(e.contains("steel") && !e.contains('\n'));
    }
}
