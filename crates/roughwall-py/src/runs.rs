//! A scene's stochastic and deterministic runs (`rebound stochastic`, `rebound deterministic`)
//! from keyword parameters: the library's runners (`tally::tally::run` with
//! `models::models::fill_block` or `deterministic::fill_block`) and tallies
//! (`ConditionTally::result`), returned as arrays instead of CSV files. Case files are the
//! application's (serde, toml): the Python package takes the scene's values directly, checked
//! with the ranges and messages of the case keys they stand for.

use crate::errors::{guarded, invalid, on_threads, to_py};
use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use roughwall::check::{check_int_range, check_range};
use roughwall::deterministic::{
    build_surfaces, realisations, SceneOptions, SurfacePlan, WallDeviations,
};
use roughwall::models;
use roughwall::tally::{self, Plan, Silent};
use roughwall::tally::{ConditionResult, ConditionTally, Estimate};
use roughwall::CollisionParams;
use roughwall::Triangulation;
use roughwall::{IncidentCondition, SpeedLaw, SpinLaw};
use roughwall::{WallModel, WallParams};

/// Incident conditions of a run.
const MAX_CONDITIONS: usize = 10_000;

/// Particles per condition, as a case's `[particles] count`.
const MAX_PARTICLES: u64 = 100_000_000;

/// The scene both models share, checked.
pub struct Scene {
    wall: WallModel,
    conditions: Vec<IncidentCondition>,
    speed: SpeedLaw,
    diameter_m: f64,
    particles: u64,
    bin_width_deg: f64,
    target_se_deg: Option<f64>,
    seed: u64,
    threads: usize,
}

/// The Sommerfeld–Huber parameters `(e_h, alpha_e_deg, mu_0, mu_h, alpha_mu_deg)`, each
/// `None` for the preset's.
type Collision = (
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<f64>,
);

/// The scene's keyword parameters as Python passes them.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct SceneArgs<'py> {
    delta_xi_deg: f64,
    delta_zeta_deg: f64,
    law: Option<String>,
    preset: Option<String>,
    collision: Collision,
    model: Option<String>,
    delta_gamma_deg: Option<f64>,
    psi: Option<f64>,
    escape_table: Option<String>,
    wall_table: Option<String>,
    /// A sequence of `(alpha_in_deg, beta_in_deg)` pairs: its length is checked before it is
    /// copied.
    conditions: Bound<'py, PyAny>,
    speed_m_s: (f64, f64),
    diameter_m: f64,
    particles: u64,
    bin_width_deg: f64,
    target_se_deg: Option<f64>,
    seed: u64,
    threads: usize,
}

impl SceneArgs<'_> {
    /// The scene, with the checks of the case keys each value stands for.
    fn checked(self) -> PyResult<Scene> {
        let (e_h, alpha_e_deg, mu_0, mu_h, alpha_mu_deg) = self.collision;
        let (wall, _warnings) = WallModel::new(&WallParams {
            delta_xi_deg: self.delta_xi_deg,
            delta_zeta_deg: self.delta_zeta_deg,
            collision: CollisionParams {
                model: self.law,
                preset: self.preset,
                e_h,
                alpha_e_deg,
                mu_0,
                mu_h,
                alpha_mu_deg,
            },
            psi: self.psi,
            seed: self.seed,
            model: self.model,
            delta_gamma_deg: self.delta_gamma_deg,
            escape_table: self.escape_table,
            wall_table: self.wall_table,
        })
        .map_err(to_py)?;
        let allowed = "1 to 10000 (alpha_in_deg, beta_in_deg) pairs";
        let count = self
            .conditions
            .len()
            .map_err(|_| PyTypeError::new_err(format!("`conditions`: allowed {allowed}")))?;
        if count == 0 || count > MAX_CONDITIONS {
            return Err(invalid(
                "conditions",
                format!("{count} conditions"),
                allowed,
            ));
        }
        let pairs: Vec<(f64, f64)> = self
            .conditions
            .extract()
            .map_err(|_| PyTypeError::new_err(format!("`conditions`: allowed {allowed}")))?;
        let mut conditions = Vec::new();
        for &(a, b) in &pairs {
            if !(-90.0..0.0).contains(&a) {
                return Err(invalid("alpha_in_deg", a, "angles in [-90, 0) degrees"));
            }
            if !(-180.0..=180.0).contains(&b) {
                return Err(invalid("beta_in_deg", b, "angles in [-180, 180] degrees"));
            }
            // Normal incidence has no incident plane: β⁻ is taken as 0 (docs/physics.md §1).
            conditions.push(IncidentCondition::from_degrees(
                a,
                if a == -90.0 { 0.0 } else { b },
            ));
        }
        let (mean, std) = self.speed_m_s;
        // The library's range checks (roughwall::check), with their one-line messages.
        check_range(
            "speed_m_s",
            mean,
            1e-6,
            1e4,
            "a mean speed from 1e-6 to 10000 m/s",
        )
        .map_err(to_py)?;
        if std != 0.0 {
            check_range(
                "speed_m_s",
                std,
                1e-6,
                1e4,
                "a standard deviation of 0 or 1e-6 to 10000 m/s",
            )
            .map_err(to_py)?;
        }
        check_range("diameter_m", self.diameter_m, 1e-9, 1.0, "1e-9 to 1 m").map_err(to_py)?;
        check_int_range(
            "particles",
            i64::try_from(self.particles).unwrap_or(i64::MAX),
            1,
            MAX_PARTICLES as i64,
            "an integer from 1 to 100000000",
        )
        .map_err(to_py)?;
        check_range(
            "bin_width_deg",
            self.bin_width_deg,
            0.01,
            10.0,
            "a width in [0.01, 10] degrees",
        )
        .map_err(to_py)?;
        if let Some(t) = self.target_se_deg.filter(|t| !(t.is_finite() && *t > 0.0)) {
            return Err(invalid("target_se_deg", t, "a standard error > 0 degrees"));
        }
        Ok(Scene {
            wall,
            conditions,
            speed: SpeedLaw::horizontal(mean, std),
            diameter_m: self.diameter_m,
            particles: self.particles,
            bin_width_deg: self.bin_width_deg,
            target_se_deg: self.target_se_deg,
            seed: self.seed,
            threads: self.threads,
        })
    }
}

