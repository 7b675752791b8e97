//! A paper's figure beside ours: [`Cell`], the [`Check`]s that judge it and its [`Verdict`];
//! [`Row`], [`Table`].
//!
//! A check says which figure it judges (the paper's or ours), the range that figure must lie
//! in, the value the range is built around, and what the range is made of with the source of
//! each part. A check is informative only when a computed 0, or a value ten times the expected
//! one, would fall outside its range; a cell with an uninformative check is reported as such,
//! never as agreeing. An informative check has a power too: the relative error of the judged
//! figure it catches with probability [`POWER_PROBABILITY`] ([`Check::detectable`]); a cell
//! agrees only if each of its checks would catch an error of [`POWER`] of the quantity its row
//! studies (the figure itself, or the effect the row measures, [`Cell::effect`]), else it is
//! [`Verdict::Weak`].

/// The relative error a check must catch for its cell to count as agreement: a tenth of the
/// quantity the row is about. The tables' quantities are the effects the papers study (a
/// temperature at a time, an error E_end or E_max made of the finite-n bias and the time-step
/// term, a tail amplitude): a check that lets the figure be off by more than a tenth of the
/// quantity itself cannot tell the paper's effect from a neighbouring one (Euler's first-order
/// term from Strang's at the tables' time steps differs by more than that), so it confirms
/// little. Checks wider than this are reported, with their power, as *weak*.
pub const POWER: f64 = 0.10;

/// The probability with which a check must catch an error for it to count as caught: an error
/// of [`Check::detectable`] puts the figure's mean beyond the range by this one-sided quantile
/// of its noise, so the figure falls outside with at least this probability (an error equal
/// to the half-width alone is caught only half the time).
pub const POWER_PROBABILITY: f64 = 0.95;

/// The one-sided standard normal quantile of [`POWER_PROBABILITY`] (1.645).
fn z_power() -> f64 {
    use statrs::distribution::{ContinuousCDF, Normal};
    Normal::standard().inverse_cdf(POWER_PROBABILITY)
}

/// Which figure a check judges.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The published figure.
    Paper,
    /// Our figure.
    Ours,
}

/// What a check's range is built around.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Against {
    /// A value known exactly (a closed form, the exact expectation of the estimator): a figure
    /// outside the range is that side's error.
    Exact,
    /// The other side's figure: a disagreement cannot be assigned to either side.
    Other,
}

/// One judgement: the figure of `side` must lie in `[lo, hi]` (the 99.9% range of this cell);
/// `[family_lo, family_hi]` is the same range at the 99.9% level of the whole report
/// (Bonferroni over `bounds::FAMILY` checks), which decides whether the run fails.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    /// The figure judged.
    pub side: Side,
    /// What the range is built around.
    pub against: Against,
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// Lower end at the report's level.
    pub family_lo: f64,
    /// Upper end at the report's level.
    pub family_hi: f64,
    /// The value the range is built around.
    pub expected: f64,
    /// What the range is made of, with the source of each part.
    pub basis: String,
    /// The judged figure's standard score against the law of its estimator, where that law is
    /// known to be (near) Gaussian with a known spread: what the table-wide test
    /// ([`Table::joint`]) sums. `None` for checks without one.
    pub z: Option<f64>,
    /// The standard deviation of the judged figure's noise, in its units (0 for a figure
    /// computed without noise): what an error must add to the range's reach to be caught with
    /// probability [`POWER_PROBABILITY`] ([`Check::detectable`]).
    pub sd: f64,
}

impl Check {
    /// `expected +- tol`, the same at the report's level; the figure's noise taken as all of
    /// `tol` at the 99.9% level, `sd = tol / 3.2` (the most it can be for a Gaussian figure:
    /// Student-t and Bonferroni multipliers are larger, a rounding part is no noise), until
    /// [`Check::with_sd`] says what it is.
    pub fn around(
        side: Side,
        against: Against,
        expected: f64,
        tol: f64,
        basis: impl Into<String>,
    ) -> Self {
        Check {
            side,
            against,
            lo: expected - tol,
            hi: expected + tol,
            family_lo: expected - tol,
            family_hi: expected + tol,
            expected,
            basis: basis.into(),
            z: None,
            sd: tol.abs() / gdsmc_stats::LAMBDA_999,
        }
    }

