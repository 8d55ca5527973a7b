//! The CSV tables of `rebound pipe-stats` (docs/outputs.md, "pipe-stats"): `summary.csv`
//! (one row per run), `profiles.csv`, `distributions.csv` and `comparisons.csv` (the
//! difference between two walls, or meshes, or windows, with its paired standard error).

use super::jackknife::{estimate, Estimate};
use super::read::Run;
use super::section::CrossSection;
use super::stats::{angle_pdf, erosion_profile, profile, Profile, QUANTITIES};
use super::sums::{RunSums, LAWS};
use crate::output::csv::CsvTable;
use roughwall::format::fmt_num;

/// A run with its sums.
pub struct Analysed<'a> {
    pub run: &'a Run,
    pub sums: RunSums,
}

impl Analysed<'_> {
    fn radius(&self) -> f64 {
        0.5 * self.run.params.pipe_diameter_m
    }

    /// The run's cross-section (the mesh's polygon when the run recorded it).
    pub fn section(&self) -> CrossSection {
        CrossSection::new(self.run.params.mesh_sides)
    }
}

/// The whole-run quantities of one run (`runs` = `[a]`) or of the difference of two
/// (`[a, b]`: a − b, paired), `(name, estimate)` per quantity.
pub fn quantities(runs: &[&Analysed]) -> Vec<(&'static str, Estimate)> {
    let sums: Vec<&RunSums> = runs.iter().map(|a| &a.sums).collect();
    let l = sums[0].layout;
    let r: Vec<f64> = runs.iter().map(|a| a.radius()).collect();
    QUANTITIES
        .iter()
        .map(|q| {
            let f = q.f;
            let e = match sums.len() {
                1 => estimate(&sums, |s| f(&l, s[0], r[0])),
                _ => estimate(&sums, |s| f(&l, s[0], r[0]) - f(&l, s[1], r[1])),
            };
            (q.name, e)
        })
        .collect()
}

/// Every whole-run quantity's ratio `a/b` (paired: the same batches of particles), in
/// [`QUANTITIES`] order.
fn ratios(a: &Analysed, b: &Analysed) -> Vec<Estimate> {
    let l = a.sums.layout;
    let (ra, rb) = (a.radius(), b.radius());
    let sums = [&a.sums, &b.sums];
    QUANTITIES
        .iter()
        .map(|q| {
            let f = q.f;
            estimate(&sums, |s| f(&l, s[0], ra) / f(&l, s[1], rb))
        })
        .collect()
}

/// The columns that name a run, first in every per-run table; [`id_cells`] fills them.
const ID_COLUMNS: [&str; 5] = ["run", "kind", "diameter_um", "wall", "model"];

/// A per-run table's header: [`ID_COLUMNS`], then `rest`.
fn with_id_columns(rest: &[&str]) -> CsvTable {
    let header: Vec<&str> = ID_COLUMNS.iter().chain(rest).copied().collect();
    CsvTable::new(&header)
}

/// The run of `runs` of this kind, diameter, wall and model.
fn find_run(runs: &[Analysed], kind: &str, d: f64, wall: &str, model: &str) -> Option<usize> {
    runs.iter().position(|a| {
        let i = &a.run.info;
        i.kind == kind && i.diameter_um == d && i.wall == wall && i.model == model
    })
}

fn id_cells(a: &Analysed) -> Vec<String> {
    let i = &a.run.info;
    vec![
        i.name.clone(),
        i.kind.clone(),
        fmt_num(i.diameter_um),
        i.wall.clone(),
        i.model.clone(),
    ]
}

/// `summary.csv`.
pub fn summary(runs: &[Analysed]) -> CsvTable {
    let mut header: Vec<String> = ID_COLUMNS
        .iter()
        .chain(&[
            "delta_xi_deg",
            "delta_zeta_deg",
            "particles",
            "samples",
            "hits",
        ])
        .map(|c| c.to_string())
        .collect();
    let names: Vec<&str> = QUANTITIES.iter().map(|q| q.name).collect();
    for n in &names {
        header.push(n.to_string());
        header.push(format!("{n}_se"));
    }
    let mut t = CsvTable {
        header,
        rows: Vec::new(),
    };
    for a in runs {
        let mut row = id_cells(a);
        let p = &a.run.params;
        row.push(fmt_num(p.delta_xi_deg));
        row.push(fmt_num(p.delta_zeta_deg));
        row.push(a.run.particles.len().to_string());
        row.push(fmt_num(a.run.particles.iter().map(|p| p.samples).sum()));
        row.push(a.run.hits.len().to_string());
        for (_, e) in quantities(&[a]) {
            row.push(fmt_num(e.value));
            row.push(fmt_num(e.se));
        }
        t.push(row);
    }
    t
}

fn est_cells(e: Option<Estimate>) -> [String; 2] {
    match e {
        Some(e) => [fmt_num(e.value), fmt_num(e.se)],
        None => [String::new(), String::new()],
    }
}

