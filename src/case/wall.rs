//! `[surface]`, `[wall]` and `[stats]`: the wall as deviations or a full surface to generate,
//! and the statistics `rebound surface` measures on it (Radenkovic & Simonin 2021, Sec. 2).

use super::schema::*;
use roughwall::check::{check_int_range, check_length, within};
use roughwall::wall;
use roughwall::Deviations;
pub use roughwall::SurfaceSpec;
use roughwall::Warning;
use roughwall::{Error, Result};

pub use roughwall::wall::{LOW_ROUGHNESS_LIMIT_DEG, MAX_DEVIATION_DEG};
/// Steepest rms slope (degrees) a generated surface may have.
pub const MAX_SURFACE_SLOPE_DEG: f64 = 45.0;

/// What a case says about the wall.
#[derive(Clone, Debug, PartialEq)]
pub enum WallSource {
    /// A full surface (grid and roughness): generated as given.
    Surface(SurfaceSpec),
    /// Only the statistical wall: deviations (a surface, if needed, is chosen to fit).
    Deviations(Deviations),
}

impl WallSource {
    pub fn deviations(&self) -> Deviations {
        match self {
            WallSource::Surface(s) => s.deviations(),
            WallSource::Deviations(d) => *d,
        }
    }
}

/// Particle diameters (µm): a nanometre to a metre (`[particles]`, `[stats]`).
pub const DIAMETER_RANGE_UM: (f64, f64) = (1e-3, 1e6);
/// Lengths of a generated surface (µm): a picometre to a kilometre.
pub const LENGTH_RANGE_UM: (f64, f64) = (1e-6, 1e9);
/// Longest `[stats] diameter_um` list.
pub const MAX_DIAMETERS: usize = 64;
/// Longest `[stats] beta_star_deg` list.
pub const MAX_BETA_STAR: usize = 1000;

impl Case {
    /// The `[surface]` or `[wall]` section and its name.
    fn wall_spec(&self) -> Option<(&'static str, &WallSpec)> {
        match (&self.surface, &self.wall) {
            (Some(s), _) => Some(("surface", s)),
            (None, Some(w)) => Some(("wall", w)),
            _ => None,
        }
    }

    /// The wall: a full surface when grid keys are given, else deviations
    /// (from `delta_*_deg`, or from `corr_length_*_um` and `rms_height_um` by Eq. 15).
    pub fn wall_source(&self, warnings: &mut Vec<Warning>) -> Result<WallSource> {
        let Some((sec, w)) = self.wall_spec() else {
            return Err(Error::Input(
                "the case needs a [wall] (delta_xi_deg, delta_zeta_deg) or [surface] section"
                    .into(),
            ));
        };
        let has_grid = w.length_um.is_some() || w.nodes.is_some();
        if has_grid {
            return Ok(WallSource::Surface(self.surface_spec(warnings)?));
        }
        // The lengths a [wall] gives have the ranges of a [surface]'s.
        let (lo, hi) = LENGTH_RANGE_UM;
        let lengths = "a surface's lengths, a picometre to a kilometre";
        let length = |key: &str, v: f64| within(&format!("{sec}.{key}"), v, lo, hi, " µm", lengths);
        if let Some(h) = w.rms_height_um.filter(|&h| h != 0.0) {
            within(
                &format!("{sec}.rms_height_um"),
                h,
                lo,
                hi,
                " µm (or 0)",
                lengths,
            )?;
        }
        let mut axis = |c: Option<f64>, d: Option<f64>, cname: &str, dname: &str| -> Result<f64> {
            match (c, d) {
                (Some(_), Some(_)) => Err(Error::Input(format!(
                    "[{sec}] gives both `{cname}` and `{dname}`: give one of them"
                ))),
                (None, Some(d)) => wall::checked_deviation(&format!("{sec}.{dname}"), d, warnings),
                (Some(c), None) => {
                    let c = length(cname, c)?;
                    let h = w.rms_height_um.ok_or_else(|| {
                        Error::Input(format!(
                            "[{sec}] gives `{cname}` but not `rms_height_um` (needed by Eq. 15)"
                        ))
                    })?;
                    let h = length("rms_height_um", h)?;
                    wall::checked_deviation(
                        &format!("{sec}.{cname} (as a deviation)"),
                        wall::deviation_from_surface(h, c).to_degrees(),
                        warnings,
                    )
                }
                (None, None) => Err(Error::Input(format!(
                    "[{sec}] needs `{dname}` or `{cname}`"
                ))),
            }
        };
        Ok(WallSource::Deviations(Deviations {
            delta_xi: axis(
                w.corr_length_x_um,
                w.delta_xi_deg,
                "corr_length_x_um",
                "delta_xi_deg",
            )?,
            delta_zeta: axis(
                w.corr_length_z_um,
                w.delta_zeta_deg,
                "corr_length_z_um",
                "delta_zeta_deg",
            )?,
        }))
    }

