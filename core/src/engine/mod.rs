//! Event loops. [`NoSplitting`] is the exact scheme of GRW Section 3 / RW Algorithm 3.

pub mod collision_map;
mod counts;
pub mod event;
pub mod frame;
pub(crate) mod jumps;
pub mod nosplit;
pub mod pairs;
pub mod splitting;
pub mod sum_form;
pub mod time_stepped;

pub use collision_map::CollisionMap;
pub use counts::Counts;
pub use frame::Frame;
pub use nosplit::NoSplitting;
pub use splitting::{Splitting, SplittingOrder};
pub use sum_form::SumNoSplitting;
pub use time_stepped::TimeStepped;

use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::Rng;

/// What a caller needs from any event loop: advance to an observation time, read counts.
pub trait EventLoop {
    /// Runs to `t_end` and returns the observables there (every particle at `t_end`).
    fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError>;
    /// Re-synchronizes after the caller changed the velocities (all at the current time).
    fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError>;
    /// Current time.
    fn time(&self) -> Real;
    /// Event counts so far.
    fn counts(&self) -> Counts;
    /// Work units per unit time from the current state of `n` particles on: the majorant's
    /// candidate events (GRW Section 3, RW (20)), a host medium's background events (BRS
    /// (28)'s bound at the majorant's speed) and a stepped scheme's particle updates. The
    /// work of an advance to `t` is about `work_rate(n) * (t - time())` ([`work_to`]); a
    /// heated gas's majorant grows during it, so this is an estimate, not a bound.
    fn work_rate(&self, n: usize) -> Real;
    /// Collisions per particle so far, `2 collisions / n` for a run of `n` particles; weighted
    /// particles count each collision by the weight it moved (over the total weight).
    fn collisions_per_particle(&self, n: usize) -> Real {
        2.0 * self.counts().collisions as Real / n as Real
    }
    /// The map `v_phys = offset + scale v` from stored to physical velocities.
    fn velocity_map(&self) -> Frame {
        Frame::IDENTITY
    }
    /// A mixture's observables per species of the synchronized particles `p` (right after
    /// [`EventLoop::advance_to`] or a start), in physical units; `None` for a one-species gas.
    fn species(&self, _p: &Particles<'_>) -> Option<crate::observe::MixtureObservables> {
        None
    }

    /// A rough gas's rotational observables (`None` for a smooth gas). The particles must be
    /// at the current time (as after [`EventLoop::advance_to`]).
    fn rough(&self, _p: &Particles<'_>) -> Option<crate::observe::RoughObservables> {
        None
    }

    /// The collisional cooling of the particles `p` at the current time (as after
    /// [`EventLoop::advance_to`]): the collision frequency and `zeta*` from `pairs >= 1`
    /// random pairs drawn from `rng` (the caller's own stream: the loop and the particles are
    /// untouched), collided by this loop's kernel, direction law and map
    /// ([`crate::observe::cooling`]).
    fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling;
}

