//! `roughwall.surface`: a Garcia–Stoll rough surface (`roughwall::surface::generate`,
//! Radenkovic & Simonin 2021, Eqs. 1–2), as a 2-D array and its grid spacing.

use crate::errors::{guarded, invalid, on_threads, require, to_py};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use roughwall::check::check_range;
use roughwall::surface::generate;
use roughwall::SurfaceSpec;

/// The lengths a surface may have (m): a picometre to a kilometre, as in a case file.
const LENGTH_RANGE_M: (f64, f64) = (1e-12, 1e3);

/// The steepest rms slope `√2 h/c_L` (Eq. 14) a generated surface may have (degrees), as in
/// a case file.
const MAX_SLOPE_DEG: f64 = 45.0;

/// Nodes per side, as a case file's `[surface] nodes`.
const NODES_RANGE: (usize, usize) = (16, 40_000);

/// Checks the grid and roughness with the ranges of a case file's `[surface]`.
fn checked(spec: &SurfaceSpec) -> PyResult<()> {
    let (lo, hi) = LENGTH_RANGE_M;
    let why = "a picometre to a kilometre";
    let length = |key: &str, v: f64| {
        check_range(key, v, lo, hi, &format!("{lo} to {hi} m ({why})")).map_err(to_py)
    };
    length("length_m", spec.length_m)?;
    if !(NODES_RANGE.0..=NODES_RANGE.1).contains(&spec.nodes) {
        return Err(invalid("nodes", spec.nodes, "an integer from 16 to 40000"));
    }
    let h = spec.rms_height_m;
    if h != 0.0 {
        length("rms_height_m", h)?;
    }
    for (key, c) in [
        ("corr_length_x_m", spec.corr_length_x_m),
        ("corr_length_z_m", spec.corr_length_z_m),
    ] {
        let Some(c) = c else { continue };
        length(key, c)?;
        let slope = roughwall::wall::deviation_from_surface(h, c).to_degrees();
        if h > 0.0 && (slope.is_nan() || slope > MAX_SLOPE_DEG) {
            return Err(invalid(
                key,
                c,
                &format!("a correlation length giving an rms slope √2 h/c_L of at most {MAX_SLOPE_DEG}° (Eq. 14); it gives {slope}°"),
            ));
        }
    }
    require(
        "nodes",
        spec.nodes,
        roughwall::surface::generation_bytes(spec),
        &format!("generating a {0} × {0} surface", spec.nodes),
    )
}

/// Generates the surface; returns (heights `(nz, nx)` in metres, `dx`, `dz` in metres).
#[pyfunction]
#[pyo3(signature = (length_m, nodes, rms_height_m, corr_length_x_m, corr_length_z_m, seed, threads))]
#[allow(clippy::too_many_arguments)]
pub fn surface<'py>(
    py: Python<'py>,
    length_m: f64,
    nodes: usize,
    rms_height_m: f64,
    corr_length_x_m: Option<f64>,
    corr_length_z_m: Option<f64>,
    seed: u64,
    threads: usize,
) -> PyResult<Bound<'py, PyTuple>> {
    guarded(|| {
        let spec = SurfaceSpec {
            length_m,
            nodes,
            rms_height_m,
            corr_length_x_m,
            corr_length_z_m,
        };
        checked(&spec)?;
        let field = py.detach(|| guarded(|| on_threads(threads, || generate(&spec, seed))))?;
        let (nx, nz, dx, dz) = (field.nx, field.nz, field.dx, field.dz);
        let heights = PyArray1::from_vec(py, field.heights).reshape([nz, nx])?;
        PyTuple::new(
            py,
            [
                heights.into_any(),
                dx.into_pyobject(py)?.into_any(),
                dz.into_pyobject(py)?.into_any(),
            ],
        )
    })
}
