//! `gdsmc reproduce`: every table of the four papers (GRW Tables 1-2, RW Tables 1-6, BRS
//! Tables 1-2 with the equilibrium temperatures of Examples 4-5, MS Table 1), our figures
//! printed beside the paper's, each judged by checks that could fail.
//!
//! A cell's checks (cells.rs) each judge one figure, the paper's or ours, against a range that
//! holds at the 99.9% level, and say what the range is made of: where the estimator's
//! expectation is known exactly (bounds.rs, judged.rs) the paper's figure is judged against it
//! with the paper's noise (its stated interval read as the paper defines it, or ours rescaled
//! to its ensembles) and ours with ours; elsewhere ours is judged against the paper's figure
//! with both noises. A range that holds 0, or ten times the expected value, makes its cell
//! uninformative, never agreeing; every table is checked for that when it is made
//! ([`self_check`]). Disputes are computed (ms.rs: the cooling-state check).
//!
//! `--quick` keeps every table but runs fewer ensembles (and skips the costliest rows, listed
//! in the report); the full mode runs the papers' sizes.

mod bounds;
mod brs;
mod cells;
mod command;
mod entry;
mod figure;
mod grw;
mod judged;
mod ms;
mod report;
mod runs;
mod rw;

pub use cells::{
    Against, Blame, Cell, Check, Counts, Joint, POWER, POWER_PROBABILITY, ReadingScores, Row, Side,
    Table, Verdict, percent, rounding,
};
pub use command::command;
pub use entry::{Entry, Options};
pub use figure::fmt;
pub use report::{epilogue, markdown, text};
pub use runs::with_cached_runs;
pub(crate) use runs::{at, ensembles, go, largest, relative, scene, steady};

use crate::Error;

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

/// Every figure of ours that misses its range, as "table: figure" (empty when the run passes).
pub fn failures(tables: &[Table]) -> Vec<String> {
    tables
        .iter()
        .flat_map(|t| {
            t.failures()
                .into_iter()
                .map(move |d| format!("{}: {d}", t.name))
        })
        .collect()
}

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
    let mut out: Vec<Table> = Vec::new();
    for (j, e) in TABLES.iter().enumerate() {
        if names.is_empty() || names.iter().any(|n| n == e.name) {
            let t = (e.run)(opts, opts.seed.wrapping_add(1000 * j as u64))?;
            self_check(&t)?;
            out.push(t);
            let checks: usize = out
                .iter()
                .flat_map(|t| &t.rows)
                .flat_map(|r| &r.cells)
                .map(|c| c.checks.len())
                .sum();
            if checks > bounds::FAMILY {
                return Err(Error::Argument {
                    flag: "reproduce".into(),
                    message: format!(
                        "{checks} checks exceed the {} the run's Bonferroni level allows \
                         (bounds::FAMILY)",
                        bounds::FAMILY
                    ),
                });
            }
            done(out.last().expect("just pushed"));
        }
    }
    Ok(out)
}

