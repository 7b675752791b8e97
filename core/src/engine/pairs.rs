//! Candidate pairs drawn a few events ahead of use, their particles prefetched.
//!
//! At large `n` every candidate pair costs two cache misses. Pairs are i.i.d. uniform
//! (GRW Section 3, RW Algorithms 1-3), so drawing them `LOOKAHEAD` events early changes
//! nothing in distribution, and asking for their cache lines then lets the misses of
//! independent pairs overlap. Measured with `gdsmc bench throughput` (no-splitting loop,
//! Maxwell kernel, n = 10^7): 2.9e6 -> 1.2e7 collisions/s heated, 6.1e6 -> 2.4e7 elastic, the
//! latter at the machine's rate of independent random reads (4.9e7/s, two per pair).

use crate::particles::Particles;
use crate::rng::{Rng, uniform_pair};

/// How many candidate pairs are drawn ahead of use: 16 (was 8) measured elastic Maxwell at
/// n = 1e7 2.23e7 -> 2.42e7 collisions/s (4 alternating runs each, huge pages), 1e6 +4-8%,
/// 1e5 unchanged (within 1%).
pub const LOOKAHEAD: usize = 16;

/// Below this many particles (1 MiB of particle records, within the L2 cache) pairs are drawn
/// when used: the ring's bookkeeping cost 8% at n = 1000 and prefetching gains nothing there.
pub const PREFETCH_FROM: usize = 1 << 15;

/// A ring of `LOOKAHEAD` pairs drawn ahead, filled on first use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PairsAhead {
    ahead: [(usize, usize); LOOKAHEAD],
    /// Next slot to use; `LOOKAHEAD` while the ring is empty.
    head: usize,
}

impl Default for PairsAhead {
    fn default() -> Self {
        PairsAhead {
            ahead: [(0, 1); LOOKAHEAD],
            head: LOOKAHEAD,
        }
    }
}

impl PairsAhead {
    /// The next uniform pair `i != j` of `p` (drawn `LOOKAHEAD` calls ago); draws its
    /// successor and prefetches that one's particles.
    ///
    /// Inlined into the loops on hosts (at n = 1e5, two sets of three interleaved CPU-timed
    /// bench runs: elastic Maxwell +6% and +9%, heated Maxwell +3% and +7%, heated VHS +11%
    /// and +13%; the same bits); left to the compiler on bare-metal targets,
    /// where forcing it grew the M4F firmware by 34 KiB and the Cortex-M0's GRW Example 3 by
    /// 3% in instructions per collision.
    #[cfg_attr(not(target_os = "none"), inline(always))]
    #[cfg_attr(target_os = "none", inline)]
    pub fn next<R: Rng + ?Sized>(&mut self, p: &Particles<'_>, rng: &mut R) -> (usize, usize) {
        let n = p.len();
        if n < PREFETCH_FROM {
            return uniform_pair(rng, n);
        }
        if self.head == LOOKAHEAD {
            for slot in &mut self.ahead {
                *slot = uniform_pair(rng, n);
            }
            self.head = 0;
        }
        let pair = self.ahead[self.head];
        let next = uniform_pair(rng, n);
        p.prefetch(next.0);
        p.prefetch(next.1);
        self.ahead[self.head] = next;
        self.head = (self.head + 1) % LOOKAHEAD;
        pair
    }
}
