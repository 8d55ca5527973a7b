//! Measured walls: an instrument file read by `topography` (the readers `rebound scan`
//! uses), and a height field levelled and characterised by
//! `roughwall::scan::characterise`, with the wall card's per-diameter deviations
//! (`resolution::seen_by`) and notes (`notes`), as `rebound scan` writes them.

use crate::errors::{bytes_of, guarded, invalid, on_threads, require, to_py, with_capacity};
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};
use roughwall::check::{check_int_range, check_range};
use roughwall::scan::centre_surface_bytes;
use roughwall::scan::{characterise, Characterisation, MAX_DEGREE, MAX_POINTS, SPACING_RANGE_M};
use roughwall::scan::{labelled, notes, spread};
use roughwall::scan::{seen_by, SeenBy};
use roughwall::ScanField;
use std::path::PathBuf;
use topography::{ErrorKind, Format};

/// Diameters a card may hold, as a case's `[scan] diameters_um`.
const MAX_DIAMETERS: usize = 64;

/// Diameters allowed (m): a nanometre to a metre.
const DIAMETER_RANGE_M: (f64, f64) = (1e-9, 1.0);

/// A pixel size or unit given with a plain-text scan: finite and `> 0` (the reader and the
/// wall card check their ranges).
fn positive(key: &str, v: f64, what: &str) -> PyResult<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(invalid(key, v, &format!("{what}: a finite number > 0")))
    }
}

/// Reads an instrument file; returns (heights `(ny, nx)` in metres with NaN for missing
/// points, `dx`, `dy` in metres, the format's name, the file's other information). What is
/// not a regular file (a FIFO, a directory, a device) is refused before it is opened, as an
/// `OSError` naming the file.
#[pyfunction]
#[pyo3(signature = (path, format, pixel_m, height_unit_m))]
pub fn read_scan<'py>(
    py: Python<'py>,
    path: PathBuf,
    format: Option<String>,
    pixel_m: Option<(f64, f64)>,
    height_unit_m: Option<f64>,
) -> PyResult<Bound<'py, PyTuple>> {
    guarded(|| {
        let format = match format.as_deref() {
            None | Some("auto") => None,
            Some(name) => Some(Format::from_name(name).ok_or_else(|| {
                let names: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
                invalid(
                    "format",
                    format!("\"{name}\""),
                    &format!("\"auto\" or one of {}", names.join(", ")),
                )
            })?),
        };
        let units = matches!(format, Some(Format::Matrix | Format::Xyz));
        if units != (pixel_m.is_some() && height_unit_m.is_some()) || (!units && pixel_m.is_some())
        {
            return Err(PyValueError::new_err(
                "`pixel_m` and `height_unit_m`: give both with format=\"matrix\" or \"xyz\" (their files state no units), and neither otherwise",
            ));
        }
        if let Some((dx, dy)) = pixel_m {
            positive("pixel_m", dx, "pixel sizes (dx, dy) in m")?;
            positive("pixel_m", dy, "pixel sizes (dx, dy) in m")?;
        }
        if let Some(u) = height_unit_m {
            positive("height_unit_m", u, "the length of one height unit in m")?;
        }
        let t = py.detach(|| {
            guarded(|| {
                let read = match (format, pixel_m, height_unit_m) {
                    (Some(Format::Matrix), Some((dx, dy)), Some(u)) => {
                        topography::read_matrix(&path, dx, dy, u)
                    }
                    (Some(Format::Xyz), Some((dx, dy)), Some(u)) => {
                        topography::read_xyz(&path, 1.0, u).map(|mut t| {
                            t.dx_m = dx;
                            t.dy_m = dy;
                            t
                        })
                    }
                    (Some(f), _, _) => topography::read_as(&path, f),
                    (None, _, _) => topography::read(&path),
                };
                read.map_err(|e| match e.kind() {
                    ErrorKind::Io => PyOSError::new_err(e.to_string()),
                    _ => PyValueError::new_err(e.to_string()),
                })
            })
        })?;
        let heights = PyArray1::from_vec(py, t.heights_m).reshape([t.ny, t.nx])?;
        PyTuple::new(
            py,
            [
                heights.into_any(),
                t.dx_m.into_pyobject(py)?.into_any(),
                t.dy_m.into_pyobject(py)?.into_any(),
                t.format.name().into_pyobject(py)?.into_any(),
                PyList::new(py, t.info)?.into_any(),
            ],
        )
    })
}

