//! The splitting schemes of RW Section 3: Euler splitting (Algorithm 1, the scheme of MS) and
//! Strang splitting (Algorithm 2), with a time step `dt`.
//!
//! A collision step of length `h` runs the same Markov jump process as the no-splitting scheme
//! (RW Section 2: waiting times from the majorant rate, uniform pairs, fictitious collisions,
//! GRW (3)) with the drive switched off; a kicking step applies the drive to every particle for
//! the whole `dt` at once (RW step 2.2.1, SIMD batch). Euler: collide `dt`, kick `dt`. Strang:
//! collide `dt/2`, kick `dt`, collide `dt/2`. The time-step error is first and second order in
//! `dt` (RW Tables 2-4); the no-splitting scheme ([`super::NoSplitting`]) has none.
//!
//! Observation times must lie on the grid `t0 + k dt`. The scheme is generic over the collision
//! map (a restitution law, or the rough map with the particles' spins) and the dimension
//! (spheres or disks), as the no-splitting loop is: the collision steps are the same jump
//! process, and a kicking step moves what the drive moves (a rough gas's spins too).

use super::collision_map::CollisionMap;
use super::event::{Collider, observables_dim};
use super::nosplit::spins_finite;
use super::{Counts, EngineError};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::moments::Observables;
use crate::observe::RoughObservables;
use crate::particles::Particles;
use crate::rng::{Rng, uniform01};
use crate::sample::standard_exponential;

/// Which splitting: RW Algorithm 1 or 2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplittingOrder {
    /// Euler splitting (RW Algorithm 1): collide `dt`, then kick `dt`. First order.
    Euler,
    /// Strang splitting (RW Algorithm 2): collide `dt/2`, kick `dt`, collide `dt/2`. Second order.
    Strang,
}

/// A splitting scheme for kernel `K`, drive `D`, collision map `A` (a restitution law, or the
/// rough map) and dimension `G` (spheres unless named).
#[derive(Clone, Debug)]
pub struct Splitting<K, D, A, G = Spheres> {
    c: Collider<K, D, A, G>,
    order: SplittingOrder,
    dt: Real,
    t0: Real,
    steps: u64,
}

impl<K: Kernel, D: Drive, A: CollisionMap, G: Geometry> Splitting<K, D, A, G> {
    /// Starts the scheme at `t0` with time step `dt > 0` on particles holding the initial
    /// velocities (and, for the rough map, one spin each: [`EngineError::Spins`] otherwise), in
    /// dimension `G` (named by the result's type). Returns the observables at `t0`.
    // Out of line: called once per run, and the dispatch above it stays small.
    #[inline(never)]
    pub fn start(
        kernel: K,
        drive: D,
        restitution: A,
        order: SplittingOrder,
        dt: Real,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        super::check_step(dt)?;
        super::open(p, t0, A::SPINS)?;
        let mut s = Splitting {
            c: Collider::new(kernel, drive, restitution),
            order,
            dt,
            t0,
            steps: 0,
        };
        let obs = s.synchronized(p)?;
        Ok((s, obs))
    }

    /// A rough gas's rotational observables now (the particles at the current time, as after
    /// [`Self::advance_to`]); `None` for smooth particles.
    pub fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
        self.c.map.rough(p, 1.0, G::CHOICE)
    }

    /// Current time `t0 + k dt`.
    pub fn time(&self) -> Real {
        self.t0 + self.steps as Real * self.dt
    }

    /// Stored and physical velocities coincide (see [`super::NoSplitting::velocity_map`]).
    pub fn velocity_map(&self) -> super::Frame {
        super::Frame::IDENTITY
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]): the
    /// collision stages' candidates and drive events, and `n` kicks per step.
    pub fn work_rate(&self, n: usize) -> Real {
        self.c.work_rate(n, 1.0, crate::vec3::Vec3::ZERO) + n as Real / self.dt
    }

    /// The time step.
    pub fn dt(&self) -> Real {
        self.dt
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.c.counts
    }

    /// Runs whole steps up to `t_end`, which must lie on the grid `t0 + k dt`
    /// ([`super::grid_index`]: to within `1e-9` of a step, and a later time at least half a
    /// step on) and not before the current time. Returns the observables there.
    // Its own function, called once per observation: the engine's dispatch above it stays
    // small and a profile names the loop.
    #[inline(never)]
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError> {
        let target = super::grid_target(self.t0, self.dt, self.time(), t_end)?;
        while self.steps < target {
            self.step(p, rng);
        }
        self.synchronized(p)
    }

    /// Re-synchronizes after the caller changed velocities between calls: every last-kick time
    /// becomes the current time and `V`, `Umax` are recomputed. Returns the observables.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        p.reset_kick_times(self.time());
        self.synchronized(p)
    }

    fn step<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, rng: &mut R) {
        let t1 = self.t0 + (self.steps + 1) as Real * self.dt;
        match self.order {
            SplittingOrder::Euler => {
                self.collide_for(p, self.dt, rng);
                self.c
                    .drive
                    .kick_all_counting(p, t1, rng, &mut self.c.counts.background);
            }
            SplittingOrder::Strang => {
                self.collide_for(p, 0.5 * self.dt, rng);
                self.c
                    .drive
                    .kick_all_counting(p, t1, rng, &mut self.c.counts.background);
                self.collide_for(p, 0.5 * self.dt, rng);
            }
        }
        if D::ACTS && K::USES_UMAX {
            // The kicks moved every particle: the majorant must cover them again.
            for q in p.as_slice() {
                self.c.maj.cover(q.velocity());
            }
        }
        self.steps += 1;
    }

    /// The collision process alone for a time `h` (RW Algorithm 1 steps 2.1.1-2.1.7).
    fn collide_for<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, h: Real, rng: &mut R) {
        let n = p.len();
        let mut rate = self.c.rate(n, 1.0);
        let mut s = 0.0;
        loop {
            s += standard_exponential(rng) / rate;
            if s.partial_cmp(&h) != Some(core::cmp::Ordering::Less) {
                return;
            }
            let (i, j) = self.c.pairs.next(p, rng);
            let accept = if K::USES_UMAX { uniform01(rng) } else { 0.0 };
            if self.c.candidate(p, i, j, false, accept, rng) {
                rate = self.c.rate(n, 1.0);
            }
        }
    }

    fn synchronized(&mut self, p: &Particles<'_>) -> Result<Observables, EngineError> {
        let obs = observables_dim(p, G::CHOICE.d())?;
        if A::SPINS {
            spins_finite(p)?;
        }
        self.c.synchronized(&obs);
        Ok(obs)
    }
}

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<K: Kernel, D: Drive, A: CollisionMap + crate::engine::collision_map::Inertia, G: Geometry>
    Splitting<K, D, A, G>
{
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs
    /// ([`crate::engine::EventLoop::cooling`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        // The splitting moves physical velocities.
        crate::engine::collision_map::one_species_cooling::<K, G, A, R>(
            (&self.c.kernel, &self.c.map, 1.0),
            p,
            pairs,
            rng,
        )
    }
}
