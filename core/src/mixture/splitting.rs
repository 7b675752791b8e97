//! RW's Euler and Strang splittings (RW Section 3, Algorithms 1 and 2) for a mixture: the
//! collision steps are the mixture's exact jump process with the drives switched off (the
//! no-splitting loop [`super::MixtureNoSplitting`] with [`NoDrive`], run for the step's
//! collision time), the kicking step moves every particle of species `s` with its drive for
//! the whole `dt` at once. Euler: collide `dt`, kick `dt`; Strang: collide `dt/2`, kick `dt`,
//! collide `dt/2`. No loop is written here: the collision process is the exact loop's, so a
//! rough mixture and a mixture of disks split as a smooth mixture of spheres does.
//!
//! Observation times must lie on the grid `t0 + k dt`. Each step synchronizes the particles
//! once after each collision stage and once after the kick (O(n) each, as the kick itself is).

use super::StartError;
use super::drives::{kick_species, tell_drives};
use super::map::PairLaw;
use super::nosplit::{MixtureNoSplitting, PairPhysics, drives_off};
use crate::drive::{Drive, NoDrive};
use crate::engine::frame::Frame;
use crate::engine::{Counts, EngineError, SplittingOrder, check_step, grid_target};
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::observe::MixtureObservables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::species::{MAX_SPECIES, Species};

/// A splitting scheme for a mixture: kernel `K`, drive `D` (one per species), pair law `L`,
/// dimension `G` (spheres unless named).
#[derive(Clone, Debug)]
pub struct MixtureSplitting<K, D, L: PairLaw, G = Spheres> {
    collide: MixtureNoSplitting<K, NoDrive, L, G>,
    drives: [D; MAX_SPECIES],
    order: SplittingOrder,
    dt: Real,
    t0: Real,
    steps: u64,
    observations: u64,
}

impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureSplitting<K, D, L, G> {
    /// Starts the scheme at `t0` with time step `dt > 0` (the arguments of
    /// [`MixtureNoSplitting::start`], the order and the step), in dimension `G` (named by the
    /// result's type). Returns the observables at `t0`.
    #[inline(never)]
    pub fn start(
        sp: Species,
        physics: &[PairPhysics<K, L>],
        drives: &[D],
        order: SplittingOrder,
        dt: Real,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, MixtureObservables), StartError> {
        check_step(dt).map_err(StartError::Engine)?;
        let (collide, obs) = drives_off(sp, physics, drives, p, t0)?;
        let mut s = MixtureSplitting {
            collide,
            drives: core::array::from_fn(|k| drives[k.min(sp.len() - 1)]),
            order,
            dt,
            t0,
            steps: 0,
            observations: 1,
        };
        tell_drives(&mut s.drives, &obs);
        Ok((s, obs))
    }

    /// Current time `t0 + k dt`.
    pub fn time(&self) -> Real {
        self.t0 + self.steps as Real * self.dt
    }

    /// Event counts so far; `observations` counts the caller's (the steps' own
    /// synchronizations are left out).
    pub fn counts(&self) -> Counts {
        Counts {
            observations: self.observations,
            ..self.collide.counts()
        }
    }

    /// Work units per unit time from here: the collision process's, and `n / dt` particle
    /// updates of the kicks.
    pub fn work_rate(&self, n: usize) -> Real {
        self.collide.work_rate(n) + n as Real / self.dt
    }

    /// Stored and physical velocities coincide.
    pub fn velocity_map(&self) -> Frame {
        Frame::IDENTITY
    }

    /// Runs the scheme to the grid time `t_end` ([`crate::engine::grid_index`]), not before the current
    /// time. Returns the observables there.
    #[inline(never)]
    pub fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<MixtureObservables, EngineError> {
        let target = grid_target(self.t0, self.dt, self.time(), t_end)?;
        self.observations += 1;
        if self.steps == target {
            // No step to take: the particles are as the last call (or a resync) left them.
            return self.collide.resync(p);
        }
        let mut obs = None;
        while self.steps < target {
            // Every collision stage ends synchronized: its observables serve the kick.
            obs = Some(match self.order {
                SplittingOrder::Euler => {
                    let t = self.collide.time() + self.dt;
                    let synced = self.collide.advance_to(p, t, rng)?;
                    self.kick(p, &synced, rng)?
                }
                SplittingOrder::Strang => {
                    let t = self.collide.time() + 0.5 * self.dt;
                    let synced = self.collide.advance_to(p, t, rng)?;
                    self.kick(p, &synced, rng)?;
                    let t = self.collide.time() + 0.5 * self.dt;
                    self.collide.advance_to(p, t, rng)?
                }
            });
            self.steps += 1;
        }
        obs.ok_or(EngineError::Invariant("a step was taken"))
    }

    /// Each species' observables of the synchronized particles `p`.
    pub fn species_now(&self, p: &Particles<'_>) -> MixtureObservables {
        self.collide.species_now(p)
    }

    /// Re-synchronizes after the caller changed velocities between calls.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<MixtureObservables, EngineError> {
        let obs = self.collide.resync(p)?;
        tell_drives(&mut self.drives, &obs);
        Ok(obs)
    }

    /// The kicking step after a collision stage that left the particles synchronized with
    /// observables `synced`: every particle moved by its species' drive over `dt` (the drives
    /// told the flow velocity first), then the collision loop synchronized on the new
    /// velocities.
    fn kick<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        synced: &MixtureObservables,
        rng: &mut R,
    ) -> Result<MixtureObservables, EngineError> {
        if !D::ACTS {
            return Ok(*synced);
        }
        let now = self.collide.time();
        tell_drives(&mut self.drives, synced);
        p.reset_kick_times(now - self.dt);
        let sp = *self.collide.species();
        let mut background = 0;
        kick_species(&self.drives, &sp, p, now, rng, &mut background);
        self.collide.resync(p)
    }
}

crate::engine::impl_event_loop!(
    MixtureSplitting,
    [K: Kernel, D: Drive, L: PairLaw, G: Geometry],
    MixtureSplitting<K, D, L, G>,
    {
        #[inline(never)]
        fn species(&self, p: &Particles<'_>) -> Option<MixtureObservables> {
            Some(MixtureSplitting::species_now(self, p))
        }
    }
);

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureSplitting<K, D, L, G> {
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs: the pair
    /// table's ([`MixtureNoSplitting::cooling`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        self.collide.cooling(p, pairs, rng)
    }
}
