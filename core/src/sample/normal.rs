//! The standard normal distribution, density `exp(-x^2/2) / sqrt(2 pi)`, by the ziggurat method
//! of Marsaglia and Tsang (2000) with 256 layers: one 64-bit draw and one table comparison in
//! about 98.8% of cases; the wedges are resolved by exact rejection (squeezed: `exp` only near
//! the wedge's bounds, `super::squeeze`) and the tail beyond `R = 3.654...` by Marsaglia's
//! exact tail method. Used for the white-noise kicks GRW (18).
//!
//! [`standard_normal_pair`] makes two variates from one 64-bit word (stream version 2): each
//! 32-bit half gives a layer from its low 8 bits and the abscissa from its high 24, a grid of
//! 2^24 midpoints across the layer instead of 2^52 points; the rejection path is the same
//! (fresh 64-bit draws). The law is the ziggurat's on that grid, whose spacing (`2^-23 x_i`,
//! at most 4.7e-7) is far below any statistic's resolution (two-sample tests in
//! `core/tests/`).
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::standard_normal};
//! let mut rng = seeded(1);
//! let x = standard_normal(&mut rng);
//! assert!(x.is_finite());
//! ```

use super::squeeze::{Shape, Wedge};
use super::ziggurat_tables::{NORM_F, NORM_R, NORM_X};
use crate::math::{Real, abs, exp, ln, one_to_two};
use crate::rng::{Rng, halves, uniform_open01, uniform01};
use crate::vec3::Vec3;

/// One standard normal variate (Marsaglia-Tsang ziggurat, 256 layers). The fast path (about
/// 99% of draws: one generator word, one multiply, one compare) is inlined at every call site;
/// the rejection path is a cold function of its own, so the inliner of a large event loop keeps
/// the fast path (measured: callgrind, heated hard spheres, see ARCHITECTURE.md).
#[inline(always)]
pub fn standard_normal<R: Rng + ?Sized>(rng: &mut R) -> Real {
    let bits = rng.next_u64();
    let i = (bits & 0xff) as usize;
    // Uniform in [-1, 1) from the top 52 bits, `u = 2 one_to_two(bits) - 3 = m 2^-51` with the
    // integer `m = (bits >> 12) - 2^51` (an arithmetic shift of the word with its top bit
    // flipped), so `u X_i` is `m` times the table's `X_i 2^-51`: the same product, rounded once,
    // in fewer instructions. The layer index uses the low 8 bits.
    // (A firmware keeps `2 one_to_two(bits) - 3`: the table would not fit the micro:bit's
    // flash.)
    #[cfg(target_os = "none")]
    let (u, x) = {
        let u = 2.0 * one_to_two(bits) - 3.0;
        (u, u * NORM_X[i])
    };
    #[cfg(not(target_os = "none"))]
    let (u, x) = {
        let m = ((bits ^ (1 << 63)) as i64) >> 12;
        (m as Real * TWO_POW_M51, m as Real * NORM_X_WORD[i])
    };
    if abs(x) < NORM_X[i + 1] {
        return x;
    }
    normal_rejection(rng, i, u, x)
}

/// Two independent standard normal variates from one generator word (module docs): the
/// ziggurat's fast path on each 32-bit half, the rejection path as [`standard_normal`]'s.
#[inline(always)]
pub fn standard_normal_pair<R: Rng + ?Sized>(rng: &mut R) -> (Real, Real) {
    let (hi, lo) = halves(rng.next_u64());
    if cfg!(target_os = "none") {
        // A loop over the halves: one copy of the fast path in a firmware built for size (the
        // micro:bit's); on hosts two inlined copies (the loop cost 3% more instructions).
        let mut x = [0.0; 2];
        for (x, h) in x.iter_mut().zip([lo, hi]) {
            *x = normal_from_half(rng, h);
        }
        (x[0], x[1])
    } else {
        let x = normal_from_half(rng, lo);
        (x, normal_from_half(rng, hi))
    }
}

/// The ziggurat on a 32-bit half `h`: layer `h & 0xff`, abscissa `u` in (-1, 1) from the high
/// 24 bits at the midpoints of 2^24 cells.
#[inline(always)]
fn normal_from_half<R: Rng + ?Sized>(rng: &mut R, h: u32) -> Real {
    let (x, inside, i, m) = half_fast(h);
    if inside {
        return x;
    }
    normal_rejection(rng, i, m as Real * TWO_POW_M24, x)
}

