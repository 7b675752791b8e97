//! The statically composed engine behind a [`super::Model`]: a nest of small enums, one level
//! per choice (particle model, species and dimension; kernel, written once for every family;
//! drive, restitution law or collision map, scheme), whose leaves are the monomorphized event
//! loops. No box and no allocation (a C caller or a firmware keeps it in its own memory);
//! each call goes down the nest once (four `match`es per call, i.e. per observation) and then
//! runs a loop that holds only the physics it names.

// Clippy sizes a variant whose payload is a [`Built`] projection as empty and then reports the
// others as large; the loops of one level are of like size (the mixture's, at the family level,
// is explained at [`Engine`]).
#![allow(clippy::large_enum_variant)]

use crate::drive::{
    ConstantForce, Drive, GaussianThermostat, HardSphereBackground, HostMedium, MaxwellBackground,
    NoDrive, PlanarWhiteNoise, WhiteNoise, WhiteNoiseIn,
};
use crate::engine::{
    CollisionMap, Counts, EngineError, EventLoop, Frame, NoSplitting, Splitting, SumNoSplitting,
    TimeStepped,
};
use crate::geometry::{Disks, Geometry, Spheres};
use crate::kernel::{HardSpheres, Kernel, Maxwell, Vhs};
use crate::math::Real;
use crate::mixture::{
    MixtureNoSplitting, MixtureObservables, MixtureSplitting, MixtureTimeStepped, PairLaw,
};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::{Constant, ImpactSpeed, Restitution};
use crate::rng::Rng;
use crate::rough::{RoughMap, RoughNoise, RoughObservables, RoughPairLaw};

/// The engine of a validated physics: by particle model, species and dimension, then one
/// kernel level ([`ByKernel`]) over the family's nest of drives, laws and schemes.
// The mixture's loop keeps its per-species and per-pair state in fixed arrays (about 1.4 KB
// against 0.5 KB for the one-species loops); the core has no allocator to box it, and an
// engine lives in its caller's memory once per system, so the size is paid once, not per
// particle or event.
#[derive(Clone, Debug)]
pub enum Engine {
    /// Smooth spheres of one species: by drive, law and scheme.
    Smooth(ByKernel<Smooth>),
    /// A mixture of several species of smooth spheres (feature `mixtures`).
    Mixture(Built<ByKernel<Mixture<Spheres>>, MIXTURES>),
    /// Rough spheres (translation and rotation; feature `rough`).
    Rough(Built<ByKernel<Rough<Spheres>>, ROUGH>),
    /// Smooth disks (`d = 2`; feature `disks`).
    Disks(Built<ByKernel<SmoothDisks>, DISKS>),
    /// Rough disks (features `rough`, `disks`).
    RoughDisks(Built<ByKernel<Rough<Disks>>, ROUGH_DISKS>),
    /// A mixture of smooth disks (features `mixtures`, `disks`).
    DiskMixture(Built<ByKernel<Mixture<Disks>>, DISK_MIXTURES>),
    /// A mixture of rough spheres (features `mixtures`, `rough`).
    RoughMixture(Built<ByKernel<RoughMixture<Spheres>>, ROUGH_MIXTURES>),
    /// A mixture of rough disks (features `mixtures`, `rough`, `disks`).
    RoughDiskMixture(Built<ByKernel<RoughMixture<Disks>>, ROUGH_DISK_MIXTURES>),
}

/// Whether this build holds each engine family (the cargo features of gdsmc-core).
const MIXTURES: bool = cfg!(feature = "mixtures");
const ROUGH: bool = cfg!(feature = "rough");
const DISKS: bool = cfg!(feature = "disks");
const ROUGH_DISKS: bool = ROUGH && DISKS;
const DISK_MIXTURES: bool = MIXTURES && DISKS;
const ROUGH_MIXTURES: bool = MIXTURES && ROUGH;
const ROUGH_DISK_MIXTURES: bool = MIXTURES && ROUGH && DISKS;
/// Whether this build holds each kernel, drive, law and scheme (the same features).
const MAXWELL: bool = cfg!(feature = "maxwell");
const HARD_SPHERES: bool = cfg!(feature = "hard-spheres");
const VHS: bool = cfg!(feature = "vhs");
const COOLING: bool = cfg!(feature = "cooling");
const WHITE_NOISE: bool = cfg!(feature = "white-noise");
const GAUSSIAN: bool = cfg!(feature = "gaussian-thermostat");
const CONSTANT_FORCE: bool = cfg!(feature = "constant-force");
const HOST_MEDIUM: bool = cfg!(feature = "host-medium");
const IMPACT_SPEED: bool = cfg!(feature = "impact-speed");
const SPLITTING: bool = cfg!(feature = "splitting");
const TIME_STEPPED: bool = cfg!(feature = "time-stepped");

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
    fn species(&self, _p: &Particles<'_>) -> Option<MixtureObservables> {
        match self.0 {}
    }
    fn rough(&self, _p: &Particles<'_>) -> Option<RoughObservables> {
        match self.0 {}
    }
}

