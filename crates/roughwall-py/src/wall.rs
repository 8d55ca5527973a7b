//! `roughwall.Wall`'s core: a wall handle (`roughwall::WallModel`, the model the C
//! library's `rw_wall_new` builds) and the rebound of many hits at once, each exactly
//! `WallModel::rebound` — what `rw_rebound` and `rw_rebound_batch` return for the same key.
//! The Python layer (`python/roughwall/_wall.py`) checks and broadcasts the arguments; this
//! file checks them again (never trusting a caller) and runs the hits without the GIL.

use crate::errors::{bytes_of, guarded, invalid, require, to_py, zeroed};
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use roughwall::CollisionParams;
use roughwall::RoughWallModel;
use roughwall::{Hit, HitOutcome, WallModel, WallParams};

/// An immutable wall: the rough-wall model, its collision law and the seed of every hit's
/// random stream. Share one between threads.
#[pyclass(frozen, name = "WallCore", module = "roughwall._roughwall")]
pub struct WallCore {
    model: WallModel,
    warnings: Vec<String>,
}

/// The inputs of a batch: C-contiguous rows, each holding either one row (broadcast to every
/// hit) or one row per hit.
struct Inputs<'a> {
    velocity: &'a [f64],
    normal: &'a [f64],
    lay: &'a [f64],
    spin: &'a [f64],
    wall_velocity: &'a [f64],
    diameter: &'a [f64],
    particle_id: &'a [u64],
    collision_index: &'a [u64],
}

impl Inputs<'_> {
    /// Row `i` of a 3-vector input (row 0 when it holds one row).
    #[inline]
    fn vec3(a: &[f64], i: usize) -> [f64; 3] {
        let j = if a.len() == 3 { 0 } else { 3 * i };
        [a[j], a[j + 1], a[j + 2]]
    }

    #[inline]
    fn one<T: Copy>(a: &[T], i: usize) -> T {
        a[if a.len() == 1 { 0 } else { i }]
    }

    /// Hit `i`.
    #[inline]
    fn hit(&self, i: usize) -> Hit {
        Hit {
            velocity: Self::vec3(self.velocity, i),
            spin: Self::vec3(self.spin, i),
            normal: Self::vec3(self.normal, i),
            lay: Self::vec3(self.lay, i),
            wall_velocity: Self::vec3(self.wall_velocity, i),
            diameter_m: Self::one(self.diameter, i),
            particle_id: Self::one(self.particle_id, i),
            collision_index: Self::one(self.collision_index, i),
        }
    }
}

/// `alpha_element` cut into the threads' shares: `chunk` values each, or, when the angles were
/// not asked for (an empty slice), an empty slice for each of the `t` threads.
fn element_shares(alpha_element: &mut [f64], chunk: usize, t: usize) -> Vec<&mut [f64]> {
    if alpha_element.is_empty() {
        (0..t).map(|_| <&mut [f64]>::default()).collect()
    } else {
        alpha_element.chunks_mut(chunk).collect()
    }
}

/// The outputs of a run of consecutive hits.
struct Outputs<'a> {
    velocity: &'a mut [f64],
    spin: &'a mut [f64],
    status: &'a mut [i32],
    gamma: &'a mut [f64],
    gamma_star: &'a mut [f64],
    candidate_walls: &'a mut [u32],
    alpha_element: &'a mut [f64],
}

impl Outputs<'_> {
    fn put(&mut self, k: usize, hit: &Hit, o: &HitOutcome) {
        self.velocity[3 * k..3 * k + 3].copy_from_slice(&o.velocity);
        self.spin[3 * k..3 * k + 3].copy_from_slice(&o.spin);
        self.status[k] = o.status as i32;
        self.gamma[k] = o.gamma;
        self.gamma_star[k] = o.gamma_star;
        self.candidate_walls[k] = o.candidate_walls;
        // The C library's `rw_element_impact_angle` of the same hit and result, when asked
        // for (an empty slice otherwise: it costs a frame and three arcsines a hit).
        if let Some(a) = self.alpha_element.get_mut(k) {
            *a = o.element_impact_angle(hit);
        }
    }
}

