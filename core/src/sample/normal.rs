//! The standard normal distribution, density `exp(-x^2/2) / sqrt(2 pi)`, by the ziggurat method
//! of Marsaglia and Tsang (2000) with 256 layers: one 64-bit draw and one table comparison in
//! about 98.8% of cases; the wedges are resolved by exact rejection and the tail beyond
//! `R = 3.654...` by Marsaglia's exact tail method. Used for the white-noise kicks GRW (18).
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::standard_normal};
//! let mut rng = seeded(1);
//! let x = standard_normal(&mut rng);
//! assert!(x.is_finite());
//! ```

use super::ziggurat_tables::{NORM_F, NORM_R, NORM_X};
use crate::math::{Real, abs, exp, ln, one_to_two};
use crate::rng::{Rng, uniform_open01, uniform01};
use crate::vec3::Vec3;

/// One standard normal variate.
#[inline]
pub fn standard_normal<R: Rng + ?Sized>(rng: &mut R) -> Real {
    loop {
        let bits = rng.next_u64();
        let i = (bits & 0xff) as usize;
        // Uniform in [-1, 1) from the top 52 bits; the layer index uses the low 8 bits.
        let u = 2.0 * one_to_two(bits) - 3.0;
        let x = u * NORM_X[i];
        if abs(x) < NORM_X[i + 1] {
            return x;
        }
        if i == 0 {
            return tail(rng, u < 0.0);
        }
        let y = NORM_F[i + 1] + (NORM_F[i] - NORM_F[i + 1]) * uniform01(rng);
        if y < exp(-0.5 * x * x) {
            return x;
        }
    }
}

/// The normal tail beyond `R` (Marsaglia 1964): exact.
#[cold]
fn tail<R: Rng + ?Sized>(rng: &mut R, negative: bool) -> Real {
    loop {
        let x = ln(uniform_open01(rng)) / NORM_R;
        let y = ln(uniform_open01(rng));
        if -2.0 * y >= x * x {
            return if negative { x - NORM_R } else { NORM_R - x };
        }
    }
}

/// A vector of three independent standard normal variates.
#[inline(always)]
pub fn standard_normal3<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
    let x = standard_normal(rng);
    let y = standard_normal(rng);
    let z = standard_normal(rng);
    Vec3::new(x, y, z)
}
