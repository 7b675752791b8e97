//! What a run hands back: per (time, column) statistics, steady-state averages, histograms,
//! counts and timing.

use gdsmc_core::engine::Counts;
use gdsmc_stats::Accumulator;
use std::time::Duration;

/// Steady-state averages (RW Section 4.2): every observable averaged over the observation
/// times from `first` on, per ensemble; `acc` holds those averages' statistics over ensembles.
#[derive(Clone, Debug)]
pub struct SteadyStats {
    /// Index of the first observation time averaged.
    pub first: usize,
    /// Number of observation times averaged.
    pub points: usize,
    /// Statistics over ensembles of the per-ensemble averages (one entry per column).
    pub acc: Accumulator,
}

impl SteadyStats {
    /// Mean over ensembles of the steady-state average of column `col`, and the half-width of
    /// its 99.9% confidence interval. With one ensemble the interval comes from the spread of
    /// the observation points (RW Section 4.2), widened for their lag-1 autocorrelation.
    pub fn steady_mean_ci(&self, stats: &RunStats, col: usize) -> (f64, f64) {
        if self.acc.count() > 1 {
            return (self.acc.mean(col), self.acc.ci(col));
        }
        let xs: Vec<f64> = (self.first..stats.times.len())
            .map(|ti| stats.mean(ti, col))
            .collect();
        let mut a = Accumulator::new(1);
        for &x in &xs {
            a.push(&[x]);
        }
        // Successive observations of one system are correlated; with the lag-1
        // autocorrelation r (an AR(1) model), the variance of their mean is larger by
        // (1 + r)/(1 - r). Points spaced as RW Section 4.2 spaces them have r near 0.2.
        let m = a.mean(0);
        let var = a.variance(0);
        let r = if xs.len() > 2 && var > 0.0 {
            let cov: f64 =
                xs.windows(2).map(|w| (w[0] - m) * (w[1] - m)).sum::<f64>() / (xs.len() - 1) as f64;
            (cov / var).clamp(0.0, 0.99)
        } else {
            0.0
        };
        (m, a.ci(0) * ((1.0 + r) / (1.0 - r)).sqrt())
    }
}

/// Statistics of a finished (or interrupted) run.
#[derive(Clone, Debug)]
pub struct RunStats {
    /// Observation times.
    pub times: Vec<f64>,
    /// Column names (see [`crate::run::columns::names`]).
    pub names: Vec<&'static str>,
    /// Per (time, column) statistics, row-major `times x names`.
    pub acc: Accumulator,
    /// Event counts summed over ensembles.
    pub counts: Counts,
    /// Ensembles finished.
    pub ensembles: u64,
    /// Wall time.
    pub wall: Duration,
    /// CPU time of the process during the run (all threads).
    pub cpu: Duration,
    /// Threads used.
    pub threads: usize,
    /// Steady-state averages, when the scene asks for them.
    pub steady: Option<SteadyStats>,
    /// The radial-shell histogram at the last observation, when the scene asks for it.
    pub histogram: Option<ShellHistogram>,
    /// The dimension of velocity space (3: spheres, 2: disks): the shells' volumes.
    pub dimension: usize,
    /// The reduced-speed histogram of `c = |v - V| / v0` (its radius `c_max`), each
    /// ensemble's averaged over the steady observations.
    pub reduced: Option<ShellHistogram>,
    /// The reduced histogram's cumulative tail `P(c >= c_k)` at each shell's inner edge with
    /// its covariances, for at most [`crate::run::totals::TAIL_EDGES`] shells.
    pub reduced_tail: Option<gdsmc_stats::Covariance>,
    /// The marginal histogram at the first and at the last observation.
    pub marginal: Option<MarginalHistogram>,
}

/// A histogram of a speed in equal shells: the statistics over ensembles of the weights of
/// the K shells on [0, `radius`) and of the one beyond.
#[derive(Clone, Debug)]
pub struct ShellHistogram {
    /// The shells' outer radius (R, or `c_max` for the reduced speed).
    pub radius: f64,
    /// The K + 1 shell weights' statistics.
    pub weights: Accumulator,
}

/// A histogram of one velocity component at the first and the last observation: the
/// statistics over ensembles of the weights of the bins on [-R, R) and of one beyond each end.
#[derive(Clone, Debug)]
pub struct MarginalHistogram {
    /// The component, 0..=2.
    pub axis: usize,
    /// R.
    pub radius: f64,
    /// The K + 2 weights' statistics at the first observation.
    pub first: Accumulator,
    /// The same at the last observation.
    pub last: Accumulator,
}

impl RunStats {
    /// Mean of column `col` at time index `ti`.
    pub fn mean(&self, ti: usize, col: usize) -> f64 {
        self.acc.mean(ti * self.names.len() + col)
    }
    /// Half-width of the 99.9% confidence interval of column `col` at time index `ti`.
    pub fn ci(&self, ti: usize, col: usize) -> f64 {
        self.acc.ci(ti * self.names.len() + col)
    }
    /// Standard deviation over ensembles of column `col` at time index `ti` (one ensemble's
    /// spread; the standard error of the mean is this over `sqrt(ensembles)`).
    pub fn sd(&self, ti: usize, col: usize) -> f64 {
        self.acc.sd(ti * self.names.len() + col)
    }
    /// Index of the column `name`.
    pub fn col(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| *n == name)
    }
}
