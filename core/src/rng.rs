//! Random numbers: the Xoshiro256++ generator, independent streams by jumps, and the uniform
//! variates every sampler starts from.
//!
//! Every sampler in the core is generic over [`Rng`] (rand_core 0.10's name for the former
//! `RngCore`), so callers may plug in any generator; runs of gdsmc use [`Xoshiro256PlusPlus`].

use crate::math::Real;
pub use rand_core::{Rng, SeedableRng};
pub use rand_xoshiro::Xoshiro256PlusPlus;

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
/// 2.3-2.4, with `j` drawn from the `n - 1` others directly instead of by repetition.
#[inline(always)]
pub fn uniform_pair<R: Rng + ?Sized>(rng: &mut R, n: usize) -> (usize, usize) {
    let i = uniform_index(rng, n);
    let mut j = uniform_index(rng, n - 1);
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
