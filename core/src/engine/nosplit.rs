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
//! between observations: with a drive, whenever more than half of the last `2n` (then `4n`, ...)
//! candidates were fictitious, after kicking every particle to the current time as an
//! observation does, so the process stays the same ([`Counts::refreshes`]); with no drive (every
//! particle always current) every `2n` candidates, in one light pass
//! ([`crate::batch::sync`]): `Umax = 2 max |v_i - V|` about the `V` of the last observation
//! (the momentum is conserved, and any `V` gives a true bound), the temperature for the
//! rescale test below, and the finiteness of the velocities.
//!
//! A gas with no drive cools for ever: at a synchronization whose temperature has fallen
//! below [`RESCALE_BELOW`] the velocities are stored rescaled ([`super::frame`]); the
//! observables are returned in physical units ([`Counts::rescales`]).
//!
//! The particle model is the collision map `A` ([`CollisionMap`]): a restitution law (smooth
//! particles, GRW (3)) or [`crate::rough::RoughMap`] (rough particles: rotation does not enter
//! the collision rate, so the majorant, the waiting times, the fictitious test and the refresh
//! schedule are unchanged; an accepted pair draws its impact direction and applies the rough
//! map, and the drive kicks translation and rotation together). With spins the loop checks
//! them at every synchronization and rescales them with the velocities.
//!
//! For Maxwell pseudo-molecules the majorant is the kernel itself: no `Umax`, no fictitious
//! collisions, and none of that bookkeeping is compiled in.

use super::collision_map::CollisionMap;
use super::event::{Collider, Majorant, RefreshWindow, observables_dim};
use super::frame::{Frame, rescale_due};
use super::jumps::{Jumps, jumps_state, run_events};
use super::{Counts, EngineError};
use crate::batch::sync::{SyncSums, sync_sums};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{Real, sqrt};
use crate::moments::Observables;
use crate::observe::RoughObservables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

pub use super::frame::RESCALE_BELOW;

/// The exact (no-splitting) event loop for kernel `K`, drive `D`, collision map `A` (a
/// restitution law, or the rough map) and dimension `G` (spheres unless named; disks:
/// [`crate::geometry::Disks`], whose drive acts in the plane).
#[derive(Clone, Debug)]
pub struct NoSplitting<K, D, A, G = Spheres> {
    c: Collider<K, D, A, G>,
    t: Real,
    refresh: RefreshWindow,
    frame: Frame,
    rescale_below: Real,
}

impl<K: Kernel, D: Drive, A: CollisionMap> NoSplitting<K, D, A> {
    /// Starts the scheme at time `t0` on the particles `p` (already holding the initial
    /// velocities): sets every last-kick time to `t0` and `Umax = 2 max |v_i - V|`
    /// (GRW steps 1.1-1.4). Returns the observables at `t0`. A rough gas's `p` holds one spin
    /// per particle ([`EngineError::Spins`] otherwise). Spheres; disks:
    /// [`NoSplitting::start_in`].
    pub fn start(
        kernel: K,
        drive: D,
        restitution: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        Self::start_in(kernel, drive, restitution, p, t0)
    }
}

impl<K: Kernel, D: Drive, A: CollisionMap, G: Geometry> NoSplitting<K, D, A, G> {
    /// As [`NoSplitting::start`] in dimension `G` (named by the result's type).
    // Out of line: called once per run, and the dispatch above it stays small.
    #[inline(never)]
    pub fn start_in(
        kernel: K,
        drive: D,
        restitution: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        super::open(p, t0, A::SPINS)?;
        let mut s = NoSplitting {
            c: Collider::new(kernel, drive, restitution),
            t: t0,
            refresh: RefreshWindow::new(p.len()),
            frame: Frame::IDENTITY,
            rescale_below: RESCALE_BELOW,
        };
        let obs = s.synchronized(p)?;
        Ok((s, obs))
    }

    /// Current time of the system.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]).
    pub fn work_rate(&self, n: usize) -> Real {
        self.c.work_rate(n, self.frame.scale, self.frame.offset)
    }

    /// Current majorant of the relative speed (0 for kernels that need none).
    pub fn umax(&self) -> Real {
        self.c.maj.umax
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.c.counts
    }

    /// The kernel.
    pub fn kernel(&self) -> &K {
        &self.c.kernel
    }

    /// The collision map (a restitution law, or the rough map).
    pub fn map(&self) -> &A {
        &self.c.map
    }

