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

use std::fmt::Write;

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
    /// probability [`POWER_PROBABILITY`], [`Check::reach`], relative to the row's effect or
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
                super::figure::fmt(c.lo),
                super::figure::fmt(c.hi),
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
        (1.0 - p.log10().floor()).clamp(1.0, 6.0) as usize
    };
    format!("{p:.decimals$}%")
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
    /// What the table's figures show together beyond the cells (e.g. which reading of the
    /// paper's estimator its figures fit), as sentences.
    pub findings: Vec<String>,
    /// The published figures' scores under two readings of what they estimate (RW's steady
    /// tables), which the report pools over its tables.
    pub readings: Vec<ReadingScores>,
}

/// A published figure's standard scores under two readings of what it estimates: RW (23)'s
/// raw temperature, and the temperature about the bulk velocity (RW's steady tables).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReadingScores {
    /// Against the exact mean of the raw temperature.
    pub raw: f64,
    /// Against the exact mean of the temperature about the bulk velocity.
    pub bulk: f64,
}

impl ReadingScores {
    /// The two readings' chi^2 tests over `scores` as a sentence: `the raw temperature of RW
    /// (23), chi^2 = .. on k (p = .., mean z = ..); the temperature about the bulk velocity, ..:
    /// RW's figures fit ..`.
    pub fn words(scores: &[ReadingScores]) -> String {
        use statrs::distribution::{ChiSquared, ContinuousCDF};
        let k = scores.len() as f64;
        let test = |z: &dyn Fn(&ReadingScores) -> f64| {
            let z: Vec<f64> = scores.iter().map(z).collect();
            let chi2: f64 = z.iter().map(|x| x * x).sum();
            let p = ChiSquared::new(k).map_or(f64::NAN, |c| c.sf(chi2));
            let mean = z.iter().sum::<f64>() / k;
            (chi2, p, mean)
        };
        let (raw, p_raw, m_raw) = test(&|r| r.raw);
        let (bulk, p_bulk, m_bulk) = test(&|r| r.bulk);
        format!(
            "the raw temperature of RW (23), chi^2 = {raw:.1} on {k} (p = {p_raw:.1e}, mean z = {m_raw:+.2}); the temperature about the bulk \
             velocity, chi^2 = {bulk:.1} on {k} (p = {p_bulk:.1e}, mean z = {m_bulk:+.2}): RW's \
             figures fit {}.",
            if p_bulk > 10.0 * p_raw && p_bulk > 0.01 {
                "the temperature about the bulk velocity better than RW (23)'s raw temperature"
            } else if p_raw > 10.0 * p_bulk && p_raw > 0.01 {
                "RW (23)'s raw temperature better than the temperature about the bulk velocity"
            } else {
                "neither reading decisively better"
            }
        )
    }
}

/// A table-wide test of one side's figures against their exact laws: the standard scores of
/// every check of that side that has one ([`Check::z`]), taken together.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Joint {
    /// Whose figures.
    pub side: Side,
    /// How many scores.
    pub k: usize,
    /// `sum z^2`, chi-squared with `k` degrees of freedom if every figure follows its law.
    pub chi2: f64,
    /// Its upper tail probability.
    pub p_chi2: f64,
    /// The mean score, `sum z / k`: a shared offset shows here (one-sided alternatives).
    pub mean_z: f64,
    /// The largest `|z|`.
    pub max_z: f64,
    /// The probability that the largest of `k` independent `|z|` is at least `max_z`
    /// (Sidak).
    pub p_max: f64,
    /// How many scores are 0: figures inside the bracket of their estimator's laws, where the
    /// conservative score is 0 ([`Check::z`]), so that a small chi^2 says they are not off,
    /// not that they fit better than chance.
    pub zeros: usize,
}

impl Joint {
    /// Whether the side's figures, taken together, are off their laws at the report's 99.9%
    /// level (either statistic, Bonferroni over the two).
    pub fn off(&self) -> bool {
        self.p_chi2.min(self.p_max) < 0.5 * gdsmc_stats::miss()
    }

    /// One line: `paper, 10 figures: chi^2 = 31.2 on 10 (p = 5e-4), mean z = +1.2, largest |z| = 3.5 (p = 5e-3)`.
    pub fn line(&self) -> String {
        format!(
            "{}, {} figures against their exact laws: chi^2 = {:.1} on {} (p = {:.1e}), mean z = \
             {:+.2}, largest |z| = {:.2} (p = {:.1e}){}{}",
            match self.side {
                Side::Paper => "the paper's",
                Side::Ours => "ours",
            },
            self.k,
            self.chi2,
            self.k,
            self.p_chi2,
            self.mean_z,
            self.max_z,
            self.p_max,
            if self.zeros > 0 {
                format!(
                    "; {} of the scores are 0 (inside the bracket of their laws: not off, which \
                     is all a conservative score can say)",
                    self.zeros
                )
            } else {
                String::new()
            },
            if self.off() { ": jointly off" } else { "" }
        )
    }
}

