//! Validated SI views of case sections. Each accessor checks its keys and returns
//! one-line errors naming the key, the value and what is allowed (exit status 2).

use super::check::{
    check_greater_than, check_int_range, check_length, check_less_than, check_range, check_value,
    Warning,
};
pub(super) use super::check::{positive, within};
use super::schema::*;
use crate::collision::{CollisionLaw, ShParams};
use crate::error::{Error, Result};
pub use crate::incidence::{IncidentCondition, SpeedLaw, SpeedReference};
pub use crate::surface::SurfaceSpec;
use crate::wall::{self, Deviations};

/// Above this deviation the low-roughness approximation (Radenkovic & Simonin 2021, Eq. 6) is
/// stretched: run, but warn (the paper validates Eq. 14 up to about 7.5°).
pub const LOW_ROUGHNESS_LIMIT_DEG: f64 = 7.5;
/// Beyond this deviation the wall models are not meant to be used at all.
pub const MAX_DEVIATION_DEG: f64 = 20.0;
/// Steepest rms slope (degrees) a generated surface may have.
pub const MAX_SURFACE_SLOPE_DEG: f64 = 45.0;

/// What a case says about the wall.
#[derive(Clone, Debug, PartialEq)]
pub enum WallSource {
    /// A full surface (grid and roughness): generated as given.
    Surface(SurfaceSpec),
    /// Only the statistical wall: deviations (a surface, if needed, is chosen to fit).
    Deviations(Deviations),
}

impl WallSource {
    pub fn deviations(&self) -> Deviations {
        match self {
            WallSource::Surface(s) => s.deviations(),
            WallSource::Deviations(d) => *d,
        }
    }
}

/// Everything `deterministic` and `stochastic` share: one scene, two models.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub wall: WallSource,
    pub conditions: Vec<IncidentCondition>,
    pub speed: SpeedLaw,
    /// Histories per condition (the cap when a target standard error is set).
    pub count: usize,
    /// Target standard error (degrees) of mean `α⁺` and mean `β⁺ − β⁻`.
    pub target_se_deg: Option<f64>,
    pub diameter_m: f64,
    pub law: CollisionLaw,
    pub bin_width_deg: f64,
    pub psi: f64,
    /// The erosion law of `[erosion]` (none: nothing is computed).
    pub erosion: Option<crate::erosion::ErosionModel>,
    /// Particle density (kg/m³): with the diameter, the particle mass.
    pub density_kg_m3: f64,
    /// The stochastic model's rough-wall variant (`[stochastic] model`).
    pub variant: crate::stochastic::Variant,
    /// Incident spin (`[incidence] spin_rad_s`, `spin_std_rad_s`).
    pub spin: crate::incidence::SpinLaw,
}

impl Scene {
    /// Mass of one particle (kg): a sphere of the case's diameter and density.
    pub fn particle_mass_kg(&self) -> f64 {
        self.density_kg_m3 * std::f64::consts::PI / 6.0 * self.diameter_m.powi(3)
    }
}

impl Scene {
    /// Applies `--particles N` (overrides `[particles] count`).
    pub fn set_count(&mut self, particles: Option<u64>) -> Result<()> {
        if let Some(n) = particles {
            if n == 0 || n > MAX_PARTICLES as u64 {
                return Err(Error::invalid(
                    "--particles",
                    n,
                    "an integer from 1 to 100000000",
                ));
            }
            self.count = n as usize;
        }
        Ok(())
    }

    /// Applies `--target-se DEG` (overrides `[particles] target_se_deg`).
    pub fn set_target_se(&mut self, target: Option<f64>) -> Result<()> {
        if let Some(t) = target {
            self.target_se_deg = Some(target_se("--target-se", t)?);
        }
        Ok(())
    }
}

