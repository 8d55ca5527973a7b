//! The tables of `rebound surface`: the statistics of Radenkovic & Simonin 2021, Table 1
//! (Eqs. 7–9, 14–15) and the effective roughness of spheres.

use crate::output::{fmt_num, CsvTable};
use roughwall::surface::EffectiveRoughness;
use roughwall::surface::SurfaceStats;
use roughwall::wall::{self, rotated_moments};
use roughwall::Deviations;
use roughwall::{HeightField, SurfaceSpec};

/// Columns of `surface_summary.csv` (issue #2).
pub const SUMMARY_HEADER: [&str; 14] = [
    "nodes",
    "length_um",
    "spacing_um",
    "rms_height_um",
    "target_rms_height_um",
    "rms_slope_x",
    "target_rms_slope_x",
    "rms_slope_z",
    "target_rms_slope_z",
    "delta_xi_deg",
    "target_delta_xi_deg",
    "delta_zeta_deg",
    "target_delta_zeta_deg",
    "max_height_um",
];

/// Columns of `normal_angles.csv` (issue #2).
pub const ANGLES_HEADER: [&str; 9] = [
    "beta_star_deg",
    "delta_xi_star_deg",
    "delta_zeta_star_deg",
    "rho_xi_zeta",
    "rho_xi_eta",
    "rho_eta_zeta",
    "model_delta_xi_star_deg",
    "model_delta_zeta_star_deg",
    "model_rho_xi_zeta",
];

/// The files the command writes into `--out`.
pub const OUTPUT_FILES: [&str; 7] = [
    "surface_summary.csv",
    "normal_angles.csv",
    "height_map.svg",
    "normal_angle_pdfs.svg",
    "run.toml",
    "effective_roughness.csv",
    "effective_roughness.svg",
];

/// Columns of `effective_roughness.csv`.
/// The last three: the large-sphere asymptote `√(h/D)` (rad, shown in degrees; `h` the
/// measured rms height) and each effective deviation over it.
pub const EFFECTIVE_HEADER: [&str; 11] = [
    "diameter_um",
    "d_over_cl_x",
    "d_over_cl_z",
    "delta_xi_eff_deg",
    "delta_zeta_eff_deg",
    "delta_xi_ratio",
    "delta_zeta_ratio",
    "contact_fraction",
    "sqrt_h_over_d_deg",
    "delta_xi_eff_over_sqrt_h_over_d",
    "delta_zeta_eff_over_sqrt_h_over_d",
];

/// The large-sphere law `Δ_eff ≈ √(h/D)` (rad): a sphere much larger than `h/Δ²` rests on
/// asperity tops, and its centre surface is made of caps whose slopes scale as `√(h/R)`,
/// whatever the correlation lengths. Measured, not assumed: `effective_roughness.csv` gives
/// the ratio of each effective deviation to it.
pub fn large_sphere_deviation(rms_height_m: f64, diameter_m: f64) -> f64 {
    if diameter_m > 0.0 {
        (rms_height_m / diameter_m).sqrt()
    } else {
        f64::INFINITY
    }
}

/// Bins of the `ξ*`, `ζ*` histograms.
pub const HIST_BINS: usize = 100;

/// `D/c_L` along an axis (empty for `c_L = ∞`, 2-D roughness).
pub fn d_over_cl(d: f64, c: Option<f64>) -> Option<f64> {
    c.map(|c| d / c)
}

pub fn effective_table(
    spec: &SurfaceSpec,
    s: &SurfaceStats,
    eff: &[EffectiveRoughness],
) -> CsvTable {
    let ratio = |x: f64, base: f64| {
        if base > 0.0 {
            fmt_num(x / base)
        } else {
            String::new()
        }
    };
    let mut t = CsvTable::new(&EFFECTIVE_HEADER);
    for e in eff {
        let a = large_sphere_deviation(s.rms_height_m, e.diameter_m);
        t.push(vec![
            fmt_num(e.diameter_m * 1e6),
            d_over_cl(e.diameter_m, spec.corr_length_x_m)
                .map(fmt_num)
                .unwrap_or_default(),
            d_over_cl(e.diameter_m, spec.corr_length_z_m)
                .map(fmt_num)
                .unwrap_or_default(),
            fmt_num(e.delta_xi.to_degrees()),
            fmt_num(e.delta_zeta.to_degrees()),
            ratio(e.delta_xi, s.delta_xi),
            ratio(e.delta_zeta, s.delta_zeta),
            fmt_num(e.contact_fraction),
            fmt_num(a.to_degrees()),
            ratio(e.delta_xi, a),
            ratio(e.delta_zeta, a),
        ]);
    }
    t
}

