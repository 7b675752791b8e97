//! The cells the tables build, each with its checks and their sources: a figure against an
//! exact value (the paper's with the paper's noise, ours with ours), and a figure against the
//! paper's when nothing is known exactly.

use super::bounds::{FAMILY, KNOWN, joint, max_error, report_factor};
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

impl PaperNoise {
    /// The paper's noise as our spread of one ensemble `sd` (the largest over the times)
    /// over the paper's `ensembles`, estimated from our `ours` ensembles; `paper` names it and
    /// `why` says why it is used (the paper states no interval, or one that fits no reading).
    pub fn ours_rescaled(sd: f64, ensembles: u64, ours: u64, paper: &str, why: &str) -> Self {
        PaperNoise {
            se: sd / (ensembles as f64).sqrt(),
            dof: ours.saturating_sub(1),
            source: format!(
                "our spread of one ensemble over {paper}'s {ensembles} ensembles; {why}"
            ),
        }
    }
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

/// The law of a largest relative error `max_k |b_k + e_k|` over the observation times: the
/// exact relative bias `b_k` of the ensemble mean at each time and the relative standard
/// deviation `sd_k` of one ensemble there (our spread), so that with `N` ensembles
/// `e_k ~ N(0, sd_k^2 / N)`.
#[derive(Clone, Debug)]
pub struct MaxLaw {
    /// `b_k`, signed.
    pub bias: Vec<f64>,
    /// `sd_k`.
    pub sd: Vec<f64>,
}

impl MaxLaw {
    /// Draws of the law's simulation: the mean and spread it gives are good to about 2% of
    /// the spread.
    const DRAWS: usize = 4000;

    /// Mean and standard deviation of `max_k |b_k + s sd_k Z_k|`, simulated with a fixed
    /// seed, for the `Z_k` independent standard normal (`comonotone` false) or all one normal
    /// (`comonotone` true). The noise of a run's mean is positively correlated across times
    /// (each ensemble's temperature is a continuous process), and by Slepian's inequality a
    /// maximum of Gaussians with more correlation is stochastically smaller: the estimator's
    /// law lies between these two.
    pub fn moments(&self, s: f64, comonotone: bool) -> (f64, f64) {
        use gdsmc_core::sample::normal::standard_normal;
        use rand_core::SeedableRng;
        let mut rng = rand_xoshiro::Xoshiro256PlusPlus::seed_from_u64(35);
        let draws: Vec<f64> = (0..Self::DRAWS)
            .map(|_| {
                let shared = standard_normal(&mut rng);
                self.bias
                    .iter()
                    .zip(&self.sd)
                    .map(|(b, sd)| {
                        let z = if comonotone {
                            shared
                        } else {
                            standard_normal(&mut rng)
                        };
                        (b + s * sd * z).abs()
                    })
                    .fold(0.0, f64::max)
            })
            .collect();
        let st = gdsmc_stats::Sample::of(&draws);
        (st.mean, st.sd)
    }

    /// The standard score of a figure `x` of the estimator whose per-time noise is `s sd_k`,
    /// with a rounding of at most `round` (uniform: variance `round^2 / 3`), taken
    /// conservatively: 0 between the means of the comonotone and the independent law, else
    /// the smaller in size of its two scores, one against each law (its mean and its spread;
    /// the nearer mean with its own spread could give the larger one: an audit found p-values
    /// 3-7x below the conservative ones at n = 64 and 256, issue 51). Its square is stochastically no
    /// larger than a true score's, so a chi-squared test of such scores errs towards finding
    /// nothing. No score (NaN) when the two means lie more than a spread apart: the bracket is
    /// then too wide for a score to say anything (a noise-dominated maximum over many times),
    /// and a run of zeros would only dilute the table-wide test.
    fn z(&self, x: f64, s: f64, round: f64) -> f64 {
        let (co_mean, co_sd) = self.moments(s, true);
        let (in_mean, in_sd) = self.moments(s, false);
        if (in_mean - co_mean).abs() > co_sd.max(in_sd) {
            return f64::NAN;
        }
        let r2 = round * round / 3.0;
        let z_co = (x - co_mean) / (co_sd * co_sd + r2).sqrt();
        let z_in = (x - in_mean) / (in_sd * in_sd + r2).sqrt();
        if z_co.signum() != z_in.signum() {
            0.0
        } else if z_co.abs() <= z_in.abs() {
            z_co
        } else {
            z_in
        }
    }

    /// The law over observation times `times` of a relative-error profile `rel` (each time's
    /// mean error and relative spread of one ensemble, as `reproduce::relative` gives them)
    /// whose exact relative bias at time `t` is `bias(t)`.
    pub fn over(times: &[f64], rel: &[(f64, f64)], bias: impl Fn(f64) -> f64) -> Self {
        MaxLaw {
            bias: times.iter().map(|&t| bias(t)).collect(),
            sd: rel.iter().map(|r| r.1).collect(),
        }
    }

