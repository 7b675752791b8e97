//! What the mixture's exact loop reports: every species synchronized (majorants made exact, a
//! cooling gas rescaled, each drive told), its observables in physical units with a rough
//! mixture's rotation.

use super::MixtureNoSplitting;
use crate::drive::Drive;
use crate::engine::EngineError;
use crate::engine::collision_map::CollisionMap;
use crate::engine::event::Majorant;
use crate::engine::frame::{Frame, RESCALE_BELOW};
use crate::geometry::Geometry;
use crate::kernel::Kernel;
use crate::mixture::drives::tell_drives;
use crate::mixture::map::PairLaw;
use crate::observe::MixtureObservables;
use crate::particles::Particles;

impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureNoSplitting<K, D, L, G> {
    /// Re-synchronizes after the caller changed velocities between calls (physical units):
    /// every last-kick time becomes the current time, the majorants are recomputed.
    pub fn resync(&mut self, p: &mut Particles<'_>) -> Result<MixtureObservables, EngineError> {
        // The caller's velocities are physical (a rough mixture's spins are left as stored).
        let back = self.frame.reset(p, L::Map::SPINS);
        if !D::ACTS {
            // Only a mixture with no drive is ever stored rescaled.
            self.stored_maps(back);
        }
        p.reset_kick_times(self.t);
        self.synchronized(p)
    }

    /// Every pair type's map in new stored units, `scale` times which are the old ones
    /// ([`CollisionMap::stored_map`]: an impact-speed law at the physical impact speed).
    fn stored_maps(&mut self, scale: crate::math::Real) {
        for m in &mut self.maps {
            *m = m.stored_map(scale);
        }
    }

    /// The map `v_phys = offset + scale v` from stored to physical velocities.
    pub fn velocity_map(&self) -> Frame {
        self.frame
    }

    /// Each species' observables of the synchronized particles `p` (right after an advance or
    /// a start), in physical units.
    pub fn species_now(&self, p: &Particles<'_>) -> MixtureObservables {
        let obs = MixtureObservables::of_dim(p.as_slice(), &self.sp, G::CHOICE);
        self.physical(p, obs)
    }
    /// Observables of the synchronized system (physical units); makes every species'
    /// majorant exact and rescales a cooling gas (as [`crate::engine::NoSplitting`] does).
    pub(super) fn synchronized(
        &mut self,
        p: &mut Particles<'_>,
    ) -> Result<MixtureObservables, EngineError> {
        let mut obs = MixtureObservables::of_dim(p.as_slice(), &self.sp, G::CHOICE);
        if let Some(what) = obs.all.non_finite() {
            return Err(EngineError::NonFinite(what));
        }
        if L::Map::SPINS {
            crate::engine::nosplit::spins_finite(p)?;
        }
        let mut all = obs.all;
        let d = G::CHOICE.d();
        let rescaled = if !D::ACTS && self.rescale {
            self.frame
                .rescale(p, &mut all, RESCALE_BELOW, d, L::Map::SPINS)
        } else {
            None
        };
        if let Some(f) = rescaled {
            self.counts.rescales += 1;
            self.stored_maps(f);
            obs = MixtureObservables::of_dim(p.as_slice(), &self.sp, G::CHOICE);
        }
        self.counts.observations += 1;
        tell_drives(&mut self.drives, &obs);
        for s in 0..self.sp.len() {
            if K::USES_UMAX {
                self.maj[s] = Majorant::about(&obs.species[s]);
            }
        }
        for k in 0..self.sp.pair_types() {
            let (s, t) = self.pair_of[k];
            self.apart[k] = if s == t {
                0.0
            } else {
                (obs.species[s].bulk - obs.species[t].bulk).norm()
            };
        }
        Ok(self.physical(p, obs))
    }

    /// The observables `obs` of the stored particles `p` in physical units, with a rough
    /// mixture's rotation.
    fn physical(&self, p: &Particles<'_>, obs: MixtureObservables) -> MixtureObservables {
        let obs = self.with_raw_v6(p, obs.in_units(self.frame.scale, self.frame.offset));
        if !L::Map::SPINS {
            return obs;
        }
        obs.with_rotation(
            p.as_slice(),
            p.spins(),
            &self.sp,
            &self.kappa,
            self.frame.scale,
        )
    }

    /// `<|v|^6>` of a gas stored rescaled about a bulk velocity, summed from the physical
    /// velocities (as [`crate::engine::NoSplitting`] does; [`crate::moments::Observables::in_units`]
    /// leaves it NaN).
    fn with_raw_v6(&self, p: &Particles<'_>, mut obs: MixtureObservables) -> MixtureObservables {
        if D::ACTS {
            return obs;
        }
        obs.all = self.frame.with_raw_v6(p.as_slice(), obs.all);
        for s in 0..self.sp.len() {
            obs.species[s] = self
                .frame
                .with_raw_v6(&p.as_slice()[self.sp.range(s)], obs.species[s]);
        }
        obs
    }
}

/// The collisional cooling ([`crate::engine::EventLoop::cooling`]).
impl<K: Kernel, D: Drive, L: PairLaw, G: Geometry> MixtureNoSplitting<K, D, L, G> {
    /// The collision frequency and `zeta*` of `p` now from `pairs` random pairs
    /// ([`crate::observe::cooling`]): each particle of its species' mass and `kappa`, each
    /// pair collided by its pair type's kernel and map, the lower species first as the loop
    /// collides them.
    pub fn cooling<R: crate::rng::Rng + ?Sized>(
        &self,
        p: &Particles<'_>,
        pairs: u64,
        rng: &mut R,
    ) -> crate::observe::Cooling {
        let sp = &self.sp;
        // Every particle is in one species' range (the ranges tile 0..n).
        let species = |i: usize| (0..sp.len()).find(|&s| sp.range(s).contains(&i));
        let of = |i: usize| species(i).unwrap_or(0);
        crate::observe::cooling::estimate(
            p,
            pairs,
            rng,
            |i| {
                let m = sp.mass(of(i));
                (m, m * self.kappa[of(i)])
            },
            |(i, j), s: &mut Particles<'_>, rng: &mut R| {
                let (si, sj) = (of(i), of(j));
                let k = sp.pair_index(si, sj);
                let (a, b) = if si <= sj { (0, 1) } else { (1, 0) };
                let (va, vb) = (s.velocity(a), s.velocity(b));
                self.maps[k].collide_pair::<K, G, R>(
                    s,
                    (a, b),
                    (va, vb),
                    rng,
                    &mut crate::engine::Counts::default(),
                );
                self.kernels[k].pair_rate(self.frame.scale * (va - vb).norm())
            },
        )
    }
}
