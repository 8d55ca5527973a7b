//! The outputs of `rebound scan` (issue 29): `scan_summary.csv`, `wall_card.toml`, the
//! notes on how far the wall is from what the models assume, and the `[scan]` table of
//! `run.toml`.

use super::measured_wall::MeasuredWallEntry;
use super::scan_diameters::card_tables;
use crate::output::{fmt_num, fmt_opt, toml_float, toml_str, CsvTable};
use roughwall::scan::Characterisation;
use roughwall::scan::SeenBy;
use roughwall::scan::{missing_fraction, spread};

/// The columns of `scan_summary.csv`.
pub const SUMMARY_HEADER: [&str; 27] = [
    "file",
    "format",
    "nx",
    "ny",
    "dx_um",
    "dy_um",
    "valid_points",
    "missing_fraction",
    "level_degree",
    "sq_um",
    "ssk",
    "sku",
    "sdq",
    "sdq_x",
    "sdq_y",
    "lay_deg",
    "delta_xi_deg",
    "delta_zeta_deg",
    "rho_xi_zeta",
    "skewness_xi",
    "skewness_zeta",
    "kurtosis_xi",
    "kurtosis_zeta",
    "delta_scan_x_deg",
    "delta_scan_y_deg",
    "corr_length_along_um",
    "corr_length_across_um",
];

/// Below this Sq (m), a femtometre, far below any instrument's resolution, the heights are
/// the round-off of the levelling (a plane): their shape (Ssk, Sku) is undefined.
const NO_SPREAD_M: f64 = 1e-15;

/// What was characterised: the file as read (empty for a generated wall) and its format.
pub struct Source<'a> {
    pub file: &'a str,
    pub format: &'a str,
}

/// `x` when `defined`, else an empty cell.
fn cell(x: f64, defined: bool) -> String {
    if defined {
        fmt_num(x)
    } else {
        String::new()
    }
}

/// `scan_summary.csv`: one row; an undefined value is an empty cell.
pub fn summary_table(src: &Source, c: &Characterisation) -> CsvTable {
    let f = &c.levelled;
    let p = &c.parameters;
    let mut row = vec![
        src.file.to_string(),
        src.format.to_string(),
        f.nx.to_string(),
        f.ny.to_string(),
        fmt_num(f.dx * 1e6),
        fmt_num(f.dy * 1e6),
        p.valid_points.to_string(),
        fmt_num(missing_fraction(c)),
        c.degree.to_string(),
        fmt_num(p.sq_m * 1e6),
        cell(p.ssk, p.sq_m > NO_SPREAD_M),
        cell(p.sku, p.sq_m > NO_SPREAD_M),
        fmt_opt(p.sdq),
        fmt_opt(p.sdq_x),
        fmt_opt(p.sdq_y),
    ];
    match &c.lay {
        Some(l) => {
            let [sx, sz] = spread(l);
            row.extend([
                cell(l.angle.to_degrees(), sx || sz),
                fmt_num(l.delta_xi.to_degrees()),
                fmt_num(l.delta_zeta.to_degrees()),
                cell(l.rho, sx && sz),
                cell(l.skewness[0], sx),
                cell(l.skewness[1], sz),
                cell(l.kurtosis[0], sx),
                cell(l.kurtosis[1], sz),
                fmt_num(l.delta_scan_axes[0].to_degrees()),
                fmt_num(l.delta_scan_axes[1].to_degrees()),
            ]);
        }
        None => row.extend(std::iter::repeat_n(String::new(), 10)),
    }
    // The 1/e lengths of the autocorrelation along and across the lay (empty when it does
    // not fall to 1/e within a quarter of the scan).
    let um = |x: Option<f64>| x.map(|x| fmt_num(x * 1e6)).unwrap_or_default();
    row.extend([
        um(c.correlation.length_along_m),
        um(c.correlation.length_across_m),
    ]);
    let mut t = CsvTable::new(&SUMMARY_HEADER);
    t.push(row);
    t
}