/// The rebounds of hits `first..first + out.status.len()`.
fn run(model: &WallModel, inputs: &Inputs, first: usize, mut out: Outputs) {
    for k in 0..out.status.len() {
        let hit = inputs.hit(first + k);
        out.put(k, &hit, &model.rebound(&hit));
    }
}

/// Every hit's rebound, split over `threads` threads in contiguous shares (as
/// `rw_rebound_batch` splits them); each hit's result depends on its key alone. A thread the
/// system cannot start is an error (the shares already started finish first).
fn run_all(
    model: &WallModel,
    inputs: &Inputs,
    n: usize,
    threads: usize,
    out: Outputs,
) -> std::io::Result<()> {
    let t = threads.clamp(1, n.max(1));
    if t == 1 {
        run(model, inputs, 0, out);
        return Ok(());
    }
    let chunk = n.div_ceil(t);
    let Outputs {
        velocity,
        spin,
        status,
        gamma,
        gamma_star,
        candidate_walls,
        alpha_element,
    } = out;
    std::thread::scope(|s| {
        let shares = velocity
            .chunks_mut(3 * chunk)
            .zip(spin.chunks_mut(3 * chunk))
            .zip(status.chunks_mut(chunk))
            .zip(gamma.chunks_mut(chunk))
            .zip(gamma_star.chunks_mut(chunk))
            .zip(candidate_walls.chunks_mut(chunk))
            .zip(element_shares(alpha_element, chunk, t));
        for (
            k,
            ((((((velocity, spin), status), gamma), gamma_star), candidate_walls), alpha_element),
        ) in shares.enumerate()
        {
            let share = Outputs {
                velocity,
                spin,
                status,
                gamma,
                gamma_star,
                candidate_walls,
                alpha_element,
            };
            std::thread::Builder::new()
                .spawn_scoped(s, move || run(model, inputs, k * chunk, share))?;
        }
        Ok(())
    })
}

/// The rows of a checked input: 1 (broadcast) or `n`.
fn rows(name: &str, len: usize, width: usize, n: usize) -> PyResult<()> {
    if len == width || width.checked_mul(n) == Some(len) {
        Ok(())
    } else {
        Err(PyValueError::new_err(format!(
            "`{name}` has {} rows: allowed 1 or {n} (the number of hits)",
            len / width.max(1)
        )))
    }
}

