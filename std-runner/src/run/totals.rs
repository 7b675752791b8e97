//! The fold of finished ensembles into a run's statistics, in ensemble order.
//!
//! Every way of running a scene (one process, shards merged, MPI ranks, a resumed run) folds
//! the same per-ensemble rows through [`Totals::push`] in the same order, so their statistics
//! are bit-identical: floating-point sums depend on the order, so the order is the one rule.

use crate::run::columns::names;
use crate::scene::Scene;
use gdsmc_core::engine::Counts;
use gdsmc_stats::Accumulator;

/// The statistics of the ensembles folded so far (a prefix of a range of ensembles).
#[derive(Clone, Debug)]
pub struct Totals {
    /// Per (time, column) statistics, row-major `times x columns`.
    pub acc: Accumulator,
    /// Statistics of each ensemble's steady-state averages (one per column).
    pub steady: Accumulator,
    /// Statistics of the histogram values each ensemble appends after its observables.
    pub hist: Accumulator,
    /// Event counts summed.
    pub counts: Counts,
    /// Ensembles folded.
    pub ensembles: u64,
    ncol: usize,
    times: usize,
    first: usize,
}

impl Totals {
    /// No ensemble yet, shaped for `scene`.
    pub fn new(scene: &Scene) -> Self {
        let ncol = names(scene).len();
        let times = scene.times().len();
        Totals {
            acc: Accumulator::new(times * ncol),
            steady: Accumulator::new(ncol),
            hist: Accumulator::new(scene.extra_len()),
            counts: Counts::default(),
            ensembles: 0,
            ncol,
            times,
            first: scene.steady_from().unwrap_or(0),
        }
    }

    /// Values in one ensemble's row of `scene`, without allocating the fold: the observables
    /// (`times x columns`), then the histograms.
    pub fn row_len_of(scene: &Scene) -> usize {
        scene.times().len() * names(scene).len() + scene.extra_len()
    }

    /// Values in one ensemble's row: the observables (`times x columns`), then the histograms.
    pub fn row_len(&self) -> usize {
        self.acc.len() + self.hist.len()
    }

    /// Folds the next ensemble (its row as [`crate::run::run_ensemble`] returns it, and its
    /// counts). Each ensemble is its own one-sample accumulator merged into the total (Chan),
    /// as the runs have always done, so earlier outputs stay bit-identical.
    pub fn push(&mut self, row: &[f64], counts: &Counts) {
        let (obs, h) = row.split_at(self.acc.len());
        let mut one = Accumulator::new(obs.len());
        one.push(obs);
        self.acc.merge(&one);
        let mut st = Accumulator::new(self.ncol);
        st.push(&self.steady_of(obs));
        self.steady.merge(&st);
        let mut hi = Accumulator::new(h.len());
        hi.push(h);
        self.hist.merge(&hi);
        self.counts = self.counts.add(counts);
        self.ensembles += 1;
    }

    /// Each column averaged over the observations from the steady window's first on.
    fn steady_of(&self, obs: &[f64]) -> Vec<f64> {
        let pts = self.times - self.first;
        (0..self.ncol)
            .map(|c| {
                (self.first..self.times)
                    .map(|ti| obs[ti * self.ncol + c])
                    .sum::<f64>()
                    / pts as f64
            })
            .collect()
    }
}
