//! What `rebound deterministic` (and `calibrate`) resolve from a case: the `[deterministic]`
//! options, the scene, the surface plan and what to tally
//! (Radenkovic & Simonin 2021, Sec. 3.1–3.3, 3.5, 4).

use super::{Case, Scene, WallSource};
use crate::runner::TallyOverrides;
use roughwall::check::{check_int_range, check_range, check_value};
use roughwall::deterministic::{tally_spec, ModelSetup, DEFAULT_MAX_COLLISIONS};
use roughwall::deterministic::{ScanReference, SceneOptions, SurfacePlan, WallDeviations};
use roughwall::tally::TallySpec;
use roughwall::ErosionSetup;
use roughwall::Triangulation;
use roughwall::Warning;
use roughwall::{Error, Result};
use std::path::Path;

/// Flattest incident angle the tracker is asked to follow (degrees): a descent from the top
/// of a shipped surface to its bottom at this angle takes some 2 · 10⁵ cells, well within
/// the step budget (`deterministic::trace::MAX_STEPS`).
pub const MIN_ABS_ALPHA_DEG: f64 = 1e-3;

/// Largest accepted `[deterministic] max_collisions`.
const MAX_COLLISIONS_LIMIT: i64 = 1_000_000;

/// Largest accepted `[deterministic] surfaces` (each realisation is held in memory).
pub const MAX_SURFACES: i64 = 1024;

/// The `[deterministic]` section, validated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeterministicOptions {
    pub max_collisions: u32,
    pub scene: SceneOptions,
    /// A sphere of this diameter (m) bounces (its centre on the dilated surface);
    /// `None`: the particle centre bounces on the surface (the paper's).
    pub sphere_diameter_m: Option<f64>,
    /// How the surface's cells are split into triangles (`[deterministic] triangulation`).
    pub triangulation: Triangulation,
    /// Independent surface realisations (`[deterministic] surfaces`, default 1).
    pub surfaces: u32,
    /// What a measured scan becomes (`[deterministic] scan_wall`).
    pub scan_reference: ScanReference,
    /// The degree a measured scan is levelled by (`[deterministic] scan_level_degree`).
    pub scan_level_degree: u32,
    /// On a scan in place: one entry region for every direction, that of this `|α⁻|` (rad;
    /// `[deterministic] entry_alpha_deg`); `None`: the region follows each direction.
    pub entry_alpha: Option<f64>,
}

/// `[deterministic] triangulation`, validated: how the cells of a generated or read surface
/// are split into triangles (`deterministic`, `calibrate`, and `surface`'s statistics).
pub fn triangulation(case: &Case) -> Result<Triangulation> {
    let given = case
        .deterministic
        .as_ref()
        .and_then(|d| d.triangulation.as_deref());
    let names = Triangulation::NAMES;
    let k = check_value(
        "deterministic.triangulation",
        given.unwrap_or(Triangulation::default().name()),
        &names,
        "\"alternating\" (the diagonal alternates between neighbouring cells, mirror symmetric; the default) or \"uniform\" (every cell split along the same diagonal, the earlier default)",
    )?;
    Triangulation::from_name(names[k])
        .ok_or_else(|| Error::Internal(format!("triangulation `{}`", names[k])))
}

