//! The one dispatch from a validated [`Model`] to the statically composed [`Engine`]: one
//! `match` per level (kernel, drive, restitution law, scheme), each level generic over the
//! choices above it, so that every leaf is a monomorphized event loop. An engine a build
//! leaves out (gdsmc-core's features: the families `mixtures`, `rough`, `disks`; each kernel,
//! drive, the impact-speed law, the splitting and time-stepped schemes) is refused here with
//! [`EngineError::NotBuilt`] naming the feature, and its builders are then unused.
#![cfg_attr(
    not(feature = "full"),
    allow(dead_code, unused_imports, unused_variables)
)]

use super::axes::kernel_table;
use super::build::{Begun, Build, MixtureBuild, RoughBuild, SmoothBuild, built, wrap};
use super::engine::{ByDrive, ByKernel, ByLaw, Engine, RoughPairs, SmoothPairs};
use super::kinds::declared_drives;
use super::model::Model;
use super::momentum::{Momentum, set_mean};
use super::parts::{DriveModel, KernelModel, LawModel};
use crate::drive::{Drive, NoDrive};
use crate::engine::EngineError;
use crate::geometry::{DimensionChoice, Disks, Spheres};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::{Particle, Particles, Spin};
use crate::rng::Xoshiro256PlusPlus;
use crate::vec3::Vec3;
use core::marker::PhantomData;

impl Model {
    /// Draws every particle's velocity from the initial distribution (one uniform for the
    /// component, then the Maxwellian; particle by particle), with [`Momentum::Exact`] shifts
    /// them (each species' sample) onto the distribution's mean, and sets its last-kick time to
    /// `t0`; rough particles' rim velocities come from the spin stream (`spin_stream`), so
    /// `rng` advances exactly as for smooth particles. Fails with
    /// [`EngineError::ParticleCount`] unless `p` holds `n` particles.
    pub fn initialize(
        &self,
        p: &mut Particles<'_>,
        t0: Real,
        rng: &mut Xoshiro256PlusPlus,
    ) -> Result<(), EngineError> {
        if p.len() != self.n() {
            return Err(EngineError::ParticleCount);
        }
        let disks = self.dimension == DimensionChoice::Two;
        if self.has_species() {
            let mx = self
                .mixture()
                .ok_or_else(|| EngineError::NotBuilt(self.mixture_features()))?;
            // Species by species, each from its own Maxwellian, in particle order (disks drop
            // the z components, as below).
            for s in 0..mx.species.len() {
                for q in &mut p.as_mut_slice()[mx.species.range(s)] {
                    let v = mx.starts[s].sample(rng);
                    *q = Particle::new(if disks { Vec3::new(v.x, v.y, 0.0) } else { v }, t0);
                }
                if self.momentum == Momentum::Exact {
                    let d = mx.starts[s].drift();
                    let target = if disks { Vec3::new(d.x, d.y, 0.0) } else { d };
                    set_mean(&mut p.as_mut_slice()[mx.species.range(s)], target);
                }
            }
            if let Some(r) = &mx.rotation {
                // The rim velocities species by species, from the spin stream.
                if !p.has_spins() {
                    return Err(EngineError::Spins);
                }
                let mut spins = spin_stream(rng);
                for s in 0..mx.species.len() {
                    for w in &mut p.spins_mut()[mx.species.range(s)] {
                        *w = Spin::new(planar_spin(r.starts[s].sample(&mut spins), disks));
                    }
                }
            }
            return Ok(());
        }
        let mut bad = false;
        // Weighted particles start with weight 1 each (the run's `n0` is `n`).
        p.reset_weights();
        p.fill_with(t0, || {
            // The weights were validated: a positive total, so sampling cannot fail.
            self.initial().sample(rng).unwrap_or_else(|_| {
                bad = true;
                Vec3::ZERO
            })
        });
        if bad {
            return Err(EngineError::NonFinite("an initial velocity"));
        }
        if disks {
            // A Maxwellian's projection on the plane is the Maxwellian of disks at the same
            // temperature (the components are independent): the z components are dropped.
            for q in p.as_mut_slice() {
                q.vz = 0.0;
            }
        }
        if self.momentum == Momentum::Exact {
            // The drifts lie in the plane for disks (validated), so the mean is the plane's.
            set_mean(p.as_mut_slice(), self.initial().mean());
        }
        if let Some(r) = &self.rough {
            // The rim velocities from their own Maxwellian (disks keep its z component, their
            // one rotational degree of freedom), drawn from the spin stream.
            if !p.has_spins() {
                return Err(EngineError::Spins);
            }
            let mut spins = spin_stream(rng);
            for s in p.spins_mut() {
                *s = Spin::new(planar_spin(r.start.sample(&mut spins), disks));
            }
        }
        Ok(())
    }

