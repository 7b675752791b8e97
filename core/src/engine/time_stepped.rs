//! The time-stepped DSMC scheme of MS Section 3 for inelastic hard spheres (Bird's scheme with
//! the Enskog factor folded into the kernel's rate constant), in dimension `G`: hard disks
//! draw `s` on the circle and accept with `omega_ij = 4 pi^2 gamma C (u . s)`
//! ([`Geometry::OMEGA_FACTOR`]), which keeps the pair rate `4 pi gamma C |u|` and gives the
//! impact direction its hard-disk law (density `u_hat . s`).
//!
//! Each step of length `h`: a collision stage with `(1/2) (n - 1) omega_max h` candidate pairs
//! (the fractional part carried to the next step), each with a direction `s` uniform on the
//! sphere and accepted with probability `Theta(u . s) omega_ij / omega_max`,
//! `omega_ij = 16 pi gamma C |u . s|` (so that averaged over `s` a pair collides at the rate
//! `4 pi gamma C |u|` of the no-splitting scheme), then the impact map
//! `v_{1,2} -/+ (1 + alpha)/2 (u . s) s` (GRW (3) through
//! [`crate::collision::scattering_direction_from_impact`]; rough particles: the map of
//! Huthmann and Zippelius at the impact `s`, [`crate::engine::CollisionMap::collide_at_impact`]);
//! a candidate with
//! `omega_ij > omega_max` raises `omega_max` and is counted. Then a free-streaming stage kicks
//! every particle for `h` (MS (57)-(62), the drive's batch kick). MS take `N` where this takes
//! `n - 1` candidates per unit: with `n - 1` the scheme converges, as `h -> 0`, to the same
//! `n`-particle process as the no-splitting scheme.
//!
//! The step adapts to the gas: `h = f lambda / v_0(t)` with the mean free path
//! `lambda = 1 / (sqrt(2) 4 pi gamma C)` (MS: `(sqrt(2) pi chi n sigma^2)^{-1}`,
//! `pi chi n sigma^2 = 4 pi gamma C`) and `v_0 = (2 T)^{1/2}`, `f = 0.01` in MS; the last step
//! before an observation is shortened to land on it.

