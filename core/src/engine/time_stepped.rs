//! The time-stepped DSMC scheme of MS Section 3 for inelastic hard spheres (Bird's scheme with
//! the Enskog factor folded into the kernel's rate constant), in dimension `G`, and Bird's
//! no-time-counter form of it for the Maxwell and VHS kernels (GRW (5)).
//!
//! Each step of length `h`: a collision stage, then a free-streaming stage that kicks every
//! particle for `h` (MS (57)-(62), the drive's batch kick). MS take `N` where this takes `n - 1`
//! candidates per unit, the no-splitting scheme's pair rate. The candidates come in whole
//! numbers per step (the fraction carried), as in Bird's scheme, so every ensemble draws the
//! same number of candidates by time `t` where the jump process draws a Poisson number: beside
//! its `O(h)` step error the scheme differs from the no-splitting one by `O(1/n)`, which at
//! n = 8 Maxwell molecules is 5% of `T` and at n = 256 is below the statistics
//! (tests/tests/time_stepped.rs). For hard spheres most candidates are rejected, which makes
//! the accepted ones nearly Poisson.
//!
//! Hard spheres (MS Section 3 as written): `(1/2) (n - 1) omega_max h` candidate pairs (the
//! fractional part carried to the next step), each with a direction `s` uniform on the sphere
//! and accepted with probability `Theta(u . s) omega_ij / omega_max`,
//! `omega_ij = 16 pi gamma C |u . s|` (so that averaged over `s` a pair collides at the rate
//! `4 pi gamma C |u|` of the no-splitting scheme), then the impact map
//! `v_{1,2} -/+ (1 + alpha)/2 (u . s) s` (GRW (3) through
//! [`crate::collision::scattering_direction_from_impact`]; rough particles: the map of
//! Huthmann and Zippelius at the impact `s`, [`crate::engine::CollisionMap::collide_at_impact`]).
//! Hard disks draw `s` on the circle and accept with `omega_ij = 4 pi^2 gamma C (u . s)`
//! ([`Geometry::OMEGA_FACTOR`]), which keeps the pair rate `4 pi gamma C |u|` and gives the
//! impact direction its hard-disk law (density `u_hat . s`).
//!
//! Maxwell and VHS kernels (`B = gamma C |u|^lambda`): the same stage with the kernel's own
//! majorant, `(1/2) (n - 1) B_max h` candidates, `B_max = 4 pi gamma C Umax^lambda` (GRW (19)),
//! each accepted with probability `(|u| / Umax)^lambda` (GRW (20); Maxwell: always, and no
//! `Umax` is kept) and collided by the map the no-splitting scheme uses
//! ([`crate::engine::CollisionMap::collide_pair`]: `e` uniform, GRW (3)).
//!
//! For every kernel a candidate above the bound (`omega_ij > omega_max`, `|u| > Umax`) raises
//! it and is counted ([`Counts::overshoots`]); the bound starts from `Umax = 2 max |v - V|`.
//!
//! The step adapts to the gas: `h = f / (sqrt(2) B(v_0))` with `v_0 = (2 T)^{1/2}` and the pair
//! rate `B(u) = 4 pi gamma C u^lambda`, `f = 0.01` in MS. For hard spheres this is MS's
//! `h = f lambda / v_0` with the mean free path `lambda = 1 / (sqrt(2) 4 pi gamma C)` (MS:
//! `(sqrt(2) pi chi n sigma^2)^{-1}`, `pi chi n sigma^2 = 4 pi gamma C`); for Maxwell
//! molecules it is the constant `f / (sqrt(2) 4 pi gamma C)`. The last step before an
//! observation is shortened to land on it.

