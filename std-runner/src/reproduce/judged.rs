//! The cells the tables build, each with its checks and their sources: a figure against an
//! exact value (the paper's with the paper's noise, ours with ours), and a figure against the
//! paper's when nothing is known exactly.

use super::bounds::{FAMILY, KNOWN, family_factor, joint, max_error};
use super::cells::{Against, Cell, Check, Side, rounding};
use super::figure::fmt;

/// The noise of the paper's estimator, and where it comes from.
#[derive(Clone, Debug)]
pub struct PaperNoise {
    /// Standard error of the paper's figure (largest over the times of a largest-error
    /// statistic; in the figure's units).
    pub se: f64,
    /// Degrees of freedom of the variance behind `se` (`bounds::KNOWN` when the paper states it from
    /// many ensembles; ours minus one when it is ours rescaled).
    pub dof: u64,
    /// Where `se` comes from.
    pub source: String,
}

/// Our largest error: its value, our largest standard error over the times, our ensembles.
#[derive(Clone, Copy, Debug)]
pub struct OurLargest {
    /// The largest error of our ensemble mean.
    pub value: f64,
    /// Our largest standard error over the times (relative).
    pub se: f64,
    /// Our ensembles.
    pub ensembles: u64,
}

/// A largest-relative-error cell (GRW (29), RW's `E_max`, `E_end` with `k = 1`) whose
/// estimator's bias is known exactly: `bmax = max_t |E T_n(t) - T(t)| / T(t)`. Ours must lie in
/// `bmax +- joint(k, m - 1) se` (Bonferroni over the `k` times, [`max_error`]), the paper's in
/// `bmax +- joint(k, dof) s_paper + rounding`.
pub fn max_error_exact(
    quantity: &str,
    paper: f64,
    bmax: f64,
    k: usize,
    ours: OurLargest,
    noise: &PaperNoise,
) -> Cell {
    let OurLargest {
        value: ours,
        se: s_ours,
        ensembles,
    } = ours;
    let dof = ensembles.saturating_sub(1);
    let tol_o = max_error(s_ours, k, dof);
    let tol_p = max_error(noise.se, k, noise.dof) + rounding(paper);
    let over = if k > 1 {
        format!(" over {k} times (Bonferroni)")
    } else {
        String::new()
    };
    Cell::new(quantity, paper, (ours, tol_o))
        .exact(bmax)
        .check(
            Check::around(
                Side::Ours,
                Against::Exact,
                bmax,
                tol_o,
                format!(
                    "the exact {quantity} of the ensemble mean {} +- {:.2} x our largest \
                     standard error {} ({ensembles} ensembles, Student t){over}",
                    fmt(bmax),
                    joint(k, dof),
                    fmt(s_ours)
                ),
            )
            .family(max_error(s_ours, k * FAMILY, dof)),
        )
        .check(
            Check::around(
                Side::Paper,
                Against::Exact,
                bmax,
                tol_p,
                format!(
                    "{} +- {:.2} x the paper's standard error {} ({}){over} + half its last \
                     digit {}",
                    fmt(bmax),
                    joint(k, noise.dof),
                    fmt(noise.se),
                    noise.source,
                    fmt(rounding(paper))
                ),
            )
            .family(max_error(noise.se, k * FAMILY, noise.dof) + rounding(paper)),
        )
}

/// The paper's stated interval for a mean: its 3.2-sigma half-width read from the paper as
/// `source` says, and half a unit of its last printed digit.
#[derive(Clone, Copy, Debug)]
pub struct PaperInterval<'a> {
    /// Half-width.
    pub half: f64,
    /// Half a unit of the last digit.
    pub round: f64,
    /// How the half-width is read from the paper.
    pub source: &'a str,
}

/// A mean against its exact expectation: ours in `exact +- ours_ci` (`dof` degrees of freedom
/// behind it), the paper's in `exact +- half + round`.
pub fn mean_exact(
    quantity: &str,
    paper: f64,
    ours: (f64, f64),
    dof: u64,
    exact: f64,
    stated: &PaperInterval<'_>,
) -> Cell {
    let PaperInterval {
        half: paper_half,
        round,
        source,
    } = *stated;
    Cell::new(quantity, paper, ours)
        .exact(exact)
        .check(
            Check::around(
                Side::Ours,
                Against::Exact,
                exact,
                ours.1,
                format!(
                    "the exact mean of the estimator {} +- our 99.9% half-width",
                    fmt(exact)
                ),
            )
            .family(ours.1 * family_factor(1, dof)),
        )
        .check(
            Check::around(
                Side::Paper,
                Against::Exact,
                exact,
                paper_half + round,
                format!(
                    "{} +- the paper's half-width {} ({source}) + half its last digit {}",
                    fmt(exact),
                    fmt(paper_half),
                    fmt(round)
                ),
            )
            .family(paper_half * family_factor(1, KNOWN) + round),
        )
}

/// Ours against the paper's figure when nothing is known exactly: ours in
/// `paper +- (tol + round)`; `tol` (noise of both sides, made as `source` says) is given at the
/// cell's level and at the report's.
pub fn against_paper(
    quantity: &str,
    paper: f64,
    ours: (f64, f64),
    tol: (f64, f64),
    round: f64,
    source: &str,
) -> Cell {
    Cell::new(quantity, paper, ours).check(
        Check::around(
            Side::Ours,
            Against::Other,
            paper,
            tol.0 + round,
            format!(
                "the paper's {} +- {} ({source}) + half its last digit {}",
                fmt(paper),
                fmt(tol.0),
                fmt(round)
            ),
        )
        .family(tol.1 + round),
    )
}

/// A figure computed without noise (a closed form, an ODE) against the paper's printed digits:
/// ours in `paper +- round`.
pub fn computed(quantity: &str, paper: f64, ours: f64, round: f64, what: &str) -> Cell {
    against_paper(
        quantity,
        paper,
        (ours, 0.0),
        (0.0, 0.0),
        round,
        &format!("{what}, no noise"),
    )
}
