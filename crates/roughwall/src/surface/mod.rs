//! Rough walls as generated surfaces (Radenkovic & Simonin 2021, Sec. 2).
pub(crate) mod dilation;
pub(crate) mod generate;
pub(crate) mod height_field;
pub(crate) mod heights_io;
pub(crate) mod normal_angles;
pub(crate) mod spec;
pub(crate) mod stats;
pub use dilation::{
    dilate_paraboloid, dilate_sphere_exact, effective_roughness, sphere_centre_surface, Dilated,
    EffectiveRoughness, BYTES_PER_NODE,
};
pub use generate::generate;
pub use generate::generation_bytes;
pub use height_field::{HeightField, Triangulation};
pub use heights_io::{is_height_file, read_heights, write_heights, MAGIC};
pub use normal_angles::expected_deviations;
pub use spec::SurfaceSpec;
pub use stats::{
    measured_deviations, pooled_deviations, surface_stats, AngleSums, Histogram, HistogramSpec,
    RotatedStats, SurfaceStats,
};
