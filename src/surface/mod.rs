//! Rough walls as generated surfaces (Radenkovic & Simonin 2021, Sec. 2).
pub mod height_field;
pub use height_field::HeightField;
