//! The calibrated table as a file (the text `rebound calibrate` writes and a case or a C
//! host gives back): its writer, its reader with one-line errors for a malformed, edited
//! or mismatched table, and the built-in table shipped with the library.
//!
//! Format: the magic line [`MAGIC`], `# source: …`, then five CSV blocks with their
//! headers: one row per escape cell (`stage,x_in,x_out,collisions,escaped,p_escape`), per
//! element cell (`element_stage,x_in,s,deterministic,model,weight`), per `x_in` row (its
//! sums and positions), per first stage (its `Δγ` sum and position) and per later stage
//! (its transverse sums, slope and fresh part). The counts are what the table is; every
//! value after them is recomputed on reading and must match what is written.

use super::constants::*;
use super::counts::EscapeCounts;
use super::grid::*;
use super::table::EscapeTable;
use super::transverse_memory::plausible;
use crate::error::{Error, Result};
use std::sync::{Mutex, OnceLock};

/// First line of a table file (names the format and its version).
pub const MAGIC: &str = "# roughwall escape table v9";

/// What every version's first line starts with.
pub(super) const MAGIC_STEM: &str = "# roughwall escape table v";

pub(super) const HEADER: &str = "stage,x_in,x_out,collisions,escaped,p_escape";

pub(super) const ELEMENT_HEADER: &str = "element_stage,x_in,s,deterministic,model,weight";

pub(super) const ROW_HEADER: &str =
    "row_stage,x_in,escape_x_in_sum,escape_position,element_x_in_sum,element_position";

pub(super) const FIRST_HEADER: &str = "first_stage,collisions,delta_gamma_sum,delta_gamma_position";

pub(super) const TRANSVERSE_HEADER: &str =
    "transverse_stage,pairs,z_prev_sq_sum,cross_sum,slope,fresh";

