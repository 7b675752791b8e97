//! The fold of finished ensembles into a run's statistics, in ensemble order.
//!
//! Every way of running a scene (one process, shards merged, MPI ranks, a resumed run) folds
//! the same per-ensemble rows through [`Totals::push`] in the same order, so their statistics
//! are bit-identical: floating-point sums depend on the order, so the order is the one rule.

use crate::run::columns::names;
use crate::scene::Scene;
use gdsmc_core::engine::Counts;
use gdsmc_stats::{Accumulator, Covariance};

/// The statistics of the ensembles folded so far (a prefix of a range of ensembles).
#[derive(Clone, Debug)]
pub struct Totals {
    /// Per (time, column) statistics, row-major `times x columns`.
    pub acc: Accumulator,
    /// Statistics of each ensemble's steady-state averages (one per column).
    pub steady: Accumulator,
    /// Statistics of the histogram values each ensemble appends after its observables.
    pub hist: Accumulator,
    /// Statistics of the reduced histogram's cumulative tail `P(c >= c_k)` at each shell's
    /// inner edge, with their covariances (the tail exponent's interval), when the scene asks
    /// for at most [`TAIL_EDGES`] reduced shells.
    pub tail: Option<Covariance>,
    /// Event counts summed.
    pub counts: Counts,
    /// Ensembles folded.
    pub ensembles: u64,
    ncol: usize,
    times: usize,
    first: usize,
    /// Where the reduced histogram's weights start in the histogram values.
    reduced_at: usize,
}

/// The most reduced shells (with the one beyond) whose cumulative tail is folded with its
/// covariances: `TAIL_EDGES^2` co-moments (half a mebibyte).
pub const TAIL_EDGES: usize = 257;

impl Totals {
    /// No ensemble yet, shaped for `scene`.
    pub fn new(scene: &Scene) -> Self {
        let ncol = names(scene).len();
        let times = scene.times().len();
        Totals {
            acc: Accumulator::new(times * ncol),
            steady: Accumulator::new(ncol),
            hist: Accumulator::new(scene.extra_len()),
            tail: scene
                .reduced_histogram()
                .filter(|h| h.weights() <= TAIL_EDGES)
                .map(|h| Covariance::new(h.weights())),
            counts: Counts::default(),
            ensembles: 0,
            ncol,
            times,
            first: scene.steady_from().unwrap_or(0),
            reduced_at: scene.histogram().map_or(0, |h| h.weights()),
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
        if let Some(tail) = &mut self.tail {
            let shells = &h[self.reduced_at..self.reduced_at + tail.len()];
            let mut beyond = vec![0.0; shells.len()];
            let mut sum = 0.0;
            for (b, w) in beyond.iter_mut().zip(shells).rev() {
                sum += w;
                *b = sum;
            }
            tail.push(&beyond);
        }
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