/// Validates `[deterministic]` (keys named in one-line errors); `height_file`: the run reads
/// its surface from a file (`--surface`), which gives the roughness's absolute scale.
pub fn deterministic_options(case: &Case, height_file: bool) -> Result<DeterministicOptions> {
    let d = case.deterministic.clone().unwrap_or_default();
    let mc = d.max_collisions.unwrap_or(DEFAULT_MAX_COLLISIONS as i64);
    let mc = check_int_range(
        "deterministic.max_collisions",
        mc,
        1,
        MAX_COLLISIONS_LIMIT,
        "an integer from 1 to 1000000",
    )?;
    let def = SceneOptions::default();
    let spc = d
        .spacing_per_corr_length
        .unwrap_or(def.spacing_per_corr_length);
    let spc = check_range(
        "deterministic.spacing_per_corr_length",
        spc,
        1.0,
        64.0,
        "a number from 1 to 64",
    )?;
    let side = d.side_per_corr_length.unwrap_or(def.side_per_corr_length);
    let side = check_range(
        "deterministic.side_per_corr_length",
        side,
        1.0,
        10_000.0,
        "a number from 1 to 10000",
    )?;
    let h_um = d.rms_height_um.unwrap_or(def.rms_height_m * 1e6);
    // A picometre to a metre: the scale of a sphere's contact (and far from overflow in
    // the squared heights of the statistics).
    let h_um = check_range(
        "deterministic.rms_height_um",
        h_um,
        1e-6,
        1e6,
        "1e-6 to 1000000 µm (a picometre to a metre)",
    )?;
    let contact = d.contact.as_deref().unwrap_or("centre");
    let sphere = check_value(
        "deterministic.contact",
        contact,
        &["centre", "sphere"],
        "\"centre\" (the particle centre bounces) or \"sphere\" (a sphere of [particles] diameter_um)",
    )? == 1;
    // A sphere needs the roughness's absolute scale: the automatic surface's height from
    // `[deterministic] rms_height_um` or the wall's `rms_height_um` (or a [surface], or a
    // height file: then the grid is given).
    let wall_h = case.wall.as_ref().and_then(|w| w.rms_height_um);
    let h_um = if sphere && d.rms_height_um.is_none() {
        match wall_h {
            Some(h) => h,
            None if case.surface.is_some() || height_file => h_um,
            None => {
                return Err(Error::Input(
                    "[deterministic] contact = \"sphere\" needs the roughness's absolute scale: set `deterministic.rms_height_um` (or `wall.rms_height_um` with correlation lengths, or give a [surface] or --surface)".into(),
                ))
            }
        }
    } else {
        h_um
    };
    let sphere_diameter_m = if sphere {
        let p = case.particles.clone().unwrap_or_default();
        let d_um = p.diameter_um.ok_or_else(|| {
            Error::Input(
                "[deterministic] contact = \"sphere\" needs `particles.diameter_um`, the sphere's diameter".into(),
            )
        })?;
        Some(d_um * 1e-6)
    } else {
        None
    };
    let triangulation = triangulation(case)?;
    let names = WallDeviations::NAMES;
    let k = check_value(
        "deterministic.wall_deviations",
        d.wall_deviations
            .as_deref()
            .unwrap_or(WallDeviations::default().name()),
        &names,
        "\"normal-angles\" ([wall]'s deviations are those of the generated triangles' normal angles, as the models and `scan` take them; the default) or \"eq15\" (c_L = √2 h/Δ as the papers build their walls: the triangles have 0.3–2.1 % less)",
    )?;
    let deviations = WallDeviations::from_name(names[k])
        .ok_or_else(|| Error::Internal(format!("wall_deviations `{}`", names[k])))?;
    let surfaces = check_int_range(
        "deterministic.surfaces",
        d.surfaces.unwrap_or(1),
        1,
        MAX_SURFACES,
        "an integer from 1 to 1024 (independent surface realisations the histories are spread over)",
    )?;
    let names = ScanReference::NAMES;
    let k = check_value(
        "deterministic.scan_wall",
        d.scan_wall
            .as_deref()
            .unwrap_or(ScanReference::default().name()),
        &names,
        "\"in-place\" (a scan given as --surface is bounced on as measured, the incident direction turned by its lay; the default) or \"mirrored\" (turned to its lay, resampled and mirror-tiled into a periodic wall, the earlier reference)",
    )?;
    let scan_reference = ScanReference::from_name(names[k])
        .ok_or_else(|| Error::Internal(format!("scan_wall `{}`", names[k])))?;
    let scan_level_degree = check_int_range(
        "deterministic.scan_level_degree",
        d.scan_level_degree.unwrap_or(1),
        1,
        3,
        "1 (a plane), 2 or 3: the total degree of the polynomial form removed from a scan given as --surface",
    )? as u32;
    let entry_alpha = match d.entry_alpha_deg {
        None => None,
        Some(a) => {
            if scan_reference != ScanReference::InPlace {
                return Err(Error::Input(format!(
                    "deterministic.entry_alpha_deg = {a}: only for a scan bounced on in place (scan_wall = \"in-place\"); the mirrored wall is periodic and has no entry region"
                )));
            }
            let a = check_range(
                "deterministic.entry_alpha_deg",
                a,
                MIN_ABS_ALPHA_DEG,
                90.0,
                "an angle |α⁻| from 0.001 to 90 degrees whose margins fix one entry region for every direction of a scan in place",
            )?;
            Some(a.to_radians())
        }
    };
    Ok(DeterministicOptions {
        max_collisions: mc as u32,
        triangulation,
        surfaces: surfaces as u32,
        scan_reference,
        scan_level_degree,
        entry_alpha,
        scene: SceneOptions {
            spacing_per_corr_length: spc,
            side_per_corr_length: side,
            rms_height_m: h_um * 1e-6,
            deviations,
        },
        sphere_diameter_m,
    })
}

/// The plan for a scene: its `[surface]` as given, or chosen from the deviations.
pub fn surface_plan(scene: &Scene, opt: &SceneOptions) -> Result<SurfacePlan> {
    match &scene.wall {
        WallSource::Surface(spec) => Ok(SurfacePlan::Case(spec.clone())),
        WallSource::Deviations(d) => SurfacePlan::auto(d.delta_xi, d.delta_zeta, opt),
    }
}

/// What a deterministic run resolves from its case before the surface is built.
pub struct Prepared {
    pub scene: Scene,
    pub options: DeterministicOptions,
    pub setup: ModelSetup,
    pub specs: Vec<TallySpec>,
    /// Where the surface comes from (`None`: a height file).
    pub surface: Option<SurfacePlan>,
    /// Manifest entries that follow from the case alone (notes).
    pub notes: toml::Table,
    /// Warnings of the resolution, for the command to print.
    pub warnings: Vec<Warning>,
}