/// A family of loops that takes every kernel: what it is for kernel `K` ([`ByKernel`] holds
/// one of them).
pub trait Family {
    /// The family's engine for kernel `K`.
    type Of<K: Kernel>: EventLoop + Clone + core::fmt::Debug;
}

/// The one kernel level, for every family: the kernel chosen at run time, the family's nest
/// below it generic over the kernel.
#[derive(Clone, Debug)]
pub enum ByKernel<F: Family> {
    /// Maxwell pseudo-molecules (feature `maxwell`).
    Maxwell(Built<F::Of<Maxwell>, MAXWELL>),
    /// Hard spheres (hard disks in `d = 2`; feature `hard-spheres`).
    HardSpheres(Built<F::Of<HardSpheres>, HARD_SPHERES>),
    /// Variable hard spheres (feature `vhs`).
    Vhs(Built<F::Of<Vhs>, VHS>),
}

/// Smooth spheres of one species ([`ByDrive`]).
#[derive(Clone, Copy, Debug)]
pub struct Smooth;
impl Family for Smooth {
    type Of<K: Kernel> = ByDrive<K>;
}

/// Smooth disks ([`ByDiskDrive`]).
#[derive(Clone, Copy, Debug)]
pub struct SmoothDisks;
impl Family for SmoothDisks {
    type Of<K: Kernel> = ByDiskDrive<K>;
}

/// Rough particles in dimension `G` ([`ByRoughDrive`]).
#[derive(Clone, Copy, Debug)]
pub struct Rough<G>(core::marker::PhantomData<G>);
impl<G: Geometry> Family for Rough<G> {
    type Of<K: Kernel> = ByRoughDrive<K, G>;
}

/// Mixtures of smooth particles in dimension `G` ([`ByMixtureDrive`]).
#[derive(Clone, Copy, Debug)]
pub struct Mixture<G>(core::marker::PhantomData<G>);
impl<G: WhiteNoiseIn> Family for Mixture<G> {
    type Of<K: Kernel> = ByMixtureDrive<K, G>;
}

/// Mixtures of rough particles in dimension `G` ([`ByRoughMixtureDrive`]).
#[derive(Clone, Copy, Debug)]
pub struct RoughMixture<G>(core::marker::PhantomData<G>);
impl<G: Geometry> Family for RoughMixture<G> {
    type Of<K: Kernel> = ByRoughMixtureDrive<K, G>;
}

/// A rough mixture by drive, for kernel `K` and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByRoughMixtureDrive<K: Kernel, G: Geometry> {
    /// No drive: the mixture cools (feature `cooling`).
    None(Built<ByMixtureLaw<K, NoDrive, G, RoughPairs>, COOLING>),
    /// White noise on translation and rotation, each species its own strengths (feature
    /// `white-noise`).
    Noise(Built<ByMixtureLaw<K, RoughNoise<G>, G, RoughPairs>, WHITE_NOISE>),
    /// The Gaussian thermostat (MS (12)) on every species' translation, about the flow
    /// velocity (feature `gaussian-thermostat`).
    Gaussian(Built<ByMixtureLaw<K, GaussianThermostat, G, RoughPairs>, GAUSSIAN>),
    /// The constant force on every species' translation, its correction weighted by mass
    /// (MS (14), (62); a stepping scheme; feature `constant-force`).
    ConstantForce(Built<ByMixtureLaw<K, ConstantForce, G, RoughPairs>, CONSTANT_FORCE>),
    /// A host medium of Maxwell background kernel met by each species with its own mass, the
    /// encounters smooth (BRS (2), (11); feature `host-medium`).
    HostMaxwell(
        Built<ByMixtureLaw<K, HostMedium<MaxwellBackground, G>, G, RoughPairs>, HOST_MEDIUM>,
    ),
    /// A host medium of hard-sphere background kernel (BRS (19); feature `host-medium`).
    HostHardSpheres(
        Built<ByMixtureLaw<K, HostMedium<HardSphereBackground, G>, G, RoughPairs>, HOST_MEDIUM>,
    ),
}