fn opt_array<'py>(py: Python<'py>, values: Vec<f64>) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_vec(py, values)
}

/// The tallies as a dict of arrays: one entry per condition in each array.
fn results<'py>(
    py: Python<'py>,
    scene: &Scene,
    tallies: &[ConditionTally],
) -> PyResult<Bound<'py, PyDict>> {
    let res: Vec<ConditionResult> = tallies.iter().map(|t| t.result()).collect();
    let out = PyDict::new(py);
    let alpha: Vec<f64> = scene.conditions.iter().map(|c| c.alpha_in_deg()).collect();
    let beta: Vec<f64> = scene.conditions.iter().map(|c| c.beta_in_deg()).collect();
    out.set_item("alpha_in_deg", opt_array(py, alpha))?;
    out.set_item("beta_in_deg", opt_array(py, beta))?;
    let particles: Vec<u64> = res.iter().map(|r| r.summary.particles).collect();
    out.set_item("particles", PyArray1::from_vec(py, particles))?;
    let lost: Vec<u64> = res.iter().map(|r| r.summary.lost.unwrap_or(0)).collect();
    out.set_item("lost", PyArray1::from_vec(py, lost))?;
    let p: Vec<f64> = res
        .iter()
        .map(|r| r.summary.p_single.map_or(f64::NAN, |p| p.value))
        .collect();
    let p_se: Vec<f64> = res
        .iter()
        .map(|r| r.summary.p_single.and_then(|p| p.se).unwrap_or(f64::NAN))
        .collect();
    out.set_item("p_single", opt_array(py, p))?;
    out.set_item("p_single_se", opt_array(py, p_se))?;
    // Means, standard deviations and standard errors of every quantity with values.
    let mut names: Vec<&'static str> = Vec::new();
    for r in &res {
        for (q, _) in &r.estimates {
            if !names.contains(&q.name()) {
                names.push(q.name());
            }
        }
    }
    let (mean, std, se) = (PyDict::new(py), PyDict::new(py), PyDict::new(py));
    for name in &names {
        let pick = |f: &dyn Fn(&Estimate) -> Option<f64>| -> Vec<f64> {
            res.iter()
                .map(|r| {
                    r.estimates
                        .iter()
                        .find(|(q, _)| q.name() == *name)
                        .and_then(|(_, e)| f(e))
                        .unwrap_or(f64::NAN)
                })
                .collect()
        };
        mean.set_item(name, opt_array(py, pick(&|e| Some(e.mean))))?;
        std.set_item(name, opt_array(py, pick(&|e| e.std)))?;
        se.set_item(name, opt_array(py, pick(&|e| e.se)))?;
    }
    out.set_item("mean", mean)?;
    out.set_item("std", std)?;
    out.set_item("se", se)?;
    // PDFs: per condition, per quantity, bin edges and densities (1/degree).
    let pdfs = PyList::empty(py);
    for r in &res {
        let per = PyDict::new(py);
        for pdf in &r.pdfs {
            let d = PyDict::new(py);
            let b = &pdf.bins;
            d.set_item("lo_deg", opt_array(py, b.iter().map(|b| b.lo).collect()))?;
            d.set_item("hi_deg", opt_array(py, b.iter().map(|b| b.hi).collect()))?;
            d.set_item("value", opt_array(py, b.iter().map(|b| b.value).collect()))?;
            d.set_item(
                "se",
                opt_array(py, b.iter().map(|b| b.se.unwrap_or(f64::NAN)).collect()),
            )?;
            per.set_item(pdf.quantity.name(), d)?;
        }
        pdfs.append(per)?;
    }
    out.set_item("pdfs", pdfs)?;
    Ok(out)
}

impl Scene {
    fn plan(&self, specs: Vec<roughwall::tally::TallySpec>) -> Plan {
        Plan {
            specs,
            count: self.particles,
            target_se_deg: self.target_se_deg,
            shard: None,
        }
    }
}

