//! The readers' tests as one binary: real instrument files (`real_files`), and broken, hostile
//! and edge-case files (`errors`). Each file of `tests/` is a module here, so its tests keep
//! their names under the file's (`cargo test -p topography errors::`); `cargo test -p
//! topography` needs nothing but the toolchain. A new test file is added below:
//! `every_test_file_is_a_test_target_or_a_module_of_one` in the application's
//! `tests/integration.rs` fails until it is.

mod errors;
mod mutations;
mod real_files;
