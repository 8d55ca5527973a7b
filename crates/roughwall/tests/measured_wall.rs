//! The measured-wall model (issue 39, part 4): its table against the deterministic reference
//! it was measured on, at incident directions between the table's grid points; a wall that is
//! not its own mirror image; the table's text, read back bit for bit and refused when edited.

use crate::common::deterministic::{mean_se, std, UNIT};
use crate::common::{ks, ks_critical};
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use roughwall::angles::incident_angles;
use roughwall::deterministic::{history, Fate, ModelSetup};
use roughwall::measured_wall::{build_table, BuildOptions, MeasuredWallTable, MAGIC};
use roughwall::measured_wall::{
    CellLaw, QuantileFunction, ALPHA_ROWS_DEG, BETA_COLUMNS, RANK_BINS, XI_KNOTS, ZETA_KNOTS,
};
use roughwall::models::{rebound_with, AnyModel, MeasuredWall};
use roughwall::stochastic::Contact;
use roughwall::surface::{generate, measured_deviations, SurfaceSpec};
use roughwall::{CollisionLaw, Deviations, HeightField, IncidentCondition, Tracker, Triangulation};

fn setup(wall: Deviations) -> ModelSetup {
    ModelSetup {
        law: CollisionLaw::Elastic,
        diameter_m: 0.0,
        speed: UNIT,
        wall,
        psi: 2.0,
        erosion: None,
        spin: Default::default(),
    }
}

/// `α⁺` (degrees) of `n` deterministic histories at `(α⁻, β⁻)` (degrees).
fn reference(t: &Tracker, wall: Deviations, a: f64, b: f64, n: u64) -> Vec<f64> {
    let cond = IncidentCondition::from_degrees(a, b);
    (0..n)
        .filter_map(|i| {
            let h = history(t, &setup(wall), &cond, 0, i, 99);
            (h.fate == Fate::Escaped).then(|| incident_angles(&h.velocity).0.to_degrees())
        })
        .collect()
}

/// `α⁺` (degrees) of `n` rebounds of `model` at `(α⁻, β⁻)` (degrees).
fn model_rebounds(model: &AnyModel, wall: Deviations, a: f64, b: f64, n: u64) -> Vec<f64> {
    let cond = IncidentCondition::from_degrees(a, b);
    let law = CollisionLaw::Elastic;
    let contact = Contact {
        wall: &wall,
        law: &law,
        psi: 2.0,
        diameter_m: 0.0,
    };
    (0..n)
        .map(|i| {
            let mut r = roughwall::rng::stream(5, &[3, i]);
            let u = UNIT.velocity(cond.alpha_in, cond.beta_in, 1.0);
            let out = rebound_with(model, u, Vector3::zeros(), &contact, &mut r);
            // Ideally elastic: the speed is kept.
            assert!((out.velocity.norm() - u.norm()).abs() < 1e-12);
            incident_angles(&out.velocity).0.to_degrees()
        })
        .collect()
}

fn gaussian() -> HeightField {
    generate(
        &SurfaceSpec {
            length_m: 256e-6,
            nodes: 256,
            rms_height_m: 0.37e-6,
            corr_length_x_m: Some(12e-6),
            corr_length_z_m: Some(4e-6),
        },
        3,
    )
}

fn table_of(t: &Tracker, wall: Deviations, n: u64) -> &'static MeasuredWallTable {
    let opts = BuildOptions {
        histories_per_cell: n,
        seed: 7,
    };
    build_table(t, wall, "test wall", &opts, &|_| {})
        .unwrap()
        .intern()
        .unwrap()
}

#[test]
fn between_its_grid_points_the_model_is_the_reference() {
    let field = gaussian();
    let t = Tracker::new(&field, 1000).unwrap();
    let wall = measured_deviations(&field);
    let model = AnyModel::MeasuredWall(MeasuredWall {
        table: table_of(&t, wall, 4181),
    });
    // Between rows and columns (never a grid point), grazing to steep, across the circle.
    for (a, b) in [(-6.25, 52.5), (-13.0, 97.5), (-31.0, -37.5), (-3.25, 172.5)] {
        let det = reference(&t, wall, a, b, 40_000);
        let mw = model_rebounds(&model, wall, a, b, 40_000);
        let paper = model_rebounds(&AnyModel::PAPER, wall, a, b, 40_000);
        let (k, k_paper) = (ks(&det, &mw), ks(&det, &paper));
        let ((m_det, se), (m_mw, _)) = (mean_se(&det), mean_se(&mw));
        // The table (4181 histories a cell) adds its own noise to the two samples': within
        // twice the KS distance two samples of these sizes exceed one time in a thousand, and
        // mean α⁺ within 0.15°.
        assert!(
            k < 2.0 * ks_critical(det.len(), mw.len()),
            "({a}, {b}): KS {k} (paper {k_paper})"
        );
        assert!(
            (m_mw - m_det).abs() < 0.15 + 4.0 * se,
            "({a}, {b}): {m_mw} vs {m_det}"
        );
    }
}