impl EscapeTable {
    /// The table as a file: the magic line, `# source:`, then one row per cell.
    pub fn to_csv(&self) -> String {
        let mut s = format!("{MAGIC}\n# source: {}\n{HEADER}\n", self.source);
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_out in 0..X_OUT_BINS {
                    let c = cell(stage, i_in, i_out);
                    s.push_str(&format!(
                        "{},{:.4},{:.3},{},{},{:.6}\n",
                        stage.name(),
                        centre_in(i_in),
                        (i_out as f64 + 0.5) * DX_OUT,
                        self.counts.collisions[c],
                        self.counts.escaped[c],
                        self.p[c]
                    ));
                }
            }
        }
        s.push_str(ELEMENT_HEADER);
        s.push('\n');
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_g in 0..G_BINS {
                    let c = (stage.0 * X_IN_BINS + i_in) * G_BINS + i_g;
                    s.push_str(&format!(
                        "{},{:.4},{:.3},{},{},{:.6}\n",
                        stage.name(),
                        centre_in(i_in),
                        G_MIN + (i_g as f64 + 0.5) * DG,
                        self.counts.element_deterministic[c],
                        self.counts.element_model[c],
                        self.weight[c]
                    ));
                }
            }
        }
        s.push_str(ROW_HEADER);
        s.push('\n');
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                let r = stage.0 * X_IN_BINS + i_in;
                s.push_str(&format!(
                    "{},{:.4},{},{:.6},{},{:.6}\n",
                    stage.name(),
                    centre_in(i_in),
                    self.counts.escape_x_sum[r],
                    self.escape_pos[r],
                    self.counts.element_x_sum[r],
                    self.element_pos[r]
                ));
            }
        }
        s.push_str(FIRST_HEADER);
        s.push('\n');
        for k in 0..FIRST_STAGES {
            s.push_str(&format!(
                "{},{},{},{:.6}\n",
                Stage(k).name(),
                self.counts.first_count[k],
                self.counts.first_dg_sum[k],
                self.first_pos[k]
            ));
        }
        s.push_str(TRANSVERSE_HEADER);
        s.push('\n');
        let t = &self.counts.transverse;
        for k in 0..LATER_STAGES {
            s.push_str(&format!(
                "{},{},{},{},{:.6},{:.6}\n",
                Stage(FIRST_STAGES + k).name(),
                t.pairs[k],
                t.prev_sq_sum[k],
                t.cross_sum[k],
                self.memory.slope(k),
                self.memory.fresh(k)
            ));
        }
        s
    }

    /// Reads a table written by [`EscapeTable::to_csv`]; `what` names it in errors. The
    /// probabilities are recomputed from the counts, and every row is checked against the
    /// grid: a malformed or mismatched table is a one-line error.
    pub fn parse(text: &str, what: &str) -> Result<EscapeTable> {
        let bad = |line: usize, msg: &str| Error::Input(format!("{what}, line {line}: {msg}"));
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim_end()));
        match lines.next() {
            Some((_, l)) if l == MAGIC => {}
            // Another version of the format: say so, rather than "not a table".
            Some((_, l)) if l.starts_with(MAGIC_STEM) => {
                return Err(Error::Input(format!(
                    "{what}: an escape table of another format (`{l}`); this version reads `{MAGIC}`: run `rebound calibrate` again"
                )))
            }
            _ => {
                return Err(Error::Input(format!(
                    "{what}: not an escape table (the first line must be `{MAGIC}`; `rebound calibrate` writes one)"
                )))
            }
        }
        let source = match lines.next() {
            Some((_, l)) if l.starts_with("# source: ") => l["# source: ".len()..].to_string(),
            Some((n, _)) => return Err(bad(n, "expected `# source: …`")),
            None => return Err(bad(2, "expected `# source: …`")),
        };
        let header = |got: Option<(usize, &str)>, want: &str, after: &str| match got {
            Some((_, l)) if l == want => Ok(()),
            Some((n, _)) => Err(bad(n, &format!("expected the header `{want}`"))),
            None => Err(Error::Input(format!(
                "{what}: truncated {after} (expected the header `{want}`)"
            ))),
        };
        header(lines.next(), HEADER, "after the source line")?;
        let mut counts = EscapeCounts::default();
        let mut written_p = vec![0.0; CELLS];
        let mut rows = 0usize;
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_out in 0..X_OUT_BINS {
                    let cell_x = (i_out as f64 + 0.5) * DX_OUT;
                    let (n, l) = lines.next().ok_or_else(|| {
                        Error::Input(format!(
                            "{what}: truncated after {rows} of {CELLS} rows (the grid is {SLICES} stages × {X_IN_BINS} × {X_OUT_BINS})"
                        ))
                    })?;
                    let (c, e, p) =
                        parse_row(l, stage, i_in, ("x_out", cell_x)).map_err(|m| bad(n, &m))?;
                    if e > c {
                        return Err(bad(n, &format!("{e} escapes out of {c} collisions")));
                    }
                    if !(0.0..=1.0).contains(&p) {
                        return Err(bad(n, &format!("p_escape = {p} is not in [0, 1]")));
                    }
                    let k = cell(stage, i_in, i_out);
                    (counts.collisions[k], counts.escaped[k], written_p[k]) = (c, e, p);
                    rows += 1;
                }
            }
        }
        header(
            lines.next(),
            ELEMENT_HEADER,
            &format!("after the {CELLS} escape rows"),
        )?;
        let mut written_w = vec![0.0; ELEMENT_CELLS];
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                for i_g in 0..G_BINS {
                    let k = (stage.0 * X_IN_BINS + i_in) * G_BINS + i_g;
                    let cell_g = G_MIN + (i_g as f64 + 0.5) * DG;
                    let (n, l) = lines.next().ok_or_else(|| {
                        Error::Input(format!(
                            "{what}: truncated after {k} of {ELEMENT_CELLS} element rows"
                        ))
                    })?;
                    let (d, m, w) =
                        parse_row(l, stage, i_in, ("s", cell_g)).map_err(|m| bad(n, &m))?;
                    if w < 0.0 {
                        return Err(bad(n, &format!("weight = {w} is negative")));
                    }
                    (
                        counts.element_deterministic[k],
                        counts.element_model[k],
                        written_w[k],
                    ) = (d, m, w);
                }
            }
        }
        header(
            lines.next(),
            ROW_HEADER,
            &format!("after the {ELEMENT_CELLS} element rows"),
        )?;
        let (mut written_escape_pos, mut written_element_pos) = (vec![0.0; ROWS], vec![0.0; ROWS]);
        for stage in Stage::all() {
            for i_in in 0..X_IN_BINS {
                let r = stage.0 * X_IN_BINS + i_in;
                let (n, l) = lines.next().ok_or_else(|| {
                    Error::Input(format!("{what}: truncated after {r} of {ROWS} x_in rows"))
                })?;
                let f = parse_position_row(l, stage, i_in).map_err(|m| bad(n, &m))?;
                (
                    counts.escape_x_sum[r],
                    written_escape_pos[r],
                    counts.element_x_sum[r],
                    written_element_pos[r],
                ) = f;
            }
        }
        header(
            lines.next(),
            FIRST_HEADER,
            &format!("after the {ROWS} x_in rows"),
        )?;
        let mut written_first_pos = vec![0.0; FIRST_STAGES];
        for (k, pos) in written_first_pos.iter_mut().enumerate() {
            let (n, l) = lines.next().ok_or_else(|| {
                Error::Input(format!(
                    "{what}: truncated after {k} of {FIRST_STAGES} first-stage rows"
                ))
            })?;
            let f = parse_first_row(l, Stage(k)).map_err(|m| bad(n, &m))?;
            (counts.first_count[k], counts.first_dg_sum[k], *pos) = f;
        }
        header(
            lines.next(),
            TRANSVERSE_HEADER,
            &format!("after the {FIRST_STAGES} first-stage rows"),
        )?;
        let (mut written_slope, mut written_fresh) =
            (vec![0.0; LATER_STAGES], vec![0.0; LATER_STAGES]);
        for k in 0..LATER_STAGES {
            let (n, l) = lines.next().ok_or_else(|| {
                Error::Input(format!(
                    "{what}: truncated after {k} of {LATER_STAGES} transverse rows"
                ))
            })?;
            let t = &mut counts.transverse;
            let f = parse_transverse_row(l, Stage(FIRST_STAGES + k)).map_err(|m| bad(n, &m))?;
            (
                t.pairs[k],
                t.prev_sq_sum[k],
                t.cross_sum[k],
                written_slope[k],
                written_fresh[k],
            ) = f;
            if !plausible(t.pairs[k], t.prev_sq_sum[k], t.cross_sum[k]) {
                return Err(bad(
                    n,
                    &format!(
                        "sums {} and {} cannot come from {} pairs of residuals within ±{Z_MAX} (0 ≤ z_prev² sum ≤ {MAX_TERM} per pair, |cross sum| as large)",
                        t.prev_sq_sum[k], t.cross_sum[k], t.pairs[k]
                    ),
                ));
            }
        }
        if let Some((n, _)) = lines.find(|(_, l)| !l.is_empty()) {
            return Err(bad(n, "more rows than the grid has"));
        }
        let table = EscapeTable::from_counts(counts, &source);
        // The written values must be the ones the counts give (a hand-edited or corrupted
        // table is refused rather than silently recomputed).
        // Compared as written (six decimals): a value on a rounding boundary must not differ
        // by the last bit of a subtraction. A written value on the six-decimal grid within
        // 4.5·10⁻⁷ of its computed one is that value rounded (the next grid value is at least
        // 5.5·10⁻⁷ away), so only the others are formatted: this keeps a host's start-up
        // short. (A hand-written value with more decimals is off the grid: formatted.)
        let edited = |kind: &str, written: &[f64], computed: &[f64]| {
            (0..written.len())
                .find(|&k| {
                    let (w, c) = (written[k], computed[k]);
                    // (A NaN difference is not close: formatted.)
                    let micro = w * 1e6;
                    let close = (micro - micro.round()).abs() < 1e-3 && (w - c).abs() < 4.5e-7;
                    !close && format!("{w:.6}") != format!("{c:.6}")
                })
                .map(|k| {
                    Error::Input(format!(
                        "{what}: {kind} row {} gives {} but its counts give {:.6} (edited or corrupted)",
                        k + 1,
                        written[k],
                        computed[k]
                    ))
                })
        };
        if let Some(e) = edited("escape", &written_p, &table.p) {
            return Err(e);
        }
        if let Some(e) = edited("element", &written_w, &table.weight) {
            return Err(e);
        }
        if let Some(e) = edited("escape position", &written_escape_pos, &table.escape_pos) {
            return Err(e);
        }
        if let Some(e) = edited("element position", &written_element_pos, &table.element_pos) {
            return Err(e);
        }
        // A row's mean must lie in its bin (else the positions do not increase).
        for (kind, pos) in [
            ("escape", &table.escape_pos),
            ("element", &table.element_pos),
        ] {
            if let Some(r) = (0..ROWS).find(|&r| {
                let i = r % X_IN_BINS;
                !(X_IN_EDGES[i]..=X_IN_EDGES[i + 1]).contains(&pos[r])
            }) {
                return Err(Error::Input(format!(
                    "{what}: the {kind} x_in sum of row {} puts its mean at {} outside its bin (edited or corrupted)",
                    r + 1,
                    pos[r]
                )));
            }
        }
        if let Some(e) = edited("first-stage position", &written_first_pos, &table.first_pos) {
            return Err(e);
        }
        let slopes: Vec<f64> = (0..LATER_STAGES).map(|k| table.memory.slope(k)).collect();
        if let Some(e) = edited("transverse slope", &written_slope, &slopes) {
            return Err(e);
        }
        let fresh: Vec<f64> = (0..LATER_STAGES).map(|k| table.memory.fresh(k)).collect();
        if let Some(e) = edited("transverse fresh", &written_fresh, &fresh) {
            return Err(e);
        }
        if table.counts.total() == 0 {
            return Err(Error::Input(format!("{what}: no collisions counted")));
        }
        Ok(table)
    }

    /// The table shipped with the library: calibrated by `rebound calibrate --case
    /// calibration/aniso.toml` on the (Δξ, Δζ) = (2.5°, 7.5°) wall of Radenkovic & Simonin
    /// 2021, Sec. 3 (`scripts/calibrate.sh` regenerates it byte for byte).
    pub fn builtin() -> &'static EscapeTable {
        static T: OnceLock<EscapeTable> = OnceLock::new();
        T.get_or_init(|| {
            EscapeTable::parse(BUILTIN, "the built-in escape table")
                .expect("the built-in escape table is checked by a test")
        })
    }

    /// A `'static` copy of `self`, shared by every wall built with an equal table: wall
    /// models are `Copy` and hold a reference, and a host building many walls from one
    /// table keeps one copy. Each distinct table is kept for the life of the process, so at
    /// most [`MAX_DISTINCT_TABLES`] distinct ones (besides the built-in table) are taken:
    /// about 1.4 MB each, 23 MB in all; one more is a one-line error, never a growing process.
    pub fn intern(self) -> Result<&'static EscapeTable> {
        static TABLES: Mutex<Vec<&'static EscapeTable>> = Mutex::new(Vec::new());
        if self == *EscapeTable::builtin() {
            return Ok(EscapeTable::builtin());
        }
        let mut v = TABLES.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(t) = v.iter().find(|t| ***t == self) {
            return Ok(t);
        }
        if v.len() >= MAX_DISTINCT_TABLES {
            return Err(Error::Input(format!(
                "`stochastic.escape_table`: more than {MAX_DISTINCT_TABLES} distinct escape tables in one process (each stays in memory for the process's life); build the walls from fewer tables"
            )));
        }
        let t: &'static EscapeTable = Box::leak(Box::new(self));
        v.push(t);
        Ok(t)
    }
}

