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
mod grw;
mod ms;
mod report;
mod rw;

pub use report::{markdown, text};

use crate::Error;
use crate::ensemble::{self, RunStats};
use crate::scene::{self, Scene};
use std::path::Path;
use std::time::Instant;

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

/// How a cell is judged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Check {
    /// `|ours - paper| <= ours_ci + paper_ci + rounding + bias`.
    Within {
        /// The paper's 99.9% half-width (published or estimated, see the table's notes).
        paper_ci: f64,
        /// Half a unit of the paper's last printed digit.
        rounding: f64,
        /// Allowance for a stated systematic difference (finite `n`); 0 when none.
        bias: f64,
    },
    /// A noise-only figure: ours must lie below `ours_bound`, its 99.9% bound at our size;
    /// `paper_bound` (the same bound at the paper's size) is printed beside the paper's figure.
    Below {
        /// Bound for the paper's run.
        paper_bound: f64,
        /// Bound for ours.
        ours_bound: f64,
    },
    /// Printed for comparison, not judged (the table's notes say why).
    Shown,
}

/// One figure of a table: the paper's, ours, and how they are compared.
#[derive(Clone, Debug)]
pub struct Cell {
    /// Column name, as in the paper.
    pub quantity: String,
    /// The paper's figure.
    pub paper: f64,
    /// Ours.
    pub ours: f64,
    /// Half-width of our 99.9% confidence interval.
    pub ours_ci: f64,
    /// The exact expected value of the paper's estimator at the paper's size, when known.
    pub exact: Option<f64>,
    /// The rule.
    pub check: Check,
    /// Why we believe the paper's figure is off, when we do (the table's notes give the
    /// evidence). A disputed cell is still judged and printed, but does not fail the run.
    pub disputed: Option<&'static str>,
}

impl Cell {
    /// A cell judged by [`Check::Within`].
    pub fn within(quantity: &str, paper: f64, ours: (f64, f64), paper_ci: f64) -> Self {
        Cell {
            quantity: quantity.into(),
            paper,
            ours: ours.0,
            ours_ci: ours.1,
            exact: None,
            check: Check::Within {
                paper_ci,
                rounding: rounding(paper),
                bias: 0.0,
            },
            disputed: None,
        }
    }

    /// A cell only shown, not judged.
    pub fn shown(quantity: &str, paper: f64, ours: f64) -> Self {
        Cell {
            quantity: quantity.into(),
            paper,
            ours,
            ours_ci: 0.0,
            exact: None,
            check: Check::Shown,
            disputed: None,
        }
    }

    /// Marks the paper's figure as disputed, with the reason.
    pub fn disputed(mut self, why: &'static str) -> Self {
        self.disputed = Some(why);
        self
    }

    /// Sets the exact expected value.
    pub fn exact(mut self, x: f64) -> Self {
        self.exact = Some(x);
        self
    }

    /// Sets the finite-size allowance of a [`Check::Within`] cell.
    pub fn bias(mut self, b: f64) -> Self {
        if let Check::Within { bias, .. } = &mut self.check {
            *bias = b;
        }
        self
    }

    /// Sets the rounding allowance of a [`Check::Within`] cell (for figures printed with
    /// a fixed number of decimals rather than significant digits).
    pub fn rounding(mut self, r: f64) -> Self {
        if let Check::Within { rounding, .. } = &mut self.check {
            *rounding = r;
        }
        self
    }

    /// The tolerance of a [`Check::Within`] cell.
    pub fn tolerance(&self) -> Option<f64> {
        match self.check {
            Check::Within {
                paper_ci,
                rounding,
                bias,
            } => Some(self.ours_ci + paper_ci + rounding + bias),
            _ => None,
        }
    }

    /// Whether the cell agrees (`None` for a cell only shown). NaN never agrees.
    pub fn agrees(&self) -> Option<bool> {
        match self.check {
            Check::Within { .. } => {
                Some((self.ours - self.paper).abs() <= self.tolerance().unwrap_or(f64::NAN))
            }
            Check::Below {
                paper_bound,
                ours_bound,
            } => {
                let _ = paper_bound;
                Some(self.ours <= ours_bound)
            }
            Check::Shown => None,
        }
    }
}

/// Half a unit of the last of three significant digits (the papers print three or four; three
/// is the coarser, used where the table gives no fixed decimals).
pub fn rounding(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return 0.0;
    }
    0.5 * 10f64.powf(x.abs().log10().floor() - 2.0)
}

/// One row: its label, its size and its cells.
#[derive(Clone, Debug)]
pub struct Row {
    /// Label (the paper's first columns, e.g. `n = 64`).
    pub label: String,
    /// Particles.
    pub n: usize,
    /// Our ensembles (the paper's in the table's notes).
    pub ensembles: u64,
    /// Wall seconds of our run.
    pub seconds: f64,
    /// The figures.
    pub cells: Vec<Cell>,
}

