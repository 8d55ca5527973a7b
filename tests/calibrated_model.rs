//! The `calibrated` wall model: `rebound calibrate` writes an escape table that reads back
//! equal to its source run, the stochastic model takes it by case key (or the built-in one),
//! and malformed or mismatched tables are one-line errors.
use crate::common;

use roughwall::calibrated::{EscapeTable, Stage};
use std::path::Path;

const CASE: &str = "name = \"cal\"\nseed = 7\n[wall]\ndelta_xi_deg = 3.0\ndelta_zeta_deg = 6.0\n\
                    [incidence]\nalpha_deg = [-3.0, -12.5]\nbeta_deg = [0.0, 90.0]\n\
                    [particles]\ncount = 3000\n[collision]\nmodel = \"elastic\"\n";

fn calibrate(dir: &Path, threads: &str) -> std::path::PathBuf {
    let case = common::write_case(dir, "cal.toml", CASE);
    common::run_case(
        "calibrate",
        &case,
        &dir.join(format!("t{threads}")),
        &["--threads", threads],
    )
}

#[test]
fn the_table_reads_back_equal_to_its_source_run() {
    let tmp = tempfile::tempdir().unwrap();
    let a = calibrate(tmp.path(), "1");
    let b = calibrate(tmp.path(), "2");
    let text = std::fs::read_to_string(a.join("escape_table.csv")).unwrap();
    assert_eq!(
        text,
        std::fs::read_to_string(b.join("escape_table.csv")).unwrap()
    );
    let table = EscapeTable::parse(&text, "t").unwrap();

    // (The same histories counted through the library give the same table: a unit test
    // of src/commands/calibrate.rs.)
    let counts = table.counts();

    // The deterministic surface's transverse memory: a trapped particle's successive
    // elements lean the same way across its path (regression slope about 0.4 on the
    // ensembles, docs/models.md; independent draws would give 0). ~700 pairs here: one
    // standard error ≈ 0.04.
    let t = &counts.transverse;
    let pairs: u64 = t.pairs.iter().sum();
    let slope = t.cross_sum.iter().sum::<i64>() as f64 / t.prev_sq_sum.iter().sum::<i64>() as f64;
    assert!(pairs > 300, "{pairs} pairs");
    assert!(
        (0.25..0.6).contains(&slope),
        "slope {slope} over {pairs} pairs"
    );

    // Against the deterministic run of the same case and seed: every history's first
    // collision is counted once at most, and a counted first collision escapes exactly when
    // the history had one collision.
    let det = common::run_case(
        "deterministic",
        &common::write_case(tmp.path(), "det.toml", CASE),
        &tmp.path().join("det"),
        &[],
    );
    let s = common::Csv::read(&det.join("summary.csv"));
    let (mut followed, mut single) = (0.0, 0.0);
    for row in &s.rows {
        let n = s.num(row, "particles") - s.num(row, "lost");
        followed += n;
        single += s.num(row, "p_single") * n;
    }
    // The first stages lead the table.
    use roughwall::calibrated::X_OUT_BINS;
    use roughwall::calibrated::{FIRST_STAGES, X_IN_BINS};
    let first_cells = FIRST_STAGES * X_IN_BINS * X_OUT_BINS;
    let first: u64 = counts.collisions[..first_cells].iter().sum();
    let first_escaped: u64 = counts.escaped[..first_cells].iter().sum();
    // Every followed history has a first collision, counted once along Δγ.
    let along_dg: u64 = counts.first_count.iter().sum();
    assert!(along_dg as f64 >= followed, "{along_dg} of {followed}");
    assert!(along_dg <= 4 * 3000, "{along_dg}");
    assert!(
        first as f64 <= followed,
        "{first} first collisions of {followed} histories"
    );
    assert!(first as f64 > 0.5 * followed, "{first} of {followed}");
    // Single-collision histories whose rebound is steeper than the table (x_out ≥ 4) are
    // not counted: fewer escapes than single collisions, but most of them.
    assert!(
        first_escaped as f64 <= single.round() + 0.5,
        "{first_escaped} > {single}"
    );
    assert!(
        first_escaped as f64 > 0.5 * single,
        "{first_escaped} vs {single}"
    );
    let manifest = std::fs::read_to_string(a.join("run.toml")).unwrap();
    assert!(manifest.contains("measured_delta_xi_deg"), "{manifest}");
}

