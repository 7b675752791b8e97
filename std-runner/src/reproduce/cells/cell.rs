//! One figure of a table: the paper's, ours and the checks that judge them ([`Cell`]), and how
//! a figure's error and rounding are written.

use super::{Against, Blame, Check, POWER, Side, Verdict};
use std::fmt::Write;

/// One figure of a table: the paper's, ours, and the checks that judge them.
#[derive(Clone, Debug)]
pub struct Cell {
    /// Column name, as in the paper.
    pub quantity: String,
    /// The paper's figure.
    pub paper: f64,
    /// Ours.
    pub ours: f64,
    /// Half-width of our 99.9% confidence interval (0 for a figure computed without noise).
    pub ours_ci: f64,
    /// The exact expected value of the estimator, when known.
    pub exact: Option<f64>,
    /// The judgements (none: shown only).
    pub checks: Vec<Check>,
    /// The evidence, computed in the same run, that the paper's figure is off; turns a
    /// disagreement into [`Verdict::Disputed`] (it does not touch a cell that agrees).
    pub dispute: Option<String>,
    /// The size of the effect the row studies, when it is not the figure itself (RW's steady
    /// temperatures: the time step's shift, or the raw term, is what a row shows), and its
    /// words: the power rule asks the checks to catch [`POWER`] of it.
    pub effect: Option<(f64, &'static str)>,
}

impl Cell {
    /// A cell with our figure and its half-width, not yet judged.
    pub fn new(quantity: &str, paper: f64, ours: (f64, f64)) -> Self {
        Cell {
            quantity: quantity.into(),
            paper,
            ours: ours.0,
            ours_ci: ours.1,
            exact: None,
            checks: Vec::new(),
            dispute: None,
            effect: None,
        }
    }

    /// A cell only shown, not judged.
    pub fn shown(quantity: &str, paper: f64, ours: f64) -> Self {
        Cell::new(quantity, paper, (ours, 0.0))
    }

    /// Adds a check.
    pub fn check(mut self, c: Check) -> Self {
        self.checks.push(c);
        self
    }

    /// Sets the effect the row studies ([`Cell::effect`]): `size` in the figure's units.
    #[must_use]
    pub fn effect(mut self, size: f64, what: &'static str) -> Self {
        self.effect = Some((size.abs(), what));
        self
    }

    /// What a check's power is judged against: the row's effect, or the check's own expected
    /// value.
    fn scale(&self, c: &Check) -> f64 {
        self.effect.map_or(c.expected.abs(), |e| e.0)
    }

    /// Sets the exact expected value.
    pub fn exact(mut self, x: f64) -> Self {
        self.exact = Some(x);
        self
    }

    /// The verdict.
    pub fn verdict(&self) -> Verdict {
        self.verdict_with(self.ours)
    }

    /// The verdict had our figure been `ours` (the tests feed 0 and values ten times off).
    pub fn verdict_with(&self, ours: f64) -> Verdict {
        self.judge(ours, POWER)
    }

    /// The verdict under a power rule of `power` instead of [`POWER`] (`f64::INFINITY`: the
    /// rule before it, every informative check agreeing): for the mutation check's test,
    /// which shows that without the rule it would find cells that miss a wrong reference.
    pub fn verdict_at_power(&self, power: f64) -> Verdict {
        self.judge(self.ours, power)
    }

    /// The verdict with our figure `ours` under a power rule of `power`.
    fn judge(&self, ours: f64, power: f64) -> Verdict {
        if self.checks.is_empty() {
            return Verdict::Shown;
        }
        let mut blame: Option<Blame> = None;
        let mut informative = true;
        let mut powerful = true;
        for c in &self.checks {
            let x = match c.side {
                Side::Paper => self.paper,
                Side::Ours => ours,
            };
            if !c.passes(x) {
                let b = c.blame();
                blame = Some(blame.map_or(b, |a| a.max(b)));
            }
            informative &= c.informative();
            powerful &= c.reach() <= power * self.scale(c);
        }
        match (blame, &self.dispute) {
            (Some(_), Some(_)) => Verdict::Disputed,
            (Some(b), None) => Verdict::Disagree(b),
            (None, _) if !informative => Verdict::Uninformative,
            (None, _) if !powerful => Verdict::Weak,
            (None, _) => Verdict::Agree,
        }
    }

