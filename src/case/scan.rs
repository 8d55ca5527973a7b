//! `[scan]` of `rebound scan` (issue 29): which measured wall to read and how, or, without a
//! file, the case's `[wall]`/`[surface]` generated and read as a scan (the self-check of the
//! chain); then the scan itself, read with `topography` into the library's `ScanField`.

use super::wall::{DIAMETER_RANGE_UM, MAX_DIAMETERS};
use super::{Case, WallSource};
use roughwall::check::{check_int_range, check_length, check_value, not_a_regular_file, within};
use roughwall::deterministic::{SceneOptions, SurfacePlan};
use roughwall::scan::MAX_DEGREE;
use roughwall::ScanField;
use roughwall::Warning;
use roughwall::{Error, Result};
use std::path::{Path, PathBuf};
use topography::{ErrorKind, Format};

/// Pixel sizes and height units a case may give (µm): a picometre to a metre.
pub const UNIT_RANGE_UM: (f64, f64) = (1e-6, 1e6);

/// What `rebound scan` characterises, resolved from `[scan]` and `--scan`.
#[derive(Clone, Debug, PartialEq)]
pub struct ScanSetup {
    /// Degree of the polynomial form removed (1 … 3).
    pub level_degree: u32,
    pub source: ScanSource,
    /// Particle diameters (m) whose centre surfaces the card measures (`[scan] diameters_um`
    /// or `--diameter-um`), in the order given.
    pub diameters_m: Vec<f64>,
    /// Whether to build the measured-wall tables (`[scan] measured_wall`, `--measured-wall`).
    pub measured_wall: bool,
    /// Histories per incident direction of each table (`[scan] measured_wall_histories`).
    pub measured_wall_histories: u64,
}

/// Where the heights come from.
#[derive(Clone, Debug, PartialEq)]
pub enum ScanSource {
    /// A scan file.
    File(ScanFile),
    /// The case's wall, generated (its heights' rows are the scan's `y`).
    Generated(SurfacePlan),
}

/// A scan file and how to read it.
#[derive(Clone, Debug, PartialEq)]
pub struct ScanFile {
    /// The file read (a relative `scan.file` joined to the case file's directory).
    pub path: PathBuf,
    /// The path as outputs show it: [`tidy`] of `path`.
    pub shown: String,
    /// Who named it, for messages: `scan.file` or `--scan`.
    pub key: &'static str,
    /// `None`: told by the file (`format = "auto"`).
    pub format: Option<Format>,
    /// Pixel sizes `(dx, dy)` in metres (matrix and x-y-z text only).
    pub pixel_m: Option<(f64, f64)>,
    /// One height unit in metres (matrix and x-y-z text only).
    pub height_unit_m: Option<f64>,
}

/// A scan read from its file or generated: the heights and what the file states.
pub struct ReadScan {
    pub field: ScanField,
    /// The format read, or `generated`.
    pub format: String,
    /// What the file states beside the heights (instrument, date, units…), in file order.
    pub info: Vec<(String, String)>,
}

/// The formats `scan.format` names, after `"auto"`.
fn format_names() -> Vec<&'static str> {
    std::iter::once("auto")
        .chain(Format::ALL.iter().map(|f| f.name()))
        .collect()
}

/// The formats that state no units: the case gives them (`pixel_um`, `height_unit_um`).
fn needs_units(f: Option<Format>) -> bool {
    matches!(f, Some(Format::Matrix | Format::Xyz))
}

/// `path` without `.` components and with `dir/..` pairs dropped, as outputs show the file
/// read (`configs/scans/../../tests/data/scans/a.x3p` is `tests/data/scans/a.x3p`). Lexical
/// only: the file read is `path` itself.
pub fn tidy(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut out: Vec<Component> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if matches!(out.last(), Some(Component::Normal(_))) => {
                out.pop();
            }
            c => out.push(c),
        }
    }
    if out.is_empty() {
        return PathBuf::from(".");
    }
    out.iter().collect()
}

/// A TOML-like list of numbers for messages.
fn list(v: &[f64]) -> String {
    let items: Vec<String> = v.iter().map(|x| x.to_string()).collect();
    format!("[{}]", items.join(", "))
}

