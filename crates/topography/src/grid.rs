//! The checks every reader makes on a grid: the declared shape and data length before anything
//! is allocated, the pixel sizes, and, on the finished height field, that it has points to use.

use crate::error::{ErrorKind, Problem, Result};
use crate::Topography;

/// The most points a scan may have: 2^28 (268 million, 2 GiB of heights). A header claiming
/// more is refused before anything is allocated.
pub const MAX_POINTS: usize = 1 << 28;

/// Checks a declared grid of `nx` × `ny` points (as the header states them, possibly
/// negative): at least 2 along each axis and at most [`MAX_POINTS`] in all. Returns the number
/// of points.
pub(crate) fn check_shape(nx: i64, ny: i64) -> Result<usize> {
    if nx < 1 || ny < 1 {
        return Err(Problem::corrupt(format!(
            "the header declares {nx} × {ny} points; a grid needs a positive number along each axis"
        )));
    }
    if nx < 2 || ny < 2 {
        return Err(Problem::new(
            ErrorKind::NoData,
            format!(
                "the scan has {nx} × {ny} points; a height field needs at least 2 × 2 \
                 (a single point or a line profile is not a surface)"
            ),
        ));
    }
    match nx.checked_mul(ny) {
        Some(n) if n <= MAX_POINTS as i64 => Ok(n as usize),
        _ => Err(Problem::new(
            ErrorKind::TooLarge,
            format!(
                "the header declares {nx} × {ny} points; at most {MAX_POINTS} (2^28) points \
                 are read"
            ),
        )),
    }
}

/// Checks that `available` bytes hold `points` values of `size` bytes (`what` names the data
/// and its type, e.g. "SUR data (32-bit integers)").
pub(crate) fn check_data_len(
    points: usize,
    size: usize,
    available: usize,
    what: &str,
) -> Result<()> {
    let need = points as u128 * size as u128;
    if (available as u128) < need {
        return Err(Problem::truncated(format!(
            "{what}: the header declares {points} points of {size} bytes ({need} bytes) but \
             the file holds only {available}"
        )));
    }
    Ok(())
}

/// Checks a pixel size in metres: finite and positive.
pub(crate) fn check_pixel(d_m: f64, axis: &str) -> Result<f64> {
    if d_m.is_finite() && d_m > 0.0 {
        Ok(d_m)
    } else {
        Err(Problem::corrupt(format!(
            "the pixel size along {axis} is {d_m} m; it must be a positive length"
        )))
    }
}

/// The last check of every read: shape, pixel sizes, heights that did not overflow when
/// converted to metres, and at least one valid point.
pub(crate) fn finish(t: Topography) -> Result<Topography> {
    check_shape(t.nx as i64, t.ny as i64)?;
    debug_assert_eq!(t.heights_m.len(), t.nx * t.ny);
    check_pixel(t.dx_m, "x")?;
    check_pixel(t.dy_m, "y")?;
    if let Some(i) = t.heights_m.iter().position(|h| h.is_infinite()) {
        return Err(Problem::corrupt(format!(
            "the height of point ({}, {}) overflows: the file's value times its height unit \
             is beyond the largest number (±1.8e308 m); heights must be finite",
            i % t.nx,
            i / t.nx
        )));
    }
    if t.valid_count() == 0 {
        return Err(Problem::new(
            ErrorKind::NoData,
            format!(
                "all {} × {} points are marked missing or invalid; a scan needs measured points",
                t.nx, t.ny
            ),
        ));
    }
    Ok(t)
}
