//! Reading a pipe-flow study written by `scripts/pipe-flow.sh`: `study.tsv` lists the runs
//! (name, kind, diameter, wall, model, directory); each run directory holds the
//! `pipe.params` it ran with, the per-particle tallies `particles.csv` (the columns of
//! `examples/code_saturne/pipe/case_src/pipe_tally.h`) and the wall hits of its sampling
//! window, `hits_rank<r>.csv` (one file per MPI rank).

use crate::output::csv::Rows;
use roughwall::{Error, Result};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// One run as `study.tsv` lists it.
#[derive(Clone, Debug, PartialEq)]
pub struct RunInfo {
    pub name: String,
    /// `main` (the study), `mesh` (the finer mesh) or `development` (the later window).
    pub kind: String,
    pub diameter_um: f64,
    /// `smooth`, `ts0.5`, `ts1`, `ts2` (technically smooth), `iso`, `axial` or `circ`.
    pub wall: String,
    /// `paper`, `calibrated` or `sh1999`.
    pub model: String,
    pub dir: PathBuf,
}

impl RunInfo {
    /// Whether the run's wall is technically smooth (`ts<Δγ>`, e.g. `ts0.5`).
    pub fn technically_smooth(&self) -> bool {
        is_technically_smooth(&self.wall)
    }
}

/// Whether a wall name is a technically smooth wall of the study (`ts<Δγ>`: `ts0.5`, `ts1`,
/// `ts2`; scripts/pipe-flow.sh `walls_for`).
pub fn is_technically_smooth(wall: &str) -> bool {
    wall.starts_with("ts")
}

/// The smooth limit or a technically smooth wall: run with the paper's model only.
pub fn is_smooth_limit(wall: &str) -> bool {
    wall == "smooth" || is_technically_smooth(wall)
}

/// The `pipe.params` values the statistics need.
#[derive(Clone, Debug, PartialEq)]
pub struct Params {
    pub pipe_diameter_m: f64,
    pub length_m: f64,
    pub n_bins: usize,
    pub particle_diameter_m: f64,
    pub particle_density: f64,
    pub delta_xi_deg: f64,
    pub delta_zeta_deg: f64,
    /// Sides of the mesh's polygonal wall (`mesh_sides`; `None`: not recorded, a circle).
    pub mesh_sides: Option<usize>,
}

/// One particle's tallies over the sampling window.
#[derive(Clone, Debug, PartialEq)]
pub struct ParticleRow {
    pub id: usize,
    pub samples: f64,
    /// Axial distance travelled (m).
    pub dist: f64,
    /// Wall rebounds (status OK) in the window.
    pub hits: f64,
    /// Sum of the heights y at the samples (m).
    pub sum_y: f64,
    /// Samples per horizontal slab (bins of y), per vertical slab (bins of z).
    pub cy: Vec<f64>,
    pub cz: Vec<f64>,
    /// Per horizontal slab: sums of u_x, u_x², u_r, u_r².
    pub ux: Vec<f64>,
    pub ux2: Vec<f64>,
    pub ur: Vec<f64>,
    pub ur2: Vec<f64>,
    /// Samples along the vertical diameter (bins of y, |z| < R/5) and the horizontal one
    /// (bins of z, |y| < R/5).
    pub sy: Vec<f64>,
    pub sz: Vec<f64>,
}

/// One wall rebound in the sampling window (a logged hit whose status is `RW_OK`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    pub particle_id: usize,
    pub y: f64,
    pub z: f64,
    pub alpha_in_deg: f64,
    pub lay_angle_deg: f64,
    pub speed_in: f64,
    pub speed_out: f64,
    pub alpha_out_deg: f64,
    pub deflection_deg: f64,
    /// The impact angle on the wall element the library drew (`rw_element_impact_angle`):
    /// the facet struck, which the erosion laws take.
    pub alpha_element_deg: f64,
}

/// One run, read.
#[derive(Clone, Debug)]
pub struct Run {
    pub info: RunInfo,
    pub params: Params,
    pub particles: Vec<ParticleRow>,
    pub hits: Vec<Hit>,
    /// What the carrier-flow forces cost (`forces_cost.csv`; `None` for a run without it).
    pub cost: Option<ForcesCost>,
}

/// `forces_cost.csv` of a run (examples/code_saturne/pipe/case_src/pipe_forces.h): its
/// particle steps and the seconds, summed over ranks, spent in the lifts, the spin's
/// relaxation, the spins' exchange between ranks and whole steps (from the second on).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForcesCost {
    pub particle_steps: f64,
    pub lift_s: f64,
    pub spin_relax_s: f64,
    pub spin_exchange_s: f64,
    pub step_s: f64,
}