/// The particle diameters (m) of `--diameter-um` (`arg`, when given) or else of
/// `[scan] diameters_um`: at most [`MAX_DIAMETERS`], each a nanometre to a metre, none
/// twice. A sphere wider than the scan is not refused: its row says the scan is too small.
fn diameters(arg: &[f64], case: &[f64]) -> Result<Vec<f64>> {
    let (key, list) = match arg.is_empty() {
        true => ("scan.diameters_um", case),
        false => ("--diameter-um", arg),
    };
    let allowed = format!("at most {MAX_DIAMETERS} diameters");
    check_length(key, list.len(), MAX_DIAMETERS, "diameters", &allowed)?;
    let (lo, hi) = DIAMETER_RANGE_UM;
    let mut out: Vec<f64> = Vec::with_capacity(list.len());
    for &d in list {
        within(key, d, lo, hi, " µm", "a nanometre to a metre")?;
        if out.contains(&(d * 1e-6)) {
            return Err(Error::invalid(
                key,
                d,
                "each diameter once (it is given twice)",
            ));
        }
        out.push(d * 1e-6);
    }
    Ok(out)
}

impl Case {
    /// The `[scan]` section, `--scan FILE` (which overrides `scan.file`) and
    /// `--diameter-um` (`diameters_arg`, which overrides `scan.diameters_um` when given),
    /// checked: `case_dir` is the directory of the case file (`None` for a built-in case),
    /// against which a relative `scan.file` is read. Without a file, the case's `[wall]` or
    /// `[surface]` is the wall to generate: a `[surface]` grid as given, deviations on the
    /// automatic grid of `deterministic` (spacing `c_L,min/8`, side `100 c_L,max`).
    pub fn scan_setup(
        &self,
        case_dir: Option<&Path>,
        scan_arg: Option<&Path>,
        diameters_arg: &[f64],
        (measured_wall_arg, histories_arg): (bool, Option<i64>),
        warnings: &mut Vec<Warning>,
    ) -> Result<ScanSetup> {
        let s = self.scan.clone().unwrap_or_default();
        let measured_wall = measured_wall_arg || s.measured_wall.unwrap_or(false);
        let measured_wall_histories = check_int_range(
            if histories_arg.is_some() {
                "--measured-wall-histories"
            } else {
                "scan.measured_wall_histories"
            },
            histories_arg
                .or(s.measured_wall_histories)
                .unwrap_or(roughwall::measured_wall::HISTORIES_PER_CELL as i64),
            1024,
            1_000_000,
            "1024 to 1000000 histories per incident direction of the table's grid",
        )? as u64;
        let diameters_m = diameters(diameters_arg, &s.diameters_um)?;
        let degree = check_int_range(
            "scan.level_degree",
            s.level_degree.unwrap_or(1),
            1,
            MAX_DEGREE as i64,
            "1 (a plane), 2 or 3: the total degree of the polynomial form removed",
        )? as u32;
        let names = format_names();
        let allowed = format!(
            "\"auto\" (told by the file's first bytes, then its extension) or one of {}",
            names[1..]
                .iter()
                .map(|n| format!("\"{n}\""))
                .collect::<Vec<_>>()
                .join(", ")
        );
        let k = check_value(
            "scan.format",
            s.format.as_deref().unwrap_or("auto"),
            &names,
            &allowed,
        )?;
        let format = Format::from_name(names[k]);
        let (lo, hi) = UNIT_RANGE_UM;
        let pixel = match &s.pixel_um {
            None => None,
            Some(v) if v.len() != 2 => {
                return Err(Error::invalid(
                    "scan.pixel_um",
                    list(v),
                    "two pixel sizes [dx, dy] in µm",
                ))
            }
            Some(v) => {
                for &d in v {
                    within("scan.pixel_um", d, lo, hi, " µm", "a picometre to a metre")?;
                }
                Some((v[0] * 1e-6, v[1] * 1e-6))
            }
        };
        let unit = s
            .height_unit_um
            .map(|u| {
                within(
                    "scan.height_unit_um",
                    u,
                    lo,
                    hi,
                    " µm",
                    "a picometre to a metre",
                )
            })
            .transpose()?
            .map(|u| u * 1e-6);
        // (the path read, who named it, the value as given, whether it is relative to the case)
        let file = match (scan_arg, &s.file) {
            (Some(p), _) => Some((p.to_path_buf(), "--scan", p.display().to_string(), false)),
            (None, Some(f)) if f.trim().is_empty() => {
                return Err(Error::invalid(
                    "scan.file",
                    "\"\"",
                    "the path of a scan file (relative to the case file's directory)",
                ))
            }
            (None, Some(f)) => {
                let given = Path::new(f);
                let (path, relative) = match case_dir {
                    Some(dir) if given.is_relative() => (dir.join(given), true),
                    _ => (given.to_path_buf(), false),
                };
                Some((path, "scan.file", format!("\"{f}\""), relative))
            }
            (None, None) => None,
        };
        let Some((path, key, shown, relative)) = file else {
            // Generated: the reading keys have nothing to read.
            let stray = [
                (
                    "scan.format",
                    s.format
                        .as_ref()
                        .filter(|f| *f != "auto")
                        .map(|f| format!("\"{f}\"")),
                ),
                ("scan.pixel_um", s.pixel_um.as_deref().map(list)),
                (
                    "scan.height_unit_um",
                    s.height_unit_um.map(|u| u.to_string()),
                ),
            ];
            if let Some((key, Some(v))) = stray.into_iter().find(|(_, v)| v.is_some()) {
                return Err(Error::invalid(
                    key,
                    v,
                    "only with a scan file (`scan.file` or --scan); without one the case's [wall] or [surface] is generated",
                ));
            }
            if self.wall.is_none() && self.surface.is_none() {
                return Err(Error::Input(
                    "the case gives no scan (`[scan] file` or --scan FILE) and no wall to generate ([wall] or [surface])".into(),
                ));
            }
            let plan = match self.wall_source(warnings)? {
                WallSource::Surface(spec) => SurfacePlan::Case(spec),
                WallSource::Deviations(d) => {
                    SurfacePlan::auto(d.delta_xi, d.delta_zeta, &SceneOptions::default())
                        .map_err(|e| match e {
                            // `scan` does not read [deterministic], whose keys the message names.
                            Error::Input(m) => Error::Input(format!(
                                "[wall] on the automatic grid of `deterministic` (spacing c_L,min/8, side 100 c_L,max): {m}; `scan` reads no [deterministic]: give a [surface] with its own grid"
                            )),
                            e => e,
                        })?
                }
            };
            if plan.spec().corr_length_z_m.is_none() {
                let sec = if self.surface.is_some() {
                    "surface"
                } else {
                    "wall"
                };
                return Err(Error::Input(format!(
                    "[{sec}] has no roughness along z (Δζ = 0, or a flat wall): it is one profile, and `scan` characterises an areal height field; give delta_zeta_deg > 0"
                )));
            }
            return Ok(ScanSetup {
                level_degree: degree,
                source: ScanSource::Generated(plan),
                diameters_m,
                measured_wall,
                measured_wall_histories,
            });
        };
        for (sec, there) in [
            ("wall", self.wall.is_some()),
            ("surface", self.surface.is_some()),
        ] {
            if there {
                warnings.push(Warning(format!(
                    "section [{sec}] is not read by `scan` with a scan file ({key} {shown}): the wall is the scan's"
                )));
            }
        }
        // Pixel sizes and height units: given for the formats that state none, and only there.
        let unitless = "\"matrix\" or \"xyz\" (a plain matrix or x-y-z text states no units; every other format states its own)";
        if !needs_units(format) {
            if let Some(v) = &s.pixel_um {
                return Err(Error::invalid(
                    "scan.pixel_um",
                    list(v),
                    &format!("only with `scan.format` = {unitless}"),
                ));
            }
            if let Some(u) = s.height_unit_um {
                return Err(Error::invalid(
                    "scan.height_unit_um",
                    u,
                    &format!("only with `scan.format` = {unitless}"),
                ));
            }
        } else if pixel.is_none() || unit.is_none() {
            let missing = if pixel.is_none() {
                "scan.pixel_um"
            } else {
                "scan.height_unit_um"
            };
            return Err(Error::Input(format!(
                "`scan.format` = \"{}\" needs `scan.pixel_um` = [dx, dy] and `scan.height_unit_um` (µm): the file states no units; `{missing}` is missing",
                names[k]
            )));
        }
        if let Some(kind) = not_a_regular_file(&path) {
            return Err(Error::Input(format!(
                "`{key}` = {shown}: `{}` is {kind}, not a file",
                path.display()
            )));
        }
        if !path.is_file() {
            let hint = match relative {
                true => " (a relative `scan.file` is read from the case file's directory)",
                false => "",
            };
            return Err(Error::invalid(
                key,
                &shown,
                &format!(
                    "an existing scan file: `{}` is not found{hint}",
                    path.display()
                ),
            ));
        }
        Ok(ScanSetup {
            level_degree: degree,
            source: ScanSource::File(ScanFile {
                shown: tidy(&path).display().to_string(),
                path,
                key,
                format,
                pixel_m: pixel,
                height_unit_m: unit,
            }),
            diameters_m,
            measured_wall,
            measured_wall_histories,
        })
    }
}

