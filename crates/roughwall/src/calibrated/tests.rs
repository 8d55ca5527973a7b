//! Tests of the calibrated model's grid, counts, table and file, and of the model's draws.

use super::constants::*;
use super::counts::EscapeCounts;
use super::grid::*;
use super::model::CalibratedIncidence;
use super::slope_space::reduced_slope;
use super::table::*;
use super::table_file::*;
use crate::collision::CollisionLaw;
use crate::stochastic::{Contact, Rebound};
use crate::wall::Deviations;
use nalgebra::Vector3;
use rand::SeedableRng;

/// The calibrated model's rebound of a particle of velocity `u` moving towards the rough
/// `wall` (no spin, D = 0.1 mm), with `table` (`None`: the built-in one).
fn calibrated_rebound(
    table: Option<&'static EscapeTable>,
    u: Vector3<f64>,
    wall: &Deviations,
    law: &CollisionLaw,
    rng: &mut rand_xoshiro::Xoshiro256PlusPlus,
) -> Rebound {
    let contact = Contact {
        wall,
        law,
        psi: 2.0,
        diameter_m: 1e-4,
    };
    let (alpha, beta) = crate::angles::incident_angles(&u);
    let inc = CalibratedIncidence::new(alpha, beta, wall);
    let table = table.unwrap_or_else(EscapeTable::builtin);
    super::model::rebound(
        &inc,
        table,
        u,
        Vector3::zeros(),
        &contact,
        rng,
        |_, _, _| {},
    )
}

fn wall() -> Deviations {
    Deviations {
        delta_xi: 0.05,
        delta_zeta: 0.12,
    }
}

#[test]
fn the_builtin_table_parses_and_is_a_probability() {
    let t = EscapeTable::builtin();
    assert!(t.counts().total() > 1_000_000);
    for stage in Stage::all() {
        for x_in in [-7.0, -3.3, -0.1, 0.0, 0.4, 2.0, 9.0] {
            let mut last = 0.0;
            for k in 0..=90 {
                let x_out = k as f64 * 0.05;
                let p = t.p_escape(stage, x_in, x_out);
                assert!((0.0..=1.0).contains(&p), "{p}");
                // (The later stage is sparse and noisier: range only.)
                if stage.is_first() && k > 0 && x_out < 3.0 {
                    // Steeper rebounds escape more often (up to the counting noise).
                    assert!(
                        p > last - 0.08,
                        "{stage:?} {x_in} {x_out}: {p} after {last}"
                    );
                }
                last = p;
            }
        }
    }
    assert_eq!(t.p_escape(Stage::FIRST, -1.0, 0.0), 0.0);
    assert_eq!(t.p_escape(Stage::FIRST, -1.0, -0.3), 0.0);
    assert_eq!(t.p_escape(Stage::FIRST, -1.0, 4.0), 1.0);
    assert!(t.p_escape(Stage::FIRST, f64::NAN, 1.0).is_finite());
}

#[test]
fn counts_round_trip_through_the_file_exactly() {
    let mut c = EscapeCounts::default();
    let w = wall();
    let u_in = Vector3::new(1.0, -0.1, 0.3);
    for k in 0..2000 {
        let a = 0.001 + 0.0004 * k as f64;
        let u_out = Vector3::new(a.cos(), a.sin(), 0.1);
        let stage = if k % 3 == 0 {
            Stage::later(-2.0 + 0.001 * k as f64)
        } else {
            Stage::FIRST
        };
        c.push(stage, &u_in, &u_out, &w, k % 5 != 0);
        let g = -1.0 + 0.004 * k as f64;
        c.push_element(stage, -1.2, g, g + 0.3);
        let z = (k as f64 * 0.01).sin();
        c.push_transverse(stage, z, 0.3 * z);
        c.push_transverse(Stage::later(-1.0), z, 0.3 * z);
    }
    assert_eq!(c.transverse.pairs.iter().sum::<u64>(), 2667);
    let t = EscapeTable::from_counts(c.clone(), "test");
    assert!(t.transverse_slope(Stage::later(-1.0)) > 0.29);
    assert_eq!(t.transverse_slope(Stage::FIRST), 0.0);
    assert_eq!(t.transverse_residual(Stage::FIRST, 2.0, 0.5), 0.5);
    let back = EscapeTable::parse(&t.to_csv(), "t").unwrap();
    assert_eq!(back, t);
    assert_eq!(back.counts(), &c);
    assert_eq!(back.to_csv(), t.to_csv());
}

