//! The measured-wall tables of `rebound scan --measured-wall` as the card and `run.toml` name
//! them: what was built for each particle ([`MeasuredWallEntry`]), the card's lines and the
//! `[[measured_wall]]` array.

use crate::output::toml_str;

/// What was built for one particle: the point (`diameter_m = 0`) or a sphere.
#[derive(Clone, Debug, PartialEq)]
pub struct MeasuredWallEntry {
    /// Particle diameter (m); 0 for the point particle.
    pub diameter_m: f64,
    /// The table's file name in the card's directory; `None` when none could be built.
    pub file: Option<String>,
    /// The lowest incident angle `|α⁻|` (degrees) the table serves as measured.
    pub lowest_alpha_deg: f64,
    /// The largest share of a served cell's histories that left the scan.
    pub max_left_share: f64,
    /// Why there is no table, or what limits it ("" when nothing does).
    pub note: String,
    /// Seconds the build took.
    pub seconds: f64,
    /// Histories per grid cell.
    pub histories_per_cell: u64,
    /// The rows (`|α⁻|`, degrees) the build added to the base grid where the wall's law bends.
    pub refined_rows_deg: Vec<f64>,
    /// What the Gaussian assumption costs on this wall: the paper's model against the table.
    pub versus_paper: Option<VersusPaper>,
}

/// The paper's model, given the deviations of the wall a table was measured on, against the
/// table's own law (the measured-wall model, which stands for the reference on the scan), over
/// [`VERSUS_DIRECTIONS`]: the largest KS distance of `α⁺` and where, the largest bias of mean
/// `α⁺` (paper − wall's own, degrees) and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VersusPaper {
    pub ks: f64,
    pub ks_at: (f64, f64),
    pub bias_deg: f64,
    pub bias_at: (f64, f64),
}

/// The incident directions `(α⁻, β⁻)` (degrees) of [`VersusPaper`]: the scan check's.
pub use roughwall::gaussian_cost::DIRECTIONS as VERSUS_DIRECTIONS;

/// Rebounds of each model per direction of [`VersusPaper`]: the KS distance of two such
/// samples is then about `0.87 √(2/n)` ≈ 0.009 by chance, far below the misses it reports
/// (0.1–0.3 on the study's non-Gaussian walls), at about 0.3 s per table.
pub const VERSUS_REBOUNDS: u64 = 20_000;

impl VersusPaper {
    /// The card's line: what the Gaussian models miss this wall by, and what to use instead.
    pub fn line(&self) -> String {
        format!(
            "the paper's model with this wall's deviations differs from the wall's own law (this table) by a KS distance of α⁺ up to {:.3} (at α⁻ = {}°, β⁻ = {}°) and by up to {:+.2}° in mean α⁺ (at {}°, {}°), over α⁻ = −5°, −15°, −35° × β⁻ = 0°, 45°, 90°, −90° ({} rebounds each): the Gaussian models miss this wall by that much; model = \"measured-wall\" takes it as measured",
            self.ks,
            crate::output::fmt_num(self.ks_at.0),
            crate::output::fmt_num(self.ks_at.1),
            self.bias_deg,
            crate::output::fmt_num(self.bias_at.0),
            crate::output::fmt_num(self.bias_at.1),
            VERSUS_REBOUNDS
        )
    }
}

/// A card's lines naming a particle's measured-wall table (`measured_wall_table`, with
/// `measured_wall_note` when something limits it or there is none).
pub fn table_lines(t: &MeasuredWallEntry) -> String {
    let mut s = String::new();
    if let Some(f) = &t.file {
        s += &format!(
            "measured_wall_table = {}    # model = \"measured-wall\"\n",
            toml_str(f)
        );
        s += &format!(
            "measured_wall_entry_alpha_deg = {}    # its reference: deterministic with [deterministic] entry_alpha_deg = this\n",
            crate::output::fmt_num(roughwall::measured_wall::ENTRY_ALPHA_DEG)
        );
    }
    if !t.note.is_empty() {
        s += &format!("measured_wall_note = {}\n", toml_str(&t.note));
    }
    if let Some(v) = &t.versus_paper {
        s += &format!("measured_wall_versus_paper = {}\n", toml_str(&v.line()));
    }
    s
}

/// The `[[measured_wall]]` array of `run.toml`: one table per particle, what limits it and
/// how long it took.
pub fn manifest_entries(entries: &[MeasuredWallEntry]) -> toml::Value {
    let rows = entries
        .iter()
        .map(|e| {
            let mut t = toml::Table::new();
            // Rounded to the picometre, as the card writes diameters.
            t.insert(
                "diameter_um".into(),
                ((e.diameter_m * 1e15).round() / 1e9).into(),
            );
            if let Some(f) = &e.file {
                t.insert("file".into(), f.clone().into());
                t.insert("lowest_alpha_deg".into(), e.lowest_alpha_deg.into());
                t.insert(
                    "entry_alpha_deg".into(),
                    roughwall::measured_wall::ENTRY_ALPHA_DEG.into(),
                );
                t.insert("max_left_share".into(), e.max_left_share.into());
                t.insert(
                    "refined_rows_deg".into(),
                    toml::Value::Array(e.refined_rows_deg.iter().map(|&a| a.into()).collect()),
                );
            }
            if !e.note.is_empty() {
                t.insert("note".into(), e.note.clone().into());
            }
            t.insert("build_s".into(), super::surface::round_ms(e.seconds).into());
            t.insert(
                "histories_per_cell".into(),
                (e.histories_per_cell as i64).into(),
            );
            if let Some(v) = &e.versus_paper {
                t.insert("paper_max_ks_alpha_out".into(), v.ks.into());
                t.insert("paper_max_abs_bias_deg".into(), v.bias_deg.abs().into());
            }
            toml::Value::Table(t)
        })
        .collect();
    toml::Value::Array(rows)
}