impl ScanFile {
    /// Reads the file into a scan: one-line input errors naming the file (an I/O failure
    /// is an I/O error); a plain matrix or x-y-z text takes the case's pixel size and height
    /// unit.
    pub fn read(&self) -> Result<ReadScan> {
        let t = match (self.format, self.pixel_m, self.height_unit_m) {
            (Some(Format::Matrix), Some((dx, dy)), Some(u)) => {
                topography::read_matrix(&self.path, dx, dy, u)
            }
            (Some(Format::Xyz), Some((dx, dy)), Some(u)) => {
                // The positions fix the grid and its order; the case gives its spacing.
                topography::read_xyz(&self.path, 1.0, u).map(|mut t| {
                    t.dx_m = dx;
                    t.dy_m = dy;
                    t
                })
            }
            (Some(f), _, _) => topography::read_as(&self.path, f),
            (None, _, _) => topography::read(&self.path),
        }
        .map_err(|e| {
            let hint = match e.kind() {
                ErrorKind::NoUnits => {
                    " (for a plain matrix or x-y-z text set `scan.format` = \"matrix\" or \"xyz\" with `scan.pixel_um` and `scan.height_unit_um`)"
                }
                _ => "",
            };
            let m = format!("`{}`: {e}{hint}", self.key);
            match e.kind() {
                ErrorKind::Io => Error::Io(m),
                _ => Error::Input(m),
            }
        })?;
        let format = t.format.name().to_string();
        let field = ScanField::new(t.nx, t.ny, t.dx_m, t.dy_m, t.heights_m)
            .map_err(|e| Error::Input(format!("`{}` {}: {e}", self.key, self.path.display())))?;
        Ok(ReadScan {
            field,
            format,
            info: t.info,
        })
    }
}

