//! `[erosion]`: the erosion law of a case, validated. Each model takes only its own keys;
//! a key of another model, a missing required key or a value out of range is a one-line
//! error naming it.

use super::schema::{Case, ErosionSection};
use roughwall::check::within;
use roughwall::erosion::Finnie;
use roughwall::erosion::OkaInput;
use roughwall::erosion::{AngleDependency, Dnv};
use roughwall::ErosionModel;
use roughwall::{Error, Result};

/// Finnie's `K` and `ψ` (dimensionless ratios): OpenFOAM's default for both is 2.
const FINNIE_RATIO_RANGE: (f64, f64) = (1e-3, 1e3);
/// Flow stresses (Pa): from soft polymers to the hardest ceramics.
const FLOW_STRESS_RANGE_PA: (f64, f64) = (1e3, 1e13);
/// Densities of wall materials (kg/m³).
const TARGET_DENSITY_RANGE: (f64, f64) = (10.0, 3e4);
/// Vickers hardness (GPa).
const HARDNESS_RANGE_GPA: (f64, f64) = (1e-3, 100.0);

/// The keys each model takes (besides `model`).
fn keys_of(model: &str) -> &'static [&'static str] {
    match model {
        "finnie" => &["flow_stress_pa", "psi", "k"],
        "dnv" => &["k", "n", "target_density_kg_m3", "angle_dependency"],
        _ => &[
            "hardness_gpa",
            "k",
            "k1",
            "k2",
            "k3",
            "n1",
            "n2",
            "reference_speed_m_s",
            "reference_diameter_um",
        ],
    }
}

/// The keys given in the section (besides `model`).
fn given(e: &ErosionSection) -> Vec<&'static str> {
    let f = [
        ("flow_stress_pa", e.flow_stress_pa.is_some()),
        ("psi", e.psi.is_some()),
        ("k", e.k.is_some()),
        ("n", e.n.is_some()),
        ("target_density_kg_m3", e.target_density_kg_m3.is_some()),
        ("angle_dependency", e.angle_dependency.is_some()),
        ("hardness_gpa", e.hardness_gpa.is_some()),
        ("k1", e.k1.is_some()),
        ("k2", e.k2.is_some()),
        ("k3", e.k3.is_some()),
        ("n1", e.n1.is_some()),
        ("n2", e.n2.is_some()),
        ("reference_speed_m_s", e.reference_speed_m_s.is_some()),
        ("reference_diameter_um", e.reference_diameter_um.is_some()),
    ];
    f.into_iter().filter(|k| k.1).map(|k| k.0).collect()
}

fn exponent(key: &str, v: Option<f64>) -> Result<Option<f64>> {
    v.map(|v| within(key, v, -10.0, 10.0, "", "an exponent of Oka's law"))
        .transpose()
}

