//! The exact no-splitting loop of a rough gas: GRW Section 3's scheme with the rough map.
//!
//! Rotation does not enter the collision rate: a pair collides at the rate of its kernel in
//! the translational relative speed `|v_i - v_j|` (hard spheres: `|g . n|` over the impact
//! directions; Luding et al. 1998), so the majorant, the waiting times, the fictitious-collision
//! test and the refresh schedule are those of [`crate::engine::NoSplitting`] unchanged. An
//! accepted pair draws its impact direction `n` with density proportional to `n . u_hat` where
//! the pair approaches ([`super::impact_direction`]: the hard-sphere impact law; disks:
//! the impact parameter uniform, [`crate::geometry::Disks`]; for the Maxwell kernel
//! the same law at a constant rate, which with `beta = -1` is GRW (3) with a uniform
//! direction, so the smooth gas is recovered in law) and applies [`RoughMap::collide`]
//! (Huthmann and Zippelius 1997). Both partners are kicked lazily from their last-kick times
//! ([`RoughDrive`]), translation and rotation together.
//!
//! A gas with no drive cools for ever; as in [`crate::engine::NoSplitting`] it is stored
//! rescaled when its translational temperature falls below
//! [`crate::engine::nosplit::RESCALE_BELOW`]: `v_phys = offset + scale v`, `w_phys = scale w`.
//! The map is linear in `(v, w)` together and the acceptance depends on ratios, so the stored
//! system follows the same rules at the majorant rate times `scale^lambda`.

use super::drive::RoughDrive;
use super::map::RoughMap;
use super::observables::RoughObservables;
use crate::engine::event::{Majorant, RefreshWindow, admits, observables_dim};
use crate::engine::jumps::{Jumps, jumps_state, run_events};
use crate::engine::nosplit::{RESCALE_BELOW, light_resync, rescale_due};
use crate::engine::pairs::PairsAhead;
use crate::engine::{Counts, EngineError};
use crate::geometry::{Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::{Real, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The exact event loop of a rough gas with kernel `K`, drive `D` and dimension `G` (rough
/// spheres unless named; disks: impact directions in the plane, rim velocities along `z`).
#[derive(Clone, Debug)]
pub struct RoughNoSplitting<K, D, G = Spheres> {
    kernel: K,
    drive: D,
    map: RoughMap,
    maj: Majorant,
    counts: Counts,
    pairs: PairsAhead,
    t: Real,
    refresh: RefreshWindow,
    scale: Real,
    offset: Vec3,
    dim: core::marker::PhantomData<G>,
}

impl<K: Kernel, D: RoughDrive> RoughNoSplitting<K, D> {
    /// Starts at `t0` on the particles and spins `p` (holding the initial velocities): every
    /// last-kick time becomes `t0` and `Umax = 2 max |v_i - V|` (GRW steps 1.1-1.4). Returns
    /// the translational observables at `t0`. Spheres; disks: [`RoughNoSplitting::start_in`].
    pub fn start(
        kernel: K,
        drive: D,
        map: RoughMap,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        Self::start_in(kernel, drive, map, p, t0)
    }
}

impl<K: Kernel, D: RoughDrive, G: Geometry> RoughNoSplitting<K, D, G> {
    /// As [`RoughNoSplitting::start`] in dimension `G` (named by the result's type).
    pub fn start_in(
        kernel: K,
        drive: D,
        map: RoughMap,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Self, Observables), EngineError> {
        if !t0.is_finite() {
            return Err(EngineError::TimeBackwards);
        }
        if !p.has_spins() {
            return Err(EngineError::Spins);
        }
        p.reset_kick_times(t0);
        let mut s = RoughNoSplitting {
            kernel,
            drive,
            map,
            maj: Majorant::default(),
            counts: Counts::default(),
            pairs: PairsAhead::default(),
            t: t0,
            refresh: RefreshWindow::new(p.len()),
            scale: 1.0,
            offset: Vec3::ZERO,
            dim: core::marker::PhantomData,
        };
        let obs = s.synchronized(p)?;
        Ok((s, obs))
    }

    /// Current time.
    pub fn time(&self) -> Real {
        self.t
    }

    /// Event counts so far.
    pub fn counts(&self) -> Counts {
        self.counts
    }

    /// Work units per unit time from here ([`crate::engine::EventLoop::work_rate`]): the
    /// majorant's candidates (the rough drives act in closed form).
    pub fn work_rate(&self, n: usize) -> Real {
        self.rate(n)
    }

    /// The collision map.
    pub fn map(&self) -> &RoughMap {
        &self.map
    }

    /// The map from stored to physical velocities (`w_phys = scale w`).
    pub fn velocity_map(&self) -> (Real, Vec3) {
        (self.scale, self.offset)
    }

    /// The rotational observables now (the particles must be at the current time, as they are
    /// after [`Self::advance_to`]).
    pub fn rough(&self, p: &Particles<'_>) -> RoughObservables {
        RoughObservables::of_dim(p, self.map.kappa(), self.scale, G::CHOICE)
    }

    #[inline(always)]
    fn rate(&self, n: usize) -> Real {
        self.kernel.majorant_rate(n, self.scale * self.maj.umax)
    }

    #[inline(always)]
    fn kick<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, i: usize, t: Real, rng: &mut R) {
        if !D::ACTS {
            return;
        }
        let dt = t - p.kick_time(i);
        if dt > 0.0 {
            let (v, w) = self.drive.evolve::<G, R>(p.velocity(i), p.spin(i), dt, rng);
            p.set_velocity(i, v);
            p.set_spin(i, w);
            p.get_mut(i).t_kick = t;
        }
    }

    fn kick_all<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        if D::ACTS {
            for i in 0..p.len() {
                self.kick(p, i, t, rng);
            }
        }
    }

    /// Runs the process to `t_end >= time()`, kicks every particle to `t_end` and returns the
    /// translational observables there (GRW steps 2-3).
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
        self.kick_all(p, t_end, rng);
        self.synchronized(p)
    }

    /// A candidate pair at the event time: the fictitious-collision test against the majorant
    /// that generated the event (GRW (20)), else an impact direction and the rough map; the
    /// majorant covers the new velocities. True when the majorant changed.
    #[inline(always)]
    fn candidate<R: Rng + ?Sized>(
        &mut self,
        p: &mut Particles<'_>,
        i: usize,
        j: usize,
        rng: &mut R,
    ) -> bool {
        let (vi, vj) = (p.velocity(i), p.velocity(j));
        let umax_event = self.maj.umax;
        let (maj, counts) = (&mut self.maj, &mut self.counts);
        if !admits(&self.kernel, maj, counts, vi, vj, D::ACTS, rng) {
            return self.maj.umax != umax_event;
        }
        let nrm = G::impact(vi - vj, rng);
        let (a, wa, b, wb) = self.map.collide(vi, p.spin(i), vj, p.spin(j), nrm);
        p.set_velocity(i, a);
        p.set_spin(i, wa);
        p.set_velocity(j, b);
        p.set_spin(j, wb);
        self.counts.collisions += 1;
        if K::USES_UMAX {
            self.maj.cover(a);
            self.maj.cover(b);
        }
        self.maj.umax != umax_event
    }

    /// Re-synchronizes after the caller replaced the velocities between calls (they are
    /// physical; the spins are left as stored and converted to physical units here): every
    /// last-kick time becomes the current time; `V`, `Umax` recomputed.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        if self.scale != 1.0 {
            for w in p.spins_mut() {
                *w = crate::particles::Spin::new(self.scale * w.rim_velocity());
            }
        }
        (self.scale, self.offset) = (1.0, Vec3::ZERO);
        p.reset_kick_times(self.t);
        self.synchronized(p)
    }

    /// Observables of the synchronized system (physical units): refreshes `V` and `Umax`,
    /// checks the spins, and rescales a cooling gas whose stored temperature fell below the
    /// threshold (module docs).
    fn synchronized(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        let d = G::CHOICE.d();
        let mut obs = observables_dim(p, d)?;
        spins_finite(p)?;
        if !D::ACTS && rescale_due(obs.t_bulk, obs.bulk, RESCALE_BELOW) {
            let s = 1.0 / sqrt(obs.t_bulk);
            for q in p.as_mut_slice() {
                let v = q.velocity();
                q.set_velocity(s * (v - obs.bulk));
            }
            for w in p.spins_mut() {
                *w = crate::particles::Spin::new(s * w.rim_velocity());
            }
            self.offset += self.scale * obs.bulk;
            self.scale /= s;
            self.counts.rescales += 1;
            obs = Observables::of_dim(p, d);
        }
        self.counts.observations += 1;
        if K::USES_UMAX {
            self.maj = Majorant::new(2.0 * obs.max_peculiar_speed, obs.bulk);
        }
        Ok(obs.in_units_dim(self.scale, self.offset, d))
    }
}

