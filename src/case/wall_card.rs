//! `--wall-card FILE` of `stochastic` and `deterministic`: the wall of a `wall_card.toml`
//! written by `rebound scan`, in place of the case's `[wall]`, so that a scan becomes a run in
//! two commands (issue 29, part 5; docs/models.md "Measured walls").
//!
//! Which deviations the run takes:
//! - `stochastic`, with `[[diameter]]` rows in the card: the row of the particle diameter
//!   (`[particles] diameter_um`, default 500 µm), the deviations a sphere of that diameter sees
//!   (its centre surface on the scan); no row of that diameter is an error listing the card's.
//!   The row already is what `[stochastic] effective_for_diameter` would compute, which is
//!   then switched off.
//! - `stochastic` without rows or with `--wall-card-point` ([`CardWall::Point`]), and
//!   `deterministic` always: `[wall]`, the wall's own (the point particle's). `deterministic`
//!   generates the wall and, with `contact = "sphere"`, rolls the sphere on it itself: a row
//!   would smooth the wall twice.
//!
//! The card's `[scan] sq_um` becomes the wall's `rms_height_um`, the absolute scale a sphere
//! on the automatic surface needs (`[deterministic] rms_height_um` still wins).
//!
//! With `[stochastic] model = "measured-wall"` and no `wall_table`, `stochastic` takes the
//! measured-wall table the taken row (or `[wall]`) names (`measured_wall_table`, written by
//! `rebound scan --measured-wall` beside the card; relative to the card's directory).

use super::scene::DEFAULT_DIAMETER_UM;
use super::schema::{Case, WallSpec};
use crate::output::{fmt_num, sha256_hex};
use roughwall::check::not_a_regular_file;
use roughwall::Warning;
use roughwall::{Error, Result};
use std::path::Path;

/// Which of a card's walls `stochastic` takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CardWall {
    /// The `[[diameter]]` row of the particles' diameter when the card has rows, else `[wall]`.
    OfTheParticles,
    /// `[wall]`, the point particle's (and its table), whatever rows the card has
    /// (`--wall-card-point`): a case cannot name a point particle by its diameter.
    Point,
}

/// Largest card read (bytes): a card with 64 diameters is about 20 kB.
const MAX_CARD_BYTES: u64 = 1 << 20;

/// Relative tolerance of a diameter match: the card writes 7 significant digits.
const DIAMETER_MATCH: f64 = 1e-6;

/// One `[[diameter]]` row of a card.
#[derive(Clone, Debug, PartialEq)]
struct Row {
    diameter_um: f64,
    /// `(Δξ, Δζ)` in degrees; `None` when nothing of the centre surface was exact.
    deviations: Option<(f64, f64)>,
    note: String,
    /// `measured_wall_table`: the row's measured-wall table, relative to the card.
    table: Option<String>,
}

/// A wall card, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct WallCard {
    /// The file as given.
    shown: String,
    sha256: String,
    /// `[wall]`: `(Δξ, Δζ)` in degrees.
    wall: (f64, f64),
    /// `[scan] sq_um`, when positive.
    sq_um: Option<f64>,
    /// `[scan] file`, when the card names one.
    scan_file: Option<String>,
    rows: Vec<Row>,
    /// `[wall] measured_wall_table`: the point particle's table, relative to the card.
    wall_table: Option<String>,
    /// The card's directory (its tables are named relative to it).
    dir: std::path::PathBuf,
}

/// What applying a card did: the `[wall_card]` table of `run.toml` and the lines to print.
#[derive(Debug)]
pub struct Applied {
    pub manifest: toml::Table,
    pub warnings: Vec<Warning>,
}

/// A text of the card at `table.key` (`None` when absent), or the one-line error naming the
/// file and the key.
fn text_of(what: &str, table: &toml::Table, section: &str, key: &str) -> Result<Option<String>> {
    match table.get(key) {
        None => Ok(None),
        Some(toml::Value::String(s)) if !s.trim().is_empty() => Ok(Some(s.clone())),
        Some(v) => Err(Error::Input(format!(
            "{what}: `{section}{key}` = {v} is not a file name"
        ))),
    }
}

