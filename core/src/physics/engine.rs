//! The statically composed engine behind a [`super::Model`]: a nest of small enums, one level
//! per choice (kernel, drive, restitution law, scheme), whose leaves are the monomorphized
//! event loops. No box and no allocation (a C caller or a firmware keeps it in its own memory);
//! each call goes down the nest once (four `match`es per call, i.e. per observation) and then
//! runs a loop that holds only the physics it names.

use crate::drive::{
    ConstantForce, Drive, GaussianThermostat, HardSphereBackground, HostMedium, MaxwellBackground,
    NoDrive, PlanarWhiteNoise, WhiteNoise,
};
use crate::engine::{
    Counts, EngineError, EventLoop, NoSplitting, Splitting, SumNoSplitting, TimeStepped,
};
use crate::geometry::{Disks, Geometry, Spheres};
use crate::kernel::{HardSpheres, Kernel, Maxwell, Vhs};
use crate::math::Real;
use crate::mixture::{MixtureNoSplitting, MixtureObservables};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::{Constant, ImpactSpeed, Restitution};
use crate::rng::Rng;
use crate::rough::{RoughNoSplitting, RoughNoise, RoughObservables};
use crate::vec3::Vec3;

/// The engine of a validated physics, by kernel.
// The mixture's loop keeps its per-species and per-pair state in fixed arrays (about 1.4 KB
// against 0.5 KB for the one-species loops); the core has no allocator to box it, and an
// engine lives in its caller's memory once per system, so the size is paid once, not per
// particle or event.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum Engine {
    /// Maxwell pseudo-molecules.
    Maxwell(ByDrive<Maxwell>),
    /// Hard spheres (also the time-stepped scheme).
    HardSpheres(ByDrive<HardSpheres>),
    /// Variable hard spheres.
    Vhs(ByDrive<Vhs>),
    /// A mixture of several species.
    Mixture(MixtureEngine),
    /// Rough particles (translation and rotation).
    Rough(RoughEngine),
    /// Disks (`d = 2`), smooth or rough.
    Disks(DiskEngine),
}

/// The engine of disks (`d = 2`, no-splitting, a constant restitution), smooth by kernel or
/// rough.
#[derive(Clone, Debug)]
pub enum DiskEngine {
    /// Maxwell pseudo-molecules.
    Maxwell(ByDiskDrive<Maxwell>),
    /// Hard disks.
    HardSpheres(ByDiskDrive<HardSpheres>),
    /// Variable hard disks (isotropic scattering).
    Vhs(ByDiskDrive<Vhs>),
    /// Rough disks.
    Rough(RoughDiskEngine),
}

/// Smooth disks by drive, for kernel `K`.
#[derive(Clone, Debug)]
pub enum ByDiskDrive<K> {
    /// No drive: the disks cool.
    None(NoSplitting<K, NoDrive, Constant, Disks>),
    /// White noise in the plane.
    WhiteNoise(NoSplitting<K, PlanarWhiteNoise, Constant, Disks>),
}

/// Rough disks by kernel.
#[derive(Clone, Debug)]
pub enum RoughDiskEngine {
    /// Maxwell pseudo-molecules.
    Maxwell(ByRoughDrive<Maxwell, Disks>),
    /// Hard disks.
    HardSpheres(ByRoughDrive<HardSpheres, Disks>),
    /// Variable hard disks.
    Vhs(ByRoughDrive<Vhs, Disks>),
}

/// A rough gas's engine (no-splitting, a constant normal restitution), by kernel.
#[derive(Clone, Debug)]
pub enum RoughEngine {
    /// Maxwell pseudo-molecules.
    Maxwell(ByRoughDrive<Maxwell>),
    /// Hard spheres.
    HardSpheres(ByRoughDrive<HardSpheres>),
    /// Variable hard spheres.
    Vhs(ByRoughDrive<Vhs>),
}

/// A rough gas's engine by drive, for kernel `K` and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByRoughDrive<K, G = Spheres> {
    /// No drive: the gas cools.
    None(RoughNoSplitting<K, NoDrive, G>),
    /// White noise on translation and rotation.
    Noise(RoughNoSplitting<K, RoughNoise, G>),
}