/// The generated wall of `plan` (seed `seed`) as a scan: its rows are the scan's `y`.
pub fn generated_scan(plan: &SurfacePlan, seed: u64) -> Result<ReadScan> {
    let g = roughwall::surface::generate(plan.spec(), seed);
    let field = ScanField::new(g.nx, g.nz, g.dx, g.dz, g.heights)
        .map_err(|e| Error::Internal(format!("generated wall as a scan: {e}")))?;
    Ok(ReadScan {
        field,
        format: "generated".into(),
        info: Vec::new(),
    })
}

/// Bytes the characterisation of a generated `plan` needs: the generation's (the heights are
/// levelled in place).
pub fn generated_bytes(plan: &SurfacePlan) -> u64 {
    roughwall::surface::generation_bytes(plan.spec())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup(text: &str, scan: Option<&Path>) -> Result<ScanSetup> {
        let case = super::super::parse(&format!("name = \"t\"\n{text}"), "t.toml")?;
        case.scan_setup(
            Some(Path::new("/nonexistent-dir")),
            scan,
            &[],
            (false, None),
            &mut Vec::new(),
        )
    }

    fn err(text: &str) -> String {
        let e = setup(text, None).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{e}");
        e.to_string()
    }

    #[test]
    fn bad_values_name_the_key_the_value_and_what_is_allowed() {
        let e = err("[scan]\nlevel_degree = 4\n");
        assert!(
            e.starts_with("invalid `scan.level_degree` = 4: allowed 1 (a plane), 2 or 3"),
            "{e}"
        );
        let e = err("[scan]\nfile = \"a.x3p\"\nformat = \"x3q\"\n");
        assert!(
            e.starts_with("invalid `scan.format` = \"x3q\": allowed \"auto\""),
            "{e}"
        );
        assert!(e.contains("\"x3p\"") && e.contains("\"plu\""), "{e}");
        let e = err("[scan]\nfile = \"a.x3p\"\npixel_um = [1.0, 1.0]\n");
        assert!(e.starts_with("invalid `scan.pixel_um` = [1, 1]: allowed only with `scan.format` = \"matrix\" or \"xyz\""), "{e}");
        let e = err("[scan]\nfile = \"a.txt\"\nformat = \"matrix\"\npixel_um = [1.0]\n");
        assert!(
            e.contains("`scan.pixel_um` = [1]: allowed two pixel sizes"),
            "{e}"
        );
        let e = err("[scan]\nfile = \"a.txt\"\nformat = \"matrix\"\npixel_um = [1.0, 0.0]\n");
        assert!(
            e.contains("`scan.pixel_um` = 0: allowed 0.000001 to 1000000 µm"),
            "{e}"
        );
        let e = err("[scan]\nfile = \"a.txt\"\nformat = \"xyz\"\npixel_um = [1.0, 1.0]\n");
        assert!(e.contains("`scan.height_unit_um` is missing"), "{e}");
        let e = err("[scan]\nfile = \"a.x3p\"\n");
        assert!(e.starts_with("invalid `scan.file` = \"a.x3p\": allowed an existing scan file: `/nonexistent-dir/a.x3p` is not found"), "{e}");
        let e = err("[scan]\nfile = \"\"\n");
        assert!(e.contains("`scan.file` = \"\""), "{e}");
        let e = err("[scan]\nformat = \"x3p\"\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n");
        assert!(
            e.contains("`scan.format` = \"x3p\": allowed only with a scan file"),
            "{e}"
        );
        let e = err("[scan]\nlevel_degree = 2\n");
        assert!(e.contains("no wall to generate"), "{e}");
        let e = err("[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 0.0\n");
        assert!(e.contains("no roughness along z"), "{e}");
    }

    #[test]
    fn diameters_are_checked_and_the_command_line_overrides_the_case() {
        let wall = "[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n";
        let case = |list: &str| {
            super::super::parse(
                &format!("name = \"t\"\n[scan]\ndiameters_um = {list}\n{wall}"),
                "t.toml",
            )
            .unwrap()
        };
        let run = |list: &str, arg: &[f64]| {
            case(list).scan_setup(None, None, arg, (false, None), &mut Vec::new())
        };
        let um = |d: &[f64]| d.iter().map(|d| d * 1e-6).collect::<Vec<_>>();
        assert_eq!(
            run("[100.0, 50.0]", &[]).unwrap().diameters_m,
            um(&[100.0, 50.0])
        );
        assert_eq!(run("[100.0]", &[2.5]).unwrap().diameters_m, um(&[2.5]));
        assert!(run("[]", &[]).unwrap().diameters_m.is_empty());
        let err = |list: &str, arg: &[f64]| {
            let e = run(list, arg).unwrap_err();
            assert_eq!(e.exit_code(), 2, "{e}");
            e.to_string()
        };
        assert_eq!(
            err("[100.0, 0.0]", &[]),
            "invalid `scan.diameters_um` = 0: allowed 0.001 to 1000000 µm (a nanometre to a metre)"
        );
        assert!(err("[100.0]", &[f64::NAN])
            .starts_with("invalid `--diameter-um` = NaN: allowed 0.001 to"));
        assert!(err("[]", &[f64::INFINITY]).starts_with("invalid `--diameter-um` = inf: "));
        assert!(err("[]", &[-5.0]).starts_with("invalid `--diameter-um` = -5: "));
        assert_eq!(
            err("[100.0, 50.0, 100.0]", &[]),
            "invalid `scan.diameters_um` = 100: allowed each diameter once (it is given twice)"
        );
        let many = format!("[{}]", vec!["1.0"; MAX_DIAMETERS + 1].join(", "));
        assert_eq!(
            err(&many, &[]),
            format!("invalid `scan.diameters_um` = a list of 65 diameters: allowed at most {MAX_DIAMETERS} diameters")
        );
    }

    #[test]
    fn the_command_line_file_overrides_the_case_and_is_read_as_given() {
        let here = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/scans/x3p-2.x3p");
        let s = setup("[scan]\nfile = \"elsewhere.x3p\"\n", Some(&here)).unwrap();
        let ScanSource::File(f) = s.source else {
            panic!("not a file")
        };
        assert_eq!((f.path, f.key, f.format), (here, "--scan", None));
        let t = |p: &str| tidy(Path::new(p)).display().to_string();
        assert_eq!(t("configs/scans/../../tests/a.x3p"), "tests/a.x3p");
        assert_eq!(t("/a/./b/../c"), "/a/c");
        assert_eq!(t("../x/../y"), "../y");
        assert_eq!(t("a/.."), ".");
        // Without a file: the wall, generated on the automatic grid of `deterministic`.
        let s = setup("[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n", None).unwrap();
        let ScanSource::Generated(plan) = s.source else {
            panic!("not generated")
        };
        assert_eq!((s.level_degree, plan.source()), (1, "auto"));
        // 8 nodes per c_Lz, 100 c_Lx a side, with the correlation lengths whose triangles
        // have (2.5°, 7.5°): 2560 (Eq. 15's c_L would give 2400).
        assert_eq!(plan.spec().nodes, 2560);
    }
}