    /// Starts the statically composed engine of this physics at `t0` on `p` (which holds the
    /// initial velocities): the one dispatch from the description to the event loop. Returns
    /// the engine and the observables at `t0`.
    pub fn start(
        &self,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(Engine, Observables), EngineError> {
        if p.len() != self.n() {
            return Err(EngineError::ParticleCount);
        }
        let k = self.kernel;
        if self.has_species() {
            let mx = self
                .mixture()
                .ok_or_else(|| EngineError::NotBuilt(self.mixture_features()))?;
            return match (&mx.rotation, self.dimension) {
                (None, DimensionChoice::Three) => {
                    built!(feature = "mixtures", self.mixture_features(), {
                        let b = MixtureBuild::<Spheres, SmoothPairs>::smooth(mx, self);
                        wrap(by_kernel(k, &b, p, t0), Engine::Mixture)
                    })
                }
                (None, DimensionChoice::Two) => built!(
                    all(feature = "mixtures", feature = "disks"),
                    self.mixture_features(),
                    {
                        let b = MixtureBuild::<Disks, SmoothPairs>::smooth(mx, self);
                        wrap(by_kernel(k, &b, p, t0), Engine::DiskMixture)
                    }
                ),
                (Some(r), DimensionChoice::Three) => built!(
                    all(feature = "mixtures", feature = "rough"),
                    self.mixture_features(),
                    {
                        let b = MixtureBuild::<Spheres, RoughPairs>::rough(mx, r, self);
                        wrap(by_kernel(k, &b, p, t0), Engine::RoughMixture)
                    }
                ),
                (Some(r), DimensionChoice::Two) => built!(
                    all(feature = "mixtures", feature = "rough", feature = "disks"),
                    self.mixture_features(),
                    {
                        let b = MixtureBuild::<Disks, RoughPairs>::rough(mx, r, self);
                        wrap(by_kernel(k, &b, p, t0), Engine::RoughDiskMixture)
                    }
                ),
            };
        }
        match (&self.rough, self.dimension) {
            (Some(r), DimensionChoice::Three) => built!(feature = "rough", "rough", {
                let b = RoughBuild::<Spheres>(r, self, PhantomData);
                wrap(by_kernel(k, &b, p, t0), Engine::Rough)
            }),
            (Some(r), DimensionChoice::Two) => built!(
                all(feature = "rough", feature = "disks"),
                "rough` and `disks",
                {
                    let b = RoughBuild::<Disks>(r, self, PhantomData);
                    wrap(by_kernel(k, &b, p, t0), Engine::RoughDisks)
                }
            ),
            (None, DimensionChoice::Two) => built!(feature = "disks", "disks", {
                let b = SmoothBuild::<Disks>(self, PhantomData);
                wrap(by_kernel(k, &b, p, t0), Engine::Disks)
            }),
            (None, DimensionChoice::Three) => {
                let b = SmoothBuild::<Spheres>(self, PhantomData);
                wrap(by_kernel(k, &b, p, t0), Engine::Smooth)
            }
        }
    }

    /// [`Model::initialize`] then [`Model::start`].
    pub fn launch(
        &self,
        p: &mut Particles<'_>,
        t0: Real,
        rng: &mut Xoshiro256PlusPlus,
    ) -> Result<(Engine, Observables), EngineError> {
        self.initialize(p, t0, rng)?;
        self.start(p, t0)
    }

    /// The cargo features a mixture's engine family needs (by rotation and dimension): the name
    /// a build without them refuses it with.
    fn mixture_features(&self) -> &'static str {
        match (self.rotates(), self.dimension) {
            (false, DimensionChoice::Three) => "mixtures",
            (false, DimensionChoice::Two) => "mixtures` and `disks",
            (true, DimensionChoice::Three) => "mixtures` and `rough",
            (true, DimensionChoice::Two) => "mixtures`, `rough` and `disks",
        }
    }
}