impl Case {
    /// The erosion law of `[erosion]`, or `None` without the section.
    pub fn erosion_model(&self) -> Result<Option<ErosionModel>> {
        let Some(e) = &self.erosion else {
            return Ok(None);
        };
        let model = e.model.as_deref().ok_or_else(|| {
            Error::Input(
                "[erosion] needs `model` = \"finnie\", \"dnv\" or \"oka\" (docs/cases.md)".into(),
            )
        })?;
        if !matches!(model, "finnie" | "dnv" | "oka") {
            return Err(Error::invalid(
                "erosion.model",
                format!("\"{model}\""),
                "\"finnie\", \"dnv\" or \"oka\"",
            ));
        }
        let keys = keys_of(model);
        if let Some(k) = given(e).into_iter().find(|k| !keys.contains(k)) {
            return Err(Error::Input(format!(
                "`erosion.{k}` is not a key of model = \"{model}\" (its keys: {})",
                keys.join(", ")
            )));
        }
        let m = match model {
            "finnie" => {
                let p = e.flow_stress_pa.ok_or_else(|| {
                    Error::Input(
                        "[erosion] model = \"finnie\" needs `flow_stress_pa`, the wall's plastic flow stress p in Pa".into(),
                    )
                })?;
                let (lo, hi) = FLOW_STRESS_RANGE_PA;
                let (rlo, rhi) = FINNIE_RATIO_RANGE;
                ErosionModel::Finnie(Finnie {
                    flow_stress_pa: within(
                        "erosion.flow_stress_pa",
                        p,
                        lo,
                        hi,
                        " Pa",
                        "a flow stress; steels are about 1e9",
                    )?,
                    psi: within(
                        "erosion.psi",
                        e.psi.unwrap_or(2.0),
                        rlo,
                        rhi,
                        "",
                        "contact depth over cut depth; OpenFOAM's default is 2",
                    )?,
                    k: within(
                        "erosion.k",
                        e.k.unwrap_or(2.0),
                        rlo,
                        rhi,
                        "",
                        "vertical over horizontal force; OpenFOAM's default is 2",
                    )?,
                })
            }
            "dnv" => {
                // Defaults: carbon steel, K = 2e-9 (m/s)^-n, n = 2.6, ρ_t = 7800 kg/m³, the
                // RP-O501 steel constants as pysand's `material_dict['carbon_steel']` holds them
                // (tests/data/dnv_pysand.csv, first rows).
                let angle_dependency = match e.angle_dependency.as_deref() {
                    None | Some("ductile") => AngleDependency::Ductile,
                    Some("brittle") => AngleDependency::Brittle,
                    Some(other) => {
                        return Err(Error::invalid(
                            "erosion.angle_dependency",
                            format!("\"{other}\""),
                            "\"ductile\" or \"brittle\"",
                        ))
                    }
                };
                let (lo, hi) = TARGET_DENSITY_RANGE;
                ErosionModel::Dnv(Dnv {
                    k: within(
                        "erosion.k",
                        e.k.unwrap_or(2e-9),
                        1e-15,
                        1e-3,
                        " (m/s)^-n",
                        "RP-O501's material constant; steels 2e-9",
                    )?,
                    n: within(
                        "erosion.n",
                        e.n.unwrap_or(2.6),
                        0.1,
                        10.0,
                        "",
                        "RP-O501's velocity exponent; steels 2.6",
                    )?,
                    target_density_kg_m3: within(
                        "erosion.target_density_kg_m3",
                        e.target_density_kg_m3.unwrap_or(7800.0),
                        lo,
                        hi,
                        " kg/m³",
                        "the wall material's density",
                    )?,
                    angle_dependency,
                })
            }
            _ => {
                let hv = e.hardness_gpa.ok_or_else(|| {
                    Error::Input(
                        "[erosion] model = \"oka\" needs `hardness_gpa`, the wall's Vickers hardness in GPa".into(),
                    )
                })?;
                let (lo, hi) = HARDNESS_RANGE_GPA;
                let input = OkaInput {
                    hardness_gpa: within(
                        "erosion.hardness_gpa",
                        hv,
                        lo,
                        hi,
                        " GPa",
                        "a Vickers hardness; steels 1.5 to 8",
                    )?,
                    k: e.k
                        .map(|k| {
                            within(
                                "erosion.k",
                                k,
                                1e-6,
                                1e6,
                                " mm³/kg",
                                "Oka's particle factor; SiO2 65",
                            )
                        })
                        .transpose()?,
                    k1: exponent("erosion.k1", e.k1)?,
                    k2: exponent("erosion.k2", e.k2)?,
                    k3: exponent("erosion.k3", e.k3)?,
                    n1: exponent("erosion.n1", e.n1)?,
                    n2: exponent("erosion.n2", e.n2)?,
                    reference_speed_m_s: e
                        .reference_speed_m_s
                        .map(|v| {
                            within(
                                "erosion.reference_speed_m_s",
                                v,
                                1e-3,
                                1e4,
                                " m/s",
                                "Oka's U'; 104 for SiO2",
                            )
                        })
                        .transpose()?,
                    reference_diameter_m: e
                        .reference_diameter_um
                        .map(|v| {
                            within(
                                "erosion.reference_diameter_um",
                                v,
                                1e-3,
                                1e6,
                                " µm",
                                "Oka's D'; 326 for SiO2",
                            )
                            .map(|d| d * 1e-6)
                        })
                        .transpose()?,
                };
                ErosionModel::Oka(input.resolve())
            }
        };
        Ok(Some(m))
    }
}

