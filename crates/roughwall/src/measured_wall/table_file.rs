//! The measured-wall table as text: what `rebound scan --measured-wall` writes beside the
//! wall card, a case names (`[stochastic] wall_table`) and the C library and Python take.
//!
//! Format: the magic line [`MAGIC`], then `key = value` lines (`source`, `seed`,
//! `first_row`, the deviations and the grid: the table's rows, which are the base rows and at
//! most [`MAX_REFINED_ROWS`] more, and the columns, knots and bins, which must be this
//! version's), then the header
//! [`CELL_HEADER`] and one line per cell: its row and column, `α⁻` and `β⁻`, its counts,
//! then the [`XI_KNOTS`] knots of `ξ'` and the [`RANK_BINS`] × [`ZETA_KNOTS`] knots of `ζ'`
//! (as whole multiples of [`KNOT_UNIT_RAD`], 0.1 µrad), then, for `ξ'` and each rank bin of
//! `ζ'` in turn, the number of knots added where the law has atoms and gaps and each as its
//! `t` (a whole number of [`ADDED_T_UNIT`]) and its value, then the number of the cell's joint
//! atoms and each as its `ξ'` and `ζ'` (whole multiples of [`KNOT_UNIT_RAD`]) and its count of
//! histories ([`super::atoms`]). Knots and atoms are kept on that resolution,
//! so a table read back is the table written, bit for bit. Everything is checked on reading: a malformed, edited
//! or truncated table is a one-line error naming the line.

use super::atoms::{Atoms, MAX_ATOMS};
use super::grid::*;
use super::quantiles::{first_served_row, CellLaw, QuantileFunction, ADDED_T_UNIT};
use super::refine::MAX_REFINED_ROWS;
use super::table::MeasuredWallTable;
use crate::error::{Error, Result};
use crate::wall::Deviations;
use std::sync::Mutex;

/// First line of a table file (names the format and its version: v5 has the 43 base rows and
/// the rows its build added, the 32 rank bins, the mixture between cells, the knots its
/// quantile functions added where the law has atoms, and each cell's joint atoms). A v4 table
/// (no joint atoms), a v3 table (no added knots either) and a v2 table (the base rows alone as
/// well) are read as they are; a v1 table, of 29 rows, 16 bins and blended cells, is refused
/// with the advice to build it again.
pub const MAGIC: &str = "# roughwall measured-wall table v5";

/// The first line of a v4 table: v5 without joint atoms.
const MAGIC_V4: &str = "# roughwall measured-wall table v4";

/// The first line of a v3 table: v4 without added knots.
const MAGIC_V3: &str = "# roughwall measured-wall table v3";

/// The first line of a v2 table: v3 without added rows.
const MAGIC_V2: &str = "# roughwall measured-wall table v2";

const MAGIC_STEM: &str = "# roughwall measured-wall table v";

/// The header of the cell lines.
pub const CELL_HEADER: &str =
    "row,column,alpha_deg,beta_deg,histories,left_patch,lost_other,xi_knots_0.1urad...,zeta_knots_0.1urad...,(added,t_1e-9,knot_0.1urad...)x33,atoms,(xi_0.1urad,zeta_0.1urad,histories)...";

/// The cell header of v4 tables.
const CELL_HEADER_V4: &str =
    "row,column,alpha_deg,beta_deg,histories,left_patch,lost_other,xi_knots_0.1urad...,zeta_knots_0.1urad...,(added,t_1e-9,knot_0.1urad...)x33";

/// The cell header of v2 and v3 tables.
const CELL_HEADER_V3: &str =
    "row,column,alpha_deg,beta_deg,histories,left_patch,lost_other,xi_knots_0.1urad...,zeta_knots_0.1urad...";

/// Distinct tables a process may hold (see [`MeasuredWallTable::intern`]): a host's walls
/// use one or a few.
pub const MAX_DISTINCT_TABLES: usize = 16;

/// Values per cell line before the knots.
const LEADING: usize = 7;

/// Knots per cell line.
const KNOTS: usize = XI_KNOTS + RANK_BINS * ZETA_KNOTS;