/// `profiles.csv`: every profile of every run (the vertical slabs with velocities).
pub fn profiles(runs: &[Analysed]) -> CsvTable {
    let mut t = with_id_columns(&[
        "profile",
        "position_over_r",
        "concentration",
        "concentration_se",
        "ux_mean_m_s",
        "ux_mean_se",
        "ux_rms_m_s",
        "ux_rms_se",
        "ur_mean_m_s",
        "ur_mean_se",
        "ur_rms_m_s",
        "ur_rms_se",
    ]);
    for a in runs {
        let section = a.section();
        for kind in Profile::ALL {
            for p in profile(&a.sums, &section, kind) {
                let mut row = id_cells(a);
                row.push(kind.name().into());
                row.push(fmt_num(p.position_over_r));
                row.extend(est_cells(Some(p.concentration)));
                for e in [p.ux_mean, p.ux_rms, p.ur_mean, p.ur_rms] {
                    row.extend(est_cells(e));
                }
                t.push(row);
            }
        }
    }
    t
}

/// `distributions.csv`: impact-angle and lay-angle PDFs (per degree) and erosion around the
/// circumference (µm per tonne, angle from the bottom, folded).
pub fn distributions(runs: &[Analysed]) -> CsvTable {
    let mut t = with_id_columns(&["quantity", "lo_deg", "hi_deg", "value", "se"]);
    for a in runs {
        let mut sets = vec![
            ("impact_angle_pdf".to_string(), angle_pdf(&a.sums, false)),
            ("lay_angle_pdf".to_string(), angle_pdf(&a.sums, true)),
        ];
        for (k, law) in LAWS.iter().enumerate() {
            sets.push((
                format!("erosion_{law}_um_per_t"),
                erosion_profile(&a.sums, a.radius(), k),
            ));
        }
        for (q, bins) in sets {
            for b in bins {
                let mut row = id_cells(a);
                row.push(q.clone());
                row.push(fmt_num(b.lo));
                row.push(fmt_num(b.hi));
                row.extend(est_cells(Some(b.value)));
                t.push(row);
            }
        }
    }
    t
}

/// The pairs the study compares, as indices into `runs`: `(a, b)` for "a − b".
pub fn pairs(runs: &[Analysed]) -> Vec<(usize, usize)> {
    let find = |kind: &str, d: f64, wall: &str, model: &str| find_run(runs, kind, d, wall, model);
    let mut out = Vec::new();
    let mut push = |a: Option<usize>, b: Option<usize>| {
        if let (Some(a), Some(b)) = (a, b) {
            if !out.contains(&(a, b)) {
                out.push((a, b));
            }
        }
    };
    for a in runs {
        let i = &a.run.info;
        let d = i.diameter_um;
        if i.kind != "main" {
            // the finer mesh, the later window: against the study's run of the same wall
            push(
                find(&i.kind, d, &i.wall, &i.model),
                find("main", d, &i.wall, &i.model),
            );
            continue;
        }
        let m = i.model.as_str();
        let smooth = find("main", d, "smooth", "paper");
        // The technically smooth walls (`ts<Δγ>`, paper's model) of this diameter.
        let technically_smooth: Vec<usize> = runs
            .iter()
            .enumerate()
            .filter(|(_, b)| {
                let j = &b.run.info;
                j.kind == "main" && j.diameter_um == d && j.technically_smooth()
            })
            .map(|(k, _)| k)
            .collect();
        match i.wall.as_str() {
            "axial" | "circ" => {
                push(find("main", d, &i.wall, m), find("main", d, "iso", m));
                push(find("main", d, &i.wall, m), smooth);
            }
            "iso" => push(find("main", d, "iso", m), smooth),
            w if super::read::is_technically_smooth(w) => push(find("main", d, w, m), smooth),
            _ => {}
        }
        if m == "paper" && matches!(i.wall.as_str(), "iso" | "axial" | "circ") {
            for &t in &technically_smooth {
                push(find("main", d, &i.wall, m), Some(t));
            }
        }
        if i.wall == "circ" {
            push(find("main", d, "circ", m), find("main", d, "axial", m));
        }
        if i.wall == "iso" && m != "paper" {
            push(find("main", d, "iso", m), find("main", d, "iso", "paper"));
        }
    }
    out
}

/// `comparisons.csv`: for each pair, every whole-run quantity of both runs, their
/// difference with its paired jackknife standard error and z, and their ratio a/b with its
/// paired jackknife standard error.
pub fn comparisons(runs: &[Analysed]) -> CsvTable {
    let mut t = CsvTable::new(&[
        "diameter_um",
        "a",
        "b",
        "quantity",
        "value_a",
        "se_a",
        "value_b",
        "se_b",
        "difference",
        "se",
        "z",
        "ratio",
        "ratio_se",
    ]);
    for (ia, ib) in pairs(runs) {
        let (a, b) = (&runs[ia], &runs[ib]);
        let qa = quantities(&[a]);
        let qb = quantities(&[b]);
        let qd = quantities(&[a, b]);
        let qr = ratios(a, b);
        for (((name, ea), ((_, eb), (_, ed))), er) in
            qa.iter().zip(qb.iter().zip(qd.iter())).zip(qr.iter())
        {
            t.push(vec![
                fmt_num(a.run.info.diameter_um),
                a.run.info.name.clone(),
                b.run.info.name.clone(),
                name.to_string(),
                fmt_num(ea.value),
                fmt_num(ea.se),
                fmt_num(eb.value),
                fmt_num(eb.se),
                fmt_num(ed.value),
                fmt_num(ed.se),
                fmt_num(ed.z()),
                fmt_num(er.value),
                fmt_num(er.se),
            ]);
        }
    }
    t
}

