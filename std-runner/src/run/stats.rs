//! Ensemble statistics: mean, empirical variance and the 99.9% confidence interval
//! (GRW (25), lambda_p = 3.2), accumulated by Welford's method and merged by Chan's formula in a
//! fixed order, so that results do not depend on how ensembles were spread over threads.
//!
//! The papers' interval, mean +- 3.2 sqrt(Var/M) (GRW (25), BRS (33): "p = 0.999 and lambda_p =
//! 3.2"), assumes the variance known; estimated from M samples it undercovers when M is small
//! (at M = 8 a 3.2 interval covers about 98.5%, not 99.86%). Every half-width here therefore uses the
//! Student-t quantile with M - 1 degrees of freedom at the level of 3.2 normal sigma
//! ([`multiplier`]): 5.1 at M = 8, 3.54 at M = 30, 3.29 at M = 100, 3.21 at M = 1000, and
//! 3.2 in the limit, so large runs print the papers' interval.

use statrs::distribution::{ContinuousCDF, Normal, StudentsT};

/// The confidence multiplier lambda_p of GRW (25) for p = 0.999 (the limit of [`multiplier`]).
pub const LAMBDA_999: f64 = 3.2;

/// The two-sided level of a 3.2-sigma interval of a normal mean, `2 Phi(3.2) - 1` (0.99863).
pub fn level_999() -> f64 {
    2.0 * Normal::standard().cdf(LAMBDA_999) - 1.0
}

/// The half-width multiplier of a mean of `samples` values with estimated variance: the
/// Student-t quantile with `samples - 1` degrees of freedom at the two-sided level of
/// [`LAMBDA_999`] (see the module docs). NaN below two samples.
pub fn multiplier(samples: u64) -> f64 {
    // The inverse of Student's t costs microseconds and every cell of a run asks for the same
    // one: the last answer is kept (per thread; the same bits as computing it again).
    thread_local! {
        static LAST: std::cell::Cell<Option<(u64, f64)>> = const { std::cell::Cell::new(None) };
    }
    LAST.with(|last| match last.get() {
        Some((m, x)) if m == samples => x,
        _ => {
            let x = quantile_t(samples.saturating_sub(1), level_999());
            last.set(Some((samples, x)));
            x
        }
    })
}

/// The two-sided quantile of Student's t with `dof` degrees of freedom: the `x` with
/// `P(|T| <= x) = level`. NaN for `dof = 0`; the normal quantile for very large `dof`.
pub fn quantile_t(dof: u64, level: f64) -> f64 {
    let p = 0.5 + 0.5 * level;
    if dof == 0 {
        return f64::NAN;
    }
    if dof > 10_000_000 {
        return Normal::standard().inverse_cdf(p);
    }
    StudentsT::new(0.0, 1.0, dof as f64).map_or(f64::NAN, |t| t.inverse_cdf(p))
}

/// Degrees of freedom standing for a variance known exactly (the normal quantile).
pub const KNOWN: u64 = u64::MAX;

/// The probability a 99.9% interval may miss: `1 - level_999()` (0.00137).
pub fn miss() -> f64 {
    1.0 - level_999()
}

/// The multiplier that makes `k` two-sided intervals hold together at the 99.9% level
/// (Bonferroni: each at `1 - miss/k`), Student-t with `dof` degrees of freedom ([`KNOWN`]: the
/// normal quantile). `joint(1, KNOWN)` is 3.2.
pub fn joint(k: usize, dof: u64) -> f64 {
    let level = 1.0 - miss() / k.max(1) as f64;
    quantile_t(if dof == KNOWN { u64::MAX / 2 } else { dof }, level)
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
        let k = self.count as f64;
        for ((m, s), &x) in self.mean.iter_mut().zip(self.m2.iter_mut()).zip(xs) {
            let d = x - *m;
            *m += d / k;
            *s += d * (x - *m);
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

    /// The multiplier against published Student-t tables (two-sided 99.9%: 12.92 at 3 degrees
    /// of freedom, 4.587 at 10, 3.646 at 30) and the 3.2-sigma level in the limit.
    #[test]
    fn student_quantiles() {
        assert!((quantile_t(3, 0.999) - 12.924).abs() < 2e-3);
        assert!((quantile_t(10, 0.999) - 4.587).abs() < 2e-3);
        assert!((quantile_t(30, 0.999) - 3.646).abs() < 2e-3);
        assert!((multiplier(1_000_000) - 3.2).abs() < 1e-4);
        // Computed independently (Simpson's rule on the t density, bisection): 5.1164 at M = 8,
        // 3.5394 at M = 30, 3.2932 at M = 100.
        assert!((multiplier(8) - 5.1164).abs() < 1e-3);
        assert!((multiplier(30) - 3.5394).abs() < 1e-3);
        assert!((multiplier(100) - 3.2932).abs() < 1e-3);
        assert!(multiplier(1).is_nan());
        let m: Vec<f64> = [2, 3, 10, 30, 100, 1000].map(multiplier).to_vec();
        assert!(m.windows(2).all(|w| w[0] > w[1] && w[1] > 3.2), "{m:?}");
    }
}