#[cfg(test)]
mod tests {
    use crate::case::parse;

    fn model(text: &str) -> roughwall::Result<Option<roughwall::ErosionModel>> {
        parse(&format!("name = \"t\"\n{text}"), "t.toml")
            .unwrap()
            .erosion_model()
    }

    fn err(text: &str) -> String {
        model(text).unwrap_err().to_string()
    }

    #[test]
    fn no_section_no_model() {
        assert_eq!(model("").unwrap(), None);
    }

    #[test]
    fn non_positive_k_or_flow_stress_are_errors_naming_the_key() {
        for (text, key) in [
            (
                "model = \"finnie\"\nflow_stress_pa = 0",
                "erosion.flow_stress_pa",
            ),
            (
                "model = \"finnie\"\nflow_stress_pa = -1e9",
                "erosion.flow_stress_pa",
            ),
            (
                "model = \"finnie\"\nflow_stress_pa = 1e9\nk = 0",
                "erosion.k",
            ),
            (
                "model = \"finnie\"\nflow_stress_pa = 1e9\nk = -2",
                "erosion.k",
            ),
            (
                "model = \"finnie\"\nflow_stress_pa = 1e9\npsi = 0",
                "erosion.psi",
            ),
            ("model = \"dnv\"\nk = 0", "erosion.k"),
            ("model = \"oka\"\nhardness_gpa = 0", "erosion.hardness_gpa"),
            ("model = \"oka\"\nhardness_gpa = 1\nk = -65", "erosion.k"),
        ] {
            let e = err(&format!("[erosion]\n{text}"));
            assert!(e.contains(&format!("`{key}`")) && !e.contains('\n'), "{e}");
        }
    }

    #[test]
    fn missing_and_foreign_keys_are_named() {
        assert!(err("[erosion]\nflow_stress_pa = 1e9").contains("`model`"));
        assert!(err("[erosion]\nmodel = \"finnie\"").contains("flow_stress_pa"));
        assert!(err("[erosion]\nmodel = \"oka\"").contains("hardness_gpa"));
        let e = err("[erosion]\nmodel = \"finnie\"\nflow_stress_pa = 1e9\nn = 2.6");
        assert!(
            e.contains("`erosion.n`") && e.contains("flow_stress_pa, psi, k"),
            "{e}"
        );
        assert!(err("[erosion]\nmodel = \"grit\"").contains("\"finnie\", \"dnv\" or \"oka\""));
        let e = err("[erosion]\nmodel = \"dnv\"\nangle_dependency = \"soft\"");
        assert!(e.contains("erosion.angle_dependency"), "{e}");
        // Unknown keys: the loader's error.
        let e = parse("name = \"t\"\n[erosion]\nmodel = \"dnv\"\nkk = 1", "t.toml").unwrap_err();
        assert!(e.to_string().contains("kk"), "{e}");
    }

    #[test]
    fn defaults_are_openfoams_and_rp_o501s() {
        use roughwall::ErosionModel::*;
        match model("[erosion]\nmodel = \"finnie\"\nflow_stress_pa = 1e9").unwrap() {
            Some(Finnie(f)) => assert_eq!((f.psi, f.k), (2.0, 2.0)),
            m => panic!("{m:?}"),
        }
        match model("[erosion]\nmodel = \"dnv\"").unwrap() {
            Some(Dnv(d)) => assert_eq!((d.k, d.n, d.target_density_kg_m3), (2e-9, 2.6, 7800.0)),
            m => panic!("{m:?}"),
        }
        match model("[erosion]\nmodel = \"oka\"\nhardness_gpa = 1.5\nreference_diameter_um = 200")
            .unwrap()
        {
            Some(Oka(o)) => {
                assert_eq!(o.k, 65.0);
                assert!((o.reference_diameter_m - 200e-6).abs() < 1e-18);
            }
            m => panic!("{m:?}"),
        }
    }
}