/// Resolves the scene, the tracker options, the surface plan and what to tally.
/// `surface_file`: a height file given with `--surface` (replaces the generated surface;
/// the case's wall then only labels the deviations).
pub fn prepare(case: &Case, o: &TallyOverrides, surface_file: Option<&Path>) -> Result<Prepared> {
    let mut warnings = Vec::new();
    let mut scene = case.scene(&mut warnings)?;
    scene.set_count(o.particles)?;
    scene.set_target_se(o.target_se)?;
    let options = deterministic_options(case, surface_file.is_some())?;
    // Flatter than this, every history would exhaust the tracker's step budget.
    if let Some(c) = scene
        .conditions
        .iter()
        .find(|c| c.alpha_in_deg().abs() < MIN_ABS_ALPHA_DEG)
    {
        return Err(Error::invalid(
            "incidence.alpha_deg",
            c.alpha_in_deg(),
            &format!(
                "|α⁻| ≥ {MIN_ABS_ALPHA_DEG}° for the deterministic model (the grazing limit its step budget follows; the stochastic model takes any angle)"
            ),
        ));
    }
    let surface = match surface_file {
        Some(path) if options.surfaces > 1 => {
            return Err(Error::Input(format!(
                "`deterministic.surfaces` = {} needs generated surfaces, but --surface `{}` gives one: remove the key or the option",
                options.surfaces,
                path.display()
            )))
        }
        Some(_) => None,
        None => Some(surface_plan(&scene, &options.scene)?),
    };
    let dev = scene.wall.deviations();
    let mut notes = toml::Table::new();
    if scene.conditions.iter().any(|c| c.alpha_in_deg() == -90.0) {
        notes.insert(
            "notes".into(),
            toml::Value::String("normal incidence (α⁻ = −90°) has no incident plane: β⁻ is taken as 0° (docs/physics.md §1)".into()),
        );
    }
    let setup = ModelSetup {
        law: scene.law,
        diameter_m: scene.diameter_m,
        speed: scene.speed,
        spin: scene.spin,
        erosion: scene.erosion.map(|model| ErosionSetup {
            model,
            particle_mass_kg: scene.particle_mass_kg(),
            diameter_m: scene.diameter_m,
        }),
        wall: dev,
        psi: scene.psi,
    };
    // A scan in place is one realisation: its sub-patches are the clusters of its errors.
    let clusters = match surface_file {
        Some(path) if walks_in_place(path, &options) => roughwall::deterministic::SUB_PATCHES,
        _ => options.surfaces,
    };
    let specs = scene
        .conditions
        .iter()
        .map(|c| {
            tally_spec(&dev, *c, scene.bin_width_deg, setup.erosion.as_ref())
                .with_realisations(clusters)
        })
        .collect();
    Ok(Prepared {
        scene,
        options,
        setup,
        specs,
        surface,
        notes,
        warnings,
    })
}

/// Whether `path` is a measured scan that the run walks in place (not a height file of
/// `rebound surface --heights`, and `[deterministic] scan_wall` not `"mirrored"`): its
/// tallies then take the scan's sub-patches as clusters
/// ([`roughwall::deterministic::SUB_PATCHES`]).
fn walks_in_place(path: &std::path::Path, opt: &DeterministicOptions) -> bool {
    path.is_file()
        && !roughwall::surface::is_height_file(path)
        && opt.scan_reference == roughwall::deterministic::ScanReference::InPlace
}

#[cfg(test)]
mod tests {
    use super::*;
    use roughwall::CollisionLaw;

    /// The shipped case `configs/cases/<name>.toml`.
    fn shipped(name: &str) -> Case {
        let path = std::path::PathBuf::from(format!("cases/{name}.toml"));
        let (text, origin) = super::super::load_text(Some(&path), "").unwrap();
        super::super::parse(&text, &origin).unwrap()
    }

    #[test]
    fn shipped_cases_resolve() {
        use roughwall::deterministic::SurfacePlan;
        for name in [
            "aniso",
            "aniso-rev",
            "glass-steel",
            "glass-steel-2d",
            "glass-steel-iso",
            "glass-steel-fig16",
            "glass-steel-fig16-2d",
            "glass-steel-fig17",
            "glass-steel-fig17-2d",
        ] {
            let case = shipped(name);
            assert_eq!(case.name, name);
            let scene = case.scene(&mut Vec::new()).unwrap();
            let opt = deterministic_options(&case, false).unwrap();
            let plan = surface_plan(&scene, &opt.scene).unwrap();
            assert!(matches!(plan, SurfacePlan::Auto(_)));
            if name.starts_with("glass") {
                assert!(matches!(scene.law, CollisionLaw::SommerfeldHuber(_)));
                assert_eq!(scene.speed.mean_m_s, 5.91);
            }
        }
    }
}