/// `wall_card.toml`: `[wall]` ready to paste into a case, the lay, the scan, the notes and
/// the `[[diameter]]` tables of the spheres of `seen` (none: no table), with comments saying
/// how a case and the C library take them; with `tables` (`--measured-wall`: the point's
/// first, then one per sphere) each names its measured-wall table.
pub fn wall_card(
    src: &Source,
    c: &Characterisation,
    notes: &[String],
    seen: &[SeenBy],
    tables: &[MeasuredWallEntry],
) -> String {
    let what = if src.file.is_empty() {
        "the generated wall, a self-check of the chain (docs/models.md, \"Measured walls\")"
            .to_string()
    } else {
        format!("the scan {}", toml_str(src.file))
    };
    let f = &c.levelled;
    let diameters = card_tables(seen, f, tables);
    let mut s = format!(
        "# Wall card of {what}.\n\
         # Written by `rebound scan`.\n\
         #\n\
         # For particles of diameter D, take the [[diameter]] row of D (below, before [wall]):\n\
         # `rebound stochastic --wall-card THIS_FILE` does, for [particles] diameter_um.\n\
         # [wall] is the point particle's: every triangle of the scan, so a property of its\n\
         # pixel as much as of the wall (its resolution check is in wall_card_diameters.csv).\n\
         # The deviations are those along the lay (Δξ) and across it (Δζ), so the models' x runs\n\
         # along the lay and β⁻ is measured from the lay ([lay] angle_deg gives it in the scan's\n\
         # axes). `deterministic --surface` on the scan itself is the reference to check against.\n\
         # For the C library: set rw_wall_params.delta_xi_deg and delta_zeta_deg to a row's values,\n\
         # and rw_hit.lay to the lay direction (direction_scan_xy, in the scan's x and y) turned\n\
         # into the CFD wall's axes.\n\
         # Only [wall] (or a row's two deviations under [wall]) goes into a case file: [lay],\n\
         # [scan] and notes describe the measurement.\n"
    );
    if !tables.is_empty() {
        s += "#\n\
              # The wall's own model: `measured_wall_table` (of [wall] and of each row) is the\n\
              # rebound law of the reference on this scan for that particle; with [stochastic]\n\
              # model = \"measured-wall\", `rebound stochastic --wall-card THIS_FILE` takes the\n\
              # table of its row. For the C library: RW_MODEL_MEASURED_WALL with the file's text\n\
              # as rw_wall_params.wall_table_text, and rw_hit.lay along direction_scan_xy (its\n\
              # sign matters: a measured wall need not be its own mirror image).\n";
    }
    // A scan smaller than a particle: said first.
    let (lx, ly) = ((f.nx - 1) as f64 * f.dx, (f.ny - 1) as f64 * f.dy);
    for d in seen.iter().map(|r| r.seen.diameter_m) {
        if d > lx.min(ly) {
            s += &format!(
                "#\n# THE SCAN ({:.0} × {:.0} µm) IS SMALLER THAN THE {} µm PARTICLE: no row for it can be trusted.\n",
                lx * 1e6,
                ly * 1e6,
                fmt_num(d * 1e6)
            );
        }
    }
    s += "\n";
    s += "notes = [";
    if notes.is_empty() {
        s += "]\n";
    } else {
        s += "\n";
        for n in notes {
            s += &format!("    {},\n", toml_str(n));
        }
        s += "]\n";
    }
    s += &diameters;
    if let Some(l) = &c.lay {
        // A wall whose anisotropy the scan does not show beyond its noise is isotropic: no
        // lay, and both deviations the rms of the two.
        let u = c.lay_uncertainty;
        let isotropic = u.is_some_and(|u| !u.significant());
        let (xi, zeta) = if isotropic {
            let rms = (0.5 * (l.delta_xi.powi(2) + l.delta_zeta.powi(2))).sqrt();
            (rms, rms)
        } else {
            (l.delta_xi, l.delta_zeta)
        };
        let (along, across) = if isotropic {
            (
                "isotropic: the rms of the two",
                "isotropic: the rms of the two",
            )
        } else {
            ("along the lay", "across the lay")
        };
        s += &format!(
            "\n# The point particle: every triangle at the scan's pixel.\n\
             [wall]\n\
             delta_xi_deg = {}    # {along}\n\
             delta_zeta_deg = {}    # {across}\n",
            toml_float(xi.to_degrees()),
            toml_float(zeta.to_degrees())
        );
        if let Some(t) = tables.first() {
            s += &super::measured_wall::table_lines(t);
        }
        let [sx, sz] = spread(l);
        if (sx || sz) && !isotropic {
            s += &format!(
                "\n[lay]\n\
                 angle_deg = {}    # from the scan's x towards its y: the models' β* of the lay\n\
                 direction_scan_xy = [{}, {}]    # unit vector along the lay, in the scan's x, y\n",
                toml_float(l.angle.to_degrees()),
                toml_float(l.angle.cos()),
                toml_float(l.angle.sin())
            );
            if let Some(u) = u {
                s += &format!(
                    "angle_se_deg = {}    # standard error, from {} sub-patches\n\
                     anisotropy_t = {}    # (Δζ − Δξ) over its standard error between sub-patches\n",
                    toml_float(u.angle_se.to_degrees()),
                    u.patches,
                    toml_float(if u.t().is_finite() { u.t() } else { f64::MAX }),
                );
            }
        }
    }
    let p = &c.parameters;
    s += "\n[scan]\n";
    if !src.file.is_empty() {
        s += &format!("file = {}\n", toml_str(src.file));
    }
    s += &format!(
        "format = {}\n\
         grid = [{}, {}]    # points along x, y\n\
         pixel_um = [{}, {}]\n\
         valid_fraction = {}\n\
         level_degree = {}    # the polynomial form removed (1: a plane)\n\
         sq_um = {}    # rms height of the levelled scan (ISO 25178-2 Sq)\n",
        toml_str(src.format),
        f.nx,
        f.ny,
        toml_float(f.dx * 1e6),
        toml_float(f.dy * 1e6),
        toml_float(1.0 - missing_fraction(c)),
        c.degree,
        toml_float(p.sq_m * 1e6),
    );
    if let Some(sdq) = p.sdq {
        s += &format!(
            "sdq = {}    # rms slope (ISO 25178-2 Sdq)\n",
            toml_float(sdq)
        );
    }
    s
}