fn deg(x: f64) -> f64 {
    x.to_degrees()
}

/// One particle's row of the card: what `wall_card_diameters.csv` holds.
fn diameter_row<'py>(py: Python<'py>, s: &SeenBy, f: &ScanField) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let r = &s.resolution;
    d.set_item("diameter_m", s.seen.diameter_m)?;
    d.set_item("delta_xi_deg", s.seen.lay.map(|l| deg(l.delta_xi)))?;
    d.set_item("delta_zeta_deg", s.seen.lay.map(|l| deg(l.delta_zeta)))?;
    d.set_item("exact_fraction", r.exact_fraction)?;
    let [rx, ry] = roughwall::scan::reach_um(s, f);
    d.set_item("reach_m", (rx * 1e-6, ry * 1e-6))?;
    d.set_item("footprint_m", r.footprint_m)?;
    d.set_item("correlation_areas", r.correlation_areas)?;
    let se = r.relative_error();
    d.set_item("delta_rel_se", se.is_finite().then_some(se))?;
    d.set_item("too_small", s.seen.lay.is_none() || r.too_small())?;
    // The resolution check: the same deviations at twice the pixel and their change.
    d.set_item(
        "delta_xi_deg_2x_pixel",
        s.at_double_pixel.map(|l| deg(l.delta_xi)),
    )?;
    d.set_item(
        "delta_zeta_deg_2x_pixel",
        s.at_double_pixel.map(|l| deg(l.delta_zeta)),
    )?;
    d.set_item(
        "change_2x_pixel",
        s.resolution_change().map(|[a, b]| (a, b)),
    )?;
    d.set_item("resolution_limited", s.resolution_limited())?;
    d.set_item("notes", labelled(s, f))?;
    Ok(d)
}

/// The characterisation as a dict (lengths in metres, angles in degrees).
fn card<'py>(
    py: Python<'py>,
    c: Characterisation,
    seen: &[SeenBy],
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let p = &c.parameters;
    let params = PyDict::new(py);
    params.set_item("valid_points", p.valid_points)?;
    params.set_item("mean_m", p.mean_m)?;
    params.set_item("sq_m", p.sq_m)?;
    params.set_item("ssk", p.ssk)?;
    params.set_item("sku", p.sku)?;
    params.set_item("sdq", p.sdq)?;
    params.set_item("sdq_x", p.sdq_x)?;
    params.set_item("sdq_y", p.sdq_y)?;
    out.set_item("parameters", params)?;
    out.set_item("level_degree", c.degree)?;
    match &c.lay {
        Some(l) => {
            // As `rebound scan`'s card: a wall whose anisotropy is not significant over the
            // sub-patches is isotropic, both deviations the rms of the two.
            let u = c.lay_uncertainty;
            let isotropic = u.is_some_and(|u| !u.significant());
            let rms = (0.5 * (l.delta_xi.powi(2) + l.delta_zeta.powi(2))).sqrt();
            let wall = PyDict::new(py);
            wall.set_item(
                "delta_xi_deg",
                deg(if isotropic { rms } else { l.delta_xi }),
            )?;
            wall.set_item(
                "delta_zeta_deg",
                deg(if isotropic { rms } else { l.delta_zeta }),
            )?;
            out.set_item("wall", wall)?;
            let lay = PyDict::new(py);
            lay.set_item("isotropic", isotropic)?;
            lay.set_item("angle_se_deg", u.map(|u| deg(u.angle_se)))?;
            lay.set_item("anisotropy_t", u.map(|u| u.t()))?;
            let [sx, sz] = spread(l);
            lay.set_item("angle_deg", (sx || sz).then_some(deg(l.angle)))?;
            lay.set_item("direction_scan_xy", (l.angle.cos(), l.angle.sin()))?;
            lay.set_item("rho", (sx && sz).then_some(l.rho))?;
            lay.set_item("skewness", (l.skewness[0], l.skewness[1]))?;
            lay.set_item("kurtosis", (l.kurtosis[0], l.kurtosis[1]))?;
            lay.set_item(
                "delta_scan_axes_deg",
                (deg(l.delta_scan_axes[0]), deg(l.delta_scan_axes[1])),
            )?;
            lay.set_item("triangles", l.triangles)?;
            out.set_item("lay", lay)?;
        }
        None => {
            out.set_item("wall", py.None())?;
            out.set_item("lay", py.None())?;
        }
    }
    let corr = PyDict::new(py);
    let k = &c.correlation;
    corr.set_item("angle_deg", deg(k.angle))?;
    corr.set_item("lags_m", PyArray1::from_slice(py, &k.lags_m))?;
    corr.set_item("along", PyArray1::from_slice(py, &k.along))?;
    corr.set_item("across", PyArray1::from_slice(py, &k.across))?;
    corr.set_item("length_along_m", k.length_along_m)?;
    corr.set_item("length_across_m", k.length_across_m)?;
    out.set_item("correlation", corr)?;
    // The card's notes: the wall's and the point particle's, as `rebound scan` writes them;
    // a sphere's are in its row.
    let cost = roughwall::gaussian_cost::of_scan(&c, roughwall::Triangulation::default())
        .map_err(to_py)?;
    let mut card_notes = notes(&c, cost.as_ref().map(|c| c.effect()).as_ref());
    let rows = PyList::empty(py);
    for s in seen {
        rows.append(diameter_row(py, s, &c.levelled)?)?;
        if s.seen.diameter_m == 0.0 {
            card_notes.extend(labelled(s, &c.levelled));
        }
    }
    out.set_item("diameters", rows)?;
    out.set_item("notes", card_notes)?;
    let f = c.levelled;
    out.set_item("spacing_m", (f.dx, f.dy))?;
    out.set_item(
        "levelled",
        PyArray1::from_vec(py, f.heights).reshape([f.ny, f.nx])?,
    )?;
    Ok(out)
}

