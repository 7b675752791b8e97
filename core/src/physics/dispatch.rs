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

use super::engine::{
    ByDiskDrive, ByDrive, ByKernel, ByLaw, ByMixtureDrive, ByMixtureLaw, ByMixtureScheme,
    ByRoughDrive, ByRoughLaw, ByRoughMixtureDrive, ByScheme, BySplit, Engine, Family, Mixture,
    PairModel, Rough, RoughMixture, RoughPairs, Smooth, SmoothDisks,
};
use super::model::Model;
use super::parts::{DriveModel, KernelModel, LawModel, SchemeModel};
use super::rotation::{MixtureRotation, RoughModel};
use super::species::MixtureModel;
use super::{MAX_PAIRS, MAX_SPECIES};
use crate::drive::host_medium::BackgroundKernel;
use crate::drive::{Drive, HostMedium, NoDrive, WhiteNoiseIn};
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
                        wrap(
                            by_kernel(k, &MixtureBuild::<Spheres>(mx, self, PhantomData), p, t0),
                            Engine::Mixture,
                        )
                    })
                }
                (None, DimensionChoice::Two) => built!(
                    all(feature = "mixtures", feature = "disks"),
                    self.mixture_features(),
                    {
                        wrap(
                            by_kernel(k, &MixtureBuild::<Disks>(mx, self, PhantomData), p, t0),
                            Engine::DiskMixture,
                        )
                    }
                ),
                (Some(r), DimensionChoice::Three) => built!(
                    all(feature = "mixtures", feature = "rough"),
                    self.mixture_features(),
                    {
                        wrap(
                            by_kernel(
                                k,
                                &RoughMixtureBuild::<Spheres>(mx, r, self, PhantomData),
                                p,
                                t0,
                            ),
                            Engine::RoughMixture,
                        )
                    }
                ),
                (Some(r), DimensionChoice::Two) => built!(
                    all(feature = "mixtures", feature = "rough", feature = "disks"),
                    self.mixture_features(),
                    {
                        wrap(
                            by_kernel(
                                k,
                                &RoughMixtureBuild::<Disks>(mx, r, self, PhantomData),
                                p,
                                t0,
                            ),
                            Engine::RoughDiskMixture,
                        )
                    }
                ),
            };
        }
        match (&self.rough, self.dimension) {
            (Some(r), DimensionChoice::Three) => built!(feature = "rough", "rough", {
                wrap(
                    by_kernel(k, &RoughBuild::<Spheres>(r, self, PhantomData), p, t0),
                    Engine::Rough,
                )
            }),
            (Some(r), DimensionChoice::Two) => built!(
                all(feature = "rough", feature = "disks"),
                "rough` and `disks",
                {
                    wrap(
                        by_kernel(k, &RoughBuild::<Disks>(r, self, PhantomData), p, t0),
                        Engine::RoughDisks,
                    )
                }
            ),
            (None, DimensionChoice::Two) => built!(feature = "disks", "disks", {
                wrap(by_kernel(k, &DiskBuild(self), p, t0), Engine::Disks)
            }),
            (None, DimensionChoice::Three) => {
                wrap(by_kernel(k, &SmoothBuild(self), p, t0), Engine::Smooth)
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

    fn disk_drive<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByDiskDrive<K>, Observables), EngineError> {
        match self.drive {
            DriveModel::WhiteNoise(w) => built!(feature = "white-noise", "white-noise", {
                wrap(
                    self.by_law::<K, _, Disks>(k, Disks::noise(w), p, t0),
                    ByDiskDrive::WhiteNoise,
                )
            }),
            DriveModel::Gaussian(g) => built!(
                feature = "gaussian-thermostat",
                "gaussian-thermostat",
                wrap(
                    self.by_law::<K, _, Disks>(k, g, p, t0),
                    ByDiskDrive::Gaussian
                )
            ),
            DriveModel::ConstantForce(f) => built!(
                feature = "constant-force",
                "constant-force",
                wrap(
                    self.by_law::<K, _, Disks>(k, f, p, t0),
                    ByDiskDrive::ConstantForce
                )
            ),
            DriveModel::HostMaxwell(h) => built!(feature = "host-medium", "host-medium", {
                wrap(
                    self.by_law::<K, _, Disks>(k, h.in_dim::<Disks>(), p, t0),
                    ByDiskDrive::HostMaxwell,
                )
            }),
            DriveModel::HostHardSpheres(h) => built!(feature = "host-medium", "host-medium", {
                wrap(
                    self.by_law::<K, _, Disks>(k, h.in_dim::<Disks>(), p, t0),
                    ByDiskDrive::HostHardSpheres,
                )
            }),
            _ => built!(feature = "cooling", "cooling", {
                wrap(
                    self.by_law::<K, _, Disks>(k, NoDrive, p, t0),
                    ByDiskDrive::None,
                )
            }),
        }
    }

    fn by_drive<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByDrive<K>, Observables), EngineError> {
        match self.drive {
            DriveModel::None => built!(feature = "cooling", "cooling", {
                wrap(self.by_law(k, NoDrive, p, t0), ByDrive::None)
            }),
            DriveModel::WhiteNoise(d) => built!(feature = "white-noise", "white-noise", {
                wrap(self.by_law(k, d, p, t0), ByDrive::WhiteNoise)
            }),
            DriveModel::Gaussian(d) => built!(
                feature = "gaussian-thermostat",
                "gaussian-thermostat",
                wrap(self.by_law(k, d, p, t0), ByDrive::Gaussian)
            ),
            DriveModel::ConstantForce(d) => built!(
                feature = "constant-force",
                "constant-force",
                wrap(self.by_law(k, d, p, t0), ByDrive::ConstantForce)
            ),
            DriveModel::HostMaxwell(d) => built!(feature = "host-medium", "host-medium", {
                wrap(self.by_law(k, d, p, t0), ByDrive::HostMaxwell)
            }),
            DriveModel::HostHardSpheres(d) => built!(feature = "host-medium", "host-medium", {
                wrap(self.by_law(k, d, p, t0), ByDrive::HostHardSpheres)
            }),
        }
    }

    /// Smooth particles of one species in dimension `G`, by law.
    fn by_law<K: Kernel, D: Drive, G: Geometry>(
        &self,
        k: K,
        d: D,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByLaw<K, D, G>, Observables), EngineError> {
        match self.law {
            LawModel::Constant(a) => wrap(self.by_scheme(k, d, a, p, t0), ByLaw::Constant),
            LawModel::ImpactSpeed(a) => built!(feature = "impact-speed", "impact-speed", {
                wrap(self.by_scheme(k, d, a, p, t0), ByLaw::ImpactSpeed)
            }),
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

/// The mixture loop of kernel `k` (scaled per pair) in dimension `G` and the drive (none,
/// white noise per species, or the Gaussian thermostat). Never inlined: its large locals (the
/// pair table, the per-species observables) would otherwise sit in [`Model::start`]'s frame for
/// every physics (the firmware's peak stack went from 11.6 to 29.0 KiB when they did).
#[inline(never)]
fn mixture<K: Kernel, G: WhiteNoiseIn>(
    mx: &MixtureModel,
    k: K,
    m: &Model,
    p: &mut Particles<'_>,
    t0: Real,
) -> Result<(ByMixtureDrive<K, G>, Observables), EngineError> {
    match m.drive {
        DriveModel::WhiteNoise(_) => built!(feature = "white-noise", "white-noise", {
            wrap(
                mixture_law::<K, _, G>(mx, k, m, &mx.noises.map(G::noise), p, t0),
                ByMixtureDrive::WhiteNoise,
            )
        }),
        DriveModel::Gaussian(g) => built!(
            feature = "gaussian-thermostat",
            "gaussian-thermostat",
            wrap(
                mixture_law::<K, _, G>(mx, k, m, &[g; MAX_SPECIES], p, t0),
                ByMixtureDrive::Gaussian,
            )
        ),
        DriveModel::ConstantForce(f) => built!(feature = "constant-force", "constant-force", {
            wrap(
                mixture_law::<K, _, G>(mx, k, m, &[f; MAX_SPECIES], p, t0),
                ByMixtureDrive::ConstantForce,
            )
        }),
        DriveModel::HostMaxwell(h) => built!(feature = "host-medium", "host-medium", {
            wrap(
                mixture_law::<K, _, G>(mx, k, m, &species_hosts(mx, h)?, p, t0),
                ByMixtureDrive::HostMaxwell,
            )
        }),
        DriveModel::HostHardSpheres(h) => built!(feature = "host-medium", "host-medium", {
            wrap(
                mixture_law::<K, _, G>(mx, k, m, &species_hosts(mx, h)?, p, t0),
                ByMixtureDrive::HostHardSpheres,
            )
        }),
        _ => built!(feature = "cooling", "cooling", {
            wrap(
                mixture_law::<K, _, G>(mx, k, m, &[NoDrive; MAX_SPECIES], p, t0),
                ByMixtureDrive::None,
            )
        }),
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

/// A smooth mixture's law level: each pair type's constant, or BRS's impact-speed law for
/// every pair.
fn mixture_law<K: Kernel, D: Drive, G: Geometry>(
    mx: &MixtureModel,
    k: K,
    m: &Model,
    drives: &[D; MAX_SPECIES],
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<ByMixtureLaw<K, D, G>> {
    by_pair_law::<K, D, G, _>(mx, k, m, &mx.laws, |_, a| a, drives, p, t0)
}

/// The law level of every mixture (particle model `P`): each pair type's constant law in
/// `laws`, or BRS's impact-speed law for every pair, `with_law` putting it into a pair's law
/// (whose constant, 1, is then unused).
#[allow(clippy::too_many_arguments)]
fn by_pair_law<K: Kernel, D: Drive, G: Geometry, P: PairModel>(
    mx: &MixtureModel,
    k: K,
    m: &Model,
    laws: &[P::Of<Constant>; MAX_PAIRS],
    with_law: impl Fn(&P::Of<Constant>, ImpactSpeed) -> P::Of<ImpactSpeed>,
    drives: &[D; MAX_SPECIES],
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<ByMixtureLaw<K, D, G, P>> {
    match m.law {
        LawModel::ImpactSpeed(a) => built!(feature = "impact-speed", "impact-speed", {
            let physics = pair_table(mx, k, &laws.map(|l| with_law(&l, a)))?;
            wrap(
                start_mixture::<K, _, _, G>(mx, m.scheme, &physics, drives, p, t0),
                ByMixtureLaw::ImpactSpeed,
            )
        }),
        LawModel::Constant(_) => {
            let physics = pair_table(mx, k, laws)?;
            wrap(
                start_mixture::<K, _, _, G>(mx, m.scheme, &physics, drives, p, t0),
                ByMixtureLaw::Constant,
            )
        }
    }
}

/// A rough mixture in dimension `G`: no drive, white noise on translation and rotation per
/// species, or the Gaussian thermostat on translation.
#[inline(never)]
fn rough_mixture<K: Kernel, G: Geometry>(
    mx: &MixtureModel,
    rot: &MixtureRotation,
    m: &Model,
    k: K,
    p: &mut Particles<'_>,
    t0: Real,
) -> Result<(ByRoughMixtureDrive<K, G>, Observables), EngineError> {
    let laws = &rot.laws;
    if let DriveModel::Gaussian(g) = m.drive {
        // Validated: no rotational noise beside the thermostat.
        return built!(
            feature = "gaussian-thermostat",
            "gaussian-thermostat",
            wrap(
                rough_pairs::<K, _, G>(mx, laws, m, k, &[g; MAX_SPECIES], p, t0),
                ByRoughMixtureDrive::Gaussian
            )
        );
    }
    // Validated: the constant force and a host medium have no rotational noise beside them.
    if let DriveModel::ConstantForce(f) = m.drive {
        return built!(feature = "constant-force", "constant-force", {
            wrap(
                rough_pairs::<K, _, G>(mx, laws, m, k, &[f; MAX_SPECIES], p, t0),
                ByRoughMixtureDrive::ConstantForce,
            )
        });
    }
    if let DriveModel::HostMaxwell(h) = m.drive {
        return built!(feature = "host-medium", "host-medium", {
            wrap(
                rough_pairs::<K, _, G>(mx, laws, m, k, &species_hosts(mx, h)?, p, t0),
                ByRoughMixtureDrive::HostMaxwell,
            )
        });
    }
    if let DriveModel::HostHardSpheres(h) = m.drive {
        return built!(feature = "host-medium", "host-medium", {
            wrap(
                rough_pairs::<K, _, G>(mx, laws, m, k, &species_hosts(mx, h)?, p, t0),
                ByRoughMixtureDrive::HostHardSpheres,
            )
        });
    }
    match &rot.noises {
        Some(noises) => built!(feature = "white-noise", "white-noise", {
            let noises = noises.map(|w| w.in_dim::<G>());
            wrap(
                rough_pairs::<K, _, G>(mx, laws, m, k, &noises, p, t0),
                ByRoughMixtureDrive::Noise,
            )
        }),
        None => built!(feature = "cooling", "cooling", {
            wrap(
                rough_pairs::<K, _, G>(mx, laws, m, k, &[NoDrive; MAX_SPECIES], p, t0),
                ByRoughMixtureDrive::None,
            )
        }),
    }
}

/// A rough mixture's law level: [`by_pair_law`] over the pairs' rough laws `laws`.
fn rough_pairs<K: Kernel, D: Drive, G: Geometry>(
    mx: &MixtureModel,
    laws: &[crate::rough::RoughPairLaw; MAX_PAIRS],
    m: &Model,
    k: K,
    drives: &[D; MAX_SPECIES],
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<ByMixtureLaw<K, D, G, RoughPairs>> {
    by_pair_law::<K, D, G, RoughPairs>(mx, k, m, laws, |l, a| l.with_law(a), drives, p, t0)
}

/// The rough loop of kernel `k` in dimension `G`, by drive.
#[inline(never)]
fn rough<K: Kernel, G: Geometry>(
    r: &RoughModel,
    m: &Model,
    k: K,
    p: &mut Particles<'_>,
    t0: Real,
) -> Result<(ByRoughDrive<K, G>, Observables), EngineError> {
    // Validated: white noise (on translation or rotation) is `r.noise`; the other drives
    // act on translation alone.
    match (r.noise, m.drive) {
        (Some(d), _) => built!(feature = "white-noise", "white-noise", {
            wrap(
                rough_law::<K, _, G>(m, k, d.in_dim::<G>(), r, p, t0),
                ByRoughDrive::Noise,
            )
        }),
        (None, DriveModel::Gaussian(g)) => built!(
            feature = "gaussian-thermostat",
            "gaussian-thermostat",
            wrap(
                rough_law::<K, _, G>(m, k, g, r, p, t0),
                ByRoughDrive::Gaussian
            )
        ),
        (None, DriveModel::ConstantForce(f)) => built!(
            feature = "constant-force",
            "constant-force",
            wrap(
                rough_law::<K, _, G>(m, k, f, r, p, t0),
                ByRoughDrive::ConstantForce
            )
        ),
        (None, DriveModel::HostMaxwell(h)) => built!(feature = "host-medium", "host-medium", {
            wrap(
                rough_law::<K, _, G>(m, k, h.in_dim::<G>(), r, p, t0),
                ByRoughDrive::HostMaxwell,
            )
        }),
        (None, DriveModel::HostHardSpheres(h)) => {
            built!(feature = "host-medium", "host-medium", {
                wrap(
                    rough_law::<K, _, G>(m, k, h.in_dim::<G>(), r, p, t0),
                    ByRoughDrive::HostHardSpheres,
                )
            })
        }
        _ => built!(feature = "cooling", "cooling", {
            wrap(
                rough_law::<K, _, G>(m, k, NoDrive, r, p, t0),
                ByRoughDrive::None,
            )
        }),
    }
}

/// A rough gas's law level: the rough map of a constant `alpha`, or of BRS's impact-speed law
/// (the model's `law`; the map's own constant, 1, is then unused).
fn rough_law<K: Kernel, D: Drive, G: Geometry>(
    m: &Model,
    k: K,
    d: D,
    r: &RoughModel,
    p: &mut Particles<'_>,
    t0: Real,
) -> Begun<ByRoughLaw<K, D, G>> {
    match m.law {
        LawModel::Constant(_) => wrap(by_split(m.scheme, k, d, r.map, p, t0), ByRoughLaw::Constant),
        LawModel::ImpactSpeed(a) => built!(feature = "impact-speed", "impact-speed", {
            wrap(
                by_split(m.scheme, k, d, r.map.with_law(a), p, t0),
                ByRoughLaw::ImpactSpeed,
            )
        }),
    }
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

/// What builds one family's engine for any kernel: the level below [`by_kernel`].
trait Build {
    /// The family built.
    type F: Family;
    /// The family's engine for kernel `k`, started at `t0` on `p`.
    fn build<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(<Self::F as Family>::Of<K>, Observables), EngineError>;
}

/// The one kernel level of the dispatch, for every family. Out of line: each family's start
/// keeps its locals (a mixture's pair table, its per-species observables) in its own frame,
/// not in [`Model::start`]'s for every physics.
#[inline(never)]
fn by_kernel<B: Build>(
    kernel: KernelModel,
    b: &B,
    p: &mut Particles<'_>,
    t0: Real,
) -> Result<(ByKernel<B::F>, Observables), EngineError> {
    match kernel {
        KernelModel::Maxwell(k) => built!(feature = "maxwell", "maxwell", {
            wrap(b.build(k, p, t0), ByKernel::Maxwell)
        }),
        KernelModel::HardSpheres(k) => built!(feature = "hard-spheres", "hard-spheres", {
            wrap(b.build(k, p, t0), ByKernel::HardSpheres)
        }),
        KernelModel::Vhs(k) => built!(feature = "vhs", "vhs", {
            wrap(b.build(k, p, t0), ByKernel::Vhs)
        }),
    }
}

/// Smooth spheres of one species: by drive, law and scheme.
struct SmoothBuild<'a>(&'a Model);
impl Build for SmoothBuild<'_> {
    type F = Smooth;
    fn build<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByDrive<K>, Observables), EngineError> {
        self.0.by_drive(k, p, t0)
    }
}

/// Smooth disks: by drive.
struct DiskBuild<'a>(&'a Model);
impl Build for DiskBuild<'_> {
    type F = SmoothDisks;
    fn build<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByDiskDrive<K>, Observables), EngineError> {
        self.0.disk_drive(k, p, t0)
    }
}

/// Rough particles in dimension `G`: by drive.
struct RoughBuild<'a, G>(&'a RoughModel, &'a Model, PhantomData<G>);
impl<G: Geometry> Build for RoughBuild<'_, G> {
    type F = Rough<G>;
    fn build<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByRoughDrive<K, G>, Observables), EngineError> {
        rough(self.0, self.1, k, p, t0)
    }
}

/// A mixture of rough particles in dimension `G`.
struct RoughMixtureBuild<'a, G>(
    &'a MixtureModel,
    &'a MixtureRotation,
    &'a Model,
    PhantomData<G>,
);
impl<G: Geometry> Build for RoughMixtureBuild<'_, G> {
    type F = RoughMixture<G>;
    fn build<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByRoughMixtureDrive<K, G>, Observables), EngineError> {
        rough_mixture(self.0, self.1, self.2, k, p, t0)
    }
}

/// A mixture of smooth particles in dimension `G`: the pair kernels scaled from `k`, by drive.
struct MixtureBuild<'a, G>(&'a MixtureModel, &'a Model, PhantomData<G>);
impl<G: WhiteNoiseIn> Build for MixtureBuild<'_, G> {
    type F = Mixture<G>;
    fn build<K: Kernel>(
        &self,
        k: K,
        p: &mut Particles<'_>,
        t0: Real,
    ) -> Result<(ByMixtureDrive<K, G>, Observables), EngineError> {
        mixture(self.0, k, self.1, p, t0)
    }
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