/// A run's `forces_cost.csv`, if it wrote one.
pub fn forces_cost(dir: &Path) -> Result<Option<ForcesCost>> {
    let path = dir.join("forces_cost.csv");
    let Some(rows) = Rows::read(&path)? else {
        return Ok(None);
    };
    let Some(r) = rows.rows.first() else {
        return Err(bad(&path, "no row"));
    };
    let cost = ForcesCost {
        particle_steps: num(r, "particle_steps", &path)?,
        lift_s: num(r, "lift_s", &path)?,
        spin_relax_s: num(r, "spin_relax_s", &path)?,
        spin_exchange_s: num(r, "spin_exchange_s", &path)?,
        step_s: num(r, "step_s", &path)?,
    };
    if cost.particle_steps <= 0.0 {
        return Err(bad(&path, "particle_steps must be > 0"));
    }
    Ok(Some(cost))
}

fn bad(path: &Path, what: impl std::fmt::Display) -> Error {
    Error::Input(format!("{}: {what}", path.display()))
}

/// The runs of `study.tsv` under `study`, in its order.
pub fn runs(study: &Path) -> Result<Vec<RunInfo>> {
    let path = study.join("study.tsv");
    let text = std::fs::read_to_string(&path).map_err(|e| {
        bad(
            &path,
            format!("{e} (`--study` must be a directory written by scripts/pipe-flow.sh)"),
        )
    })?;
    let mut lines = text.lines();
    let header = lines.next().unwrap_or("");
    if header != "name\tkind\tdiameter_um\twall\tmodel\tdir" {
        return Err(bad(&path, "not a pipe-flow study list (wrong header)"));
    }
    let mut out = Vec::new();
    for (i, line) in lines.enumerate() {
        let f: Vec<&str> = line.split('\t').collect();
        if f.len() != 6 {
            return Err(bad(
                &path,
                format!("line {}: 6 tab-separated fields expected", i + 2),
            ));
        }
        let diameter_um = f[2]
            .parse::<f64>()
            .ok()
            .filter(|d| *d > 0.0 && d.is_finite())
            .ok_or_else(|| bad(&path, format!("line {}: diameter_um `{}`", i + 2, f[2])))?;
        out.push(RunInfo {
            name: f[0].to_string(),
            kind: f[1].to_string(),
            diameter_um,
            wall: f[3].to_string(),
            model: f[4].to_string(),
            dir: study.join(f[5]),
        });
    }
    if out.is_empty() {
        return Err(bad(&path, "lists no run"));
    }
    Ok(out)
}

/// A run's `pipe.params`.
pub fn params(dir: &Path) -> Result<Params> {
    let path = dir.join("pipe.params");
    let text = std::fs::read_to_string(&path).map_err(|e| bad(&path, e))?;
    let mut kv: HashMap<&str, f64> = HashMap::new();
    for line in text.lines() {
        let mut it = line.split_whitespace();
        if let (Some(k), Some(v)) = (it.next(), it.next()) {
            if let Ok(x) = v.parse::<f64>() {
                kv.insert(k, x);
            }
        }
    }
    let get = |k: &str| {
        kv.get(k)
            .copied()
            .filter(|v| v.is_finite())
            .ok_or_else(|| bad(&path, format!("no numeric `{k}`")))
    };
    let n_bins = get("n_bins")?;
    if !(2.0..=200.0).contains(&n_bins) {
        return Err(bad(&path, format!("n_bins {n_bins}: allowed 2 to 200")));
    }
    Ok(Params {
        pipe_diameter_m: get("diameter_pipe")?,
        length_m: get("length")?,
        n_bins: n_bins as usize,
        particle_diameter_m: get("d_p")?,
        particle_density: get("rho_p")?,
        delta_xi_deg: get("delta_xi_deg")?,
        delta_zeta_deg: get("delta_zeta_deg")?,
        mesh_sides: kv
            .get("mesh_sides")
            .filter(|v| v.is_finite() && **v >= 8.0)
            .map(|v| *v as usize),
    })
}

fn num(row: &HashMap<String, String>, key: &str, path: &Path) -> Result<f64> {
    row.get(key)
        .and_then(|v| v.parse::<f64>().ok())
        .filter(|v| v.is_finite())
        .ok_or_else(|| {
            bad(
                path,
                format!("column `{key}` missing or not a finite number"),
            )
        })
}