#[test]
fn bilinear_reading_hits_the_cell_centres() {
    let mut c = EscapeCounts::default();
    // One populated cell column: x_in bin 10, every x_out bin, p = i_out/40.
    for i_out in 0..X_OUT_BINS {
        let k = cell(Stage::FIRST, 10, i_out);
        c.collisions[k] = 400;
        c.escaped[k] = 10 * i_out as u64;
    }
    let t = EscapeTable::from_counts(c.at_centres(), "t");
    let x_in = centre_in(10);
    for i_out in 0..X_OUT_BINS {
        let x_out = (i_out as f64 + 0.5) * DX_OUT;
        let p = t.p_escape(Stage::FIRST, x_in, x_out);
        assert!((p - i_out as f64 / 40.0).abs() < 1e-12);
    }
    // Half way between two centres: the mean; sparse bins take the populated one's value,
    // and the later stages (empty) the first stage's.
    let p = t.p_escape(Stage::later(0.0), -5.9, 1.0);
    assert!((p - 0.5 * (9.0 + 10.0) / 40.0).abs() < 1e-12, "{p}");
    // A later stage without counts of its own takes the later stages' pooled ones.
    let mut c = EscapeCounts::default();
    for i_out in 0..X_OUT_BINS {
        c.collisions[cell(Stage::later(-2.0), 10, i_out)] = 400;
        c.escaped[cell(Stage::later(-2.0), 10, i_out)] = 100;
        c.collisions[cell(Stage::later(1.0), 10, i_out)] = 400;
        c.escaped[cell(Stage::later(1.0), 10, i_out)] = 300;
        c.collisions[cell(Stage::later(-1.0), 10, i_out)] = 20;
    }
    let t = EscapeTable::from_counts(c.at_centres(), "t");
    assert!((t.p_escape(Stage::later(-2.0), x_in, 1.0) - 0.25).abs() < 1e-12);
    assert!((t.p_escape(Stage::later(1.0), x_in, 1.0) - 0.75).abs() < 1e-12);
    let pooled = t.p_escape(Stage::later(-1.0), x_in, 1.0);
    assert!((pooled - 400.0 / 820.0).abs() < 1e-12, "{pooled}");
}

#[test]
fn later_stages_are_binned_by_the_element_just_left() {
    assert_eq!(Stage::later(-1.7), Stage::later(-1.3));
    assert_ne!(Stage::later(-1.3), Stage::later(-1.2));
    assert_ne!(Stage::later(-1.8), Stage::later(-1.7));
    assert_eq!(Stage::later(-9.0), Stage::later(-2.8));
    assert_eq!(Stage::later(f64::NAN), Stage::later(0.0));
    assert_eq!(Stage::later(f64::INFINITY), Stage::later(9.0));
    let names: Vec<String> = Stage::all().map(|s| s.name()).collect();
    assert_eq!(
        names,
        [
            "first-d0", "first-d1", "first-d2", "later-q0", "later-q1", "later-q2", "later-q3",
            "later-q4", "later-q5", "later-q6"
        ]
    );
    assert!(Stage::all()
        .filter(|s| s.is_first())
        .eq([Stage(0), Stage(1), Stage(2)]));
    assert!(!Stage::later(-9.0).is_first());
}

/// The model reads a first collision's stage by its plane's `Δγ`: with a table whose
/// roughest first stage never lets a particle leave after its first collision (but for
/// rebounds beyond `x_out = 4`, which always leave), a wall rougher than that stage's
/// position loses its single collisions, one below the middle position keeps them, and
/// half way between the two upper positions half of them are lost.
#[test]
fn the_model_reads_the_first_stage_of_its_roughness_angle() {
    use crate::collision::CollisionLaw;
    use rand::SeedableRng;
    let deg = f64::to_radians;
    let table = |trap_roughest: bool| -> &'static EscapeTable {
        let mut c = EscapeCounts::default();
        for k in 0..SLICES {
            for i in 0..X_IN_BINS {
                for o in 0..X_OUT_BINS {
                    let j = cell(Stage(k), i, o);
                    c.collisions[j] = 400;
                    c.escaped[j] = if trap_roughest && k == 2 { 0 } else { 400 };
                }
            }
        }
        for d in [3.0, 5.0, 7.0] {
            c.push_first(deg(d));
        }
        EscapeTable::from_counts(c.at_centres(), "stages")
            .intern()
            .unwrap()
    };
    let single = |t: &'static EscapeTable, d: f64| {
        let wall = Deviations {
            delta_xi: deg(d),
            delta_zeta: deg(d),
        };
        // The same reduced incidence on every wall.
        let u = crate::angles::velocity_from_angles(1.0, -0.3 * deg(d), 0.0);
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(4);
        let n = 20_000;
        (0..n)
            .filter(|_| {
                let law = CollisionLaw::Elastic;
                calibrated_rebound(Some(t), u, &wall, &law, &mut rng).candidates == 1
            })
            .count() as f64
            / n as f64
    };
    let (trap, free) = (table(true), table(false));
    // (A first rebound into the mean wall is trapped whatever the table says.)
    assert!(single(free, 8.0) > 0.8, "{}", single(free, 8.0));
    let steep = single(trap, 8.0) / single(free, 8.0);
    assert!(steep < 0.25, "{steep}");
    assert_eq!(single(trap, 4.0), single(free, 4.0));
    // The stage is read at the slope spread along the path (`slope_space`), a little
    // above the angle's: t of the upper stage between the positions 5 and 7.
    let sigma = super::slope_deviations(&Deviations {
        delta_xi: deg(6.0),
        delta_zeta: deg(6.0),
    })
    .delta_xi
    .to_degrees();
    let t = (sigma - 5.0) / 2.0;
    assert!(t > 0.5 && t < 0.6, "{sigma}");
    let half = single(trap, 6.0) / single(free, 6.0);
    assert!(
        (half - ((1.0 - t) + t * steep)).abs() < 0.03,
        "{half} ({steep}, {t})"
    );
}

