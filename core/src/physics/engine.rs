//! The statically composed engine behind a [`super::Model`]: a nest of small enums, one level
//! per choice (kernel, drive, restitution law, scheme), whose leaves are the monomorphized
//! event loops. No box and no allocation (a C caller or a firmware keeps it in its own memory);
//! each call goes down the nest once (four `match`es per call, i.e. per observation) and then
//! runs a loop that holds only the physics it names.

use crate::drive::{
    ConstantForce, Drive, GaussianThermostat, HardSphereBackground, HostMedium, MaxwellBackground,
    NoDrive, WhiteNoise,
};
use crate::engine::{Counts, EngineError, EventLoop, NoSplitting, Splitting, TimeStepped};
use crate::kernel::{HardSpheres, Kernel, Maxwell, Vhs};
use crate::math::Real;
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::{Constant, ImpactSpeed, Restitution};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The engine of a validated physics, by kernel.
#[derive(Clone, Debug)]
pub enum Engine {
    /// Maxwell pseudo-molecules.
    Maxwell(ByDrive<Maxwell>),
    /// Hard spheres (also the time-stepped scheme).
    HardSpheres(ByDrive<HardSpheres>),
    /// Variable hard spheres.
    Vhs(ByDrive<Vhs>),
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
                match self { $(Self::$v(e) => e.advance_to(p, t_end, rng)),+ }
            }
            fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
                match self { $(Self::$v(e) => e.resync(p)),+ }
            }
            fn time(&self) -> Real {
                match self { $(Self::$v(e) => e.time()),+ }
            }
            fn counts(&self) -> Counts {
                match self { $(Self::$v(e) => e.counts()),+ }
            }
            fn velocity_map(&self) -> (Real, Vec3) {
                match self { $(Self::$v(e) => e.velocity_map()),+ }
            }
        }
    };
}

forward!(Engine, [], Maxwell, HardSpheres, Vhs);
forward!(ByDrive<K>, [K: Kernel], None, WhiteNoise, Gaussian, ConstantForce, HostMaxwell, HostHardSpheres);
forward!(ByLaw<K, D>, [K: Kernel, D: Drive], Constant, ImpactSpeed);
forward!(ByScheme<K, D, A>, [K: Kernel, D: Drive, A: Restitution], NoSplitting, Splitting, TimeStepped);
