//! The `measured-wall` model: a stochastic wall model that takes a wall as measured, not as
//! Gaussian (issue 39, part 4; docs/models.md, "The measured-wall model").
//!
//! A particle centre that bounces, perhaps several times, on a rough wall and leaves it
//! has turned its velocity `U⁻` into `U⁺`. For an ideally elastic bounce there is exactly one
//! plane that mirrors the one into the other, of normal `n_eff ∝ U⁺/|U⁺| − U⁻/|U⁻|` (the
//! *effective wall element* of the history, [`effective_normal`]). Its angles carry
//! everything the bounce did: the facet's slope, the shadow effect, the multiple collisions, and any
//! asymmetry of the wall between `β⁻` and `−β⁻` or `β⁻ + 180°`.
//!
//! So the model is the law of that element given the incident direction, measured on the
//! deterministic reference on the scan itself (`deterministic::in_place_wall`, for a point
//! particle or a sphere's centre surface) over a grid of incident directions ([`grid`], with
//! rows of the wall's own where its law bends, [`refine`]), kept as quantile functions
//! ([`quantiles`]) of its normal-angle fluctuations
//! `(ξ', ζ')` in the wall's frame (Eq. 4): the marginal law of `ξ'`, and the law of `ζ'`
//! within each of 32 rank bins of `ξ'` (their dependence), and beside them the law's joint
//! atoms ([`atoms`]: elements many histories share exactly, a facet's own normal for a single
//! bounce), kept as pairs. A rebound draws `(ξ', ζ')` for its
//! incident direction from one of the four surrounding grid cells, picked by its bilinear
//! weight (a mixture: unshadowed, the law of the elements met is linear in `cot α⁻`, as a
//! mixture is, and a mixture keeps a narrow peak of the law that a blend of quantile
//! functions smears), and applies the collision law in that element's frame, as the
//! paper's model does with its virtual wall.
//! With the elastic law the rebound then has the reference's law up to the table's
//! resolution and sampling noise, at any incident direction, by construction; with another
//! law it is the one-element approximation every stochastic model makes.
//!
//! The files follow the model's life: `grid` (the incident directions and the resolution,
//! with how they were chosen), `effective_normal`, `atoms`, `quantiles`, `refine` (the rows a wall
//! adds), `build` (the table from a deterministic reference), `table` (the law a rebound reads) and `table_file` (the text a
//! card points to and the C library and Python take).

pub(crate) mod atoms;
pub(crate) mod build;
pub(crate) mod effective_normal;
pub(crate) mod grid;
pub(crate) mod quantiles;
pub(crate) mod refine;
pub(crate) mod table;
pub(crate) mod table_file;

pub use atoms::{Atoms, ATOM_BUDGET, ATOM_MIN_HISTORIES, MAX_ATOMS};
pub use build::{build_table, scan_table, BuildOptions, BUILD_CELLS};
pub use effective_normal::{effective_gammas, effective_normal};
pub use grid::CELLS;
pub use grid::{
    ALPHA_ROWS_DEG, BETA_COLUMNS, ENTRY_ALPHA_DEG, HISTORIES_PER_CELL, LINEAR_BELOW_DEG, RANK_BINS,
    SERVED_LEFT_BOUND, XI_ADDED_BUDGET, XI_ADDED_TOLERANCE, XI_KNOTS, ZETA_ADDED_BUDGET,
    ZETA_ADDED_TOLERANCE, ZETA_KNOTS,
};
pub use quantiles::{CellLaw, QuantileFunction, ADDED_T_UNIT};
pub use refine::{MAX_REFINED_ROWS, REFINE_ABOVE_DEG};
pub use table::{MeasuredWallIncidence, MeasuredWallTable};
pub use table_file::{MAGIC, MAX_DISTINCT_TABLES};

/// The generated anisotropic Gaussian wall of the crate's unit tests (Δξ ≈ 2.5°, Δζ ≈ 7.5°):
/// `nodes` of 1 µm a side, from `seed`.
#[cfg(test)]
pub(crate) fn test_wall(nodes: usize, seed: u64) -> crate::HeightField {
    crate::surface::generate(
        &crate::surface::SurfaceSpec {
            length_m: nodes as f64 * 1e-6,
            nodes,
            rms_height_m: 0.37e-6,
            corr_length_x_m: Some(12e-6),
            corr_length_z_m: Some(4e-6),
        },
        seed,
    )
}

/// A small table for the crate's unit tests: [`test_wall`] of 128 nodes, 1024 histories per
/// cell, built once.
#[cfg(test)]
pub(crate) fn small_table() -> &'static MeasuredWallTable {
    use std::sync::OnceLock;
    static TABLE: OnceLock<&'static MeasuredWallTable> = OnceLock::new();
    TABLE.get_or_init(|| {
        let field = test_wall(128, 3);
        let tracker = crate::Tracker::new(&field, 1000).unwrap();
        let dev = crate::surface::measured_deviations(&field);
        build_table(
            &tracker,
            dev,
            "small test wall",
            &BuildOptions {
                histories_per_cell: 1024,
                seed: 1,
            },
            &|_| {},
        )
        .unwrap()
        .intern()
        .unwrap()
    })
}
