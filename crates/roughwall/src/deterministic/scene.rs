//! The surface a deterministic scene needs when the case gives only the
//! normal-angle deviations `Δξ`, `Δζ` of the wall.
//!
//! Radenkovic & Simonin 2021, Eq. (15): `Δ = √2 h / c_L` to first order, so only `h / c_L`
//! matters; the rms height is arbitrary (elastic bouncing has no length scale,
//! and Sommerfeld–Huber only the particle diameter in the spin, which drops out of
//! the contact-point velocity `u + (D/2) ω`). The grid spacing and the side are
//! chosen from the correlation lengths: spacing `≤ c_L,min / spacing_per_corr_length`,
//! side `≥ side_per_corr_length · c_L,max`, with an FFT-friendly node count.
//!
//! What the deviations mean ([`WallDeviations`]): by default the standard deviations of the
//! normal's angles over the generated triangles, as the models and `scan` take them, so the
//! correlation lengths are those whose grid gives the triangles the deviations wanted
//! ([`crate::surface::normal_angles`]); `Eq15` takes `c_L = √2 h/Δ` as the paper does, and
//! its triangles have 0.3–2.1 % less.

use super::{Realisations, Tracker};
use crate::error::{Error, Result};
use crate::surface::heights_io::read_heights;
use crate::surface::{generate, HeightField, SurfaceSpec, Triangulation};
use crate::wall::Deviations;
use std::path::Path;

/// Knobs of the choice (case section `[deterministic]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneOptions {
    /// Correlation lengths per grid spacing along the shorter correlation length.
    pub spacing_per_corr_length: f64,
    /// Side of the surface in units of the longer correlation length.
    pub side_per_corr_length: f64,
    /// RMS height (m), arbitrary.
    pub rms_height_m: f64,
    /// What the deviations the surface is built from mean.
    pub deviations: WallDeviations,
}

/// How `choose_surface` reads the deviations it is given (`[deterministic] wall_deviations`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WallDeviations {
    /// The standard deviations of the normal's angles `ξ'`, `ζ'` over the triangles the
    /// particles meet (Radenkovic & Simonin 2021, Eqs. 4, 7 at `β* = 0`): what the stochastic
    /// models draw from, what `surface`, `deterministic` and `scan` measure. The correlation
    /// lengths are chosen so that the generated grid has them on average.
    #[default]
    NormalAngles,
    /// Eq. (15) taken as exact, `c_L = √2 h/Δ`, as the papers build their walls: the
    /// triangles have 0.3–2.1 % less (finite differences over `δ`, angles below slopes).
    Eq15,
}

impl WallDeviations {
    /// Names in case files, in the order of [`WallDeviations::from_name`].
    pub const NAMES: [&'static str; 2] = ["normal-angles", "eq15"];

    /// The case-file name.
    pub fn name(self) -> &'static str {
        match self {
            WallDeviations::NormalAngles => "normal-angles",
            WallDeviations::Eq15 => "eq15",
        }
    }

    /// The variant of a case-file name.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "normal-angles" => Some(WallDeviations::NormalAngles),
            "eq15" => Some(WallDeviations::Eq15),
            _ => None,
        }
    }
}

impl Default for SceneOptions {
    fn default() -> Self {
        SceneOptions {
            spacing_per_corr_length: 8.0,
            side_per_corr_length: 100.0,
            rms_height_m: 1e-6,
            deviations: WallDeviations::NormalAngles,
        }
    }
}

/// Largest node count per side the automatic choice accepts (64 Mi nodes).
pub const MAX_NODES: usize = 8192;

/// A 2-D-roughness profile (one grid line) is this many times longer than a square wall's side.
pub const ONE_D_SIDE_FACTOR: f64 = 100.0;

/// Node limit of such a profile (one line: memory is no concern).
pub const MAX_NODES_ONE_D: usize = 4_000_000;

/// Smallest `n ≥ target` whose only prime factors are 2, 3 and 5.
pub fn next_smooth(target: usize) -> usize {
    let mut n = target.max(1);
    loop {
        let mut m = n;
        for p in [2, 3, 5] {
            while m.is_multiple_of(p) {
                m /= p;
            }
        }
        if m == 1 {
            return n;
        }
        n += 1;
    }
}

