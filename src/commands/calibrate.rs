//! `rebound calibrate`: the escape table of the `calibrated` stochastic model, measured
//! on the deterministic simulation of a case (`roughwall::calibrated::calibrate`).

use crate::case::{builtin, deterministic::prepare};
use crate::cli::CalibrateArgs;
use crate::commands::{begin_out, context, counted, grouped, warn, Summary};
use crate::output::out_dir::check_out;
use crate::output::write_atomic;
use crate::runner::TallyOverrides;
use roughwall::calibrated::escape_counts;
use roughwall::calibrated::EscapeTable;
use roughwall::deterministic::{build_surfaces, realisations};
use roughwall::surface::pooled_deviations;
use roughwall::HeightField;
use roughwall::{Error, Result};

/// Runs the subcommand.
pub fn run(args: &CalibrateArgs) -> Result<Summary> {
    let ctx = context(&args.common, "calibrate", builtin::CALIBRATE)?;
    let o = TallyOverrides {
        particles: args.particles,
        ..Default::default()
    };
    let mut p = prepare(&ctx.case, &o, None)?;
    warn(std::mem::take(&mut p.warnings));
    if p.options.sphere_diameter_m.is_some() {
        return Err(Error::Input(
            "`deterministic.contact` = \"sphere\": `rebound calibrate` measures the particle-centre model the stochastic model stands for; remove the key".into(),
        ));
    }
    let Some(plan) = &p.surface else {
        return Err(Error::Internal("no surface plan".into()));
    };
    check_out(&ctx.out_dir, "--out")?;
    let n = p.options.surfaces;
    let built = build_surfaces(Some(plan), None, None, ctx.seed, p.options.triangulation, n)?;
    let fields: Vec<&HeightField> = built.iter().map(|b| &b.field).collect();
    warn(fields[0].triangulation_seam());
    let surfaces = realisations(&built, p.options.max_collisions, None)?;
    // The reduced angles use the deviations the surfaces have, not the ones they were meant
    // to have: the table must not absorb the surface's discretisation (a few per cent).
    let measured = pooled_deviations(&fields);
    let out = begin_out(&ctx.out_dir)?;
    let t0 = std::time::Instant::now();
    let mut setup = p.setup;
    setup.wall = measured;
    let count = p.scene.count as u64;
    let conditions = &p.scene.conditions;
    let counts = escape_counts(&surfaces, &setup, conditions, count, ctx.seed);
    let seconds = t0.elapsed().as_secs_f64();
    if counts.total() == 0 {
        return Err(Error::Model(
            "no collision was counted: every history was lost or left too steeply to be trapped"
                .into(),
        ));
    }
    // One realisation: the line earlier tables carry (so they regenerate byte for byte).
    let realisations = match n {
        1 => String::new(),
        n => format!(" surfaces {n}"),
    };
    let source = format!(
        "case {} seed {} particles {} conditions {} wall (measured) {:.4} {:.4} deg triangulation {}{realisations}",
        ctx.case.name,
        ctx.seed,
        count,
        conditions.len(),
        measured.delta_xi.to_degrees(),
        measured.delta_zeta.to_degrees(),
        fields[0].triangulation.name()
    );
    let table = EscapeTable::from_counts(counts, &source);
    write_atomic(
        &out.path().join("escape_table.csv"),
        table.to_csv().as_bytes(),
    )?;
    let mut manifest = ctx.manifest;
    let round = |x: f64| toml::Value::Float((x * 1e4).round() / 1e4);
    let mut t = toml::Table::new();
    t.insert(
        "measured_delta_xi_deg".into(),
        round(measured.delta_xi.to_degrees()),
    );
    t.insert(
        "measured_delta_zeta_deg".into(),
        round(measured.delta_zeta.to_degrees()),
    );
    t.insert(
        "collisions_counted".into(),
        toml::Value::Integer(table.counts().total() as i64),
    );
    t.insert(
        "histories".into(),
        toml::Value::Integer((count * conditions.len() as u64) as i64),
    );
    t.insert(
        "use".into(),
        "[stochastic] model = \"calibrated\", escape_table = \"<this file>\"".into(),
    );
    if n > 1 {
        t.insert("surfaces".into(), toml::Value::Integer(n as i64));
    }
    manifest.set("calibration", toml::Value::Table(t));
    manifest.set_run(
        "compute_s",
        toml::Value::Float((seconds * 1e3).round() / 1e3),
    );
    manifest.write(out.path())?;
    let dir = out.commit()?;
    let histories = count * conditions.len() as u64;
    Ok(Summary {
        work: format!(
            "{}, {} histories, {} collisions counted",
            counted(conditions.len(), "condition"),
            grouped(histories),
            grouped(table.counts().total())
        ),
        rate: Some((histories, "histories")),
        wrote: dir,
    })
}

#[cfg(test)]
mod tests {
    use crate::case::deterministic::prepare;
    use roughwall::calibrated::escape_counts;
    use roughwall::calibrated::EscapeTable;
    use roughwall::deterministic::generate_surface;
    use roughwall::Tracker;

    const CASE: &str =
        "name = \"cal\"\nseed = 7\n[wall]\ndelta_xi_deg = 3.0\ndelta_zeta_deg = 6.0\n\
                        [incidence]\nalpha_deg = [-3.0, -12.5]\nbeta_deg = [0.0, 90.0]\n\
                        [particles]\ncount = 3000\n[collision]\nmodel = \"elastic\"\n";

    /// `rebound calibrate` writes the counts the library counts on the case's surface.
    #[test]
    fn the_table_counts_the_histories_the_library_counts() {
        use clap::Parser;
        let tmp = tempfile::tempdir().unwrap();
        let case_file = tmp.path().join("cal.toml");
        std::fs::write(&case_file, CASE).unwrap();
        let out = tmp.path().join("out");
        let cli = crate::cli::Cli::try_parse_from([
            "rebound".as_ref(),
            "calibrate".as_ref(),
            "--quiet".as_ref(),
            "--case".as_ref(),
            case_file.as_os_str(),
            "--out".as_ref(),
            out.as_os_str(),
        ])
        .unwrap();
        crate::commands::run(cli).unwrap();
        let text = std::fs::read_to_string(out.join("escape_table.csv")).unwrap();
        let table = EscapeTable::parse(&text, "t").unwrap();

        let case = crate::case::parse(CASE, "cal").unwrap();
        let p = prepare(&case, &Default::default(), None).unwrap();
        let field =
            generate_surface(p.surface.as_ref().unwrap(), 7, p.options.triangulation).unwrap();
        let tracker = Tracker::new(&field, p.options.max_collisions).unwrap();
        let mut setup = p.setup;
        setup.wall = roughwall::surface::measured_deviations(&field);
        let counts = escape_counts(&tracker.into(), &setup, &p.scene.conditions, 3000, 7);
        assert_eq!(table.counts(), &counts);
    }
}
