//! `rebound deterministic --surface FILE` with a measured scan instead of a height file of
//! `rebound surface --heights`: read by `topography`, levelled by its plane, and made the
//! run's wall as `[deterministic] scan_wall` asks: in place (the scan's own triangles, the
//! incident directions turned by its lay; the default) or turned to its lay and mirror-tiled
//! into a periodic wall. What was done is recorded in `run.toml` (`[scan]`).

use crate::case::deterministic::DeterministicOptions;
use roughwall::deterministic::{in_place_wall, surface_from_field, BuiltSurface, ScanReference};
use roughwall::deterministic::{LEFT_PATCH_BOUND, MARGIN_FLIGHTS};
use roughwall::scan::{characterise, mirrored_wall};
use roughwall::surface::is_height_file;
use roughwall::ScanField;
use roughwall::Warning;
use roughwall::{Error, Result};
use std::path::Path;

/// A measured scan made the run's wall.
pub struct ScanWall {
    /// The wall the tracker walks (a patch in place, or the periodic mirrored wall).
    pub built: BuiltSurface,
    /// The `[scan]` table of `run.toml`.
    pub table: toml::Table,
    /// What the reader read despite a flaw.
    pub warnings: Vec<Warning>,
    /// In place: `(Δξ, Δζ)` (rad) of the wall's own triangles along and across its lay,
    /// what the particles met (the periodic wall's are measured on it as for any surface).
    pub met: Option<(f64, f64)>,
}

/// The wall of a measured scan; `None` for a height file of `rebound surface --heights` (or
/// a path that is not a file: its reader says so).
pub fn scan_wall(path: &Path, opt: &DeterministicOptions) -> Result<Option<ScanWall>> {
    if !path.is_file() || is_height_file(path) {
        return Ok(None);
    }
    let t0 = std::time::Instant::now();
    let t = topography::read(path).map_err(|e| Error::Input(format!("--surface {e}")))?;
    // What the reader read despite a flaw (an X3P whose main.xml alone fails its checksum).
    let warnings: Vec<Warning> = t
        .info
        .iter()
        .filter(|(k, _)| k == "warning")
        .map(|(_, v)| Warning(format!("--surface `{}`: {v}", path.display())))
        .collect();
    let named = |e: Error| match e {
        Error::Input(m) => Error::Input(format!("--surface `{}`: {m}", path.display())),
        other => other,
    };
    let field = ScanField::new(t.nx, t.ny, t.dx_m, t.dy_m, t.heights_m).map_err(named)?;
    let c = characterise(field, opt.scan_level_degree).map_err(named)?;
    let lay = c.lay.ok_or_else(|| {
        named(Error::Input(
            "no cell with four valid corners: no wall to bounce on".into(),
        ))
    })?;
    let mut table = toml::Table::new();
    let mut put = |k: &str, v: toml::Value| {
        table.insert(k.into(), v);
    };
    put("file", path.display().to_string().into());
    put("format", t.format.name().into());
    put(
        "points",
        toml::Value::Array(vec![(t.nx as i64).into(), (t.ny as i64).into()]),
    );
    put(
        "pixel_um",
        toml::Value::Array(vec![(t.dx_m * 1e6).into(), (t.dy_m * 1e6).into()]),
    );
    put(
        "levelling",
        match opt.scan_level_degree {
            1 => "plane".to_string(),
            d => format!("polynomial of degree {d}"),
        }
        .into(),
    );
    put("sq_um", (c.parameters.sq_m * 1e6).into());
    put("lay_deg", lay.angle.to_degrees().into());
    put("delta_xi_deg", lay.delta_xi.to_degrees().into());
    put("delta_zeta_deg", lay.delta_zeta.to_degrees().into());
    put("reference", opt.scan_reference.name().into());
    let secs = t0.elapsed().as_secs_f64();
    let (built, met) = match opt.scan_reference {
        ScanReference::InPlace => {
            let t1 = std::time::Instant::now();
            let mut wall = in_place_wall(
                &c.levelled,
                lay.angle,
                opt.sphere_diameter_m,
                opt.triangulation,
            )
            .map_err(named)?;
            wall.entry_alpha = opt.entry_alpha;
            let dilation_s = t1.elapsed().as_secs_f64();
            let [x0, y0, nx, ny] = wall.crop;
            put(
                "block_first_point",
                toml::Value::Array(vec![(x0 as i64).into(), (y0 as i64).into()]),
            );
            put(
                "block_points",
                toml::Value::Array(vec![(nx as i64).into(), (ny as i64).into()]),
            );
            put("block_area_fraction", wall.area_fraction.into());
            let range = {
                let h = &wall.field.heights;
                let (lo, hi) = h
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                        (a.min(x), b.max(x))
                    });
                hi - lo
            };
            put("height_range_um", (range * 1e6).into());
            put("margin_flights", MARGIN_FLIGHTS.into());
            put(
                "entry_region",
                match opt.entry_alpha {
                    Some(a) => format!(
                        "one for every direction: the margins of |α⁻| = {}° on every side",
                        crate::output::fmt_num(a.to_degrees())
                    ),
                    None => {
                        "follows each direction (its margins grow with cot α⁻, most downstream)"
                            .to_string()
                    }
                }
                .into(),
            );
            if let Some(a) = opt.entry_alpha {
                // The one region's sides (µm, along the scan's x and y): the part of the scan
                // every direction's histories enter over.
                let tracker = wall.tracker().map_err(named)?;
                if let Some(patch) = tracker.patch() {
                    let m = patch
                        .margins(a, &nalgebra::Vector3::new(1.0, -1.0, 0.0))
                        .sides;
                    let sides = [
                        (patch.extent.0 - m[0] - m[1]) * 1e6,
                        (patch.extent.1 - m[2] - m[3]) * 1e6,
                    ];
                    put(
                        "entry_region_um",
                        toml::Value::Array(sides.iter().map(|&x| x.into()).collect()),
                    );
                }
            }
            put("left_patch_bound", LEFT_PATCH_BOUND.into());
            put(
                "wall",
                "the scan's own triangles at its pixel, not resampled or mirrored; incident directions turned by the lay; particles enter over an inner region (docs/models.md, Measured walls)".into(),
            );
            let met = wall.deviations.as_ref().map(|d| (d.delta_xi, d.delta_zeta));
            (BuiltSurface::in_place(wall, secs, dilation_s), met)
        }
        ScanReference::Mirrored => {
            let (wall, info) = mirrored_wall(&c.levelled, lay.angle).map_err(named)?;
            put(
                "rectangle_points",
                toml::Value::Array(vec![
                    (info.rectangle[0] as i64).into(),
                    (info.rectangle[1] as i64).into(),
                ]),
            );
            put("rectangle_area_fraction", info.area_fraction.into());
            put("spacing_um", (info.spacing_m * 1e6).into());
            put(
                "periodic_wall",
                "mirrored tiling of the rectangle along the lay (docs/models.md, Measured walls)"
                    .into(),
            );
            let built =
                surface_from_field(wall, "scan", secs, opt.sphere_diameter_m, opt.triangulation)?;
            (built, None)
        }
    };
    Ok(Some(ScanWall {
        built,
        table,
        warnings,
        met,
    }))
}