#[test]
fn first_collisions_are_binned_and_read_by_the_roughness_angle() {
    let deg = f64::to_radians;
    assert_eq!(Stage::first(deg(2.5)), Stage::FIRST);
    assert_eq!(Stage::first(deg(4.49)), Stage::FIRST);
    assert_eq!(Stage::first(deg(4.5)), Stage(1));
    assert_eq!(Stage::first(deg(7.5)), Stage(2));
    assert_eq!(Stage::first(f64::NAN), Stage::FIRST);
    // Three first stages with different escape probabilities in one cell column, their
    // collisions at mean Δγ 3°, 5° and 7°.
    let mut c = EscapeCounts::default();
    for (k, (d, escaped)) in [(3.0, 100), (5.0, 200), (7.0, 300)].into_iter().enumerate() {
        for i_out in 0..X_OUT_BINS {
            c.collisions[cell(Stage(k), 10, i_out)] = 400;
            c.escaped[cell(Stage(k), 10, i_out)] = escaped;
        }
        for _ in 0..4 {
            c.push_first(deg(d));
        }
    }
    let t = EscapeTable::from_counts(c.at_centres(), "t");
    let x_in = centre_in(10);
    // The mixture's escape probability over a uniform grid of draws.
    let n = 10_000;
    let p = |d: f64| {
        (0..n)
            .map(|i| {
                t.p_escape(
                    t.first_stage(deg(d), (i as f64 + 0.5) / n as f64),
                    x_in,
                    1.0,
                )
            })
            .sum::<f64>()
            / n as f64
    };
    // At a stage's position its own value, between two positions the linear blend,
    // beyond the ends the end stage's value.
    for (d, want) in [
        (3.0, 0.25),
        (5.0, 0.5),
        (7.0, 0.75),
        (4.0, 0.375),
        (6.5, 0.6875),
        (1.0, 0.25),
        (9.0, 0.75),
    ] {
        assert!((p(d) - want).abs() < 1e-4, "{d}: {} against {want}", p(d));
    }
    assert!(p(f64::NAN).is_finite());
    // Round trip; a position is kept inside its bin (so positions increase), and one
    // that is not what its sum gives is refused.
    let text = t.to_csv();
    assert_eq!(EscapeTable::parse(&text, "t").unwrap(), t);
    let mut c = EscapeCounts::default();
    c.first_count[0] = 1;
    c.first_dg_sum[0] = 9_000_000;
    c.collisions[0] = 1;
    assert_eq!(
        EscapeTable::from_counts(c, "edge").first_pos[0],
        FIRST_DG_EDGES_DEG[0] - DG_SUM_UNIT
    );
    let bad = text.replace(
        "first-d0,4,12000000,3.000000",
        "first-d0,4,12000000,3.500000",
    );
    assert_ne!(bad, text);
    let err = EscapeTable::parse(&bad, "t").unwrap_err().to_string();
    assert!(
        err.contains("first-stage position") && err.contains("edited or corrupted"),
        "{err}"
    );
}

