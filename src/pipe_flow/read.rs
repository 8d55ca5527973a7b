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
    let rows = Rows::read(&path)?.ok_or_else(|| bad(&path, "not found"))?;
    let mut out = Vec::with_capacity(rows.rows.len());
    for r in &rows.rows {
        let group = |g: &str| -> Result<Vec<f64>> {
            (0..n_bins)
                .map(|b| num(r, &format!("{g}_{b}"), &path))
                .collect()
        };
        out.push(ParticleRow {
            id: num(r, "particle_id", &path)? as usize,
            samples: num(r, "n", &path)?,
            dist: num(r, "dist", &path)?,
            hits: num(r, "hits", &path)?,
            sum_y: num(r, "sum_y", &path)?,
            cy: group("cy")?,
            cz: group("cz")?,
            ux: group("ux")?,
            ux2: group("ux2")?,
            ur: group("ur")?,
            ur2: group("ur2")?,
            sy: group("sy")?,
            sz: group("sz")?,
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
        let Some(rows) = Rows::read(&path)? else {
            continue;
        };
        for r in &rows.rows {
            if num(r, "status", &path)? != 0.0 {
                continue;
            }
            out.push(Hit {
                particle_id: num(r, "particle_id", &path)? as usize,
                y: num(r, "y", &path)?,
                z: num(r, "z", &path)?,
                alpha_in_deg: num(r, "alpha_in_deg", &path)?,
                lay_angle_deg: num(r, "lay_angle_deg", &path)?,
                speed_in: num(r, "speed_in", &path)?,
                speed_out: num(r, "speed_out", &path)?,
                alpha_out_deg: num(r, "alpha_out_deg", &path)?,
                deflection_deg: num(r, "deflection_deg", &path)?,
                alpha_element_deg: num(r, "alpha_element_deg", &path)?,
            });
        }
    }
    Ok(out)
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
            Ok(Run {
                info,
                params,
                particles,
                hits,
            })
        })
        .collect()
}
