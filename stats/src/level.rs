//! The levels and multipliers of every interval gdsmc prints or tests: the papers' 99.9%
//! interval (GRW (25), lambda_p = 3.2), its Student-t form at few samples, and Bonferroni
//! families of checks judged together.
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
#[must_use]
pub fn level_999() -> f64 {
    2.0 * Normal::standard().cdf(LAMBDA_999) - 1.0
}

/// The half-width multiplier of a mean of `samples` values with estimated variance: the
/// Student-t quantile with `samples - 1` degrees of freedom at the two-sided level of
/// [`LAMBDA_999`] (see the module docs). NaN below two samples.
#[must_use]
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
#[must_use]
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

/// The degrees of freedom of a variance estimated from `samples` values: `samples - 1`
/// (0 for an empty sample, whose quantile is NaN).
#[must_use]
pub fn dof(samples: u64) -> u64 {
    samples.saturating_sub(1)
}

/// Degrees of freedom standing for a variance known exactly (the normal quantile).
pub const KNOWN: u64 = u64::MAX;

/// The probability a 99.9% interval may miss: `1 - level_999()` (0.00137).
#[must_use]
pub fn miss() -> f64 {
    1.0 - level_999()
}

/// The multiplier that makes `k` two-sided intervals hold together at the 99.9% level
/// (Bonferroni: each at `1 - miss/k`), Student-t with `dof` degrees of freedom ([`KNOWN`]: the
/// normal quantile). `joint(1, KNOWN)` is 3.2.
#[must_use]
pub fn joint(k: usize, dof: u64) -> f64 {
    let level = 1.0 - miss() / k.max(1) as f64;
    quantile_t(if dof == KNOWN { u64::MAX / 2 } else { dof }, level)
}

/// The factor that widens a single check's 99.9% half-width (made with `joint(1, dof)`, i.e.
/// [`multiplier`]) so that `k` checks hold together at the 99.9% level (Bonferroni):
/// `joint(k, dof) / joint(1, dof)`. 1 for one check; about 1.34 for 100 normal checks.
#[must_use]
pub fn family(k: usize, dof: u64) -> f64 {
    joint(k, dof) / joint(1, dof)
}

#[cfg(test)]
mod tests {
    use super::*;

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

    /// The Bonferroni widening against the normal quantile found independently (bisection on
    /// erfc): one check is not widened, and 100 checks at 1 - 0.00137/100 need z = 4.353.
    #[test]
    fn family_widens_as_bonferroni() {
        assert_eq!(family(1, KNOWN), 1.0);
        assert_eq!(family(1, 7), 1.0);
        let p = miss() / 100.0;
        let (mut lo, mut hi) = (0.0f64, 40.0f64);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if statrs::function::erf::erfc(mid / std::f64::consts::SQRT_2) > p {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        assert!(
            (joint(100, KNOWN) - lo).abs() < 1e-6,
            "{} vs {lo}",
            joint(100, KNOWN)
        );
        assert!((family(100, KNOWN) * joint(1, KNOWN) - lo).abs() < 1e-6);
        // Few samples widen more than the normal family does.
        assert!(family(100, 9) > family(100, KNOWN));
        assert_eq!(dof(1), 0);
        assert_eq!(dof(0), 0);
        assert!(joint(1, dof(1)).is_nan());
    }
}