#[test]
fn malformed_or_mismatched_tables_are_one_line_errors() {
    let good = EscapeTable::builtin().to_csv();
    let lines: Vec<&str> = good.lines().collect();
    let edit = |k: usize, to: &str| {
        let mut l = lines.clone();
        l[k] = to;
        l.join("\n")
    };
    let row = lines[10];
    let fields: Vec<&str> = row.split(',').collect();
    // Row 10 with field `k` replaced.
    let field = |k: usize, v: &str| {
        let mut f = fields.clone();
        f[k] = v;
        edit(10, &f.join(","))
    };
    let cases: Vec<(String, &str)> = vec![
        (String::new(), "not an escape table"),
        (good.replacen("v9", "v8", 1), "another format"),
        (
            good.replacen("# roughwall", "# other", 1),
            "not an escape table",
        ),
        (edit(1, "source"), "# source"),
        (edit(2, "a,b"), "header"),
        (lines[..100].join("\n"), "truncated after 97"),
        (edit(10, "first,1,2"), "3 fields"),
        (field(0, "later-q0"), "does not match this version's grid"),
        (field(1, "-0.3125"), "does not match this version's grid"),
        (field(2, "9.999"), "does not match"),
        (field(3, "x"), "`x` is not a non-negative integer"),
        (
            edit(10, &format!("{},1,2,0.5", fields[..3].join(","))),
            "2 escapes out of 1",
        ),
        (field(5, "1.5"), "not in [0, 1]"),
        (field(5, "nan"), "`nan` is not a number"),
        (
            format!("{good}first,0,0,0,0,0\n"),
            "more rows than the grid",
        ),
    ];
    // Line `row` with field `k` replaced.
    let field_of = |row: usize, k: usize, v: &str| {
        let mut f: Vec<&str> = lines[row].split(',').collect();
        f[k] = v;
        edit(row, &f.join(","))
    };
    // The rows' block: its first row with field `k` replaced.
    let first_row = lines.iter().position(|l| *l == ROW_HEADER).unwrap() + 1;
    let row_field = |k: usize, v: &str| field_of(first_row, k, v);
    let truncated = format!("truncated after 3 of {ROWS} x_in rows");
    let cases: Vec<(String, &str)> = cases
        .into_iter()
        .chain([
            (edit(first_row, "first,1"), "2 fields"),
            (row_field(2, "1.5"), "`1.5` is not an integer"),
            (row_field(3, "x"), "`x` is not a number"),
            (
                row_field(1, "-5.2500"),
                "does not match this version's grid",
            ),
            (lines[..first_row + 3].join("\n"), &truncated),
        ])
        .collect();
    // The transverse block: its first row with field `k` replaced.
    let t_row = lines.iter().position(|l| *l == TRANSVERSE_HEADER).unwrap() + 1;
    let t_field = |k: usize, v: &str| field_of(t_row, k, v);
    let t_truncated = format!("truncated after 2 of {LATER_STAGES} transverse rows");
    let cases: Vec<(String, &str)> = cases
        .into_iter()
        .chain([
            (
                edit(t_row, "later-q0,1,2,3,4"),
                "expected the transverse row",
            ),
            (t_field(0, "later-q1"), "expected the transverse row"),
            (t_field(1, "-1"), "not a non-negative integer"),
            (t_field(2, "-5"), "cannot come from"),
            (t_field(1, "0"), "cannot come from"),
            (t_field(4, "0.123457"), "transverse slope row 1 gives"),
            (t_field(5, "0.123457"), "transverse fresh row 1 gives"),
            // More pairs for the same sums: the slope is the same, the fresh part not.
            (t_field(1, "98789"), "transverse fresh row 1 gives"),
            (lines[..t_row + 2].join("\n"), &t_truncated),
            (
                lines[..t_row - 1].join("\n"),
                "after the 3 first-stage rows",
            ),
        ])
        .collect();
    for (text, needle) in cases {
        let e = match EscapeTable::parse(&text, "`stochastic.escape_table` = \"t.csv\"") {
            Ok(_) => panic!("accepted a bad table (wanted {needle})"),
            Err(e) => e.to_string(),
        };
        assert!(e.contains(needle), "{e} (wanted {needle})");
        assert!(e.contains("t.csv"), "{e}");
        assert!(!e.contains('\n'), "{e}");
    }
    // A probability that disagrees with its counts (hand-edited): refused.
    let k = (3..3 + CELLS)
        .find(|&k| {
            let f: Vec<&str> = lines[k].split(',').collect();
            f[3].parse::<u64>().unwrap() >= MIN_COUNT && f[5] != "0.999999"
        })
        .unwrap();
    let f: Vec<&str> = lines[k].split(',').collect();
    let e = EscapeTable::parse(&edit(k, &format!("{},0.999999", f[..5].join(","))), "t");
    match e {
        Ok(_) => panic!("accepted an edited table"),
        Err(e) => assert!(e.to_string().contains("edited or corrupted"), "{e}"),
    }
}

