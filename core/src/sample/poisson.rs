//! The Poisson distribution, `P(k) = mu^k e^-mu / k!`: the number of events of a Poisson
//! process of rate `r` in a time `t` (`mu = r t`). The undriven Maxwell gas's loop draws how
//! many collisions an interval holds from it (GRW Section 3: every candidate of the Maxwell
//! kernel collides and nothing between collisions depends on their times; stream version 2).
//!
//! For `mu < 10` Knuth's product of uniforms; above, Hörmann's transformed rejection with
//! squeeze, PTRS ("The transformed rejection method for generating Poisson random variables",
//! Insurance: Mathematics and Economics 12 (1993) 39-45), its acceptance test on `ln P(k)`
//! evaluated by Loader's saddle-point form ("Fast and accurate computation of binomial
//! probabilities", 2000: `ln P(k) = -stirlerr(k) - bd0(k, mu) - ln sqrt(2 pi k)`), which keeps
//! its digits where `k ln mu`, `mu` and `ln k!` are each far larger than their sum. A mean
//! above 2^40 is drawn as a sum of means of 2^40 and the rest (the law is additive).
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::poisson};
//! let mut rng = seeded(1);
//! let k = poisson(&mut rng, 1e6);
//! assert!((k as f64 - 1e6).abs() < 6e3);
//! ```

use crate::math::{Real, abs, exp, floor, ln, sqrt};
use crate::rng::{Rng, uniform_open01, uniform01};

/// Means at most this are drawn in one piece.
const PIECE: Real = 1_099_511_627_776.0;

/// `ln sqrt(2 pi)`.
const LN_SQRT_2PI: Real = 0.918_938_533_204_672_8;

/// `ln k!` for `k = 0..=15` (the logarithms of the exact factorials).
#[allow(clippy::excessive_precision)]
const LN_FACTORIAL: [Real; 16] = [
    0.0,
    0.0,
    core::f64::consts::LN_2,
    1.791759469228055,
    3.1780538303479458,
    4.787491742782046,
    6.579251212010101,
    8.525161361065415,
    10.60460290274525,
    12.801827480081469,
    15.104412573075516,
    17.502307845873887,
    19.987214495661885,
    22.552163853123425,
    25.19122118273868,
    27.89927138384089,
];

/// A Poisson variate of mean `mu` (0 when `mu` is not positive: no events).
pub fn poisson<R: Rng + ?Sized>(rng: &mut R, mu: Real) -> u64 {
    let (mut k, mut left) = (0u64, mu);
    while left > PIECE {
        k += ptrs(rng, PIECE);
        left -= PIECE;
    }
    // Not `left <= 0.0` alone: a NaN mean draws no events either.
    if left.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        k
    } else if left < 10.0 {
        k + knuth(rng, left)
    } else {
        k + ptrs(rng, left)
    }
}

/// Knuth: the number of uniforms whose running product stays above `e^-mu` (`mu < 10`).
fn knuth<R: Rng + ?Sized>(rng: &mut R, mu: Real) -> u64 {
    let limit = exp(-mu);
    let (mut k, mut product) = (0, uniform_open01(rng));
    while product > limit {
        product *= uniform_open01(rng);
        k += 1;
    }
    k
}

/// PTRS (Hörmann 1993, `mu >= 10`).
fn ptrs<R: Rng + ?Sized>(rng: &mut R, mu: Real) -> u64 {
    let b = 0.931 + 2.53 * sqrt(mu);
    let a = -0.059 + 0.02483 * b;
    let inv_alpha = 1.1239 + 1.1328 / (b - 3.4);
    let v_r = 0.9277 - 3.6224 / (b - 2.0);
    loop {
        let u = uniform01(rng) - 0.5;
        let v = uniform_open01(rng);
        let us = 0.5 - abs(u);
        let k = floor((2.0 * a / us + b) * u + mu + 0.43);
        if us >= 0.07 && v <= v_r {
            return k as u64;
        }
        if k < 0.0 || (us < 0.013 && v > us) {
            continue;
        }
        if ln(v * inv_alpha / (a / (us * us) + b)) <= ln_probability(k, mu) {
            return k as u64;
        }
    }
}

/// `ln P(k)` for a whole `k >= 0` (Loader's form, module docs).
fn ln_probability(k: Real, mu: Real) -> Real {
    if k == 0.0 {
        return -mu;
    }
    -stirling_error(k) - bd0(k, mu) - LN_SQRT_2PI - 0.5 * ln(k)
}

/// `ln k! - ((k + 1/2) ln k - k + ln sqrt(2 pi))`, Stirling's error for a whole `k >= 1`: its
/// series beyond 15, from the table of `ln k!` below (where the terms are small; no `lgamma`,
/// which would not fit the micro:bit's firmware).
fn stirling_error(k: Real) -> Real {
    if k <= 15.0 {
        return LN_FACTORIAL[k as usize] - (k + 0.5) * ln(k) + k - LN_SQRT_2PI;
    }
    let k2 = k * k;
    (1.0 / 12.0 - (1.0 / 360.0 - (1.0 / 1260.0 - (1.0 / 1680.0) / k2) / k2) / k2) / k
}

/// `k ln(k/mu) + mu - k`, the deviance term, by its series where `k` is near `mu` (Loader).
fn bd0(k: Real, mu: Real) -> Real {
    if abs(k - mu) < 0.1 * (k + mu) {
        let v = (k - mu) / (k + mu);
        let mut s = (k - mu) * v;
        let mut ej = 2.0 * k * v;
        let v2 = v * v;
        let mut j = 1.0;
        loop {
            ej *= v2;
            let next = s + ej / (2.0 * j + 1.0);
            if next == s {
                return s;
            }
            s = next;
            j += 1.0;
        }
    }
    k * ln(k / mu) + mu - k
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Loader's form against `ln Gamma` where the direct form keeps its digits.
    #[test]
    fn log_probability_matches_the_direct_form() {
        let ln_gamma = libm::lgamma;
        for &mu in &[10.0, 37.5, 200.0] {
            for k in [0.0, 1.0, 5.0, 14.0, 15.0, 16.0, 40.0, 180.0, 230.0] {
                let direct = -mu + k * ln(mu) - ln_gamma(k + 1.0);
                let loader = ln_probability(k, mu);
                assert!(
                    (direct - loader).abs() < 1e-11 * (1.0 + direct.abs()),
                    "mu {mu} k {k}: {direct} vs {loader}"
                );
            }
        }
    }
}
