//! The built-in case of each command: what it runs without `--case`.

/// `surface`: the surface of Radenkovic & Simonin 2021, Table 1 (L = 5 mm, N = 5001,
/// h = 0.37 µm, c_Lx = 12 µm, c_Lz = 4 µm).
pub const SURFACE: &str = include_str!("../../configs/cases/table1.toml");

/// `deterministic`: the first wall of Sec. 3, (Δξ, Δζ) = (2.5°, 7.5°).
pub const DETERMINISTIC: &str = include_str!("../../configs/cases/aniso.toml");

/// `stochastic`: the Sec. 4 scene (glass beads, D = 500 µm, on steel with the
/// `glass-steel` Sommerfeld–Huber preset, Δξ = 3.8°, Δζ = 7.5°, horizontal speed
/// `N(5.91, 1.16)` m/s, α⁻ ∈ {−5°, −15°, −25°}, β⁻ ∈ {0°, 60°}).
pub const STOCHASTIC: &str = r#"# Radenkovic & Simonin 2021, Sec. 4 (Figs. 14-15, high roughness anisotropy).
name = "glass-steel-sec4"
seed = 2021

[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5

[incidence]
alpha_deg = [-5.0, -15.0, -25.0]
beta_deg = [0.0, 60.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16

[particles]
count = 100000
diameter_um = 500.0

[collision]
model = "sommerfeld-huber"
preset = "glass-steel"

[output]
bin_width_deg = 1.0

[stochastic]
psi = 2.0
"#;

/// `force-sweep`: Hu et al. 2021, Fig. 6.
pub const FORCE_SWEEP: &str = include_str!("../../configs/cases/hu-fig6.toml");

/// `calibrate`: the calibration of the shipped escape table.
pub const CALIBRATE: &str = include_str!("../../configs/calibration/aniso.toml");

/// `scan`: the self-check of the chain, the Sec. 3 wall (Δξ, Δζ) = (2.5°, 7.5°) generated
/// and read as a scan.
pub const SCAN: &str = include_str!("../../configs/scans/self-check.toml");