fn list(v: &[f64]) -> String {
    v.iter()
        .map(|x| x.to_string())
        .collect::<Vec<_>>()
        .join(",")
}

impl MeasuredWallTable {
    /// The table as text ([`MeasuredWallTable::parse`] reads it back, bit for bit).
    pub fn to_text(&self) -> String {
        let mut s = String::with_capacity(self.cells.len() * KNOTS * 12);
        s.push_str(MAGIC);
        s.push('\n');
        // The source is one line: a newline in a file name would break the format.
        let source = self.source.replace(['\n', '\r'], " ");
        s.push_str(&format!("source = {source}\n"));
        s.push_str(&format!("seed = {}\n", self.seed));
        s.push_str(&format!("first_row = {}\n", self.first_row));
        s.push_str(&format!("delta_xi_rad = {}\n", self.deviations.delta_xi));
        s.push_str(&format!(
            "delta_zeta_rad = {}\n",
            self.deviations.delta_zeta
        ));
        s.push_str(&format!(
            "alpha_rows_deg = {}\n",
            list(&self.alpha_rows_deg)
        ));
        s.push_str(&format!("beta_columns = {BETA_COLUMNS}\n"));
        s.push_str(&format!("xi_knots = {XI_KNOTS}\n"));
        s.push_str(&format!("rank_bins = {RANK_BINS}\n"));
        s.push_str(&format!("zeta_knots = {ZETA_KNOTS}\n"));
        s.push_str(CELL_HEADER);
        s.push('\n');
        for (k, c) in self.cells.iter().enumerate() {
            let (row, column) = (k / BETA_COLUMNS, k % BETA_COLUMNS);
            s.push_str(&format!(
                "{row},{column},{},{},{},{},{}",
                self.alpha_rows_deg[row],
                beta_column_deg(column),
                c.histories,
                c.left_patch,
                c.lost_other
            ));
            let unit = |x: f64| ((x / KNOT_UNIT_RAD).round() as i64).to_string();
            for q in std::iter::once(&c.xi).chain(&c.zeta) {
                for &x in &q.knots {
                    s.push(',');
                    s.push_str(&unit(x));
                }
            }
            for q in std::iter::once(&c.xi).chain(&c.zeta) {
                s.push_str(&format!(",{}", q.added().len()));
                for &(t, x) in q.added() {
                    s.push_str(&format!(
                        ",{},{}",
                        (t / ADDED_T_UNIT).round() as i64,
                        unit(x)
                    ));
                }
            }
            s.push_str(&format!(",{}", c.atoms.len()));
            for (xi, zeta, count) in c.atoms.units() {
                s.push_str(&format!(",{xi},{zeta},{count}"));
            }
            s.push('\n');
        }
        s
    }