/// A run's `particles.csv` (`n_bins` bins).
pub fn particles(dir: &Path, n_bins: usize) -> Result<Vec<ParticleRow>> {
    let path = dir.join("particles.csv");
    if !path.is_file() {
        return Err(bad(&path, "not found"));
    }
    let mut r = csv::Reader::from_path(&path).map_err(|e| bad(&path, e))?;
    let header = r.byte_headers().map_err(|e| bad(&path, e))?.clone();
    let missing = |k: &str| {
        bad(
            &path,
            format!("column `{k}` missing or not a finite number"),
        )
    };
    // Column indices, resolved once: 5 scalars, then 8 groups of n_bins (a study reads
    // hundreds of thousands of rows of about 165 cells).
    let mut names: Vec<String> = ["particle_id", "n", "dist", "hits", "sum_y"]
        .iter()
        .map(|k| k.to_string())
        .collect();
    for g in ["cy", "cz", "ux", "ux2", "ur", "ur2", "sy", "sz"] {
        names.extend((0..n_bins).map(|b| format!("{g}_{b}")));
    }
    let at: Vec<usize> = names
        .iter()
        .map(|k| {
            header
                .iter()
                .position(|h| h == k.as_bytes())
                .ok_or_else(|| missing(k))
        })
        .collect::<Result<_>>()?;
    let mut out = Vec::new();
    let mut rec = csv::ByteRecord::new();
    let mut values = vec![0.0; at.len()];
    while r.read_byte_record(&mut rec).map_err(|e| bad(&path, e))? {
        for (k, &i) in at.iter().enumerate() {
            values[k] = std::str::from_utf8(&rec[i])
                .ok()
                .and_then(|t| t.parse::<f64>().ok())
                .filter(|x| x.is_finite())
                .ok_or_else(|| missing(&names[k]))?;
        }
        let group = |g: usize| values[5 + g * n_bins..5 + (g + 1) * n_bins].to_vec();
        out.push(ParticleRow {
            id: values[0] as usize,
            samples: values[1],
            dist: values[2],
            hits: values[3],
            sum_y: values[4],
            cy: group(0),
            cz: group(1),
            ux: group(2),
            ux2: group(3),
            ur: group(4),
            ur2: group(5),
            sy: group(6),
            sz: group(7),
        });
    }
    if out.is_empty() {
        return Err(bad(&path, "no particle"));
    }
    Ok(out)
}

/// A run's wall rebounds: the hits of every `hits_rank*.csv` whose `status` is 0 (`RW_OK`;
/// a hit the library refused or found not approaching the wall is no rebound).
pub fn hits(dir: &Path) -> Result<Vec<Hit>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| bad(dir, e))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("hits_rank") && n.ends_with(".csv"))
        })
        .collect();
    files.sort();
    let mut out = Vec::new();
    for path in files {
        read_hits(&path, &mut out)?;
    }
    Ok(out)
}

/// The columns of a hit log that [`Hit`] takes, in its field order after `status`.
const HIT_COLUMNS: [&str; 11] = [
    "status",
    "particle_id",
    "y",
    "z",
    "alpha_in_deg",
    "lay_angle_deg",
    "speed_in",
    "speed_out",
    "alpha_out_deg",
    "deflection_deg",
    "alpha_element_deg",
];

/// Appends the rebounds of one `hits_rank*.csv` to `out`, reading only the columns a [`Hit`]
/// takes (a run logs about 10⁵ hits of 30 columns; a study, millions). An empty file holds
/// no hit.
fn read_hits(path: &Path, out: &mut Vec<Hit>) -> Result<()> {
    let mut r = csv::Reader::from_path(path).map_err(|e| bad(path, e))?;
    let header = r.byte_headers().map_err(|e| bad(path, e))?.clone();
    if header.is_empty() {
        return Ok(());
    }
    let missing = |k: &str| bad(path, format!("column `{k}` missing or not a finite number"));
    let mut at = [0usize; HIT_COLUMNS.len()];
    for (i, k) in HIT_COLUMNS.iter().enumerate() {
        at[i] = header
            .iter()
            .position(|h| h == k.as_bytes())
            .ok_or_else(|| missing(k))?;
    }
    let mut rec = csv::ByteRecord::new();
    while r.read_byte_record(&mut rec).map_err(|e| bad(path, e))? {
        let v = |i: usize| -> Result<f64> {
            std::str::from_utf8(&rec[at[i]])
                .ok()
                .and_then(|t| t.parse::<f64>().ok())
                .filter(|x| x.is_finite())
                .ok_or_else(|| missing(HIT_COLUMNS[i]))
        };
        if v(0)? != 0.0 {
            continue;
        }
        out.push(Hit {
            particle_id: v(1)? as usize,
            y: v(2)?,
            z: v(3)?,
            alpha_in_deg: v(4)?,
            lay_angle_deg: v(5)?,
            speed_in: v(6)?,
            speed_out: v(7)?,
            alpha_out_deg: v(8)?,
            deflection_deg: v(9)?,
            alpha_element_deg: v(10)?,
        });
    }
    Ok(())
}

/// Every run of the study, read.
pub fn study(study: &Path) -> Result<Vec<Run>> {
    runs(study)?
        .into_iter()
        .map(|info| {
            let params = params(&info.dir)?;
            let particles = particles(&info.dir, params.n_bins)?;
            let hits = hits(&info.dir)?;
            // Every rebound the tallies counted must be in the logs (a lost or truncated
            // hits_rank*.csv would bias every hit statistic).
            let counted: f64 = particles.iter().map(|p| p.hits).sum();
            if counted != hits.len() as f64 {
                return Err(bad(
                    &info.dir,
                    format!(
                        "particles.csv counts {counted} rebounds but hits_rank*.csv log {} \
                         (a log is missing or truncated)",
                        hits.len()
                    ),
                ));
            }
            let cost = forces_cost(&info.dir)?;
            Ok(Run {
                info,
                params,
                particles,
                hits,
                cost,
            })
        })
        .collect()
}