/// Levels the heights `(ny, nx)` (m, NaN for a missing point; spacings `dx`, `dy` in m) by
/// a polynomial of degree `level_degree` and characterises them, with the deviations a
/// particle of each of `diameters_m` sees (the point particle first).
#[pyfunction]
#[pyo3(signature = (heights, dx, dy, level_degree, diameters_m, threads))]
pub fn wall_card<'py>(
    py: Python<'py>,
    heights: PyReadonlyArray2<'py, f64>,
    dx: f64,
    dy: f64,
    level_degree: u32,
    diameters_m: Vec<f64>,
    threads: usize,
) -> PyResult<Bound<'py, PyDict>> {
    guarded(|| {
        check_int_range(
            "level_degree",
            level_degree.into(),
            1,
            MAX_DEGREE as i64,
            "1, 2 or 3",
        )
        .map_err(to_py)?;
        if diameters_m.len() > MAX_DIAMETERS {
            return Err(invalid(
                "diameters_m",
                format!("{} diameters", diameters_m.len()),
                &format!("at most {MAX_DIAMETERS}"),
            ));
        }
        let (lo, hi) = DIAMETER_RANGE_M;
        if let Some(d) = diameters_m.iter().find(|d| !(lo..=hi).contains(*d)) {
            return Err(invalid(
                "diameters_m",
                d,
                &format!("diameters from {lo} to {hi} m"),
            ));
        }
        let [ny, nx] = [heights.shape()[0], heights.shape()[1]];
        if !diameters_m.is_empty() {
            require(
                "diameters_m",
                format!("{} diameters", diameters_m.len()),
                centre_surface_bytes(nx, ny),
                &format!("the centre surface of a sphere over the {nx} × {ny} scan"),
            )?;
        }
        let field = scan_field(&heights, dx, dy)?;
        let (c, seen) = py.detach(|| {
            guarded(|| {
                on_threads(threads, || {
                    let c = characterise(field, level_degree).map_err(to_py)?;
                    let seen = seen_by(&c, &diameters_m).unwrap_or_default();
                    Ok((c, seen))
                })?
            })
        })?;
        card(py, c, &seen)
    })
}