/// Incident speeds (m/s): below a micrometre per second adhesion, not rebound, decides;
/// above 10 km/s impacts are hypervelocity (the wall melts). Both bounds keep every derived
/// quantity (squares of velocity components) far from underflow and overflow.
pub const SPEED_RANGE_M_S: (f64, f64) = (1e-6, 1e4);
/// Particle diameters (µm): a nanometre to a metre.
pub const DIAMETER_RANGE_UM: (f64, f64) = (1e-3, 1e6);
/// ψ of Eq. (34): the paper uses 2 (Konan et al. 1.5); below 0.01 almost every candidate
/// rebound is rejected (hundreds of redraws per rebound), above 100 none is.
pub const PSI_RANGE: (f64, f64) = (0.01, 100.0);
/// Lengths of a generated surface (µm): a picometre to a kilometre.
pub const LENGTH_RANGE_UM: (f64, f64) = (1e-6, 1e9);
/// Longest list of incident angles (each of `alpha_deg`, `beta_deg`), and most conditions.
pub const MAX_ANGLES: usize = 1000;
pub const MAX_CONDITIONS: usize = 10_000;
/// Longest `[stats] diameter_um` list.
pub const MAX_DIAMETERS: usize = 64;
/// Longest `[stats] beta_star_deg` list.
pub const MAX_BETA_STAR: usize = 1000;

/// Narrowest PDF bin (degrees).
pub const MIN_BIN_WIDTH_DEG: f64 = 0.01;

/// Largest particle count per condition the schema admits.
pub const MAX_PARTICLES: i64 = 100_000_000;

fn target_se(key: &str, v: f64) -> Result<f64> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(Error::invalid(
            key,
            v,
            "a positive standard error in degrees",
        ))
    }
}

fn deviation(key: &str, v: f64, warnings: &mut Vec<Warning>) -> Result<f64> {
    if !(0.0..=MAX_DEVIATION_DEG).contains(&v) {
        return Err(Error::invalid(
            key,
            v,
            &format!("0 to {MAX_DEVIATION_DEG} degrees"),
        ));
    }
    if v > LOW_ROUGHNESS_LIMIT_DEG {
        warnings.push(Warning(format!(
            "`{key}` = {v}° is beyond the low-roughness approximation (Eq. 6, up to ~{LOW_ROUGHNESS_LIMIT_DEG}°); results are extrapolated"
        )));
    }
    Ok(v.to_radians())
}

impl Case {
    /// The `[surface]` or `[wall]` section and its name.
    fn wall_spec(&self) -> Option<(&'static str, &WallSpec)> {
        match (&self.surface, &self.wall) {
            (Some(s), _) => Some(("surface", s)),
            (None, Some(w)) => Some(("wall", w)),
            _ => None,
        }
    }

    /// The wall: a full surface when grid keys are given, else deviations
    /// (from `delta_*_deg`, or from `corr_length_*_um` and `rms_height_um` by Eq. 15).
    pub fn wall_source(&self, warnings: &mut Vec<Warning>) -> Result<WallSource> {
        let Some((sec, w)) = self.wall_spec() else {
            return Err(Error::Input(
                "the case needs a [wall] (delta_xi_deg, delta_zeta_deg) or [surface] section"
                    .into(),
            ));
        };
        let has_grid = w.length_um.is_some() || w.nodes.is_some();
        if has_grid {
            return Ok(WallSource::Surface(self.surface_spec(warnings)?));
        }
        let mut axis = |c: Option<f64>, d: Option<f64>, cname: &str, dname: &str| -> Result<f64> {
            match (c, d) {
                (Some(_), Some(_)) => Err(Error::Input(format!(
                    "[{sec}] gives both `{cname}` and `{dname}`: give one of them"
                ))),
                (None, Some(d)) => deviation(&format!("{sec}.{dname}"), d, warnings),
                (Some(c), None) => {
                    let c = positive(&format!("{sec}.{cname}"), c)?;
                    let h = w.rms_height_um.ok_or_else(|| {
                        Error::Input(format!(
                            "[{sec}] gives `{cname}` but not `rms_height_um` (needed by Eq. 15)"
                        ))
                    })?;
                    let h = positive(&format!("{sec}.rms_height_um"), h)?;
                    deviation(
                        &format!("{sec}.{cname} (as a deviation)"),
                        wall::deviation_from_surface(h, c).to_degrees(),
                        warnings,
                    )
                }
                (None, None) => Err(Error::Input(format!(
                    "[{sec}] needs `{dname}` or `{cname}`"
                ))),
            }
        };
        Ok(WallSource::Deviations(Deviations {
            delta_xi: axis(
                w.corr_length_x_um,
                w.delta_xi_deg,
                "corr_length_x_um",
                "delta_xi_deg",
            )?,
            delta_zeta: axis(
                w.corr_length_z_um,
                w.delta_zeta_deg,
                "corr_length_z_um",
                "delta_zeta_deg",
            )?,
        }))
    }

