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

use super::collision_map::CollisionMap;
use super::{Counts, EngineError};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{PI, Real, floor, max, min, powf, sqrt};
use crate::moments::Observables;
use crate::observe::RoughObservables;
use crate::particles::Particles;
use crate::rng::{Rng, uniform_pair, uniform01};

/// The collision stage of one pair type (module docs): its kernel, the candidates' bound (MS's
/// `omega_max` for hard spheres, `Umax` for the VHS kernel, unused for Maxwell molecules) and
/// the fraction of a candidate carried to the next step. One for a gas of one species
/// ([`TimeStepped`]), one per pair of species for a mixture
/// ([`crate::mixture::MixtureTimeStepped`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stage<K, G> {
    kernel: K,
    bound: Real,
    carry: Real,
    dim: core::marker::PhantomData<G>,
}

impl<K: Kernel, G: Geometry> Stage<K, G> {
    /// A stage of kernel `kernel` whose bound covers no relative speed yet.
    pub(crate) fn new(kernel: K) -> Self {
        Stage {
            kernel,
            bound: 0.0,
            carry: 0.0,
            dim: core::marker::PhantomData,
        }
    }

    /// Raises the bound to cover relative speeds up to `umax` (`Umax = 2 max |v - V|` for one
    /// species).
    pub(crate) fn cover(&mut self, umax: Real) {
        self.bound = max(self.bound, self.bound_for(umax));
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
    pub(crate) fn candidate_rate(&self) -> Real {
        if K::HARD {
            self.bound
        } else {
            self.kernel.b_max(self.bound)
        }
    }

    /// The step length `f / (sqrt(2) B(v_0))` for a relative thermal speed `v_0` (module docs;
    /// hard spheres: MS's `f lambda / v_0`).
    pub(crate) fn step_length(&self, f: Real, v0: Real) -> Real {
        let lambda = 1.0 / (sqrt(2.0) * self.kernel.pair_rate(1.0));
        let speed = if K::HARD {
            v0
        } else if K::USES_UMAX {
            powf(v0, self.kernel.lambda())
        } else {
            1.0
        };
        f * lambda / speed
    }

    /// The whole number of candidates of a step of length `h` at `rate` candidates per unit
    /// time, the fraction carried to the next step.
    pub(crate) fn count(&mut self, rate: Real, h: Real) -> u64 {
        let expected = rate * h + self.carry;
        let m = floor(expected);
        self.carry = expected - m;
        m as u64
    }

    /// One candidate pair `(i, j)` (module docs): hard spheres draw `s` and accept with
    /// `Theta(u . s) omega_ij / omega_max`, the other kernels accept with `(|u| / Umax)^lambda`;
    /// a candidate above the bound raises it and is counted. An accepted pair collides by
    /// `map`.
    #[inline(always)]
    pub(crate) fn candidate<A: CollisionMap, R: Rng + ?Sized>(
        &mut self,
        map: &A,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        rng: &mut R,
        counts: &mut Counts,
    ) {
        counts.candidates += 1;
        if K::HARD {
            let s = G::direction(rng);
            let (vi, vj) = (p.velocity(i), p.velocity(j));
            let un = (vi - vj).dot(s);
            if un <= 0.0 {
                counts.fictitious += 1;
                return;
            }
            let omega = self.omega_factor() * un;
            let bound = self.bound;
            if omega > bound {
                counts.overshoots += 1;
                self.bound = omega;
            }
            if uniform01(rng) * bound >= omega {
                counts.fictitious += 1;
                return;
            }
            map.collide_at_impact(p, (i, j), (vi, vj), s, counts);
        } else {
            let (vi, vj) = (p.velocity(i), p.velocity(j));
            if K::USES_UMAX {
                let u2 = (vi - vj).norm2();
                let umax = self.bound;
                if u2 > umax * umax {
                    counts.overshoots += 1;
                    self.bound = sqrt(u2);
                }
                if !self.kernel.accepts(u2, umax, uniform01(rng)) {
                    counts.fictitious += 1;
                    return;
                }
            }
            map.collide_pair::<K, G, R>(p, (i, j), (vi, vj), rng, counts);
        }
        counts.collisions += 1;
    }
}

/// The next step from `t` towards `t_end` of full length `full`: its length `h` (the last one
/// shortened to land on `t_end`; all of it when `full` is not finite and positive) and the time
/// it ends at.
pub(crate) fn next_step(t: Real, t_end: Real, full: Real) -> (Real, Real) {
    let h = if full.is_finite() && full > 0.0 {
        min(full, t_end - t)
    } else {
        t_end - t
    };
    (h, if t_end - t <= h { t_end } else { t + h })
}

/// MS's time-stepped scheme (Bird's no-time-counter form for kernels other than hard spheres)
/// with kernel `K`, drive `D` and collision map `A` (a restitution law: smooth particles;
/// [`crate::rough::RoughMap`]: rough ones, whose impact direction is hard spheres' candidate
/// `s`) in dimension `G` (module docs).
#[derive(Clone, Debug)]
pub struct TimeStepped<K, D, A, G = Spheres> {
    stage: Stage<K, G>,
    drive: D,
    restitution: A,
    step_factor: Real,
    t: Real,
    temperature: Real,
    steps: u64,
    counts: Counts,
}

impl<K: Kernel, D: Drive, A: CollisionMap, G: Geometry> TimeStepped<K, D, A, G> {
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
        super::open(p, t0, A::SPINS)?;
        let mut s = TimeStepped {
            stage: Stage::new(kernel),
            drive,
            restitution,
            step_factor,
            t: t0,
            temperature: 0.0,
            steps: 0,
            counts: Counts::default(),
        };
        let obs = s.synchronized(p)?;
        s.stage.cover(2.0 * obs.max_peculiar_speed);
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
        let candidates = 0.5 * (n.max(1) - 1) as Real * self.stage.candidate_rate();
        candidates + n as Real / self.step_length(self.temperature)
    }

    /// Steps taken so far.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The step length at temperature `t`: `f / (sqrt(2) B(v_0))`, `v_0 = (2 T)^{1/2}`; for
    /// hard spheres MS's `f lambda / v_0` (module docs).
    pub fn step_length(&self, temperature: Real) -> Real {
        self.stage
            .step_length(self.step_factor, sqrt(2.0 * temperature))
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
            let (h, t_next) = next_step(self.t, t_end, self.step_length(self.temperature));
            let n = p.len();
            let m = self
                .stage
                .count(0.5 * (n - 1) as Real * self.stage.candidate_rate(), h);
            for _ in 0..m {
                let pair = uniform_pair(rng, n);
                self.stage
                    .candidate(&self.restitution, p, pair, rng, &mut self.counts);
            }
            self.t = t_next;
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
        self.stage.cover(2.0 * obs.max_peculiar_speed);
        Ok(obs)
    }
}

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<K: Kernel, D: Drive, A: CollisionMap + crate::engine::collision_map::Inertia, G: Geometry>
    TimeStepped<K, D, A, G>
{
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs
    /// ([`crate::engine::EventLoop::cooling`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        // The stepped scheme moves physical velocities.
        crate::engine::collision_map::one_species_cooling::<K, G, A, R>(
            (&self.stage.kernel, &self.restitution, 1.0),
            p,
            pairs,
            rng,
        )
    }
}
