//! Which commands read each section of a case file (issue 14, part 9).
//!
//! A section no command reads is refused when the case is parsed (unknown sections are
//! unknown keys). A section that only *other* commands read would be silently ignored — a
//! stochastic case with force-sweep's particle section runs with the default diameter — so
//! each command warns about it, naming the commands that do read it.

use super::{Case, Warning};

/// One case file drives both Monte Carlo models on the same scene (and `calibrate` runs the
/// deterministic one): each reads, or at least checks, every scene section.
const MONTE_CARLO: &[&str] = &["deterministic", "stochastic", "calibrate"];
const SURFACE_AND_MONTE_CARLO: &[&str] = &["surface", "deterministic", "stochastic", "calibrate"];
/// The wall: also `scan`, which generates it and reads it as a scan when it has no file.
const WALL: &[&str] = &[
    "surface",
    "deterministic",
    "stochastic",
    "calibrate",
    "scan",
];

/// Every section of the schema, in [`present`]'s order.
const SECTION_NAMES: [&str; 14] = [
    "surface",
    "wall",
    "stats",
    "incidence",
    "particles",
    "collision",
    "output",
    "stochastic",
    "deterministic",
    "erosion",
    "impactor",
    "particle",
    "sweep",
    "scan",
];

/// Each section present in `case` with the commands that read it.
fn present(case: &Case) -> Vec<(&'static str, &'static [&'static str])> {
    let sections: [(&str, bool, &[&str]); SECTION_NAMES.len()] = [
        ("surface", case.surface.is_some(), WALL),
        ("wall", case.wall.is_some(), WALL),
        ("stats", case.stats.is_some(), &["surface"]),
        ("incidence", case.incidence.is_some(), MONTE_CARLO),
        ("particles", case.particles.is_some(), MONTE_CARLO),
        ("collision", case.collision.is_some(), MONTE_CARLO),
        ("output", case.output.is_some(), MONTE_CARLO),
        ("stochastic", case.stochastic.is_some(), MONTE_CARLO),
        // `surface` reads its `triangulation` (the statistics are of the tracker's triangles).
        (
            "deterministic",
            case.deterministic.is_some(),
            SURFACE_AND_MONTE_CARLO,
        ),
        ("erosion", case.erosion.is_some(), MONTE_CARLO),
        ("impactor", case.impactor.is_some(), &["force-sweep"]),
        ("particle", case.particle.is_some(), &["force-sweep"]),
        ("sweep", case.sweep.is_some(), &["force-sweep"]),
        ("scan", case.scan.is_some(), &["scan"]),
    ];
    debug_assert!(sections.iter().zip(SECTION_NAMES).all(|(s, n)| s.0 == n));
    sections
        .into_iter()
        .filter(|(_, there, _)| *there)
        .map(|(name, _, readers)| (name, readers))
        .collect()
}

/// The warnings of running `command` on `case`: one per section that `command` does not read
/// (naming the commands that do), and one for force-sweep's old section name `[particle]`.
pub fn unread(case: &Case, command: &str) -> Vec<Warning> {
    let mut out = Vec::new();
    for (name, readers) in present(case) {
        if name == "particle" && command == "force-sweep" {
            out.push(Warning(
                "section [particle] is the old name of [impactor] (force-sweep's particle, not the [particles] of deterministic and stochastic): rename it; it is still read".into(),
            ));
            continue;
        }
        if readers.contains(&command) {
            continue;
        }
        let by = readers
            .iter()
            .map(|c| format!("`{c}`"))
            .collect::<Vec<_>>()
            .join(", ");
        let hint = if name == "particle" && MONTE_CARLO.contains(&command) {
            " (did you mean [particles]?)"
        } else {
            ""
        };
        out.push(Warning(format!(
            "section [{name}] is not read by `{command}`{hint}: it is read by {by} only"
        )));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::case::parse;

    fn warnings(text: &str, command: &str) -> Vec<String> {
        let case = parse(&format!("name = \"t\"\n{text}"), "t.toml").unwrap();
        unread(&case, command).into_iter().map(|w| w.0).collect()
    }

    #[test]
    fn force_sweeps_particle_in_a_stochastic_case_is_named_with_a_hint() {
        let w = warnings(
            "[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n[particle]\ndiameter_um = 100.0\n",
            "stochastic",
        );
        assert_eq!(
            w,
            ["section [particle] is not read by `stochastic` (did you mean [particles]?): it is read by `force-sweep` only"]
        );
    }

    #[test]
    fn one_scene_file_drives_both_models_without_warnings() {
        let scene = "[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n[incidence]\nalpha_deg = [-10.0]\n\
                     [particles]\ncount = 10\n[collision]\nmodel = \"elastic\"\n[output]\nbin_width_deg = 1.0\n\
                     [stochastic]\npsi = 2.0\n[deterministic]\nmax_collisions = 10\n";
        for command in MONTE_CARLO {
            assert!(warnings(scene, command).is_empty(), "{command}");
        }
        // `surface` reads the wall (and [deterministic] triangulation) only.
        let w = warnings(scene, "surface");
        assert_eq!(w.len(), 5, "{w:?}");
        assert!(!w.iter().any(|w| w.contains("[deterministic]")), "{w:?}");
        assert!(w[0].starts_with("section [incidence] is not read by `surface`: it is read by `deterministic`, `stochastic`, `calibrate` only"), "{w:?}");
    }

    #[test]
    fn a_scan_case_and_a_scene_case_warn_about_each_other() {
        // The card's [wall] pasted beside [scan]: the models warn about [scan]; `scan` reads
        // [wall] (the wall it generates without a file) and warns itself when a file is given.
        let case = "[scan]\nfile = \"a.x3p\"\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n";
        assert_eq!(
            warnings(case, "stochastic"),
            ["section [scan] is not read by `stochastic`: it is read by `scan` only"]
        );
        assert!(warnings(case, "scan").is_empty());
        let w = warnings("[incidence]\nalpha_deg = [-10.0]\n", "scan");
        assert_eq!(w.len(), 1);
        assert!(
            w[0].starts_with("section [incidence] is not read by `scan`"),
            "{w:?}"
        );
    }

    #[test]
    fn the_old_particle_name_is_deprecated_for_force_sweep() {
        let w = warnings("[particle]\npreset = \"glass\"\n", "force-sweep");
        assert_eq!(w.len(), 1);
        assert!(w[0].contains("old name of [impactor]"), "{w:?}");
        assert!(warnings("[impactor]\npreset = \"glass\"\n", "force-sweep").is_empty());
        let w = warnings(
            "[impactor]\npreset = \"glass\"\n[stats]\nbeta_star_deg = [0.0]\n",
            "force-sweep",
        );
        assert_eq!(
            w,
            ["section [stats] is not read by `force-sweep`: it is read by `surface` only"]
        );
    }

    #[test]
    fn every_schema_section_has_its_readers() {
        // The schema's own list of keys (serde names them all for an unknown one) against
        // the sections `present` knows: a section added to the schema must get its readers.
        let e = parse("name = \"t\"\n[no_such_section]\n", "t.toml")
            .unwrap_err()
            .to_string();
        let mut schema: Vec<&str> = e
            .split('`')
            .skip(3) // the message, `no_such_section`, then "expected one of"
            .step_by(2)
            .filter(|k| !["name", "seed"].contains(k))
            .collect();
        schema.sort_unstable();
        let mut known: Vec<&str> = SECTION_NAMES.to_vec();
        known.sort_unstable();
        assert_eq!(schema, known, "{e}");
    }
}