/// A mixture's engine (no-splitting, a constant restitution per species pair), by kernel.
#[derive(Clone, Debug)]
pub enum MixtureEngine {
    /// Maxwell pseudo-molecules.
    Maxwell(ByMixtureDrive<Maxwell>),
    /// Hard spheres.
    HardSpheres(ByMixtureDrive<HardSpheres>),
    /// Variable hard spheres.
    Vhs(ByMixtureDrive<Vhs>),
}

/// A mixture's engine by drive, for kernel `K`.
#[derive(Clone, Debug)]
pub enum ByMixtureDrive<K> {
    /// No drive: the mixture cools.
    None(MixtureNoSplitting<K, NoDrive, Constant>),
    /// White noise, each species its own strength.
    WhiteNoise(MixtureNoSplitting<K, WhiteNoise, Constant>),
    /// The Gaussian thermostat (MS (12)) on every species, about the flow velocity.
    Gaussian(MixtureNoSplitting<K, GaussianThermostat, Constant>),
}

/// By drive, for kernel `K`.
#[derive(Clone, Debug)]
pub enum ByDrive<K> {
    /// No drive.
    None(ByLaw<K, NoDrive>),
    /// White noise (GRW (18)).
    WhiteNoise(ByLaw<K, WhiteNoise>),
    /// The Gaussian thermostat (MS (12)).
    Gaussian(ByLaw<K, GaussianThermostat>),
    /// The constant force (MS (14)).
    ConstantForce(ByLaw<K, ConstantForce>),
    /// A host medium with the Maxwell background kernel (BRS (11)).
    HostMaxwell(ByLaw<K, HostMedium<MaxwellBackground>>),
    /// A host medium with the hard-sphere background kernel (BRS (19)).
    HostHardSpheres(ByLaw<K, HostMedium<HardSphereBackground>>),
}

/// By restitution law, for kernel `K` and drive `D`.
#[derive(Clone, Debug)]
pub enum ByLaw<K, D> {
    /// A constant coefficient.
    Constant(ByScheme<K, D, Constant>),
    /// The impact-speed law BRS (9)-(10).
    ImpactSpeed(ByScheme<K, D, ImpactSpeed>),
}

/// By scheme: the event loops themselves.
#[derive(Clone, Debug)]
pub enum ByScheme<K, D, A> {
    /// The exact no-splitting scheme (GRW Section 3).
    NoSplitting(NoSplitting<K, D, A>),
    /// Euler or Strang splitting (RW Algorithms 1, 2).
    Splitting(Splitting<K, D, A>),
    /// MS's time-stepped scheme (hard spheres only; built only under [`Engine::HardSpheres`]).
    TimeStepped(TimeStepped<D, A>),
    /// The exact scheme of hard spheres with no drive on the sum-form majorant (built only under
    /// [`Engine::HardSpheres`] with [`ByDrive::None`]).
    SumForm(SumNoSplitting<A>),
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
            fn velocity_map(&self) -> (Real, Vec3) {
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

forward!(Engine, [], Maxwell, HardSpheres, Vhs, Mixture, Rough, Disks);
forward!(DiskEngine, [], Maxwell, HardSpheres, Vhs, Rough);
forward!(ByDiskDrive<K>, [K: Kernel], None, WhiteNoise);
forward!(RoughDiskEngine, [], Maxwell, HardSpheres, Vhs);
forward!(RoughEngine, [], Maxwell, HardSpheres, Vhs);
forward!(ByRoughDrive<K, G>, [K: Kernel, G: Geometry], None, Noise);
forward!(MixtureEngine, [], Maxwell, HardSpheres, Vhs);
forward!(ByMixtureDrive<K>, [K: Kernel], None, WhiteNoise, Gaussian);
forward!(ByDrive<K>, [K: Kernel], None, WhiteNoise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(ByLaw<K, D>, [K: Kernel, D: Drive], Constant, ImpactSpeed);
forward!(ByScheme<K, D, A>, [K: Kernel, D: Drive, A: Restitution], NoSplitting, Splitting, TimeStepped, SumForm);