#[test]
fn the_stochastic_model_takes_the_table_by_key_or_the_built_in_one() {
    let tmp = tempfile::tempdir().unwrap();
    let table = calibrate(tmp.path(), "2").join("escape_table.csv");
    let builtin = tmp.path().join("builtin.csv");
    std::fs::write(&builtin, roughwall::calibrated::BUILTIN).unwrap();
    let run = |name: &str, extra: &str| {
        let case = common::write_case(
            tmp.path(),
            &format!("{name}.toml"),
            &format!("{CASE}[stochastic]\nmodel = \"calibrated\"\n{extra}"),
        );
        let out = common::run_case("stochastic", &case, &tmp.path().join(name), &[]);
        std::fs::read(out.join("summary.csv")).unwrap()
    };
    let default = run("default", "");
    let same = run(
        "same",
        &format!("escape_table = \"{}\"\n", builtin.display()),
    );
    let own = run("own", &format!("escape_table = \"{}\"\n", table.display()));
    assert_eq!(
        default, same,
        "the built-in table given as a file changed the run"
    );
    assert_ne!(default, own, "a different table gave the same run");
}

#[test]
fn bad_tables_are_refused_in_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let good = roughwall::calibrated::BUILTIN;
    let write = |name: &str, text: &str| {
        let p = tmp.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let half: Vec<&str> = good.lines().take(900).collect();
    let truncated = write("trunc.csv", &half.join("\n"));
    let not_table = write("other.csv", "alpha,beta\n1,2\n");
    let old_format = write("old.csv", &good.replacen("table v9", "table v8", 1));
    let lines: Vec<&str> = good.lines().collect();
    let mut shifted = lines.clone();
    shifted[3] = "first-d0,-5.500,0.050,10,1,0.100000";
    let shifted = write("shifted.csv", &shifted.join("\n"));
    for (model, path, needle) in [
        (
            "calibrated",
            truncated.display().to_string(),
            "truncated after",
        ),
        (
            "calibrated",
            not_table.display().to_string(),
            "not an escape table",
        ),
        (
            "calibrated",
            old_format.display().to_string(),
            "another format",
        ),
        (
            "calibrated",
            shifted.display().to_string(),
            "does not match this version's grid",
        ),
        ("calibrated", "no/such/table.csv".into(), "file not found"),
        (
            "radenkovic-simonin-2021",
            truncated.display().to_string(),
            "applies to model = \"calibrated\" only",
        ),
    ] {
        let case = common::write_case(
            tmp.path(),
            "bad.toml",
            &format!("{CASE}[stochastic]\nmodel = \"{model}\"\nescape_table = \"{path}\"\n"),
        );
        common::refuse_case("stochastic", &case, tmp.path(), needle);
        common::refuse_case("stochastic", &case, tmp.path(), "stochastic.escape_table");
    }
    let sphere = common::write_case(
        tmp.path(),
        "sphere.toml",
        &format!("{CASE}[particles.x]\n")
            .replace(
                "[particles]\ncount = 3000\n",
                "[particles]\ncount = 3000\ndiameter_um = 50.0\n",
            )
            .replace(
                "[particles.x]\n",
                "[deterministic]\ncontact = \"sphere\"\nrms_height_um = 1.0\n",
            ),
    );
    common::refuse_case("calibrate", &sphere, tmp.path(), "deterministic.contact");
}

