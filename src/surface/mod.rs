//! Rough walls as generated surfaces (Radenkovic & Simonin 2021, Sec. 2).
pub mod generate;
pub mod height_field;
pub mod stats;
pub use generate::{generate, SurfaceParams};
pub use height_field::HeightField;