/// The ziggurat's fast path on a 32-bit half `h`: its draw `x`, whether `x` lies in its layer's
/// rectangle (then `x` is the variate), the layer `i = h & 0xff` and the integer `m` of the
/// abscissa `u = m 2^-24`. `u = (k + 1/2) 2^-23 - 1` for the high 24 bits `k` is
/// `m = 2 k + 1 - 2^24`: the half with its top bit flipped, shifted arithmetically by 7, its
/// lowest bit set. `u X_i` is then `m` times the table's `X_i 2^-24`, the same product rounded
/// once (a power of two scales exactly).
#[inline(always)]
fn half_fast(h: u32) -> (Real, bool, usize, i32) {
    let i = (h & 0xff) as usize;
    let m = (((h ^ 0x8000_0000) as i32) >> 7) | 1;
    // A firmware multiplies `X_i` by `u` built from the half's bits: the same product without
    // the scaled table, which would not fit the micro:bit's flash.
    #[cfg(target_os = "none")]
    let x = half_abscissa_from_bits(h) * NORM_X[i];
    #[cfg(not(target_os = "none"))]
    let x = m as Real * NORM_X_HALF[i];
    (x, abs(x) < NORM_X[i + 1], i, m)
}

/// A half's abscissa `u = 2 (1 + (k + 1/2) 2^-24) - 3` for its high 24 bits `k`, built from
/// the bits of `1 + (k + 1/2) 2^-24` (exact): the written form the firmware keeps, and the
/// tests' reference for [`half_fast`]'s integer.
#[cfg(any(target_os = "none", test))]
#[inline(always)]
fn half_abscissa_from_bits(h: u32) -> Real {
    let f = f64::from_bits(((h >> 8) as u64) << 28 | 1 << 27 | 0x3ff0_0000_0000_0000);
    2.0 * f - 3.0
}

/// 2^-24, the spacing of a half's abscissa integer `m` ([`half_fast`]).
const TWO_POW_M24: Real = 1.0 / 16_777_216.0;
/// 2^-51, the spacing of a word's abscissa integer ([`standard_normal`]).
#[cfg(not(target_os = "none"))]
const TWO_POW_M51: Real = 1.0 / 2_251_799_813_685_248.0;

/// `NORM_X` times `scale` (a power of two: exact), at compile time.
#[cfg(not(target_os = "none"))]
const fn scaled(scale: Real) -> [Real; 257] {
    let mut t = [0.0; 257];
    let mut k = 0;
    while k < 257 {
        t[k] = NORM_X[k] * scale;
        k += 1;
    }
    t
}

/// The layers' abscissae times 2^-24, for the 32-bit halves' integers ([`half_fast`]).
#[cfg(not(target_os = "none"))]
static NORM_X_HALF: [Real; 257] = scaled(TWO_POW_M24);
/// The layers' abscissae times 2^-51, for the words' integers ([`standard_normal`]).
#[cfg(not(target_os = "none"))]
static NORM_X_WORD: [Real; 257] = scaled(TWO_POW_M51);

/// The ziggurat's rejection path from a draw `(i, u, x)` outside its layer's rectangle: the
/// base strip's tail, or the wedge test, then fresh draws as [`standard_normal`] makes them.
#[cold]
#[inline(never)]
fn normal_rejection<R: Rng + ?Sized>(rng: &mut R, i: usize, u: Real, x: Real) -> Real {
    let (mut i, mut u, mut x) = (i, u, x);
    loop {
        if i == 0 {
            return tail(rng, u < 0.0);
        }
        let y = NORM_F[i + 1] + (NORM_F[i] - NORM_F[i + 1]) * uniform01(rng);
        let inside = match wedge(i).and_then(|w| w.decide(abs(x), y)) {
            Some(d) => d,
            None => y < exp(-0.5 * x * x),
        };
        if inside {
            return x;
        }
        let bits = rng.next_u64();
        i = (bits & 0xff) as usize;
        u = 2.0 * one_to_two(bits) - 3.0;
        x = u * NORM_X[i];
        if abs(x) < NORM_X[i + 1] {
            return x;
        }
    }
}