    /// Whether the cell fails the run: a check that puts the disagreement on us, or on
    /// nobody, fails at the report's level too (Bonferroni over the report: with a hundred
    /// cells at 99.9% each, one would miss by chance every tenth run), and no consistency check
    /// disputes it.
    pub fn fails_run(&self) -> bool {
        self.dispute.is_none()
            && self.checks.iter().any(|c| {
                let x = match c.side {
                    Side::Paper => self.paper,
                    Side::Ours => self.ours,
                };
                c.blame() != Blame::Paper && !c.passes_family(x)
            })
    }

    /// Whether the published figure lies within one standard deviation of its noise of an end of
    /// a range built around an exact value (inside or outside): a redraw of the paper's
    /// ensembles would land on the other side with probability over 16%, so its agreement, or
    /// its finding of a published figure off, is fragile (a small error of the exact value
    /// would flip it too). The report marks such cells "at the edge".
    pub fn at_edge(&self) -> bool {
        self.checks.iter().any(|c| {
            c.side == Side::Paper
                && c.against == Against::Exact
                && c.sd > 0.0
                && (self.paper - c.lo).abs().min((self.paper - c.hi).abs()) < c.sd
        })
    }

    /// The verdict's word, with "at the edge" where [`Cell::at_edge`].
    pub fn word(&self) -> String {
        let v = self.verdict();
        if self.at_edge() && v != Verdict::Shown {
            format!("{} (at the edge)", v.word())
        } else {
            v.word().to_string()
        }
    }

    /// The least power of the cell's checks (the largest error one of them lets through with
    /// probability [`super::POWER_PROBABILITY`], [`Check::reach`], relative to the row's effect or
    /// to the check's expected value), `None` for a cell only shown.
    pub fn detectable(&self) -> Option<f64> {
        self.checks
            .iter()
            .map(|c| self.relative_reach(c))
            .reduce(f64::max)
    }

    /// A check's [`Check::reach`] relative to what the cell's power is judged against
    /// ([`Cell::scale`]; infinite against 0).
    fn relative_reach(&self, c: &Check) -> f64 {
        let scale = self.scale(c);
        if scale == 0.0 {
            f64::INFINITY
        } else {
            c.reach() / scale
        }
    }

    /// The words of what [`Cell::detectable`] is relative to.
    pub fn power_of(&self) -> &'static str {
        self.effect.map_or("the quantity", |e| e.1)
    }

    /// The checks as one line: `paper in [lo, hi], detects 4.1% (basis); ours in [...]`.
    pub fn basis(&self) -> String {
        let mut s = String::new();
        for (i, c) in self.checks.iter().enumerate() {
            let side = match c.side {
                Side::Paper => "paper",
                Side::Ours => "ours",
            };
            let _ = write!(
                s,
                "{}{side} in [{}, {}]{}: {}",
                if i > 0 { "; " } else { "" },
                crate::reproduce::figure::fmt(c.lo),
                crate::reproduce::figure::fmt(c.hi),
                if c.informative() {
                    match self.effect {
                        None => format!(", detects {}", percent(c.detectable())),
                        Some((_, what)) => format!(
                            ", detects {} ({} of {what})",
                            percent(c.detectable()),
                            percent(self.relative_reach(c))
                        ),
                    }
                } else {
                    " (cannot fail)".into()
                },
                c.basis
            );
        }
        s
    }
}

/// A relative error as a percentage with two significant digits (`4.1%`, `0.52%`, `130%`).
pub fn percent(r: f64) -> String {
    if !r.is_finite() {
        return "no error".into();
    }
    let p = 100.0 * r;
    let decimals = if p >= 10.0 {
        0
    } else if p >= 1.0 {
        1
    } else {
        (1.0 - libm::log10(p).floor()).clamp(1.0, 6.0) as usize
    };
    format!("{p:.decimals$}%")
}

/// Half a unit of the last of three significant digits (the papers print three or four; three
/// is the coarser, used where the table gives no fixed decimals).
pub fn rounding(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return 0.0;
    }
    0.5 * libm::pow(10f64, libm::log10(x.abs()).floor() - 2.0)
}
