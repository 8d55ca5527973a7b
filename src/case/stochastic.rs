//! What `rebound stochastic` resolves from a case: the scene, the wall the model sees and
//! what to tally (Radenkovic & Simonin 2021, Sec. 3.6, Fig. 13; docs/physics.md §3). No surface is
//! built, except for `[stochastic] effective_for_diameter`; a case with surface parameters
//! is converted to deviations (Eq. 15).

use super::{Case, Scene, WallSource, Warning};
use crate::runner::TallyOverrides;
use roughwall::models::{tally_spec, ModelSetup};
use roughwall::stochastic::{checked_psi, PSI_PAPER};
use roughwall::tally::TallySpec;
use roughwall::Deviations;
use roughwall::ErosionSetup;
use roughwall::{AnyModel, ModelParams, RoughWallModel};
use roughwall::{Error, Result};

/// What a stochastic run resolves from its case before any rebound is drawn.
pub struct Prepared {
    pub scene: Scene,
    pub setup: ModelSetup,
    pub specs: Vec<TallySpec>,
    /// Manifest entries that follow from the case alone (notes).
    pub notes: toml::Table,
    /// Warnings of the resolution, for the command to print.
    pub warnings: Vec<Warning>,
}

/// Resolves the scene, the model and what to tally (and the warnings to print).
pub fn prepare(case: &Case, o: &TallyOverrides, seed: u64) -> Result<Prepared> {
    let mut warnings = Vec::new();
    let mut scene = case.scene(&mut warnings)?;
    // One case file drives both models: its `[deterministic]` section is checked here too.
    super::deterministic::deterministic_options(case, false)?;
    scene.set_count(o.particles)?;
    scene.set_target_se(o.target_se)?;
    let mut notes = toml::Table::new();
    let wall = match effective_wall(case, seed, &mut warnings)? {
        Some((dev, table)) => {
            notes.insert("effective_for_diameter".into(), toml::Value::Table(table));
            dev
        }
        None => scene.wall.deviations(),
    };
    // A model measured on a wall of its own (`measured-wall`) rebounds off that wall.
    let given = wall;
    let wall = scene.model.wall(&given);
    if wall != given {
        notes.insert(
            "wall_from_model".into(),
            toml::Value::String(format!(
                "model = \"{}\" rebounds off the wall its table was measured on: Δξ = {:.4}°, Δζ = {:.4}° (the case's [wall] is not used)",
                scene.model.name(),
                wall.delta_xi.to_degrees(),
                wall.delta_zeta.to_degrees()
            )),
        );
    }
    if let WallSource::Surface(_) = scene.wall {
        let note = format!(
            "the case gives a surface; the stochastic model uses its deviations from Eq. (15): Δξ = {:.4}°, Δζ = {:.4}°",
            wall.delta_xi.to_degrees(),
            wall.delta_zeta.to_degrees()
        );
        warnings.push(Warning(note.clone()));
        notes.insert("wall_from_surface".into(), toml::Value::String(note));
    }
    if scene.conditions.iter().any(|c| c.alpha_in_deg() == -90.0) {
        notes.insert(
            "notes".into(),
            toml::Value::String(
                "normal incidence (α⁻ = −90°) has no incident plane: β⁻ is taken as 0° (docs/physics.md §1)"
                    .into(),
            ),
        );
    }
    let setup = ModelSetup {
        wall,
        law: scene.law,
        psi: scene.psi,
        diameter_m: scene.diameter_m,
        speed: scene.speed,
        spin: scene.spin,
        model: scene.model,
        erosion: scene.erosion.map(|model| ErosionSetup {
            model,
            particle_mass_kg: scene.particle_mass_kg(),
            diameter_m: scene.diameter_m,
        }),
    };
    let specs = scene
        .conditions
        .iter()
        .map(|c| tally_spec(&wall, *c, scene.bin_width_deg, setup.erosion.as_ref()))
        .collect();
    Ok(Prepared {
        scene,
        setup,
        specs,
        notes,
        warnings,
    })
}

