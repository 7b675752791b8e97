//! Standard normal pairs drawn in blocks, bit for bit as [`super::standard_normal_pair`] draws
//! them one after another (stream version 2), in fewer instructions.
//!
//! A block of `W` pairs takes its `W` generator words first, one after another, so the
//! generator's state stays in registers between them (drawn pair by pair, each word's draw
//! loads and stores the state, because the rejection path between two words may read it:
//! 20 instructions a word against 12). Then the ziggurat's fast path on all `2 W` halves
//! ([`super::normal::half_fast`]). In about 99% of halves that is the variate; when one is
//! not (the block's chance is `1 - 0.988^(2W)`, 13% for six words), the block resumes from its
//! first such half exactly as the pairs drawn one by one would: that half's rejection path
//! reads its words from [`Replay`], which hands out the words the block drew ahead in their
//! order before it draws new ones, and the later pairs take the words it left (fresh ones at
//! the end), their fast paths evaluated again. The sequence of words each draw sees is the
//! sequential one, so every variate is.
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::{standard_normal_pair, standard_normal_pairs}};
//! let (mut a, mut b) = (seeded(3), seeded(3));
//! let block: [(f64, f64); 6] = standard_normal_pairs(&mut a);
//! let one_by_one: [(f64, f64); 6] = core::array::from_fn(|_| standard_normal_pair(&mut b));
//! assert_eq!(block, one_by_one);
//! assert_eq!(a, b);
//! ```

use super::normal::{TWO_POW_M24, half_fast, normal_rejection};
use crate::math::Real;
use crate::rng::{Rng, halves};
use core::convert::Infallible;

/// `W` pairs of independent standard normal variates, the same values and the same words as
/// `W` calls of [`super::standard_normal_pair`] in a row (module docs). Hot call sites take
/// the pairs one by one from a [`NormalWords`] instead: an array of pairs made here may be
/// assembled in memory, and the loads that read it back as other lanes then stall.
#[inline(always)]
pub fn standard_normal_pairs<R: Rng + ?Sized, const W: usize>(rng: &mut R) -> [(Real, Real); W] {
    let mut block = NormalWords::<R, W>::new(rng);
    core::array::from_fn(|k| block.pair_at(k))
}

/// A block of `W` generator words drawn ahead for normal pairs (module docs): pair `k` of
/// the block, asked for in order (`k = 0, 1, ..., W - 1`), is the pair the `k`-th call of
/// [`super::standard_normal_pair`] would give.
pub struct NormalWords<'a, R: ?Sized, const W: usize> {
    words: [u64; W],
    /// The words the rejection paths took so far: pair `k` reads word `k + lag` (of the block
    /// while there is one, then the generator's).
    lag: usize,
    rng: &'a mut R,
}

impl<'a, R: Rng + ?Sized, const W: usize> NormalWords<'a, R, W> {
    /// Draws the block's `W` words, one after another.
    #[inline(always)]
    pub fn new(rng: &'a mut R) -> Self {
        NormalWords {
            words: core::array::from_fn(|_| rng.next_u64()),
            lag: 0,
            rng,
        }
    }

    /// Pair `k` (asked for in order, module docs): the fast path on the halves of its word, a
    /// half outside its rectangle by its rejection path from the words after it. Written out
    /// with constant `k`, the word is read at a fixed place until a rejection took words.
    #[inline(always)]
    pub fn pair_at(&mut self, k: usize) -> (Real, Real) {
        let w = if self.lag == 0 {
            self.words[k]
        } else {
            self.shifted_word(k)
        };
        let (hi, lo) = halves(w);
        let a = self.half(k, lo);
        (a, self.half(k, hi))
    }

    /// Word `k + lag` once a rejection path took words.
    #[cold]
    #[inline(never)]
    fn shifted_word(&mut self, k: usize) -> u64 {
        match self.words.get(k + self.lag) {
            Some(&w) => w,
            None => self.rng.next_u64(),
        }
    }

    /// A half of pair `k`'s word: the fast path, or the rejection path.
    #[inline(always)]
    fn half(&mut self, k: usize, h: u32) -> Real {
        let (x, inside, i, m) = half_fast(h);
        if inside {
            return x;
        }
        self.reject(k, (i, m, x))
    }

    /// The rejection path of a half of pair `k` outside its rectangle (layer `i`, abscissa
    /// integer `m`, draw `x`), its words from [`Replay`]: the block's after pair `k`'s, then
    /// the generator's.
    #[cold]
    #[inline(never)]
    fn reject(&mut self, k: usize, (i, m, x): (usize, i32, Real)) -> Real {
        let from = (k + 1 + self.lag).min(W);
        let ahead = &self.words[from..];
        let mut replay = Replay {
            ahead,
            rng: &mut *self.rng,
            drawn: 0,
        };
        let x = normal_rejection(&mut replay, i, m as Real * TWO_POW_M24, x);
        // The words it drew past the block are the generator's own: counted too, since the
        // later pairs then read the generator.
        self.lag += ahead.len() - replay.ahead.len() + replay.drawn;
        x
    }
}

