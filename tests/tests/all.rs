//! Cross-crate validation, one test binary: each file of this directory is a module here (one link of
//! the engine instead of one per file: the test build is faster and its binaries a fraction
//! of the disk). Run one file's tests with `cargo test --release -p gdsmc-validation --test all FILE::`.

// The tests' own expected values may use std's math: a tolerance compares them, not bits
// (clippy.toml keeps it out of what computes outputs).
#![allow(clippy::disallowed_methods)]

mod cited_references;
mod combinations;
mod convergence_in_n;
mod cooling_and_thermostats;
mod cooling_rate;
mod determinism;
mod disks;
mod docs_links;
mod finite_outputs;
mod hard_spheres;
mod host_medium;
mod impact_speed;
mod langevin;
mod linear_heating;
mod maxwell_impact;
mod maxwell_relaxation;
mod mixture;
mod mixture_steady;
mod momentum;
mod mutated_scenes;
mod power_tail;
mod rough;
mod source_sizes;
mod splitting;
mod stability;
mod steady_state;
mod tail_warning;
mod thermostats_ms;
mod time_stepped;
mod timings;
mod weighted_scheme;
mod words;
mod work_limits;