    /// A full surface: `length_um`, `nodes`, `rms_height_um` and per axis a correlation length
    /// or a deviation (converted with Eq. 15). Checks the grid against the correlation lengths:
    /// `δ > c_L/2` is an error, `L < 20 c_L` a warning.
    pub fn surface_spec(&self, warnings: &mut Vec<Warning>) -> Result<SurfaceSpec> {
        let Some((sec, w)) = self.wall_spec() else {
            return Err(Error::Input("the case needs a [surface] section".into()));
        };
        let need =
            |v: Option<f64>, k: &str| v.ok_or_else(|| Error::Input(format!("[{sec}] needs `{k}`")));
        let (lo, hi) = LENGTH_RANGE_UM;
        let lengths = "a surface's lengths, a picometre to a kilometre";
        let length_um = within(
            &format!("{sec}.length_um"),
            need(w.length_um, "length_um")?,
            lo,
            hi,
            " µm",
            lengths,
        )?;
        let nodes = w
            .nodes
            .ok_or_else(|| Error::Input(format!("[{sec}] needs `nodes`")))?;
        let key = format!("{sec}.nodes");
        check_int_range(&key, nodes, 16, 40_000, "an integer from 16 to 40000")?;
        let h_um = need(w.rms_height_um, "rms_height_um")?;
        if h_um != 0.0 {
            within(
                &format!("{sec}.rms_height_um"),
                h_um,
                lo,
                hi,
                " µm (or 0)",
                lengths,
            )?;
        }
        let mut axis = |c: Option<f64>,
                        d: Option<f64>,
                        cname: &str,
                        dname: &str|
         -> Result<Option<f64>> {
            let c = match (c, d) {
                (Some(_), Some(_)) => {
                    return Err(Error::Input(format!(
                        "[{sec}] gives both `{cname}` and `{dname}`: give one of them"
                    )))
                }
                (Some(c), None) => {
                    let c = within(&format!("{sec}.{cname}"), c, lo, hi, " µm", lengths)?;
                    // The rms slope √2 h/c_L (Eq. 14) of a generated surface: up to 45°
                    // (Fig. 4 studies it beyond the low-roughness range; the wall models
                    // themselves stop at 20°, checked in `scene`).
                    if h_um > 0.0 {
                        let d = wall::deviation_from_surface(h_um, c).to_degrees();
                        if d.is_nan() || d > MAX_SURFACE_SLOPE_DEG {
                            return Err(Error::invalid(
                                    &format!("{sec}.{cname}"),
                                    c,
                                    &format!(
                                        "a correlation length giving an rms slope √2 h/c_L of at most {MAX_SURFACE_SLOPE_DEG}° (Eq. 14); it gives {d}°"
                                    ),
                                ));
                        }
                        if d > LOW_ROUGHNESS_LIMIT_DEG {
                            warnings.push(Warning(format!(
                                    "`{sec}.{cname}` = {c} µm gives Δ = √2 h/c_L = {d:.2}° (Eq. 15), beyond the low-roughness approximation (Eq. 6, up to ~{LOW_ROUGHNESS_LIMIT_DEG}°)"
                                )));
                        }
                    }
                    Some(c)
                }
                (None, Some(d)) => {
                    let dr = deviation(&format!("{sec}.{dname}"), d, warnings)?;
                    let c = wall::corr_length_from_deviation(h_um, dr);
                    if let Some(c) = c.filter(|_| h_um > 0.0) {
                        within(
                            &format!("{sec}.{dname} (as the correlation length √2 h/Δ, Eq. 15)"),
                            c,
                            lo,
                            hi,
                            " µm",
                            lengths,
                        )?;
                    }
                    c
                }
                (None, None) => {
                    return Err(Error::Input(format!(
                        "[{sec}] needs `{cname}` or `{dname}`"
                    )))
                }
            };
            Ok(c)
        };
        let cx = axis(
            w.corr_length_x_um,
            w.delta_xi_deg,
            "corr_length_x_um",
            "delta_xi_deg",
        )?;
        let cz = axis(
            w.corr_length_z_um,
            w.delta_zeta_deg,
            "corr_length_z_um",
            "delta_zeta_deg",
        )?;
        let spec = SurfaceSpec {
            length_m: length_um * 1e-6,
            nodes: nodes as usize,
            rms_height_m: h_um * 1e-6,
            corr_length_x_m: if h_um > 0.0 {
                cx.map(|c| c * 1e-6)
            } else {
                None
            },
            corr_length_z_m: if h_um > 0.0 {
                cz.map(|c| c * 1e-6)
            } else {
                None
            },
        };
        let spacing_um = length_um / nodes as f64;
        for (name, c) in [("corr_length_x_um", cx), ("corr_length_z_um", cz)] {
            if let Some(c) = c {
                if h_um > 0.0 && spacing_um > c / 2.0 {
                    return Err(Error::invalid(
                        &format!("{sec}.nodes"),
                        nodes,
                        &format!(
                            "a grid spacing L/nodes ≤ c_L/2 = {} µm ({name} = {c} µm); spacing is {spacing_um} µm",
                            c / 2.0
                        ),
                    ));
                }
                if h_um > 0.0 && length_um < 20.0 * c {
                    warnings.push(Warning(format!(
                        "[{sec}] length_um = {length_um} is less than 20 correlation lengths ({name} = {c} µm): statistics will be noisy and biased"
                    )));
                }
            }
        }
        crate::memory::require(
            &format!("{sec}.nodes"),
            nodes,
            crate::surface::generate::generation_bytes(&spec),
            &format!("a {nodes} × {nodes} surface"),
        )?;
        Ok(spec)
    }