/// Smooth disks by drive, for kernel `K`.
#[derive(Clone, Debug)]
pub enum ByDiskDrive<K: Kernel> {
    /// No drive: the disks cool (feature `cooling`).
    None(Built<ByLaw<K, NoDrive, Disks>, COOLING>),
    /// White noise in the plane (feature `white-noise`).
    WhiteNoise(Built<ByLaw<K, PlanarWhiteNoise, Disks>, WHITE_NOISE>),
    /// The Gaussian thermostat (MS (12); feature `gaussian-thermostat`).
    Gaussian(Built<ByLaw<K, GaussianThermostat, Disks>, GAUSSIAN>),
    /// The constant force along the peculiar velocity (MS (14); a stepping scheme; feature
    /// `constant-force`).
    ConstantForce(Built<ByLaw<K, ConstantForce, Disks>, CONSTANT_FORCE>),
    /// A host medium of Maxwell background kernel in the plane (feature `host-medium`).
    HostMaxwell(Built<ByLaw<K, HostMedium<MaxwellBackground, Disks>, Disks>, HOST_MEDIUM>),
    /// A host medium of hard-disk background kernel (feature `host-medium`).
    HostHardSpheres(Built<ByLaw<K, HostMedium<HardSphereBackground, Disks>, Disks>, HOST_MEDIUM>),
}

/// A rough gas's engine by drive, for kernel `K` and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByRoughDrive<K: Kernel, G: Geometry = Spheres> {
    /// No drive: the gas cools (feature `cooling`).
    None(Built<ByRoughLaw<K, NoDrive, G>, COOLING>),
    /// White noise on translation and rotation (feature `white-noise`).
    Noise(Built<ByRoughLaw<K, RoughNoise<G>, G>, WHITE_NOISE>),
    /// The Gaussian thermostat on translation (MS (12); feature `gaussian-thermostat`).
    Gaussian(Built<ByRoughLaw<K, GaussianThermostat, G>, GAUSSIAN>),
    /// The constant force on translation (MS (14); a splitting scheme; feature
    /// `constant-force`).
    ConstantForce(Built<ByRoughLaw<K, ConstantForce, G>, CONSTANT_FORCE>),
    /// A host medium of Maxwell background kernel, its encounters smooth (BRS (2), (11);
    /// feature `host-medium`).
    HostMaxwell(Built<ByRoughLaw<K, HostMedium<MaxwellBackground, G>, G>, HOST_MEDIUM>),
    /// A host medium of hard-sphere background kernel (BRS (19); feature `host-medium`).
    HostHardSpheres(Built<ByRoughLaw<K, HostMedium<HardSphereBackground, G>, G>, HOST_MEDIUM>),
}

/// A rough gas by normal restitution law (the rough map of it), for kernel `K`, drive `D`
/// and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByRoughLaw<K: Kernel, D: Drive, G: Geometry> {
    /// A constant `alpha`.
    Constant(BySplit<K, D, RoughMap<Constant>, G>),
    /// BRS's impact-speed law (9) at the normal impact speed `|g . n|` (feature
    /// `impact-speed`).
    ImpactSpeed(Built<BySplit<K, D, RoughMap<ImpactSpeed>, G>, IMPACT_SPEED>),
}

/// By scheme, the exact loop, the splittings or MS's time-stepped scheme, for every family
/// but the mixtures (smooth spheres add the sum form in [`ByScheme`]): kernel `K`, drive `D`,
/// collision map `A`, dimension `G`.
#[derive(Clone, Debug)]
pub enum BySplit<K: Kernel, D: Drive, A: CollisionMap, G: Geometry> {
    /// The exact no-splitting scheme (GRW Section 3).
    NoSplitting(NoSplitting<K, D, A, G>),
    /// Euler or Strang splitting (RW Algorithms 1, 2; feature `splitting`).
    Splitting(Built<Splitting<K, D, A, G>, SPLITTING>),
    /// MS's time-stepped scheme (Bird's no-time-counter form for the Maxwell and VHS kernels;
    /// feature `time-stepped`).
    TimeStepped(Built<TimeStepped<K, D, A, G>, TIME_STEPPED>),
}