    /// Reads a table written by [`MeasuredWallTable::to_text`]; `what` names it in errors
    /// (e.g. "`stochastic.wall_table` `path`").
    pub fn parse(text: &str, what: &str) -> Result<MeasuredWallTable> {
        let bad = |line: usize, msg: &str| Error::Input(format!("{what}, line {line}: {msg}"));
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim_end()));
        // (v2: base rows only; v3: no added knots; v4: no joint atoms)
        let (v2, v3, v4) = match lines.next() {
            Some((_, l)) if l == MAGIC => (false, false, false),
            Some((_, l)) if l == MAGIC_V4 => (false, false, true),
            Some((_, l)) if l == MAGIC_V3 => (false, true, true),
            Some((_, l)) if l == MAGIC_V2 => (true, true, true),
            Some((_, l)) if l.starts_with(MAGIC_STEM) => {
                return Err(Error::Input(format!(
                    "{what}: a measured-wall table of another format (`{l}`); this version reads `{MAGIC}`: build it again with `rebound scan --measured-wall`"
                )))
            }
            _ => {
                return Err(Error::Input(format!(
                    "{what}: not a measured-wall table (the first line must be `{MAGIC}`; `rebound scan --measured-wall` writes one)"
                )))
            }
        };
        let mut value = |key: &str| -> Result<(usize, String)> {
            match lines.next() {
                Some((n, l)) => match l.strip_prefix(key).and_then(|r| r.strip_prefix(" = ")) {
                    Some(v) => Ok((n, v.to_string())),
                    None => Err(bad(n, &format!("expected `{key} = …`"))),
                },
                None => Err(Error::Input(format!(
                    "{what}: truncated (expected `{key} = …`)"
                ))),
            }
        };
        let (_, source) = value("source")?;
        let number = |(n, v): (usize, String), key: &str| -> Result<f64> {
            v.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| bad(n, &format!("`{key}` = `{v}` is not a finite number")))
        };
        let (n, v) = value("seed")?;
        let seed: u64 = v
            .parse()
            .map_err(|_| bad(n, &format!("`seed` = `{v}` is not an integer")))?;
        let (first_row_line, first_row_text) = value("first_row")?;
        let xi = number(value("delta_xi_rad")?, "delta_xi_rad")?;
        let zeta = number(value("delta_zeta_rad")?, "delta_zeta_rad")?;
        let (n, v) = value("alpha_rows_deg")?;
        let alpha_rows_deg = parse_rows(&v, v2).map_err(|m| bad(n, &m))?;
        let first_row: usize = first_row_text
            .parse()
            .ok()
            .filter(|&r: &usize| r < alpha_rows_deg.len())
            .ok_or_else(|| {
                bad(
                    first_row_line,
                    &format!(
                        "`first_row` = `{first_row_text}`: allowed 0 to {}",
                        alpha_rows_deg.len() - 1
                    ),
                )
            })?;
        for (key, want) in [
            ("beta_columns", BETA_COLUMNS.to_string()),
            ("xi_knots", XI_KNOTS.to_string()),
            ("rank_bins", RANK_BINS.to_string()),
            ("zeta_knots", ZETA_KNOTS.to_string()),
        ] {
            let (n, v) = value(key)?;
            if v != want {
                return Err(bad(
                    n,
                    &format!("`{key}` = `{v}`: this version's grid is `{want}`: build the table again with `rebound scan --measured-wall`"),
                ));
            }
        }
        let header = match (v3, v4) {
            (true, _) => CELL_HEADER_V3,
            (false, true) => CELL_HEADER_V4,
            (false, false) => CELL_HEADER,
        };
        match lines.next() {
            Some((_, l)) if l == header => {}
            Some((n, _)) => return Err(bad(n, &format!("expected the header `{header}`"))),
            None => {
                return Err(Error::Input(format!(
                    "{what}: truncated (expected the cell header)"
                )))
            }
        }
        let rows = alpha_rows_deg.len();
        let count = rows * BETA_COLUMNS;
        let mut cells = Vec::with_capacity(count);
        for k in 0..count {
            let (n, l) = lines.next().ok_or_else(|| {
                Error::Input(format!(
                    "{what}: truncated after {k} of {count} cells (the grid is {rows} rows × {BETA_COLUMNS} columns)"
                ))
            })?;
            cells.push(parse_cell(l, k, &alpha_rows_deg, (v3, v4)).map_err(|m| bad(n, &m))?);
        }
        if let Some((n, _)) = lines.find(|(_, l)| !l.is_empty()) {
            return Err(bad(n, &format!("more than the {count} cells of the grid")));
        }
        let t = MeasuredWallTable {
            source,
            alpha_rows_deg,
            first_row,
            deviations: Deviations {
                delta_xi: xi,
                delta_zeta: zeta,
            },
            seed,
            cells,
        };
        // The served rows follow from the counts: an edited `first_row` is refused.
        if first_row != first_served_row(&t.cells) {
            return Err(Error::Input(format!(
                "{what}: `first_row` = {first_row} does not match the cells' counts of histories that left the scan"
            )));
        }
        Ok(t)
    }

    /// This table kept for the process's life, shared by every wall that reads it (the
    /// models are small `Copy` values holding a reference): an equal table already held is
    /// reused; more than [`MAX_DISTINCT_TABLES`] distinct ones is a one-line error.
    pub fn intern(self) -> Result<&'static MeasuredWallTable> {
        static TABLES: Mutex<Vec<&'static MeasuredWallTable>> = Mutex::new(Vec::new());
        let mut v = TABLES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(t) = v.iter().find(|t| ***t == self) {
            return Ok(t);
        }
        if v.len() >= MAX_DISTINCT_TABLES {
            return Err(Error::Input(format!(
                "`stochastic.wall_table`: more than {MAX_DISTINCT_TABLES} distinct measured-wall tables in one process (each stays in memory for the process's life); build the walls from fewer tables"
            )));
        }
        let t: &'static MeasuredWallTable = Box::leak(Box::new(self));
        v.push(t);
        Ok(t)
    }
}