/// Seconds rounded to milliseconds (timings in `run.toml`).
pub fn round_ms(s: f64) -> f64 {
    (s * 1e3).round() / 1e3
}

/// How the field is stored (see `HeightField`): `nz = 1` for a surface constant along z.
pub fn grid_table(f: &HeightField) -> toml::Value {
    let mut t = toml::Table::new();
    t.insert("nx".into(), toml::Value::Integer(f.nx as i64));
    t.insert("nz".into(), toml::Value::Integer(f.nz as i64));
    t.insert("dx_m".into(), toml::Value::Float(f.dx));
    t.insert("dz_m".into(), toml::Value::Float(f.dz));
    t.insert("triangulation".into(), f.triangulation.name().into());
    t.insert(
        "statistics".into(),
        "every triangle of the grid (two per cell), equally weighted".into(),
    );
    toml::Value::Table(t)
}

/// Target rms slope `√2 h / c_L` (Radenkovic & Simonin 2021, Eq. 14); 0 for `c_L = ∞`.
pub fn target_slope(h: f64, c: Option<f64>) -> f64 {
    c.map_or(0.0, |c| wall::deviation_from_surface(h, c))
}

/// `surface_summary.csv`: measured against target (Eqs. 14–15).
pub fn summary_table(spec: &SurfaceSpec, target: &Deviations, s: &SurfaceStats) -> CsvTable {
    let um = |m: f64| fmt_num(m * 1e6);
    let deg = |r: f64| fmt_num(r.to_degrees());
    let mut t = CsvTable::new(&SUMMARY_HEADER);
    t.push(vec![
        spec.nodes.to_string(),
        um(spec.length_m),
        um(spec.spacing_m()),
        um(s.rms_height_m),
        um(spec.rms_height_m),
        fmt_num(s.rms_slope_x),
        fmt_num(target_slope(spec.rms_height_m, spec.corr_length_x_m)),
        fmt_num(s.rms_slope_z),
        fmt_num(target_slope(spec.rms_height_m, spec.corr_length_z_m)),
        deg(s.delta_xi),
        deg(target.delta_xi),
        deg(s.delta_zeta),
        deg(target.delta_zeta),
        um(s.max_height_m),
    ]);
    t
}

/// Model columns: Eq. (9) with the target deviations of Eq. (15), and Eq. (8). At
/// multiples of 90° the covariance is exactly 0 (not `cos(π/2) ≈ 6e-17` times something).
pub fn model_row(target: &Deviations, beta_star: f64) -> (f64, f64, f64) {
    let mut m = rotated_moments(target, beta_star);
    let q = beta_star / std::f64::consts::FRAC_PI_2;
    if (q - q.round()).abs() < 1e-12 {
        m.cov = 0.0;
    }
    (m.var_a.sqrt(), m.var_b.sqrt(), m.rho())
}

/// `normal_angles.csv`: the rotated frames of Table 1, measured and modelled (Eqs. 8–9).
pub fn angles_table(target: &Deviations, s: &SurfaceStats) -> CsvTable {
    let deg = |r: f64| fmt_num(r.to_degrees());
    let mut t = CsvTable::new(&ANGLES_HEADER);
    for r in &s.rotated {
        let (mx, mz, mrho) = model_row(target, r.beta_star);
        t.push(vec![
            deg(r.beta_star),
            deg(r.delta_xi_star),
            deg(r.delta_zeta_star),
            fmt_num(r.rho_xi_zeta),
            fmt_num(r.rho_xi_eta),
            fmt_num(r.rho_eta_zeta),
            deg(mx),
            deg(mz),
            fmt_num(mrho),
        ]);
    }
    t
}
