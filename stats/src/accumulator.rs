//! Ensemble statistics: mean, empirical variance and the 99.9% confidence interval
//! (GRW (25)), accumulated by Welford's method and merged by Chan's formula in a fixed order, so
//! that results do not depend on how ensembles were spread over threads.

use crate::level::multiplier;

/// Welford's step: `x`, the `count`-th value, moves the running `mean` and the sum of squared
/// deviations `m2` (the one arithmetic of every ensemble mean: [`Accumulator::push`] and the C
/// ABI's `gdsmc_mean_add`).
#[inline]
pub fn welford(count: u64, mean: &mut f64, m2: &mut f64, x: f64) {
    let d = x - *mean;
    *mean += d / count as f64;
    *m2 += d * (x - *mean);
}

/// Running mean and sum of squared deviations of a vector of quantities.
#[derive(Clone, Debug, PartialEq)]
pub struct Accumulator {
    count: u64,
    mean: Vec<f64>,
    m2: Vec<f64>,
}

impl Accumulator {
    /// An empty accumulator for `len` quantities.
    pub fn new(len: usize) -> Self {
        Accumulator {
            count: 0,
            mean: vec![0.0; len],
            m2: vec![0.0; len],
        }
    }

    /// Number of samples.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// Number of quantities.
    pub fn len(&self) -> usize {
        self.mean.len()
    }

    /// True when there are no quantities.
    pub fn is_empty(&self) -> bool {
        self.mean.is_empty()
    }

    /// Adds one sample (one ensemble's values).
    pub fn push(&mut self, xs: &[f64]) {
        assert_eq!(xs.len(), self.mean.len());
        self.count += 1;
        for ((m, s), &x) in self.mean.iter_mut().zip(self.m2.iter_mut()).zip(xs) {
            welford(self.count, m, s, x);
        }
    }

    /// The statistics of the quantities in `range` alone.
    pub fn slice(&self, range: std::ops::Range<usize>) -> Accumulator {
        Accumulator {
            count: self.count,
            mean: self.mean[range.clone()].to_vec(),
            m2: self.m2[range].to_vec(),
        }
    }

    /// Merges another accumulator (Chan, Golub, LeVeque 1979).
    pub fn merge(&mut self, o: &Accumulator) {
        if o.count == 0 {
            return;
        }
        if self.count == 0 {
            *self = o.clone();
            return;
        }
        let (na, nb) = (self.count as f64, o.count as f64);
        let n = na + nb;
        for i in 0..self.mean.len() {
            let d = o.mean[i] - self.mean[i];
            self.mean[i] += d * nb / n;
            self.m2[i] += o.m2[i] + d * d * na * nb / n;
        }
        self.count += o.count;
    }

    /// Empirical mean of quantity `i` (GRW (24)).
    pub fn mean(&self, i: usize) -> f64 {
        self.mean[i]
    }

    /// Empirical variance of quantity `i` (GRW (26) with the empirical moments; divisor M - 1).
    pub fn variance(&self, i: usize) -> f64 {
        if self.count > 1 {
            self.m2[i] / (self.count - 1) as f64
        } else {
            f64::NAN
        }
    }

    /// Half-width of the 99.9% confidence interval of the mean: `t_(M-1) sqrt(Var / M)`, with
    /// the Student-t [`multiplier`] (3.2 for large `M`, more for few ensembles).
    pub fn ci(&self, i: usize) -> f64 {
        multiplier(self.count) * (self.variance(i) / self.count as f64).sqrt()
    }

    /// Empirical standard deviation of quantity `i` (one sample's spread).
    pub fn sd(&self, i: usize) -> f64 {
        self.variance(i).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level::multiplier;

    #[test]
    fn merge_equals_sequential() {
        let xs: Vec<f64> = (0..100)
            .map(|i| ((i * 37) % 11) as f64 + 0.25 * i as f64)
            .collect();
        let mut all = Accumulator::new(1);
        for x in &xs {
            all.push(&[*x]);
        }
        let mut a = Accumulator::new(1);
        let mut b = Accumulator::new(1);
        for x in &xs[..40] {
            a.push(&[*x]);
        }
        for x in &xs[40..] {
            b.push(&[*x]);
        }
        a.merge(&b);
        let n = xs.len() as f64;
        let mean = xs.iter().sum::<f64>() / n;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
        assert!((a.mean(0) - mean).abs() < 1e-12 && (all.mean(0) - mean).abs() < 1e-12);
        assert!((a.variance(0) - var).abs() < 1e-10 && (all.variance(0) - var).abs() < 1e-10);
        assert!((a.ci(0) - multiplier(n as u64) * (var / n).sqrt()).abs() < 1e-12);
    }
}