/// Distinct escape tables a process may hold besides the built-in one (see
/// [`EscapeTable::intern`]): a host's walls use one or a few calibrations.
pub const MAX_DISTINCT_TABLES: usize = 16;

/// The built-in table's text.
pub const BUILTIN: &str = include_str!("aniso-escape.csv");

/// A table row's fields (six for a cell or an `x_in` row, checked by [`Fields::of`]; four for
/// a first-stage row, checked by [`parse_first_row`]; six for a transverse row, checked by
/// [`parse_transverse_row`]).
struct Fields<'a>(Vec<&'a str>);

impl<'a> Fields<'a> {
    fn of(line: &'a str) -> std::result::Result<Self, String> {
        let f: Vec<&str> = line.split(',').collect();
        match f.len() {
            6 => Ok(Fields(f)),
            n => Err(format!("{n} fields, expected 6")),
        }
    }

    /// Field `j` as a finite number.
    fn num(&self, j: usize) -> std::result::Result<f64, String> {
        self.0[j]
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| format!("`{}` is not a number", self.0[j]))
    }

    /// Field `j` as a count.
    fn count(&self, j: usize) -> std::result::Result<u64, String> {
        self.0[j]
            .parse::<u64>()
            .map_err(|_| format!("`{}` is not a non-negative integer", self.0[j]))
    }

    /// Field `j` as a signed integer.
    fn int(&self, j: usize) -> std::result::Result<i64, String> {
        self.0[j]
            .parse::<i64>()
            .map_err(|_| format!("`{}` is not an integer", self.0[j]))
    }

    /// Checks that the row is the one the fixed grid has here: its stage, its `x_in` bin
    /// centre and, for a cell, the centre along its second axis (field 2).
    fn at(
        &self,
        stage: Stage,
        i_in: usize,
        axis: Option<(&str, f64)>,
    ) -> std::result::Result<(), String> {
        let (stage, x_in) = (stage.name(), centre_in(i_in));
        let axis_ok = match axis {
            Some((_, v)) => (self.num(2)? - v).abs() <= 1e-9,
            None => true,
        };
        if self.0[0] == stage && (self.num(1)? - x_in).abs() <= 1e-9 && axis_ok {
            return Ok(());
        }
        let what = match axis {
            Some((name, v)) => format!("the cell ({stage}, x_in = {x_in}, {name} = {v})"),
            None => format!("the row ({stage}, x_in = {x_in})"),
        };
        Err(format!(
            "expected {what}: the table does not match this version's grid"
        ))
    }
}

