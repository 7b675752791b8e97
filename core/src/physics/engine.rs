//! The statically composed engine behind a [`super::Model`]: a nest of small enums, one level
//! per choice (particle model, species and dimension; then kernel, drive and restitution law,
//! each level written once for every family; then the family's scheme level), whose leaves are
//! the monomorphized event loops. No box and no allocation (a C caller or a firmware keeps it in its own memory);
//! each call goes down the nest once (four `match`es per call, i.e. per observation) and then
//! runs a loop that holds only the physics it names.

// Clippy sizes a variant whose payload is a [`Built`] projection as empty and then reports the
// others as large; the loops of one level are of like size (the mixture's, at the family level,
// is explained at [`Engine`]).
#![allow(clippy::large_enum_variant)]

use super::axes::kernel_table;
pub use super::built::{Built, Exact, NotBuilt, Pick, Select};
use super::kinds::declared_drives;
use crate::drive::{
    Declared, Drive, HardSphereBackground, HostMedium, MaxwellBackground, NoDrive, WhiteNoiseIn,
};
use crate::engine::{
    CollisionMap, Counts, EngineError, EventLoop, Frame, NoSplitting, Splitting, SumNoSplitting,
    TimeStepped,
};
use crate::geometry::{Disks, Geometry, Spheres};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::mixture::{
    MixtureNoSplitting, MixtureObservables, MixtureSplitting, MixtureTimeStepped, PairLaw,
};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::{Constant, ImpactSpeed, Restitution};
use crate::rng::{Rng, Xoshiro256PlusPlus};
use crate::rough::{RoughMap, RoughNoise, RoughObservables, RoughPairLaw};
use crate::weighted::nosplit::WeightedNoSplitting;

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
    Disks(Built<ByKernel<Smooth<Disks>>, DISKS>),
    /// Rough disks (features `rough`, `disks`).
    RoughDisks(Built<ByKernel<Rough<Disks>>, ROUGH_DISKS>),
    /// A mixture of smooth disks (features `mixtures`, `disks`).
    DiskMixture(Built<ByKernel<Mixture<Disks>>, DISK_MIXTURES>),
    /// A mixture of rough spheres (features `mixtures`, `rough`).
    RoughMixture(Built<ByKernel<Mixture<Spheres, RoughPairs>>, ROUGH_MIXTURES>),
    /// A mixture of rough disks (features `mixtures`, `rough`, `disks`).
    RoughDiskMixture(Built<ByKernel<Mixture<Disks, RoughPairs>>, ROUGH_DISK_MIXTURES>),
}

