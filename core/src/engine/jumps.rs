//! The skeleton every exact (no-splitting) loop shares: GRW Section 3's steps 2.1-2.2 and RW
//! Algorithm 3's waiting times, with the synchronizations and refreshes of the majorant
//! ([`RefreshWindow`]). The loops ([`super::NoSplitting`] and the rough gas's) differ only in
//! what one event does ([`Jumps::step`]: which pair, which kicks, which map) and in how they
//! synchronize; the schedule is here once. A loop with no `Umax` (the Maxwell kernel)
//! collides at every candidate at a fixed rate, so its events run as a burst
//! ([`Jumps::collide`]): the same draws in the same order, with none of the
//! fictitious-collision bookkeeping; with no drive either, only their number matters, drawn
//! at once per interval ([`counted`]). The mixture's loop keeps its own copy: on this skeleton
//! its `advance_to` took 3.5% more instructions (callgrind, the mixture cooling scene), the
//! one-species and rough loops within 0.5% either way.

use super::event::RefreshWindow;
use super::{Counts, EngineError};
use crate::math::Real;
use crate::particles::Particles;
use crate::rng::{Rng, halves, unit_open32};
use crate::sample::{exponential_from_half, poisson, standard_exponential};

/// An exact event loop as the skeleton sees it.
pub(crate) trait Jumps {
    /// Whether a drive acts between collisions (else every particle is always current).
    const ACTS: bool;
    /// Whether the majorant depends on a bound `Umax` that can go loose.
    const USES_UMAX: bool;
    /// The total majorant event rate of the `n` particles (physical units).
    fn rate(&mut self, n: usize) -> Real;
    /// The majorant's bound in physical units (the refresh rule's "did it gain" test).
    fn bound(&self) -> Real;
    /// Current time.
    fn now(&self) -> Real;
    /// Moves the current time to `t`.
    fn set_now(&mut self, t: Real);
    /// The refresh schedule.
    fn window(&mut self) -> &mut RefreshWindow;
    /// Event counts.
    fn tally(&mut self) -> &mut Counts;
    /// Kicks every particle to time `t` (with a drive).
    fn kick_all<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R);
    /// Makes the majorant exact with every particle at the current time (and rescales a
    /// cooling gas), without counting an observation.
    fn resynchronize(&mut self, p: &mut Particles<'_>) -> Result<(), EngineError>;
    /// One event at time `t`: a candidate pair, its kicks, the fictitious test (against the
    /// uniform `accept` in (0, 1), drawn with the event's waiting time) and the map. True when
    /// the majorant changed (the rate is then recomputed).
    fn step<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t: Real,
        accept: Real,
        rng: &mut R,
    ) -> bool;
    /// One event at time `t` of a loop with no `Umax`, which always collides: a pair, its
    /// kicks and the map, counted as a candidate and a collision. [`run_events`] calls it
    /// only when not `USES_UMAX`; a loop with a `Umax` may run [`Jumps::step`] here.
    fn collide<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R);
}

/// The four accessors of [`Jumps`] every loop writes the same way, from the loop's time field,
/// its [`RefreshWindow`] field and the place of its [`Counts`]:
/// `jumps_state!(t, refresh, counts)` or `jumps_state!(t, refresh, c.counts)`.
macro_rules! jumps_state {
    ($t:ident, $window:ident, $($counts:ident).+) => {
        #[inline(always)]
        fn now(&self) -> $crate::math::Real {
            self.$t
        }
        #[inline(always)]
        fn set_now(&mut self, t: $crate::math::Real) {
            self.$t = t;
        }
        #[inline(always)]
        fn window(&mut self) -> &mut $crate::engine::event::RefreshWindow {
            &mut self.$window
        }
        #[inline(always)]
        fn tally(&mut self) -> &mut $crate::engine::Counts {
            &mut self.$($counts).+
        }
    };
}
pub(crate) use jumps_state;