/// One reproduced table.
#[derive(Clone, Debug)]
pub struct Table {
    /// Short name, e.g. `grw-table1`.
    pub name: &'static str,
    /// Paper, table and what it shows.
    pub title: &'static str,
    /// How the figures are made and compared.
    pub notes: String,
    /// The rows run.
    pub rows: Vec<Row>,
    /// Rows of the paper left out in this mode.
    pub skipped: Vec<String>,
}

impl Table {
    /// Cells that disagree (and are not disputed), as `row: quantity` strings.
    pub fn disagreements(&self) -> Vec<String> {
        self.rows
            .iter()
            .flat_map(|r| {
                r.cells
                    .iter()
                    .filter(|c| c.agrees() == Some(false) && c.disputed.is_none())
                    .map(move |c| format!("{}: {}", r.label, c.quantity))
            })
            .collect()
    }
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

/// The shipped scenes, compiled in so that `reproduce` runs from any directory.
const SCENES: &[(&str, &str)] = &[
    (
        "grw-example3",
        include_str!("../../../scenes/grw-example3.toml"),
    ),
    (
        "grw-example4",
        include_str!("../../../scenes/grw-example4.toml"),
    ),
    (
        "rw-transient",
        include_str!("../../../scenes/rw-transient.toml"),
    ),
    ("rw-steady", include_str!("../../../scenes/rw-steady.toml")),
    (
        "rw-steady-30",
        include_str!("../../../scenes/rw-steady-30.toml"),
    ),
    (
        "brs-example1",
        include_str!("../../../scenes/brs-example1.toml"),
    ),
    (
        "brs-example2",
        include_str!("../../../scenes/brs-example2.toml"),
    ),
    (
        "brs-example4",
        include_str!("../../../scenes/brs-example4.toml"),
    ),
    (
        "brs-example5",
        include_str!("../../../scenes/brs-example5.toml"),
    ),
    (
        "ms-white-noise",
        include_str!("../../../scenes/ms-white-noise.toml"),
    ),
    (
        "ms-gaussian",
        include_str!("../../../scenes/ms-gaussian.toml"),
    ),
    (
        "ms-constant-force",
        include_str!("../../../scenes/ms-constant-force.toml"),
    ),
];

/// A shipped scene with overrides (`--set` syntax), `n` particles, `m` ensembles and a seed.
pub(crate) fn scene(name: &str, set: &[String], n: usize, m: u64, seed: u64) -> Scene {
    let text = SCENES
        .iter()
        .find(|(k, _)| *k == name)
        .map(|(_, t)| *t)
        .expect("a compiled-in scene");
    let path = format!("scenes/{name}.toml");
    let mut s = scene::parse_with_overrides(Path::new(&path), text, set)
        .expect("shipped scenes and reproduce's overrides are valid");
    s.physics.n = n;
    s.ensembles = m;
    s.seed = seed;
    s
}

/// Runs a scene, returning its statistics and wall seconds.
pub(crate) fn go(s: &Scene, opts: &Options) -> Result<(RunStats, f64), Error> {
    let t = Instant::now();
    let st = ensemble::run(s, opts.threads, &|_| {})?;
    Ok((st, t.elapsed().as_secs_f64()))
}

/// Ensembles for a row: the paper's `paper` in full mode; in quick mode as many as keep
/// `n * m` near `budget` (at least 16, at most the paper's).
pub(crate) fn ensembles(opts: &Options, n: usize, paper: u64, budget: u64) -> u64 {
    if opts.quick {
        (budget / n as u64).clamp(16, paper)
    } else {
        paper
    }
}

/// Mean and half-width of column `col` at time index `ti`.
pub(crate) fn at(st: &RunStats, ti: usize, col: &str) -> (f64, f64) {
    let c = st.col(col).expect("a known column");
    (st.mean(ti, c), st.ci(ti, c))
}

/// Steady-state mean and half-width of column `col`.
pub(crate) fn steady(st: &RunStats, col: &str) -> (f64, f64) {
    st.steady
        .as_ref()
        .expect("a steady-state scene")
        .mean_ci(st, st.col(col).expect("a known column"))
}

/// `max_t |mean(t) - exact(t)| / exact(t)` over the observation times with `t >= from`, and
/// the largest relative half-width there: GRW (29), RW's `E_max`, BRS's `Err`.
pub(crate) fn max_relative_error(
    st: &RunStats,
    col: &str,
    from: f64,
    exact: impl Fn(f64) -> f64,
) -> (f64, f64) {
    let mut e: f64 = 0.0;
    let mut ci: f64 = 0.0;
    for (ti, &t) in st.times.iter().enumerate() {
        if t < from {
            continue;
        }
        let (m, c) = at(st, ti, col);
        let x = exact(t);
        e = e.max(((m - x) / x).abs());
        ci = ci.max(c / x.abs());
    }
    (e, ci)
}

#[cfg(test)]
mod tests {
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