/// The surface for deviations `delta_xi`, `delta_zeta` (rad).
///
/// The node count is a multiple of 8 (for the tracker's tile map) times a
/// 5-smooth number. A smooth wall (both deviations zero) gets a small flat grid.
pub fn choose_surface(
    delta_xi: f64,
    delta_zeta: f64,
    opt: &SceneOptions,
) -> std::result::Result<SurfaceSpec, String> {
    for (key, v) in [("delta_xi_deg", delta_xi), ("delta_zeta_deg", delta_zeta)] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(format!(
                "invalid `{key}` = {}: allowed finite values ≥ 0",
                v.to_degrees()
            ));
        }
    }
    if !(opt.spacing_per_corr_length.is_finite() && opt.spacing_per_corr_length >= 1.0) {
        return Err(format!(
            "invalid `deterministic.spacing_per_corr_length` = {}: allowed ≥ 1",
            opt.spacing_per_corr_length
        ));
    }
    if !(opt.side_per_corr_length.is_finite() && opt.side_per_corr_length >= 1.0) {
        return Err(format!(
            "invalid `deterministic.side_per_corr_length` = {}: allowed ≥ 1",
            opt.side_per_corr_length
        ));
    }
    if !(opt.rms_height_m.is_finite() && opt.rms_height_m > 0.0) {
        return Err(format!(
            "invalid `deterministic.rms_height_um` = {}: allowed > 0",
            opt.rms_height_m * 1e6
        ));
    }
    let h = opt.rms_height_m;
    // The continuous rms slopes √2 h/c_L (Eq. 14) the wall is generated with.
    let slopes = match opt.deviations {
        WallDeviations::Eq15 => [delta_xi, delta_zeta],
        WallDeviations::NormalAngles => crate::surface::normal_angles::slopes_for_deviations(
            Deviations {
                delta_xi,
                delta_zeta,
            },
            opt.spacing_per_corr_length,
        )
        .ok_or_else(|| {
            format!(
                "no generated wall has normal-angle deviations ({}°, {}°): allowed 0 to 20 degrees each",
                delta_xi.to_degrees(),
                delta_zeta.to_degrees()
            )
        })?,
    };
    let cx = crate::wall::corr_length_from_deviation(h, slopes[0]);
    let cz = crate::wall::corr_length_from_deviation(h, slopes[1]);
    let cs: Vec<f64> = [cx, cz].into_iter().flatten().collect();
    if cs.is_empty() {
        // Smooth wall: any grid will do.
        let nodes = 16;
        let spacing = h;
        return Ok(SurfaceSpec {
            length_m: nodes as f64 * spacing,
            nodes,
            rms_height_m: 0.0,
            corr_length_x_m: None,
            corr_length_z_m: None,
        });
    }
    let c_min = cs.iter().copied().fold(f64::INFINITY, f64::min);
    let c_max = cs.iter().copied().fold(0.0, f64::max);
    let spacing = c_min / opt.spacing_per_corr_length;
    // 2-D roughness (Δζ = 0) is one profile along x, stored as a single grid line: it holds
    // only side/c_L independent correlation lengths (a square wall holds their square), so a
    // profile of 100 c_L has its Δξ scatter by about √(c_L/2L) ≈ 7 % between seeds, enough to
    // shift the angle PDFs visibly. One line is cheap, so make it ONE_D_SIDE_FACTOR longer.
    let one_d = cz.is_none() && cx.is_some();
    let (side, max_nodes) = if one_d {
        (
            opt.side_per_corr_length * ONE_D_SIDE_FACTOR,
            MAX_NODES_ONE_D,
        )
    } else {
        (opt.side_per_corr_length, MAX_NODES)
    };
    // The ratio is exact in theory; forgive the last bits of rounding.
    let target = (side * c_max / spacing * (1.0 - 1e-12)).ceil();
    if target.is_nan() || target > max_nodes as f64 {
        return Err(format!(
            "the wall needs {target} nodes per side (> {max_nodes}) for spacing c_L,min/{} and side {}·c_L,max: \
             lower `deterministic.spacing_per_corr_length` or `deterministic.side_per_corr_length`",
            opt.spacing_per_corr_length, side
        ));
    }
    let nodes = 8 * next_smooth((target as usize).div_ceil(8));
    let spec = SurfaceSpec {
        length_m: nodes as f64 * spacing,
        nodes,
        rms_height_m: h,
        corr_length_x_m: cx,
        corr_length_z_m: cz,
    };
    crate::memory::require(
        "deterministic.side_per_corr_length",
        opt.side_per_corr_length,
        crate::surface::generate::generation_bytes(&spec),
        &format!("the automatic {nodes}-node surface"),
    )
    .map_err(|e| e.to_string())?;
    Ok(spec)
}

