//! A paper's figure beside ours: [`Cell`] (how it is judged), [`Row`], [`Table`].

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
