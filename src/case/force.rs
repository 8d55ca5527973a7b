//! The particle and sweep of `rebound force-sweep` (`[impactor]`, formerly `[particle]`;
//! `[sweep]`).

use super::{Case, ParticleSection, SweepSection};
use roughwall::force::Sweep;
use roughwall::force::{material, Model, Particle};
use roughwall::{Error, Result};

/// Fig. 6 values used for any `[particle]` property a case leaves out (no preset).
const FIG6: Particle = Particle {
    density: 2500.0,
    youngs: 64e9,
    poisson: 0.24,
    diameter: 2.45e-6,
};

/// The particle material (ρ, E, σ; diameter as the default D) and the sweep of a case.
///
/// `[impactor]`: `preset` (Hu et al. 2021, Table 1) with any property overriding it; without a
/// preset, missing properties take Fig. 6's values (ρ = 2500 kg/m³, E = 64 GPa, σ = 0.24,
/// D = 2.45 µm). `[sweep]`: missing keys take Fig. 6's sweep; `diameter_um` may be swept here
/// or given once in `[particle]`, not both.
pub fn resolve(case: &Case) -> Result<(Particle, Sweep)> {
    // `[particle]` is the old name (issue 14): read, with a warning from `case::sections`.
    let (section, ps): (&str, ParticleSection) = match (&case.impactor, &case.particle) {
        (Some(_), Some(_)) => {
            return Err(Error::Input(
                "both [impactor] and [particle], its old name: keep [impactor] only".into(),
            ))
        }
        (None, Some(old)) => ("particle", old.clone()),
        (s, None) => ("impactor", s.clone().unwrap_or_default()),
    };
    let mut p = match &ps.preset {
        Some(name) => {
            let m = material::preset(&format!("{section}.preset"), name)?;
            Particle {
                density: m.density,
                youngs: m.youngs,
                poisson: m.poisson,
                diameter: m.diameter_um * 1e-6,
            }
        }
        None => FIG6,
    };
    if let Some(v) = ps.density_kg_m3 {
        p.density = v;
    }
    if let Some(v) = ps.youngs_pa {
        p.youngs = v;
    }
    if let Some(v) = ps.poisson {
        p.poisson = v;
    }
    if let Some(v) = ps.diameter_um {
        p.diameter = v * 1e-6;
    }
    p.validate()?;

    let ss: SweepSection = case.sweep.clone().unwrap_or_default();
    let fig6 = Sweep::fig6();
    let models = match &ss.models {
        Some(names) => names
            .iter()
            .map(|n| Model::from_name(n))
            .collect::<Result<Vec<_>>>()?,
        None => fig6.models.clone(),
    };
    let lambdas = match &ss.lambda {
        Some(v) => v.expand("sweep.lambda")?,
        None => fig6.lambdas.clone(),
    };
    let betas_deg = match &ss.beta_deg {
        Some(v) => v.expand("sweep.beta_deg")?,
        None => fig6.betas_deg.clone(),
    };
    let u_ns = match &ss.u_n_m_s {
        Some(v) => v.expand("sweep.u_n_m_s")?,
        None => fig6.u_ns.clone(),
    };
    let diameters = match &ss.diameter_um {
        Some(_) if ps.diameter_um.is_some() => {
            return Err(Error::Input(format!(
                "give `diameter_um` in [{section}] or in [sweep], not both"
            )))
        }
        Some(v) => v
            .expand("sweep.diameter_um")?
            .into_iter()
            .map(|d| d * 1e-6)
            .collect(),
        None => vec![p.diameter],
    };
    let sweep = Sweep {
        models,
        lambdas,
        betas_deg,
        u_ns,
        diameters,
    };
    sweep.validate()?;
    for &d in &sweep.diameters {
        Particle { diameter: d, ..p }.validate()?;
    }
    Ok((p, sweep))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_hu_case_resolves() {
        for name in [
            "hu-fig4",
            "hu-fig6",
            "hu-fig8",
            "hu-fig9",
            "hu-fig10",
            "hu-fig10b",
            "hu-fig11",
            "hu-fig11b",
            "hu-fig12",
        ] {
            let path = std::path::PathBuf::from(format!("cases/{name}.toml"));
            let (text, origin) = super::super::load_text(Some(&path), "").unwrap();
            let case = super::super::parse(&text, &origin).unwrap();
            let (p, s) = resolve(&case).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(p.validate().is_ok() && !s.is_empty(), "{name}");
        }
    }
}
