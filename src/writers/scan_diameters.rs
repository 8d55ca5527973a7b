//! The per-diameter outputs of `rebound scan` (issue 29, parts 2 and 5): for the point
//! particle and each `[scan] diameters_um` (`--diameter-um`), the deviations of the sphere's
//! centre surface on the scan (`roughwall::scan::seen_by`), and where
//! the scan is too small or too coarse for it (the criteria of
//! `roughwall::scan::resolution`): `wall_card_diameters.csv`, the card's
//! `[[diameter]]` tables, the `[[diameter]]` of `run.toml` and the notes.

use super::measured_wall::{table_lines, MeasuredWallEntry};
use crate::output::{fmt_num, toml_float, toml_str, CsvTable};
use roughwall::scan::SeenBy;
use roughwall::scan::{criteria, reach_um};
use roughwall::ScanField;

/// The columns of `wall_card_diameters.csv`.
pub const DIAMETERS_HEADER: [&str; 14] = [
    "diameter_um",
    "delta_xi_deg",
    "delta_zeta_deg",
    "delta_xi_deg_2x_pixel",
    "delta_zeta_deg_2x_pixel",
    "change_xi_2x_pixel",
    "change_zeta_2x_pixel",
    "exact_fraction",
    "reach_x_um",
    "reach_y_um",
    "footprint_um",
    "correlation_areas",
    "delta_rel_se",
    "note",
];

/// `wall_card_diameters.csv`: one row per particle, the point first; an undefined value (no
/// exact triangle, no correlation area) is an empty cell.
pub fn diameters_table(rows: &[SeenBy], f: &ScanField) -> CsvTable {
    let mut t = CsvTable::new(&DIAMETERS_HEADER);
    for s in rows {
        let r = &s.resolution;
        let [rx, ry] = reach_um(s, f);
        let (xi, zeta) = match &s.seen.lay {
            Some(l) => (
                fmt_num(l.delta_xi.to_degrees()),
                fmt_num(l.delta_zeta.to_degrees()),
            ),
            None => (String::new(), String::new()),
        };
        let se = r.relative_error();
        let (xi2, zeta2) = match &s.at_double_pixel {
            Some(l) => (
                fmt_num(l.delta_xi.to_degrees()),
                fmt_num(l.delta_zeta.to_degrees()),
            ),
            None => (String::new(), String::new()),
        };
        let (cxi, czeta) = match s.resolution_change() {
            Some([a, b]) => (fmt_num(a), fmt_num(b)),
            None => (String::new(), String::new()),
        };
        t.push(vec![
            fmt_num(s.seen.diameter_m * 1e6),
            xi,
            zeta,
            xi2,
            zeta2,
            cxi,
            czeta,
            fmt_num(r.exact_fraction),
            fmt_num(rx),
            fmt_num(ry),
            fmt_num(r.footprint_m * 1e6),
            fmt_num(r.correlation_areas),
            if se.is_finite() {
                fmt_num(se)
            } else {
                String::new()
            },
            criteria(s, f).join("; "),
        ]);
    }
    t
}

/// The card's `[[diameter]]` tables (the spheres; the point is `[wall]`), with the comment
/// that says how to use them; empty without a sphere.
pub fn card_tables(rows: &[SeenBy], f: &ScanField, tables: &[MeasuredWallEntry]) -> String {
    let spheres: Vec<&SeenBy> = rows.iter().filter(|s| s.seen.diameter_m > 0.0).collect();
    if spheres.is_empty() {
        return String::new();
    }
    let mut s = "\n\
        # One [[diameter]] per particle diameter: Δξ (along the lay) and Δζ (across it) of the\n\
        # surface the sphere's centre rides on. Use the row of your particles' diameter:\n\
        # `rebound stochastic --wall-card THIS_FILE` takes the row of [particles] diameter_um;\n\
        # or paste a row's delta_xi_deg and delta_zeta_deg under a case's [wall]. For the C\n\
        # library: rw_wall_params.delta_xi_deg and delta_zeta_deg for particles of that\n\
        # diameter. `*_2x_pixel`: the same on the scan read at twice its pixel, and their\n\
        # relative change (the resolution check); `note` says where the scan is too small or\n\
        # the row resolution-limited (\"\": it serves it); without deviations no triangle of the\n\
        # centre surface is exact.\n"
        .to_string();
    for d in spheres {
        s += &format!(
            "\n[[diameter]]\ndiameter_um = {}\n",
            toml_float(d.seen.diameter_m * 1e6)
        );
        if let Some(l) = &d.seen.lay {
            s += &format!(
                "delta_xi_deg = {}\ndelta_zeta_deg = {}\n",
                toml_float(l.delta_xi.to_degrees()),
                toml_float(l.delta_zeta.to_degrees())
            );
        }
        if let (Some(l), Some([a, b])) = (&d.at_double_pixel, d.resolution_change()) {
            s += &format!(
                "delta_xi_deg_2x_pixel = {}\ndelta_zeta_deg_2x_pixel = {}\nchange_2x_pixel = [{}, {}]\n",
                toml_float(l.delta_xi.to_degrees()),
                toml_float(l.delta_zeta.to_degrees()),
                toml_float(a),
                toml_float(b)
            );
        }
        s += &format!(
            "exact_fraction = {}\nnote = {}\n",
            toml_float(d.resolution.exact_fraction),
            toml_str(&criteria(d, f).join("; "))
        );
        if let Some(t) = tables
            .iter()
            .find(|t| t.diameter_m == d.seen.diameter_m && t.diameter_m > 0.0)
        {
            s += &table_lines(t);
        }
    }
    s
}

