//! # gdsmc
//!
//! The runner of the gdsmc DSMC engine: scenes (TOML), ensembles over all cores with
//! deterministic streams, statistics with 99.9% confidence intervals, exact references and
//! output files. The `gdsmc` command is a thin shell over this library.

pub mod bench;
pub mod charts;
pub mod columns;
pub mod distribution;
pub mod ensemble;
pub mod error;
pub mod hydro;
pub mod output;
pub mod reference;
pub mod references;
pub mod reproduce;
pub use gdsmc_scene as scene;
pub mod stats;
pub mod summary;
pub mod tails;
pub mod warnings;

pub use error::Error;
