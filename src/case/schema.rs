//! The case-file schema. Units sit in the key names (`_um`, `_deg`, `_m_s`, `_pa`).
//! Unknown keys are rejected everywhere. Sections are optional; each command checks
//! that it has what it needs and fills documented defaults.

use serde::{Deserialize, Serialize};

/// A whole case file.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Names the run; default output folder is `results/<name>/<command>/`.
    pub name: String,
    /// Seed of every random stream; a fixed default when absent.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// A generated surface (grid and roughness).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface: Option<WallSpec>,
    /// A wall given by its normal-angle deviations (or surface parameters).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wall: Option<WallSpec>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stats: Option<StatsSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub incidence: Option<IncidenceSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub particles: Option<ParticlesSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub collision: Option<CollisionSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub output: Option<OutputSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stochastic: Option<StochasticSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub deterministic: Option<DeterministicSection>,
    /// force-sweep's impacting particle (`[impactor]`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impactor: Option<ParticleSection>,
    /// The old name of `[impactor]`, still read by force-sweep with a warning.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub particle: Option<ParticleSection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sweep: Option<SweepSection>,
    /// Wall erosion by the impacts (`deterministic`, `stochastic`); nothing is computed
    /// without it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub erosion: Option<ErosionSection>,
    /// A measured wall (`scan`): the scan file and how to read and level it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scan: Option<ScanSection>,
}

/// `[surface]` or `[wall]`: either correlation lengths or normal-angle deviations per axis
/// (Radenkovic & Simonin 2021, Eq. 15 links them: `Δ = √2 h / c_L`).
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct WallSpec {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nodes: Option<i64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rms_height_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corr_length_x_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub corr_length_z_um: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub delta_xi_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub delta_zeta_deg: Option<f64>,
}

/// `[stats]`: directions `β*` of the rotated frames of Table 1.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct StatsSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub beta_star_deg: Option<Vec<f64>>,
    /// Sphere diameters (µm) whose effective roughness `surface` measures (the centre
    /// surface of each sphere; `effective_roughness.csv`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub diameter_um: Vec<f64>,
}

/// `[incidence]`: incident angles and the horizontal-speed law.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct IncidenceSection {
    pub alpha_deg: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub beta_deg: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_mean_m_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_std_m_s: Option<f64>,
    /// `"horizontal"` (default: the speed law is the horizontal speed, the paper's
    /// convention) or `"magnitude"` (it is `|U|`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_reference: Option<String>,
    /// Incident angular velocity (rad/s, wall frame `[x, y, z]`): mean and standard
    /// deviation of each component; zero by default.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin_rad_s: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin_std_rad_s: Option<Vec<f64>>,
}

/// `[particles]`: how many histories per condition (or a target standard error), and
/// the sphere diameter.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ParticlesSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<i64>,
    /// Run whole blocks until the standard errors of mean `α⁺` and mean `β⁺ − β⁻` are at
    /// most this (degrees), or `count` is reached.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_se_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diameter_um: Option<f64>,
    /// Particle density (kg/m³): the particle mass of the per-particle erosion volume.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub density_kg_m3: Option<f64>,
}

/// `[collision]`: the collision law and its parameters.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CollisionSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub preset: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub e_h: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha_e_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mu_0: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mu_h: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha_mu_deg: Option<f64>,
}

/// `[output]`: histogram bin width of every angle PDF.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct OutputSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bin_width_deg: Option<f64>,
}

/// `[stochastic]`: the multiple-collision parameter ψ of Eq. (34) and the rough-wall model.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct StochasticSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub psi: Option<f64>,
    /// The rough-wall model: `"radenkovic-simonin-2021"` (default), `"sommerfeld-huber-1999"`,
    /// `"gaussian-angle"`, `"gaussian-tilt"` or `"normal-perturbation"`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model: Option<String>,
    /// The isotropic variants' roughness angle Δγ (degrees); default `(Δξ + Δζ)/2`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub delta_gamma_deg: Option<f64>,
    /// Run with the deviations a sphere of `[particles] diameter_um` sees: those of its
    /// centre surface on the surface `deterministic` would generate (same seed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub effective_for_diameter: Option<bool>,
    /// The escape table of `model = "calibrated"` (a file `rebound calibrate` wrote; as
    /// given, else under `configs/`); default: the built-in table.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub escape_table: Option<String>,
    /// `measured-wall` only, and required there: the wall's table (`rebound scan
    /// --measured-wall` writes it; a path as given, else under `configs/`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wall_table: Option<String>,
}