/// The kinds of run that are not sensitivity switches: the study itself and its checks.
const NOT_SWITCHES: [&str; 3] = ["main", "mesh", "development"];

/// The quantities whose lay ratio (circumferential over axial) `sensitivity.csv` follows.
pub const SENSITIVE: [&str; 5] = [
    "collisions_per_m",
    "rms_ur_m_s",
    "erosion_finnie_um_per_t",
    "erosion_oka_um_per_t",
    "erosion_dnv_um_per_t",
];

/// `sensitivity.csv`: for each physics switch (a run `kind` other than `main`, `mesh` and
/// `development`, run for both the axial and the circumferential lay), each quantity of
/// [`SENSITIVE`]: the lay ratio circumferential/axial in the study and with the switch, and
/// the switch's change of it, with paired jackknife standard errors (the four runs share
/// their particles, batch by batch).
pub fn sensitivity(runs: &[Analysed]) -> CsvTable {
    let mut t = CsvTable::new(&[
        "diameter_um",
        "switch",
        "model",
        "quantity",
        "ratio_study",
        "ratio_study_se",
        "ratio_switch",
        "ratio_switch_se",
        "change",
        "change_se",
        "z",
    ]);
    let find = |kind: &str, d: f64, wall: &str, model: &str| {
        find_run(runs, kind, d, wall, model).map(|k| &runs[k])
    };
    let mut done: Vec<(String, u64, String)> = Vec::new();
    for a in runs {
        let i = &a.run.info;
        let key = (i.kind.clone(), i.diameter_um.to_bits(), i.model.clone());
        if NOT_SWITCHES.contains(&i.kind.as_str()) || done.contains(&key) {
            continue;
        }
        done.push(key);
        let (d, m) = (i.diameter_um, i.model.as_str());
        let (Some(sc), Some(sa), Some(mc), Some(ma)) = (
            find(&i.kind, d, "circ", m),
            find(&i.kind, d, "axial", m),
            find("main", d, "circ", m),
            find("main", d, "axial", m),
        ) else {
            continue;
        };
        let l = sc.sums.layout;
        let r = 0.5 * sc.run.params.pipe_diameter_m;
        let sums = [&mc.sums, &ma.sums, &sc.sums, &sa.sums];
        for q in QUANTITIES.iter().filter(|q| SENSITIVE.contains(&q.name)) {
            let f = q.f;
            let ratio = |s: &[&[f64]], k: usize| f(&l, s[k], r) / f(&l, s[k + 1], r);
            let study = estimate(&sums, |s| ratio(s, 0));
            let switched = estimate(&sums, |s| ratio(s, 2));
            let change = estimate(&sums, |s| ratio(s, 2) - ratio(s, 0));
            t.push(vec![
                fmt_num(d),
                i.kind.clone(),
                m.to_string(),
                q.name.to_string(),
                fmt_num(study.value),
                fmt_num(study.se),
                fmt_num(switched.value),
                fmt_num(switched.se),
                fmt_num(change.value),
                fmt_num(change.se),
                fmt_num(change.z()),
            ]);
        }
    }
    t
}

/// `costs.csv`: per run that timed its carrier-flow forces (`forces_cost.csv`), what the
/// lifts and the spin (relaxation and the exchange between ranks) cost per particle step,
/// against the whole step's cost per particle step (tracking, wall hits, dispersion and
/// the forces; CPU time summed over ranks), and their share of it.
pub fn costs(runs: &[Analysed]) -> CsvTable {
    let mut t = with_id_columns(&[
        "particle_steps",
        "lift_ns_per_particle_step",
        "spin_ns_per_particle_step",
        "step_ns_per_particle_step",
        "forces_share",
    ]);
    for a in runs {
        let Some(c) = a.run.cost else {
            continue;
        };
        let per = |s: f64| 1e9 * s / c.particle_steps;
        let spin = c.spin_relax_s + c.spin_exchange_s;
        let share = if c.step_s > 0.0 {
            fmt_num((c.lift_s + spin) / c.step_s)
        } else {
            String::new()
        };
        let mut row = id_cells(a);
        row.extend([
            fmt_num(c.particle_steps),
            fmt_num(per(c.lift_s)),
            fmt_num(per(spin)),
            fmt_num(per(c.step_s)),
            share,
        ]);
        t.push(row);
    }
    t
}
