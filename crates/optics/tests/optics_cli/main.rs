//! The `optics` binary, run as a user runs it: the course's quiz answers
//! with their rounding, the JSON record's fields, `optics batch`
//! round-tripping every law, the realistic-scene techniques' commands,
//! and bad input refused by name, in the chosen language, without a panic.
//!
//! An integration test of the `optics` package, so that cargo builds the
//! binary first and hands its path in `CARGO_BIN_EXE_optics`.

mod batch;
mod common;
mod edge_numbers;
mod errata;
mod errors;
mod help;
mod laws;
mod quiz;
mod techniques;