/// The `[[diameter]]` array of `run.toml`: every row of the CSV, the point first.
pub fn manifest_rows(rows: &[SeenBy], f: &ScanField) -> toml::Value {
    let table = diameters_table(rows, f);
    let text = String::from_utf8(table.to_bytes()).unwrap_or_default();
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let out = reader
        .records()
        .filter_map(|r| r.ok())
        .map(|r| {
            let mut t = toml::Table::new();
            for (k, v) in DIAMETERS_HEADER.iter().zip(r.iter()) {
                let value = match (*k, v.parse::<f64>()) {
                    ("note", _) => toml::Value::String(v.into()),
                    (_, Ok(x)) => toml::Value::Float(x),
                    // Empty: undefined, left out.
                    (_, Err(_)) => continue,
                };
                t.insert((*k).into(), value);
            }
            toml::Value::Table(t)
        })
        .collect();
    toml::Value::Array(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use roughwall::scan::characterise;
    use roughwall::scan::labelled;
    use roughwall::scan::seen_by;

    /// A Gaussian wall generated as a `size`-node scan read every `every`-th node (h = 1 µm,
    /// c_Lx = 32.4 µm, c_Lz = 10.8 µm, 8 nodes per c_Lz before the reading).
    fn wall(nodes: usize, every: usize) -> roughwall::scan::Characterisation {
        let c = |deg: f64| 2f64.sqrt() * 1e-6 / deg.to_radians();
        let spec = roughwall::SurfaceSpec {
            length_m: nodes as f64 * c(7.5) / 8.0,
            nodes,
            rms_height_m: 1e-6,
            corr_length_x_m: Some(c(2.5)),
            corr_length_z_m: Some(c(7.5)),
        };
        let g = roughwall::surface::generate(&spec, 7);
        let (nx, ny) = (g.nx.div_ceil(every), g.nz.div_ceil(every));
        let h = (0..ny)
            .flat_map(|iy| (0..nx).map(move |ix| (ix, iy)))
            .map(|(ix, iy)| g.heights[iy * every * g.nx + ix * every])
            .collect();
        let f = ScanField::new(nx, ny, g.dx * every as f64, g.dz * every as f64, h).unwrap();
        characterise(f, 1).unwrap()
    }

    /// The card's rows paste into a case: a row's two deviation lines under `[wall]` give a
    /// case whose wall is that row's; the point is `[wall]`, not a row; a sphere wider than
    /// the scan has a row without deviations and a note, and its CSV cells are empty.
    #[test]
    fn the_diameter_rows_paste_into_a_case_and_say_where_the_scan_is_too_small() {
        let c = wall(256, 1);
        let f = &c.levelled;
        let rows = seen_by(&c, &[100e-6, 1.0]).unwrap();
        let card = card_tables(&rows, f, &[]);
        let t: toml::Table = card.parse().unwrap_or_else(|e| panic!("{e}\n{card}"));
        let table = t["diameter"].as_array().unwrap();
        assert_eq!(table.len(), 2);
        assert_eq!(table[0]["diameter_um"].as_float(), Some(100.0));
        let lay = rows[1].seen.lay.unwrap();
        let row = card.split("[[diameter]]\n").nth(1).unwrap();
        let lines: Vec<&str> = row
            .lines()
            .filter(|l| l.starts_with("delta_xi_deg =") || l.starts_with("delta_zeta_deg ="))
            .collect();
        assert_eq!(lines.len(), 2);
        let case = crate::case::parse(
            &format!("name = \"pasted\"\n[wall]\n{}\n", lines.join("\n")),
            "pasted.toml",
        )
        .unwrap();
        let w = case.wall.unwrap();
        assert!((w.delta_xi_deg.unwrap() - lay.delta_xi.to_degrees()).abs() < 1e-5);
        assert!((w.delta_zeta_deg.unwrap() - lay.delta_zeta.to_degrees()).abs() < 1e-5);
        // The 1 m sphere: nothing exact, a note, no deviations.
        assert!(table[1].get("delta_xi_deg").is_none());
        let note = table[1]["note"].as_str().unwrap();
        assert!(note.starts_with("too small: no triangle"), "{note}");
        let csv = String::from_utf8(diameters_table(&rows, f).to_bytes()).unwrap();
        assert!(!csv.to_ascii_lowercase().contains("nan"), "{csv}");
        let last: Vec<&str> = csv.lines().nth(3).unwrap().split(',').collect();
        let se = DIAMETERS_HEADER
            .iter()
            .position(|h| *h == "delta_rel_se")
            .unwrap();
        assert_eq!((last[1], last[2], last[se]), ("", "", ""), "{csv}");
        assert_eq!(csv.lines().next().unwrap(), DIAMETERS_HEADER.join(","));
        assert!(csv.lines().nth(1).unwrap().starts_with("0,"), "{csv}");
        // run.toml: the same rows, the undefined values left out.
        let m = manifest_rows(&rows, f);
        let m = m.as_array().unwrap();
        assert_eq!(m.len(), 3);
        assert_eq!(m[0]["diameter_um"].as_float(), Some(0.0));
        assert!(m[2].get("delta_zeta_deg").is_none() && m[2].get("note").is_some());
        // Without spheres there is no [[diameter]].
        assert_eq!(card_tables(&rows[..1], f, &[]), "");
    }

    /// Each note's trigger, worded with its numbers: too few correlation areas (a point on a
    /// 7 × 20 c_L scan), too little exact (a 500 µm sphere on it), resolution-limited (2
    /// pixels per c_Lz: Δζ changes by about −16 % at twice the pixel).
    #[test]
    fn each_note_names_its_trigger_and_its_numbers() {
        let small = wall(160, 1);
        let rows = seen_by(&small, &[]).unwrap();
        let n = labelled(&rows[0], &small.levelled);
        assert_eq!(n.len(), 1, "{n:?}");
        assert!(
            n[0].starts_with(
                "point particle ([wall]): the scan is too small: its valid part holds "
            ),
            "{n:?}"
        );
        assert!(
            n[0].contains("(fewer than 250): Δ is uncertain by about"),
            "{n:?}"
        );
        let rows = seen_by(&small, &[500e-6]).unwrap();
        let n = labelled(&rows[1], &small.levelled);
        assert!(
            n[0].starts_with("D = 500 µm: the scan is too small: "),
            "{n:?}"
        );
        assert!(
            n[0].contains("% of it is exact (the edges lose a band of √(2RΔh) = "),
            "{n:?}"
        );
        assert!(n[0].contains(" µm along y), less than 50 %"), "{n:?}");
        let coarse = wall(512, 4);
        let rows = seen_by(&coarse, &[]).unwrap();
        let n = criteria(&rows[0], &coarse.levelled);
        assert_eq!(n.len(), 1, "{n:?}");
        assert!(
            n[0].starts_with("resolution-limited: Δξ and Δζ change by ")
                && n[0].contains(" when the pixel is doubled (more than 5 %): a point particle's deviations are those of the pixel"),
            "{n:?}"
        );
        let change = rows[0].resolution_change().unwrap()[1];
        assert!((-0.2..-0.12).contains(&change), "{change}");
        // A wall served: no note.
        let good = wall(512, 1);
        let rows = seen_by(&good, &[50e-6]).unwrap();
        assert!(rows.iter().all(|r| criteria(r, &good.levelled).is_empty()));
    }
}