    /// A full surface: `length_um`, `nodes`, `rms_height_um` and per axis a correlation length
    /// or a deviation (converted with Eq. 15). Checks the grid against the correlation lengths:
    /// `δ > c_L/2` is an error, `L < 20 c_L` a warning.
    pub fn surface_spec(&self, warnings: &mut Vec<Warning>) -> Result<SurfaceSpec> {
        let Some((sec, w)) = self.wall_spec() else {
            return Err(Error::Input("the case needs a [surface] section".into()));
        };
        let need =
            |v: Option<f64>, k: &str| v.ok_or_else(|| Error::Input(format!("[{sec}] needs `{k}`")));
        let (lo, hi) = LENGTH_RANGE_UM;
        let lengths = "a surface's lengths, a picometre to a kilometre";
        let length_um = within(
            &format!("{sec}.length_um"),
            need(w.length_um, "length_um")?,
            lo,
            hi,
            " µm",
            lengths,
        )?;
        let nodes = w
            .nodes
            .ok_or_else(|| Error::Input(format!("[{sec}] needs `nodes`")))?;
        let key = format!("{sec}.nodes");
        check_int_range(&key, nodes, 16, 40_000, "an integer from 16 to 40000")?;
        let h_um = need(w.rms_height_um, "rms_height_um")?;
        if h_um != 0.0 {
            within(
                &format!("{sec}.rms_height_um"),
                h_um,
                lo,
                hi,
                " µm (or 0)",
                lengths,
            )?;
        }
        let mut axis = |c: Option<f64>,
                        d: Option<f64>,
                        cname: &str,
                        dname: &str|
         -> Result<Option<f64>> {
            let c = match (c, d) {
                (Some(_), Some(_)) => {
                    return Err(Error::Input(format!(
                        "[{sec}] gives both `{cname}` and `{dname}`: give one of them"
                    )))
                }
                (Some(c), None) => {
                    let c = within(&format!("{sec}.{cname}"), c, lo, hi, " µm", lengths)?;
                    // The rms slope √2 h/c_L (Eq. 14) of a generated surface: up to 45°
                    // (Fig. 4 studies it beyond the low-roughness range; the wall models
                    // themselves stop at 20°, checked in `scene`).
                    if h_um > 0.0 {
                        let d = wall::deviation_from_surface(h_um, c).to_degrees();
                        if d.is_nan() || d > MAX_SURFACE_SLOPE_DEG {
                            return Err(Error::invalid(
                                    &format!("{sec}.{cname}"),
                                    c,
                                    &format!(
                                        "a correlation length giving an rms slope √2 h/c_L of at most {MAX_SURFACE_SLOPE_DEG}° (Eq. 14); it gives {d}°"
                                    ),
                                ));
                        }
                        if d > LOW_ROUGHNESS_LIMIT_DEG {
                            warnings.push(Warning(format!(
                                    "`{sec}.{cname}` = {c} µm gives Δ = √2 h/c_L = {d:.2}° (Eq. 15), beyond the low-roughness approximation (Eq. 6, up to ~{LOW_ROUGHNESS_LIMIT_DEG}°)"
                                )));
                        }
                    }
                    Some(c)
                }
                (None, Some(d)) => {
                    let dr = wall::checked_deviation(&format!("{sec}.{dname}"), d, warnings)?;
                    let c = wall::corr_length_from_deviation(h_um, dr);
                    if let Some(c) = c.filter(|_| h_um > 0.0) {
                        within(
                            &format!("{sec}.{dname} (as the correlation length √2 h/Δ, Eq. 15)"),
                            c,
                            lo,
                            hi,
                            " µm",
                            lengths,
                        )?;
                    }
                    c
                }
                (None, None) => {
                    return Err(Error::Input(format!(
                        "[{sec}] needs `{cname}` or `{dname}`"
                    )))
                }
            };
            Ok(c)
        };
        let cx = axis(
            w.corr_length_x_um,
            w.delta_xi_deg,
            "corr_length_x_um",
            "delta_xi_deg",
        )?;
        let cz = axis(
            w.corr_length_z_um,
            w.delta_zeta_deg,
            "corr_length_z_um",
            "delta_zeta_deg",
        )?;
        let spec = SurfaceSpec {
            length_m: length_um * 1e-6,
            nodes: nodes as usize,
            rms_height_m: h_um * 1e-6,
            corr_length_x_m: if h_um > 0.0 {
                cx.map(|c| c * 1e-6)
            } else {
                None
            },
            corr_length_z_m: if h_um > 0.0 {
                cz.map(|c| c * 1e-6)
            } else {
                None
            },
        };
        let spacing_um = length_um / nodes as f64;
        for (name, c) in [("corr_length_x_um", cx), ("corr_length_z_um", cz)] {
            if let Some(c) = c {
                if h_um > 0.0 && spacing_um > c / 2.0 {
                    return Err(Error::invalid(
                        &format!("{sec}.nodes"),
                        nodes,
                        &format!(
                            "a grid spacing L/nodes ≤ c_L/2 = {} µm ({name} = {c} µm); spacing is {spacing_um} µm",
                            c / 2.0
                        ),
                    ));
                }
                if h_um > 0.0 && length_um < 20.0 * c {
                    warnings.push(Warning(format!(
                        "[{sec}] length_um = {length_um} is less than 20 correlation lengths ({name} = {c} µm): statistics will be noisy and biased"
                    )));
                }
            }
        }
        roughwall::memory::require(
            &format!("{sec}.nodes"),
            nodes,
            roughwall::surface::generation_bytes(&spec),
            &format!("a {nodes} × {nodes} surface"),
        )?;
        Ok(spec)
    }