/// The table's rows from the text of `alpha_rows_deg`: the base rows (alone in a v2 table)
/// and at most [`MAX_REFINED_ROWS`] more between them, increasing.
fn parse_rows(v: &str, v2: bool) -> std::result::Result<Vec<f64>, String> {
    let base = list(&ALPHA_ROWS_DEG);
    let again = "build the table again with `rebound scan --measured-wall`";
    if v2 {
        return match v == base {
            true => Ok(ALPHA_ROWS_DEG.to_vec()),
            false => Err(format!(
                "`alpha_rows_deg` = `{v}`: a v2 table has the base rows `{base}`: {again}"
            )),
        };
    }
    let rows: Vec<f64> = v
        .split(',')
        .map(|x| x.parse::<f64>().ok().filter(|a| a.is_finite()))
        .collect::<Option<_>>()
        .ok_or_else(|| format!("`alpha_rows_deg` = `{v}` is not a list of numbers"))?;
    let allowed = format!(
        "the base rows `{base}` and at most {MAX_REFINED_ROWS} more between them, increasing"
    );
    let increasing = rows.windows(2).all(|w| w[0] < w[1]);
    let has_base = ALPHA_ROWS_DEG.iter().all(|a| rows.contains(a));
    let inside = rows
        .iter()
        .all(|&a| (ALPHA_ROWS_DEG[0]..=90.0).contains(&a));
    if !increasing || !has_base || !inside || rows.len() > ALPHA_ROWS_DEG.len() + MAX_REFINED_ROWS {
        return Err(format!(
            "`alpha_rows_deg` = `{v}`: allowed {allowed}: {again}"
        ));
    }
    Ok(rows)
}