    /// The largest `|b_k|`: the exact expectation of the largest error without noise.
    pub fn largest_bias(&self) -> f64 {
        self.bias.iter().map(|b| b.abs()).fold(0.0, f64::max)
    }

    /// The largest `sd_k`.
    fn sd_max(&self) -> f64 {
        self.sd.iter().copied().fold(0.0, f64::max)
    }
}

/// The standard normal score with the same tail probability as Student's `t` with `dof`
/// degrees of freedom (the identity for [`KNOWN`]): so that scores of means with few degrees
/// of freedom can be summed in a chi-squared test.
pub fn t_to_z(t: f64, dof: u64) -> f64 {
    use statrs::distribution::{ContinuousCDF, Normal, StudentsT};
    if dof == KNOWN || !t.is_finite() {
        return t;
    }
    let Ok(law) = StudentsT::new(0.0, 1.0, dof as f64) else {
        return f64::NAN;
    };
    // By the upper tail, so that large scores keep their precision; the sign restored.
    let p = law.sf(t.abs());
    let z = -Normal::standard().inverse_cdf(p);
    z.copysign(t)
}

/// A largest-relative-error cell (GRW (29), RW's `E_max`, `E_end` with `k = 1`) whose
/// estimator's bias is known exactly: `bmax = max_t |E T_n(t) - T(t)| / T(t)`. Ours must lie in
/// `bmax +- joint(k, m - 1) se` (Bonferroni over the `k` times, [`max_error`]), the paper's in
/// `bmax +- joint(k, dof) s_paper + rounding`. Each check carries its figure's score against
/// `law` (conservative, [`MaxLaw::moments`]) for the table-wide test, the paper's noise scaled
/// from ours by `s_paper / sd_max`.
pub fn max_error_exact(
    quantity: &str,
    paper: f64,
    bmax: f64,
    law: &MaxLaw,
    ours: OurLargest,
    noise: &PaperNoise,
) -> Cell {
    let k = law.bias.len();
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
            .report_range(max_error(s_ours, k * FAMILY, dof))
            .with_z(law.z(ours, 1.0 / (ensembles as f64).sqrt(), 0.0))
            // The largest error's noise is that of one time's mean, at most the largest.
            .with_sd(s_ours),
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
            .report_range(max_error(noise.se, k * FAMILY, noise.dof) + rounding(paper))
            .with_z(law.z(paper, noise.se / law.sd_max(), rounding(paper)))
            .with_sd(noise.se),
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
            .report_range(ours.1 * report_factor(1, dof))
            .with_z(t_to_z(
                (ours.0 - exact) / (ours.1 / gdsmc_stats::multiplier(dof + 1)),
                dof,
            ))
            .with_sd(ours.1 / gdsmc_stats::multiplier(dof + 1)),
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
            .report_range(paper_half * report_factor(1, KNOWN) + round)
            .with_z(
                (paper - exact)
                    / ((paper_half / gdsmc_stats::LAMBDA_999).powi(2) + round * round / 3.0).sqrt(),
            )
            .with_sd(paper_half / gdsmc_stats::LAMBDA_999),
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
        .report_range(tol.1 + round)
        // Both sides' noise, given at 99.9% (the rounding is none).
        .with_sd(tol.0 / gdsmc_stats::LAMBDA_999),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Student's t at its one-sided 5% point (5 degrees of freedom: 2.015048) maps to the
    /// normal's (1.644854); the sign is kept and many degrees of freedom change nothing.
    #[test]
    fn t_scores_become_normal_scores() {
        assert!((t_to_z(2.015_048, 5) - 1.644_854).abs() < 1e-4);
        assert!((t_to_z(-2.015_048, 5) + 1.644_854).abs() < 1e-4);
        assert_eq!(t_to_z(2.5, KNOWN), 2.5);
    }

    /// One time: the largest error is `|b + e|`, Gaussian about `b` when `b` is many sigma
    /// from 0: a figure three of its sigma above scores 3 (within the simulation's 2%), one
    /// between nothing. Two times of equal bias: the independent law's maximum lies above
    /// the comonotone one's, and a figure between them scores 0.
    #[test]
    fn largest_error_scores_are_conservative() {
        let one = MaxLaw {
            bias: vec![0.1],
            sd: vec![1.0],
        };
        assert!((one.z(0.13, 0.01, 0.0) - 3.0).abs() < 0.1);
        assert!((one.z(0.07, 0.01, 0.0) + 3.0).abs() < 0.1);
        let two = MaxLaw {
            bias: vec![0.1, 0.1],
            sd: vec![1.0, 1.0],
        };
        let (co, _) = two.moments(0.01, true);
        let (ind, _) = two.moments(0.01, false);
        assert!(ind > co + 0.004, "{ind} against {co}");
        assert_eq!(two.z(0.5 * (co + ind), 0.01, 0.0), 0.0);
        // Noise over many times of equal bias: the bracket is wider than a spread, no score.
        let many = MaxLaw {
            bias: vec![0.1; 500],
            sd: vec![1.0; 500],
        };
        assert!(many.z(0.1, 0.01, 0.0).is_nan());
    }
}