/// The heights `(ny, nx)` (m, NaN for a missing point) with spacings `dx`, `dy` (m) as a
/// scan: the spacings and the size checked, and the copy's memory before it is made.
fn scan_field(heights: &PyReadonlyArray2<'_, f64>, dx: f64, dy: f64) -> PyResult<ScanField> {
    // The spacings ScanField takes, named as the arguments that give them.
    let (lo, hi) = SPACING_RANGE_M;
    for (key, d) in [("dx", dx), ("dy", dy)] {
        check_range(
            key,
            d,
            lo,
            hi,
            &format!("a pixel size from {lo:e} to {hi} m (one outside this is a unit mistake)"),
        )
        .map_err(to_py)?;
    }
    let [ny, nx] = [heights.shape()[0], heights.shape()[1]];
    let size = format!("{ny} × {nx} points");
    let points = nx
        .checked_mul(ny)
        .filter(|&p| p <= MAX_POINTS)
        .ok_or_else(|| invalid("scan", &size, &format!("at most {MAX_POINTS} points")))?;
    let copy = bytes_of("scan", &size, points, 8, "a copy of the heights")?;
    require("scan", &size, copy, "a copy of the heights")?;
    let mut h = with_capacity::<f64>("scan", &size, points, "a copy of the heights")?;
    // Row-major: a C-ordered array in one copy, any other layout point by point.
    let view = heights.as_array();
    match view.as_slice() {
        Some(s) => h.extend_from_slice(s),
        None => h.extend(view.iter().copied()),
    }
    ScanField::new(nx, ny, dx, dy, h).map_err(to_py)
}

/// The measured-wall table (its text) of the heights `(ny, nx)` levelled by a polynomial of
/// degree `level_degree`: the in-place deterministic reference of the point particle, or of a
/// sphere of `diameter_m`, over the table's grid with `histories_per_cell` histories per cell
/// (the law of `rebound scan --measured-wall`'s table, bit for bit, for the same seed; its
/// `source` line says "a scan").
#[pyfunction]
#[pyo3(signature = (heights, dx, dy, level_degree, diameter_m, histories_per_cell, seed, threads))]
#[allow(clippy::too_many_arguments)]
pub fn measured_wall_table<'py>(
    py: Python<'py>,
    heights: PyReadonlyArray2<'py, f64>,
    dx: f64,
    dy: f64,
    level_degree: u32,
    diameter_m: Option<f64>,
    histories_per_cell: u64,
    seed: u64,
    threads: usize,
) -> PyResult<String> {
    guarded(|| {
        check_int_range(
            "level_degree",
            level_degree.into(),
            1,
            MAX_DEGREE as i64,
            "1, 2 or 3",
        )
        .map_err(to_py)?;
        if let Some(d) = diameter_m {
            let (lo, hi) = DIAMETER_RANGE_M;
            if !(lo..=hi).contains(&d) {
                return Err(invalid(
                    "diameter_m",
                    d,
                    &format!("a diameter from {lo} to {hi} m, or None (the point particle)"),
                ));
            }
        }
        check_int_range(
            "histories_per_cell",
            histories_per_cell.min(i64::MAX as u64) as i64,
            1024,
            1_000_000,
            "1024 to 1000000 histories per cell of the table's grid",
        )
        .map_err(to_py)?;
        let field = scan_field(&heights, dx, dy)?;
        if diameter_m.is_some() {
            require(
                "diameter_m",
                format!("{:?}", diameter_m),
                centre_surface_bytes(field.nx, field.ny),
                &format!(
                    "the centre surface of a sphere over the {} × {} scan",
                    field.nx, field.ny
                ),
            )?;
        }
        py.detach(|| {
            guarded(|| {
                on_threads(threads, || {
                    let c = characterise(field, level_degree).map_err(to_py)?;
                    let lay = c.lay.ok_or_else(|| {
                        invalid(
                            "scan",
                            "no cell with four valid corners",
                            "a scan with a lay",
                        )
                    })?;
                    let what = match diameter_m {
                        Some(d) => {
                            format!("a scan, {} µm sphere", roughwall::format::fmt_num(d * 1e6))
                        }
                        None => "a scan, point particle".to_string(),
                    };
                    let opts = roughwall::measured_wall::BuildOptions {
                        histories_per_cell,
                        seed,
                    };
                    let table = roughwall::measured_wall::scan_table(
                        &c.levelled,
                        &lay,
                        diameter_m,
                        roughwall::Triangulation::default(),
                        &what,
                        &opts,
                        &|_| {},
                    )
                    .map_err(to_py)?;
                    Ok(table.to_text())
                })?
            })
        })
    })
}