#[pymethods]
impl WallCore {
    /// Builds the wall through `WallModel::new`: the checks, ranges and one-line messages of
    /// a case file and of the C library's `rw_wall_new`.
    #[new]
    #[pyo3(signature = (delta_xi_deg, delta_zeta_deg, law, preset, e_h, alpha_e_deg, mu_0, mu_h, alpha_mu_deg, psi, seed, model, delta_gamma_deg, escape_table, wall_table))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        delta_xi_deg: f64,
        delta_zeta_deg: f64,
        law: Option<String>,
        preset: Option<String>,
        e_h: Option<f64>,
        alpha_e_deg: Option<f64>,
        mu_0: Option<f64>,
        mu_h: Option<f64>,
        alpha_mu_deg: Option<f64>,
        psi: Option<f64>,
        seed: u64,
        model: Option<String>,
        delta_gamma_deg: Option<f64>,
        escape_table: Option<String>,
        wall_table: Option<String>,
    ) -> PyResult<Self> {
        guarded(|| {
            // The collision law is the case key `collision.model`: a name it refuses is named
            // here as the argument Python passes. (Parameters given to the elastic law keep the
            // library's message, the C library's `rw_wall_new`'s.)
            if let Some(other) = law
                .as_deref()
                .filter(|l| !["elastic", "sommerfeld-huber"].contains(l))
            {
                return Err(invalid(
                    "law",
                    format!("\"{other}\""),
                    "\"elastic\" or \"sommerfeld-huber\"",
                ));
            }
            let params = WallParams {
                delta_xi_deg,
                delta_zeta_deg,
                collision: CollisionParams {
                    model: law,
                    preset,
                    e_h,
                    alpha_e_deg,
                    mu_0,
                    mu_h,
                    alpha_mu_deg,
                },
                psi,
                seed,
                model,
                delta_gamma_deg,
                escape_table,
                wall_table,
            };
            let (model, warnings) = WallModel::new(&params).map_err(to_py)?;
            Ok(WallCore { model, warnings })
        })
    }

    /// Warnings of the parameters (e.g. a deviation beyond the low-roughness range).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    /// The model's deviations (degrees), ψ, seed and the rough-wall model's name.
    #[getter]
    fn description(&self) -> (f64, f64, f64, u64, &'static str) {
        let m = &self.model;
        (
            m.wall.delta_xi.to_degrees(),
            m.wall.delta_zeta.to_degrees(),
            m.psi,
            m.seed,
            m.model.name(),
        )
    }

    /// The rebounds of `n` hits. Vector inputs are C-contiguous `(1, 3)` or `(n, 3)` float64
    /// arrays, the others `(1,)` or `(n,)`; returns (velocity, spin, status, gamma,
    /// gamma_star, candidate_walls, alpha_element) as new arrays, alpha_element `None` unless
    /// `element_angle`. The GIL is released while the hits run.
    /// `n_from` names the argument whose rows set `n` in messages (default `n`): outputs the
    /// process cannot hold are a `MemoryError` naming it, before anything is allocated.
    #[pyo3(signature = (n, velocity, normal, lay, spin, wall_velocity, diameter, particle_id, collision_index, threads, n_from=None, element_angle=false))]
    #[allow(clippy::too_many_arguments)]
    fn rebound<'py>(
        &self,
        py: Python<'py>,
        n: usize,
        velocity: PyReadonlyArray2<'py, f64>,
        normal: PyReadonlyArray2<'py, f64>,
        lay: PyReadonlyArray2<'py, f64>,
        spin: PyReadonlyArray2<'py, f64>,
        wall_velocity: PyReadonlyArray2<'py, f64>,
        diameter: PyReadonlyArray1<'py, f64>,
        particle_id: PyReadonlyArray1<'py, u64>,
        collision_index: PyReadonlyArray1<'py, u64>,
        threads: usize,
        n_from: Option<String>,
        element_angle: bool,
    ) -> PyResult<Bound<'py, PyTuple>> {
        guarded(|| {
            // Outputs: 3 + 3 float64, 2 (3 with the element angles) float64, an int32 and a
            // uint32 per hit.
            let (key, value) = match n_from.as_deref() {
                None | Some("n") => ("n".to_string(), n.to_string()),
                Some(name) => (name.to_string(), format!("{n} hits")),
            };
            let per_hit =
                ((8 + usize::from(element_angle)) * size_of::<f64>() + 2 * size_of::<u32>()) as u64;
            let what = format!("returning the rebounds of {n} hits");
            let bytes = bytes_of(&key, &value, n, per_hit, &what)?;
            let n3 = n.checked_mul(3).ok_or_else(|| {
                invalid(
                    &key,
                    &value,
                    "a number of hits whose 3-vectors can be indexed (n · 3 < 2⁶⁴)",
                )
            })?;
            let contiguous = |name: &str| {
                PyValueError::new_err(format!("`{name}`: a C-contiguous array is needed here"))
            };
            let inputs = Inputs {
                velocity: velocity.as_slice().map_err(|_| contiguous("velocity"))?,
                normal: normal.as_slice().map_err(|_| contiguous("normal"))?,
                lay: lay.as_slice().map_err(|_| contiguous("lay"))?,
                spin: spin.as_slice().map_err(|_| contiguous("spin"))?,
                wall_velocity: wall_velocity
                    .as_slice()
                    .map_err(|_| contiguous("wall_velocity"))?,
                diameter: diameter.as_slice().map_err(|_| contiguous("diameter"))?,
                particle_id: particle_id
                    .as_slice()
                    .map_err(|_| contiguous("particle_id"))?,
                collision_index: collision_index
                    .as_slice()
                    .map_err(|_| contiguous("collision_index"))?,
            };
            for (name, a, w) in [
                ("velocity", &velocity, 3),
                ("normal", &normal, 3),
                ("lay", &lay, 3),
                ("spin", &spin, 3),
                ("wall_velocity", &wall_velocity, 3),
            ] {
                if a.shape()[1] != w {
                    return Err(PyValueError::new_err(format!(
                        "`{name}` has shape {:?}: allowed (3,) or (n, 3)",
                        a.shape()
                    )));
                }
            }
            rows("velocity", inputs.velocity.len(), 3, n)?;
            rows("normal", inputs.normal.len(), 3, n)?;
            rows("lay", inputs.lay.len(), 3, n)?;
            rows("spin", inputs.spin.len(), 3, n)?;
            rows("wall_velocity", inputs.wall_velocity.len(), 3, n)?;
            rows("diameter", inputs.diameter.len(), 1, n)?;
            rows("particle_id", inputs.particle_id.len(), 1, n)?;
            rows("collision_index", inputs.collision_index.len(), 1, n)?;
            let model = self.model;
            let threads = if threads == 0 {
                std::thread::available_parallelism().map_or(1, |t| t.get())
            } else {
                threads
            };
            let (velocity_out, spin_out, status, gamma, gamma_star, candidate_walls, alpha_element) =
                py.detach(|| {
                    guarded(|| {
                        require(&key, &value, bytes, &what)?;
                        let mut v = zeroed(&key, &value, n3, "the rebound velocities")?;
                        let mut w = zeroed(&key, &value, n3, "the rebound spins")?;
                        let mut status = zeroed::<i32>(&key, &value, n, "the statuses")?;
                        let mut gamma = zeroed(&key, &value, n, "the inclinations γ")?;
                        let mut gamma_star = zeroed(&key, &value, n, "the inclinations γ*")?;
                        let mut candidates =
                            zeroed::<u32>(&key, &value, n, "the candidate counts")?;
                        let mut alpha_element = if element_angle {
                            zeroed(&key, &value, n, "the impact angles on the elements")?
                        } else {
                            Vec::new()
                        };
                        let out = Outputs {
                            velocity: &mut v,
                            spin: &mut w,
                            status: &mut status,
                            gamma: &mut gamma,
                            gamma_star: &mut gamma_star,
                            candidate_walls: &mut candidates,
                            alpha_element: &mut alpha_element,
                        };
                        run_all(&model, &inputs, n, threads, out).map_err(|e| {
                            PyOSError::new_err(format!(
                                "`threads` = {threads}: could not start the threads ({e})"
                            ))
                        })?;
                        Ok((v, w, status, gamma, gamma_star, candidates, alpha_element))
                    })
                })?;
            let vec3 = |v: Vec<f64>| PyArray1::from_vec(py, v).reshape([n, 3]);
            PyTuple::new(
                py,
                [
                    vec3(velocity_out)?.into_any(),
                    vec3(spin_out)?.into_any(),
                    PyArray1::from_vec(py, status).into_any(),
                    PyArray1::from_vec(py, gamma).into_any(),
                    PyArray1::from_vec(py, gamma_star).into_any(),
                    PyArray1::from_vec(py, candidate_walls).into_any(),
                    if element_angle {
                        PyArray1::from_vec(py, alpha_element).into_any()
                    } else {
                        py.None().into_bound(py)
                    },
                ],
            )
        })
    }
}