use super::{Counts, EngineError};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::{HardSpheres, Kernel};
use crate::math::{PI, Real, floor, max, min, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::{Rng, uniform_pair, uniform01};
use crate::rough::RoughObservables;

/// MS's time-stepped scheme for hard spheres (hard disks for `G = Disks`) with drive `D` and
/// collision map `A` (a restitution law: smooth particles; [`crate::rough::RoughMap`]: rough
/// ones, whose impact direction is the candidate's `s`).
#[derive(Clone, Debug)]
pub struct TimeStepped<D, A, G = Spheres> {
    dim: core::marker::PhantomData<G>,
    kernel: HardSpheres,
    drive: D,
    restitution: A,
    step_factor: Real,
    t: Real,
    temperature: Real,
    omega_max: Real,
    carry: Real,
    steps: u64,
    counts: Counts,
}

impl<D: Drive, A: crate::engine::CollisionMap, G: Geometry> TimeStepped<D, A, G> {
    /// Starts at `t0` with step factor `f > 0` (`h = f lambda / v_0`; MS: 0.01) on particles
    /// holding the initial velocities (and, for a rough map, one spin each:
    /// [`EngineError::Spins`] otherwise). `omega_max` starts from `Umax = 2 max |v - V|`.
    // Out of line: called once per run, and the dispatch above it stays small.
    #[inline(never)]
    pub fn start(
        kernel: HardSpheres,
        drive: D,
        restitution: A,
        step_factor: Real,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        super::check_step(step_factor)?;
        if A::SPINS && !p.has_spins() {
            return Err(EngineError::Spins);
        }
        if !t0.is_finite() {
            return Err(EngineError::TimeBackwards);
        }
        p.reset_kick_times(t0);
        let mut s = TimeStepped {
            dim: core::marker::PhantomData,
            kernel,
            drive,
            restitution,
            step_factor,
            t: t0,
            temperature: 0.0,
            omega_max: 0.0,
            carry: 0.0,
            steps: 0,
            counts: Counts::default(),
        };
        let obs = s.synchronized(p)?;
        s.omega_max = G::OMEGA_FACTOR * PI * kernel.strength() * 2.0 * obs.max_peculiar_speed;
        Ok((s, obs))
    }

    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Event counts so far (`candidates`, `collisions`, `fictitious`, `overshoots`).
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]): the
    /// candidates `(1/2) (n - 1) omega_max` and `n` kicks per step of [`Self::step_length`].
    pub fn work_rate(&self, n: usize) -> Real {
        let candidates = 0.5 * (n.max(1) - 1) as Real * self.omega_max;
        candidates + n as Real / self.step_length(self.temperature)
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The step length at temperature `t`: `f lambda / v_0`.
    pub fn step_length(&self, temperature: Real) -> Real {
        let lambda = 1.0 / (sqrt(2.0) * self.kernel.pair_rate(1.0));
        self.step_factor * lambda / sqrt(2.0 * temperature)
    }

    /// Runs steps up to `t_end` (the last one shortened to land on it) and returns the
    /// observables there.
    // Its own function, called once per observation: the engine's dispatch above it stays
    // small and a profile names the loop.
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
        let mut obs = None;
        while self.t < t_end {
            let full = self.step_length(self.temperature);
            let h = if full.is_finite() && full > 0.0 {
                min(full, t_end - self.t)
            } else {
                t_end - self.t
            };
            self.collide(p, h, rng);
            self.t = if t_end - self.t <= h {
                t_end
            } else {
                self.t + h
            };
            self.drive
                .kick_all_counting(p, self.t, rng, &mut self.counts.background);
            self.steps += 1;
            let o = super::event::observables_dim(p, G::CHOICE.d())?;
            self.temperature = o.t_bulk;
            self.drive.observe(&o);
            obs = Some(o);
        }
        self.counts.observations += 1;
        match obs {
            Some(o) => Ok(o),
            None => self.synchronized(p),
        }
    }

    /// The collision stage of one step (MS Section 3).
    fn collide<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, h: Real, rng: &mut R) {
        let n = p.len();
        let expected = 0.5 * (n - 1) as Real * self.omega_max * h + self.carry;
        let m = floor(expected);
        self.carry = expected - m;
        let k16 = G::OMEGA_FACTOR * PI * self.kernel.strength();
        for _ in 0..m as u64 {
            let (i, j) = uniform_pair(rng, n);
            let s = G::direction(rng);
            let (vi, vj) = (p.velocity(i), p.velocity(j));
            let u = vi - vj;
            let un = u.dot(s);
            self.counts.candidates += 1;
            if un <= 0.0 {
                self.counts.fictitious += 1;
                continue;
            }
            let omega = k16 * un;
            let bound = self.omega_max;
            if omega > bound {
                self.counts.overshoots += 1;
                self.omega_max = omega;
            }
            if uniform01(rng) * bound >= omega {
                self.counts.fictitious += 1;
                continue;
            }
            self.restitution
                .collide_at_impact(p, (i, j), (vi, vj), s, &mut self.counts);
            self.counts.collisions += 1;
        }
    }

    fn synchronized(&mut self, p: &Particles<'_>) -> Result<Observables, EngineError> {
        let obs = super::event::observables_dim(p, G::CHOICE.d())?;
        self.temperature = obs.t_bulk;
        self.drive.observe(&obs);
        Ok(obs)
    }

    /// A rough gas's rotational observables now; `None` for smooth particles.
    pub fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
        self.restitution.rough(p, 1.0, G::CHOICE)
    }

    /// Re-synchronizes after the caller changed the velocities.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        p.reset_kick_times(self.t);
        let obs = self.synchronized(p)?;
        self.omega_max = max(
            self.omega_max,
            G::OMEGA_FACTOR * PI * self.kernel.strength() * 2.0 * obs.max_peculiar_speed,
        );
        Ok(obs)
    }
}