/// `[stochastic] effective_for_diameter = true`: the deviations a sphere of the case's
/// diameter sees — those of its centre surface (paraboloid dilation, `surface::dilation`) on
/// the surface `deterministic` generates for the case and seed — with the manifest entries.
/// `None` without the key.
fn effective_wall(
    case: &Case,
    seed: u64,
    warnings: &mut Vec<Warning>,
) -> Result<Option<(Deviations, toml::Table)>> {
    let on = case
        .stochastic
        .as_ref()
        .and_then(|s| s.effective_for_diameter)
        .unwrap_or(false);
    if !on {
        return Ok(None);
    }
    let key = "stochastic.effective_for_diameter";
    if case
        .particles
        .as_ref()
        .and_then(|p| p.diameter_um)
        .is_none()
    {
        return Err(Error::Input(format!(
            "`{key}` needs `particles.diameter_um`, the sphere's diameter"
        )));
    }
    let scale = case.surface.is_some()
        || case.wall.as_ref().and_then(|w| w.rms_height_um).is_some()
        || case
            .deterministic
            .as_ref()
            .and_then(|d| d.rms_height_um)
            .is_some();
    if !scale {
        return Err(Error::Input(format!(
            "`{key}` needs the roughness's absolute scale: set `deterministic.rms_height_um` (or `wall.rms_height_um` with correlation lengths, or give a [surface])"
        )));
    }
    // The surface and the sphere of `deterministic` with `contact = "sphere"`.
    let mut sphere_case = case.clone();
    let mut d = sphere_case.deterministic.clone().unwrap_or_default();
    d.contact = Some("sphere".into());
    sphere_case.deterministic = Some(d);
    let det = super::deterministic::prepare(&sphere_case, &TallyOverrides::default(), None)?;
    // The sphere run's own warnings; the scene's, which it repeats, were already given.
    for w in det.warnings {
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    }
    let (Some(plan), Some(diameter)) = (&det.surface, det.options.sphere_diameter_m) else {
        return Err(Error::Internal("no surface plan for the sphere".into()));
    };
    // Over the realisations `deterministic` bounces on (`[deterministic] surfaces`), one
    // at a time.
    use roughwall::deterministic::{generate_surface, realisation_seed};
    use roughwall::surface::AngleSums;
    let n = det.options.surfaces;
    let (mut nominal, mut eff, mut contact) = (AngleSums::default(), AngleSums::default(), 0.0);
    for r in 0..n {
        let field = generate_surface(plan, realisation_seed(seed, r), det.options.triangulation)?;
        nominal.add(&field);
        let dil = roughwall::surface::sphere_centre_surface(&field, diameter, &format!("`{key}`"))?;
        eff.add(&dil.field);
        contact += dil.contact_fraction;
    }
    let (nominal, eff, contact_fraction) =
        (nominal.deviations(), eff.deviations(), contact / n as f64);
    if !(eff.delta_xi.is_finite() && eff.delta_zeta.is_finite()) {
        return Err(Error::Model(format!(
            "`{key}`: the deviations of the sphere's centre surface are not finite numbers"
        )));
    }
    let mut t = toml::Table::new();
    let deg = |r: f64| toml::Value::Float((r.to_degrees() * 1e4).round() / 1e4);
    t.insert(
        "diameter_um".into(),
        toml::Value::Float((diameter * 1e15).round() / 1e9),
    );
    t.insert("surface_delta_xi_deg".into(), deg(nominal.delta_xi));
    t.insert("surface_delta_zeta_deg".into(), deg(nominal.delta_zeta));
    t.insert("effective_delta_xi_deg".into(), deg(eff.delta_xi));
    t.insert("effective_delta_zeta_deg".into(), deg(eff.delta_zeta));
    t.insert(
        "contact_fraction".into(),
        toml::Value::Float((contact_fraction * 1e6).round() / 1e6),
    );
    t.insert(
        "how".into(),
        "deviations of the sphere's centre surface (paraboloid dilation) on the surface deterministic generates for this case and seed".into(),
    );
    if n > 1 {
        t.insert("surfaces".into(), toml::Value::Integer(n as i64));
    }
    Ok(Some((eff, t)))
}

impl Case {
    /// ψ of the single-collision probability, Eq. (34): `[stochastic] psi`, default 2 (the paper's).
    pub fn psi(&self) -> Result<f64> {
        checked_psi(
            self.stochastic
                .as_ref()
                .and_then(|s| s.psi)
                .unwrap_or(PSI_PAPER),
        )
    }

    /// The rough-wall model of `[stochastic] model` and `delta_gamma_deg` (default: the
    /// paper's).
    pub fn model(&self) -> Result<AnyModel> {
        let st = self.stochastic.clone().unwrap_or_default();
        let read_table = || read_escape_table(st.escape_table.as_deref().unwrap_or_default());
        let read_wall_table = || read_wall_table(st.wall_table.as_deref().unwrap_or_default());
        let params = ModelParams {
            delta_gamma_deg: st.delta_gamma_deg,
            escape_table: st
                .escape_table
                .as_ref()
                .map(|_| &read_table as &dyn Fn() -> Result<_>),
            wall_table: st
                .wall_table
                .as_ref()
                .map(|_| &read_wall_table as &dyn Fn() -> Result<_>),
        };
        AnyModel::named(st.model.as_deref(), &params)
    }
}

/// Largest escape table read (bytes): a table of the fixed grid (45 152 rows) is about
/// 1.6 MB, and its counts cannot make a row much longer than 60 bytes.
const MAX_ESCAPE_TABLE_BYTES: u64 = 1 << 23;

/// Reads the escape table at `path` (`[stochastic] escape_table`): as given, else under
/// `configs/`; one-line errors that name the key and the file.
fn read_escape_table(path: &str) -> Result<&'static roughwall::calibrated::EscapeTable> {
    let (text, what) = read_table_text(
        "stochastic.escape_table",
        path,
        MAX_ESCAPE_TABLE_BYTES,
        "an escape table",
    )?;
    roughwall::calibrated::EscapeTable::parse(&text, &what)?.intern()
}