/// A number of the card at `table.key`, or the one-line error naming the file and the key.
fn number(what: &str, table: &toml::Table, section: &str, key: &str) -> Result<f64> {
    match table.get(key) {
        Some(toml::Value::Float(x)) if x.is_finite() => Ok(*x),
        Some(toml::Value::Integer(i)) => Ok(*i as f64),
        Some(v) => Err(Error::Input(format!(
            "{what}: `{section}{key}` = {v} is not a finite number"
        ))),
        None => Err(Error::Input(format!("{what}: `{section}{key}` is missing"))),
    }
}

impl WallCard {
    /// Reads the card at `path` (`--wall-card`): one-line errors naming the option, the file
    /// and what is wrong.
    pub fn read(path: &Path) -> Result<WallCard> {
        let what = format!("`--wall-card` {}", path.display());
        if let Some(kind) = not_a_regular_file(path) {
            return Err(Error::Input(format!("{what}: {kind}, not a file")));
        }
        let len = std::fs::metadata(path)
            .map_err(|e| Error::Input(format!("{what}: {e}")))?
            .len();
        if len > MAX_CARD_BYTES {
            return Err(Error::Input(format!(
                "{what}: {len} bytes, more than a wall card ({MAX_CARD_BYTES} at most)"
            )));
        }
        let bytes = std::fs::read(path).map_err(|e| Error::Input(format!("{what}: {e}")))?;
        let text = String::from_utf8(bytes.clone())
            .map_err(|_| Error::Input(format!("{what}: not UTF-8 text, not a wall card")))?;
        let t: toml::Table = text.parse().map_err(|e: toml::de::Error| {
            let first = e.to_string();
            let first = first.lines().next().unwrap_or("").trim().to_string();
            Error::Input(format!("{what}: not a wall card (TOML: {first})"))
        })?;
        let Some(toml::Value::Table(wall)) = t.get("wall") else {
            return Err(Error::Input(format!(
                "{what} has no [wall]: the scan it was written from has no lay (no cell with four valid corners), so no deviations"
            )));
        };
        let wall = (
            number(&what, wall, "wall.", "delta_xi_deg")?,
            number(&what, wall, "wall.", "delta_zeta_deg")?,
        );
        let scan = match t.get("scan") {
            Some(toml::Value::Table(s)) => s.clone(),
            _ => toml::Table::new(),
        };
        let sq_um = scan
            .get("sq_um")
            .and_then(|v| v.as_float())
            .filter(|x| x.is_finite() && *x > 0.0);
        let scan_file = scan.get("file").and_then(|v| v.as_str()).map(String::from);
        let rows = match t.get("diameter") {
            None => Vec::new(),
            Some(toml::Value::Array(a)) => a
                .iter()
                .map(|r| {
                    let r = r.as_table().ok_or_else(|| {
                        Error::Input(format!("{what}: a [[diameter]] that is not a table"))
                    })?;
                    let d = number(&what, r, "diameter.", "diameter_um")?;
                    let deviations = match r.contains_key("delta_xi_deg") {
                        true => Some((
                            number(&what, r, "diameter.", "delta_xi_deg")?,
                            number(&what, r, "diameter.", "delta_zeta_deg")?,
                        )),
                        false => None,
                    };
                    let note = r.get("note").and_then(|n| n.as_str()).unwrap_or("");
                    Ok(Row {
                        diameter_um: d,
                        deviations,
                        note: note.into(),
                        table: text_of(&what, r, "diameter.", "measured_wall_table")?,
                    })
                })
                .collect::<Result<_>>()?,
            Some(_) => {
                return Err(Error::Input(format!(
                    "{what}: `diameter` is not an array of [[diameter]] tables"
                )))
            }
        };
        let wall_table = match t.get("wall") {
            Some(toml::Value::Table(w)) => text_of(&what, w, "wall.", "measured_wall_table")?,
            _ => None,
        };
        Ok(WallCard {
            shown: path.display().to_string(),
            sha256: sha256_hex(&bytes),
            wall,
            sq_um,
            scan_file,
            rows,
            wall_table,
            dir: path.parent().map(Path::to_path_buf).unwrap_or_default(),
        })
    }

