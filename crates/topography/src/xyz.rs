//! x, y, z columns on a regular grid, in any order of the points (as SurfaceTopography 1.27.1
//! reads them, `IO/XYZ.py`: the distinct x and y positions, equally spaced, each (x, y) once).
//! A scattered or incomplete grid is refused: interpolating it would invent heights. Units
//! come from the caller, or from a Gwyddion `xyzexport.c` header (`# Lateral units: µm`,
//! `# Value units: m`).

use crate::error::{quote, ErrorKind, Problem, Result};
use crate::grid::check_shape;
use crate::matrix::positive;
use crate::text::{key_value, read_rows};
use crate::units::require_length;
use crate::{Format, Topography};
use std::path::Path;

/// How far a position may lie from its grid line, in steps: printed coordinates are rounded.
const POSITION_TOLERANCE: f64 = 0.01;

pub(crate) fn read(path: &Path, units: Option<(f64, f64)>) -> Result<Topography> {
    if let Some((xy, z)) = units {
        positive(xy, "xy_unit_m")?;
        positive(z, "z_unit_m")?;
    }
    let (mut lateral, mut value) = (None, None);
    let mut info = Vec::new();
    let rows = read_rows(path, |line_no, line| {
        let kv = key_value(line).filter(|_| line.starts_with('#'));
        match kv {
            Some(("Lateral units", u)) => lateral = Some(require_length(u, "the Lateral units")?),
            Some(("Value units", u)) => value = Some(require_length(u, "the Value units")?),
            Some((k, v)) => info.push((k.to_string(), v.to_string())),
            None if line.starts_with('#') => {}
            None => {
                return Err(Problem::corrupt(format!(
                    "line {line_no} {} is not three numbers; x y z text has a row x y z per \
                     point (header lines start with #)",
                    quote(line)
                )))
            }
        }
        Ok(())
    })?;
    let (xy_unit, z_unit) =
        match (units, lateral, value) {
            (Some(u), _, _) => u,
            (None, Some(l), Some(v)) => (l, v),
            _ => return Err(Problem::no_units(
                "x y z text without `# Lateral units:` and `# Value units:` header lines states \
                 no units: read it with read_xyz(path, xy_unit_m, z_unit_m)",
            )),
        };
    if rows.ncols != 3 {
        return Err(Problem::corrupt(format!(
            "the rows have {} numbers; x y z text has 3 per row (a matrix of heights is read \
             with read_matrix)",
            rows.ncols
        )));
    }
    let n = rows.nrows;
    let xs: Vec<f64> = rows.values.chunks_exact(3).map(|p| p[0]).collect();
    let ys: Vec<f64> = rows.values.chunks_exact(3).map(|p| p[1]).collect();
    let ax = Axis::of(&xs, "x")?;
    let ay = Axis::of(&ys, "y")?;
    let points = check_shape(ax.n as i64, ay.n as i64)?;
    if points != n {
        return Err(Problem::corrupt(format!(
            "{n} points on {} x positions × {} y positions ({points}): not a regular grid \
             (each grid position needs exactly one point)",
            ax.n, ay.n
        )));
    }
    let mut heights = vec![f64::NAN; points];
    let mut seen = vec![false; points];
    for p in rows.values.chunks_exact(3) {
        let k = ay.index(p[1]) * ax.n + ax.index(p[0]);
        if std::mem::replace(&mut seen[k], true) {
            return Err(Problem::corrupt(format!(
                "the position x = {}, y = {} appears twice; a regular grid has one point per \
                 position",
                p[0], p[1]
            )));
        }
        heights[k] = p[2] * z_unit;
    }
    info.push(("lateral unit".to_string(), format!("{xy_unit} m")));
    info.push(("value unit".to_string(), format!("{z_unit} m")));
    Ok(Topography {
        nx: ax.n,
        ny: ay.n,
        dx_m: ax.step * xy_unit,
        dy_m: ay.step * xy_unit,
        heights_m: heights,
        format: Format::Xyz,
        info,
    })
}

/// The equally spaced positions along one axis.
struct Axis {
    first: f64,
    step: f64,
    n: usize,
}

impl Axis {
    fn of(values: &[f64], name: &str) -> Result<Axis> {
        if let Some(v) = values.iter().find(|v| !v.is_finite()) {
            return Err(Problem::corrupt(format!(
                "an {name} position is {v}; positions must be numbers (only z may be NaN)"
            )));
        }
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        let (lo, hi) = (sorted[0], sorted[sorted.len() - 1]);
        let same = 1e-9 * lo.abs().max(hi.abs()).max(hi - lo);
        let mut distinct: Vec<f64> = Vec::new();
        for v in sorted {
            if distinct.last().is_none_or(|&d| v - d > same) {
                distinct.push(v);
            }
        }
        let n = distinct.len();
        if n < 2 {
            return Err(Problem::new(
                ErrorKind::NoData,
                format!(
                    "all points have the same {name}; a height field needs at least 2 × 2 points"
                ),
            ));
        }
        let step = (hi - lo) / (n - 1) as f64;
        for (i, &d) in distinct.iter().enumerate() {
            let expected = lo + i as f64 * step;
            if (d - expected).abs() > POSITION_TOLERANCE * step {
                return Err(Problem::corrupt(format!(
                    "the {n} distinct {name} positions are not equally spaced ({name} = {d} where \
                     a regular grid from {lo} to {hi} has {expected}): not a regular grid; \
                     interpolate the points onto one first"
                )));
            }
        }
        Ok(Axis { first: lo, step, n })
    }

    fn index(&self, v: f64) -> usize {
        (((v - self.first) / self.step).round() as usize).min(self.n - 1)
    }
}
