//! The Python extension module `roughwall._roughwall`, wrapped by the pure-Python package
//! `roughwall` (`python/roughwall/`), which checks and broadcasts the arguments and carries
//! the docstrings. Every function here is a thin layer over the physics library
//! `roughwall` (and the scan readers `topography`): the physics, its papers and equations
//! are documented there. No panic crosses into Python (`errors::guarded`).

mod errors;
mod runs;
mod scan;
mod surface;
mod wall;

use pyo3::prelude::*;

/// The module: the wall handle, surfaces, scans and runs.
#[pymodule]
fn _roughwall(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<wall::WallCore>()?;
    m.add_function(wrap_pyfunction!(surface::surface, m)?)?;
    m.add_function(wrap_pyfunction!(scan::read_scan, m)?)?;
    m.add_function(wrap_pyfunction!(scan::wall_card, m)?)?;
    m.add_function(wrap_pyfunction!(scan::measured_wall_table, m)?)?;
    m.add_function(wrap_pyfunction!(runs::stochastic, m)?)?;
    m.add_function(wrap_pyfunction!(runs::deterministic, m)?)?;
    m.add("VERSION", env!("CARGO_PKG_VERSION"))?;
    m.add("MODELS", roughwall::AnyModel::NAMES.to_vec())?;
    Ok(())
}
