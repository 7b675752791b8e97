//! Core integration tests, one test binary: each file of this directory is a module here (one link of
//! the engine instead of one per file: the test build is faster and its binaries a fraction
//! of the disk). Run one file's tests with `cargo test --release -p gdsmc-core --test all FILE::`.

// The tests' own expected values may use std's math: a tolerance compares them, not bits
// (clippy.toml keeps it out of what computes outputs).
#![allow(clippy::disallowed_methods)]

mod background_rate;
mod batch_kernels;
mod collision_maps;
mod collisional;
mod common;
mod disks;
mod engine_invariants;
mod histograms;
mod host_medium_choice;
mod kernel_acceptance;
mod mixture_host_medium;
mod mixture_laws;
mod mixture_maps;
mod mixture_time_stepped;
mod physics;
mod rescaling;
mod restitution_law;
mod rough_gas;
mod rough_laws;
mod rough_maps;
mod rough_mixture;
mod rough_mixture_equipartition;
mod samplers;
mod stream_v2;
mod sum_majorant;
mod weighted;
mod weighted_reduction;
mod work_rate;