use super::{Counts, EngineError};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{PI, Real, floor, max, min, powf, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::{Rng, uniform_pair, uniform01};
use crate::rough::RoughObservables;

/// MS's time-stepped scheme (Bird's no-time-counter form for kernels other than hard spheres)
/// with kernel `K`, drive `D` and collision map `A` (a restitution law: smooth particles;
/// [`crate::rough::RoughMap`]: rough ones, whose impact direction is hard spheres' candidate
/// `s`) in dimension `G` (module docs).
#[derive(Clone, Debug)]
pub struct TimeStepped<K, D, A, G = Spheres> {
    dim: core::marker::PhantomData<G>,
    kernel: K,
    drive: D,
    restitution: A,
    step_factor: Real,
    t: Real,
    temperature: Real,
    /// The candidates' bound: MS's `omega_max` for hard spheres, `Umax` for the VHS kernel
    /// (unused for Maxwell molecules).
    bound: Real,
    carry: Real,
    steps: u64,
    counts: Counts,
}

impl<K: Kernel, D: Drive, A: crate::engine::CollisionMap, G: Geometry> TimeStepped<K, D, A, G> {
    /// Starts at `t0` with step factor `f > 0` (`h = f lambda / v_0`; MS: 0.01) on particles
    /// holding the initial velocities (and, for a rough map, one spin each:
    /// [`EngineError::Spins`] otherwise). The bound starts from `Umax = 2 max |v - V|`.
    // Out of line: called once per run, and the dispatch above it stays small.
    #[inline(never)]
    pub fn start(
        kernel: K,
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
            bound: 0.0,
            carry: 0.0,
            steps: 0,
            counts: Counts::default(),
        };
        let obs = s.synchronized(p)?;
        s.bound = s.bound_for(2.0 * obs.max_peculiar_speed);
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
    /// candidates `(1/2) (n - 1) omega_max` (`B_max` for other kernels) and `n` kicks per step
    /// of [`Self::step_length`].
    pub fn work_rate(&self, n: usize) -> Real {
        let candidates = 0.5 * (n.max(1) - 1) as Real * self.candidate_rate();
        candidates + n as Real / self.step_length(self.temperature)
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The step length at temperature `t`: `f / (sqrt(2) B(v_0))`, for hard spheres MS's
    /// `f lambda / v_0` (module docs).
    pub fn step_length(&self, temperature: Real) -> Real {
        let lambda = 1.0 / (sqrt(2.0) * self.kernel.pair_rate(1.0));
        let v0 = sqrt(2.0 * temperature);
        let speed = if K::HARD {
            v0
        } else if K::USES_UMAX {
            powf(v0, self.kernel.lambda())
        } else {
            1.0
        };
        self.step_factor * lambda / speed
    }

    /// MS's `w pi gamma C` of `omega_ij = w pi gamma C (u . s)` (hard spheres and disks).
    fn omega_factor(&self) -> Real {
        let strength = self.kernel.as_hard_spheres().map_or(0.0, |h| h.strength());
        G::OMEGA_FACTOR * PI * strength
    }

    /// The bound for relative speeds up to `umax`: `omega_max = w pi gamma C Umax` for hard
    /// spheres, `Umax` itself for the other kernels.
    fn bound_for(&self, umax: Real) -> Real {
        if K::HARD {
            self.omega_factor() * umax
        } else {
            umax
        }
    }

    /// Candidates per pair and unit time: `omega_max` (hard spheres) or `B_max` (GRW (19)).
    fn candidate_rate(&self) -> Real {
        if K::HARD {
            self.bound
        } else {
            self.kernel.b_max(self.bound)
        }
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

    /// The collision stage of one step (MS Section 3; module docs).
    fn collide<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, h: Real, rng: &mut R) {
        let n = p.len();
        let expected = 0.5 * (n - 1) as Real * self.candidate_rate() * h + self.carry;
        let m = floor(expected);
        self.carry = expected - m;
        if K::HARD {
            self.collide_hard(p, m as u64, rng);
        } else {
            self.collide_kernel(p, m as u64, rng);
        }
    }

    /// `m` candidates of MS Section 3: a direction `s` each, accepted with
    /// `Theta(u . s) omega_ij / omega_max`, collided at the impact `s`.
    fn collide_hard<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, m: u64, rng: &mut R) {
        let n = p.len();
        let k16 = self.omega_factor();
        for _ in 0..m {
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
            let bound = self.bound;
            if omega > bound {
                self.counts.overshoots += 1;
                self.bound = omega;
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

    /// `m` candidates of Bird's scheme with the kernel's majorant: accepted with
    /// `(|u| / Umax)^lambda` (GRW (20); Maxwell: always), collided by the map as the
    /// no-splitting scheme does.
    fn collide_kernel<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, m: u64, rng: &mut R) {
        let n = p.len();
        for _ in 0..m {
            let (i, j) = uniform_pair(rng, n);
            let (vi, vj) = (p.velocity(i), p.velocity(j));
            self.counts.candidates += 1;
            if K::USES_UMAX {
                let u2 = (vi - vj).norm2();
                let umax = self.bound;
                if u2 > umax * umax {
                    self.counts.overshoots += 1;
                    self.bound = sqrt(u2);
                }
                if !self.kernel.accepts(u2, umax, uniform01(rng)) {
                    self.counts.fictitious += 1;
                    continue;
                }
            }
            self.restitution
                .collide_pair::<K, G, R>(p, (i, j), (vi, vj), rng, &mut self.counts);
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
        self.bound = max(self.bound, self.bound_for(2.0 * obs.max_peculiar_speed));
        Ok(obs)
    }
}