/// Runs the events of `j` up to (not including) `t_end`, leaving its time at the last event
/// (the caller then kicks every particle to `t_end` and observes). With no drive the majorant
/// is made exact every `2n` candidates (a cooling gas is rescaled then); with a drive whenever
/// the [`RefreshWindow`] says the bound went loose, after kicking every particle to the
/// current time as an observation does (the process stays exact).
#[inline(always)]
pub(crate) fn run_events<J: Jumps, R: Rng + ?Sized>(
    j: &mut J,
    p: &mut Particles<'_>,
    t_end: Real,
    rng: &mut R,
) -> Result<(), EngineError> {
    let n = p.len();
    let mut rate = j.rate(n);
    j.window().restart();
    loop {
        if !J::ACTS && j.window().synchronization_due(n) {
            j.resynchronize(p)?;
            rate = j.rate(n);
            j.window().restart();
        } else if J::ACTS && J::USES_UMAX && j.window().refresh_due() {
            let before = j.bound();
            let now = j.now();
            j.kick_all(p, now, rng);
            j.resynchronize(p)?;
            j.tally().refreshes += 1;
            rate = j.rate(n);
            let after = j.bound();
            j.window().refreshed(before, after, n);
        }
        if !J::USES_UMAX && !J::ACTS {
            counted(j, p, t_end, rate, rng)?;
            return Ok(());
        }
        if !J::USES_UMAX {
            // Every candidate collides and the rate holds until `t_end` (nothing refreshes a
            // majorant that cannot go loose): the events run as a burst, the same draws in the
            // same order as below, with none of the fictitious-collision bookkeeping.
            let done = burst(j, p, t_end, rate, rng);
            j.window().record_collisions(done);
            return Ok(());
        }
        // One word for the waiting time (its low half) and the candidate's acceptance uniform
        // (its high half; stream version 2).
        let (hi, lo) = halves(rng.next_u64());
        let t_next = j.now() + exponential_from_half(rng, lo) / rate;
        // Not `t_next >= t_end` alone: a zero rate with a zero draw gives NaN, which stops too.
        if t_next.partial_cmp(&t_end) != Some(core::cmp::Ordering::Less) {
            return Ok(());
        }
        j.set_now(t_next);
        let before = j.tally().fictitious;
        if j.step(p, t_next, unit_open32(hi), rng) {
            rate = j.rate(n);
        }
        let wasted = j.tally().fictitious - before;
        j.window().record(wasted);
    }
}

/// The events up to `t_end` of a loop with no `Umax` and no drive: their number drawn at once,
/// Poisson with mean `rate (t_end - now)` (stream version 2), then that many collisions with a
/// synchronization every `2n`. Nothing such a loop does depends on when an event happens (no
/// kick, a rate the synchronizations do not change: the Maxwell kernel's is fixed in physical
/// time), so this is the process [`burst`] runs, without a waiting time per event. The loop's
/// time is left where it was (the caller moves it to `t_end`).
#[inline(always)]
fn counted<J: Jumps, R: Rng + ?Sized>(
    j: &mut J,
    p: &mut Particles<'_>,
    t_end: Real,
    rate: Real,
    rng: &mut R,
) -> Result<(), EngineError> {
    let n = p.len();
    let now = j.now();
    let mut left = poisson(rng, rate * (t_end - now));
    while left > 0 {
        if j.window().synchronization_due(n) {
            j.resynchronize(p)?;
            debug_assert_eq!(j.rate(n), rate, "a rate with no Umax does not move");
            j.window().restart();
        }
        let k = left.min(j.window().until_synchronization(n));
        for _ in 0..k {
            j.collide(p, now, rng);
        }
        j.window().record_collisions(k);
        left -= k;
    }
    Ok(())
}

/// The events of a driven loop with no `Umax` (every candidate collides, the rate is fixed),
/// stopping before the first event at or after `t_end`: the events done. The loop's time is left at the last event. The waiting times are the
/// ones [`run_events`] draws, to the bit (`tau / rate` added to the time of the last event).
#[inline(always)]
fn burst<J: Jumps, R: Rng + ?Sized>(
    j: &mut J,
    p: &mut Particles<'_>,
    t_end: Real,
    rate: Real,
    rng: &mut R,
) -> u64 {
    let mut now = j.now();
    let mut done = 0;
    loop {
        let t_next = now + standard_exponential(rng) / rate;
        if t_next.partial_cmp(&t_end) != Some(core::cmp::Ordering::Less) {
            break;
        }
        now = t_next;
        j.collide(p, now, rng);
        done += 1;
    }
    j.set_now(now);
    done
}