/// Where the surface of a run comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum SurfacePlan {
    /// Generated from the case's `[surface]` grid as given.
    Case(SurfaceSpec),
    /// Chosen from the deviations (`[wall]`) by [`choose_surface`].
    Auto(SurfaceSpec),
}

impl SurfacePlan {
    /// The plan for deviations `delta_xi`, `delta_zeta` (rad): [`choose_surface`].
    pub fn auto(delta_xi: f64, delta_zeta: f64, opt: &SceneOptions) -> Result<SurfacePlan> {
        choose_surface(delta_xi, delta_zeta, opt)
            .map(SurfacePlan::Auto)
            .map_err(Error::Input)
    }

    /// The grid and roughness to generate.
    pub fn spec(&self) -> &SurfaceSpec {
        match self {
            SurfacePlan::Case(s) | SurfacePlan::Auto(s) => s,
        }
    }

    /// `surface_choice.source` of `run.toml`.
    pub fn source(&self) -> &'static str {
        match self {
            SurfacePlan::Case(_) => "case",
            SurfacePlan::Auto(_) => "auto",
        }
    }
}

/// Generates the planned surface with the Garcia–Stoll generator of `crate::surface`
/// (Radenkovic & Simonin 2021, Eqs. 1–2).
/// `triangulation` is how the tracker and the statistics split its cells.
pub fn generate_surface(
    plan: &SurfacePlan,
    seed: u64,
    triangulation: Triangulation,
) -> Result<HeightField> {
    let mut field = generate(plan.spec(), seed);
    field.triangulation = triangulation;
    Ok(field)
}

/// The seed of surface realisation `r` of a run seeded `seed` (`[deterministic] surfaces`):
/// realisation 0 is the run's own surface, so one realisation is the run without the key;
/// the others come from their own stream, `rng::stream(seed, &[SURFACE_REALISATION, r])`.
pub fn realisation_seed(seed: u64, r: u32) -> u64 {
    use rand::RngCore;
    match r {
        0 => seed,
        _ => crate::rng::stream(seed, &[crate::rng::domain::SURFACE_REALISATION, r as u64])
            .next_u64(),
    }
}

/// Refuses `surfaces` realisations of `plan` that would not fit in memory together: all are
/// kept (a sphere's dilated copy instead of the surface), and one generation's work space
/// is needed on top — and, for a sphere, the dilation's (`surface::dilation::BYTES_PER_NODE`
/// a node) beside the last surface.
pub fn require_realisations(plan: &SurfacePlan, surfaces: u32, sphere: bool) -> Result<()> {
    use crate::surface::generate::{field_bytes, generation_bytes};
    let spec = plan.spec();
    let field = field_bytes(spec);
    let dilation = match sphere {
        true => field + field / 8 * crate::surface::dilation::BYTES_PER_NODE,
        false => 0,
    };
    let bytes = (surfaces.max(1) as u64 - 1)
        .saturating_mul(field)
        .saturating_add(generation_bytes(spec))
        .saturating_add(dilation);
    crate::memory::require(
        "deterministic.surfaces",
        surfaces,
        bytes,
        &format!("{surfaces} realisations of the {}-node surface", spec.nodes),
    )
}