/// Every rim velocity finite, or the error naming them.
fn spins_finite(p: &Particles<'_>) -> Result<(), EngineError> {
    if p.spins()
        .iter()
        .all(|s| s.rim_velocity().norm2().is_finite())
    {
        Ok(())
    } else {
        Err(EngineError::NonFinite("a rim velocity"))
    }
}

crate::engine::impl_event_loop!(
    RoughNoSplitting,
    [K: Kernel, D: RoughDrive, G: Geometry],
    RoughNoSplitting<K, D, G>,
    {
        fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
            Some(RoughNoSplitting::rough(self, p))
        }
    }
);

impl<K: Kernel, D: RoughDrive, G: Geometry> Jumps for RoughNoSplitting<K, D, G> {
    const ACTS: bool = D::ACTS;
    const USES_UMAX: bool = K::USES_UMAX;

    #[inline(always)]
    fn rate(&mut self, n: usize) -> Real {
        RoughNoSplitting::rate(self, n)
    }
    #[inline(always)]
    fn bound(&self) -> Real {
        self.scale * self.maj.umax
    }
    jumps_state!(t, refresh, counts);
    fn kick_all<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) {
        RoughNoSplitting::kick_all(self, p, t, rng);
    }
    /// With no drive, one light pass as the smooth loop's
    /// ([`crate::engine::NoSplitting`]'s module docs), and the spins' finiteness; the full
    /// synchronization when the rescale is due or with a drive.
    fn resynchronize(&mut self, p: &mut Particles<'_>) -> Result<(), EngineError> {
        if !D::ACTS && light_resync::<K>(p, &mut self.maj, G::CHOICE.d(), RESCALE_BELOW)? {
            return spins_finite(p);
        }
        self.synchronized(p)?;
        self.counts.observations -= 1;
        Ok(())
    }
    #[inline(always)]
    fn step<R: Rng + ?Sized>(&mut self, p: &mut Particles<'_>, t: Real, rng: &mut R) -> bool {
        let (i, j) = self.pairs.next(p, rng);
        self.kick(p, i, t, rng);
        self.kick(p, j, t, rng);
        self.candidate(p, i, j, rng)
    }
}
