//! The exact no-splitting loop of hard spheres with no drive on the sum-form majorant
//! `|v_i - v_j| <= |c_i| + |c_j|` (`c = v - V` about a fixed reference velocity `V`): GRW
//! Section 3's scheme with the per-pair majorant `|c_i| + |c_j|` in place of `Umax`.
//!
//! The pair `{i, j}` is drawn with probability `(|c_i| + |c_j|) / ((n - 1) sum_k |c_k|)`:
//! `i` uniform and kept with probability `|c_i| / c_max` (else drawn again: these draws are
//! the weighted choice, not events), then `j` uniform among the others. The waiting times are
//! exponential with the total majorant rate `4 pi gamma C_1 (n - 1)/n sum_k |c_k|` (the sum
//! over pairs of `4 pi gamma C_1 (|c_i| + |c_j|)/n`, the pair rate of [`super::NoSplitting`]
//! with `Umax` replaced), and the candidate collides with probability
//! `|u| / (|c_i| + |c_j|)` (GRW (20) with this majorant), so every pair collides at its
//! hard-sphere rate `4 pi gamma C_1 |u| / n`: the same process as [`super::NoSplitting`]'s,
//! with no truncation (with no drive nothing moves between events, so the bound holds at every
//! event). For a Maxwellian `E|u| / E(|c_i| + |c_j|) = 1/sqrt(2)`: about 0.7 of the candidates
//! collide, against about 0.21 with `Umax = 2 max |c|` at n = 1e5.
//!
//! A gas with no drive does not use its particles' `t_kick` slots (every particle is always
//! current), so they hold `|c_i|` during a run (no memory beyond the particles); `sum |c|` is
//! kept by the collisions and summed anew at every synchronization (every `2n` candidates, in
//! one pass about the kept `V`, which also gives the temperature for the rescale test),
//! `c_max` only grows between synchronizations and is made exact at them. The uniform indices
//! are drawn [`AHEAD`] uses early and prefetched at large `n` (they do not depend on the
//! state, so drawing them early changes nothing). Everything else is [`super::NoSplitting`]'s
//! with no drive: the synchronization, the rescaled storage of a cooling gas
//! ([`super::nosplit::RESCALE_BELOW`]), the observables.