/// Every judged cell of `t` refuses a computed 0 and a value ten times the expected one: had
/// our figure been either, the cell would disagree or be uninformative, never agree. An error
/// here is a bug in how the table builds its checks.
pub fn self_check(t: &Table) -> Result<(), Error> {
    for r in &t.rows {
        for c in &r.cells {
            let tens = c
                .checks
                .iter()
                .filter(|k| k.side == Side::Ours)
                .map(|k| 10.0 * k.expected);
            for x in std::iter::once(0.0).chain(tens) {
                if c.verdict_with(x) == Verdict::Agree {
                    return Err(Error::Argument {
                        flag: format!("reproduce {}", t.name),
                        message: format!(
                            "{}, {}: a computed {x} would agree ({}); the check cannot fail",
                            r.label,
                            c.quantity,
                            c.basis()
                        ),
                    });
                }
            }
            if !c.checks.is_empty() && !c.checks.iter().any(|k| k.side == Side::Ours) {
                return Err(Error::Argument {
                    flag: format!("reproduce {}", t.name),
                    message: format!("{}, {}: our figure is not judged", r.label, c.quantity),
                });
            }
        }
    }
    Ok(())
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

    fn exact_cell(paper: f64, ours: f64) -> Cell {
        Cell::new("x", paper, (ours, 0.05))
            .check(Check::around(Side::Ours, Against::Exact, 1.0, 0.05, "ours"))
            .check(Check::around(
                Side::Paper,
                Against::Exact,
                1.0,
                0.06,
                "paper",
            ))
    }

    /// A cell whose paper check has score `zp` and our check `zo`.
    fn scored(zp: f64, zo: f64) -> Cell {
        Cell::new("x", 1.0, (1.0, 0.1))
            .check(Check::around(Side::Ours, Against::Exact, 1.0, 0.1, "").with_z(zo))
            .check(Check::around(Side::Paper, Against::Exact, 1.0, 0.1, "").with_z(zp))
    }

    /// The table-wide test: chi^2 and the largest score against their laws, computed by hand,
    /// and a shared offset of 3 sigma over four figures found while a scatter of +-0.5 is not.
    #[test]
    fn table_wide_test_finds_a_shared_offset() {
        let t = one_row_table((0..4).map(|_| scored(3.0, 0.5)).collect());
        let j = t.joint(Side::Paper).expect("four scores");
        assert_eq!(j.k, 4);
        assert!((j.chi2 - 36.0).abs() < 1e-12);
        // P(chi^2_4 > 36) = e^(-18) (1 + 18), the closed form for 4 degrees of freedom.
        let p = libm::exp(-18f64) * 19.0;
        assert!(
            (j.p_chi2 / p - 1.0).abs() < 1e-9,
            "{} against {p}",
            j.p_chi2
        );
        assert!((j.mean_z - 3.0).abs() < 1e-12);
        // Sidak: 1 - (1 - 0.0026998)^4.
        assert!((j.p_max - (1.0 - (1.0f64 - 0.002_699_796).powi(4))).abs() < 1e-7);
        assert!(j.off(), "{}", j.line());
        let ours = t.joint(Side::Ours).expect("four scores");
        assert!(!ours.off(), "{}", ours.line());
        assert!(
            one_row_table(vec![scored(9.0, 0.0)])
                .joint(Side::Paper)
                .is_none()
        );
        // A score that is not finite is no score.
        let nan = Check::around(Side::Ours, Against::Exact, 1.0, 0.1, "").with_z(f64::NAN);
        assert_eq!(nan.z, None);
    }

    /// Table `t` of one row `r` holding `cells`.
    fn one_row_table(cells: Vec<Cell>) -> Table {
        Table {
            name: "t",
            title: "t",
            notes: String::new(),
            rows: vec![Row {
                label: "r".into(),
                n: 2,
                ensembles: 2,
                seconds: 0.0,
                cells,
            }],
            skipped: vec![],
            findings: vec![],
            readings: vec![],
        }
    }

    #[test]
    fn verdicts_and_blame() {
        assert_eq!(exact_cell(1.05, 1.02).verdict(), Verdict::Agree);
        assert_eq!(
            exact_cell(1.2, 1.02).verdict(),
            Verdict::Disagree(Blame::Paper)
        );
        assert_eq!(
            exact_cell(1.05, 1.08).verdict(),
            Verdict::Disagree(Blame::Ours)
        );
        assert_eq!(
            exact_cell(1.2, 1.08).verdict(),
            Verdict::Disagree(Blame::Ours)
        );
        assert_eq!(
            exact_cell(1.0, f64::NAN).verdict(),
            Verdict::Disagree(Blame::Ours)
        );
        let mut c = exact_cell(1.2, 1.02);
        c.dispute = Some("evidence".into());
        assert_eq!(c.verdict(), Verdict::Disputed);
        let c = Cell::new("x", 1.0, (1.05, 0.0)).check(Check::around(
            Side::Ours,
            Against::Other,
            1.0,
            0.06,
            "both",
        ));
        assert_eq!(c.verdict(), Verdict::Agree);
        assert_eq!(c.verdict_with(1.3), Verdict::Disagree(Blame::Unresolved));
        assert!(Verdict::Disagree(Blame::Unresolved).against_us());
        assert!(!Verdict::Disagree(Blame::Paper).against_us());
        // The run fails only beyond the report-wide range: 1 +- 0.2 here, 1 +- 0.3 for the run.
        let c = Cell {
            checks: vec![
                Check::around(Side::Ours, Against::Other, 1.0, 0.2, "both").report_range(0.3),
            ],
            ..c
        };
        assert!(!c.fails_run());
        assert!(
            !Cell {
                ours: 1.25,
                ..c.clone()
            }
            .fails_run()
        );
        assert!(
            Cell {
                ours: 1.35,
                ..c.clone()
            }
            .fails_run()
        );
        assert!(
            !Cell {
                ours: 1.35,
                dispute: Some("evidence".into()),
                ..c.clone()
            }
            .fails_run()
        );
        // A paper's figure off an exact value never fails the run.
        assert!(!exact_cell(5.0, 1.0).fails_run());
        assert_eq!(Cell::shown("x", 1.0, 2.0).verdict(), Verdict::Shown);
    }

    /// A check that can fail but lets through more than `POWER` of the quantity is weak, not
    /// agreement. Its power is the error caught with probability 0.95: the reach plus 1.645
    /// standard deviations of the figure's noise (taken as the whole tolerance at 3.2 sigma
    /// unless set): 1 +- 0.2 catches 0.2 + 1.645 x 0.2 / 3.2 = 30%; 1 +- 0.06 catches 9.1% and
    /// agrees. Its power is printed in the basis; a row's effect, when set, is the scale.
    #[test]
    fn a_check_wider_than_the_power_is_weak() {
        let cell = |tol: f64| {
            Cell::new("E", 1.0, (1.05, 0.0)).check(Check::around(
                Side::Ours,
                Against::Exact,
                1.0,
                tol,
                "range",
            ))
        };
        let weak = cell(0.2);
        let want = 0.2 * (1.0 + 1.6448536269514722 / 3.2);
        assert!((weak.detectable().unwrap() - want).abs() < 1e-12);
        assert_eq!(weak.verdict(), Verdict::Weak);
        assert_eq!(weak.verdict_with(1.3), Verdict::Disagree(Blame::Ours));
        assert!(weak.basis().contains("detects 30%"), "{}", weak.basis());
        assert_eq!(cell(0.06).verdict(), Verdict::Agree);
        // The half-width alone within POWER is not enough: 0.09 + 1.645 x 0.09 / 3.2 > 0.1.
        assert_eq!(cell(0.9 * POWER).verdict(), Verdict::Weak);
        // A known noise: 1 +- 0.08 with sd 0.01 catches 9.6%.
        assert_eq!(
            Cell::new("E", 1.0, (1.05, 0.0))
                .check(Check::around(Side::Ours, Against::Exact, 1.0, 0.08, "").with_sd(0.01))
                .verdict(),
            Verdict::Agree
        );
        // Judged against the row's effect (here 0.5 of the value): 9.1% of the value is 18%
        // of the effect, weak.
        let on_effect = cell(0.06).effect(0.5, "the effect");
        assert_eq!(on_effect.verdict(), Verdict::Weak);
        assert!(
            on_effect.basis().contains("18% of the effect"),
            "{}",
            on_effect.basis()
        );
        // Asymmetric: the wider side decides; a negative expectation counts by its size.
        let c = Check {
            lo: 0.95,
            hi: 1.3,
            ..Check::around(Side::Ours, Against::Exact, 1.0, 0.0, "")
        };
        assert!((c.detectable() - 0.3).abs() < 1e-12);
        let c = Check::around(Side::Ours, Against::Exact, -2.0, 0.1, "");
        assert!((c.detectable() - 0.05 * (1.0 + 1.6448536269514722 / 3.2)).abs() < 1e-12);
        assert_eq!(
            Check::around(Side::Ours, Against::Exact, 0.0, 0.1, "").detectable(),
            f64::INFINITY
        );
        let t = one_row_table(vec![weak, cell(0.05)]);
        let k = Counts::of([&t]);
        assert_eq!((k.agree, k.weak), (1, 1));
        assert!(
            epilogue(&[t]).contains("t r: E (detects 30% of the quantity)"),
            "the epilogue names the weak cell and its power"
        );
    }

    #[test]
    fn percents_have_two_significant_digits() {
        assert_eq!(percent(0.041), "4.1%");
        assert_eq!(percent(0.0052), "0.52%");
        assert_eq!(percent(1.3), "130%");
        assert_eq!(percent(0.1), "10%");
        assert_eq!(percent(f64::INFINITY), "no error");
    }

    /// A range as wide as the value (here 1 +- 1) passes a computed 0: uninformative, and the
    /// self-check accepts the table because such a cell never says "agree".
    #[test]
    fn a_range_that_holds_zero_is_uninformative() {
        let c = Cell::new("E", 1.0, (1.1, 0.0)).check(Check::around(
            Side::Ours,
            Against::Exact,
            1.0,
            1.0,
            "wide",
        ));
        assert_eq!(c.verdict(), Verdict::Uninformative);
        assert_eq!(c.verdict_with(0.0), Verdict::Uninformative);
        assert_eq!(c.verdict_with(10.0), Verdict::Disagree(Blame::Ours));
        let t = one_row_table(vec![c, exact_cell(1.05, 1.02)]);
        assert!(self_check(&t).is_ok());
        assert_eq!(
            Counts::of([&t]),
            Counts {
                agree: 1,
                uninformative: 1,
                ..Counts::default()
            }
        );
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