/// The trackers of built realisations ([`Realisations`]): a tracker refusing a generated
/// surface is a bug (internal error), one refusing a height file names the file.
pub fn realisations<'a>(
    built: &'a [BuiltSurface],
    max_collisions: u32,
    file: Option<&Path>,
) -> Result<Realisations<'a>> {
    let trackers = built
        .iter()
        .map(|b| {
            let tracker = match b.in_place_lay {
                Some(lay) => Tracker::in_place(&b.field, max_collisions, lay)
                    .map(|t| t.with_entry_alpha(b.in_place_entry_alpha)),
                None => Tracker::new(&b.field, max_collisions),
            };
            tracker.map_err(|e| match (e, file) {
                (Error::Input(m), Some(path)) => {
                    Error::Input(format!("--surface `{}`: {m}", path.display()))
                }
                (Error::Input(m), None) => Error::Internal(format!("generated surface: {m}")),
                (e, _) => e,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Realisations::new(trackers)
}

/// The `surfaces` realisations of a run, built one after the other with
/// [`realisation_seed`]; a height file is one realisation (`prepare` refuses more).
/// Refused before generating when the realisations would not fit in memory together.
pub fn build_surfaces(
    plan: Option<&SurfacePlan>,
    file: Option<&Path>,
    sphere_diameter_m: Option<f64>,
    seed: u64,
    triangulation: Triangulation,
    surfaces: u32,
) -> Result<Vec<BuiltSurface>> {
    if surfaces > 1 {
        let Some(plan) = plan else {
            return Err(Error::Internal(
                "surface realisations of a height file".into(),
            ));
        };
        require_realisations(plan, surfaces, sphere_diameter_m.is_some())?;
    }
    (0..surfaces)
        .map(|r| {
            let seed = realisation_seed(seed, r);
            build_surface(plan, file, sphere_diameter_m, seed, triangulation)
        })
        .collect()
}

/// Reads a height field saved by `rebound surface --heights FILE`; every problem is a
/// one-line input error naming the file.
pub fn read_surface(path: &Path) -> Result<HeightField> {
    if let Some(kind) = crate::check::not_a_regular_file(path) {
        return Err(Error::Input(format!(
            "--surface file `{}` is {kind}, not a file",
            path.display()
        )));
    }
    if !path.is_file() {
        return Err(Error::Input(format!(
            "--surface file `{}` not found",
            path.display()
        )));
    }
    read_heights(path).map_err(|e| match e {
        Error::Input(m) => Error::Input(format!("--surface {m}")),
        other => other,
    })
}

/// The surface a run tracks on, and how it was made.
pub struct BuiltSurface {
    /// The surface the particle centre rides on (the dilated one for a sphere).
    pub field: HeightField,
    /// `"file"`, `"scan"`, `"case"` or `"auto"`.
    pub source: &'static str,
    /// Time to read or generate the surface (s).
    pub generate_s: f64,
    /// For a sphere: the dilation of the surface.
    pub sphere: Option<SphereDilation>,
    /// A measured scan in place ([`super::in_place`]): its lay angle (rad); the tracker then
    /// takes the field as a non-periodic patch. `None`: a periodic wall.
    pub in_place_lay: Option<f64>,
    /// On a measured scan in place: one entry region for every direction, that of
    /// `|α⁻| = α_e` (rad, [`super::Patch::with_entry_alpha`]); `None`: the region follows
    /// the direction.
    pub in_place_entry_alpha: Option<f64>,
}

impl BuiltSurface {
    /// A measured scan as the in-place reference's wall ([`super::in_place_wall`]); `secs`:
    /// the time to read and characterise the scan.
    pub fn in_place(wall: super::InPlaceWall, secs: f64, dilation_s: f64) -> BuiltSurface {
        BuiltSurface {
            sphere: wall.diameter_m.map(|d| SphereDilation {
                diameter_m: d,
                contact_fraction: wall.contact_fraction.unwrap_or(1.0),
                dilation_s,
            }),
            in_place_lay: Some(wall.lay_angle),
            in_place_entry_alpha: wall.entry_alpha,
            field: wall.field,
            source: "scan",
            generate_s: secs,
        }
    }
}

/// A sphere's centre surface, made from the generated one (`surface::dilation`).
pub struct SphereDilation {
    /// Diameter `D` of the sphere (m) whose centre surface this is.
    pub diameter_m: f64,
    /// Fraction of nodes a resting sphere touches.
    pub contact_fraction: f64,
    /// Wall-clock time to compute the dilation (s).
    pub dilation_s: f64,
}

/// Reads `file` (`--surface`) or generates the planned surface; for a sphere of
/// `sphere_diameter_m`, its centre rides on the dilated surface (paraboloid,
/// `surface::dilation`).
pub fn build_surface(
    plan: Option<&SurfacePlan>,
    file: Option<&Path>,
    sphere_diameter_m: Option<f64>,
    seed: u64,
    triangulation: Triangulation,
) -> Result<BuiltSurface> {
    let t0 = std::time::Instant::now();
    let (field, source) = match (file, plan) {
        (Some(path), _) => (read_surface(path)?, "file"),
        (None, Some(plan)) => (generate_surface(plan, seed, triangulation)?, plan.source()),
        (None, None) => return Err(Error::Internal("no surface plan".into())),
    };
    surface_from_field(
        field,
        source,
        t0.elapsed().as_secs_f64(),
        sphere_diameter_m,
        triangulation,
    )
}

/// A surface made elsewhere (e.g. a measured scan turned into a periodic wall,
/// [`crate::scan::periodic::mirrored_wall`]) as the run's surface: split by
/// `triangulation`, and for a sphere dilated to the surface its centre rides on.
/// `source` names where it came from in the manifest; `generate_s` is the time it took.
pub fn surface_from_field(
    mut field: HeightField,
    source: &'static str,
    generate_s: f64,
    sphere_diameter_m: Option<f64>,
    triangulation: Triangulation,
) -> Result<BuiltSurface> {
    field.triangulation = triangulation;
    let Some(d) = sphere_diameter_m else {
        return Ok(BuiltSurface {
            field,
            source,
            generate_s,
            sphere: None,
            in_place_lay: None,
            in_place_entry_alpha: None,
        });
    };
    let t = std::time::Instant::now();
    let dil = crate::surface::dilation::sphere_centre_surface(&field, d, "contact = \"sphere\"")?;
    Ok(BuiltSurface {
        field: dil.field,
        source,
        generate_s,
        sphere: Some(SphereDilation {
            diameter_m: d,
            contact_fraction: dil.contact_fraction,
            dilation_s: t.elapsed().as_secs_f64(),
        }),
        in_place_lay: None,
        in_place_entry_alpha: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Realisation 0 is the run's own surface; the others are distinct and follow from
    /// the seed alone.
    #[test]
    fn realisation_seeds() {
        assert_eq!(realisation_seed(2021, 0), 2021);
        let seeds: std::collections::BTreeSet<u64> =
            (0..200).map(|r| realisation_seed(2021, r)).collect();
        assert_eq!(seeds.len(), 200);
        assert_eq!(realisation_seed(2021, 5), realisation_seed(2021, 5));
        assert_ne!(realisation_seed(2021, 5), realisation_seed(2022, 5));
    }

    /// Several realisations: different surfaces of one grid, the first the single run's.
    #[test]
    fn built_realisations() {
        let plan = SurfacePlan::auto(
            5f64.to_radians(),
            5f64.to_radians(),
            &SceneOptions {
                side_per_corr_length: 4.0,
                ..SceneOptions::default()
            },
        )
        .unwrap();
        let tri = Triangulation::Alternating;
        let all = build_surfaces(Some(&plan), None, None, 9, tri, 3).unwrap();
        let one = build_surface(Some(&plan), None, None, 9, tri).unwrap();
        assert_eq!(all.len(), 3);
        assert_eq!(all[0].field.heights, one.field.heights);
        assert_ne!(all[1].field.heights, all[0].field.heights);
        assert_ne!(all[2].field.heights, all[1].field.heights);
        assert!(all
            .iter()
            .all(|b| (b.field.nx, b.field.nz) == (one.field.nx, one.field.nz)));
        // Far more realisations than memory holds: refused before generating, naming the key.
        let e = require_realisations(&plan, u32::MAX, false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("deterministic.surfaces"), "{e}");
    }

    #[test]
    fn smooth_numbers() {
        assert_eq!(next_smooth(7), 8);
        assert_eq!(next_smooth(300), 300);
        assert_eq!(next_smooth(301), 320);
        assert_eq!(next_smooth(1), 1);
    }

    #[test]
    fn two_d_roughness_gets_a_long_profile() {
        let c = choose_surface(3.8f64.to_radians(), 0.0, &SceneOptions::default()).unwrap();
        let cx = c.corr_length_x_m.unwrap();
        assert!(c.corr_length_z_m.is_none());
        assert!(c.length_m >= 100.0 * ONE_D_SIDE_FACTOR * cx);
        assert!(c.spacing_m() <= cx / 8.0 * (1.0 + 1e-12));
    }

    #[test]
    fn aniso_wall_gets_fine_spacing_and_large_side() {
        let d = |x: f64| x.to_radians();
        let eq15 = SceneOptions {
            deviations: WallDeviations::Eq15,
            ..SceneOptions::default()
        };
        let c = choose_surface(d(2.5), d(7.5), &eq15).unwrap();
        let cx = c.corr_length_x_m.unwrap();
        let cz = c.corr_length_z_m.unwrap();
        // Eq. (15): c_L = √2 h / Δ, so c_Lx / c_Lz = Δζ / Δξ = 3.
        assert!((cx / cz - 3.0).abs() < 1e-12);
        assert!(c.spacing_m() <= cz / 8.0 * (1.0 + 1e-12));
        assert!(c.length_m >= 100.0 * cx);
        assert_eq!(c.nodes % 8, 0);
        assert_eq!(next_smooth(c.nodes / 8), c.nodes / 8);
        assert_eq!(c.nodes, 2400);
    }

    /// By default the correlation lengths are those whose grid gives the triangles the
    /// deviations asked for: shorter than Eq. (15)'s, most along the rougher axis.
    #[test]
    fn the_default_wall_has_the_deviations_asked_for() {
        let d = |x: f64| x.to_radians();
        let c = choose_surface(d(2.5), d(7.5), &SceneOptions::default()).unwrap();
        let (cx, cz) = (c.corr_length_x_m.unwrap(), c.corr_length_z_m.unwrap());
        let e = crate::surface::normal_angles::expected_deviations(
            c.rms_height_m,
            [Some(cx), Some(cz)],
            c.spacing_m(),
        );
        assert!((e.delta_xi.to_degrees() - 2.5).abs() < 1e-10);
        assert!((e.delta_zeta.to_degrees() - 7.5).abs() < 1e-10);
        let eq15 = |delta: f64| crate::wall::corr_length_from_deviation(c.rms_height_m, d(delta));
        assert!(cx < eq15(2.5).unwrap() * 0.995 && cz < eq15(7.5).unwrap() * 0.985);
        assert!(c.spacing_m() <= cz / 8.0 * (1.0 + 1e-12));
        assert!(c.length_m >= 100.0 * cx);
        // A generated 100-c_L surface measures them within its scatter (~0.4 %).
        let plan = SurfacePlan::auto(d(5.0), d(5.0), &SceneOptions::default()).unwrap();
        let field = generate(plan.spec(), 3);
        let m = crate::surface::stats::measured_deviations(&field);
        assert!((m.delta_xi.to_degrees() / 5.0 - 1.0).abs() < 0.015, "{m:?}");
        assert!(
            (m.delta_zeta.to_degrees() / 5.0 - 1.0).abs() < 0.015,
            "{m:?}"
        );
        // Eq. (15) on the same grid: 1.5 % less, as predicted.
        let plan15 = SurfacePlan::auto(
            d(5.0),
            d(5.0),
            &SceneOptions {
                deviations: WallDeviations::Eq15,
                ..SceneOptions::default()
            },
        )
        .unwrap();
        let m15 = crate::surface::stats::measured_deviations(&generate(plan15.spec(), 3));
        assert!(m15.delta_xi < m.delta_xi && m15.delta_zeta < m.delta_zeta);
        let ratio = m15.delta_xi / m.delta_xi;
        assert!((ratio - 4.9258 / 5.0).abs() < 0.004, "{ratio}");
    }

    #[test]
    fn two_d_and_smooth_walls() {
        let c = choose_surface(3.8f64.to_radians(), 0.0, &SceneOptions::default()).unwrap();
        assert!(c.corr_length_z_m.is_none());
        assert_eq!(c.nodes, 80_000);
        let f = choose_surface(0.0, 0.0, &SceneOptions::default()).unwrap();
        assert_eq!(f.rms_height_m, 0.0);
        assert!(choose_surface(-1.0, 0.0, &SceneOptions::default()).is_err());
        assert!(choose_surface(
            0.5f64.to_radians(),
            10f64.to_radians(),
            &SceneOptions::default()
        )
        .is_err());
    }
}