/// Largest measured-wall table read (bytes): a measured table is 4–18 MB of text, at most
/// about 38 MiB (every row a build may add, every knot at ±π/2, every knot it may add, every
/// joint atom a cell may hold).
const MAX_WALL_TABLE_BYTES: u64 = 1 << 26;

/// Reads the measured-wall table at `path` (`[stochastic] wall_table`), as
/// [`read_escape_table`] does.
fn read_wall_table(path: &str) -> Result<&'static roughwall::measured_wall::MeasuredWallTable> {
    let (text, what) = read_table_text(
        "stochastic.wall_table",
        path,
        MAX_WALL_TABLE_BYTES,
        "a measured-wall table",
    )?;
    roughwall::measured_wall::MeasuredWallTable::parse(&text, &what)?.intern()
}

/// The text of the table file `path` of case key `key` (as given, else under `configs/`) and
/// how errors name it; one-line errors for a missing, unreadable or oversized file.
fn read_table_text(key: &str, path: &str, max_bytes: u64, kind: &str) -> Result<(String, String)> {
    let file = super::load::resolve_path(std::path::Path::new(path)).map_err(|_| {
        match roughwall::check::not_a_regular_file(std::path::Path::new(path)) {
            Some(k) => Error::Input(format!("`{key}` = \"{path}\": {k}, not a file")),
            None => Error::Input(format!(
                "`{key}` = \"{path}\": file not found (looked as given and under configs/)"
            )),
        }
    })?;
    let what = format!("`{key}` = \"{path}\"");
    let len = std::fs::metadata(&file).map(|m| m.len()).unwrap_or(0);
    if len > max_bytes {
        return Err(Error::Input(format!(
            "{what}: {len} bytes, more than {kind} ({max_bytes} at most)"
        )));
    }
    let text = std::fs::read_to_string(&file)
        .map_err(|e| Error::Input(format!("{what}: cannot read it: {e}")))?;
    Ok((text, what))
}

#[cfg(test)]
mod tests {
    use super::MAX_WALL_TABLE_BYTES;
    use roughwall::measured_wall::{
        Atoms, CellLaw, MeasuredWallTable, QuantileFunction, ADDED_T_UNIT, ALPHA_ROWS_DEG,
        BETA_COLUMNS, MAX_ATOMS, MAX_REFINED_ROWS, RANK_BINS, XI_ADDED_BUDGET, XI_KNOTS,
        ZETA_ADDED_BUDGET, ZETA_KNOTS,
    };

    /// The longest table the grid can give (every row its build may add, every knot −π/2, the
    /// widest number, every knot a quantile function may add, with a `t` of nine digits, and
    /// counts of 20 digits) is read: a finer grid that outgrew the cap would fail here, not in
    /// a user's run.
    #[test]
    fn the_largest_table_of_the_grid_fits_the_reader_cap() {
        let widest = |k: usize, added: usize| {
            let low = -std::f64::consts::FRAC_PI_2;
            // In the last interval, where `t` has the most digits.
            let t0 = (k - 2) as f64 / (k - 1) as f64;
            let added = (0..added)
                .map(|j| {
                    (
                        ((t0 + (j + 1) as f64 * 1e-6) / ADDED_T_UNIT).round() * ADDED_T_UNIT,
                        low,
                    )
                })
                .collect();
            QuantileFunction::with_added(vec![low; k], added).unwrap()
        };
        // Every joint atom a cell may hold, at the widest units and counts.
        let low = -15_707_963i64;
        let count = u64::MAX / MAX_ATOMS as u64;
        let atoms = (0..MAX_ATOMS as i64)
            .map(|j| (low, low + j, count))
            .collect();
        let cell = CellLaw {
            histories: u64::MAX,
            left_patch: 0,
            lost_other: 0,
            xi: widest(XI_KNOTS, XI_ADDED_BUDGET),
            zeta: vec![widest(ZETA_KNOTS, ZETA_ADDED_BUDGET); RANK_BINS],
            atoms: Atoms::from_units(atoms, u64::MAX).unwrap(),
        };
        // The base rows and as many midpoints as a build may add.
        let mut rows: Vec<f64> = ALPHA_ROWS_DEG.to_vec();
        rows.extend(
            ALPHA_ROWS_DEG
                .windows(2)
                .rev()
                .take(MAX_REFINED_ROWS)
                .map(|w| 0.5 * (w[0] + w[1])),
        );
        rows.sort_by(f64::total_cmp);
        let table = MeasuredWallTable {
            source: "x".repeat(255),
            first_row: 0,
            deviations: roughwall::Deviations {
                delta_xi: 0.1,
                delta_zeta: 0.1,
            },
            seed: u64::MAX,
            cells: vec![cell; rows.len() * BETA_COLUMNS],
            alpha_rows_deg: rows,
        };
        let text = table.to_text();
        // It is a table a reader takes, apart from its size.
        MeasuredWallTable::parse(&text, "t").unwrap();
        let bytes = text.len() as u64;
        assert!(bytes <= MAX_WALL_TABLE_BYTES, "{bytes} bytes");
        // The text is the worst case it claims to be (measured tables are 4–18 MB).
        assert!(bytes > 38 << 20, "{bytes} bytes");
    }
}
