//! The no-splitting scheme: GRW Section 3 ("Algorithm"), RW Algorithm 3.
//!
//! A Markov jump process with no time step: waiting times `tau ~ Exp(rate)` with the majorant
//! rate `2 pi gamma C_lambda (n - 1) Umax^lambda` (GRW step 2.1, RW (20)); a uniform ordered
//! pair `i != j`; both partners kicked lazily from their last-kick times (GRW (18), steps
//! 2.5-2.6); the pair is fictitious with probability `1 - (|v_i - v_j| / Umax)^lambda` (GRW (20));
//! otherwise `e` uniform on the sphere and the inelastic map GRW (3). Before each observation
//! every particle is kicked to the observation time (step 3.1) and a fresh waiting time is drawn
//! afterwards (RW step 3.3; exact by memorylessness).
//!
//! The adaptive majorant: `Umax = 2 max_i |v_i - V|` at the start (step 1.4). After every kick
//! and every collision it becomes `max(Umax, 2|v_i - V|, 2|v_j - V|)`: the bound that really
//! holds (RW (21) and the text around it; GRW's step 2.7 omits the factor 2). Because the
//! untouched particles keep diffusing between their kicks, a candidate's relative speed can still
//! exceed the `Umax` that generated its waiting time; then the kernel is truncated there
//! (RW (19)), the pair is accepted, and [`Counts::overshoots`] counts it. At each observation,
//! with every particle synchronized, `V` and `Umax` are recomputed exactly; and so they are
//! between observations whenever, over the last `2n` candidates, more than half were fictitious
//! (a cooling gas leaves the bound loose): every particle is kicked to the current time first,
//! as at an observation, so the process stays the same ([`Counts::refreshes`]).
//!
//! For Maxwell pseudo-molecules the majorant is the kernel itself: no `Umax`, no fictitious
//! collisions, and none of that bookkeeping is compiled in.

use super::event::{Majorant, candidate};
use super::{Counts, EngineError};
use crate::drive::Drive;
use crate::kernel::Kernel;
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::{Rng, uniform_pair};
use crate::sample::standard_exponential;

/// The exact (no-splitting) event loop for kernel `K`, drive `D` and restitution law `A`.
#[derive(Clone, Debug)]
pub struct NoSplitting<K, D, A> {
    kernel: K,
    drive: D,
    restitution: A,
    t: Real,
    maj: Majorant,
    counts: Counts,
    refresh_after: u64,
}

impl<K: Kernel, D: Drive, A: Restitution> NoSplitting<K, D, A> {
    /// Starts the scheme at time `t0` on the particles `p` (already holding the initial
    /// velocities): sets every last-kick time to `t0` and `Umax = 2 max |v_i - V|`
    /// (GRW steps 1.1-1.4). Returns the observables at `t0`.
    pub fn start(
        kernel: K,
        drive: D,
        restitution: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        if !t0.is_finite() {
            return Err(EngineError::TimeBackwards);
        }
        p.reset_kick_times(t0);
        let mut s = NoSplitting {
            kernel,
            drive,
            restitution,
            t: t0,
            maj: Majorant::default(),
            counts: Counts::default(),
            refresh_after: 2 * p.len() as u64,
        };
        let obs = s.synchronized(p)?;
        Ok((s, obs))
    }

    /// Current time of the system.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Current majorant of the relative speed (0 for kernels that need none).
    pub fn umax(&self) -> Real {
        self.maj.umax
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// The kernel.
    pub fn kernel(&self) -> &K {
        &self.kernel
    }

    /// Runs the process to time `t_end >= time()`, kicks every particle to `t_end` and returns
    /// the observables there (GRW steps 2-3, RW Algorithm 3).
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError> {
        if !t_end.is_finite() || t_end < self.t {
            return Err(EngineError::TimeBackwards);
        }
        let n = p.len();
        let mut rate = self.kernel.majorant_rate(n, self.maj.umax);
        // Candidates and fictitious ones since the majorant was last made exact.
        let (mut window, mut wasted) = (0u64, 0u64);
        loop {
            if K::USES_UMAX && window >= self.refresh_after && 2 * wasted > window {
                // The bound may have gone loose (a cooling gas): make it exact again. Kicking
                // every particle to the current time is what an observation does; the process
                // stays exact, and the O(n) cost is amortized over the window. A refresh that
                // gains little doubles the window, so a steady gas soon stops paying for it.
                let before = self.maj.umax;
                self.drive.kick_all(p, self.t, rng);
                self.synchronized(p)?;
                self.counts.observations -= 1;
                self.counts.refreshes += 1;
                rate = self.kernel.majorant_rate(n, self.maj.umax);
                (window, wasted) = (0, 0);
                self.refresh_after = if self.maj.umax > 0.8 * before {
                    self.refresh_after.saturating_mul(2)
                } else {
                    2 * n as u64
                };
            }
            let t_next = self.t + standard_exponential(rng) / rate;
            // Not `t_next >= t_end` alone: a zero rate with a zero draw gives NaN, which stops too.
            if t_next.partial_cmp(&t_end) != Some(core::cmp::Ordering::Less) {
                break;
            }
            self.t = t_next;
            let (i, j) = uniform_pair(rng, n);
            self.drive.kick(p, i, t_next, rng);
            self.drive.kick(p, j, t_next, rng);
            let (k, a) = (&self.kernel, &self.restitution);
            let before = self.counts.fictitious;
            if candidate(k, a, p, i, j, &mut self.maj, D::ACTS, &mut self.counts, rng) {
                rate = self.kernel.majorant_rate(n, self.maj.umax);
            }
            window += 1;
            wasted += self.counts.fictitious - before;
        }
        self.t = t_end;
        self.drive.kick_all(p, t_end, rng);
        self.synchronized(p)
    }

    /// Re-synchronizes after the caller changed velocities between calls: every last-kick time
    /// becomes the current time and `V`, `Umax` are recomputed. Returns the observables.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        p.reset_kick_times(self.t);
        self.synchronized(p)
    }

    /// Observables of the synchronized system; refreshes `V` and `Umax` from them.
    fn synchronized(&mut self, p: &Particles<'_>) -> Result<Observables, EngineError> {
        let obs = Observables::of(p);
        if !obs.is_finite() {
            return Err(EngineError::NonFinite);
        }
        self.counts.observations += 1;
        self.drive.observe(&obs);
        if K::USES_UMAX {
            self.maj = Majorant {
                umax: 2.0 * obs.max_peculiar_speed,
                vref: obs.bulk,
            };
        }
        Ok(obs)
    }
}
