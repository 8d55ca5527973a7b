//! The parameters a wall is built from, declared once: their key in a case file (the key every
//! one-line error names), their name in the C library's `rw_wall_params`, the Fortran module
//! and Python's `roughwall.Wall`, their unit and what is allowed. [`crate::WallParams`],
//! [`crate::CollisionParams`] and [`crate::ModelParams`] hold the values; the checks are the
//! laws' and models' own ([`crate::CollisionParams::law`], [`crate::NamedModel::from_params`],
//! [`crate::wall::checked_deviation`], [`crate::stochastic::checked_psi`]).
//!
//! The tests hold every interface to this list: the C header's and the Fortran type's fields
//! (`crates/roughwall/tests/c_header.rs`), Python's `Wall` signature, its stub and the PyO3
//! signature, the case-file reference `docs/cases.md`, the finiteness checks of
//! [`crate::WallModel::new`] and the message each range gives
//! (`crates/roughwall/tests/parameters.rs`; the case file's reading of each number:
//! the application's `tests/wall_messages.rs`). A parameter added here and forgotten in one of them fails there.

/// What values a parameter takes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParameterKind {
    /// A finite number; `allowed` says the range.
    Number,
    /// One of a few names (a C enum constant).
    Choice,
    /// An unsigned 64-bit integer.
    Seed,
    /// Text (a file's contents from C and Python, a path in a case file).
    Text,
}

/// One parameter of a wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallParameter {
    /// The key in a case file, `section.name` (top-level keys without a section).
    pub case_key: &'static str,
    /// The field of `rw_wall_params` (C and Fortran).
    pub c_name: &'static str,
    /// The keyword of Python's `roughwall.Wall(...)` (and of the PyO3 constructor).
    pub python_name: &'static str,
    /// What values it takes.
    pub kind: ParameterKind,
    /// Its unit (empty when it has none).
    pub unit: &'static str,
    /// What is allowed, as the error messages say it.
    pub allowed: &'static str,
}

const fn p(
    case_key: &'static str,
    c_name: &'static str,
    python_name: &'static str,
    kind: ParameterKind,
    unit: &'static str,
    allowed: &'static str,
) -> WallParameter {
    WallParameter {
        case_key,
        c_name,
        python_name,
        kind,
        unit,
        allowed,
    }
}

use ParameterKind::{Choice, Number, Seed, Text};

/// Every parameter of a wall, in the order of `rw_wall_params` (the C ABI's field order).
pub const WALL_PARAMETERS: [WallParameter; 15] = [
    // Radenkovic & Simonin 2021, Eq. (15).
    p(
        "wall.delta_xi_deg",
        "delta_xi_deg",
        "delta_xi_deg",
        Number,
        "degrees",
        "0 to 20 degrees",
    ),
    p(
        "wall.delta_zeta_deg",
        "delta_zeta_deg",
        "delta_zeta_deg",
        Number,
        "degrees",
        "0 to 20 degrees",
    ),
    // The collision law (Eqs. 36–42).
    p(
        "collision.model",
        "law",
        "law",
        Choice,
        "",
        "\"elastic\" or \"sommerfeld-huber\"",
    ),
    p(
        "collision.preset",
        "preset",
        "preset",
        Choice,
        "",
        "\"glass-steel\"",
    ),
    p(
        "collision.e_h",
        "e_h",
        "e_h",
        Number,
        "",
        "a restitution coefficient in (0, 1]",
    ),
    p(
        "collision.alpha_e_deg",
        "alpha_e_deg",
        "alpha_e_deg",
        Number,
        "degrees",
        "an angle in (0, 90] degrees",
    ),
    p(
        "collision.mu_0",
        "mu_0",
        "mu_0",
        Number,
        "",
        "a friction coefficient in [0, 2]",
    ),
    p(
        "collision.mu_h",
        "mu_h",
        "mu_h",
        Number,
        "",
        "a friction coefficient in [0, 2]",
    ),
    p(
        "collision.alpha_mu_deg",
        "alpha_mu_deg",
        "alpha_mu_deg",
        Number,
        "degrees",
        "an angle in (0, 90] degrees",
    ),
    // ψ of Eq. (34).
    p("stochastic.psi", "psi", "psi", Number, "", "0.01 to 100"),
    p("seed", "seed", "seed", Seed, "", "0 to 2^64 − 1"),
    // The rough-wall model and its parameters.
    p(
        "stochastic.model",
        "model",
        "model",
        Choice,
        "",
        "a registered rough-wall model",
    ),
    p(
        "stochastic.delta_gamma_deg",
        "delta_gamma_deg",
        "delta_gamma_deg",
        Number,
        "degrees",
        "0 to 20 degrees",
    ),
    p(
        "stochastic.escape_table",
        "escape_table_csv",
        "escape_table",
        Text,
        "",
        "an escape table as `rebound calibrate` writes it",
    ),
    p(
        "stochastic.wall_table",
        "wall_table_text",
        "wall_table",
        Text,
        "",
        "a measured-wall table as `rebound scan --measured-wall` writes it",
    ),
];

/// The parameter whose case-file key is `case_key`.
pub fn wall_parameter(case_key: &str) -> Option<&'static WallParameter> {
    WALL_PARAMETERS.iter().find(|p| p.case_key == case_key)
}