/// A ratchet wall: along `x`, ramps rising at 5° for 14 nodes and falling at 31° over 2,
/// with small random heights across; not its own mirror image under `x → −x`.
fn ratchet() -> HeightField {
    let (nx, nz, dx) = (256usize, 64usize, 1e-6);
    let rise = dx * 5f64.to_radians().tan();
    let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(1);
    let heights = (0..nx * nz)
        .map(|k| {
            let i = k % nx;
            let p = i % 16;
            let ramp = if p < 14 {
                p as f64
            } else {
                14.0 - 7.0 * (p - 13) as f64
            } * rise;
            ramp + 0.02e-6 * rng.gen::<f64>()
        })
        .collect();
    HeightField {
        nx,
        nz,
        dx,
        dz: dx,
        heights,
        triangulation: Triangulation::Alternating,
    }
}

#[test]
fn a_wall_that_is_not_its_own_mirror_image_keeps_its_direction_dependence() {
    const N_TABLE: u64 = 4096;
    let field = ratchet();
    let t = Tracker::new(&field, 1000).unwrap();
    let wall = measured_deviations(&field);
    let model = AnyModel::MeasuredWall(MeasuredWall {
        table: table_of(&t, wall, N_TABLE),
    });
    let mut means = Vec::new();
    for b in [0.0, 180.0] {
        let det = reference(&t, wall, -12.0, b, 20_000);
        let mw = model_rebounds(&model, wall, -12.0, b, 20_000);
        let paper = model_rebounds(&AnyModel::PAPER, wall, -12.0, b, 20_000);
        let ((d, se), m, p) = (mean_se(&det), mean_se(&mw).0, mean_se(&paper).0);
        // The law is a few facet families, far apart: the table's own noise on the mean is
        // the spread over √N_TABLE.
        let tol = 4.0 * (se * se + std(&det).powi(2) / N_TABLE as f64).sqrt();
        assert!(
            (m - d).abs() < tol,
            "β⁻ = {b}: model {m} vs reference {d} (± {tol})"
        );
        means.push((d, m, p, tol));
    }
    let ((d0, m0, p0, t0), (d1, m1, p1, t1)) = (means[0], means[1]);
    // Up the ramps and down them differ by degrees; the model carries it, the paper's model
    // (a function of the deviations alone, mirror symmetric) cannot.
    assert!((d0 - d1).abs() > 2.0, "{d0} vs {d1}");
    assert!(
        ((m0 - m1) - (d0 - d1)).abs() < t0 + t1,
        "{m0} − {m1} vs {d0} − {d1}"
    );
    assert!((p0 - p1).abs() < 0.3, "the paper's model: {p0} vs {p1}");
}

/// Values before a cell line's knots.
const LEADING: usize = 7;

/// `law` with its fixed knots alone (what a v3 table holds).
fn without_added_knots(law: &CellLaw) -> CellLaw {
    let fixed = |q: &QuantileFunction| QuantileFunction::fixed(q.knots.clone());
    CellLaw {
        xi: fixed(&law.xi),
        zeta: law.zeta.iter().map(fixed).collect(),
        atoms: Default::default(),
        ..law.clone()
    }
}

/// A v5 table's text (of a table without added knots or joint atoms) as v3 wrote it: its magic
/// line and cell header, and its cell lines without the counts of added knots and atoms.
fn as_v3(text: &str) -> String {
    let fields = LEADING + XI_KNOTS + RANK_BINS * ZETA_KNOTS;
    let mut cells = false;
    let mut out: Vec<String> = Vec::new();
    for l in text.lines() {
        if cells {
            let f: Vec<&str> = l.split(',').collect();
            assert!(f[fields..].iter().all(|c| *c == "0"), "added knots in {l}");
            out.push(f[..fields].join(","));
        } else if l.starts_with("row,") {
            out.push(
                l.trim_end_matches(",atoms,(xi_0.1urad,zeta_0.1urad,histories)...")
                    .trim_end_matches(",(added,t_1e-9,knot_0.1urad...)x33")
                    .to_string(),
            );
            cells = true;
        } else {
            out.push(l.replacen("table v5", "table v3", 1));
        }
    }
    out.join("\n") + "\n"
}

