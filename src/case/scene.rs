//! `[incidence]`, `[particles]` and `[output]`: the scene `deterministic` and `stochastic`
//! share (incident conditions, speeds, spin, particle counts, PDF bins).

use super::schema::*;
use super::wall::{WallSource, DIAMETER_RANGE_UM, MAX_DEVIATION_DEG};
use roughwall::check::{check_int_range, check_length, check_range, check_value, within};
pub use roughwall::incidence::SpeedReference;
use roughwall::CollisionLaw;
use roughwall::Warning;
use roughwall::{Error, Result};
pub use roughwall::{IncidentCondition, SpeedLaw};

/// Everything `deterministic` and `stochastic` share: one scene, two models.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub wall: WallSource,
    pub conditions: Vec<IncidentCondition>,
    pub speed: SpeedLaw,
    /// Histories per condition (the cap when a target standard error is set).
    pub count: usize,
    /// Whether `count` was given (`[particles] count` or `--particles`): without it, a target
    /// standard error runs up to [`MAX_PARTICLES`], one without a target 10 000.
    pub count_given: bool,
    /// Target standard error (degrees) of mean `α⁺` and mean `β⁺ − β⁻`.
    pub target_se_deg: Option<f64>,
    pub diameter_m: f64,
    pub law: CollisionLaw,
    pub bin_width_deg: f64,
    pub psi: f64,
    /// The erosion law of `[erosion]` (none: nothing is computed).
    pub erosion: Option<roughwall::ErosionModel>,
    /// Particle density (kg/m³): with the diameter, the particle mass.
    pub density_kg_m3: f64,
    /// The stochastic rough-wall model (`[stochastic] model`).
    pub model: roughwall::AnyModel,
    /// Incident spin (`[incidence] spin_rad_s`, `spin_std_rad_s`).
    pub spin: roughwall::SpinLaw,
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
            self.count_given = true;
        }
        Ok(())
    }

    /// Applies `--target-se DEG` (overrides `[particles] target_se_deg`). Like a target in the
    /// case, it runs up to [`MAX_PARTICLES`] per condition unless a count was given.
    pub fn set_target_se(&mut self, target: Option<f64>) -> Result<()> {
        if let Some(t) = target {
            self.target_se_deg = Some(target_se("--target-se", t)?);
            if !self.count_given {
                self.count = MAX_PARTICLES as usize;
            }
        }
        Ok(())
    }
}

/// Incident speeds (m/s): below a micrometre per second adhesion, not rebound, decides;
/// above 10 km/s impacts are hypervelocity (the wall melts). Both bounds keep every derived
/// quantity (squares of velocity components) far from underflow and overflow.
pub const SPEED_RANGE_M_S: (f64, f64) = (1e-6, 1e4);
/// Longest list of incident angles (each of `alpha_deg`, `beta_deg`), and most conditions.
pub const MAX_ANGLES: usize = 1000;
pub const MAX_CONDITIONS: usize = 10_000;

/// Narrowest PDF bin (degrees).
pub const MIN_BIN_WIDTH_DEG: f64 = 0.01;

/// Particle diameter (µm) without `[particles] diameter_um`: the glass beads of Radenkovic &
/// Simonin 2021, Sec. 4.
pub const DEFAULT_DIAMETER_UM: f64 = 500.0;

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

impl Case {
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
                // Normal incidence has no incident plane: β⁻ is taken as 0 (docs/physics.md §1).
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
            None => SpeedReference::Horizontal,
            Some(name) => [SpeedReference::Horizontal, SpeedReference::Magnitude][check_value(
                "incidence.speed_reference",
                name,
                &["horizontal", "magnitude"],
                "\"horizontal\" (the speed law is the horizontal speed) or \"magnitude\" (it is |U|)",
            )?],
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
        check_int_range(
            "particles.count",
            count,
            1,
            MAX_PARTICLES,
            "an integer from 1 to 100000000",
        )?;
        let (lo, hi) = DIAMETER_RANGE_UM;
        let diameter_um = within(
            "particles.diameter_um",
            p.diameter_um.unwrap_or(DEFAULT_DIAMETER_UM),
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
        check_range(
            "output.bin_width_deg",
            bin,
            MIN_BIN_WIDTH_DEG,
            10.0,
            &format!("a width in [{MIN_BIN_WIDTH_DEG}, 10] degrees"),
        )?;
        let psi = self.psi()?;
        // Every condition keeps its tally (12 histograms and 2 ratio curves of these bins),
        // and a few blocks per thread are in flight.
        let per_tally = (12.0 * 360.0 / bin * 8.0 + 2.0 * 180.0 / bin * 32.0) as u64;
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get()) as u64;
        let tallies = conditions.len() as u64 + 4 * 8 * threads;
        roughwall::memory::require(
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
            count_given: p.count.is_some(),
            target_se_deg: target,
            diameter_m: diameter_um * 1e-6,
            law: self.collision_law()?,
            bin_width_deg: bin,
            psi,
            erosion: self.erosion_model()?,
            model: self.model()?,
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
}

/// Largest incident spin component (rad/s): beyond, the contact point would move faster than
/// the hypervelocity bound of the speeds for any particle above a micrometre.
pub const MAX_SPIN_RAD_S: f64 = 1e7;

/// `[incidence] spin_rad_s`, `spin_std_rad_s`: three components each, finite, within
/// `±MAX_SPIN_RAD_S` (standard deviations `≥ 0`).
fn spin_law(inc: &IncidenceSection) -> Result<roughwall::SpinLaw> {
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
    Ok(roughwall::SpinLaw {
        mean_rad_s: three("incidence.spin_rad_s", &inc.spin_rad_s, false)?,
        std_rad_s: three("incidence.spin_std_rad_s", &inc.spin_std_rad_s, true)?,
    })
}