/// The `[scan]` table of `run.toml`: what was read, the grid, the levelling, and what the
/// file states beside the heights.
pub fn manifest_table(
    src: &Source,
    c: &Characterisation,
    info: &[(String, String)],
    triangles: Option<u64>,
) -> toml::Value {
    let f = &c.levelled;
    let mut t = toml::Table::new();
    t.insert(
        "source".into(),
        if src.file.is_empty() {
            "generated"
        } else {
            "file"
        }
        .into(),
    );
    if !src.file.is_empty() {
        t.insert("file".into(), src.file.into());
    }
    t.insert("format".into(), src.format.into());
    t.insert("nx".into(), (f.nx as i64).into());
    t.insert("ny".into(), (f.ny as i64).into());
    t.insert("dx_m".into(), f.dx.into());
    t.insert("dy_m".into(), f.dy.into());
    t.insert(
        "valid_points".into(),
        (c.parameters.valid_points as i64).into(),
    );
    t.insert("level_degree".into(), (c.degree as i64).into());
    if let Some(n) = triangles {
        t.insert("triangles".into(), (n as i64).into());
    }
    if !info.is_empty() {
        let mut i = toml::Table::new();
        for (k, v) in info {
            i.entry(k.clone()).or_insert_with(|| v.clone().into());
        }
        t.insert("file_info".into(), toml::Value::Table(i));
    }
    toml::Value::Table(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use roughwall::scan::characterise;
    use roughwall::scan::notes;
    use roughwall::ScanField;

    /// A sinusoid along x with its grooves along y, some points missing.
    fn grooves(nx: usize, ny: usize) -> Characterisation {
        let mut h: Vec<f64> = (0..nx * ny)
            .map(|i| 1e-6 * ((i % nx) as f64 * 0.7).sin() + 1e-8 * ((i / nx) as f64 * 0.3).cos())
            .collect();
        h[3] = f64::NAN;
        characterise(ScanField::new(nx, ny, 1e-6, 2e-6, h).unwrap(), 1).unwrap()
    }

    #[test]
    fn the_card_parses_and_its_wall_pastes_into_a_case() {
        let c = grooves(40, 30);
        let src = Source {
            file: "dir/a \"b\".x3p",
            format: "x3p",
        };
        let notes = notes(&c, None);
        // Steep, far from Gaussian (a sinusoid), small.
        assert!(notes.iter().any(|n| n.contains("beyond 20°")), "{notes:?}");
        assert!(
            notes.iter().any(|n| n.contains("far from Gaussian")),
            "{notes:?}"
        );
        assert!(
            notes.iter().any(|n| n.contains("40 × 30 scan")),
            "{notes:?}"
        );
        assert!(!notes.iter().any(|n| n.contains("missing")), "{notes:?}");
        let card = wall_card(&src, &c, &notes, &[], &[]);
        let t: toml::Table = card.parse().unwrap_or_else(|e| panic!("{e}\n{card}"));
        assert_eq!(t["scan"]["file"].as_str(), Some("dir/a \"b\".x3p"));
        assert_eq!(t["scan"]["grid"].as_array().unwrap().len(), 2);
        assert_eq!(t["notes"].as_array().unwrap().len(), notes.len());
        let lay = c.lay.unwrap();
        let angle = t["lay"]["angle_deg"].as_float().unwrap();
        assert!((angle - lay.angle.to_degrees()).abs() < 1e-5);
        // The grooves run along y.
        assert!((angle.abs() - 90.0).abs() < 1.0, "{angle}");
        let wall = format!(
            "name = \"pasted\"\n[wall]\n{}",
            card.split("[wall]\n")
                .nth(1)
                .unwrap()
                .split("\n[")
                .next()
                .unwrap()
        );
        let case = crate::case::parse(&wall, "pasted.toml").unwrap();
        let w = case.wall.unwrap();
        assert!((w.delta_xi_deg.unwrap() - lay.delta_xi.to_degrees()).abs() < 1e-4);
        assert!((w.delta_zeta_deg.unwrap() - lay.delta_zeta.to_degrees()).abs() < 1e-4);
    }

    #[test]
    fn undefined_values_are_empty_cells_never_nan() {
        // A plane: no spread, so no lay direction, shape or correlation.
        let h: Vec<f64> = (0..64).map(|i| 1e-9 * (i % 8) as f64).collect();
        let c = characterise(ScanField::new(8, 8, 1e-6, 1e-6, h).unwrap(), 1).unwrap();
        let t = summary_table(
            &Source {
                file: "",
                format: "generated",
            },
            &c,
        );
        let text = String::from_utf8(t.to_bytes()).unwrap();
        assert!(!text.to_ascii_lowercase().contains("nan"), "{text}");
        let row: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
        assert_eq!(row.len(), SUMMARY_HEADER.len());
        let col = |n: &str| row[SUMMARY_HEADER.iter().position(|h| *h == n).unwrap()];
        assert_eq!(col("file"), "");
        assert_eq!((col("lay_deg"), col("rho_xi_zeta")), ("", ""));
        assert_eq!((col("ssk"), col("sku")), ("", ""));
        assert!(col("delta_xi_deg").parse::<f64>().unwrap() < 1e-9);
        let card = wall_card(
            &Source {
                file: "",
                format: "generated",
            },
            &c,
            &[],
            &[],
            &[],
        );
        let t: toml::Table = card.parse().unwrap();
        assert!(t.get("lay").is_none() && t["scan"].get("file").is_none());
    }
}
