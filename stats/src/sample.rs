//! A sample held in memory (a test's draws, a Monte Carlo check of a reference): its mean,
//! spread and 99.9% interval (GRW (25) with the Student-t multiplier), the slice counterpart of
//! [`Accumulator`](crate::Accumulator).

use crate::level::{dof, joint, multiplier};

/// Mean and empirical standard deviation of `n` values (two passes; divisor `n - 1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Number of values.
    pub n: u64,
    /// Their mean (GRW (24)).
    pub mean: f64,
    /// Their empirical standard deviation (GRW (26); NaN for fewer than two values).
    pub sd: f64,
}

impl Sample {
    /// The summary of `xs`.
    #[must_use]
    pub fn of(xs: &[f64]) -> Sample {
        let n = xs.len() as f64;
        let mean = xs.iter().sum::<f64>() / n;
        let var = if xs.len() > 1 {
            xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1.0)
        } else {
            f64::NAN
        };
        Sample {
            n: xs.len() as u64,
            mean,
            sd: var.sqrt(),
        }
    }

    /// The standard error of the mean, `sd / sqrt(n)`.
    #[must_use]
    pub fn se(&self) -> f64 {
        self.sd / (self.n as f64).sqrt()
    }

    /// The half-width of the mean's 99.9% interval: [`multiplier`]`(n) * se` (3.2 se for large
    /// `n`, GRW (25)).
    #[must_use]
    pub fn ci(&self) -> f64 {
        multiplier(self.n) * self.se()
    }

    /// The half-width that holds together with `k - 1` others at the 99.9% level (Bonferroni,
    /// [`joint`]); `ci()` for `k = 1`.
    #[must_use]
    pub fn joint_ci(&self, k: usize) -> f64 {
        joint(k, dof(self.n)) * self.se()
    }

    /// Whether `value` lies within the mean's interval when `k` such checks are judged together:
    /// `|mean - value| <= joint_ci(k)`. False for a NaN mean or spread (never silently true).
    #[must_use]
    pub fn admits(&self, value: f64, k: usize) -> bool {
        (self.mean - value).abs() <= self.joint_ci(k)
    }
}

/// The mean of `xs` and the half-width of its 99.9% interval, `(mean, ci)`.
#[must_use]
pub fn mean_ci(xs: &[f64]) -> (f64, f64) {
    let s = Sample::of(xs);
    (s.mean, s.ci())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Draws of a known law without a generator crate: the sum of 12 uniforms minus 6 (mean 0,
    /// variance 1) from a 64-bit linear congruential stream.
    fn draws(n: usize, seed: u64) -> Vec<f64> {
        let mut s = seed;
        let mut u = move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n)
            .map(|_| (0..12).map(|_| u()).sum::<f64>() - 6.0)
            .collect()
    }

    #[test]
    fn the_summary_equals_the_definitions() {
        let xs = [1.0, 2.0, 4.0, 7.0];
        let s = Sample::of(&xs);
        assert_eq!(s.n, 4);
        assert_eq!(s.mean, 3.5);
        assert!((s.sd * s.sd - 7.0).abs() < 1e-12);
        assert!((s.ci() - multiplier(4) * 7f64.sqrt() / 2.0).abs() < 1e-12);
        assert_eq!(mean_ci(&xs), (s.mean, s.ci()));
        assert!(Sample::of(&[1.0]).sd.is_nan());
        assert!(
            !Sample::of(&[1.0]).admits(1.0, 1),
            "a NaN spread admits nothing"
        );
    }

    /// The helper must be able to fail: it admits the true mean and refuses a shift of 6 standard
    /// errors (beyond the 99.9% interval and beyond a family of 100) on the same sample.
    #[test]
    fn admits_the_true_mean_and_refuses_a_shift() {
        let s = Sample::of(&draws(20_000, 7));
        assert!((s.sd - 1.0).abs() < 0.05, "{s:?}");
        assert!(s.admits(0.0, 1), "{s:?}");
        assert!(s.admits(0.0, 100), "{s:?}");
        assert!(!s.admits(6.0 * s.se(), 1));
        assert!(!s.admits(-6.0 * s.se(), 100));
        assert!(s.joint_ci(100) > s.ci());
    }
}