/// A generator that hands out the words a block drew ahead, in order, then draws from `rng`.
/// Only 64-bit words are asked of it: the normal sampler draws nothing else.
struct Replay<'a, R: ?Sized> {
    ahead: &'a [u64],
    rng: &'a mut R,
    /// Words drawn from `rng`.
    drawn: usize,
}

impl<R: Rng + ?Sized> rand_core::TryRng for Replay<'_, R> {
    type Error = Infallible;
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        // Never asked by the normal sampler; the high half of the next word, as a generator of
        // words gives one.
        self.try_next_u64().map(|w| (w >> 32) as u32)
    }
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        Ok(match self.ahead.split_first() {
            Some((&w, rest)) => {
                self.ahead = rest;
                w
            }
            None => {
                self.drawn += 1;
                self.rng.next_u64()
            }
        })
    }
    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        for chunk in dst.chunks_mut(8) {
            let w = self.try_next_u64()?.to_le_bytes();
            chunk.copy_from_slice(&w[..chunk.len()]);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::seeded;
    use crate::sample::standard_normal_pair;

    /// Words chosen so that given halves fall outside their rectangles: layer 0's base strip
    /// (the tail test) and a wedge, at every position of a block.
    struct Scripted<'a> {
        words: &'a [u64],
        at: usize,
        then: crate::rng::Xoshiro256PlusPlus,
    }

    impl rand_core::TryRng for Scripted<'_> {
        type Error = Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Infallible> {
            self.try_next_u64().map(|w| w as u32)
        }
        fn try_next_u64(&mut self) -> Result<u64, Infallible> {
            let w = self.words.get(self.at).copied();
            self.at += 1;
            Ok(w.unwrap_or_else(|| self.then.next_u64()))
        }
        fn try_fill_bytes(&mut self, _: &mut [u8]) -> Result<(), Infallible> {
            Ok(())
        }
    }

    fn same_as_one_by_one<const W: usize>(words: &[u64]) {
        let mut a = Scripted {
            words,
            at: 0,
            then: seeded(9),
        };
        let mut b = Scripted {
            words,
            at: 0,
            then: seeded(9),
        };
        let block: [(Real, Real); W] = standard_normal_pairs(&mut a);
        let seq: [(Real, Real); W] = core::array::from_fn(|_| standard_normal_pair(&mut b));
        for (x, y) in block.iter().zip(&seq) {
            assert_eq!(x.0.to_bits(), y.0.to_bits());
            assert_eq!(x.1.to_bits(), y.1.to_bits());
        }
        assert_eq!(a.at, b.at, "words drawn");
        assert_eq!(a.then, b.then);
    }

    #[test]
    fn a_block_is_the_pairs_one_by_one_wherever_a_half_is_rejected() {
        // A half outside its rectangle: layer 0 (the base strip, |u| near 1) or layer 200 at
        // the layer's edge (its wedge), as low or high half; words from seed 9 elsewhere.
        let out_halves = [0xffff_ff00_u32, 0x0000_0000, 0xffff_ffc8, 0x0000_00c8];
        for &h in &out_halves {
            assert!(!half_fast(h).1, "{h:#x} must fall outside its rectangle");
        }
        let mut filler = seeded(5);
        let put = |words: &mut [u64], pos: usize, h: u32| {
            let w = &mut words[pos / 2];
            *w = if pos.is_multiple_of(2) {
                (*w & !0xffff_ffff) | h as u64
            } else {
                (*w & 0xffff_ffff) | (h as u64) << 32
            };
        };
        // One half outside at every position, and two (the second where the first one's
        // rejection may or may not have taken its word).
        for pos in 0..12 {
            for (n, &h) in out_halves.iter().enumerate() {
                for second in pos..12 {
                    let mut words: [u64; 8] = core::array::from_fn(|_| filler.next_u64());
                    put(&mut words, pos, h);
                    if second > pos {
                        put(&mut words, second, out_halves[(n + second) % 4]);
                    }
                    same_as_one_by_one::<6>(&words);
                    same_as_one_by_one::<3>(&words);
                }
            }
        }
    }

    #[test]
    fn blocks_from_a_generator_are_the_pairs_one_by_one() {
        let (mut a, mut b) = (seeded(11), seeded(11));
        for _ in 0..20_000 {
            let block: [(Real, Real); 6] = standard_normal_pairs(&mut a);
            for p in block {
                let q = standard_normal_pair(&mut b);
                assert_eq!(
                    (p.0.to_bits(), p.1.to_bits()),
                    (q.0.to_bits(), q.1.to_bits())
                );
            }
        }
        assert_eq!(a, b);
    }
}
