//! Drives: what acts on every particle between collisions.
//!
//! A drive is applied lazily, particle by particle, from its last-kick time to the time it is
//! needed (GRW Section 3 steps 2.5-2.6, RW Algorithm 3), and in one batch to every particle at
//! an observation time (GRW step 3.1). The event loop is generic over [`Drive`].

pub mod declared;
pub mod host_medium;
pub mod langevin;
pub mod none;
pub mod thermostat;
pub mod white_noise;

pub use declared::{Declared, Heating, MAX_DRIVE_PARAMS, ParamSpec, Rule, WorkInput};
pub use host_medium::{HardSphereBackground, HostMedium, HostMediumParams, MaxwellBackground};
pub use langevin::Langevin;
pub use none::NoDrive;
pub use thermostat::{ConstantForce, GaussianThermostat};
pub use white_noise::{PlanarWhiteNoise, WhiteNoise, WhiteNoiseIn};

use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// A drive acting on each particle independently between collisions.
pub trait Drive: Copy + core::fmt::Debug {
    /// False for a drive that does nothing (then no kick is ever computed).
    const ACTS: bool;

    /// False for a drive no exact (no-splitting) scheme runs (the constant force, whose
    /// correction couples every particle's free motion): its exact loops are then never
    /// compiled (the engine's `Exact` level), and the validation refuses the scheme first.
    const EXACT: bool = true;

    /// True for a drive that reads the observables ([`Drive::observe`] does something): a loop
    /// may skip computing them for a drive that does not (the weighted loop's synchronizations
    /// before a reduction).
    const OBSERVES: bool = false;

    /// Called by the event loops whenever every particle is at one time, with the observables
    /// there (drives that act about the bulk velocity take it from here; they set
    /// [`Drive::OBSERVES`]). Default: nothing.
    #[inline(always)]
    fn observe(&mut self, _obs: &Observables) {}

    /// True for a drive made of discrete events that [`Drive::evolve_counting`] counts (the
    /// host medium's background collisions); false: every kick counts nothing.
    const COUNTS_EVENTS: bool = false;

    /// True for a drive whose batch kick couples the particles (the constant force's
    /// momentum-keeping correction, MS (62)): a mixture then kicks every species in one pass,
    /// [`Drive::kick_weighted`], not species by species.
    const COUPLES: bool = false;

    /// All particles to `t`, those of `groups[k].0` having mass `groups[k].1` (a mixture's
    /// species, one drive for all). Default: each particle alone, as [`Drive::kick`]; a
    /// coupling drive keeps what its correction keeps, weighted by mass.
    fn kick_weighted<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        groups: &[(core::ops::Range<usize>, Real)],
        t: Real,
        rng: &mut R,
    ) {
        for (range, _) in groups {
            for i in range.clone() {
                self.kick(p, i, t, rng);
            }
        }
    }

    /// Events per unit time the drive costs one grain whose speed is at most `speed`: a host
    /// medium's background majorant (BRS (28)); 0 (the default) for a drive in closed form. For
    /// [`crate::engine::EventLoop::work_rate`].
    #[inline(always)]
    fn event_rate(&self, _speed: Real) -> Real {
        0.0
    }

    /// The velocity after the drive acted on `v` for a time `dt >= 0`.
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, rng: &mut R) -> Vec3;

    /// As [`Drive::evolve`], adding the drive's discrete events to `events` (the same draws,
    /// the same velocity). Default: none.
    #[inline(always)]
    fn evolve_counting<R: Rng + ?Sized>(
        &self,
        v: Vec3,
        dt: Real,
        rng: &mut R,
        _events: &mut u64,
    ) -> Vec3 {
        self.evolve(v, dt, rng)
    }

    /// As [`Drive::kick`], adding the drive's events to `events`.
    #[inline(always)]
    fn kick_counting<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        i: usize,
        t: Real,
        rng: &mut R,
        events: &mut u64,
    ) {
        if Self::COUNTS_EVENTS {
            let q = p.get_mut(i);
            let v = self.evolve_counting(q.velocity(), t - q.t_kick, rng, events);
            q.set_velocity(v);
            q.t_kick = t;
        } else {
            self.kick(p, i, t, rng);
        }
    }

    /// Brings the two partners `i` and `j` of a candidate to `t`, adding the drive's events to
    /// `events`. Default: [`Drive::kick_counting`] for `i`, then for `j`; the white noise on
    /// spheres draws both partners' six normals from three words (stream version 2).
    #[inline(always)]
    fn kick_pair_counting<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        (i, j): (usize, usize),
        t: Real,
        rng: &mut R,
        events: &mut u64,
    ) {
        self.kick_counting(p, i, t, rng, events);
        self.kick_counting(p, j, t, rng, events);
    }

    /// As [`Drive::kick_all`], adding the drive's events to `events`.
    fn kick_all_counting<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        t: Real,
        rng: &mut R,
        events: &mut u64,
    ) {
        if Self::COUNTS_EVENTS {
            for i in 0..p.len() {
                self.kick_counting(p, i, t, rng, events);
            }
        } else {
            self.kick_all(p, t, rng);
        }
    }

    /// Brings particle `i` to time `t`: `v_i := evolve(v_i, t - t_i)`, `t_i := t`.
    #[inline(always)]
    fn kick<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, i: usize, t: Real, rng: &mut R) {
        if Self::ACTS {
            let q = p.get_mut(i);
            let v = self.evolve(q.velocity(), t - q.t_kick, rng);
            q.set_velocity(v);
            q.t_kick = t;
        }
    }

    /// Brings every particle to time `t` (GRW step 3.1). The default goes particle by particle;
    /// drives override it with a batch kernel.
    fn kick_all<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        if Self::ACTS {
            for i in 0..p.len() {
                self.kick(p, i, t, rng);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A drive's observation changes it exactly when it declares [`Drive::OBSERVES`] (a loop
    /// that skips the observables for a drive that does not would otherwise lose its state).
    fn observes_as_declared<D: Drive + PartialEq>(d: D) {
        let mut seen = d;
        let obs = Observables {
            bulk: Vec3::new(0.5, -0.25, 2.0),
            ..Observables::default()
        };
        seen.observe(&obs);
        assert_eq!(seen != d, D::OBSERVES, "{d:?}");
    }

    #[test]
    fn every_drive_that_reads_the_observables_says_so() {
        observes_as_declared(NoDrive);
        observes_as_declared(WhiteNoise::new(1.0).unwrap());
        observes_as_declared(PlanarWhiteNoise::new(1.0).unwrap());
        observes_as_declared(GaussianThermostat::new(0.5).unwrap());
        observes_as_declared(ConstantForce::new(0.5).unwrap());
    }
}