/// One cell line, checked against its place `k` in the grid of `rows` (`v3`: a line of a v2
/// or v3 table, without added knots; `v4`: without joint atoms, as every older one).
fn parse_cell(
    line: &str,
    k: usize,
    rows: &[f64],
    (v3, v4): (bool, bool),
) -> std::result::Result<CellLaw, String> {
    let f: Vec<&str> = line.split(',').collect();
    let fixed = LEADING + KNOTS;
    if (v3 && f.len() != fixed) || (!v3 && f.len() < fixed + 1 + RANK_BINS) {
        let expected = match v3 {
            true => fixed.to_string(),
            false => format!("at least {}", fixed + 1 + RANK_BINS),
        };
        return Err(format!("{} fields, expected {expected}", f.len()));
    }
    let (row, column) = (k / BETA_COLUMNS, k % BETA_COLUMNS);
    let int = |i: usize, name: &str| -> std::result::Result<u64, String> {
        f[i].parse::<u64>()
            .map_err(|_| format!("`{name}` = `{}` is not a count", f[i]))
    };
    if int(0, "row")? != row as u64 || int(1, "column")? != column as u64 {
        return Err(format!(
            "cell ({}, {}) where the grid has ({row}, {column})",
            f[0], f[1]
        ));
    }
    let (a, b) = (f[2].parse::<f64>(), f[3].parse::<f64>());
    if a != Ok(rows[row]) || b != Ok(beta_column_deg(column)) {
        return Err(format!(
            "α⁻ = {}, β⁻ = {} where the grid has {}, {}",
            f[2],
            f[3],
            rows[row],
            beta_column_deg(column)
        ));
    }
    let (histories, left, lost) = (
        int(4, "histories")?,
        int(5, "left_patch")?,
        int(6, "lost_other")?,
    );
    if left.saturating_add(lost) > histories {
        return Err(format!("{left} + {lost} lost histories out of {histories}"));
    }
    let knot_at = |s: &str| -> std::result::Result<f64, String> {
        match s.parse::<i64>() {
            Ok(k) if (k as f64 * KNOT_UNIT_RAD).abs() <= std::f64::consts::FRAC_PI_2 => {
                Ok(k as f64 * KNOT_UNIT_RAD)
            }
            _ => Err(format!(
                "knot `{s}` is not a whole number of 0.1 µrad within ±π/2"
            )),
        }
    };
    let knots = f[LEADING..fixed]
        .iter()
        .map(|s| knot_at(s))
        .collect::<std::result::Result<Vec<f64>, String>>()?;
    // The added knots of each function in turn (none in a v3 line).
    let mut rest = f[fixed..].iter();
    // A function may hold no more added knots than a build gives it (`budget`).
    let mut added = |budget: usize| -> std::result::Result<Vec<(f64, f64)>, String> {
        if v3 {
            return Ok(Vec::new());
        }
        let count = rest.next().ok_or("truncated added knots")?;
        let count: usize = count
            .parse()
            .ok()
            .filter(|&c| c <= budget)
            .ok_or_else(|| format!("`{count}` added knots: allowed 0 to {budget}"))?;
        (0..count)
            .map(|_| {
                let (t, x) = (rest.next(), rest.next());
                let (Some(t), Some(x)) = (t, x) else {
                    return Err("truncated added knots".to_string());
                };
                let t = t.parse::<i64>().map_err(|_| {
                    format!("added knot's `t` = `{t}` is not a whole number of 1e-9")
                })?;
                Ok((t as f64 * ADDED_T_UNIT, knot_at(x)?))
            })
            .collect()
    };
    let mut function =
        |v: &[f64], budget: usize| -> std::result::Result<QuantileFunction, String> {
            QuantileFunction::with_added(v.to_vec(), added(budget)?)
        };
    let xi = function(&knots[..XI_KNOTS], XI_ADDED_BUDGET)?;
    let zeta = knots[XI_KNOTS..]
        .chunks(ZETA_KNOTS)
        .map(|v| function(v, ZETA_ADDED_BUDGET))
        .collect::<std::result::Result<Vec<_>, _>>()?;
    let atoms = match v4 {
        true => Atoms::default(),
        false => {
            let count = rest.next().ok_or("truncated: no count of joint atoms")?;
            let count: usize = count
                .parse()
                .ok()
                .filter(|&c| c <= MAX_ATOMS)
                .ok_or_else(|| format!("`{count}` joint atoms: allowed 0 to {MAX_ATOMS}"))?;
            let list = (0..count)
                .map(|_| {
                    let (Some(a), Some(b), Some(c)) = (rest.next(), rest.next(), rest.next())
                    else {
                        return Err("truncated joint atoms".to_string());
                    };
                    let unit = |s: &str| {
                        knot_at(s)?;
                        Ok::<i64, String>(s.parse::<i64>().unwrap_or_default())
                    };
                    let c = c
                        .parse::<u64>()
                        .map_err(|_| format!("joint atom's count `{c}` is not a count"))?;
                    Ok((unit(a)?, unit(b)?, c))
                })
                .collect::<std::result::Result<Vec<_>, String>>()?;
            let escaped = histories - left - lost;
            Atoms::from_units(list, escaped).ok_or_else(|| {
                format!("joint atoms out of order, of no history, or holding more than the cell's {escaped} escaped histories")
            })?
        }
    };
    if rest.next().is_some() {
        return Err("more fields than the cell's added knots and joint atoms".into());
    }
    Ok(CellLaw {
        histories,
        left_patch: left,
        lost_other: lost,
        xi,
        zeta,
        atoms,
    })
}