impl Table {
    /// The table-wide test of `side`'s figures ([`Joint`]), when at least two have scores.
    pub fn joint(&self, side: Side) -> Option<Joint> {
        use statrs::distribution::{ChiSquared, ContinuousCDF, Normal};
        let z: Vec<f64> = self
            .rows
            .iter()
            .flat_map(|r| &r.cells)
            .flat_map(|c| &c.checks)
            .filter(|k| k.side == side && k.against == Against::Exact)
            .filter_map(|k| k.z)
            .collect();
        if z.len() < 2 {
            return None;
        }
        let k = z.len();
        let chi2: f64 = z.iter().map(|x| x * x).sum();
        let max_z = z.iter().map(|x| x.abs()).fold(0.0, f64::max);
        let normal = Normal::standard();
        let one = 2.0 * normal.sf(max_z);
        Some(Joint {
            side,
            k,
            chi2,
            p_chi2: ChiSquared::new(k as f64).map_or(f64::NAN, |c| c.sf(chi2)),
            mean_z: z.iter().sum::<f64>() / k as f64,
            max_z,
            p_max: -f64::exp_m1(k as f64 * f64::ln_1p(-one)),
            zeros: z.iter().filter(|x| **x == 0.0).count(),
        })
    }
}

/// How many cells of each verdict a table (or a report) has.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// [`Verdict::Agree`].
    pub agree: usize,
    /// [`Verdict::Disagree`] with the paper's figure off an exact value.
    pub paper_off: usize,
    /// Other disagreements (ours off, or unresolved).
    pub failing: usize,
    /// Those of them beyond the report-level range: these fail the run.
    pub fails_run: usize,
    /// [`Verdict::Disputed`].
    pub disputed: usize,
    /// [`Verdict::Weak`].
    pub weak: usize,
    /// [`Verdict::Uninformative`].
    pub uninformative: usize,
    /// [`Verdict::Shown`].
    pub shown: usize,
}

impl Counts {
    /// Counts the cells of `tables`.
    pub fn of<'a>(tables: impl IntoIterator<Item = &'a Table>) -> Counts {
        let mut k = Counts::default();
        for c in tables
            .into_iter()
            .flat_map(|t| &t.rows)
            .flat_map(|r| &r.cells)
        {
            k.fails_run += usize::from(c.fails_run());
            match c.verdict() {
                Verdict::Agree => k.agree += 1,
                Verdict::Disagree(Blame::Paper) => k.paper_off += 1,
                Verdict::Disagree(_) => k.failing += 1,
                Verdict::Disputed => k.disputed += 1,
                Verdict::Weak => k.weak += 1,
                Verdict::Uninformative => k.uninformative += 1,
                Verdict::Shown => k.shown += 1,
            }
        }
        k
    }

    /// One line: `12 agree, 1 disagree (paper), 0 disagree, 2 disputed, 5 weak, 3
    /// uninformative, 4 shown`, with how many fail the run.
    pub fn line(&self) -> String {
        format!(
            "{} agree, {} disagree (the paper's figure off an exact value), {} disagree \
             (ours off, or unresolved; {} of them beyond the report-wide range, failing the run), \
             {} disputed, {} weak (agree, but would let an error of more than {} of the quantity \
             or its row's effect through with probability {}), {} uninformative, {} shown",
            self.agree,
            self.paper_off,
            self.failing,
            self.fails_run,
            self.disputed,
            self.weak,
            percent(POWER),
            percent(POWER_PROBABILITY),
            self.uninformative,
            self.shown
        )
    }
}

impl Table {
    /// Cells that fail the run ([`Cell::fails_run`]), as `row: quantity` strings.
    pub fn failures(&self) -> Vec<String> {
        self.rows
            .iter()
            .flat_map(|r| {
                r.cells
                    .iter()
                    .filter(|c| c.fails_run())
                    .map(move |c| format!("{}: {}", r.label, c.quantity))
            })
            .collect()
    }

    /// Cells whose verdict is `v`-like, as `row: quantity` strings.
    pub fn cells_where(&self, keep: impl Fn(Verdict) -> bool) -> Vec<String> {
        self.rows
            .iter()
            .flat_map(|r| {
                r.cells
                    .iter()
                    .filter(|c| keep(c.verdict()))
                    .map(move |c| format!("{}: {}", r.label, c.quantity))
            })
            .collect()
    }
}