    /// Directions `β*` (radians) of Table 1's rotated frames; default 0°, 30°, 60°, 90°.
    /// Sphere diameters (m) of `[stats] diameter_um` whose effective roughness `surface`
    /// measures: each in the diameter range and at most the surface side `length_m` (a
    /// sphere wider than the period would rest on its own images).
    pub fn effective_diameters(&self, length_m: f64) -> Result<Vec<f64>> {
        let list = self
            .stats
            .as_ref()
            .map(|s| s.diameter_um.clone())
            .unwrap_or_default();
        let allowed = format!("at most {MAX_DIAMETERS} diameters");
        check_length(
            "stats.diameter_um",
            list.len(),
            MAX_DIAMETERS,
            "diameters",
            &allowed,
        )?;
        let (lo, hi) = DIAMETER_RANGE_UM;
        list.iter()
            .map(|&d| {
                let d = within("stats.diameter_um", d, lo, hi, " µm", "a nanometre to a metre")?;
                if d * 1e-6 > length_m {
                    return Err(Error::invalid(
                        "stats.diameter_um",
                        d,
                        &format!(
                            "at most the surface side, {} µm (a wider sphere rests on its own periodic images)",
                            crate::output::fmt_num(length_m * 1e6)
                        ),
                    ));
                }
                Ok(d * 1e-6)
            })
            .collect()
    }

    pub fn beta_star(&self) -> Result<Vec<f64>> {
        let list = self
            .stats
            .as_ref()
            .and_then(|s| s.beta_star_deg.clone())
            .unwrap_or_else(|| vec![0.0, 30.0, 60.0, 90.0]);
        let allowed = format!("at most {MAX_BETA_STAR} directions");
        check_length(
            "stats.beta_star_deg",
            list.len(),
            MAX_BETA_STAR,
            "angles",
            &allowed,
        )?;
        if list.is_empty() {
            return Err(Error::invalid(
                "stats.beta_star_deg",
                "[]",
                "a non-empty list",
            ));
        }
        list.iter()
            .map(|&b| {
                if (-180.0..=180.0).contains(&b) {
                    Ok(b.to_radians())
                } else {
                    Err(Error::invalid(
                        "stats.beta_star_deg",
                        b,
                        "angles in [-180, 180] degrees",
                    ))
                }
            })
            .collect()
    }