use super::collision_map::clamped_coefficient;
use super::event::{RefreshWindow, observables};
use super::frame::{Frame, RESCALE_BELOW, rescale_due};
use super::jumps::{Jumps, jumps_state, run_events};
use super::nosplit::checked_sync;
use super::pairs::PREFETCH_FROM;
use super::{Counts, EngineError};
use crate::batch::sync::SyncSums;
use crate::collision::inelastic;
use crate::kernel::{HardSpheres, Kernel};
use crate::math::{Real, max, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::{Rng, uniform_index, uniform01};
use crate::sample::unit_sphere;
use crate::vec3::Vec3;

/// Uniform indices drawn this many uses ahead at large `n` (their particles prefetched).
pub const AHEAD: usize = 16;

/// The exact loop of hard spheres with no drive and restitution law `A` on the sum-form
/// majorant (module docs).
#[derive(Clone, Debug)]
pub struct SumNoSplitting<A> {
    kernel: HardSpheres,
    restitution: A,
    /// Uniform indices in `0..n`, drawn ahead (a ring; `head == AHEAD`: empty).
    ahead: [usize; AHEAD],
    head: usize,
    /// The reference velocity `V` (stored units).
    vref: Vec3,
    /// `sum_k |c_k|` and an upper bound of every `|c_k|` (stored units).
    sum: Real,
    cmax: Real,
    /// Whether the `t_kick` slots hold `|c|`.
    ready: bool,
    /// `<|c|>` about the bulk velocity at the last synchronization (stored units; the
    /// `t_kick` slots are the caller's between calls, so [`Self::work_rate`] reads this).
    mean_c: Real,
    /// Uniform draws of the weighted choice of `i` so far (each a random particle read; the
    /// bench's reads per candidate). Kept here, not in [`Counts`], which journals carry.
    choice_draws: u64,
    counts: Counts,
    t: Real,
    refresh: RefreshWindow,
    frame: Frame,
}

impl<A: Restitution> SumNoSplitting<A> {
    /// Starts at `t0` on the particles `p` (holding the initial velocities); returns the
    /// observables at `t0`.
    // Out of line: called once per run, and the dispatch above it stays small.
    #[inline(never)]
    pub fn start(
        kernel: HardSpheres,
        restitution: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        super::open(p, t0, false)?;
        let mut s = SumNoSplitting {
            kernel,
            restitution,
            ahead: [0; AHEAD],
            head: AHEAD,
            vref: Vec3::ZERO,
            sum: 0.0,
            cmax: 0.0,
            ready: false,
            mean_c: 0.0,
            choice_draws: 0,
            counts: Counts::default(),
            t: t0,
            refresh: RefreshWindow::new(p.len()),
            frame: Frame::IDENTITY,
        };
        let obs = s.synchronized(p, false)?;
        Ok((s, obs))
    }

    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Uniform draws (random particle reads) the weighted choice of the candidates' first
    /// particle has made so far: `c_max / <|c|>` per candidate on average (module docs).
    pub fn choice_draws(&self) -> u64 {
        self.choice_draws
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]): the
    /// sum-form majorant's candidates (there is no drive) with `sum |c| = n <|c|>` as at the
    /// last synchronization (start, advance, resync).
    pub fn work_rate(&self, n: usize) -> Real {
        self.rate_of(n, n as Real * self.mean_c)
    }

    /// The total majorant rate of `n >= 1` particles whose `sum |c|` is `sum` (stored units):
    /// `4 pi gamma C_1 (n - 1)/n sum |c|` (module docs).
    #[inline(always)]
    fn rate_of(&self, n: usize, sum: Real) -> Real {
        let n = n.max(1);
        self.kernel.pair_rate(self.frame.scale * sum) * ((n - 1) as Real / n as Real)
    }

    /// The map from stored to physical velocities.
    pub fn velocity_map(&self) -> Frame {
        self.frame
    }

    /// Stores `|c_k|` about `vref` in every `t_kick` slot and sums them; `c_max` exact. One
    /// pass, which also returns a synchronization's sums about `vref` ([`SyncSums`]).
    fn prepare(&mut self, p: &mut Particles<'_>, vref: Vec3) -> SyncSums {
        self.vref = vref;
        let (mut sum, mut cmax) = (0.0, 0.0);
        let mut sums = SyncSums {
            n: p.len(),
            ..SyncSums::default()
        };
        for q in p.as_mut_slice() {
            let c = q.velocity() - vref;
            let c2 = c.norm2();
            let cn = sqrt(c2);
            q.t_kick = cn;
            sum += cn;
            cmax = max(cmax, cn);
            sums.s1[0] += c.x;
            sums.s1[1] += c.y;
            sums.s1[2] += c.z;
            sums.s2 += c2;
        }
        sums.max2 = cmax * cmax;
        (self.sum, self.cmax, self.ready) = (sum, cmax, true);
        sums
    }

    /// Runs to `t_end >= time()` and returns the observables there (every particle is always
    /// current: there is no drive).
    #[inline(never)]
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError> {
        if !t_end.is_finite() || t_end < self.t {
            return Err(EngineError::TimeBackwards);
        }
        if !self.ready {
            let vref = Observables::of(p).bulk;
            self.prepare(p, vref);
        }
        run_events(self, p, t_end, rng)?;
        self.t = t_end;
        // The t_kick slots are the caller's again.
        p.reset_kick_times(t_end);
        self.ready = false;
        self.synchronized(p, false)
    }

    /// Re-synchronizes after the caller changed the velocities (physical ones).
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        self.restitution = self.restitution.in_stored_units(1.0 / self.frame.scale);
        self.frame = Frame::IDENTITY;
        p.reset_kick_times(self.t);
        self.ready = false;
        self.synchronized(p, false)
    }

    /// Observables of the system (physical units); rescales a cooling gas below the threshold
    /// and, within a run (`in_run`), stores and sums `|c|` anew about the bulk velocity.
    fn synchronized(
        &mut self,
        p: &mut Particles<'_>,
        in_run: bool,
    ) -> Result<Observables, EngineError> {
        let mut obs = observables(p)?;
        if let Some(f) = self.frame.rescale(p, &mut obs, RESCALE_BELOW, 3, false) {
            self.counts.rescales += 1;
            self.restitution = self.restitution.in_stored_units(f);
        }
        self.counts.observations += 1;
        self.mean_c = obs.c1;
        if in_run {
            self.prepare(p, obs.bulk);
        }
        // `v6` of a gas stored rescaled, at every synchronization (the start included).
        Ok(self
            .frame
            .with_raw_v6(p.as_slice(), self.frame.observables(&obs, 3)))
    }

    /// The next uniform index in `0..n`: drawn [`AHEAD`] uses ago and prefetched at large `n`.
    #[inline(always)]
    fn uniform<R: Rng + ?Sized>(&mut self, p: &Particles<'_>, rng: &mut R) -> usize {
        let n = p.len();
        if n < PREFETCH_FROM {
            return uniform_index(rng, n);
        }
        if self.head == AHEAD {
            for k in 0..AHEAD {
                self.ahead[k] = uniform_index(rng, n);
                p.prefetch(self.ahead[k]);
            }
            self.head = 0;
        }
        let i = self.ahead[self.head];
        let next = uniform_index(rng, n);
        p.prefetch(next);
        self.ahead[self.head] = next;
        self.head = (self.head + 1) % AHEAD;
        i
    }
}

