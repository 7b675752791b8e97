//! What builds one family's engine below the kernel level (`Build`: its drives as its loops
//! take them, its scheme level) for the dispatch (`dispatch.rs`), and the scheme levels
//! every family shares: the one-species `by_split` and smooth spheres' `Model::by_scheme`,
//! the mixtures' `start_mixture`.
#![cfg_attr(
    not(feature = "full"),
    allow(dead_code, unused_imports, unused_variables)
)]

use super::engine::{
    ByMixtureScheme, ByScheme, BySplit, Exact, Family, HostIn, Mixture, PairModel, Rough,
    RoughPairs, Smooth, SmoothPairs,
};
use super::model::Model;
use super::parts::SchemeModel;
use super::rotation::{MixtureRotation, RoughModel};
use super::species::MixtureModel;
use super::{MAX_PAIRS, MAX_SPECIES};
use crate::drive::host_medium::BackgroundKernel;
use crate::drive::{Declared, Drive, HostMedium, WhiteNoiseIn};
use crate::engine::{
    CollisionMap, EngineError, NoSplitting, Splitting, SumNoSplitting, TimeStepped,
};
use crate::geometry::{DimensionChoice, Geometry};
use crate::kernel::Kernel;
use crate::math::Real;
use crate::mixture::{
    MixtureNoSplitting, MixtureSplitting, MixtureTimeStepped, PairLaw, PairPhysics, StartError,
};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::restitution::{Constant, ImpactSpeed, Restitution};
use crate::rough::{RoughMap, RoughNoise};
use crate::weighted::nosplit::WeightedNoSplitting;
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
pub(super) use built;

impl Model {
    pub(super) fn by_scheme<K: Kernel, D: Drive, A: Restitution, G: Geometry>(
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
            #[cfg(feature = "weighted")]
            SchemeModel::Weighted(w) => built!(feature = "weighted", "weighted", {
                let start = || {
                    let mut e = WeightedNoSplitting::<K, A, D, G>::start(
                        (k, a, d),
                        w.transfer,
                        w.reduction(self.n()),
                        p,
                        t0,
                    )?
                    .with_windows(w.split);
                    let obs = e.resync(p)?;
                    Ok((e, obs))
                };
                wrap(Exact::start(start), ByScheme::Weighted)
            }),
            SchemeModel::NoSplitting | SchemeModel::Splitting(..) | SchemeModel::TimeStepped(_) => {
                wrap(by_split(self.scheme, k, d, a, p, t0), ByScheme::Split)
            }
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
            Exact::start(|| started(MixtureNoSplitting::start_in(sp, physics, drives, p, t0))),
            ByMixtureScheme::NoSplitting,
        ),
        #[cfg(feature = "weighted")]
        SchemeModel::Weighted(_) => Err(WEIGHTED_SMOOTH),
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

#[cfg(feature = "weighted")] // validation refused a rough gas or a mixture before this
const WEIGHTED_SMOOTH: EngineError =
    EngineError::Invariant("validated: weighted: 1 smooth species");

/// An engine started, with its observables at the start.
pub(super) type Begun<E> = Result<(E, Observables), EngineError>;

/// The scheme level every family but the mixtures shares: the exact loop, a splitting or MS's
/// time-stepped scheme (smooth spheres' sum form is [`Model::by_scheme`]'s).
fn by_split<
    K: Kernel,
    D: Drive,
    A: CollisionMap + crate::engine::collision_map::Inertia,
    G: Geometry,
>(
    scheme: SchemeModel,
    k: K,
    d: D,
    a: A,
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<BySplit<K, D, A, G>> {
    match scheme {
        SchemeModel::NoSplitting => {
            let exact = Exact::start(|| NoSplitting::start_in(k, d, a, p, t0));
            wrap(exact, BySplit::NoSplitting)
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
        #[cfg(feature = "weighted")]
        SchemeModel::Weighted(_) => Err(WEIGHTED_SMOOTH),
    }
}

/// What builds one family's engine: the family's part of each level below the kernel (its
/// drives as its loops take them, its scheme level); [`by_kernel`], [`by_drive`] and
/// [`by_law`] are written once over it.
pub(super) trait Build {
    /// The family built.
    type F: Family;
    /// What the family's loops take for a drive `D`: `D` itself (one species) or one per
    /// species (a mixture).
    type Drives<D: Drive>;
    /// The validated physics.
    fn model(&self) -> &Model;
    /// The drive `d` as the family's loops take it (every species the same).
    fn each<D: Drive>(&self, d: D) -> Self::Drives<D>;
    /// The family's white noise, if any (a rough gas's on translation or rotation, per species).
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
pub(super) trait Law: Restitution {
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

/// Smooth particles of one species in dimension `G`.
pub(super) struct SmoothBuild<'a, G>(pub(super) &'a Model, pub(super) PhantomData<G>);
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
pub(super) struct RoughBuild<'a, G>(
    pub(super) &'a RoughModel,
    pub(super) &'a Model,
    pub(super) PhantomData<G>,
);
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
pub(super) struct MixtureBuild<'a, G: WhiteNoiseIn, P: PairModel> {
    mx: &'a MixtureModel,
    m: &'a Model,
    /// The pair types' constant laws.
    laws: &'a [P::Of<Constant>; MAX_PAIRS],
    /// Each species' white noise, when the physics has it.
    noises: Option<[P::Noise<G>; MAX_SPECIES]>,
}

impl<'a, G: WhiteNoiseIn> MixtureBuild<'a, G, SmoothPairs> {
    /// A mixture of smooth particles.
    pub(super) fn smooth(mx: &'a MixtureModel, m: &'a Model) -> Self {
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
    pub(super) fn rough(mx: &'a MixtureModel, r: &'a MixtureRotation, m: &'a Model) -> Self {
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

pub(super) fn wrap<E, F>(
    r: Result<(E, Observables), EngineError>,
    f: impl FnOnce(E) -> F,
) -> Result<(F, Observables), EngineError> {
    r.map(|(e, o)| (f(e), o))
}