/// The stochastic model on the scene (`rebound stochastic`): a dict of arrays.
#[pyfunction]
pub fn stochastic<'py>(py: Python<'py>, args: SceneArgs<'py>) -> PyResult<Bound<'py, PyDict>> {
    guarded(|| {
        let scene = args.checked()?;
        let w = &scene.wall;
        let setup = models::ModelSetup {
            wall: w.wall,
            law: w.law,
            psi: w.psi,
            diameter_m: scene.diameter_m,
            speed: scene.speed,
            erosion: None,
            model: w.model,
            spin: SpinLaw::default(),
        };
        let specs = scene
            .conditions
            .iter()
            .map(|c| models::tally_spec(&w.wall, *c, scene.bin_width_deg, None))
            .collect();
        let plan = scene.plan(specs);
        let tallies = py.detach(|| {
            guarded(|| {
                on_threads(scene.threads, || {
                    tally::run(&plan, &Silent, |k, start, end, block| {
                        models::fill_block(
                            &setup,
                            &scene.conditions[k],
                            k as u64,
                            scene.seed,
                            (start, end),
                            block,
                        )
                    })
                })
            })
        })?;
        let tallies: Vec<ConditionTally> = tallies.into_iter().map(|(t, _)| t).collect();
        results(py, &scene, &tallies)
    })
}

/// What the deterministic model adds to the scene.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct SurfaceArgs {
    max_collisions: u32,
    spacing_per_corr_length: f64,
    side_per_corr_length: f64,
    surfaces: u32,
    triangulation: String,
    wall_deviations: String,
}

/// The deterministic model on the scene (`rebound deterministic`): particle centres on
/// generated surfaces; a dict of arrays.
#[pyfunction]
pub fn deterministic<'py>(
    py: Python<'py>,
    args: SceneArgs<'py>,
    surface: SurfaceArgs,
) -> PyResult<Bound<'py, PyDict>> {
    guarded(|| {
        let scene = args.checked()?;
        let s = &surface;
        check_int_range(
            "max_collisions",
            s.max_collisions.into(),
            1,
            1_000_000,
            "an integer from 1 to 1000000",
        )
        .and_then(|_| {
            check_int_range(
                "surfaces",
                s.surfaces.into(),
                1,
                1024,
                "an integer from 1 to 1024",
            )
        })
        .and_then(|_| {
            check_range(
                "spacing_per_corr_length",
                s.spacing_per_corr_length,
                1.0,
                64.0,
                "a number from 1 to 64",
            )
        })
        .and_then(|_| {
            check_range(
                "side_per_corr_length",
                s.side_per_corr_length,
                1.0,
                10_000.0,
                "a number from 1 to 10000",
            )
        })
        .map_err(to_py)?;
        let triangulation = Triangulation::from_name(&surface.triangulation).ok_or_else(|| {
            invalid(
                "triangulation",
                format!("\"{}\"", surface.triangulation),
                "\"alternating\" or \"uniform\"",
            )
        })?;
        let deviations = WallDeviations::from_name(&surface.wall_deviations).ok_or_else(|| {
            invalid(
                "wall_deviations",
                format!("\"{}\"", surface.wall_deviations),
                "\"normal-angles\" or \"eq15\"",
            )
        })?;
        let w = &scene.wall;
        let options = SceneOptions {
            spacing_per_corr_length: surface.spacing_per_corr_length,
            side_per_corr_length: surface.side_per_corr_length,
            deviations,
            ..SceneOptions::default()
        };
        let surface_plan =
            SurfacePlan::auto(w.wall.delta_xi, w.wall.delta_zeta, &options).map_err(to_py)?;
        let setup = roughwall::deterministic::ModelSetup {
            law: w.law,
            diameter_m: scene.diameter_m,
            speed: scene.speed,
            wall: w.wall,
            psi: w.psi,
            erosion: None,
            spin: SpinLaw::default(),
        };
        let specs = scene
            .conditions
            .iter()
            .map(|c| {
                roughwall::deterministic::tally_spec(&w.wall, *c, scene.bin_width_deg, None)
                    .with_realisations(surface.surfaces)
            })
            .collect();
        let plan = scene.plan(specs);
        let tallies = py.detach(|| {
            guarded(|| {
                on_threads(scene.threads, || {
                    let built = build_surfaces(
                        Some(&surface_plan),
                        None,
                        None,
                        scene.seed,
                        triangulation,
                        surface.surfaces,
                    )
                    .map_err(to_py)?;
                    let real = realisations(&built, surface.max_collisions, None).map_err(to_py)?;
                    Ok(tally::run(&plan, &Silent, |k, start, end, block| {
                        roughwall::deterministic::fill_block(
                            &real,
                            &setup,
                            &scene.conditions[k],
                            k as u64,
                            scene.seed,
                            (start, end),
                            block,
                        )
                    }))
                })?
            })
        })?;
        let tallies: Vec<ConditionTally> = tallies.into_iter().map(|(t, _)| t).collect();
        results(py, &scene, &tallies)
    })
}