#[test]
fn the_table_reads_back_bit_for_bit_and_an_edited_one_is_refused() {
    let field = gaussian();
    let t = Tracker::new(&field, 1000).unwrap();
    let wall = measured_deviations(&field);
    let opts = BuildOptions {
        histories_per_cell: 1024,
        seed: 9,
    };
    let table = build_table(&t, wall, "test wall", &opts, &|_| {}).unwrap();
    // The same table for one thread and for all.
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| build_table(&t, wall, "test wall", &opts, &|_| {}).unwrap());
    assert!(one == table);
    let text = table.to_text();
    assert!(text.starts_with(MAGIC));
    let back = MeasuredWallTable::parse(&text, "t").unwrap();
    assert!(back == table);
    assert_eq!(back.to_text(), text);
    let err = |t: &str| {
        let e = MeasuredWallTable::parse(t, "`stochastic.wall_table` = \"w\"")
            .unwrap_err()
            .to_string();
        assert!(!e.contains('\n'), "{e}");
        e
    };
    let lines: Vec<&str> = text.lines().collect();
    // A knot that makes a quantile function decrease.
    let header = lines.iter().position(|l| l.starts_with("row,")).unwrap();
    let mut cell: Vec<String> = lines[header + 5].split(',').map(String::from).collect();
    // Knot 3 of `ξ'` one unit above knot 4.
    let next: i64 = cell[11].parse().unwrap();
    cell[10] = (next + 1).to_string();
    let mut edited: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    edited[header + 5] = cell.join(",");
    let e = err(&edited.join("\n"));
    assert!(
        e.contains(&format!("line {}", header + 6)) && e.contains("decreases"),
        "{e}"
    );
    // Truncated, another version, another grid, an edited `first_row`, not a table at all.
    assert!(err(&lines[..header + 3].join("\n")).contains("truncated after 2 of"));
    assert!(err(&text.replacen("table v5", "table v1", 1)).contains("another format"));
    // The rows: the base rows must all be there, increasing, and at most 12 more.
    let rows_line = lines
        .iter()
        .find(|l| l.starts_with("alpha_rows_deg = "))
        .unwrap();
    for edit in [
        rows_line.replacen(",90", "", 1),
        rows_line.replacen("1,1.5", "1.5,1", 1),
        // 13 rows of its own, increasing, between 24 and 26°: one too many.
        rows_line.replacen(
            ",24,",
            &format!(
                ",24,{},",
                (1..=13)
                    .map(|i| format!("24.{i:02}"))
                    .collect::<Vec<_>>()
                    .join(",")
            ),
            1,
        ),
        rows_line.replacen("= 1,", "= 0.5,1,", 1),
    ] {
        let e = err(&text.replacen(rows_line, &edit, 1));
        assert!(e.contains("allowed the base rows"), "{e}");
    }
    // A v2 table (the base rows alone, as v2 wrote them, and no added knots) is read as it was
    // written; a v2 table with rows of its own is not one.
    let base_only = MeasuredWallTable {
        alpha_rows_deg: ALPHA_ROWS_DEG.to_vec(),
        cells: table
            .cells
            .chunks(BETA_COLUMNS)
            .zip(&table.alpha_rows_deg)
            .filter(|(_, a)| ALPHA_ROWS_DEG.contains(a))
            .flat_map(|(c, _)| c.iter().map(without_added_knots))
            .collect(),
        ..table.clone()
    };
    let v2 = as_v3(&base_only.to_text()).replacen("table v3", "table v2", 1);
    assert!(MeasuredWallTable::parse(&v2, "t").unwrap() == base_only);
    // The same with a row of its own at 39° (a copy of the 38° row's cells): v3 reads it
    // back, v2 does not.
    let r38 = ALPHA_ROWS_DEG.iter().position(|&a| a == 38.0).unwrap();
    let mut cells = base_only.cells.clone();
    let copy = cells[r38 * BETA_COLUMNS..(r38 + 1) * BETA_COLUMNS].to_vec();
    cells.splice((r38 + 1) * BETA_COLUMNS..(r38 + 1) * BETA_COLUMNS, copy);
    let mut rows = ALPHA_ROWS_DEG.to_vec();
    rows.insert(r38 + 1, 39.0);
    let refined = MeasuredWallTable {
        alpha_rows_deg: rows,
        cells,
        ..base_only.clone()
    };
    assert_eq!(refined.refined_rows_deg(), vec![39.0]);
    let refined_text = as_v3(&refined.to_text());
    assert!(MeasuredWallTable::parse(&refined_text, "t").unwrap() == refined);
    let v2_refined = refined_text.replacen("table v3", "table v2", 1);
    assert!(err(&v2_refined).contains("a v2 table has the base rows"));
    // Added knots: read back; refused out of order or beyond their budget.
    assert!(MeasuredWallTable::parse(&refined.to_text(), "t").unwrap() == refined);
    let fields = LEADING + XI_KNOTS + RANK_BINS * ZETA_KNOTS;
    let header = lines.iter().position(|l| l.starts_with("row,")).unwrap();
    let first_cell = lines[header + 1];
    let prefix: Vec<&str> = first_cell.split(',').take(fields).collect();
    let prefix = prefix.join(",");
    let zeros = ",0".repeat(RANK_BINS);
    let with = |xi: &str| text.replacen(first_cell, &format!("{prefix},{xi}{zeros},0"), 1);
    // Just after the middle fixed knot (t = 0.5), at its value.
    let middle = prefix.split(',').nth(LEADING + 64).unwrap();
    let ok = with(&format!("1,501000000,{middle}"));
    let back = MeasuredWallTable::parse(&ok, "t").unwrap();
    assert_eq!(
        back.cells[0].xi.added(),
        &[(0.501, back.cells[0].xi.knots[64])]
    );
    let e = err(&with(&format!("1,500000000,{middle}")));
    assert!(e.contains("not strictly between"), "{e}");
    let e = err(&with(&format!("1,2000000000,{middle}")));
    assert!(e.contains("not strictly between"), "{e}");
    // One count short: too few fields; one short after an added knot: truncated.
    let e = err(&text.replacen(first_cell, &format!("{prefix}{zeros}"), 1));
    assert!(e.contains("expected at least"), "{e}");
    let short = format!(
        "{prefix},1,501000000,{middle}{}",
        ",0".repeat(RANK_BINS - 1)
    );
    let e = err(&text.replacen(first_cell, &short, 1));
    assert!(e.contains("truncated added knots"), "{e}");
    let e = err(&with("999,1,1"));
    assert!(e.contains("added knots: allowed 0 to 64"), "{e}");
    // A bin of ζ' holds at most its own budget (8), fewer than ξ' (64).
    let zeta_nine = format!("{prefix},0,9{}", ",0".repeat(RANK_BINS - 1));
    let e = err(&text.replacen(first_cell, &zeta_nine, 1));
    assert!(e.contains("`9` added knots: allowed 0 to 8"), "{e}");
    // Joint atoms: read back with their shares; refused out of order, beyond the cell's
    // escaped histories or truncated; a v4 table (none) is read as it was written.
    let atoms = |list: &str| text.replacen(first_cell, &format!("{prefix},0{zeros},{list}"), 1);
    let back = MeasuredWallTable::parse(&atoms("2,-5,7,100,3,0,24"), "t").unwrap();
    let a = &back.cells[0].atoms;
    let escaped = a.histories() as f64 / a.share();
    assert_eq!(
        a.units().collect::<Vec<_>>(),
        vec![(-5, 7, 100), (3, 0, 24)]
    );
    assert_eq!(
        escaped.round(),
        (table.cells[0].histories - table.cells[0].left_patch - table.cells[0].lost_other) as f64
    );
    assert_eq!(a.pick(0.0), (-5e-7, 7e-7));
    assert!(MeasuredWallTable::parse(&back.to_text(), "t").unwrap() == back);
    let e = err(&atoms("2,3,0,24,-5,7,100"));
    assert!(e.contains("joint atoms out of order"), "{e}");
    let e = err(&atoms("1,0,0,99999"));
    assert!(e.contains("more than the cell's"), "{e}");
    let e = err(&atoms("2,-5,7,100"));
    assert!(e.contains("truncated joint atoms"), "{e}");
    let e = err(&atoms("999"));
    assert!(e.contains("joint atoms: allowed 0 to 320"), "{e}");
    let v4: String = text
        .lines()
        .map(|l| match l {
            l if l.starts_with('#') => l.replacen("table v5", "table v4", 1),
            l if l.starts_with("row,") => l
                .trim_end_matches(",atoms,(xi_0.1urad,zeta_0.1urad,histories)...")
                .to_string(),
            l if l.contains(',') && !l.contains(" = ") => l.strip_suffix(",0").unwrap().to_string(),
            l => l.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n");
    assert!(table.cells.iter().all(|c| c.atoms.is_empty()));
    assert!(MeasuredWallTable::parse(&v4, "t").unwrap() == table);
    let grid = text.replacen("beta_columns = 24", "beta_columns = 12", 1);
    assert!(err(&grid).contains("this version's grid"));
    let first = text.replacen("first_row = 0", "first_row = 3", 1);
    assert!(err(&first).contains("does not match"));
    assert!(err("alpha,beta\n").contains("not a measured-wall table"));
}