    /// A rough gas's rotational observables now (the particles at the current time, as after
    /// [`Self::advance_to`]); `None` for smooth particles.
    pub fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
        self.c.map.rough(p, self.frame.scale, G::CHOICE)
    }

    /// Runs the process to time `t_end >= time()`, kicks every particle to `t_end` and returns
    /// the observables there (GRW steps 2-3, RW Algorithm 3).
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
        run_events(self, p, t_end, rng)?;
        self.t = t_end;
        self.c
            .drive
            .kick_all_counting(p, t_end, rng, &mut self.c.counts.background);
        self.synchronized(p)
    }

    /// Re-synchronizes after the caller changed velocities between calls: every last-kick time
    /// becomes the current time and `V`, `Umax` are recomputed. Returns the observables.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        // The caller's velocities are physical (a rough gas's spins are left as stored).
        let back = self.frame.reset(p, A::SPINS);
        if !D::ACTS {
            // Only a gas with no drive is ever stored rescaled.
            self.c.map = self.c.map.stored_map(back);
        }
        p.reset_kick_times(self.t);
        self.synchronized(p)
    }

    /// Observables of the synchronized system (in physical units); refreshes `V` and `Umax`,
    /// checks a rough gas's spins, and rescales a cooling gas whose stored temperature fell
    /// below the threshold.
    fn synchronized(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        let d = G::CHOICE.d();
        let mut obs = observables_dim(p, d)?;
        if A::SPINS {
            spins_finite(p)?;
        }
        if D::ACTS {
            // A driven gas is never stored rescaled.
        } else if let Some(f) = self
            .frame
            .rescale(p, &mut obs, self.rescale_below, d, A::SPINS)
        {
            self.c.counts.rescales += 1;
            self.c.map = self.c.map.stored_map(f);
        }
        self.c.synchronized(&obs);
        let obs = self.frame.observables(&obs, d);
        if D::ACTS {
            // A driven gas is never stored rescaled: its `v6` is the central moments' (and no
            // code for the sum is built into a driven engine: the micro:bit's 64 KiB).
            return Ok(obs);
        }
        // `v6` of a gas stored rescaled summed from the physical velocities here, at every
        // synchronization (the start of a continuation's cooling gas included: it was NaN
        // there, issue 77).
        Ok(self.frame.with_raw_v6(p.as_slice(), obs))
    }

    /// Sets the stored temperature below which a gas with no drive is rescaled (default
    /// [`RESCALE_BELOW`]; 0 never rescales).
    pub fn set_rescale_below(&mut self, t: Real) {
        self.rescale_below = t;
    }

    /// The map from stored to physical velocities, `v_phys = offset + scale v` (identity unless
    /// a cooling gas was rescaled).
    pub fn velocity_map(&self) -> Frame {
        self.frame
    }
}

/// Every rim velocity finite, or the error naming them.
pub(crate) fn spins_finite(p: &Particles<'_>) -> Result<(), EngineError> {
    if p.spins()
        .iter()
        .all(|s| s.rim_velocity().norm2().is_finite())
    {
        Ok(())
    } else {
        Err(EngineError::NonFinite("a rim velocity"))
    }
}

/// A gas with no drive re-synchronized within a run by the light pass ([`crate::batch::sync`]):
/// `Umax = 2 max |v_i - vref|` about the majorant's reference (the last bulk velocity: the
/// momentum is conserved, and the bound is as exact about any reference); kernels with no
/// `Umax` move the reference to the bulk for the next pass. False, changing nothing, when the
/// cooling gas's rescale is due (the caller then synchronizes in full).
pub(crate) fn light_resync<K: Kernel>(
    p: &Particles<'_>,
    maj: &mut Majorant,
    d: usize,
    below: Real,
) -> Result<bool, EngineError> {
    let vref = maj.vref;
    let sums = sync_sums(p.as_slice(), vref);
    let (bulk, t_bulk) = checked_sync(&sums, vref, d)?;
    if rescale_due(t_bulk, bulk, below) {
        return Ok(false);
    }
    *maj = Majorant::new(2.0 * sqrt(sums.max2), vref);
    if !K::USES_UMAX {
        maj.vref = bulk;
    }
    Ok(true)
}

/// The bulk velocity and the temperature of a synchronization's light sums about `vref`, or
/// the error naming the first that is not finite (as [`super::event::observables`] would).
pub(crate) fn checked_sync(
    sums: &SyncSums,
    vref: Vec3,
    d: usize,
) -> Result<(Vec3, Real), EngineError> {
    let (bulk, t_bulk) = (sums.bulk(vref), sums.t_bulk(d));
    if !bulk.is_finite() {
        return Err(EngineError::NonFinite("the bulk velocity V"));
    }
    if !(t_bulk.is_finite() && sums.max2.is_finite()) {
        return Err(EngineError::NonFinite("T_bulk"));
    }
    Ok((bulk, t_bulk))
}

impl<K: Kernel, D: Drive, A: CollisionMap, G: Geometry> Jumps for NoSplitting<K, D, A, G> {
    const ACTS: bool = D::ACTS;
    const USES_UMAX: bool = K::USES_UMAX;

    #[inline(always)]
    fn rate(&mut self, n: usize) -> Real {
        self.c.rate(n, self.frame.scale)
    }
    #[inline(always)]
    fn bound(&self) -> Real {
        self.frame.scale * self.c.maj.umax
    }
    jumps_state!(t, refresh, c.counts);
    fn kick_all<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        self.c
            .drive
            .kick_all_counting(p, t, rng, &mut self.c.counts.background);
    }
    fn resynchronize(&mut self, p: &mut Particles<'_>) -> Result<(), EngineError> {
        if !D::ACTS && light_resync::<K>(p, &mut self.c.maj, G::CHOICE.d(), self.rescale_below)? {
            return if A::SPINS { spins_finite(p) } else { Ok(()) };
        }
        self.synchronized(p)?;
        self.c.counts.observations -= 1;
        Ok(())
    }
    #[inline(always)]
    fn step<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        t: Real,
        accept: Real,
        rng: &mut R,
    ) -> bool {
        let (i, j) = self.c.kicked_pair(p, t, rng);
        self.c.candidate(p, i, j, D::ACTS, accept, rng)
    }
    #[inline(always)]
    fn collide<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        let (i, j) = self.c.kicked_pair(p, t, rng);
        let v = (p.velocity(i), p.velocity(j));
        self.c
            .map
            .collide_pair::<K, G, R>(p, (i, j), v, rng, &mut self.c.counts);
        self.c.counts.candidates += 1;
        self.c.counts.collisions += 1;
    }
}

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<K: Kernel, D: Drive, A: CollisionMap + crate::engine::collision_map::Inertia, G: Geometry>
    NoSplitting<K, D, A, G>
{
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs
    /// ([`crate::engine::EventLoop::cooling`]).
    pub fn cooling<R: Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        crate::engine::collision_map::one_species_cooling::<K, G, A, R>(
            (&self.c.kernel, &self.c.map, self.frame.scale),
            p,
            pairs,
            rng,
        )
    }
}
