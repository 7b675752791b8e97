//! Random numbers: the Xoshiro256++ generator, independent streams by jumps, and the uniform
//! variates every sampler starts from.
//!
//! Every sampler in the core is generic over [`Rng`] (rand_core 0.10's name for the former
//! `RngCore`), so callers may plug in any generator; runs of gdsmc use [`Xoshiro256PlusPlus`].

use crate::math::Real;
pub use rand_core::{Rng, SeedableRng};
pub use rand_xoshiro::Xoshiro256PlusPlus;

/// The version of the random streams: which draws a run makes from its generator, and how.
/// A run is a pure function of (scene, seed, stream version); outputs, journals and the C ABI
/// state it, and a journal of another version is refused.
///
/// - 1: every sampler took whole 64-bit words.
/// - 2: a candidate pair from one word (two 32-bit Lemire draws, [`uniform_pair`]); a direction
///   on the sphere or the circle from one word per try (two 32-bit coordinates,
///   [`signed_unit32`]); two normals from one word (two 32-bit ziggurat draws,
///   [`crate::sample::standard_normal_pair`]); the undriven Maxwell gas's events counted per
///   interval by a Poisson draw instead of one waiting time each.
pub const STREAM_VERSION: u32 = 2;

/// 2^-32, the spacing of [`signed_unit32`]'s values divided by 2.
const TWO_POW_M31: Real = 1.0 / 2_147_483_648.0;

/// 2^-53, the spacing of the doubles produced by [`uniform01`].
const TWO_POW_M53: Real = 1.0 / 9_007_199_254_740_992.0;
/// 2^-52, the spacing of the doubles produced by [`uniform_open01`].
const TWO_POW_M52: Real = 1.0 / 4_503_599_627_370_496.0;

/// The generator of ensemble 0 of a run with this seed (SplitMix64 seeding of Xoshiro256++).
pub fn seeded(seed: u64) -> Xoshiro256PlusPlus {
    Xoshiro256PlusPlus::seed_from_u64(seed)
}

/// The generator of ensemble `k` of a run: the seed's generator jumped `k` times (2^128 draws
/// each), so ensembles never share a stretch of the sequence. Costs `k` jumps; to visit many
/// ensembles in order use [`Streams`].
pub fn stream(seed: u64, k: u64) -> Xoshiro256PlusPlus {
    let mut g = seeded(seed);
    for _ in 0..k {
        g.jump();
    }
    g
}

/// The ensemble generators of a run in order, each the previous one jumped once.
#[derive(Clone, Debug)]
pub struct Streams {
    next: Xoshiro256PlusPlus,
}

impl Streams {
    /// The streams of a run with this seed, starting at ensemble 0.
    pub fn new(seed: u64) -> Self {
        Streams { next: seeded(seed) }
    }
}

impl Iterator for Streams {
    type Item = Xoshiro256PlusPlus;
    fn next(&mut self) -> Option<Xoshiro256PlusPlus> {
        let out = self.next.clone();
        self.next.jump();
        Some(out)
    }
}

/// A uniform double in the open interval (0, 1): `(k + 1/2) 2^-52` for a uniform 52-bit `k`,
/// the midpoints of 2^52 equal cells. Never 0 and never 1 (with 53 bits the top value
/// `1 - 2^-54` would round to 1), so a logarithm may follow.
#[inline(always)]
pub fn uniform_open01<R: Rng + ?Sized>(rng: &mut R) -> Real {
    ((rng.next_u64() >> 12) as Real + 0.5) * TWO_POW_M52
}

/// A uniform double in [0, 1): `k 2^-53` for a uniform 53-bit `k`.
#[inline(always)]
pub fn uniform01<R: Rng + ?Sized>(rng: &mut R) -> Real {
    (rng.next_u64() >> 11) as Real * TWO_POW_M53
}

/// The high and low 32-bit halves of one generator word: two independent uniform 32-bit
/// integers.
#[inline(always)]
pub fn halves(bits: u64) -> (u32, u32) {
    ((bits >> 32) as u32, bits as u32)
}

/// A uniform double in the open interval (-1, 1) from a uniform 32-bit `h`: `(h + 1/2) 2^-31 - 1`,
/// the midpoints of 2^32 equal cells, symmetric about 0 (a coordinate of Marsaglia's point in
/// the disk, [`crate::sample::unit_sphere`]).
#[inline(always)]
pub fn signed_unit32(h: u32) -> Real {
    (h as Real + 0.5) * TWO_POW_M31 - 1.0
}

/// A uniform double in the open interval (0, 1) from a uniform 32-bit `h`: `(h + 1/2) 2^-32`,
/// the midpoints of 2^32 equal cells (the exact loops' acceptance uniform, stream version 2).
#[inline(always)]
pub fn unit_open32(h: u32) -> Real {
    (h as Real + 0.5) * (0.5 * TWO_POW_M31)
}

