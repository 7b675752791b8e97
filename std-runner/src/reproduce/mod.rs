//! `gdsmc reproduce`: every table of the four papers (GRW Tables 1-2, RW Tables 1-6, BRS
//! Tables 1-2 with the equilibrium temperatures of Examples 4-5, MS Table 1), our figures
//! printed beside the paper's, each with its 99.9% half-width and, where one is known, the
//! exact expected value of the paper's estimator at the paper's `n`.
//!
//! A cell agrees when `|ours - paper| <= ours_ci + paper_ci + rounding + bias`: our half-width,
//! the paper's (published, or ours rescaled to the paper's number of ensembles when the paper
//! gives none), half a unit of the paper's last printed digit, and a stated finite-`n` bias
//! where we run fewer particles than the paper. Noise-only figures (GRW's `||V||_inf`) must lie
//! below their 99.9% bound at our size instead.
//!
//! `--quick` keeps every table but runs fewer ensembles (and skips the costliest rows, listed
//! in the report); the full mode runs the papers' sizes.

mod brs;
mod cells;
mod grw;
mod ms;
mod report;
mod runs;
mod rw;

pub use cells::{Cell, Check, Row, Table, rounding};
pub use report::{markdown, text};
pub(crate) use runs::{at, ensembles, go, max_relative_error, scene, steady};

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

/// Every table, in paper order.
pub const TABLES: &[Entry] = &[
    grw::TABLE1,
    grw::TABLE2,
    rw::TABLE1,
    rw::TABLE2,
    rw::TABLE3,
    rw::TABLE4,
    rw::TABLE5,
    rw::TABLE6,
    brs::TABLE1,
    brs::TABLE2,
    brs::EQUILIBRIA,
    ms::TABLE1,
];

/// Runs the named tables (all when `names` is empty), calling `done` after each.
pub fn run(
    names: &[String],
    opts: &Options,
    mut done: impl FnMut(&Table),
) -> Result<Vec<Table>, Error> {
    for n in names {
        if !TABLES.iter().any(|e| e.name == n) {
            let known: Vec<_> = TABLES.iter().map(|e| e.name).collect();
            return Err(Error::Argument {
                flag: format!("reproduce {n}"),
                message: format!("is not a table; known: {}", known.join(", ")),
            });
        }
    }
    let mut out = Vec::new();
    for (j, e) in TABLES.iter().enumerate() {
        if names.is_empty() || names.iter().any(|n| n == e.name) {
            let t = (e.run)(opts, opts.seed.wrapping_add(1000 * j as u64))?;
            done(&t);
            out.push(t);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::runs::SCENES;
    use super::*;

    #[test]
    fn rounding_is_half_the_third_digit() {
        assert!((rounding(0.895e-1) - 0.5e-4).abs() < 1e-15);
        assert!((rounding(2.6684) - 0.005).abs() < 1e-15);
        assert_eq!(rounding(0.0), 0.0);
    }

    #[test]
    fn a_cell_agrees_within_its_tolerance_only() {
        let c = Cell::within("x", 1.0, (1.1, 0.05), 0.04).rounding(0.0);
        assert_eq!(c.agrees(), Some(false));
        let c = Cell::within("x", 1.0, (1.08, 0.05), 0.04).rounding(0.0);
        assert_eq!(c.agrees(), Some(true));
        let c = Cell::within("x", 1.0, (f64::NAN, 0.05), 0.04);
        assert_eq!(c.agrees(), Some(false));
        let c = Cell {
            check: Check::Below {
                paper_bound: 1.0,
                ours_bound: 2.0,
            },
            ..Cell::within("v", 1.5, (1.0, 0.0), 0.0)
        };
        assert_eq!(c.agrees(), Some(true));
        let c = Cell { ours: 2.5, ..c };
        assert_eq!(c.agrees(), Some(false));
    }

    #[test]
    fn every_compiled_scene_parses() {
        for (name, _) in SCENES {
            let s = scene(name, &[], 8, 2, 1);
            assert_eq!(s.n(), 8);
        }
    }

    #[test]
    fn an_unknown_table_is_named() {
        let o = Options {
            quick: true,
            threads: 1,
            seed: 1,
        };
        let e = run(&["grw-table9".into()], &o, |_| {}).unwrap_err();
        let m = e.to_string();
        assert!(m.contains("grw-table9") && m.contains("grw-table1"), "{m}");
    }
}