    /// The scene shared by `deterministic` and `stochastic`.
    pub fn scene(&self, warnings: &mut Vec<Warning>) -> Result<Scene> {
        let wall = self.wall_source(warnings)?;
        // A generated surface may be steeper than the wall models go (`surface` studies it).
        let d = wall.deviations();
        for (key, v) in [
            ("delta_xi_deg", d.delta_xi),
            ("delta_zeta_deg", d.delta_zeta),
        ] {
            let deg = v.to_degrees();
            if deg > MAX_DEVIATION_DEG {
                return Err(Error::invalid(
                    &format!("surface ({key} by Eq. 15)"),
                    deg,
                    &format!("0 to {MAX_DEVIATION_DEG} degrees for the wall models"),
                ));
            }
        }
        let inc = self.incidence.as_ref().ok_or_else(|| {
            Error::Input("the case needs an [incidence] section with `alpha_deg`".into())
        })?;
        if inc.alpha_deg.is_empty() {
            return Err(Error::invalid(
                "incidence.alpha_deg",
                "[]",
                "a non-empty list of angles in [-90, 0)",
            ));
        }
        let betas = inc.beta_deg.clone().unwrap_or_else(|| vec![0.0]);
        if betas.is_empty() {
            return Err(Error::invalid(
                "incidence.beta_deg",
                "[]",
                "a non-empty list of angles in [-180, 180]",
            ));
        }
        for (key, list) in [
            ("incidence.alpha_deg", &inc.alpha_deg),
            ("incidence.beta_deg", &betas),
        ] {
            let allowed = format!("at most {MAX_ANGLES} angles");
            check_length(key, list.len(), MAX_ANGLES, "angles", &allowed)?;
        }
        let mut conditions = Vec::new();
        let mut seen = std::collections::HashSet::new();
        for &a in &inc.alpha_deg {
            if !(-90.0..0.0).contains(&a) {
                return Err(Error::invalid(
                    "incidence.alpha_deg",
                    a,
                    "angles in [-90, 0) degrees",
                ));
            }
            for &b in &betas {
                if !(-180.0..=180.0).contains(&b) {
                    return Err(Error::invalid(
                        "incidence.beta_deg",
                        b,
                        "angles in [-180, 180] degrees",
                    ));
                }
                // Normal incidence has no incident plane: β⁻ is taken as 0 (notes §1).
                let beta = if a == -90.0 { 0.0 } else { b };
                let c = IncidentCondition::from_degrees(a, beta);
                // −0 and 0 are one angle.
                if seen.insert(((a + 0.0).to_bits(), (beta + 0.0).to_bits())) {
                    conditions.push(c);
                }
            }
        }
        if conditions.len() > MAX_CONDITIONS {
            return Err(Error::invalid(
                "incidence.alpha_deg",
                format!("{} × {} conditions", inc.alpha_deg.len(), betas.len()),
                &format!("at most {MAX_CONDITIONS} (α⁻, β⁻) conditions"),
            ));
        }
        let (lo, hi) = SPEED_RANGE_M_S;
        let why = "rebound off a rigid wall, neither adhesion nor hypervelocity";
        let mean = within(
            "incidence.speed_mean_m_s",
            inc.speed_mean_m_s.unwrap_or(1.0),
            lo,
            hi,
            " m/s",
            why,
        )?;
        let std = inc.speed_std_m_s.unwrap_or(0.0);
        if std != 0.0 {
            within("incidence.speed_std_m_s", std, lo, hi, " m/s (or 0)", why)?;
        }
        let reference = match inc.speed_reference.as_deref() {
            None | Some("horizontal") => SpeedReference::Horizontal,
            Some("magnitude") => SpeedReference::Magnitude,
            Some(other) => {
                return Err(Error::invalid(
                    "incidence.speed_reference",
                    format!("\"{other}\""),
                    "\"horizontal\" (the speed law is the horizontal speed) or \"magnitude\" (it is |U|)",
                ))
            }
        };
        let p = self.particles.clone().unwrap_or_default();
        let target = p
            .target_se_deg
            .map(|t| target_se("particles.target_se_deg", t))
            .transpose()?;
        // Under a target, `count` is only the cap: without one, the schema's largest.
        let count = p.count.unwrap_or(if target.is_some() {
            MAX_PARTICLES
        } else {
            10_000
        });
        if !(1..=MAX_PARTICLES).contains(&count) {
            return Err(Error::invalid(
                "particles.count",
                count,
                "an integer from 1 to 100000000",
            ));
        }
        let (lo, hi) = DIAMETER_RANGE_UM;
        let diameter_um = within(
            "particles.diameter_um",
            p.diameter_um.unwrap_or(500.0),
            lo,
            hi,
            " µm",
            "a nanometre to a metre",
        )?;
        let bin = self
            .output
            .as_ref()
            .and_then(|o| o.bin_width_deg)
            .unwrap_or(1.0);
        // At most 36 000 bins over the widest range (±180°): a bounded tally per block.
        if !(MIN_BIN_WIDTH_DEG..=10.0).contains(&bin) {
            return Err(Error::invalid(
                "output.bin_width_deg",
                bin,
                &format!("a width in [{MIN_BIN_WIDTH_DEG}, 10] degrees"),
            ));
        }
        let psi = self.psi()?;
        // Every condition keeps its tally (12 histograms and 2 ratio curves of these bins),
        // and a few blocks per thread are in flight.
        let per_tally = (12.0 * 360.0 / bin * 8.0 + 2.0 * 180.0 / bin * 32.0) as u64;
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get()) as u64;
        let tallies = conditions.len() as u64 + 4 * 8 * threads;
        crate::memory::require(
            "output.bin_width_deg",
            bin,
            per_tally.saturating_mul(tallies),
            &format!("tallying {} conditions", conditions.len()),
        )?;
        Ok(Scene {
            wall,
            conditions,
            speed: SpeedLaw {
                reference,
                ..SpeedLaw::horizontal(mean, std)
            },
            count: count as usize,
            target_se_deg: target,
            diameter_m: diameter_um * 1e-6,
            law: self.collision_law()?,
            bin_width_deg: bin,
            psi,
            erosion: self.erosion_model()?,
            variant: self.variant()?,
            spin: spin_law(inc)?,
            density_kg_m3: within(
                "particles.density_kg_m3",
                // Soda-lime glass beads, the particles of Radenkovic & Simonin 2021, Sec. 4.
                p.density_kg_m3.unwrap_or(2500.0),
                10.0,
                3e4,
                " kg/m³",
                "a solid particle; glass 2500",
            )?,
        })
    }

    /// ψ of the single-collision probability, Eq. (34): `[stochastic] psi`, default 2 (the paper's).
    pub fn psi(&self) -> Result<f64> {
        let psi = self.stochastic.as_ref().and_then(|s| s.psi).unwrap_or(2.0);
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

    /// The rough-wall model of `[stochastic] model` and `delta_gamma_deg` (default: the
    /// paper's).
    pub fn variant(&self) -> Result<crate::stochastic::Variant> {
        use crate::stochastic::{Variant, VariantKind};
        let st = self.stochastic.clone().unwrap_or_default();
        let kind = match st.model.as_deref() {
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
        let delta_gamma = match st.delta_gamma_deg {
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
        let escape = match (&st.escape_table, kind) {
            (None, _) => None,
            (Some(path), VariantKind::Calibrated) => Some(read_escape_table(path)?),
            (Some(_), _) => {
                return Err(Error::Input(format!(
                "`stochastic.escape_table` applies to model = \"calibrated\" only (model = \"{}\")",
                kind.name()
            )))
            }
        };
        Ok(Variant {
            kind,
            delta_gamma,
            escape,
        })
    }

    /// The collision law of `[collision]` (default: ideally elastic).
    pub fn collision_law(&self) -> Result<CollisionLaw> {
        let c = self.collision.clone().unwrap_or_default();
        let model = c.model.as_deref().unwrap_or("elastic");
        match model {
            "elastic" => {
                if c.preset.is_some()
                    || c.e_h.is_some()
                    || c.mu_0.is_some()
                    || c.mu_h.is_some()
                    || c.alpha_e_deg.is_some()
                    || c.alpha_mu_deg.is_some()
                {
                    return Err(Error::Input(
                        "[collision] model = \"elastic\" takes no preset or parameters (use model = \"sommerfeld-huber\")".into(),
                    ));
                }
                Ok(CollisionLaw::Elastic)
            }
            "sommerfeld-huber" => {
                let base = match c.preset.as_deref() {
                    Some(name) => {
                        check_value(
                            "collision.preset",
                            name,
                            &["glass-steel"],
                            "\"glass-steel\"",
                        )?;
                        Some(ShParams::glass_steel())
                    }
                    None => None,
                };
                let pick = |v: Option<f64>, b: Option<f64>, key: &str| -> Result<f64> {
                    v.or(b).ok_or_else(|| {
                        Error::Input(format!("[collision] sommerfeld-huber needs `{key}` (or preset = \"glass-steel\")"))
                    })
                };
                let e_h = pick(c.e_h, base.map(|b| b.e_h), "e_h")?;
                let alpha_e = pick(
                    c.alpha_e_deg.map(f64::to_radians),
                    base.map(|b| b.alpha_e),
                    "alpha_e_deg",
                )?;
                let mu_0 = pick(c.mu_0, base.map(|b| b.mu_0), "mu_0")?;
                let mu_h = pick(c.mu_h, base.map(|b| b.mu_h), "mu_h")?;
                let alpha_mu = pick(
                    c.alpha_mu_deg.map(f64::to_radians),
                    base.map(|b| b.alpha_mu),
                    "alpha_mu_deg",
                )?;
                let allowed = "a restitution coefficient in (0, 1]";
                check_greater_than("collision.e_h", e_h, 0.0, false, allowed)?;
                check_less_than("collision.e_h", e_h, 1.0, true, allowed)?;
                for (k, v) in [("collision.mu_0", mu_0), ("collision.mu_h", mu_h)] {
                    check_range(k, v, 0.0, 2.0, "a friction coefficient in [0, 2]")?;
                }
                for (k, v) in [
                    ("collision.alpha_e_deg", alpha_e),
                    ("collision.alpha_mu_deg", alpha_mu),
                ] {
                    if !(v > 0.0 && v <= std::f64::consts::FRAC_PI_2) {
                        return Err(Error::invalid(
                            k,
                            v.to_degrees(),
                            "an angle in (0, 90] degrees",
                        ));
                    }
                }
                Ok(CollisionLaw::SommerfeldHuber(ShParams {
                    e_h,
                    alpha_e,
                    mu_0,
                    mu_h,
                    alpha_mu,
                }))
            }
            other => Err(Error::invalid(
                "collision.model",
                format!("\"{other}\""),
                "\"elastic\" or \"sommerfeld-huber\"",
            )),
        }
    }
}

/// Largest incident spin component (rad/s): beyond, the contact point would move faster than
/// the hypervelocity bound of the speeds for any particle above a micrometre.
pub const MAX_SPIN_RAD_S: f64 = 1e7;

/// `[incidence] spin_rad_s`, `spin_std_rad_s`: three components each, finite, within
/// `±MAX_SPIN_RAD_S` (standard deviations `≥ 0`).
fn spin_law(inc: &IncidenceSection) -> Result<crate::incidence::SpinLaw> {
    let three = |key: &str, v: &Option<Vec<f64>>, std: bool| -> Result<[f64; 3]> {
        let Some(v) = v else {
            return Ok([0.0; 3]);
        };
        if v.len() != 3 {
            return Err(Error::invalid(
                key,
                format!("a list of {} values", v.len()),
                "three components [x, y, z] in rad/s (wall frame, y the wall normal)",
            ));
        }
        let lo = if std { 0.0 } else { -MAX_SPIN_RAD_S };
        let mut out = [0.0; 3];
        for (o, &x) in out.iter_mut().zip(v) {
            *o = within(key, x, lo, MAX_SPIN_RAD_S, " rad/s", "an angular velocity")?;
        }
        Ok(out)
    };
    Ok(crate::incidence::SpinLaw {
        mean_rad_s: three("incidence.spin_rad_s", &inc.spin_rad_s, false)?,
        std_rad_s: three("incidence.spin_std_rad_s", &inc.spin_std_rad_s, true)?,
    })
}

impl Values {
    /// The values, checked finite; `key` names them in errors. Ranges hold at most 1e6 points.
    pub fn expand(&self, key: &str) -> Result<Vec<f64>> {
        let v = match self {
            Values::List(v) => v.clone(),
            Values::One(x) => vec![*x],
            Values::Linear(r) => {
                if r.step <= 0.0 || r.stop < r.start {
                    return Err(Error::invalid(
                        key,
                        format!(
                            "{{start = {}, stop = {}, step = {}}}",
                            r.start, r.stop, r.step
                        ),
                        "start ≤ stop and step > 0",
                    ));
                }
                // Count in floating point first: a tiny step must not overflow the count.
                let n = ((r.stop - r.start) / r.step + 1e-9).floor() + 1.0;
                if n.is_nan() || n > 1e6 {
                    return Err(Error::invalid(
                        key,
                        format!(
                            "{{start = {}, stop = {}, step = {}}} ({n:e} points)",
                            r.start, r.stop, r.step
                        ),
                        "at most 1000000 points",
                    ));
                }
                (0..n as usize)
                    .map(|i| r.start + i as f64 * r.step)
                    .collect()
            }
            Values::Log(r) => {
                if !(1..=1_000_000).contains(&r.points) {
                    return Err(Error::invalid(
                        &format!("{key}.points"),
                        r.points,
                        "an integer from 1 to 1000000",
                    ));
                }
                let n = r.points as usize;
                (0..n)
                    .map(|i| {
                        let t = if n == 1 {
                            0.0
                        } else {
                            i as f64 / (n - 1) as f64
                        };
                        10f64.powf(r.log_start + t * (r.log_stop - r.log_start))
                    })
                    .collect()
            }
        };
        if v.is_empty() {
            return Err(Error::invalid(key, "[]", "at least one value"));
        }
        check_length(key, v.len(), 1_000_000, "values", "at most 1000000 values")?;
        if let Some(bad) = v.iter().find(|x| !x.is_finite()) {
            return Err(Error::invalid(key, bad, "finite values"));
        }
        Ok(v)
    }
}

/// Largest escape table read (bytes); a table of the fixed grid is about 60 kB.
const MAX_ESCAPE_TABLE_BYTES: u64 = 1 << 20;

/// Reads the escape table at `path` (`[stochastic] escape_table`): as given, else under
/// `configs/`; one-line errors that name the key and the file.
fn read_escape_table(path: &str) -> Result<&'static crate::stochastic::escape_table::EscapeTable> {
    let key = "stochastic.escape_table";
    let file = super::load::resolve_path(std::path::Path::new(path)).map_err(|_| {
        Error::Input(format!(
            "`{key}` = \"{path}\": file not found (looked as given and under configs/)"
        ))
    })?;
    let what = format!("`{key}` = \"{path}\"");
    let len = std::fs::metadata(&file).map(|m| m.len()).unwrap_or(0);
    if len > MAX_ESCAPE_TABLE_BYTES {
        return Err(Error::Input(format!(
            "{what}: {len} bytes, more than an escape table ({MAX_ESCAPE_TABLE_BYTES} at most)"
        )));
    }
    let text = std::fs::read_to_string(&file)
        .map_err(|e| Error::Input(format!("{what}: cannot read it: {e}")))?;
    Ok(crate::stochastic::escape_table::EscapeTable::parse(&text, &what)?.intern())
}