/// Implements [`EventLoop`] for a loop type `$ty` (generics `[$g]`) by forwarding every method
/// to the inherent one of the same name on `$t` (a mixture's return its per-species
/// observables, of which the trait's are the whole gas's, `From`); methods in a trailing
/// `{ ... }` are added (a rough gas's `rough`, a mixture's `species`). `advance_to` and
/// `resync` stay out of line: a caller's `match` over every engine (the physics dispatch)
/// would otherwise reserve a mixture's per-species observables in its frame for every physics.
macro_rules! impl_event_loop {
    ($t:ident, [$($g:tt)*], $ty:ty) => {
        $crate::engine::impl_event_loop!($t, [$($g)*], $ty, {});
    };
    ($t:ident, [$($g:tt)*], $ty:ty, { $($extra:tt)* }) => {
        impl<$($g)*> $crate::engine::EventLoop for $ty {
            $($extra)*
            #[inline(never)]
            fn advance_to<R: $crate::rng::Rng + ?Sized>(
                &mut self,
                p: &mut $crate::particles::Particles<'_>,
                t_end: $crate::math::Real,
                rng: &mut R,
            ) -> Result<$crate::moments::Observables, $crate::engine::EngineError> {
                $t::advance_to(self, p, t_end, rng).map(Into::into)
            }
            #[inline(never)]
            fn resync(
                &mut self,
                p: &mut $crate::particles::Particles<'_>,
            ) -> Result<$crate::moments::Observables, $crate::engine::EngineError> {
                $t::resync(self, p).map(Into::into)
            }
            fn time(&self) -> $crate::math::Real {
                $t::time(self)
            }
            fn counts(&self) -> $crate::engine::Counts {
                $t::counts(self)
            }
            fn work_rate(&self, n: usize) -> $crate::math::Real {
                $t::work_rate(self, n)
            }
            fn cooling<R: $crate::rng::Rng + ?Sized>(
                &self,
                p: &$crate::particles::Particles<'_>,
                pairs: u64,
                rng: &mut R,
            ) -> $crate::observe::Cooling {
                $t::cooling(self, p, pairs, rng)
            }
            fn velocity_map(&self) -> $crate::engine::Frame {
                $t::velocity_map(self)
            }
        }
    };
}
pub(crate) use impl_event_loop;
impl_event_loop!(
    NoSplitting,
    [K: crate::kernel::Kernel, D: crate::drive::Drive, A: CollisionMap + collision_map::Inertia, G: crate::geometry::Geometry],
    NoSplitting<K, D, A, G>,
    {
        fn rough(&self, p: &Particles<'_>) -> Option<crate::observe::RoughObservables> {
            NoSplitting::rough(self, p)
        }
    }
);
impl_event_loop!(
    Splitting,
    [K: crate::kernel::Kernel, D: crate::drive::Drive, A: CollisionMap + collision_map::Inertia, G: crate::geometry::Geometry],
    Splitting<K, D, A, G>,
    {
        fn rough(&self, p: &Particles<'_>) -> Option<crate::observe::RoughObservables> {
            Splitting::rough(self, p)
        }
    }
);
impl_event_loop!(
    SumNoSplitting,
    [A: crate::restitution::Restitution],
    SumNoSplitting<A>
);

impl<
    K: crate::kernel::Kernel,
    D: crate::drive::Drive,
    A: CollisionMap + collision_map::Inertia,
    G: crate::geometry::Geometry,
> EventLoop for TimeStepped<K, D, A, G>
{
    fn advance_to<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut R,
    ) -> Result<Observables, EngineError> {
        TimeStepped::advance_to(self, p, t_end, rng)
    }
    fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        TimeStepped::resync(self, p)
    }
    fn time(&self) -> Real {
        TimeStepped::time(self)
    }
    fn counts(&self) -> Counts {
        TimeStepped::counts(self)
    }
    fn work_rate(&self, n: usize) -> Real {
        TimeStepped::work_rate(self, n)
    }
    fn rough(&self, p: &Particles<'_>) -> Option<crate::observe::RoughObservables> {
        TimeStepped::rough(self, p)
    }
    fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        TimeStepped::cooling(self, p, pairs, rng)
    }
}

/// The opening every loop's start shares: the start time `t0` must be finite and a loop of
/// rough particles (`spins`) needs their spins beside them; then every particle's last kick is
/// at `t0` (GRW Section 3, step 1: all particles synchronized at the start).
pub(crate) fn open(p: &mut Particles<'_>, t0: Real, spins: bool) -> Result<(), EngineError> {
    if !t0.is_finite() {
        return Err(EngineError::TimeBackwards);
    }
    if spins && !p.has_spins() {
        return Err(EngineError::Spins);
    }
    p.reset_kick_times(t0);
    Ok(())
}

/// The work an advance may ask for before a front end refuses it unasked (`gdsmc run
/// --allow-long`, the C ABI's `gdsmc_sim_set_work_limit`): 1e12 work units, about a day of
/// one core at the measured 1e7-3e7 events per second (`gdsmc bench throughput`).
pub const WORK_LIMIT: Real = 1e12;