/// A uniform integer in `0..n` (`1 <= n <= 2^32`) from a uniform 32-bit `h`, exactly uniform:
/// Lemire's multiply-and-reject on 32 bits, a rejected `h` replaced by the high half of a fresh
/// word.
#[inline(always)]
fn index_from_half<R: Rng + ?Sized>(rng: &mut R, h: u32, n: u64) -> usize {
    let mut m = (h as u64) * n;
    if ((m as u32) as u64) < n {
        let threshold = (1u64 << 32) % n;
        while ((m as u32) as u64) < threshold {
            m = (rng.next_u64() >> 32) * n;
        }
    }
    (m >> 32) as usize
}

/// Two independent uniform integers in `0..n1` and `0..n2` (`n1, n2 >= 1`), each exactly
/// uniform, from one generator word when both are at most 2^32 (its halves,
/// `index_from_half`; a rejection, with probability below `n/2^32`, draws again), else
/// from [`uniform_index`] twice.
#[inline(always)]
pub fn uniform_index2<R: Rng + ?Sized>(rng: &mut R, n1: usize, n2: usize) -> (usize, usize) {
    debug_assert!(n1 >= 1 && n2 >= 1);
    const LIMIT: u64 = 1 << 32;
    if n1 as u64 > LIMIT || n2 as u64 > LIMIT {
        let i = uniform_index(rng, n1);
        return (i, uniform_index(rng, n2));
    }
    let (hi, lo) = halves(rng.next_u64());
    let i = index_from_half(rng, hi, n1 as u64);
    (i, index_from_half(rng, lo, n2 as u64))
}

/// A uniform integer in `0..n` (`n >= 1`), exactly uniform: Lemire's multiply-and-reject.
#[inline(always)]
pub fn uniform_index<R: Rng + ?Sized>(rng: &mut R, n: usize) -> usize {
    debug_assert!(n >= 1);
    let n = n as u64;
    let mut m = (rng.next_u64() as u128) * (n as u128);
    if (m as u64) < n {
        let threshold = n.wrapping_neg() % n;
        while (m as u64) < threshold {
            m = (rng.next_u64() as u128) * (n as u128);
        }
    }
    (m >> 64) as usize
}

/// An ordered pair `(i, j)` uniform on `{0 <= i != j < n}` (`n >= 2`): GRW Section 3 steps
/// 2.3-2.4, with `j` drawn from the `n - 1` others directly instead of by repetition; both
/// from one generator word ([`uniform_index2`]).
#[inline(always)]
pub fn uniform_pair<R: Rng + ?Sized>(rng: &mut R, n: usize) -> (usize, usize) {
    let (i, mut j) = uniform_index2(rng, n, n - 1);
    if j >= i {
        j += 1;
    }
    (i, j)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn open_interval_never_touches_the_ends() {
        struct Fixed(u64);
        impl rand_core::TryRng for Fixed {
            type Error = core::convert::Infallible;
            fn try_next_u32(&mut self) -> Result<u32, Self::Error> {
                Ok(self.0 as u32)
            }
            fn try_next_u64(&mut self) -> Result<u64, Self::Error> {
                Ok(self.0)
            }
            fn try_fill_bytes(&mut self, _: &mut [u8]) -> Result<(), Self::Error> {
                Ok(())
            }
        }
        let lo = uniform_open01(&mut Fixed(0));
        let hi = uniform_open01(&mut Fixed(u64::MAX));
        assert!(lo > 0.0 && lo < 1e-15);
        assert!(hi < 1.0 && hi > 1.0 - 1e-15);
        assert_eq!(lo, 2f64.powi(-53));
        assert_eq!(hi, 1.0 - 2f64.powi(-53));
        assert!(uniform01(&mut Fixed(0)) == 0.0);
        assert!(uniform01(&mut Fixed(u64::MAX)) < 1.0);
    }

    #[test]
    fn streams_are_jumps() {
        let mut s = Streams::new(42);
        let a0 = s.next().unwrap();
        let a3 = s.nth(2).unwrap();
        assert_eq!(a0, stream(42, 0));
        assert_eq!(a3, stream(42, 3));
        assert_ne!(stream(42, 1), stream(42, 2));
    }

    #[test]
    fn pairs_are_distinct_and_cover_all() {
        let mut rng = seeded(7);
        let n = 5;
        let mut counts = [[0u32; 5]; 5];
        for _ in 0..200_000 {
            let (i, j) = uniform_pair(&mut rng, n);
            assert_ne!(i, j);
            counts[i][j] += 1;
        }
        // 20 ordered pairs, 10,000 expected each; binomial sd ~ 97.5. Bonferroni over the 20 cells
        // at family level 99.9%: two-sided z = 4.06 per cell.
        for (i, row) in counts.iter().enumerate() {
            for (j, &c) in row.iter().enumerate() {
                if i != j {
                    assert!(
                        (c as f64 - 10_000.0).abs() < 4.06 * 97.5,
                        "pair ({i},{j}): {c}"
                    );
                }
            }
        }
    }
}