/// Layer `i >= 1`'s wedge `|x| in [x_{i+1}, x_i]` of `exp(-x^2/2)` ([`Wedge`]): convex beyond
/// `|x| = 1`, concave inside it; `None` for the one layer that straddles 1.
#[inline(always)]
pub(super) fn wedge(i: usize) -> Option<Wedge> {
    let (a, b, fa, fb) = (NORM_X[i + 1], NORM_X[i], NORM_F[i + 1], NORM_F[i]);
    let shape = if a >= 1.0 {
        Shape::Convex
    } else if b <= 1.0 {
        Shape::Concave
    } else {
        return None;
    };
    Some(Wedge {
        a,
        b,
        fa,
        fb,
        da: -a * fa,
        db: -b * fb,
        shape,
    })
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

/// A vector of three independent standard normal variates: a pair from one word
/// ([`standard_normal_pair`]) and one from another ([`standard_normal`]).
#[inline(always)]
pub fn standard_normal3<R: Rng + ?Sized>(rng: &mut R) -> Vec3 {
    let (x, y) = standard_normal_pair(rng);
    let z = standard_normal(rng);
    Vec3::new(x, y, z)
}

/// Four vectors of three independent standard normal variates, in order, from six pairs
/// ([`standard_normal_pair`]): the normals of a block of four particles' kicks.
#[inline(always)]
pub fn standard_normal3x4<R: Rng + ?Sized>(rng: &mut R) -> [Vec3; 4] {
    if cfg!(target_os = "none") {
        // A loop in a firmware built for size; on hosts the six pairs written out (the loop
        // cost 2% more instructions in GRW Example 3).
        let g: [Real; 12] = standard_normals(rng);
        return core::array::from_fn(|k| Vec3::new(g[3 * k], g[3 * k + 1], g[3 * k + 2]));
    }
    let (a, b) = standard_normal_pair(rng);
    let (c, d) = standard_normal_pair(rng);
    let (e, f) = standard_normal_pair(rng);
    let (g, h) = standard_normal_pair(rng);
    let (i, j) = standard_normal_pair(rng);
    let (k, l) = standard_normal_pair(rng);
    [
        Vec3::new(a, b, c),
        Vec3::new(d, e, f),
        Vec3::new(g, h, i),
        Vec3::new(j, k, l),
    ]
}

/// `N` (even) independent standard normal variates in order, from `N / 2` words
/// ([`standard_normal_pair`]), by a loop (one copy of the sampler in a build for size).
#[inline(always)]
pub fn standard_normals<R: Rng + ?Sized, const N: usize>(rng: &mut R) -> [Real; N] {
    let mut g = [0.0; N];
    let mut k = 0;
    while k + 1 < N {
        (g[k], g[k + 1]) = standard_normal_pair(rng);
        k += 2;
    }
    g
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::{Rng, seeded};

    /// The fast path as stream version 2 first wrote it: `u` from the half's bits, then
    /// `u X_i`.
    fn half_as_written(h: u32) -> Real {
        half_abscissa_from_bits(h) * NORM_X[(h & 0xff) as usize]
    }

    fn word_as_written(bits: u64) -> Real {
        (2.0 * one_to_two(bits) - 3.0) * NORM_X[(bits & 0xff) as usize]
    }

    fn check_half(h: u32) {
        let (x, inside, i, m) = half_fast(h);
        assert_eq!(x.to_bits(), half_as_written(h).to_bits(), "{h:#x}");
        assert_eq!(inside, abs(half_as_written(h)) < NORM_X[i + 1]);
        assert_eq!(m as Real * TWO_POW_M24, half_abscissa_from_bits(h));
    }

    #[test]
    fn the_integer_abscissa_is_the_written_one_to_the_bit() {
        let mut rng = seeded(17);
        for h in [
            0,
            1,
            0xff,
            0x100,
            0x7fff_ffff,
            0x8000_0000,
            0x8000_00ff,
            u32::MAX,
        ] {
            check_half(h);
        }
        for _ in 0..1_000_000 {
            let w = rng.next_u64();
            check_half(w as u32);
            check_half((w >> 32) as u32);
            let i = (w & 0xff) as usize;
            let m = ((w ^ (1 << 63)) as i64) >> 12;
            assert_eq!(
                (m as Real * NORM_X_WORD[i]).to_bits(),
                word_as_written(w).to_bits()
            );
            assert_eq!(m as Real * TWO_POW_M51, 2.0 * one_to_two(w) - 3.0);
        }
    }

    /// Every one of the 2^32 halves (run once by hand; release build): `cargo test --release -p
    /// gdsmc-core --lib every_half -- --ignored`.
    #[test]
    #[ignore]
    fn every_half_is_the_written_one_to_the_bit() {
        for h in 0..=u32::MAX {
            let (x, ..) = half_fast(h);
            assert_eq!(x.to_bits(), half_as_written(h).to_bits(), "{h:#x}");
        }
    }
}
