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

    /// The two-sample statistic of the means of two independent samples, `(mean - other.mean)
    /// / sqrt(se^2 + other.se^2)` (Welch's; normal for the thousands of draws the tests take):
    /// the number of standard errors of the difference between them. NaN when a spread is.
    #[must_use]
    pub fn z_from(&self, other: &Sample) -> f64 {
        (self.mean - other.mean) / libm::hypot(self.se(), other.se())
    }
}

/// The mean of `xs` and the half-width of its 99.9% interval, `(mean, ci)`.
#[must_use]
pub fn mean_ci(xs: &[f64]) -> (f64, f64) {
    let s = Sample::of(xs);
    (s.mean, s.ci())
}

/// The ratio of the means of paired samples, `mean(a) / mean(b)`, and its standard error by
/// the delta method, `sqrt(se_a^2 - 2 r cov_ab + r^2 se_b^2) / |mean(b)|` with `cov_ab` the
/// covariance of the two means (the pairs' covariance over `n`): for a ratio of two
/// observables of the same ensembles (`T_0 / T_1` of a mixture, `T_rot / T_tr`). Panics when
/// the samples are not paired (different lengths).
#[must_use]
pub fn ratio_of_means(a: &[f64], b: &[f64]) -> (f64, f64) {
    assert_eq!(a.len(), b.len(), "a ratio of means needs paired samples");
    let (sa, sb) = (Sample::of(a), Sample::of(b));
    let r = sa.mean / sb.mean;
    let n = a.len() as f64;
    let cov = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - sa.mean) * (y - sb.mean))
        .sum::<f64>()
        / (n - 1.0)
        / n;
    let var = sa.se().powi(2) - 2.0 * r * cov + r * r * sb.se().powi(2);
    (r, var.max(0.0).sqrt() / sb.mean.abs())
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

    /// Two samples of one law are within a few standard errors of each other; a shift of one
    /// standard deviation between them is tens of standard errors at 20,000 draws each.
    #[test]
    fn two_samples_of_one_law_agree_and_a_shift_is_seen() {
        let (a, b) = (Sample::of(&draws(20_000, 7)), Sample::of(&draws(20_000, 8)));
        assert!(a.z_from(&b).abs() < 3.3, "{}", a.z_from(&b));
        assert_eq!(a.z_from(&b), -b.z_from(&a));
        let shifted: Vec<f64> = draws(20_000, 8).iter().map(|x| x + 1.0).collect();
        let z = a.z_from(&Sample::of(&shifted));
        assert!(z < -50.0, "{z}");
        assert!(Sample::of(&[1.0]).z_from(&a).is_nan());
    }

    /// The delta method against the ratio's own scatter: over 400 independent paired samples
    /// of 2000 pairs (b = 2 + x, a = 1 + 0.5 x + y: correlated), the ratios' standard deviation
    /// equals the mean of the stated standard errors within 10% (the spread of a standard
    /// deviation from 400 draws is 3.5%, so 10% is about 3 of it); ignoring the covariance
    /// states sqrt(1.5) = 1.22 times the scatter here and fails.
    #[test]
    fn the_ratio_error_is_the_ratios_scatter() {
        let (mut ratios, mut stated, mut naive) = (Vec::new(), Vec::new(), Vec::new());
        for k in 0..400 {
            let x = draws(2000, 2 * k + 100);
            let y = draws(2000, 2 * k + 101);
            let b: Vec<f64> = x.iter().map(|x| 2.0 + x).collect();
            let a: Vec<f64> = x.iter().zip(&y).map(|(x, y)| 1.0 + 0.5 * x + y).collect();
            let (r, se) = ratio_of_means(&a, &b);
            ratios.push(r);
            stated.push(se);
            let (sa, sb) = (Sample::of(&a), Sample::of(&b));
            naive.push((sa.se().powi(2) + r * r * sb.se().powi(2)).sqrt() / sb.mean);
        }
        let scatter = Sample::of(&ratios).sd;
        let mean_stated = Sample::of(&stated).mean;
        let mean_naive = Sample::of(&naive).mean;
        assert!(
            (mean_stated / scatter - 1.0).abs() < 0.1,
            "{mean_stated} vs {scatter}"
        );
        assert!(
            (mean_naive / scatter - 1.0).abs() > 0.1,
            "{mean_naive} vs {scatter}"
        );
        assert!((Sample::of(&ratios).mean - 0.5).abs() < 0.01);
    }
}
