//! `rebound deterministic --surface FILE` with a measured scan instead of a height file of
//! `rebound surface --heights`: read by `topography`, levelled by its plane, turned to its
//! lay, cropped and mirror-tiled into a periodic wall (`roughwall::surface::scan`), with what
//! was done recorded in `run.toml` (`[scan]`).

use roughwall::scan::{characterise, mirrored_wall};
use roughwall::surface::MAGIC;
use roughwall::HeightField;
use roughwall::ScanField;
use roughwall::Warning;
use roughwall::{Error, Result};
use std::io::Read;
use std::path::Path;

/// Whether `path` starts like a height file of `rebound surface --heights` (it is then read
/// as one, with that reader's messages).
fn is_height_file(path: &Path) -> bool {
    let mut magic = [0u8; 4];
    std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut magic))
        .is_ok_and(|_| magic == MAGIC)
}

/// The wall of a measured scan, its `[scan]` manifest table and the reader's warnings; `None` for a height file
/// of `rebound surface --heights` (or a path that is not a file: its reader says so).
pub fn scan_wall(path: &Path) -> Result<Option<(HeightField, toml::Table, Vec<Warning>)>> {
    if !path.is_file() || is_height_file(path) {
        return Ok(None);
    }
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
    let c = characterise(field, 1).map_err(named)?;
    let lay = c.lay.ok_or_else(|| {
        named(Error::Input(
            "no cell with four valid corners: no wall to bounce on".into(),
        ))
    })?;
    let (wall, info) = mirrored_wall(&c.levelled, lay.angle).map_err(named)?;
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
    put("levelling", "plane".into());
    put("sq_um", (c.parameters.sq_m * 1e6).into());
    put("lay_deg", lay.angle.to_degrees().into());
    put("delta_xi_deg", lay.delta_xi.to_degrees().into());
    put("delta_zeta_deg", lay.delta_zeta.to_degrees().into());
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
        "mirrored tiling of the rectangle along the lay (docs/models.md, Measured walls)".into(),
    );
    Ok(Some((wall, table, warnings)))
}
