//! Gwyddion's plain-text export (Gwyddion `modules/file/asciiexport.c`): header lines
//!
//! ```text
//! # Channel: ZSensor
//! # Width: 10.00 µm
//! # Height: 10.00 µm
//! # Value units: m
//! ```
//!
//! then one row of numbers per y, one column per x. Gwyddion translates the labels; the
//! translations accepted are those SurfaceTopography 1.27.1 lists (`IO/Text.py`, `AscReader`).
//! Width and Height are the physical sizes of the whole field: the pixel size is Width / columns.

use crate::error::{quote, Problem, Result};
use crate::text::{key_value, read_rows};
use crate::units::{parse_length, require_length};
use crate::{Format, Topography};
use std::path::Path;

const CHANNEL: [&str; 8] = [
    "Channel",
    "Kanál",
    "Kanal",
    "Canal",
    "Canale",
    "チャネル",
    "채널",
    "Канал",
];
const WIDTH: [&str; 10] = [
    "Width",
    "Šířka",
    "Breite",
    "Anchura",
    "Largeur",
    "Larghezza",
    "幅",
    "폭",
    "Largura",
    "Ширина",
];
const HEIGHT: [&str; 9] = [
    "Height",
    "Výška",
    "Höhe",
    "Altura",
    "Hauteur",
    "Altezza",
    "高さ",
    "높이",
    "Высота",
];
const VALUE_UNITS: [&str; 9] = [
    "Value units",
    "Jednotky hodnot",
    "Einheiten",
    "Unités",
    "unità valore",
    "値の単位",
    "값 단위",
    "Unidades de valor",
    "Единицы измерения",
];

/// Whether a header line is one of Gwyddion's (used by format detection).
pub(crate) fn is_header_line(line: &str) -> bool {
    line.starts_with('#')
        && key_value(line).is_some_and(|(k, _)| {
            CHANNEL.contains(&k)
                || WIDTH.contains(&k)
                || HEIGHT.contains(&k)
                || VALUE_UNITS.contains(&k)
        })
}

pub(crate) fn read(path: &Path) -> Result<Topography> {
    let mut width = None;
    let mut height = None;
    let mut z_unit = None;
    let mut info = Vec::new();
    let rows = read_rows(path, |line_no, line| {
        let Some((key, value)) = key_value(line) else {
            return Err(Problem::corrupt(format!(
                "header line {line_no} {} is not `# key: value`; a Gwyddion text export has \
                 # Channel, # Width, # Height and # Value units lines before the numbers",
                quote(line)
            )));
        };
        if WIDTH.contains(&key) {
            width = Some(parse_length(value, "the Width")?);
        } else if HEIGHT.contains(&key) {
            height = Some(parse_length(value, "the Height")?);
        } else if VALUE_UNITS.contains(&key) {
            z_unit = Some(require_length(value, "the Value units")?);
        } else if CHANNEL.contains(&key) {
            info.push(("channel".to_string(), value.to_string()));
            return Ok(());
        }
        info.push((key.to_string(), value.to_string()));
        Ok(())
    })?;
    let missing = |what: &str| {
        Problem::no_units(format!(
            "the header has no `# {what}:` line; a Gwyddion text export states # Width, \
             # Height (with units) and # Value units"
        ))
    };
    let width = width.ok_or_else(|| missing("Width"))?;
    let height = height.ok_or_else(|| missing("Height"))?;
    let z_unit = z_unit.ok_or_else(|| missing("Value units"))?;
    let (nx, ny) = (rows.ncols, rows.nrows);
    Ok(Topography {
        nx,
        ny,
        dx_m: width / nx as f64,
        dy_m: height / ny as f64,
        heights_m: rows.values.into_iter().map(|v| v * z_unit).collect(),
        format: Format::GwyddionText,
        info,
    })
}
