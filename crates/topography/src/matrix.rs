//! A plain matrix of numbers: one row per y, one column per x (the layout of
//! SurfaceTopography's `AscReader` and of Gwyddion's export; note that SurfaceTopography's
//! `read_matrix` reads the transpose). Lines starting with `#` are skipped. The file states no
//! units: the caller gives the pixel sizes and the height unit.

use crate::error::{quote, ErrorKind, Problem, Result};
use crate::text::read_rows;
use crate::{Format, Topography};
use std::path::Path;

/// Checks an argument that must be a positive length in metres.
pub(crate) fn positive(value: f64, name: &str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Problem::new(
            ErrorKind::BadArgument,
            format!("{name} = {value}; it must be a positive length in metres"),
        ))
    }
}

pub(crate) fn read(path: &Path, dx_m: f64, dy_m: f64, unit_m: f64) -> Result<Topography> {
    let dx_m = positive(dx_m, "dx_m")?;
    let dy_m = positive(dy_m, "dy_m")?;
    let unit_m = positive(unit_m, "unit_m")?;
    let rows = read_rows(path, |line_no, line| {
        if line.starts_with('#') {
            Ok(())
        } else {
            Err(Problem::corrupt(format!(
                "line {line_no} {} is not numbers; a plain matrix has rows of numbers only \
                 (lines starting with # are skipped)",
                quote(line)
            )))
        }
    })?;
    if rows.ncols == 2 {
        crate::text::refuse_profile(rows.values.chunks_exact(2))?;
    }
    Ok(Topography {
        nx: rows.ncols,
        ny: rows.nrows,
        dx_m,
        dy_m,
        heights_m: rows.values.into_iter().map(|v| v * unit_m).collect(),
        format: Format::Matrix,
        info: vec![
            ("pixel size x (given)".to_string(), format!("{dx_m} m")),
            ("pixel size y (given)".to_string(), format!("{dy_m} m")),
            ("height unit (given)".to_string(), format!("{unit_m} m")),
        ],
    })
}