#[test]
fn later_collisions_follow_the_table_of_the_later_stage() {
    // The first and the later stages differ where the deterministic run says they do: a
    // particle trapped after a first collision escapes less easily at the same reduced
    // angles, whatever the first collision's roughness angle.
    let t = EscapeTable::builtin();
    for dg in [2.5, 5.5, 7.3] {
        let first = Stage::first(f64::to_radians(dg));
        let mut lower = 0;
        for x_out in [0.2, 0.4, 0.6, 0.8] {
            if t.p_escape(Stage::later(-0.75), -1.0, x_out) < t.p_escape(first, -1.0, x_out) {
                lower += 1;
            }
        }
        assert!(
            lower >= 3,
            "Δγ = {dg}°: later-stage escape not lower at 3 of 4 points"
        );
    }
}

/// `calibrated` works in slopes (`slope_space`): the first element's transverse slope given
/// its slope along the path follows Eq. (30) in slopes — mean `(Cov/σ_l²) s_l`, spread
/// `√(σ_t² − Cov²/σ_l²)` whatever `s_l` (a Gaussian surface's conditional law), on the
/// wall's slope spreads, which reproduce its normal-angle spreads. In angles the spread of
/// γ* would shrink with γ (a steep facet's transverse angle is smaller for the same slope).
#[test]
fn calibrated_transverse_slope_follows_eq30_in_slopes() {
    use nalgebra::Vector3;
    use rand::SeedableRng;
    use roughwall::angles::velocity_from_angles;
    use roughwall::calibrated::{slope_deviations, slopes_from_normal};
    use roughwall::models::rebound_with;
    use roughwall::stochastic::Contact;
    use roughwall::wall::{conditional_gamma_star, rotated_moments};
    use roughwall::AnyModel;
    use roughwall::CollisionLaw;
    use roughwall::Deviations;
    let wall = Deviations {
        delta_xi: 6f64.to_radians(),
        delta_zeta: 12f64.to_radians(),
    };
    let slopes = slope_deviations(&wall);
    // Slopes spread more than angles, and the transverse slope adds to it.
    assert!(slopes.delta_xi > wall.delta_xi.tan() && slopes.delta_zeta > wall.delta_zeta.tan());
    let beta = 30f64.to_radians();
    let m = rotated_moments(&slopes, beta);
    let sl = m.var_a.sqrt();
    let u = velocity_from_angles(1.0, (-20f64).to_radians(), beta);
    let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(13);
    let firsts: Vec<(f64, f64)> = (0..1_000_000)
        .map(|_| {
            let contact = Contact {
                wall: &wall,
                law: &CollisionLaw::Elastic,
                psi: 2.0,
                diameter_m: 1e-4,
            };
            let r = rebound_with(
                &AnyModel::calibrated(None),
                u,
                Vector3::zeros(),
                &contact,
                &mut rng,
            );
            slopes_from_normal(&r.first.normal, beta)
        })
        .collect();
    let (_, var_c) = conditional_gamma_star(&m, 1.0);
    let k = m.cov / m.var_a;
    assert!(k.abs() > 0.3, "{k}: the test wants a correlated direction");
    let slice = |g0: f64| {
        let sel: Vec<(f64, f64)> = firsts
            .iter()
            .filter(|(a, _)| (a / sl - g0).abs() < 0.1)
            .copied()
            .collect();
        let n = sel.len() as f64;
        let mean_l = sel.iter().map(|p| p.0).sum::<f64>() / n;
        let mean_t = sel.iter().map(|p| p.1).sum::<f64>() / n;
        let var = sel
            .iter()
            .map(|p| (p.1 - mean_t - k * (p.0 - mean_l)).powi(2))
            .sum::<f64>()
            / (n - 2.0);
        (mean_l, mean_t, var.sqrt(), n)
    };
    let sd = var_c.sqrt();
    for g0 in [0.0, 2.0] {
        let (ml, mt, s, n) = slice(g0);
        assert!(n > 15_000.0, "{g0}: {n}");
        let se = sd / n.sqrt();
        assert!(
            (mt - k * ml).abs() < 4.0 * se,
            "{g0}: {mt} vs {} ± {se}",
            k * ml
        );
        let se_s = sd / (2.0 * n).sqrt();
        assert!((s - sd).abs() < 4.0 * se_s, "{g0}: {s} vs {sd} ± {se_s}");
    }
}