#[test]
fn element_weights_are_the_count_ratio_and_bounded() {
    let mut c = EscapeCounts::default();
    // Row x_in ∈ [−1.5, −1.25), centre −1.375: the deterministic run saw twice the shadow
    // law's count above s = γ/Δγ − x_in = 1.375 (g = 0 at the centre) and the same below.
    for k in 0..200 {
        let s = 0.02 * k as f64 + 0.01;
        let n = if s > 1.375 {
            2 * ELEMENT_MIN_COUNT
        } else {
            ELEMENT_MIN_COUNT
        };
        let cell = element_cell(Stage::FIRST, -1.375, s - 1.375).unwrap();
        c.element_deterministic[cell] = n;
        c.element_model[cell] = ELEMENT_MIN_COUNT;
    }
    // Out of reach (s < 0) and beyond the range: no cell.
    assert_eq!(element_cell(Stage::FIRST, -1.375, -1.45), None);
    assert_eq!(element_cell(Stage::FIRST, -1.375, 9.0), None);
    let t = EscapeTable::from_counts(c.at_centres(), "w");
    assert!((t.element_weight(Stage::FIRST, -1.375, 1.05) - 2.0).abs() < 1e-12);
    assert!((t.element_weight(Stage::FIRST, -1.375, -0.5) - 1.0).abs() < 1e-12);
    // Empty cells and the other stages keep the shadow law; outside the range too.
    assert_eq!(t.element_weight(Stage::later(0.0), -1.375, 1.05), 1.0);
    assert_eq!(t.element_weight(Stage::FIRST, -1.375, 9.0), 1.0);
    assert!(t.element_bound(Stage::FIRST, -1.375) >= 2.0);
    for k in 0..400 {
        let (x, g) = (-3.0 + 0.01 * k as f64, -4.0 + 0.025 * k as f64);
        assert!(t.element_weight(Stage::FIRST, x, g) <= t.element_bound(Stage::FIRST, x) + 1e-12);
    }
}

/// A sparse cell takes the ratio of the narrowest window around it that holds enough
/// draws, so the shadow law's thin tail keeps the trend of its dense neighbours instead of
/// jumping back to 1; a row with too few draws in all keeps the shadow law.
#[test]
fn sparse_element_cells_take_their_window_ratio() {
    let n = ELEMENT_MIN_COUNT;
    // A dense cell stands alone.
    assert_eq!(window_ratio(&[3 * n, 0, 0], &[2 * n, 0, 0], 0), Some(1.5));
    // The tail: cell 3 has 100 draws; the window 2..=4 (clipped at the row's end: 2..=3
    // and then 1..=3) first holds enough at 1..=3.
    let d = [0, n / 2, n / 4, 30];
    let m = [0, n, n / 2, 100];
    let r = window_ratio(&d, &m, 3).unwrap();
    let want = (n / 2 + n / 4 + 30) as f64 / (n + n / 2 + 100) as f64;
    assert_eq!(r, want);
    assert!(r < 0.6, "{r}");
    // Too few in the whole row: the shadow law.
    assert_eq!(window_ratio(&[5, 5, 5], &[10, 10, 10], 1), None);
    // Through the table: a thin tail beyond s = 4 keeps the dense cells' ratio 0.5.
    let mut c = EscapeCounts::default();
    for k in 0..125 {
        let s = (k as f64 + 0.5) * DG;
        let cell = element_cell(Stage::FIRST, -1.375, s - 1.375).unwrap();
        let m = if s < 4.0 { 4 * n } else { 10 };
        c.element_model[cell] = m;
        c.element_deterministic[cell] = m / 2;
    }
    let t = EscapeTable::from_counts(c.at_centres(), "tail");
    assert!((t.element_weight(Stage::FIRST, -1.375, 6.0 - 1.375) - 0.5).abs() < 1e-3);
}