/// Generates [`by_kernel`] from the kernel table ([`kernel_table`]).
macro_rules! by_kernel {
    ($($v:ident($code:literal, $scene:literal, $t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
        /// The one kernel level of the dispatch, for every family (generated from the kernel
        /// table, [`super::axes`]). Out of line: each family's start keeps its locals (a
        /// mixture's pair table, its per-species observables) in its own frame, not in
        /// [`Model::start`]'s for every physics.
        #[inline(never)]
        fn by_kernel<B: Build>(
            kernel: KernelModel,
            b: &B,
            p: &mut Particles<'_>,
            t0: Real,
        ) -> Begun<ByKernel<B::F>> {
            match kernel {
                $(KernelModel::$v(k) => built!(feature = $feature, $feature, {
                    wrap(by_drive(b, k, p, t0), ByKernel::$v)
                }),)*
            }
        }
    };
}
kernel_table!(by_kernel);

/// Generates [`by_drive`] from the declared drives' table ([`declared_drives`]).
macro_rules! by_drive {
    ($($v:ident($t:ty, $feature:literal)),* $(,)?) => {
        /// The one drive level of the dispatch, for every family and kernel (the declared
        /// drives' arms generated from their table, `physics/kinds.rs`). Out of line for the
        /// reason of [`by_kernel`] (a mixture's drives are one per species).
        #[inline(never)]
        fn by_drive<B: Build, K: Kernel>(
            b: &B,
            k: K,
            p: &mut Particles<'_>,
            t0: Real,
        ) -> Begun<ByDrive<B::F, K>> {
            // White noise first: a rough gas's noise on rotation alone has no drive on
            // translation.
            if let Some(n) = b.noise() {
                return built!(feature = "white-noise", "white-noise", {
                    wrap(by_law(b, k, &n, p, t0), ByDrive::WhiteNoise)
                });
            }
            // Validated: rotational noise takes no drive but white noise beside it.
            match b.model().drive {
                DriveModel::None => built!(feature = "cooling", "cooling", {
                    wrap(by_law(b, k, &b.each(NoDrive), p, t0), ByDrive::None)
                }),
                DriveModel::HostMaxwell(h) => built!(feature = "host-medium", "host-medium", {
                    wrap(by_law(b, k, &b.host(h)?, p, t0), ByDrive::HostMaxwell)
                }),
                DriveModel::HostHardSpheres(h) => built!(feature = "host-medium", "host-medium", {
                    wrap(by_law(b, k, &b.host(h)?, p, t0), ByDrive::HostHardSpheres)
                }),
                DriveModel::WhiteNoise(_) => {
                    Err(EngineError::Invariant("white noise is its family's noise"))
                }
                $(DriveModel::$v(d) => built!(feature = $feature, $feature, {
                    wrap(by_law(b, k, &b.place(d)?, p, t0), ByDrive::$v)
                }),)*
            }
        }
    };
}
declared_drives!(by_drive);

/// The one restitution-law level of the dispatch, for every family, kernel and drive.
fn by_law<B: Build, K: Kernel, D: Drive>(
    b: &B,
    k: K,
    d: &B::Drives<D>,
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<ByLaw<B::F, K, D>> {
    match b.model().law {
        LawModel::Constant(a) => wrap(b.scheme(k, d, a, p, t0), ByLaw::Constant),
        LawModel::ImpactSpeed(a) => built!(feature = "impact-speed", "impact-speed", {
            wrap(b.scheme(k, d, a, p, t0), ByLaw::ImpactSpeed)
        }),
    }
}

/// The generator of the initial rim velocities: the ensemble's generator `rng` long-jumped
/// (2^192 draws), a stretch no ensemble's collisions reach (ensemble `k` starts `k 2^128` draws
/// into the seed's sequence, [`crate::rng::stream`]). The spins leave `rng` where smooth
/// particles leave it, so a rough gas whose collisions leave the rotation alone (`beta = -1`)
/// has the smooth gas's bits.
#[must_use]
pub(crate) fn spin_stream(rng: &Xoshiro256PlusPlus) -> Xoshiro256PlusPlus {
    let mut s = rng.clone();
    s.long_jump();
    s
}

/// A rim velocity drawn in three dimensions as a disk's (its `z` component alone) or a
/// sphere's.
fn planar_spin(w: Vec3, disks: bool) -> Vec3 {
    if disks { Vec3::new(0.0, 0.0, w.z) } else { w }
}
