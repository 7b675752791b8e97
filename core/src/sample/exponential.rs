//! The standard exponential distribution, density `exp(-x)` on `x >= 0`, by the ziggurat method
//! (Marsaglia and Tsang 2000, 256 layers); the tail beyond `R = 7.697...` is `R - ln(U)` by
//! memorylessness. Gives the waiting times `tau = -ln(r) / rate` of GRW Section 3 step 2.1
//! exactly and faster than a logarithm.
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::standard_exponential};
//! let mut rng = seeded(1);
//! assert!(standard_exponential(&mut rng) >= 0.0);
//! ```

use super::squeeze::{Shape, Wedge};
use super::ziggurat_tables::{EXP_F, EXP_R, EXP_X};
use crate::math::{Real, exp, ln, one_to_two};
use crate::rng::{Rng, uniform_open01, uniform01};

/// One standard exponential variate (ziggurat, 256 layers). As for
/// [`super::standard_normal`], the fast path is inlined and the rejection path is cold.
#[inline(always)]
pub fn standard_exponential<R: Rng + ?Sized>(rng: &mut R) -> Real {
    let bits = rng.next_u64();
    let i = (bits & 0xff) as usize;
    let u = one_to_two(bits) - 1.0;
    let x = u * EXP_X[i];
    if x < EXP_X[i + 1] {
        return x;
    }
    exponential_rejection(rng, i, x)
}

/// One standard exponential variate from a uniform 32-bit `h` (stream version 2: the exact
/// loops' waiting time shares its generator word with the candidate's acceptance uniform,
/// [`crate::engine`]): layer `h & 0xff`, abscissa from the high 24 bits on a grid of 2^24
/// points; the rejection path as [`standard_exponential`]'s (fresh 64-bit draws).
#[inline(always)]
pub fn exponential_from_half<R: Rng + ?Sized>(rng: &mut R, h: u32) -> Real {
    let i = (h & 0xff) as usize;
    // `1 + k 2^-24` for the high 24 bits `k`, from its bits (exact); `u = k 2^-24`.
    let u = f64::from_bits(((h >> 8) as u64) << 28 | 0x3ff0_0000_0000_0000) - 1.0;
    let x = u * EXP_X[i];
    if x < EXP_X[i + 1] {
        return x;
    }
    exponential_rejection(rng, i, x)
}

/// Layer `i >= 1`'s wedge `x in [x_{i+1}, x_i]` of `exp(-x)` ([`Wedge`]): convex, so squeezed
/// between its tangents and its chord.
#[inline(always)]
pub(super) fn wedge(i: usize) -> Wedge {
    let (a, b, fa, fb) = (EXP_X[i + 1], EXP_X[i], EXP_F[i + 1], EXP_F[i]);
    Wedge {
        a,
        b,
        fa,
        fb,
        da: -fa,
        db: -fb,
        shape: Shape::Convex,
    }
}

/// The rejection path from a draw `(i, x)` outside its layer's rectangle: the tail of the base
/// strip, or the wedge test, then fresh draws as [`standard_exponential`] makes them.
#[cold]
#[inline(never)]
fn exponential_rejection<R: Rng + ?Sized>(rng: &mut R, i: usize, x: Real) -> Real {
    let (mut i, mut x) = (i, x);
    loop {
        if i == 0 {
            return EXP_R - ln(uniform_open01(rng));
        }
        let y = EXP_F[i + 1] + (EXP_F[i] - EXP_F[i + 1]) * uniform01(rng);
        let inside = match wedge(i).decide(x, y) {
            Some(d) => d,
            None => y < exp(-x),
        };
        if inside {
            return x;
        }
        let bits = rng.next_u64();
        i = (bits & 0xff) as usize;
        let u = one_to_two(bits) - 1.0;
        x = u * EXP_X[i];
        if x < EXP_X[i + 1] {
            return x;
        }
    }
}