impl<A: Restitution> Jumps for SumNoSplitting<A> {
    const ACTS: bool = false;
    const USES_UMAX: bool = true;

    #[inline(always)]
    fn rate(&mut self, n: usize) -> Real {
        self.rate_of(n, self.sum)
    }
    #[inline(always)]
    fn bound(&self) -> Real {
        self.frame.scale * self.sum
    }
    jumps_state!(t, refresh, counts);
    fn kick_all<R: Rng + ?Sized>(&mut self, _p: &mut Particles<'_>, _t: Real, _rng: &mut R) {}
    /// One pass about the kept reference (the bulk velocity does not move: collisions conserve
    /// the momentum): the bounds and their sum anew, the finiteness and the cooling gas's
    /// rescale test from the same pass; the full synchronization only when it rescales.
    fn resynchronize(&mut self, p: &mut Particles<'_>) -> Result<(), EngineError> {
        let vref = self.vref;
        let sums = self.prepare(p, vref);
        let (bulk, t_bulk) = checked_sync(&sums, vref, 3)?;
        if rescale_due(t_bulk, bulk, RESCALE_BELOW) {
            self.synchronized(p, true)?;
            self.counts.observations -= 1;
        }
        Ok(())
    }
    /// One candidate (module docs): `i` in proportion to `|c_i|`, `j` uniform among the
    /// others, accepted with probability `|u| / (|c_i| + |c_j|)` (tested without a square
    /// root); then a uniform direction, GRW (3), and the two `|c|` and their sum updated.
    #[inline(always)]
    fn step<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        _t: Real,
        accept: Real,
        rng: &mut R,
    ) -> bool {
        let mut trials = 0u32;
        let i = loop {
            let i = self.uniform(p, rng);
            if uniform01(rng) * self.cmax < p.kick_time(i) {
                self.choice_draws += u64::from(trials) + 1;
                break i;
            }
            trials += 1;
            if trials == 1 << 24 {
                // Every |c| is (nearly) 0 while the kept sum is not, by rounding: sum them
                // anew (the rate then follows) and draw the next waiting time.
                let vref = self.vref;
                self.prepare(p, vref);
                return true;
            }
        };
        let j = loop {
            let j = self.uniform(p, rng);
            if j != i {
                break j;
            }
        };
        let (vi, vj) = (p.velocity(i), p.velocity(j));
        let (ci, cj) = (p.kick_time(i), p.kick_time(j));
        self.counts.candidates += 1;
        let u = vi - vj;
        let r = accept * (ci + cj);
        if r * r >= u.norm2() {
            self.counts.fictitious += 1;
            return false;
        }
        let e = unit_sphere(rng);
        let alpha = clamped_coefficient(&self.restitution, u, e, &mut self.counts);
        let (a, b) = inelastic(vi, vj, e, alpha);
        let (ca, cb) = (sqrt((a - self.vref).norm2()), sqrt((b - self.vref).norm2()));
        p.set_velocity(i, a);
        p.set_velocity(j, b);
        p.get_mut(i).t_kick = ca;
        p.get_mut(j).t_kick = cb;
        self.sum += (ca + cb) - (ci + cj);
        self.cmax = max(self.cmax, max(ca, cb));
        self.counts.collisions += 1;
        true
    }
    /// Never reached (the sum form has a bound that goes loose): one step.
    fn collide<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        let accept = uniform01(rng);
        self.step(p, t, accept, rng);
    }
}

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<A: Restitution> SumNoSplitting<A> {
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs
    /// ([`crate::engine::EventLoop::cooling`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        // Hard spheres in d = 3: the smooth map with `e` uniform.
        crate::engine::collision_map::one_species_cooling::<
            HardSpheres,
            crate::geometry::Spheres,
            A,
            R,
        >(
            (&self.kernel, &self.restitution, self.frame.scale),
            p,
            pairs,
            rng,
        )
    }
}
