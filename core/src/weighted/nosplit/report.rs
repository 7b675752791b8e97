//! What the weighted loop reports, in physical units: its time and counts, the observables of
//! its stored (possibly rescaled) particles, the collisions per particle, the work rate and the
//! cooling from random pairs; its [`EventLoop`](crate::engine::EventLoop) implementation.

use super::WeightedNoSplitting;
use crate::drive::Drive;
use crate::engine::collision_map::one_species_cooling;
use crate::engine::frame::RESCALE_BELOW;
use crate::engine::{Counts, EngineError, Frame};
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::Rng;
use crate::weighted::moments::observables;

impl<K: Kernel, A: Restitution, D: Drive, G: Geometry> WeightedNoSplitting<K, A, D, G> {
    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Reductions so far.
    pub fn reductions(&self) -> u64 {
        self.reductions
    }

    /// Re-synchronizes after the caller changed velocities (not weights) between calls: every
    /// last-kick time becomes the current time and the bounds are made exact. Returns the
    /// observables.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        let back = self.frame.reset(p, false);
        if !D::ACTS {
            // Only a gas with no drive is ever stored rescaled.
            self.law = self.law.in_stored_units(back);
        }
        p.reset_kick_times(self.t);
        self.refresh(p)?;
        let o = observables(p, G::CHOICE.d());
        self.drive.observe(&o);
        self.physical(p, &o)
    }

    /// Candidates per unit time now: the majorant's rate at the particles in use when the loop
    /// last stopped (`_n`, the particles a run started with, does not set it: collisions and
    /// reductions change the number).
    pub fn work_rate(&self, _n: usize) -> Real {
        let n = self.len as Real;
        0.5 * n
            * (n - 1.0)
            * (1.0 + self.transfer.kappa_max())
            * self.gmax
            * self.kernel.b_max(self.umax)
            / self.n0
    }

    /// The collisional cooling of `p` at the current time from `pairs` random pairs, each
    /// counted by the product of its weights ([`crate::observe::cooling::estimate`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        one_species_cooling::<K, G, A, R>(
            (&self.kernel, &self.law, self.frame.scale),
            p,
            pairs,
            rng,
        )
    }

    /// Collisions per particle so far: the weight the collisions moved over the total weight
    /// (`2/n` a collision for equal weights, whose transfer moves whole weights).
    pub fn collisions_per_particle(&self, _n: usize) -> Real {
        self.moved / self.n0
    }

    /// The map from stored to physical velocities (the identity unless a cooling gas was
    /// rescaled).
    pub fn velocity_map(&self) -> Frame {
        self.frame
    }

    /// A cooling gas (no drive) stored rescaled when its stored temperature about `o.bulk`
    /// has fallen below [`RESCALE_BELOW`] (`o` becomes the stored system's), its bounds then
    /// made exact in the new units.
    pub(super) fn rescale(
        &mut self,
        sys: &mut Particles<'_>,
        o: &mut Observables,
    ) -> Result<(), EngineError> {
        let d = G::CHOICE.d();
        if D::ACTS {
            // A driven gas is never stored rescaled.
        } else if let Some(f) = self
            .frame
            .rescale_with(sys, o, (RESCALE_BELOW, false), |p| observables(p, d))
        {
            self.counts.rescales += 1;
            self.law = self.law.in_stored_units(f);
            self.refresh(sys)?;
        }
        Ok(())
    }

    /// The stored system's observables `o` in physical units, refused when not finite.
    pub(super) fn physical(
        &self,
        sys: &Particles<'_>,
        o: &Observables,
    ) -> Result<Observables, EngineError> {
        let d = G::CHOICE.d();
        let o = (self.frame).with_raw_v6_weighted(
            sys.as_slice(),
            sys.weights(),
            self.frame.observables(o, d),
        );
        match o.non_finite() {
            Some(what) => Err(EngineError::NonFinite(what)),
            None => Ok(o),
        }
    }
}

crate::engine::impl_event_loop!(
    WeightedNoSplitting,
    [K: Kernel, A: Restitution, D: Drive, G: Geometry],
    WeightedNoSplitting<K, A, D, G>,
    {
        fn collisions_per_particle(&self, n: usize) -> Real {
            WeightedNoSplitting::collisions_per_particle(self, n)
        }
    }
);