impl Engine {
    /// [`EventLoop::advance_to`] with the generator every gdsmc run uses (GRW Section 3's
    /// loop, or the scheme the physics names), compiled once here: the loops are
    /// monomorphized in this crate's build, not again in each crate that runs them (the
    /// runner, the C ABI and their test builds each compiled all of them for about 80 s of
    /// CPU). Not inlined, so a caller links this copy; another generator goes through the
    /// trait's generic method.
    #[inline(never)]
    pub fn advance_to(
        &mut self,
        p: &mut Particles<'_>,
        t_end: Real,
        rng: &mut Xoshiro256PlusPlus,
    ) -> Result<Observables, EngineError> {
        EventLoop::advance_to(self, p, t_end, rng)
    }
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
const COOLING: bool = cfg!(feature = "cooling");
const WHITE_NOISE: bool = cfg!(feature = "white-noise");
const HOST_MEDIUM: bool = cfg!(feature = "host-medium");
const IMPACT_SPEED: bool = cfg!(feature = "impact-speed");
const SPLITTING: bool = cfg!(feature = "splitting");
const TIME_STEPPED: bool = cfg!(feature = "time-stepped");
/// Whether this build holds the sum form of hard spheres (their kernel's feature).
const HARD_SPHERES: bool = cfg!(feature = "hard-spheres");
/// Whether the build holds the weighted scheme's loop.
const WEIGHTED: bool = cfg!(feature = "weighted");

/// A family of loops (particle model, species, dimension): what the levels below the kernel
/// hold for it. Every level ([`ByKernel`], [`ByDrive`], [`ByLaw`]) is written once for all
/// families; a family names only what differs: its white noise, its dimension and its scheme
/// level.
pub trait Family: Clone + core::fmt::Debug {
    /// White noise as this family takes it (in its dimension; on translation and rotation for
    /// rough particles).
    type Noise: Drive;
    /// The dimension (a host medium's encounters are drawn in it).
    type G: Geometry;
    /// The family's scheme level, whose leaves are the event loops: kernel `K`, drive `D`,
    /// restitution law `A`.
    type Scheme<K: Kernel, D: Drive, A: Restitution>: EventLoop + Clone + core::fmt::Debug;
}

/// Generates [`ByKernel`] and its [`EventLoop`] from the kernel table (`kernel_table!`).
macro_rules! by_kernel {
    ($($v:ident($code:literal, $scene:literal, $t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
        /// The one kernel level, for every family: the kernel chosen at run time, the levels
        /// below it generic over the kernel (generated from the kernel table in
        /// `physics/axes.rs`; each variant behind its kernel's cargo feature).
        #[derive(Clone, Debug)]
        pub enum ByKernel<F: Family> {
            $(#[doc = $doc] $v(Built<ByDrive<F, $t>, { kernel_built::$v }>),)*
        }

        /// Whether this build holds each kernel (its cargo feature).
        #[allow(non_upper_case_globals)]
        mod kernel_built {
            $(pub(super) const $v: bool = cfg!(feature = $feature);)*
        }

        forward!(ByKernel<F>, [F: Family], $($v),*);
    };
}

/// Generates [`ByDrive`] and its [`EventLoop`] from the declared drives' table
/// (`declared_drives!`), beside the drives written out.
macro_rules! by_drive {
    ($($v:ident($t:ty, $feature:literal)),* $(,)?) => {
        /// The one drive level, for every family `F` and kernel `K` (the declared drives'
        /// variants generated from their table in `physics/kinds.rs`, each behind its cargo
        /// feature, as the family's loops take it: [`Declared::In`] of its dimension).
        #[derive(Clone, Debug)]
        pub enum ByDrive<F: Family, K: Kernel> {
            /// No drive: the gas cools (feature `cooling`).
            None(Built<ByLaw<F, K, NoDrive>, COOLING>),
            /// White noise (GRW (18); rough particles: on translation and rotation; a mixture:
            /// each species its own strengths; feature `white-noise`).
            WhiteNoise(Built<ByLaw<F, K, F::Noise>, WHITE_NOISE>),
            /// A host medium with the Maxwell background kernel (BRS (2), (11); a mixture's
            /// species each meets it with its own mass; feature `host-medium`).
            HostMaxwell(Built<ByLaw<F, K, HostIn<MaxwellBackground, F>>, HOST_MEDIUM>),
            /// A host medium with the hard-sphere background kernel (BRS (19); feature
            /// `host-medium`).
            HostHardSpheres(Built<ByLaw<F, K, HostIn<HardSphereBackground, F>>, HOST_MEDIUM>),
            $(
                #[doc = concat!("A declared drive (feature `", $feature, "`).")]
                $v(Built<ByLaw<F, K, <$t as Declared>::In<<F as Family>::G>>, { drive_built::$v }>),
            )*
        }

        /// Whether this build holds each declared drive (its cargo feature).
        #[allow(non_upper_case_globals)]
        mod drive_built {
            $(pub(super) const $v: bool = cfg!(feature = $feature);)*
        }

        forward!(ByDrive<F, K>, [F: Family, K: Kernel], None, WhiteNoise, HostMaxwell, HostHardSpheres $(, $v)*);
    };
}
/// A host medium of background kernel `B` in family `F`'s dimension.
pub type HostIn<B, F> = HostMedium<B, <F as Family>::G>;

/// The one restitution-law level, for every family `F`, kernel `K` and drive `D`.
#[derive(Clone, Debug)]
pub enum ByLaw<F: Family, K: Kernel, D: Drive> {
    /// A constant coefficient (a mixture: one per pair type).
    Constant(F::Scheme<K, D, Constant>),
    /// BRS's impact-speed law (9)-(10) (rough particles: at the normal impact speed; a mixture:
    /// for every pair; feature `impact-speed`).
    ImpactSpeed(Built<F::Scheme<K, D, ImpactSpeed>, IMPACT_SPEED>),
}

/// Smooth particles of one species in dimension `G`: [`ByScheme`], whose exact loop for hard
/// spheres with no drive is the sum form.
#[derive(Clone, Copy, Debug)]
pub struct Smooth<G = Spheres>(core::marker::PhantomData<G>);
impl<G: WhiteNoiseIn> Family for Smooth<G> {
    type Noise = G::Noise;
    type G = G;
    type Scheme<K: Kernel, D: Drive, A: Restitution> = ByScheme<K, D, A, G>;
}

/// Rough particles of one species in dimension `G`: [`BySplit`] over the rough map of the
/// restitution law.
#[derive(Clone, Copy, Debug)]
pub struct Rough<G>(core::marker::PhantomData<G>);
impl<G: Geometry> Family for Rough<G> {
    type Noise = RoughNoise<G>;
    type G = G;
    type Scheme<K: Kernel, D: Drive, A: Restitution> = BySplit<K, D, RoughMap<A>, G>;
}

/// A mixture of particle model `P` (smooth or rough pairs) in dimension `G`:
/// [`ByMixtureScheme`] over the pair law of the restitution law.
#[derive(Clone, Copy, Debug)]
pub struct Mixture<G, P = SmoothPairs>(core::marker::PhantomData<(G, P)>);
impl<G: WhiteNoiseIn, P: PairModel> Family for Mixture<G, P> {
    type Noise = P::Noise<G>;
    type G = G;
    type Scheme<K: Kernel, D: Drive, A: Restitution> = ByMixtureScheme<K, D, P::Of<A>, G>;
}

/// By scheme, the exact loop, the splittings or MS's time-stepped scheme, for every family
/// but the mixtures (smooth spheres add the sum form in [`ByScheme`]): kernel `K`, drive `D`,
/// collision map `A`, dimension `G`.
#[derive(Clone, Debug)]
pub enum BySplit<
    K: Kernel,
    D: Drive,
    A: CollisionMap + crate::engine::collision_map::Inertia,
    G: Geometry,
> {
    /// The exact no-splitting scheme (GRW Section 3; never made for a stepped-only drive).
    NoSplitting(Exact<NoSplitting<K, D, A, G>, D>),
    /// Euler or Strang splitting (RW Algorithms 1, 2; feature `splitting`).
    Splitting(Built<Splitting<K, D, A, G>, SPLITTING>),
    /// MS's time-stepped scheme (Bird's no-time-counter form for the Maxwell and VHS kernels;
    /// feature `time-stepped`).
    TimeStepped(Built<TimeStepped<K, D, A, G>, TIME_STEPPED>),
}

/// The particle model of a mixture's pair types over a restitution law `A`: smooth particles
/// collide by the law itself ([`SmoothPairs`]), rough ones by [`RoughPairLaw`] of it
/// ([`RoughPairs`]). The mixture family ([`Mixture`]) is written once for both.
pub trait PairModel: Clone + core::fmt::Debug {
    /// The pair law of particles of this model with normal restitution law `A`.
    type Of<A: Restitution>: PairLaw;
    /// White noise on particles of this model in dimension `G`.
    type Noise<G: WhiteNoiseIn>: Drive;
    /// The pair law `l` (of a constant law) with normal restitution law `a` instead.
    fn with_law<A: Restitution>(l: &Self::Of<Constant>, a: A) -> Self::Of<A>;
}

/// Smooth particles: the restitution law is the pair law.
#[derive(Clone, Copy, Debug)]
pub struct SmoothPairs;
impl PairModel for SmoothPairs {
    type Of<A: Restitution> = A;
    type Noise<G: WhiteNoiseIn> = G::Noise;
    fn with_law<A: Restitution>(_: &Constant, a: A) -> A {
        a
    }
}

/// Rough particles: the restitution law is the normal part of [`RoughPairLaw`].
#[derive(Clone, Copy, Debug)]
pub struct RoughPairs;
impl PairModel for RoughPairs {
    type Of<A: Restitution> = RoughPairLaw<A>;
    type Noise<G: WhiteNoiseIn> = RoughNoise<G>;
    fn with_law<A: Restitution>(l: &RoughPairLaw, a: A) -> RoughPairLaw<A> {
        l.with_law(a)
    }
}

/// A mixture by scheme: the exact loop, or RW's splittings of it (the same collision
/// process with the drives off, then every species kicked), for kernel `K`, drive `D`, pair
/// law `L` and dimension `G`.
#[derive(Clone, Debug)]
pub enum ByMixtureScheme<K: Kernel, D: Drive, L: PairLaw, G: Geometry> {
    /// The exact no-splitting scheme (GRW Section 3, one majorant per pair of species; never
    /// made for a stepped-only drive).
    NoSplitting(Exact<MixtureNoSplitting<K, D, L, G>, D>),
    /// Euler or Strang splitting (RW Algorithms 1, 2; feature `splitting`).
    Splitting(Built<MixtureSplitting<K, D, L, G>, SPLITTING>),
    /// MS's time-stepped scheme, one collision stage per pair type (feature `time-stepped`).
    TimeStepped(Built<MixtureTimeStepped<K, D, L, G>, TIME_STEPPED>),
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
    /// The exact scheme on weighted particles (Rjasanow and Wagner's SWPM; feature
    /// `weighted`).
    Weighted(Built<Exact<WeightedNoSplitting<K, A, D, G>, D>, WEIGHTED>),
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
            fn collisions_per_particle(&self, n: usize) -> Real {
                match self { $(Self::$v(e) => EventLoop::collisions_per_particle(e, n)),+ }
            }
            fn species(&self, p: &Particles<'_>) -> Option<MixtureObservables> {
                match self { $(Self::$v(e) => EventLoop::species(e, p)),+ }
            }
            fn rough(&self, p: &Particles<'_>) -> Option<RoughObservables> {
                match self { $(Self::$v(e) => EventLoop::rough(e, p)),+ }
            }
            fn cooling<R: Rng + ?Sized>(
                &self,
                p: &Particles<'_>,
                pairs: u64,
                rng: &mut R,
            ) -> crate::observe::Cooling {
                match self { $(Self::$v(e) => EventLoop::cooling(e, p, pairs, rng)),+ }
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
forward!(ByLaw<F, K, D>, [F: Family, K: Kernel, D: Drive], Constant, ImpactSpeed);
forward!(BySplit<K, D, A, G>, [K: Kernel, D: Drive, A: CollisionMap + crate::engine::collision_map::Inertia, G: Geometry], NoSplitting, Splitting, TimeStepped);
forward!(ByMixtureScheme<K, D, L, G>, [K: Kernel, D: Drive, L: PairLaw, G: Geometry], NoSplitting, Splitting, TimeStepped);
forward!(ByScheme<K, D, A, G>, [K: Kernel, D: Drive, A: Restitution, G: Geometry], Split, SumForm, Weighted);
kernel_table!(by_kernel);
declared_drives!(by_drive);