/// A sparse later-stage cell takes its own stage's ratio from nearby rows before the
/// later stages' pooled one: after a steep downslope the next element is steeper than
/// after a flat one, and pooling the stages would wash that out.
#[test]
fn sparse_later_cells_pool_their_own_stage_first() {
    let n = ELEMENT_MIN_COUNT;
    let cell = |stage: Stage, i: usize, j: usize| (stage.0 * X_IN_BINS + i) * G_BINS + j;
    let (steep, flat) = (Stage::later(-2.5), Stage::later(0.5));
    let (i, j) = (12, 40);
    let mut d = vec![0; ELEMENT_CELLS];
    let mut m = vec![0; ELEMENT_CELLS];
    // The sparse cell, 3 rows away the same stage with ratio 2, and the flat stage dense
    // with ratio 0.5 at the same place.
    m[cell(steep, i, j)] = 10;
    d[cell(steep, i, j)] = 20;
    m[cell(steep, i + 3, j)] = n;
    d[cell(steep, i + 3, j)] = 2 * n;
    m[cell(flat, i, j)] = 100 * n;
    d[cell(flat, i, j)] = 50 * n;
    let w = element_weights(&d, &m);
    let want = (2 * n + 20) as f64 / (n + 10) as f64;
    assert_eq!(w[cell(steep, i, j)], want);
    // Beyond the window along s the same stage has nothing: the pooled stages' ratio.
    let far = j + SAME_STAGE_S_CELLS + 1;
    m[cell(steep, i, far)] = 10;
    d[cell(steep, i, far)] = 10;
    m[cell(flat, i, far)] = 100 * n;
    d[cell(flat, i, far)] = 50 * n;
    let w = element_weights(&d, &m);
    let pooled = (50 * n + 10) as f64 / (100 * n + 10) as f64;
    assert_eq!(w[cell(steep, i, far)], pooled);
    // Rows beyond SAME_STAGE_ROWS do not count.
    assert_eq!(
        same_stage_ratio(&d, &m, cell(steep, i + 3 + SAME_STAGE_ROWS + 1, j)),
        None
    );
}

/// A weight on a six-decimal rounding boundary (16965/16000 = 1.0603125) reads back: the
/// check compares the values as written, not by a tolerance the rounding can exceed.
#[test]
fn a_weight_on_a_rounding_boundary_reads_back() {
    let mut c = EscapeCounts::default();
    let cell = element_cell(Stage::FIRST, -1.375, 1.0).unwrap();
    c.element_deterministic[cell] = 16965;
    c.element_model[cell] = 16000;
    c.collisions[0] = 1;
    let t = EscapeTable::from_counts(c.at_centres(), "boundary");
    let back = EscapeTable::parse(&t.to_csv(), "boundary").unwrap();
    assert_eq!(back.counts(), t.counts());
}

/// A row's values belong at its counts' mean `x_in`, not at the bin's centre: a read
/// there gives the row's value, and between two rows' means the read is linear.
#[test]
fn rows_are_read_at_their_mean_incidence() {
    let w = wall();
    let at = |x_in: f64| {
        // The velocity of reduced slope x_in along x (σ(0) = Δξ of a slope wall).
        let a = (x_in * w.delta_xi).atan();
        Vector3::new(a.cos(), a.sin(), 0.0)
    };
    let mut c = EscapeCounts::default();
    // Bin [−0.375, −0.25): 400 collisions at x_in = −0.35, a quarter escaping; bin
    // [−0.5, −0.375): 400 at −0.45, three quarters escaping; both at x_out = 1.05 (a bin
    // centre).
    let u_out = at(-1.05).component_mul(&Vector3::new(1.0, -1.0, 1.0));
    for k in 0..400 {
        c.push(Stage::FIRST, &at(-0.35), &u_out, &w, k % 4 == 0);
        c.push(Stage::FIRST, &at(-0.45), &u_out, &w, k % 4 != 0);
    }
    let t = EscapeTable::from_counts(c.clone(), "positions");
    let x_out = reduced_slope(&u_out, &w);
    let p = |x: f64| t.p_escape(Stage::FIRST, x, x_out);
    assert!((p(-0.35) - 0.25).abs() < 1e-9, "{}", p(-0.35));
    assert!((p(-0.45) - 0.75).abs() < 1e-9, "{}", p(-0.45));
    assert!((p(-0.4) - 0.5).abs() < 1e-9, "{}", p(-0.4));
    // The bins' centres would have put the values at −0.3125 and −0.4375.
    assert!((p(-0.3125) - 0.25).abs() < 1e-9);
    // The positions travel with the table.
    let back = EscapeTable::parse(&t.to_csv(), "positions").unwrap();
    assert_eq!(back, t);
    // A sum whose mean leaves its bin is refused; so is an edited position.
    let text = t.to_csv();
    let block = text.lines().position(|l| l == ROW_HEADER).unwrap();
    let row = block
        + text
            .lines()
            .skip(block)
            .position(|l| l.starts_with("first-d0,-0.3125,"))
            .unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let f: Vec<&str> = lines[row].split(',').collect();
    let edit = |to: String| {
        let mut l = lines.clone();
        l[row] = &to;
        EscapeTable::parse(&l.join("\n"), "t")
            .unwrap_err()
            .to_string()
    };
    let moved = format!(
        "first-d0,-0.3125,{},-0.150000,{},{}",
        -60_000_000, f[4], f[5]
    );
    let e = edit(moved);
    assert!(e.contains("outside its bin"), "{e}");
    let e = edit(format!(
        "first-d0,-0.3125,{},-0.340000,{},{}",
        f[2], f[4], f[5]
    ));
    assert!(e.contains("escape position") && e.contains("edited"), "{e}");
}