    /// Sphere diameters (m) of `[stats] diameter_um` whose effective roughness `surface`
    /// measures: each in the diameter range and at most the surface side `length_m` (a
    /// sphere wider than the period would rest on its own images).
    pub fn effective_diameters(&self, length_m: f64) -> Result<Vec<f64>> {
        let list = self
            .stats
            .as_ref()
            .map(|s| s.diameter_um.clone())
            .unwrap_or_default();
        let allowed = format!("at most {MAX_DIAMETERS} diameters");
        check_length(
            "stats.diameter_um",
            list.len(),
            MAX_DIAMETERS,
            "diameters",
            &allowed,
        )?;
        let (lo, hi) = DIAMETER_RANGE_UM;
        list.iter()
            .map(|&d| {
                let d = within("stats.diameter_um", d, lo, hi, " µm", "a nanometre to a metre")?;
                if d * 1e-6 > length_m {
                    return Err(Error::invalid(
                        "stats.diameter_um",
                        d,
                        &format!(
                            "at most the surface side, {} µm (a wider sphere rests on its own periodic images)",
                            crate::output::fmt_num(length_m * 1e6)
                        ),
                    ));
                }
                Ok(d * 1e-6)
            })
            .collect()
    }

    /// Directions `β*` (radians) of Table 1's rotated frames; default 0°, 30°, 60°, 90°.
    pub fn beta_star(&self) -> Result<Vec<f64>> {
        let list = self
            .stats
            .as_ref()
            .and_then(|s| s.beta_star_deg.clone())
            .unwrap_or_else(|| vec![0.0, 30.0, 60.0, 90.0]);
        let allowed = format!("at most {MAX_BETA_STAR} directions");
        check_length(
            "stats.beta_star_deg",
            list.len(),
            MAX_BETA_STAR,
            "angles",
            &allowed,
        )?;
        if list.is_empty() {
            return Err(Error::invalid(
                "stats.beta_star_deg",
                "[]",
                "a non-empty list",
            ));
        }
        list.iter()
            .map(|&b| {
                if (-180.0..=180.0).contains(&b) {
                    Ok(b.to_radians())
                } else {
                    Err(Error::invalid(
                        "stats.beta_star_deg",
                        b,
                        "angles in [-180, 180] degrees",
                    ))
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The built-in `surface` case (`configs/cases/table1.toml`) is the surface whose Table 1
    /// statistics the library's `table1_statistics_full_size` test checks: that test types
    /// the same spec and seed in, so an edit of the shipped case must show here.
    #[test]
    fn the_builtin_surface_case_is_the_full_table1_surface() {
        let case = super::super::parse(super::super::builtin::SURFACE, "built-in").unwrap();
        assert_eq!(case.seed, Some(1));
        let spec = case.surface_spec(&mut Vec::new()).unwrap();
        assert_eq!(
            spec,
            SurfaceSpec {
                length_m: 5e-3,
                nodes: 5001,
                rms_height_m: 0.37e-6,
                corr_length_x_m: Some(12e-6),
                corr_length_z_m: Some(4e-6),
            }
        );
    }
}