/// A mixture's engine by drive, for kernel `K` and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByMixtureDrive<K: Kernel, G: WhiteNoiseIn> {
    /// No drive: the mixture cools (feature `cooling`).
    None(Built<ByMixtureLaw<K, NoDrive, G>, COOLING>),
    /// White noise in the dimension, each species its own strength (feature `white-noise`).
    WhiteNoise(Built<ByMixtureLaw<K, G::Noise, G>, WHITE_NOISE>),
    /// The Gaussian thermostat (MS (12)) on every species, about the flow velocity (feature
    /// `gaussian-thermostat`).
    Gaussian(Built<ByMixtureLaw<K, GaussianThermostat, G>, GAUSSIAN>),
    /// The constant force on every species, its correction weighted by mass (MS (14), (62);
    /// a stepping scheme; feature `constant-force`).
    ConstantForce(Built<ByMixtureLaw<K, ConstantForce, G>, CONSTANT_FORCE>),
    /// A host medium of Maxwell background kernel met by each species with its own mass
    /// (BRS (2), (11); feature `host-medium`).
    HostMaxwell(Built<ByMixtureLaw<K, HostMedium<MaxwellBackground, G>, G>, HOST_MEDIUM>),
    /// A host medium of hard-sphere background kernel (BRS (19); feature `host-medium`).
    HostHardSpheres(Built<ByMixtureLaw<K, HostMedium<HardSphereBackground, G>, G>, HOST_MEDIUM>),
}

/// The particle model of a mixture's pair types over a restitution law `A`: smooth particles
/// collide by the law itself ([`SmoothPairs`]), rough ones by [`RoughPairLaw`] of it
/// ([`RoughPairs`]). The law level ([`ByMixtureLaw`]) is written once for both.
pub trait PairModel: Clone + core::fmt::Debug {
    /// The pair law of particles of this model with normal restitution law `A`.
    type Of<A: Restitution>: PairLaw;
}

/// Smooth particles: the restitution law is the pair law.
#[derive(Clone, Copy, Debug)]
pub struct SmoothPairs;
impl PairModel for SmoothPairs {
    type Of<A: Restitution> = A;
}

/// Rough particles: the restitution law is the normal part of [`RoughPairLaw`].
#[derive(Clone, Copy, Debug)]
pub struct RoughPairs;
impl PairModel for RoughPairs {
    type Of<A: Restitution> = RoughPairLaw<A>;
}

/// A mixture by restitution law, for kernel `K`, drive `D`, dimension `G` and particle model
/// `P` (smooth or rough pairs).
#[derive(Clone, Debug)]
pub enum ByMixtureLaw<K: Kernel, D: Drive, G: Geometry, P: PairModel = SmoothPairs> {
    /// A constant coefficient per pair type.
    Constant(ByMixtureScheme<K, D, P::Of<Constant>, G>),
    /// BRS's impact-speed law (9)-(10) for every pair (feature `impact-speed`).
    ImpactSpeed(Built<ByMixtureScheme<K, D, P::Of<ImpactSpeed>, G>, IMPACT_SPEED>),
}

/// A mixture by scheme: the exact loop, or RW's splittings of it (the same collision
/// process with the drives off, then every species kicked), for kernel `K`, drive `D`, pair
/// law `L` and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByMixtureScheme<K: Kernel, D: Drive, L: PairLaw, G: Geometry> {
    /// The exact no-splitting scheme (GRW Section 3, one majorant per pair of species).
    NoSplitting(MixtureNoSplitting<K, D, L, G>),
    /// Euler or Strang splitting (RW Algorithms 1, 2; feature `splitting`).
    Splitting(Built<MixtureSplitting<K, D, L, G>, SPLITTING>),
    /// MS's time-stepped scheme, one collision stage per pair type (feature `time-stepped`).
    TimeStepped(Built<MixtureTimeStepped<K, D, L, G>, TIME_STEPPED>),
}

/// By drive, for kernel `K`.
#[derive(Clone, Debug)]
pub enum ByDrive<K: Kernel> {
    /// No drive: the gas cools (feature `cooling`).
    None(Built<ByLaw<K, NoDrive>, COOLING>),
    /// White noise (GRW (18); feature `white-noise`).
    WhiteNoise(Built<ByLaw<K, WhiteNoise>, WHITE_NOISE>),
    /// The Gaussian thermostat (MS (12); feature `gaussian-thermostat`).
    Gaussian(Built<ByLaw<K, GaussianThermostat>, GAUSSIAN>),
    /// The constant force (MS (14); feature `constant-force`).
    ConstantForce(Built<ByLaw<K, ConstantForce>, CONSTANT_FORCE>),
    /// A host medium with the Maxwell background kernel (BRS (11); feature `host-medium`).
    HostMaxwell(Built<ByLaw<K, HostMedium<MaxwellBackground>>, HOST_MEDIUM>),
    /// A host medium with the hard-sphere background kernel (BRS (19); feature
    /// `host-medium`).
    HostHardSpheres(Built<ByLaw<K, HostMedium<HardSphereBackground>>, HOST_MEDIUM>),
}