/// The element table's rows are read at the mean `x_in` of their shadow-law draws too,
/// and its rejection bound holds there.
#[test]
fn element_rows_are_read_at_their_mean_incidence() {
    let mut c = EscapeCounts::default();
    for _ in 0..2000 {
        // Row [−0.375, −0.25) at −0.35: the deterministic run saw twice the draws.
        c.push_element(Stage::FIRST, -0.35, 0.1, 0.1);
        c.push_element(Stage::FIRST, -0.35, 0.1, 100.0);
        // Row [−0.5, −0.375) at −0.45: half the draws.
        c.push_element(Stage::FIRST, -0.45, 0.1, 0.1);
        c.push_element(Stage::FIRST, -0.45, 100.0, 0.1);
    }
    // (A table must count at least one collision to be read back.)
    c.collisions[0] = 1;
    let t = EscapeTable::from_counts(c, "element positions");
    for g in [-0.2, 0.1, 1.0, 3.0] {
        let w = |x: f64| t.element_weight(Stage::FIRST, x, g);
        assert!((w(-0.35) - 2.0).abs() < 1e-9, "{}", w(-0.35));
        assert!((w(-0.45) - 0.5).abs() < 1e-9, "{}", w(-0.45));
        assert!((w(-0.4) - 1.25).abs() < 1e-9, "{}", w(-0.4));
        for x in [-0.45, -0.4, -0.35, -0.3] {
            assert!(w(x) <= t.element_bound(Stage::FIRST, x) + 1e-12);
        }
    }
    let back = EscapeTable::parse(&t.to_csv(), "element positions").unwrap();
    assert_eq!(back, t);
}

#[test]
fn the_incidence_axis_is_finest_at_grazing_incidence() {
    assert_eq!(X_IN_BINS, 34);
    assert_eq!(bin_in(-100.0), 0);
    assert_eq!(bin_in(X_IN_MIN), 0);
    assert_eq!(
        bin_in(-0.125),
        X_IN_EDGES.iter().position(|&e| e == -0.125).unwrap()
    );
    assert_eq!(bin_in(-1e-12), bin_in(-0.125));
    assert_eq!(bin_in(0.0), bin_in(0.2));
    assert_eq!(bin_in(100.0), X_IN_BINS - 1);
    assert_eq!(bin_in(f64::NAN), 0);
    for w in X_IN_EDGES.windows(2) {
        assert!(w[1] > w[0]);
        let width = w[1] - w[0];
        assert!(if (-1.0..0.0).contains(&w[0]) {
            width == 0.125
        } else {
            width >= 0.25
        });
    }
}

#[test]
fn interning_keeps_one_copy_per_table() {
    let a = EscapeTable::from_counts(EscapeCounts::default(), "x");
    let p = a.clone().intern().unwrap();
    let q = a.intern().unwrap();
    assert!(std::ptr::eq(p, q));
    assert!(std::ptr::eq(
        EscapeTable::builtin().clone().intern().unwrap(),
        EscapeTable::builtin()
    ));
}