    /// The diameters of the card's rows, for messages: `100, 500 µm`. Not its [wall]: a
    /// point particle is no `particles.diameter_um` a case can give (a nanometre at least).
    fn diameters(&self) -> String {
        let d: Vec<String> = self.rows.iter().map(|r| fmt_num(r.diameter_um)).collect();
        format!("{} µm", d.join(", "))
    }

    /// Replaces the wall of `case` by the card's for `command` (`stochastic` or
    /// `deterministic`, the module doc says which deviations each takes; `taking` chooses
    /// for `stochastic`).
    pub fn apply(&self, case: &mut Case, command: &str, taking: CardWall) -> Result<Applied> {
        let what = format!("`--wall-card` {}", self.shown);
        if case.surface.is_some() {
            return Err(Error::Input(format!(
                "{what}: the case gives a [surface] (a grid of its own), which a wall card does not replace: give the case a [wall], or none"
            )));
        }
        let mut manifest = toml::Table::new();
        manifest.insert("file".into(), self.shown.clone().into());
        manifest.insert("sha256".into(), self.sha256.clone().into());
        if let Some(f) = &self.scan_file {
            manifest.insert("scan_file".into(), f.clone().into());
        }
        let mut warnings = Vec::new();
        let rows_apply =
            command == "stochastic" && !self.rows.is_empty() && taking == CardWall::OfTheParticles;
        let (dev, taken, table) = if rows_apply {
            let d = case
                .particles
                .as_ref()
                .and_then(|p| p.diameter_um)
                .unwrap_or(DEFAULT_DIAMETER_UM);
            let row = self
                .rows
                .iter()
                .find(|r| (r.diameter_um - d).abs() <= DIAMETER_MATCH * d.abs())
                .ok_or_else(|| {
                    Error::Input(format!(
                        "{what} has no [[diameter]] row for the particles' {} µm (`particles.diameter_um`, default {DEFAULT_DIAMETER_UM}): its rows are for {}; set `particles.diameter_um` to one of them, run `rebound scan --diameter-um {}`, or take its [wall], the point particle's, with `--wall-card-point`",
                        fmt_num(d),
                        self.diameters(),
                        fmt_num(d)
                    ))
                })?;
            let dev = row.deviations.ok_or_else(|| {
                Error::Input(format!(
                    "{what}: its [[diameter]] row for {} µm has no deviations (no triangle of the centre surface was exact: the scan is too small for that diameter)",
                    fmt_num(row.diameter_um)
                ))
            })?;
            manifest.insert("row".into(), "diameter".into());
            manifest.insert("diameter_um".into(), row.diameter_um.into());
            if !row.note.is_empty() {
                manifest.insert("note".into(), row.note.clone().into());
                warnings.push(Warning(format!(
                    "`--wall-card` {}, row {} µm: {}",
                    self.shown,
                    fmt_num(row.diameter_um),
                    row.note
                )));
            }
            if let Some(st) = case.stochastic.as_mut() {
                if st.effective_for_diameter == Some(true) {
                    st.effective_for_diameter = None;
                    manifest.insert("effective_for_diameter".into(), "the row's".into());
                }
            }
            (
                dev,
                format!("its [[diameter]] row of {} µm", fmt_num(row.diameter_um)),
                row.table.clone(),
            )
        } else {
            manifest.insert("row".into(), "wall".into());
            if taking == CardWall::Point && !self.rows.is_empty() {
                manifest.insert("point".into(), "--wall-card-point".into());
            }
            (self.wall, "its [wall]".to_string(), self.wall_table.clone())
        };
        // The wall's own model takes the taken row's table, unless the case names one.
        if let Some(st) = case.stochastic.as_mut() {
            if command == "stochastic"
                && st.model.as_deref() == Some("measured-wall")
                && st.wall_table.is_none()
            {
                let file = table.ok_or_else(|| {
                    Error::Input(format!(
                        "{what}: {taken} names no measured-wall table (`measured_wall_table`), which model = \"measured-wall\" needs: run `rebound scan --measured-wall`, or set `stochastic.wall_table`"
                    ))
                })?;
                let path = self.dir.join(&file);
                manifest.insert(
                    "measured_wall_table".into(),
                    path.display().to_string().into(),
                );
                st.wall_table = Some(path.display().to_string());
            }
        }
        manifest.insert("delta_xi_deg".into(), dev.0.into());
        manifest.insert("delta_zeta_deg".into(), dev.1.into());
        if let Some(sq) = self.sq_um {
            manifest.insert("rms_height_um".into(), sq.into());
        }
        if let Some(w) = &case.wall {
            let own = match (w.delta_xi_deg, w.delta_zeta_deg) {
                (Some(x), Some(z)) => format!(" (Δξ, Δζ) = ({}°, {}°)", fmt_num(x), fmt_num(z)),
                _ => String::new(),
            };
            warnings.push(Warning(format!(
                "`--wall-card` {} replaces the case's [wall]{own} by {taken}: (Δξ, Δζ) = ({}°, {}°)",
                self.shown,
                fmt_num(dev.0),
                fmt_num(dev.1)
            )));
        }
        case.wall = Some(WallSpec {
            delta_xi_deg: Some(dev.0),
            delta_zeta_deg: Some(dev.1),
            rms_height_um: self.sq_um,
            ..WallSpec::default()
        });
        Ok(Applied { manifest, warnings })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CARD: &str = "notes = []\n[wall]\ndelta_xi_deg = 1.5\ndelta_zeta_deg = 3.0\n\
        measured_wall_table = \"measured_wall_point.txt\"\n\
        [scan]\nfile = \"w.x3p\"\nsq_um = 0.08\n\
        [[diameter]]\ndiameter_um = 100.0\ndelta_xi_deg = 0.7\ndelta_zeta_deg = 1.4\nnote = \"\"\n\
        [[diameter]]\ndiameter_um = 500.0\ndelta_xi_deg = 0.3\ndelta_zeta_deg = 0.5\nnote = \"too small: x\"\n\
        [[diameter]]\ndiameter_um = 1000000.0\nnote = \"too small: no triangle\"\n";

    fn card(text: &str) -> (tempfile::TempDir, Result<WallCard>) {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("card.toml");
        std::fs::write(&p, text).unwrap();
        let c = WallCard::read(&p);
        (dir, c)
    }

    fn case(text: &str) -> Case {
        super::super::parse(&format!("name = \"t\"\n{text}"), "t.toml").unwrap()
    }

    #[test]
    fn stochastic_takes_the_row_of_its_diameter_and_deterministic_the_wall() {
        let (_d, c) = card(CARD);
        let c = c.unwrap();
        // The particles' 500 µm (the default), with effective_for_diameter switched off.
        let mut k = case("[wall]\ndelta_xi_deg = 3.8\ndelta_zeta_deg = 7.5\n[stochastic]\neffective_for_diameter = true\n");
        let a = c
            .apply(&mut k, "stochastic", CardWall::OfTheParticles)
            .unwrap();
        let w = k.wall.clone().unwrap();
        assert_eq!((w.delta_xi_deg, w.delta_zeta_deg), (Some(0.3), Some(0.5)));
        assert_eq!(w.rms_height_um, Some(0.08));
        assert_eq!(k.stochastic.unwrap().effective_for_diameter, None);
        assert_eq!(a.manifest["diameter_um"].as_float(), Some(500.0));
        assert_eq!(a.warnings.len(), 2, "{:?}", a.warnings);
        assert!(a.warnings[0].0.ends_with("row 500 µm: too small: x"));
        assert!(a.warnings[1].0.contains("replaces the case's [wall] (Δξ, Δζ) = (3.8°, 7.5°) by its [[diameter]] row of 500 µm: (Δξ, Δζ) = (0.3°, 0.5°)"), "{:?}", a.warnings);
        // 100 µm; then deterministic: [wall], whatever the diameter; no [wall] to replace, no
        // line.
        let mut k = case("[particles]\ndiameter_um = 100.0000001\n");
        c.apply(&mut k, "stochastic", CardWall::OfTheParticles)
            .unwrap();
        assert_eq!(k.wall.unwrap().delta_xi_deg, Some(0.7));
        let mut k = case("[particles]\ndiameter_um = 100.0\n");
        let a = c
            .apply(&mut k, "deterministic", CardWall::OfTheParticles)
            .unwrap();
        assert_eq!(k.wall.unwrap().delta_zeta_deg, Some(3.0));
        assert_eq!(a.manifest["row"].as_str(), Some("wall"));
        assert!(a.warnings.is_empty());
    }

    #[test]
    fn the_point_particle_is_taken_from_a_card_with_rows_when_asked_for() {
        let (_d, c) = card(CARD);
        let c = c.unwrap();
        // 250 µm has no row, and the point particle needs none: [wall] and its table.
        let mut k =
            case("[particles]\ndiameter_um = 250.0\n[stochastic]\nmodel = \"measured-wall\"\n");
        let a = c.apply(&mut k, "stochastic", CardWall::Point).unwrap();
        let w = k.wall.clone().unwrap();
        assert_eq!((w.delta_xi_deg, w.delta_zeta_deg), (Some(1.5), Some(3.0)));
        assert_eq!(a.manifest["row"].as_str(), Some("wall"));
        assert_eq!(a.manifest["point"].as_str(), Some("--wall-card-point"));
        assert!(k
            .stochastic
            .unwrap()
            .wall_table
            .unwrap()
            .ends_with("measured_wall_point.txt"));
        // The default diameter, which has a row, is not taken either.
        let mut k = case("");
        c.apply(&mut k, "stochastic", CardWall::Point).unwrap();
        assert_eq!(k.wall.unwrap().delta_xi_deg, Some(1.5));
    }

    #[test]
    fn a_missing_row_a_row_without_deviations_and_a_bad_card_are_one_line() {
        let (_d, c) = card(CARD);
        let c = c.unwrap();
        let e = c
            .apply(
                &mut case("[particles]\ndiameter_um = 250.0\n"),
                "stochastic",
                CardWall::OfTheParticles,
            )
            .unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert!(e.to_string().contains("has no [[diameter]] row for the particles' 250 µm (`particles.diameter_um`, default 500): its rows are for 100, 500, 1000000 µm; set `particles.diameter_um` to one of them, run `rebound scan --diameter-um 250`, or take its [wall], the point particle's, with `--wall-card-point`"), "{e}");
        let e = c
            .apply(
                &mut case("[particles]\ndiameter_um = 1e6\n"),
                "stochastic",
                CardWall::OfTheParticles,
            )
            .unwrap_err();
        assert!(
            e.to_string()
                .contains("row for 1000000 µm has no deviations"),
            "{e}"
        );
        let e = c
            .apply(&mut case("[surface]\nlength_um = 100.0\nnodes = 64\nrms_height_um = 1.0\ndelta_xi_deg = 2.0\ndelta_zeta_deg = 2.0\n"), "stochastic", CardWall::OfTheParticles)
            .unwrap_err();
        assert!(e.to_string().contains("the case gives a [surface]"), "{e}");
        let err = |text: &str| card(text).1.unwrap_err().to_string();
        assert!(err("notes = []\n[scan]\nsq_um = 1.0\n").ends_with("card.toml has no [wall]: the scan it was written from has no lay (no cell with four valid corners), so no deviations"));
        assert!(err("[wall]\ndelta_xi_deg = 1.0\n")
            .ends_with("card.toml: `wall.delta_zeta_deg` is missing"));
        assert!(err("[wall]\ndelta_xi_deg = nan\ndelta_zeta_deg = 1.0\n")
            .contains("`wall.delta_xi_deg` = nan is not a finite number"));
        let e = err("[wall\n");
        assert!(
            e.contains("card.toml: not a wall card (TOML: ") && !e.contains('\n'),
            "{e}"
        );
        let e = WallCard::read(Path::new("/nonexistent/card.toml")).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("`--wall-card` /nonexistent/card.toml: "),
            "{e}"
        );
        assert!(!e.to_string().contains('\n'));
    }
}
