//! Ensemble statistics of a vector with its covariances: the mean and the co-moment matrix,
//! accumulated one sample at a time and merged by Chan, Golub and LeVeque's pairwise formula
//! in a fixed order (the same rule as [`crate::Accumulator`], so a fold does not depend on how
//! ensembles were spread over threads or shards). What a nonlinear function of several means
//! needs for its interval by the delta method: `Var f(m) = grad f . Cov grad f / M`.

use crate::level::multiplier;

/// Running mean and co-moment matrix `C_ab = sum (x_a - m_a)(x_b - m_b)` of a vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Covariance {
    count: u64,
    mean: Vec<f64>,
    /// Row-major `len x len`, symmetric.
    co: Vec<f64>,
}

impl Covariance {
    /// An empty accumulator for `len` quantities (`len^2` co-moments).
    #[must_use]
    pub fn new(len: usize) -> Self {
        Covariance {
            count: 0,
            mean: vec![0.0; len],
            co: vec![0.0; len * len],
        }
    }

    /// Number of samples.
    #[must_use]
    pub fn count(&self) -> u64 {
        self.count
    }

    /// Number of quantities.
    #[must_use]
    pub fn len(&self) -> usize {
        self.mean.len()
    }

    /// True when there are no quantities.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.mean.is_empty()
    }

    /// Adds one sample: `C_ab += (x_a - m_a_old)(x_b - m_b_new)` (Welford).
    pub fn push(&mut self, xs: &[f64]) {
        assert_eq!(xs.len(), self.mean.len());
        self.count += 1;
        let k = self.count as f64;
        let before: Vec<f64> = xs.iter().zip(&self.mean).map(|(x, m)| x - m).collect();
        for (m, d) in self.mean.iter_mut().zip(&before) {
            *m += d / k;
        }
        let after: Vec<f64> = xs.iter().zip(&self.mean).map(|(x, m)| x - m).collect();
        for (row, da) in self.co.chunks_exact_mut(after.len().max(1)).zip(&before) {
            for (c, db) in row.iter_mut().zip(&after) {
                *c += da * db;
            }
        }
    }

    /// Merges another accumulator of the same length (Chan, Golub and LeVeque 1979):
    /// `C = C_A + C_B + d_a d_b n_A n_B / n`, `d = m_B - m_A`.
    pub fn merge(&mut self, o: &Covariance) {
        assert_eq!(o.mean.len(), self.mean.len());
        if o.count == 0 {
            return;
        }
        if self.count == 0 {
            *self = o.clone();
            return;
        }
        let (na, nb) = (self.count as f64, o.count as f64);
        let n = na + nb;
        let d: Vec<f64> = o.mean.iter().zip(&self.mean).map(|(b, a)| b - a).collect();
        let len = self.mean.len().max(1);
        let rows = self.co.chunks_exact_mut(len).zip(o.co.chunks_exact(len));
        for ((row, other), da) in rows.zip(&d) {
            for ((c, oc), db) in row.iter_mut().zip(other).zip(&d) {
                *c += oc + da * db * na * nb / n;
            }
        }
        for (m, da) in self.mean.iter_mut().zip(&d) {
            *m += da * nb / n;
        }
        self.count += o.count;
    }

    /// Empirical mean of quantity `a`.
    #[must_use]
    pub fn mean(&self, a: usize) -> f64 {
        self.mean[a]
    }

    /// Empirical covariance of quantities `a` and `b` (divisor `M - 1`; NaN below two samples).
    #[must_use]
    pub fn covariance(&self, a: usize, b: usize) -> f64 {
        if self.count > 1 {
            self.co[a * self.mean.len() + b] / (self.count - 1) as f64
        } else {
            f64::NAN
        }
    }

    /// A function of the means known by its value's gradient `grad` (the delta method): the
    /// half-width of its 99.9% interval, `t_(M-1) sqrt(grad . Cov grad / M)` with the
    /// Student-t [`multiplier`], as [`crate::Accumulator::ci`] for a single mean. `grad` pairs
    /// quantity indices with the partial derivatives; indices may repeat (their terms add).
    #[must_use]
    pub fn ci_of(&self, grad: &[(usize, f64)]) -> f64 {
        let mut var = 0.0;
        for &(a, ga) in grad {
            for &(b, gb) in grad {
                var += ga * gb * self.covariance(a, b);
            }
        }
        multiplier(self.count) * (var.max(0.0) / self.count as f64).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Accumulator;

    fn rows() -> Vec<[f64; 3]> {
        (0..57)
            .map(|i| {
                let x = ((i * 37) % 11) as f64 + 0.25 * i as f64;
                [x, 2.0 * x + ((i * 13) % 5) as f64, -x + (i % 3) as f64]
            })
            .collect()
    }

    #[test]
    fn push_and_merge_give_the_two_pass_covariance() {
        let xs = rows();
        let n = xs.len() as f64;
        let mean: Vec<f64> = (0..3)
            .map(|a| xs.iter().map(|r| r[a]).sum::<f64>() / n)
            .collect();
        let cov = |a: usize, b: usize| {
            xs.iter()
                .map(|r| (r[a] - mean[a]) * (r[b] - mean[b]))
                .sum::<f64>()
                / (n - 1.0)
        };
        let mut all = Covariance::new(3);
        let (mut a, mut b) = (Covariance::new(3), Covariance::new(3));
        for (i, r) in xs.iter().enumerate() {
            all.push(r);
            if i < 20 { a.push(r) } else { b.push(r) }
        }
        a.merge(&b);
        for (p, q) in [(0, 0), (0, 1), (1, 2), (2, 2), (2, 0)] {
            assert!((all.covariance(p, q) - cov(p, q)).abs() < 1e-9 * cov(p, p).abs().max(1.0));
            assert!((a.covariance(p, q) - cov(p, q)).abs() < 1e-9 * cov(p, p).abs().max(1.0));
        }
        // A sum's variance counts the covariance: Var(x0 + x1) differs from Var x0 + Var x1.
        let single: Vec<f64> = xs.iter().map(|r| r[0] + r[1]).collect();
        let mut s = Accumulator::new(1);
        for v in &single {
            s.push(&[*v]);
        }
        let via = all.ci_of(&[(0, 1.0), (1, 1.0)]);
        assert!((via - s.ci(0)).abs() < 1e-9 * s.ci(0));
        let without = libm::hypot(all.ci_of(&[(0, 1.0)]), all.ci_of(&[(1, 1.0)]));
        assert!(
            (via - without).abs() > 0.05 * via,
            "the test must see the covariance"
        );
    }
}
