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

use super::normal::{half_fast, normal_from_half};
use crate::math::Real;
use crate::rng::{Rng, halves};
use core::convert::Infallible;

/// `W` pairs of independent standard normal variates, the same values and the same words as
/// `W` calls of [`super::standard_normal_pair`] in a row (module docs).
#[inline(always)]
pub fn standard_normal_pairs<R: Rng + ?Sized, const W: usize>(rng: &mut R) -> [(Real, Real); W] {
    let words: [u64; W] = core::array::from_fn(|_| rng.next_u64());
    let mut out = [(0.0, 0.0); W];
    let mut inside = true;
    for (o, &w) in out.iter_mut().zip(&words) {
        let (hi, lo) = halves(w);
        let (a, a_in, ..) = half_fast(lo);
        let (b, b_in, ..) = half_fast(hi);
        *o = (a, b);
        inside &= a_in & b_in;
    }
    if !inside {
        resume(rng, words, &mut out);
    }
    out
}

/// The block from its first half outside its rectangle on, as the pairs drawn one by one
/// would make it: that half's rejection path reads the words after its own from [`Replay`];
/// the words it took are gone, so the later pairs take the words after them (and fresh ones
/// at the end) and their fast paths are evaluated again, until no half is outside.
#[cold]
#[inline(never)]
fn resume<R: Rng + ?Sized, const W: usize>(
    rng: &mut R,
    mut words: [u64; W],
    out: &mut [(Real, Real); W],
) {
    let outside = |w: u64| {
        let (hi, lo) = halves(w);
        (!half_fast(lo).1, !half_fast(hi).1)
    };
    let Some(mut first) = (0..W).find_map(|k| match outside(words[k]) {
        (true, _) => Some(2 * k),
        (false, true) => Some(2 * k + 1),
        _ => None,
    }) else {
        return;
    };
    loop {
        let k = first / 2;
        let mut replay = Replay {
            ahead: &words[k + 1..],
            rng,
        };
        // The pair of `words[k]`: its low half kept if it was inside (`first` is the high one).
        let (hi, lo) = halves(words[k]);
        let a = if first % 2 == 0 {
            normal_from_half(&mut replay, lo)
        } else {
            out[k].0
        };
        out[k] = (a, normal_from_half(&mut replay, hi));
        let taken = (W - k - 1) - replay.ahead.len();
        let mut next = None;
        for j in k + 1..W {
            words[j] = if j + taken < W {
                words[j + taken]
            } else {
                rng.next_u64()
            };
            let (hi, lo) = halves(words[j]);
            let (a, a_in, ..) = half_fast(lo);
            let (b, b_in, ..) = half_fast(hi);
            out[j] = (a, b);
            if next.is_none() && !(a_in && b_in) {
                next = Some(2 * j + usize::from(a_in));
            }
        }
        match next {
            Some(f) => first = f,
            None => return,
        }
    }
}

/// A generator that hands out the words a block drew ahead, in order, then draws from `rng`.
/// Only 64-bit words are asked of it: the normal sampler draws nothing else.
struct Replay<'a, R: ?Sized> {
    ahead: &'a [u64],
    rng: &'a mut R,
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
            None => self.rng.next_u64(),
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
