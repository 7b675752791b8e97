//! # gdsmc
//!
//! The runner of the gdsmc DSMC engine: scenes (the `gdsmc-scene` crate), ensembles over all
//! cores with deterministic streams, statistics with 99.9% confidence intervals, the references
//! beside them (the `gdsmc-theory` crate) and output files. The `gdsmc` command is a thin shell
//! over this library.
//!
//! The modules depend on each other in one direction:
//! [`run`] (ensembles, statistics) <- [`analysis`] (tails, distributions, warnings) <-
//! [`report`] (output sets, charts, summary) <- [`mod@bench`] (speed), [`job`] (a run from the
//! loaded scene to the written outputs: journal, shards, MPI, output set; the command's `run`
//! and `merge` and the Python package call it) <- [`sweep`] (a parameter study: many journaled
//! runs into one table); [`reproduce`] (the papers' tables) needs [`run`] only. Every module
//! takes the exact and hydrodynamic curves from `gdsmc-theory`. Beneath them all, [`files`]:
//! writing and reading files safely (never through a link, never over what gdsmc did not
//! write), and [`watch`]: what the caller sees of a running job and how it stops one.

#![deny(unsafe_code)]

pub mod analysis;
// The bench times loops by the thread's CPU clock, which a browser does not have.
#[cfg(not(target_family = "wasm"))]
pub mod bench;
pub mod clock;
pub mod error;
pub mod files;
pub mod job;
pub mod report;
pub mod reproduce;
pub mod run;
pub mod sweep;
#[cfg(feature = "cli")]
pub mod terminal;
pub mod watch;
pub use gdsmc_scene as scene;

pub use error::Error;
/// The version of the random streams every run draws from (outputs and journals state it).
pub use gdsmc_core::rng::STREAM_VERSION;