/// By restitution law, for kernel `K`, drive `D` and dimension `G` (smooth particles of one
/// species).
#[derive(Clone, Debug)]
pub enum ByLaw<K: Kernel, D: Drive, G: Geometry = Spheres> {
    /// A constant coefficient.
    Constant(ByScheme<K, D, Constant, G>),
    /// The impact-speed law BRS (9)-(10) (feature `impact-speed`).
    ImpactSpeed(Built<ByScheme<K, D, ImpactSpeed, G>, IMPACT_SPEED>),
}

/// By scheme: the event loops themselves (smooth particles of one species in dimension `G`).
#[derive(Clone, Debug)]
pub enum ByScheme<K: Kernel, D: Drive, A: Restitution, G: Geometry = Spheres> {
    /// The exact no-splitting scheme (GRW Section 3), Euler or Strang splitting (RW
    /// Algorithms 1, 2) or MS's time-stepped scheme: the scheme level every one-species family
    /// shares.
    Split(BySplit<K, D, A, G>),
    /// The exact scheme of hard spheres with no drive on the sum-form majorant (built only under
    /// [`ByKernel::HardSpheres`] with [`ByDrive::None`], for spheres; feature `hard-spheres`).
    SumForm(Built<SumNoSplitting<A>, HARD_SPHERES>),
}

/// Implements [`EventLoop`] for one level by forwarding every method to the variant.
macro_rules! forward {
    ($ty:ty, [$($g:tt)*], $($v:ident),+) => {
        impl<$($g)*> EventLoop for $ty {
            fn advance_to<R: Rng + ?Sized>(
                &mut self,
                p: &mut Particles<'_>,
                t_end: Real,
                rng: &mut R,
            ) -> Result<Observables, EngineError> {
                match self { $(Self::$v(e) => EventLoop::advance_to(e, p, t_end, rng)),+ }
            }
            fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
                match self { $(Self::$v(e) => EventLoop::resync(e, p)),+ }
            }
            fn time(&self) -> Real {
                match self { $(Self::$v(e) => EventLoop::time(e)),+ }
            }
            fn counts(&self) -> Counts {
                match self { $(Self::$v(e) => EventLoop::counts(e)),+ }
            }
            fn work_rate(&self, n: usize) -> Real {
                match self { $(Self::$v(e) => EventLoop::work_rate(e, n)),+ }
            }
            fn velocity_map(&self) -> Frame {
                match self { $(Self::$v(e) => EventLoop::velocity_map(e)),+ }
            }
            fn species(&self, p: &Particles<'_>) -> Option<MixtureObservables> {
                match self { $(Self::$v(e) => EventLoop::species(e, p)),+ }
            }
            fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
                match self { $(Self::$v(e) => EventLoop::rough(e, p)),+ }
            }
        }
    };
}

forward!(
    Engine,
    [],
    Smooth,
    Mixture,
    Rough,
    Disks,
    RoughDisks,
    DiskMixture,
    RoughMixture,
    RoughDiskMixture
);
forward!(ByKernel<F>, [F: Family], Maxwell, HardSpheres, Vhs);
forward!(ByDiskDrive<K>, [K: Kernel], None, WhiteNoise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(ByRoughDrive<K, G>, [K: Kernel, G: Geometry], None, Noise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(BySplit<K, D, A, G>, [K: Kernel, D: Drive, A: CollisionMap, G: Geometry], NoSplitting, Splitting, TimeStepped);
forward!(ByMixtureDrive<K, G>, [K: Kernel, G: WhiteNoiseIn], None, WhiteNoise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(ByRoughMixtureDrive<K, G>, [K: Kernel, G: Geometry], None, Noise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(ByMixtureLaw<K, D, G, P>, [K: Kernel, D: Drive, G: Geometry, P: PairModel], Constant, ImpactSpeed);
forward!(ByRoughLaw<K, D, G>, [K: Kernel, D: Drive, G: Geometry], Constant, ImpactSpeed);
forward!(ByMixtureScheme<K, D, L, G>, [K: Kernel, D: Drive, L: PairLaw, G: Geometry], NoSplitting, Splitting, TimeStepped);
forward!(ByDrive<K>, [K: Kernel], None, WhiteNoise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(ByLaw<K, D, G>, [K: Kernel, D: Drive, G: Geometry], Constant, ImpactSpeed);
forward!(ByScheme<K, D, A, G>, [K: Kernel, D: Drive, A: Restitution, G: Geometry], Split, SumForm);