    /// Sets the standard deviation of the judged figure's noise ([`Check::sd`]).
    #[must_use]
    pub fn with_sd(mut self, sd: f64) -> Self {
        self.sd = sd;
        self
    }

    /// Sets the judged figure's standard score ([`Check::z`]).
    #[must_use]
    pub fn with_z(mut self, z: f64) -> Self {
        self.z = z.is_finite().then_some(z);
        self
    }

    /// Sets the report-level range to `expected +- tol`.
    pub fn report_range(mut self, tol: f64) -> Self {
        self.family_lo = self.expected - tol;
        self.family_hi = self.expected + tol;
        self
    }

    /// Whether `x` lies in the range (NaN never does).
    pub fn passes(&self, x: f64) -> bool {
        x.is_finite() && self.lo <= x && x <= self.hi
    }

    /// Whether `x` lies in the report-level range.
    pub fn passes_family(&self, x: f64) -> bool {
        x.is_finite() && self.family_lo <= x && x <= self.family_hi
    }

    /// Who is off when the check fails.
    pub fn blame(&self) -> Blame {
        match (self.side, self.against) {
            (Side::Paper, Against::Exact) => Blame::Paper,
            (Side::Ours, Against::Exact) => Blame::Ours,
            _ => Blame::Unresolved,
        }
    }

    /// Whether the check can fail: neither 0 nor ten times the expected value lies in its range.
    pub fn informative(&self) -> bool {
        let inside = |x: f64| self.lo <= x && x <= self.hi;
        self.lo.is_finite() && self.hi.is_finite() && !inside(0.0) && !inside(10.0 * self.expected)
    }

    /// The check's power in the figure's units: the smallest error `e` such that a figure
    /// whose mean is `expected + e` or `expected - e` falls outside the range with probability
    /// at least [`POWER_PROBABILITY`], `max(hi - expected, expected - lo) + 1.645 sd` (its
    /// noise Gaussian; infinite for an unbounded range).
    pub fn reach(&self) -> f64 {
        let reach = (self.hi - self.expected).max(self.expected - self.lo);
        if reach.is_finite() {
            reach + z_power() * self.sd
        } else {
            f64::INFINITY
        }
    }

    /// The check's power as a relative error: [`Check::reach`] over `|expected|` (infinite for
    /// an expected 0 or an unbounded range).
    pub fn detectable(&self) -> f64 {
        if self.expected == 0.0 {
            f64::INFINITY
        } else {
            self.reach() / self.expected.abs()
        }
    }
}

/// Who is off when a check fails.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Blame {
    /// The published figure lies outside the range of an exact value: a finding about the
    /// paper, not a failure of gdsmc.
    Paper,
    /// Ours and the paper's differ and nothing known exactly says which is off.
    Unresolved,
    /// Our figure lies outside the range of an exact value: gdsmc is wrong.
    Ours,
}

/// The verdict on a cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Every check passed and every check could have failed.
    Agree,
    /// A check failed.
    Disagree(Blame),
    /// A check failed, and a consistency check computed in the same run says the paper's
    /// figure is the one off (see [`Cell::dispute`]).
    Disputed,
    /// Every check passed and could have failed, but one would let an error of more than
    /// [`POWER`] of the quantity through (its power is printed beside it).
    Weak,
    /// Every check passed, but one could not have failed (its range holds 0 or ten times the
    /// expected value).
    Uninformative,
    /// Printed for comparison, not judged.
    Shown,
}

impl Verdict {
    /// The word printed in the tables.
    pub fn word(self) -> &'static str {
        match self {
            Verdict::Agree => "agree",
            Verdict::Disagree(Blame::Paper) => "DISAGREE (paper)",
            Verdict::Disagree(Blame::Unresolved) => "DISAGREE",
            Verdict::Disagree(Blame::Ours) => "DISAGREE (ours)",
            Verdict::Disputed => "disputed",
            Verdict::Weak => "weak",
            Verdict::Uninformative => "uninformative",
            Verdict::Shown => "shown",
        }
    }

    /// Whether the verdict is a disagreement that the exact values do not put on the paper
    /// (whether it fails the run is [`Cell::fails_run`]).
    pub fn against_us(self) -> bool {
        matches!(
            self,
            Verdict::Disagree(Blame::Ours) | Verdict::Disagree(Blame::Unresolved)
        )
    }
}

mod cell;
mod table;

pub use cell::{Cell, percent, rounding};
pub use table::{Counts, Joint, ReadingScores, Row, Table};