#[test]
fn the_element_correction_samples_the_weighted_law() {
    // A table whose weight is 3 above γ = 0 and 1 below, at the direction's x_in: the
    // corrected draws must follow 3·P_eff above 0 and P_eff below (renormalised).
    let wall = Deviations {
        delta_xi: 0.05,
        delta_zeta: 0.05,
    };
    // x_in = tan α/σ = −1.125, a row's centre (where `at_centres` puts the row's values).
    let beta = 0.0;
    let sigma = super::slope_deviations(&wall).delta_xi;
    let alpha = (-1.125 * sigma).atan();
    let inc = CalibratedIncidence::new(alpha, beta, &wall);
    let x_in = -1.125;
    assert!((inc.x_in() - x_in).abs() < 1e-12, "{}", inc.x_in());
    let mut c = EscapeCounts::default();
    let mut probe = EscapeCounts::default();
    for k in 0..100 {
        // Cell centres in s = g − x_in (the reachable elements, s > 0).
        let g = x_in + 0.08 * k as f64 + 0.04;
        probe.push_element(Stage::FIRST, x_in, g, g);
        let Some(cell) = probe.element_model.iter().position(|&n| n > 0) else {
            continue;
        };
        probe.element_model[cell] = 0;
        c.element_model[cell] = ELEMENT_MIN_COUNT;
        c.element_deterministic[cell] = if g > 0.0 { 3 } else { 1 } * ELEMENT_MIN_COUNT;
    }
    let table = EscapeTable::from_counts(c.at_centres(), "w");
    let state = (
        Stage::FIRST,
        table.element_read(Stage::FIRST, inc.x_in()),
        0.0,
    );
    let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(5);
    let n = 200_000;
    let plain = (0..n)
        .filter(|_| inc.draw_proposal(&mut rng).gamma > 0.0)
        .count() as f64
        / n as f64;
    let corrected = (0..n)
        .filter(|_| inc.draw_wall_corrected(&table, &state, &mut rng).gamma > 0.0)
        .count() as f64
        / n as f64;
    // Bilinear reading smooths the step over one bin on either side of 0 (±0.08 Δγ).
    let want = 3.0 * plain / (3.0 * plain + (1.0 - plain));
    assert!(
        (corrected - want).abs() < 0.01,
        "{corrected} vs {want} (plain {plain})"
    );
}

#[test]
fn the_calibrated_incidence_is_the_reduced_slope_of_its_velocity() {
    // x_in of an incidence (from its angles) and of a velocity (`reduced_slope`, what the
    // calibration and the escape decision read) agree in every quadrant, rising or not.
    let wall = Deviations {
        delta_xi: 0.04,
        delta_zeta: 0.12,
    };
    let slopes = super::slope_deviations(&wall);
    for a in [-80.0f64, -2.0, 3.0, 60.0] {
        for b in [-150.0f64, -30.0, 0.0, 40.0, 120.0] {
            let (alpha, beta) = (a.to_radians(), b.to_radians());
            let inc = CalibratedIncidence::new(alpha, beta, &wall);
            let u = crate::angles::velocity_from_angles(1.5, alpha, beta);
            let x = super::slope_space::reduced_slope(&u, &slopes);
            assert!((x - inc.x_in()).abs() < 1e-12 * x.abs().max(1.0), "{a} {b}");
            assert_eq!(x > 0.0, a > 0.0);
        }
    }
}

#[test]
fn calibrated_rebounds_off_a_wall_without_slope_along_the_path() {
    // 2-D roughness seen along its lay (σ(β) = 0, x_in infinite): finite rebounds, the
    // transverse roughness deflecting them, no NaN.
    let wall = Deviations {
        delta_xi: 0.0,
        delta_zeta: 0.1,
    };
    let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(9);
    let u = crate::angles::velocity_from_angles(1.0, -0.2, 0.0);
    let law = CollisionLaw::Elastic;
    let mut deflected = 0;
    for _ in 0..2000 {
        let r = calibrated_rebound(None, u, &wall, &law, &mut rng);
        assert!(r.velocity.iter().all(|v| v.is_finite()) && r.velocity.y > 0.0);
        assert!((r.velocity.norm() - 1.0).abs() < 1e-12);
        deflected += (r.velocity.z.abs() > 1e-3) as u32;
    }
    assert!(deflected > 1000, "{deflected}");
}

#[test]
fn a_trapped_particle_meets_steeper_elements_after_a_downslope() {
    // The built-in table's memory (constants::Q_EDGES): on the deterministic surface a
    // particle that has just left a steep downslope (q ≈ −2) meets the valley's other
    // side, steeper than after an upslope (q ≥ 0.25), at the same incidence.
    let wall = Deviations {
        delta_xi: 0.05,
        delta_zeta: 0.05,
    };
    let inc = CalibratedIncidence::new(-0.0125, 0.0, &wall);
    let table = EscapeTable::builtin();
    let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(9);
    let mut mean = |stage: Stage| {
        let state = (stage, table.element_read(stage, inc.x_in()), 0.0);
        let n = 100_000;
        (0..n)
            .map(|_| inc.draw_wall_corrected(table, &state, &mut rng).gamma / 0.05)
            .sum::<f64>()
            / n as f64
    };
    let (down, up) = (mean(Stage::later(-2.0)), mean(Stage::later(0.5)));
    assert!(
        down - up > 0.15,
        "after a downslope {down}, after an upslope {up}"
    );
}