/// `[deterministic]`: tracker limits and the automatic surface choice.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DeterministicSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_collisions: Option<i64>,
    /// Grid points per smallest correlation length (`c_L,min / δ`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spacing_per_corr_length: Option<f64>,
    /// Surface side in largest correlation lengths (`L / c_L,max`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub side_per_corr_length: Option<f64>,
    /// RMS height of the automatically chosen surface (only ratios matter, but for
    /// `contact = "sphere"`, which needs the absolute scale).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rms_height_um: Option<f64>,
    /// What bounces on the surface: `"centre"` (the particle centre, the paper's, default)
    /// or `"sphere"` (a sphere of `[particles] diameter_um`: its centre on the dilated
    /// surface).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact: Option<String>,
    /// How each grid cell is split into two triangles: `"alternating"` (checkerboard,
    /// mirror symmetric, the default) or `"uniform"` (one diagonal, the earlier default).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangulation: Option<String>,
    /// What `[wall]`'s deviations mean for the automatic surface: `"normal-angles"` (the
    /// triangles' normal-angle deviations, the default) or `"eq15"` (`c_L = √2 h/Δ`, as the
    /// papers build their walls).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wall_deviations: Option<String>,
    /// Independent surface realisations the histories are spread over (history `i` on
    /// realisation `i mod surfaces`): the ensemble a statistical wall model stands for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surfaces: Option<i64>,
    /// What a measured scan given as `--surface` becomes: `"in-place"` (the scan itself, the
    /// incident direction turned by its lay; the default) or `"mirrored"` (turned to its lay,
    /// resampled and mirror-tiled into a periodic wall, the earlier reference).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scan_wall: Option<String>,
    /// The polynomial degree a scan given as `--surface` is levelled by (1: a plane, the
    /// default; 2 or 3 remove a curved form, as `[scan] level_degree` does for `scan`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scan_level_degree: Option<i64>,
    /// On a scan in place: one entry region for every incident direction, the margins of
    /// this `|α⁻|` (degrees) on every side, as a measured-wall table's build takes them (the
    /// wall card's `measured_wall_entry_alpha_deg`); unset, the region follows each direction.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub entry_alpha_deg: Option<f64>,
}

/// `[scan]` for `scan`: the scan of a wall (without `file`, the case's `[wall]` or `[surface]`
/// is generated and read as a scan).
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ScanSection {
    /// The scan file; a relative path is read from the case file's directory.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// `"auto"` (default: told by the file) or a `topography::Format` name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub format: Option<String>,
    /// Degree of the polynomial form removed, 1 (a plane, default) to 3.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub level_degree: Option<i64>,
    /// Pixel sizes `[dx, dy]` (µm) of a plain matrix or of x-y-z text.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pixel_um: Option<Vec<f64>>,
    /// Length of one height unit (µm) of a plain matrix or of x-y-z text.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height_unit_um: Option<f64>,
    /// Particle diameters (µm) whose deviations the wall card gives: those of each sphere's
    /// centre surface on the scan (`[[diameter]]` of `wall_card.toml`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub diameters_um: Vec<f64>,
    /// Build the measured-wall table of the point particle and of each diameter (the
    /// in-place reference's rebound law, `model = "measured-wall"`), beside the card.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub measured_wall: Option<bool>,
    /// Histories per incident direction of each measured-wall table (default 17 711).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub measured_wall_histories: Option<i64>,
}

/// `[impactor]` (formerly `[particle]`) for `force-sweep`: a material preset or explicit
/// properties.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ParticleSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub preset: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub density_kg_m3: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub youngs_pa: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub poisson: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diameter_um: Option<f64>,
}

/// `[sweep]` for `force-sweep`.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SweepSection {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lambda: Option<Values>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub beta_deg: Option<Values>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub u_n_m_s: Option<Values>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub diameter_um: Option<Values>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub models: Option<Vec<String>>,
}

/// A list of values, a linear range or a logarithmic range.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(untagged)]
pub enum Values {
    List(Vec<f64>),
    One(f64),
    Linear(LinearRange),
    Log(LogRange),
}

/// `{ start, stop, step }`, both ends included when `stop` falls on the grid.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LinearRange {
    pub start: f64,
    pub stop: f64,
    pub step: f64,
}

/// `{ log_start, log_stop, points }`: `points` values evenly spaced in `log10`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LogRange {
    pub log_start: f64,
    pub log_stop: f64,
    pub points: i64,
}

/// `[erosion]`: the erosion law and its parameters. Which keys apply depends on `model`.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ErosionSection {
    /// `"finnie"`, `"dnv"` or `"oka"`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub model: Option<String>,
    /// Finnie: the wall's plastic flow stress `p` (Pa).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flow_stress_pa: Option<f64>,
    /// Finnie: ratio `ψ` of contact depth to cutting depth.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub psi: Option<f64>,
    /// Finnie: ratio `K` of vertical to horizontal force; DNV: the material constant `K`
    /// ((m/s)^-n); Oka: the particle factor `K` (mm³/kg).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub k: Option<f64>,
    /// DNV: the velocity exponent `n`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<f64>,
    /// DNV: the wall's density `ρ_t` (kg/m³).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub target_density_kg_m3: Option<f64>,
    /// DNV: `"ductile"` or `"brittle"`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub angle_dependency: Option<String>,
    /// Oka: the wall's Vickers hardness `Hv` (GPa).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hardness_gpa: Option<f64>,
    /// Oka: exponents (defaults: Oka & Yoshida 2005 Part 2's SiO2 correlations).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub k1: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub k2: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub k3: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n1: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n2: Option<f64>,
    /// Oka: reference speed `U'` (m/s) and diameter `D'` (µm).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_speed_m_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_diameter_um: Option<f64>,
}
