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
//! A gas with no drive cools for ever (the homogeneous cooling state). Its peculiar velocities,
//! stored beside a bulk velocity `V`, would lose digits (and stop at a rounding floor near
//! `T ~ (1e-16 |V|)^2`), and its temperature would underflow. So that it can be followed for as
//! long as asked, when at a synchronization (every `2n` candidates) its temperature has fallen
//! below `1e-8 max(1, |V|^2)` ([`RESCALE_BELOW`]), the velocities are stored rescaled:
//! `v_phys = offset + scale v`, the stored peculiar velocities at unit temperature. The collision maps are linear and the fictitious-collision
//! test depends on ratios only, so the stored system evolves by the same rules, with the
//! physical majorant rate `scale^lambda` times the stored one: time is not rescaled, the event
//! rate is. Observables are returned in physical units, `log10_t_bulk` included, which stays
//! finite where the temperature itself would underflow ([`Counts::rescales`]).
//!
//! For Maxwell pseudo-molecules the majorant is the kernel itself: no `Umax`, no fictitious
//! collisions, and none of that bookkeeping is compiled in.

use super::event::{Collider, Majorant, RefreshWindow, observables_dim};
use super::jumps::{Jumps, jumps_state, run_events};
use super::{Counts, EngineError};
use crate::batch::sync::{SyncSums, sync_sums};
use crate::drive::Drive;
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{Real, max, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::Restitution;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The exact (no-splitting) event loop for kernel `K`, drive `D`, restitution law `A` and
/// dimension `G` (spheres unless named; disks: [`crate::geometry::Disks`], whose drive acts in
/// the plane).
#[derive(Clone, Debug)]
pub struct NoSplitting<K, D, A, G = Spheres> {
    c: Collider<K, D, A, G>,
    t: Real,
    refresh: RefreshWindow,
    scale: Real,
    offset: Vec3,
    rescale_below: Real,
}

/// A gas with no drive is rescaled when its stored temperature falls below this times
/// `max(1, |V|^2)` (stored units): the peculiar velocities then still carry 12 of their 16
/// digits beside the bulk velocity (module docs).
pub const RESCALE_BELOW: Real = 1e-8;

impl<K: Kernel, D: Drive, A: Restitution> NoSplitting<K, D, A> {
    /// Starts the scheme at time `t0` on the particles `p` (already holding the initial
    /// velocities): sets every last-kick time to `t0` and `Umax = 2 max |v_i - V|`
    /// (GRW steps 1.1-1.4). Returns the observables at `t0`. Spheres; disks:
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

impl<K: Kernel, D: Drive, A: Restitution, G: Geometry> NoSplitting<K, D, A, G> {
    /// As [`NoSplitting::start`] in dimension `G` (named by the result's type).
    pub fn start_in(
        kernel: K,
        drive: D,
        restitution: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        if !t0.is_finite() {
            return Err(EngineError::TimeBackwards);
        }
        p.reset_kick_times(t0);
        let mut s = NoSplitting {
            c: Collider::new(kernel, drive, restitution),
            t: t0,
            refresh: RefreshWindow::new(p.len()),
            scale: 1.0,
            offset: Vec3::ZERO,
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
        self.c.work_rate(n, self.scale, self.offset)
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
        let obs = self.synchronized(p)?;
        Ok(self.with_raw_v6(p, obs))
    }

    /// `<|v|^6>` of a gas stored rescaled about a bulk velocity cannot be rebuilt from the
    /// central moments ([`Observables::in_units`] leaves it NaN); at an observation it is
    /// summed directly from the physical velocities `offset + scale v` (their peculiar parts
    /// are below the bulk's last digits there, so this is as accurate as the sum can be).
    /// Only a gas with no drive is ever stored rescaled.
    fn with_raw_v6(&self, p: &Particles<'_>, obs: Observables) -> Observables {
        if D::ACTS {
            return obs;
        }
        with_raw_v6(p, obs, self.scale, self.offset)
    }

    /// Re-synchronizes after the caller changed velocities between calls: every last-kick time
    /// becomes the current time and `V`, `Umax` are recomputed. Returns the observables.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        // The caller's velocities are physical.
        (self.scale, self.offset) = (1.0, Vec3::ZERO);
        p.reset_kick_times(self.t);
        self.synchronized(p)
    }

    /// Observables of the synchronized system (in physical units); refreshes `V` and `Umax`,
    /// and rescales a cooling gas whose stored temperature fell below the threshold.
    fn synchronized(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        let d = G::CHOICE.d();
        let mut obs = observables_dim(p, d)?;
        if !D::ACTS
            && rescale(
                p,
                &mut obs,
                self.rescale_below,
                &mut self.scale,
                &mut self.offset,
                d,
            )
        {
            self.c.counts.rescales += 1;
        }
        self.c.synchronized(&obs);
        Ok(obs.in_units_dim(self.scale, self.offset, d))
    }

    /// Sets the stored temperature below which a gas with no drive is rescaled (default
    /// [`RESCALE_BELOW`]; 0 never rescales).
    pub fn set_rescale_below(&mut self, t: Real) {
        self.rescale_below = t;
    }

    /// The map from stored to physical velocities, `v_phys = offset + scale v` (identity unless
    /// a cooling gas was rescaled).
    pub fn velocity_map(&self) -> (Real, Vec3) {
        (self.scale, self.offset)
    }
}

/// Stores a cooling gas rescaled (module docs) when its temperature `obs.t_bulk` (stored
/// units) has fallen below `below` times `max(1, |V|^2)`: `v_phys = offset + scale v`, the
/// stored peculiar velocities at unit temperature; `obs` becomes the stored system's (in `d`
/// dimensions). True when it rescaled.
pub(crate) fn rescale(
    p: &mut Particles<'_>,
    obs: &mut Observables,
    below: Real,
    scale: &mut Real,
    offset: &mut Vec3,
    d: usize,
) -> bool {
    if !rescale_due(obs.t_bulk, obs.bulk, below) {
        return false;
    }
    let s = 1.0 / sqrt(obs.t_bulk);
    for q in p.as_mut_slice() {
        let v = q.velocity();
        q.set_velocity(s * (v - obs.bulk));
    }
    *offset += *scale * obs.bulk;
    *scale /= s;
    *obs = Observables::of_dim(p, d);
    true
}

/// Whether a gas with no drive at temperature `t_bulk` about the bulk velocity `bulk` (stored
/// units) is due to be stored rescaled: below `below` times `max(1, |V|^2)` (module docs).
pub(crate) fn rescale_due(t_bulk: Real, bulk: Vec3, below: Real) -> bool {
    t_bulk > 0.0 && t_bulk < below * max(1.0, bulk.norm2())
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

/// `<|v|^6>` of a gas stored rescaled about a bulk velocity cannot be rebuilt from the central
/// moments ([`Observables::in_units`] leaves it NaN): summed directly from the physical
/// velocities `offset + scale v` at an observation.
pub(crate) fn with_raw_v6(
    p: &Particles<'_>,
    mut obs: Observables,
    scale: Real,
    offset: Vec3,
) -> Observables {
    if obs.v6.is_nan() && offset != Vec3::ZERO {
        let mut s = 0.0;
        for q in p.as_slice() {
            let v2 = (offset + scale * q.velocity()).norm2();
            s += v2 * v2 * v2;
        }
        obs.v6 = s / p.len() as Real;
    }
    obs
}

impl<K: Kernel, D: Drive, A: Restitution, G: Geometry> Jumps for NoSplitting<K, D, A, G> {
    const ACTS: bool = D::ACTS;
    const USES_UMAX: bool = K::USES_UMAX;

    #[inline(always)]
    fn rate(&mut self, n: usize) -> Real {
        self.c.rate(n, self.scale)
    }
    #[inline(always)]
    fn bound(&self) -> Real {
        self.scale * self.c.maj.umax
    }
    jumps_state!(t, refresh, c.counts);
    fn kick_all<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        self.c
            .drive
            .kick_all_counting(p, t, rng, &mut self.c.counts.background);
    }
    fn resynchronize(&mut self, p: &mut Particles<'_>) -> Result<(), EngineError> {
        if !D::ACTS && light_resync::<K>(p, &mut self.c.maj, G::CHOICE.d(), self.rescale_below)? {
            return Ok(());
        }
        self.synchronized(p)?;
        self.c.counts.observations -= 1;
        Ok(())
    }
    #[inline(always)]
    fn step<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) -> bool {
        let (i, j) = self.c.pairs.next(p, rng);
        self.c
            .drive
            .kick_counting(p, i, t, rng, &mut self.c.counts.background);
        self.c
            .drive
            .kick_counting(p, j, t, rng, &mut self.c.counts.background);
        self.c.candidate(p, i, j, D::ACTS, rng)
    }
}
