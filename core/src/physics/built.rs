//! The payloads that keep loops out of the build: [`Built`] (a variant's engine, or the
//! uninhabited [`NotBuilt`] when its cargo feature is off) and [`Exact`] (an exact loop, never
//! compiled for a drive no exact scheme runs). Both make a variant the engine never holds cost
//! nothing: its loops are not monomorphized.

use crate::drive::Drive;
use crate::engine::{Counts, EngineError, EventLoop, Frame};
use crate::math::Real;
use crate::mixture::MixtureObservables;
use crate::moments::Observables;
use crate::observe::Cooling;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::rough::RoughObservables;

/// A variant's payload at any level (family, kernel, drive, law, scheme): the engine itself
/// when the build holds it, else [`NotBuilt`] (uninhabited: the variant cannot be made, and
/// none of its loops is compiled).
pub type Built<T, const ON: bool> = <Select<ON> as Pick<T>>::Out;

/// The switch behind [`Built`].
pub struct Select<const ON: bool>;

/// What [`Select`] picks for a payload `T`.
pub trait Pick<T> {
    /// `T` or [`NotBuilt<T>`].
    type Out: EventLoop + Clone + core::fmt::Debug;
}

impl<T: EventLoop + Clone + core::fmt::Debug> Pick<T> for Select<true> {
    type Out = T;
}

impl<T: EventLoop + Clone + core::fmt::Debug> Pick<T> for Select<false> {
    type Out = NotBuilt<T>;
}

/// An engine this build left out: no value exists, so its variant is never made (starting its
/// physics returns [`EngineError::NotBuilt`]).
#[derive(Clone, Debug)]
pub struct NotBuilt<T>(core::convert::Infallible, core::marker::PhantomData<T>);

impl<T> EventLoop for NotBuilt<T> {
    fn advance_to<R: Rng + ?Sized>(
        &mut self,
        _p: &mut Particles<'_>,
        _t_end: Real,
        _rng: &mut R,
    ) -> Result<Observables, EngineError> {
        match self.0 {}
    }
    fn resync(&mut self, _p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        match self.0 {}
    }
    fn time(&self) -> Real {
        match self.0 {}
    }
    fn counts(&self) -> Counts {
        match self.0 {}
    }
    fn work_rate(&self, _n: usize) -> Real {
        match self.0 {}
    }
    fn velocity_map(&self) -> Frame {
        match self.0 {}
    }
    fn collisions_per_particle(&self, _n: usize) -> Real {
        match self.0 {}
    }
    fn species(&self, _p: &Particles<'_>) -> Option<MixtureObservables> {
        match self.0 {}
    }
    fn rough(&self, _p: &Particles<'_>) -> Option<RoughObservables> {
        match self.0 {}
    }
    fn cooling<R: Rng + ?Sized>(&self, _p: &Particles<'_>, _k: u64, _rng: &mut R) -> Cooling {
        match self.0 {}
    }
}

/// An exact (no-splitting) loop `T` of drive `D`: the loop itself for a drive an exact scheme
/// runs; for one none does ([`Drive::EXACT`] false) it is never made (the dispatch refuses
/// first, as the validation does), and its methods' calls, behind the constant, are not
/// compiled: no exact loop of a stepped-only drive is monomorphized.
#[derive(Clone, Debug)]
pub struct Exact<T, D>(T, core::marker::PhantomData<D>);

impl<T, D: Drive> Exact<T, D> {
    /// The loop `t`, if drive `D` is run exactly; `None` never calls `t`, so the loop is not
    /// compiled for a stepped-only drive. Inlined: the loop is moved no more than it was
    /// without this level (a firmware's stack).
    #[inline(always)]
    pub(super) fn start(
        t: impl FnOnce() -> Result<(T, Observables), EngineError>,
    ) -> Result<(Self, Observables), EngineError> {
        if D::EXACT {
            let (l, obs) = t()?;
            Ok((Exact(l, core::marker::PhantomData), obs))
        } else {
            Err(EngineError::Invariant(
                "validated: no exact loop runs a drive that must be time-stepped",
            ))
        }
    }
}

/// The method of an exact loop whose drive is stepped-only: never called (no such loop is made).
#[cold]
fn never_made() -> ! {
    unreachable!("no exact loop of a stepped-only drive is made")
}

impl<T: EventLoop, D: Drive> EventLoop for Exact<T, D> {
    fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError> {
        if D::EXACT {
            self.0.advance_to(p, t_end, rng)
        } else {
            never_made()
        }
    }
    fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        if D::EXACT {
            self.0.resync(p)
        } else {
            never_made()
        }
    }
    fn time(&self) -> Real {
        if D::EXACT {
            self.0.time()
        } else {
            never_made()
        }
    }
    fn counts(&self) -> Counts {
        if D::EXACT {
            self.0.counts()
        } else {
            never_made()
        }
    }
    fn work_rate(&self, n: usize) -> Real {
        if D::EXACT {
            self.0.work_rate(n)
        } else {
            never_made()
        }
    }
    fn velocity_map(&self) -> Frame {
        if D::EXACT {
            self.0.velocity_map()
        } else {
            never_made()
        }
    }
    fn collisions_per_particle(&self, n: usize) -> Real {
        if D::EXACT {
            self.0.collisions_per_particle(n)
        } else {
            never_made()
        }
    }
    fn species(&self, p: &Particles<'_>) -> Option<MixtureObservables> {
        if D::EXACT {
            self.0.species(p)
        } else {
            never_made()
        }
    }
    fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
        if D::EXACT {
            self.0.rough(p)
        } else {
            never_made()
        }
    }
    fn cooling<R: Rng + ?Sized>(&self, p: &Particles<'_>, pairs: u64, rng: &mut R) -> Cooling {
        if D::EXACT {
            self.0.cooling(p, pairs, rng)
        } else {
            never_made()
        }
    }
}
