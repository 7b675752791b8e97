//! One event of the mixture's exact loop (a pair type by its share of the rate, a pair of it,
//! both partners kicked, the fictitious test and the collision), and the undriven Maxwell
//! mixture's events counted per interval by a Poisson draw (stream version 2).

use super::MixtureNoSplitting;
use crate::drive::Drive;
use crate::engine::EngineError;
use crate::engine::collision_map::CollisionMap;
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::Real;
use crate::mixture::map::PairLaw;
use crate::particles::Particles;
use crate::rng::{Rng, uniform_index2, uniform_pair, uniform01};
use crate::sample::poisson;

impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureNoSplitting<K, D, L, G> {
    /// The events up to `t_end` with no drive and no `Umax` (the Maxwell kernel): their number
    /// drawn at once, Poisson with mean `rate (t_end - t)`, a synchronization every `2n`, as the
    /// one-species loop's `counted` (stream version 2: nothing here depends on an event's time,
    /// and the rates do not move).
    pub(super) fn counted<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rate: Real,
        rng: &mut R,
    ) -> Result<(), EngineError> {
        let n = p.len();
        let mut left = poisson(rng, rate * (t_end - self.t));
        while left > 0 {
            if self.refresh.synchronization_due(n) {
                self.synchronized(p)?;
                self.counts.observations -= 1;
                debug_assert_eq!(self.rates(), rate, "Maxwell rates do not move");
                self.refresh.restart();
            }
            let k = left.min(self.refresh.until_synchronization(n));
            for _ in 0..k {
                self.event(p, self.t, rate, 0.0, rng);
            }
            self.refresh.record_collisions(k);
            left -= k;
        }
        Ok(())
    }

    /// One event at `t`: a pair type by its share of `rate`, a pair of it, both kicked, the
    /// candidate (against the acceptance uniform `accept`, unread with no `Umax`). True when a
    /// majorant changed.
    #[inline(always)]
    pub(super) fn event<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t: Real,
        rate: Real,
        accept: Real,
        rng: &mut R,
    ) -> bool {
        let k = if self.sp.pair_types() == 1 {
            0
        } else {
            let x = uniform01(rng) * rate;
            let mut k = 0;
            while k < self.last && x >= self.cumulative[k] {
                k += 1;
            }
            k
        };
        let (s, u) = self.pair_of[k];
        let (i, j) = if s == u {
            let (a, b) = uniform_pair(rng, self.sp.count(s));
            (self.sp.offset(s) + a, self.sp.offset(s) + b)
        } else {
            let (a, b) = uniform_index2(rng, self.sp.count(s), self.sp.count(u));
            (self.sp.offset(s) + a, self.sp.offset(u) + b)
        };
        let background = &mut self.counts.background;
        if s == u {
            // One species' drive: its pair kick, as the one-species loop's.
            self.drives[s].kick_pair_counting(p, (i, j), t, rng, background);
        } else {
            self.drives[s].kick_counting(p, i, t, rng, background);
            self.drives[u].kick_counting(p, j, t, rng, background);
        }
        self.candidate(p, k, (i, j), accept, rng)
    }

    /// The candidate `(i, j)` of pair type `k`, both at the event time: the fictitious test
    /// against `U_k` (GRW (20)) with the uniform `accept`, else the collision. True when a
    /// majorant changed.
    #[inline(always)]
    fn candidate<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        k: usize,
        (i, j): (usize, usize),
        accept: Real,
        rng: &mut R,
    ) -> bool {
        let (s, t) = self.pair_of[k];
        let (vi, vj) = (p.velocity(i), p.velocity(j));
        let u = vi - vj;
        self.counts.candidates += 1;
        let (before_s, before_t) = (self.maj[s].umax, self.maj[t].umax);
        if K::USES_UMAX {
            let umax_event = self.pair_umax(k);
            let u2 = u.norm2();
            if u2 > umax_event * umax_event {
                self.counts.overshoots += 1;
            }
            if D::ACTS {
                self.maj[s].cover(vi);
                self.maj[t].cover(vj);
            }
            if !self.kernels[k].accepts(u2, umax_event, accept) {
                self.counts.fictitious += 1;
                return self.maj[s].umax != before_s || self.maj[t].umax != before_t;
            }
        }
        let (a, b) =
            self.maps[k].collide_pair::<K, G, R>(p, (i, j), (vi, vj), rng, &mut self.counts);
        self.counts.collisions += 1;
        self.pair_collisions[k] += 1;
        if K::USES_UMAX {
            self.maj[s].cover(a);
            self.maj[t].cover(b);
        }
        self.maj[s].umax != before_s || self.maj[t].umax != before_t
    }
}
