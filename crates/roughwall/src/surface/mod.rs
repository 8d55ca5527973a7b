//! Rough walls as generated surfaces (Radenkovic & Simonin 2021, Sec. 2).
pub mod dilation;
pub mod generate;
pub mod height_field;
pub mod heights_io;
pub mod normal_angles;
pub mod scan;
pub mod spec;
pub mod stats;
pub use generate::generate;
pub use height_field::{HeightField, Triangulation};
pub use spec::SurfaceSpec;
