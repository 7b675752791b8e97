//! The runner's integration tests, one test binary: each file of this directory is a module here (one link of
//! the engine instead of one per file: the test build is faster and its binaries a fraction
//! of the disk). Run one file's tests with `cargo test --release -p gdsmc --test all FILE::`.

// The tests' own expected values may use std's math: a tolerance compares them, not bits
// (clippy.toml keeps it out of what computes outputs).
#![allow(clippy::disallowed_methods)]

mod charts;
mod cluster;
mod column_names;
mod command;
mod data_safety;
mod disk_faults;
mod distribution;
mod faults;
mod histogram;
mod hydro;
mod job;
mod limits;
mod messages;
mod mutation;
mod output_set;
mod planted;
mod reproduce_verdicts;
mod signals;
mod state;
mod state_checks;
mod state_continue;
mod steady_summary;
mod stepped;
mod sweep;
mod sweep_charts;
mod sweep_docs;
mod sweep_shards;
mod verdict;
