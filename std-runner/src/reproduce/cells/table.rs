//! A reproduced table ([`Table`]: its [`Row`]s of cells), the readings of RW's steady tables
//! ([`ReadingScores`]), the joint test of a table's cells ([`Joint`]) and the counts of its
//! verdicts ([`Counts`]).

use super::{Against, Blame, Cell, POWER, POWER_PROBABILITY, Side, Verdict, percent};

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
/// every check of that side that has one ([`super::Check::z`]), taken together.
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
    /// conservative score is 0 ([`super::Check::z`]), so that a small chi^2 says they are not off,
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
            p_max: -libm::expm1(k as f64 * libm::log1p(-one)),
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
