//! A reproducible table as the tables declare it, and how to run them.

use super::Table;
use crate::Error;

/// How to run the tables.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// Reduced sizes, for CI (minutes instead of hours).
    pub quick: bool,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Base seed; row `k` of table `j` uses `seed + 1000 j + k`.
    pub seed: u64,
}

/// A reproducible table: its name and how to make it.
pub struct Entry {
    /// Short name (`gdsmc reproduce NAME`).
    pub name: &'static str,
    /// One line.
    pub title: &'static str,
    /// Runs it.
    pub run: fn(&Options, u64) -> Result<Table, Error>,
}