/// One row `stage,x_in,<axis>,count,count,value` of a table: checked against the cell it
/// must be (the grid is fixed), the two counts and the value; the error without the line.
fn parse_row(
    line: &str,
    stage: Stage,
    i_in: usize,
    axis: (&str, f64),
) -> std::result::Result<(u64, u64, f64), String> {
    let f = Fields::of(line)?;
    f.at(stage, i_in, Some(axis))?;
    Ok((f.count(3)?, f.count(4)?, f.num(5)?))
}

/// One row `stage,x_in,sum,position,sum,position` of the `x_in` rows' block:
/// checked against the row it must be; the two sums and the two positions.
fn parse_position_row(
    line: &str,
    stage: Stage,
    i_in: usize,
) -> std::result::Result<(i64, f64, i64, f64), String> {
    let f = Fields::of(line)?;
    f.at(stage, i_in, None)?;
    Ok((f.int(2)?, f.num(3)?, f.int(4)?, f.num(5)?))
}

/// One row `stage,count,sum,position` of the first stages' block: checked against the
/// stage it must be; the count, the `Δγ` sum and the position.
fn parse_first_row(line: &str, stage: Stage) -> std::result::Result<(u64, i64, f64), String> {
    let f = Fields(line.split(',').collect());
    if f.0.len() != 4 || f.0[0] != stage.name() {
        return Err(format!(
            "expected the first-stage row `{},<collisions>,<Δγ sum>,<position>`: the table does not match this version's grid",
            stage.name()
        ));
    }
    Ok((f.count(1)?, f.int(2)?, f.num(3)?))
}

/// One row `stage,pairs,sum,sum,slope,fresh` of the transverse block: checked against the
/// stage it must be; the count, the two sums, the slope and the fresh part's spread.
fn parse_transverse_row(
    line: &str,
    stage: Stage,
) -> std::result::Result<(u64, i64, i64, f64, f64), String> {
    let f = Fields(line.split(',').collect());
    if f.0.len() != 6 || f.0[0] != stage.name() {
        return Err(format!(
            "expected the transverse row `{},<pairs>,<z_prev² sum>,<cross sum>,<slope>,<fresh>`: the table does not match this version's grid",
            stage.name()
        ));
    }
    Ok((f.count(1)?, f.int(2)?, f.int(3)?, f.num(4)?, f.num(5)?))
}
