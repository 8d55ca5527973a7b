//! The library's integration tests as one binary (ripgrep's `tests/tests.rs` is the model):
//! the physics through the public API only, no command line. Each file of `tests/` is a
//! module here, so its tests keep their names under the file's (`cargo test -p roughwall
//! --test library force_models::`). `no_allocation.rs` (a counting global allocator) and
//! `escape_table_bound.rs` (a per-process bound) stay binaries of their own.
//! A new test file is added below: `every_test_file_is_a_test_target_or_a_module_of_one` in
//! the application's `tests/integration.rs` fails until it is.

mod common;

mod c_header;
mod deterministic_hard;
mod deterministic_physics;
mod force_models;
mod in_place;
mod measured_wall;
mod own_model;
mod parameters;
mod stochastic_sampler;
mod surface_table1;
