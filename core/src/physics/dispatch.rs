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
use super::engine::{
    ByDrive, ByKernel, ByLaw, ByMixtureScheme, ByScheme, BySplit, Engine, Family, HostIn, Mixture,
    PairModel, Rough, RoughPairs, Smooth, SmoothPairs,
};
use super::kinds::declared_drives;
use super::model::Model;
use super::parts::{DriveModel, KernelModel, LawModel, SchemeModel};
use super::rotation::{MixtureRotation, RoughModel};
use super::species::MixtureModel;
use super::{MAX_PAIRS, MAX_SPECIES};
use crate::drive::host_medium::BackgroundKernel;
use crate::drive::{Declared, Drive, HostMedium, NoDrive, WhiteNoiseIn};
use crate::engine::{
    CollisionMap, EngineError, NoSplitting, Splitting, SumNoSplitting, TimeStepped,
};
use crate::geometry::{DimensionChoice, Disks, Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::mixture::{
    MixtureNoSplitting, MixtureSplitting, MixtureTimeStepped, PairLaw, PairPhysics, StartError,
};
use crate::moments::Observables;
use crate::particles::{Particle, Particles, Spin};
use crate::restitution::{Constant, ImpactSpeed, Restitution};
use crate::rng::Xoshiro256PlusPlus;
use crate::rough::{RoughMap, RoughNoise};
use crate::vec3::Vec3;
use core::marker::PhantomData;

/// `$e` when the build holds the engine (`$on`, a cfg predicate on gdsmc-core's features),
/// else the refusal naming the feature: its loops are then not compiled.
macro_rules! built {
    ($on:meta, $name:expr, $e:expr) => {{
        #[cfg($on)]
        let r = $e;
        #[cfg(not($on))]
        let r = Err(EngineError::NotBuilt($name));
        r
    }};
}

impl Model {
    /// Draws every particle's velocity from the initial distribution (one uniform for the
    /// component, then the Maxwellian; particle by particle) and sets its last-kick time to
    /// `t0`; rough particles' rim velocities come from the spin stream ([`spin_stream`]), so
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

    fn by_scheme<K: Kernel, D: Drive, A: Restitution, G: Geometry>(
        &self,
        k: K,
        d: D,
        a: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Begun<ByScheme<K, D, A, G>> {
        match self.scheme {
            // Hard spheres with no drive: the sum-form majorant.
            SchemeModel::NoSplitting
                if !D::ACTS && K::HARD && self.sum_form && G::CHOICE == DimensionChoice::Three =>
            {
                built!(feature = "hard-spheres", "hard-spheres", {
                    let hs = k
                        .as_hard_spheres()
                        .ok_or(EngineError::Invariant("a hard kernel is hard spheres"))?;
                    wrap(SumNoSplitting::start(hs, a, p, t0), ByScheme::SumForm)
                })
            }
            _ => wrap(by_split(self.scheme, k, d, a, p, t0), ByScheme::Split),
        }
    }
}

/// The pair table of a mixture: kernel `k` scaled by each pair's cross section, each pair's
/// law from `laws`.
fn pair_table<K: Kernel, L: Copy>(
    mx: &MixtureModel,
    k: K,
    laws: &[L; MAX_PAIRS],
) -> Result<[PairPhysics<K, L>; MAX_PAIRS], EngineError> {
    let mut physics = [PairPhysics {
        kernel: k,
        restitution: laws[0],
    }; MAX_PAIRS];
    for (j, pair) in physics.iter_mut().enumerate().take(mx.species.pair_types()) {
        // Validated: every scaled kernel exists.
        pair.kernel = k
            .scaled(mx.factors[j])
            .map_err(|_| EngineError::Invariant("every scaled pair kernel exists"))?;
        pair.restitution = laws[j];
    }
    Ok(physics)
}

/// Starts a mixture loop of dimension `G` with the pair table `physics` and one drive per
/// species from `drives`: the exact loop, a splitting of it, or the time-stepped scheme.
fn start_mixture<K: Kernel, D: Drive, L: PairLaw, G: Geometry>(
    mx: &MixtureModel,
    scheme: SchemeModel,
    physics: &[PairPhysics<K, L>; MAX_PAIRS],
    drives: &[D; MAX_SPECIES],
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<ByMixtureScheme<K, D, L, G>> {
    let sp = mx.species;
    let (physics, drives) = (&physics[..sp.pair_types()], &drives[..sp.len()]);
    match scheme {
        SchemeModel::Splitting(order, dt) => built!(feature = "splitting", "splitting", {
            wrap(
                started(MixtureSplitting::start(
                    sp, physics, drives, order, dt, p, t0,
                )),
                ByMixtureScheme::Splitting,
            )
        }),
        SchemeModel::TimeStepped(f) => built!(feature = "time-stepped", "time-stepped", {
            wrap(
                started(MixtureTimeStepped::start(sp, physics, drives, f, p, t0)),
                ByMixtureScheme::TimeStepped,
            )
        }),
        SchemeModel::NoSplitting => wrap(
            started(MixtureNoSplitting::start_in(sp, physics, drives, p, t0)),
            ByMixtureScheme::NoSplitting,
        ),
    }
}

/// The host medium `h` in dimension `G` as each species of `mx` meets it, with its own mass
/// ([`HostMediumParams::for_grain`](crate::drive::HostMediumParams::for_grain)).
fn species_hosts<B: BackgroundKernel, G: Geometry>(
    mx: &MixtureModel,
    h: HostMedium<B>,
) -> Result<[HostMedium<B, G>; MAX_SPECIES], EngineError> {
    let sp = &mx.species;
    let mut hosts = [h.in_dim::<G>(); MAX_SPECIES];
    for (s, host) in hosts.iter_mut().enumerate().take(sp.len()) {
        // Validated: every species' mass is finite and positive.
        host.params = h
            .params
            .for_grain(sp.mass(s))
            .ok_or(EngineError::Invariant("a species' mass is positive"))?;
    }
    Ok(hosts)
}

/// An engine started, with its observables at the start.
type Begun<E> = Result<(E, Observables), EngineError>;

/// The scheme level every family but the mixtures shares: the exact loop, a splitting or MS's
/// time-stepped scheme (smooth spheres' sum form is [`Model::by_scheme`]'s).
fn by_split<K: Kernel, D: Drive, A: CollisionMap, G: Geometry>(
    scheme: SchemeModel,
    k: K,
    d: D,
    a: A,
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<BySplit<K, D, A, G>> {
    match scheme {
        SchemeModel::NoSplitting => {
            wrap(NoSplitting::start_in(k, d, a, p, t0), BySplit::NoSplitting)
        }
        SchemeModel::Splitting(order, dt) => built!(feature = "splitting", "splitting", {
            wrap(
                Splitting::start(k, d, a, order, dt, p, t0),
                BySplit::Splitting,
            )
        }),
        SchemeModel::TimeStepped(f) => built!(feature = "time-stepped", "time-stepped", {
            wrap(TimeStepped::start(k, d, a, f, p, t0), BySplit::TimeStepped)
        }),
    }
}

/// What builds one family's engine: the family's part of each level below the kernel (its
/// drives as its loops take them, its scheme level); [`by_kernel`], [`by_drive`] and
/// [`by_law`] are written once over it.
trait Build {
    /// The family built.
    type F: Family;
    /// What the family's loops take for a drive `D`: `D` itself (one species) or one per
    /// species (a mixture).
    type Drives<D: Drive>;
    /// The validated physics.
    fn model(&self) -> &Model;
    /// The drive `d` as the family's loops take it (every species the same).
    fn each<D: Drive>(&self, d: D) -> Self::Drives<D>;
    /// The family's white noise, when the physics has it (a rough gas's on translation or
    /// rotation, a mixture's per species).
    fn noise(&self) -> Option<Self::Drives<<Self::F as Family>::Noise>>;
    /// The host medium `h` in the family's dimension, as each species meets it.
    fn host<B: BackgroundKernel>(
        &self,
        h: HostMedium<B>,
    ) -> Result<Self::Drives<HostIn<B, Self::F>>, EngineError>;
    /// The declared drive `d` in the family's dimension, as each species meets it with its
    /// own mass (one species: unit mass).
    fn place<T: Declared>(&self, d: T) -> Result<Self::Drives<Placed<T, Self::F>>, EngineError>;
    /// The family's scheme level for kernel `k`, drives `d` and restitution law `a`, started
    /// at `t0` on `p`.
    fn scheme<K: Kernel, D: Drive, A: Law>(
        &self,
        k: K,
        d: &Self::Drives<D>,
        a: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Begun<<Self::F as Family>::Scheme<K, D, A>>;
}

/// A restitution law as every family takes it: the law itself (smooth particles), the rough
/// map of it, or a mixture's pair laws of it.
trait Law: Restitution {
    /// The rough map `map` (of the model's constant law) with this law.
    fn rough(self, map: &RoughMap) -> RoughMap<Self>;
    /// A mixture's pair laws with this law, from the pair types' constant laws `laws`.
    fn pairs<P: PairModel>(self, laws: &[P::Of<Constant>; MAX_PAIRS]) -> [P::Of<Self>; MAX_PAIRS];
}

/// A constant law: the rough map and the pair types' laws as validated (a mixture's constant
/// is per pair type).
impl Law for Constant {
    fn rough(self, map: &RoughMap) -> RoughMap {
        *map
    }
    fn pairs<P: PairModel>(self, laws: &[P::Of<Constant>; MAX_PAIRS]) -> [P::Of<Self>; MAX_PAIRS] {
        *laws
    }
}

/// BRS's impact-speed law, put into the rough map and into every pair (whose constants, 1,
/// are then unused).
impl Law for ImpactSpeed {
    fn rough(self, map: &RoughMap) -> RoughMap<Self> {
        map.with_law(self)
    }
    fn pairs<P: PairModel>(self, laws: &[P::Of<Constant>; MAX_PAIRS]) -> [P::Of<Self>; MAX_PAIRS] {
        laws.map(|l| P::with_law(&l, self))
    }
}

/// Generates [`by_kernel`] from the kernel table ([`kernel_table`]).
macro_rules! by_kernel {
    ($($v:ident($t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
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

/// Smooth particles of one species in dimension `G`.
struct SmoothBuild<'a, G>(&'a Model, PhantomData<G>);
impl<G: WhiteNoiseIn> Build for SmoothBuild<'_, G> {
    type F = Smooth<G>;
    type Drives<D: Drive> = D;
    fn model(&self) -> &Model {
        self.0
    }
    fn each<D: Drive>(&self, d: D) -> D {
        d
    }
    fn noise(&self) -> Option<G::Noise> {
        self.0.drive.white_noise().map(G::noise)
    }
    fn host<B: BackgroundKernel>(&self, h: HostMedium<B>) -> Result<HostMedium<B, G>, EngineError> {
        Ok(h.in_dim::<G>())
    }
    fn place<T: Declared>(&self, d: T) -> Result<T::In<G>, EngineError> {
        unit_mass(d)
    }
    fn scheme<K: Kernel, D: Drive, A: Law>(
        &self,
        k: K,
        d: &D,
        a: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Begun<ByScheme<K, D, A, G>> {
        self.0.by_scheme(k, *d, a, p, t0)
    }
}

/// Rough particles of one species in dimension `G`: the rough map of the law.
struct RoughBuild<'a, G>(&'a RoughModel, &'a Model, PhantomData<G>);
impl<G: Geometry> Build for RoughBuild<'_, G> {
    type F = Rough<G>;
    type Drives<D: Drive> = D;
    fn model(&self) -> &Model {
        self.1
    }
    fn each<D: Drive>(&self, d: D) -> D {
        d
    }
    fn noise(&self) -> Option<RoughNoise<G>> {
        self.0.noise.map(|w| w.in_dim::<G>())
    }
    fn host<B: BackgroundKernel>(&self, h: HostMedium<B>) -> Result<HostMedium<B, G>, EngineError> {
        Ok(h.in_dim::<G>())
    }
    fn place<T: Declared>(&self, d: T) -> Result<T::In<G>, EngineError> {
        unit_mass(d)
    }
    fn scheme<K: Kernel, D: Drive, A: Law>(
        &self,
        k: K,
        d: &D,
        a: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Begun<BySplit<K, D, RoughMap<A>, G>> {
        by_split(self.1.scheme, k, *d, a.rough(&self.0.map), p, t0)
    }
}

/// A mixture of particle model `P` in dimension `G`: the pair kernels scaled from the
/// kernel, the pair laws from the law, one drive per species.
struct MixtureBuild<'a, G: WhiteNoiseIn, P: PairModel> {
    mx: &'a MixtureModel,
    m: &'a Model,
    /// The pair types' constant laws.
    laws: &'a [P::Of<Constant>; MAX_PAIRS],
    /// Each species' white noise, when the physics has it.
    noises: Option<[P::Noise<G>; MAX_SPECIES]>,
}

impl<'a, G: WhiteNoiseIn> MixtureBuild<'a, G, SmoothPairs> {
    /// A mixture of smooth particles.
    fn smooth(mx: &'a MixtureModel, m: &'a Model) -> Self {
        let noises = m.drive.white_noise().map(|_| mx.noises.map(G::noise));
        Self {
            mx,
            m,
            laws: &mx.laws,
            noises,
        }
    }
}

impl<'a, G: WhiteNoiseIn> MixtureBuild<'a, G, RoughPairs> {
    /// A mixture of rough particles (their pair laws and noises on translation and rotation
    /// in `r`).
    fn rough(mx: &'a MixtureModel, r: &'a MixtureRotation, m: &'a Model) -> Self {
        Self {
            mx,
            m,
            laws: &r.laws,
            noises: r.noises.map(|ns| ns.map(|w| w.in_dim::<G>())),
        }
    }
}

impl<G: WhiteNoiseIn, P: PairModel> Build for MixtureBuild<'_, G, P> {
    type F = Mixture<G, P>;
    type Drives<D: Drive> = [D; MAX_SPECIES];
    fn model(&self) -> &Model {
        self.m
    }
    fn each<D: Drive>(&self, d: D) -> [D; MAX_SPECIES] {
        [d; MAX_SPECIES]
    }
    fn noise(&self) -> Option<[P::Noise<G>; MAX_SPECIES]> {
        self.noises
    }
    fn host<B: BackgroundKernel>(
        &self,
        h: HostMedium<B>,
    ) -> Result<[HostMedium<B, G>; MAX_SPECIES], EngineError> {
        species_hosts(self.mx, h)
    }
    fn place<T: Declared>(&self, d: T) -> Result<[T::In<G>; MAX_SPECIES], EngineError> {
        let sp = &self.mx.species;
        let first = unit_mass::<T, G>(d)?;
        let mut placed = [first; MAX_SPECIES];
        for (s, q) in placed.iter_mut().enumerate().take(sp.len()) {
            // Validated: every species' mass places the drive.
            *q = d
                .place::<G>(sp.mass(s))
                .ok_or(EngineError::Invariant("a species' mass places its drive"))?;
        }
        Ok(placed)
    }
    fn scheme<K: Kernel, D: Drive, A: Law>(
        &self,
        k: K,
        d: &[D; MAX_SPECIES],
        a: A,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Begun<ByMixtureScheme<K, D, P::Of<A>, G>> {
        let physics = pair_table(self.mx, k, &a.pairs::<P>(self.laws))?;
        start_mixture::<K, D, _, G>(self.mx, self.m.scheme, &physics, d, p, t0)
    }
}

/// A declared drive `T` as family `F`'s loops take it (in its dimension).
type Placed<T, F> = <T as Declared>::In<<F as Family>::G>;

/// The declared drive `d` on a grain of unit mass in dimension `G` (validated: it exists).
fn unit_mass<T: Declared, G: Geometry>(d: T) -> Result<T::In<G>, EngineError> {
    d.place::<G>(1.0).ok_or(EngineError::Invariant(
        "a declared drive acts on a unit mass",
    ))
}

/// A mixture loop's start as an engine's: its refusal as an engine error (the model was
/// validated, so only the engine's own refusals remain), the whole gas's observables.
fn started<E>(
    e: Result<(E, crate::mixture::MixtureObservables), StartError>,
) -> Result<(E, Observables), EngineError> {
    e.map(|(e, o)| (e, o.all)).map_err(|e| match e {
        StartError::Engine(e) => e,
        StartError::Mixture(_) => EngineError::ParticleCount,
    })
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

fn wrap<E, F>(
    r: Result<(E, Observables), EngineError>,
    f: impl FnOnce(E) -> F,
) -> Result<(F, Observables), EngineError> {
    r.map(|(e, o)| (f(e), o))
}