/// The work units ([`EventLoop::work_rate`]) of advancing `e` (with `n` particles) from its
/// current time to `t`: 0 for `t` at or before it, infinite for a non-finite `t` or rate.
pub fn work_to<E: EventLoop + ?Sized>(e: &E, n: usize, t: Real) -> Real {
    let dt = t - e.time();
    if dt.is_nan() {
        return Real::INFINITY;
    }
    if dt <= 0.0 {
        return 0.0;
    }
    let w = e.work_rate(n) * dt;
    if w.is_nan() { Real::INFINITY } else { w }
}

/// The rule for a time step or step factor of the stepped schemes: finite and > 0
/// ([`EngineError::OffGrid`] otherwise).
pub fn check_step(h: Real) -> Result<Real, EngineError> {
    if h.is_finite() && h > 0.0 {
        Ok(h)
    } else {
        Err(EngineError::OffGrid)
    }
}

/// The step a splitting scheme at time `now` on the grid `t0 + k dt` must reach for `t_end`:
/// [`EngineError::TimeBackwards`] for a non-finite `t_end` or one before `now`,
/// [`EngineError::OffGrid`] off the grid ([`grid_index`]).
pub fn grid_target(t0: Real, dt: Real, now: Real, t_end: Real) -> Result<u64, EngineError> {
    if !t_end.is_finite() || t_end < now {
        return Err(EngineError::TimeBackwards);
    }
    grid_index(t0, dt, t_end).ok_or(EngineError::OffGrid)
}

/// The step index `k` of the time `t` on a splitting scheme's grid `t0 + k dt` (RW Algorithms
/// 1-2 observe only there), to within `1e-9` of a step: `None` when `t` is not finite, before
/// `t0`, off the grid, or later than `t0` by less than half a step (a span that would take no
/// step at all: `dt = 1e300` to `t = 8` is not the exact `t = 0`). The one grid rule of the
/// engine ([`Splitting::advance_to`]) and of every front end's check of observation times.
pub fn grid_index(t0: Real, dt: Real, t: Real) -> Option<u64> {
    if !(t.is_finite() && t >= t0 && dt.is_finite() && dt > 0.0) {
        return None;
    }
    let k = (t - t0) / dt;
    // More steps than a u64 counts (or an infinite k) is no grid a run can step on.
    if k.is_nan() || k >= u64::MAX as Real {
        return None;
    }
    let target = (k + 0.5) as u64;
    if crate::math::abs(k - target as Real) > 1e-9 * (1.0 + k) || (target == 0 && t > t0) {
        return None;
    }
    Some(target)
}

/// Why an event loop stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EngineError {
    /// The requested time lies before the system's current time (or is NaN).
    TimeBackwards,
    /// A velocity or moment became non-finite (overflow, NaN input); names the first
    /// observable that did.
    NonFinite(&'static str),
    /// A time-stepped scheme was asked for a time that is not on its grid `t0 + k dt`, or
    /// its time step is not finite and positive.
    OffGrid,
    /// The particle buffer does not hold the `n` particles the physics names.
    ParticleCount,
    /// A rough gas was started without one spin per particle.
    Spins,
    /// A rule the validated model guarantees did not hold when the engine was composed (a
    /// bug in gdsmc, never the caller's input): names the rule.
    Invariant(&'static str),
    /// The physics needs an engine family this build left out (a cargo feature of
    /// gdsmc-core: `mixtures`, `rough`, `disks`); names the feature.
    NotBuilt(&'static str),
}

impl core::fmt::Display for EngineError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            EngineError::TimeBackwards => "observation time lies before the current time",
            EngineError::NonFinite(what) => {
                return write!(
                    f,
                    "{what} became non-finite (the velocities left the range of f64)"
                );
            }
            EngineError::OffGrid => {
                "the time is not on the scheme's grid: a whole multiple of the time step from the \
                 start, at least one step on"
            }
            EngineError::ParticleCount => "the particle buffer does not hold n particles",
            EngineError::Spins => "a rough gas needs a spin buffer of n spins beside its particles",
            EngineError::Invariant(what) => {
                return write!(
                    f,
                    "a rule of the validated model did not hold ({what}): a bug in gdsmc, please \
                     report it with the scene"
                );
            }
            EngineError::NotBuilt(what) => {
                return write!(
                    f,
                    "this build of gdsmc-core leaves out the engines this physics needs (cargo \
                     feature `{what}`)"
                );
            }
        })
    }
}
