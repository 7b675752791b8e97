//! The validated mixture of a [`super::Physics`] with species: each rule from its own
//! constructor ([`Species::new`], [`Maxwellian::new`], the kernel's [`Kernel::scaled`],
//! [`Constant::new`], [`WhiteNoise::new`]), refusals named by species or pair.

use super::axes::WithKernel;
use super::error::{Param, PhysicsError, Problem};
use super::parts::{DriveModel, KernelModel, LawModel};
use super::rotation::{MixtureRotation, mixture_rotation};
use super::{DimensionChoice, MAX_PAIRS, MAX_SPECIES, Physics, SpeciesChoice};
use crate::drive::WhiteNoise;
use crate::kernel::{Kernel, KernelError};
use crate::math::Real;
use crate::mixture::{MixtureError, Species};
use crate::restitution::{ALPHA_RANGE, Constant, Restitution};
use crate::sample::{Maxwellian, ParamError};
use crate::vec3::Vec3;

/// What a [`super::Model`] keeps of a mixture: the validated [`MixtureModel`] when the build
/// holds mixtures (gdsmc-core's feature `mixtures`), else [`LeftOut`]: the rules were checked
/// all the same, and the start refuses it. Without mixtures a model is about 1.4 KB smaller
/// (a Cortex-M0 validates one in its 16 KiB of RAM).
#[cfg(feature = "mixtures")]
pub(super) type Kept = MixtureModel;
/// See the `mixtures` build's definition.
#[cfg(not(feature = "mixtures"))]
pub(super) type Kept = LeftOut;

/// A valid mixture a build without mixtures keeps: only whether its particles rotate.
#[cfg(not(feature = "mixtures"))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct LeftOut {
    rotates: bool,
}

/// What a model reads of the mixture it keeps ([`Kept`]).
pub(super) trait Slot: Sized {
    /// Keeps the validated mixture.
    fn keep(m: MixtureModel) -> Self;
    /// The mixture, when the build holds mixtures.
    fn model(&self) -> Option<&MixtureModel>;
    /// Whether its particles are rough.
    fn rotates(&self) -> bool;
}

impl Slot for MixtureModel {
    fn keep(m: MixtureModel) -> Self {
        m
    }
    fn model(&self) -> Option<&MixtureModel> {
        Some(self)
    }
    fn rotates(&self) -> bool {
        self.rotation.is_some()
    }
}

#[cfg(not(feature = "mixtures"))]
impl Slot for LeftOut {
    fn keep(m: MixtureModel) -> Self {
        LeftOut {
            rotates: m.rotation.is_some(),
        }
    }
    fn model(&self) -> Option<&MixtureModel> {
        None
    }
    fn rotates(&self) -> bool {
        self.rotates
    }
}

/// A mixture whose every rule holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MixtureModel {
    /// Counts and masses.
    pub species: Species,
    /// The start distribution of each species (a Maxwellian at rest).
    pub starts: [Maxwellian; MAX_SPECIES],
    /// The kernel factor `((d_s + d_t)/2)^2` of each pair type.
    pub factors: [Real; MAX_PAIRS],
    /// The restitution of each pair type (a constant law; under BRS's impact-speed law,
    /// which the model's `law` holds for every pair, these are 1 and unused).
    pub laws: [Constant; MAX_PAIRS],
    /// The white-noise drive of each species (with the white-noise drive).
    pub noises: [WhiteNoise; MAX_SPECIES],
    /// Rough particles: the pairs' laws and the species' spins; `None`: smooth particles.
    pub rotation: Option<MixtureRotation>,
}

/// Whether the kernel scaled by a pair's cross section ([`Kernel::scaled`]) exists.
struct Scaled(Real);
impl WithKernel for Scaled {
    type Out = Result<(), KernelError>;
    fn with<K: Kernel>(self, k: K) -> Result<(), KernelError> {
        k.scaled(self.0).map(|_| ())
    }
}

fn refuse<T>(param: Param, problem: Problem) -> Result<T, PhysicsError> {
    Err(PhysicsError { param, problem })
}

fn positive(param: Param, x: Real) -> Result<Real, PhysicsError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else if x.is_finite() {
        refuse(param, Problem::NotPositive(x))
    } else {
        refuse(param, Problem::NotFinite(x))
    }
}

fn start(k: usize, c: &SpeciesChoice) -> Result<Maxwellian, PhysicsError> {
    Maxwellian::new(c.mass, c.temperature, Vec3::ZERO).map_err(|e| {
        let (param, problem) = match e {
            ParamError::Temperature if c.temperature.is_finite() => (
                Param::SpeciesTemperature(k),
                Problem::Negative(c.temperature),
            ),
            ParamError::Temperature => (
                Param::SpeciesTemperature(k),
                Problem::NotFinite(c.temperature),
            ),
            ParamError::ThermalSpeed => (
                Param::SpeciesTemperature(k),
                Problem::ThermalSpeed(c.temperature),
            ),
            _ if c.mass.is_finite() => (Param::SpeciesMass(k), Problem::NotPositive(c.mass)),
            _ => (Param::SpeciesMass(k), Problem::NotFinite(c.mass)),
        };
        PhysicsError { param, problem }
    })
}

/// Validates the species of `physics` against the kernel, law and drive already validated
/// (every scheme takes a mixture); `None` when it has no species.
#[inline(never)]
pub(super) fn mixture(
    physics: &Physics,
    kernel: KernelModel,
    law: LawModel,
    drive: DriveModel,
) -> Result<Option<Kept>, PhysicsError> {
    let list = &physics.species;
    if list.is_empty() {
        return Ok(None);
    }
    let mut counts = [0usize; MAX_SPECIES];
    let mut masses = [1.0; MAX_SPECIES];
    let mut starts = [Maxwellian::standard(); MAX_SPECIES];
    let mut total = 0usize;
    for (k, c) in list.iter().enumerate() {
        if c.count == 0 {
            return refuse(Param::SpeciesCount(k), Problem::NotPositive(0.0));
        }
        starts[k] = start(k, c)?;
        positive(Param::SpeciesDiameter(k), c.diameter)?;
        counts[k] = c.count;
        masses[k] = c.mass;
        total = total.saturating_add(c.count);
    }
    if total != physics.n {
        return refuse(
            Param::N,
            Problem::DoesNotFit("must equal the sum of the species' counts"),
        );
    }
    let species =
        Species::new(&counts[..list.len()], &masses[..list.len()]).map_err(|e| match e {
            MixtureError::TooFewParticles => PhysicsError {
                param: Param::N,
                problem: Problem::TooFewParticles(total),
            },
            MixtureError::TooManyParticles => PhysicsError {
                param: Param::N,
                problem: Problem::TooManyParticles(total),
            },
            _ => PhysicsError {
                param: Param::Species,
                problem: Problem::DoesNotFit("is not a valid list of species"),
            },
        })?;
    let mut noises = [WhiteNoise::new(0.0).expect("0 is a valid strength"); MAX_SPECIES];
    // The declared drives act on every species as it is (the thermostats about the mixture's
    // flow velocity, which collisions and the thermostats keep; the constant force per unit
    // mass, its momentum-keeping correction weighted by mass, MS (62) for several masses; the
    // Langevin bath on each species with its own mass); every species meets a host medium's
    // one background with its own mass in BRS (3)'s ratio; white noise is each species' own.
    if drive.white_noise().is_some() {
        for (k, c) in list.iter().enumerate() {
            noises[k] = WhiteNoise::new(c.beta).ok_or(PhysicsError {
                param: Param::SpeciesBeta(k),
                problem: if c.beta.is_finite() {
                    Problem::Negative(c.beta)
                } else {
                    Problem::NotFinite(c.beta)
                },
            })?;
        }
    }
    // Each species' mass must place a declared drive (the Langevin bath's `T_b / m`).
    for (k, c) in list.iter().enumerate() {
        if !drive.places(c.mass) {
            return refuse(
                Param::SpeciesMass(k),
                Problem::DoesNotFit("is too small for the drive: its rates for this mass overflow"),
            );
        }
    }
    let types = species.pair_types();
    let base = match law {
        LawModel::Constant(a) => a,
        // BRS (9)-(10) is one law of the normal impact speed for every pair (the model's
        // `law`); the pairs' constants below are then 1 and unused.
        LawModel::ImpactSpeed(_) if !physics.pair_restitution.is_empty() => {
            return refuse(
                Param::PairRestitution(0, 0),
                Problem::DoesNotFit(
                    "is not used with the impact-speed law, which is one law for every pair",
                ),
            );
        }
        LawModel::ImpactSpeed(_) => Constant::new(1.0).expect("1 is a valid coefficient"),
    };
    let given = &physics.pair_restitution;
    if !given.is_empty() && given.len() != types {
        return refuse(
            Param::Species,
            Problem::DoesNotFit("need one restitution per species pair, or none"),
        );
    }
    let mut laws = [base; MAX_PAIRS];
    let mut factors = [1.0; MAX_PAIRS];
    for k in 0..types {
        let (s, t) = species.pair(k);
        if let Some(&alpha) = given.get(k) {
            laws[k] = Constant::new(alpha).map_err(|_| PhysicsError {
                param: Param::PairRestitution(s, t),
                problem: Problem::OutOfRange {
                    value: alpha,
                    range: ALPHA_RANGE,
                },
            })?;
        }
        // The pair's cross section: the square of its contact distance for spheres, the
        // distance itself for disks (the kernels' `C` is the total cross section).
        let d = 0.5 * (list[s].diameter + list[t].diameter);
        factors[k] = match physics.dimension {
            DimensionChoice::Three => d * d,
            DimensionChoice::Two => d,
        };
        if let Err(KernelError::C | KernelError::Strength) = kernel.with(Scaled(factors[k])) {
            return refuse(Param::SpeciesDiameter(t), Problem::Strength(factors[k]));
        }
    }
    for (k, c) in list.iter().enumerate() {
        let named = [
            (c.inertia, Param::SpeciesInertia(k)),
            (c.rotation_temperature, Param::SpeciesRotationTemperature(k)),
            (c.rotation_noise, Param::SpeciesRotationNoise(k)),
        ];
        for (value, param) in named {
            if value.is_some() && physics.rotation.is_none() {
                return refuse(
                    param,
                    Problem::DoesNotFit("is only used with rough particles"),
                );
            }
        }
    }
    let rotation = match physics.rotation {
        None if !physics.pair_tangential_restitution.is_empty() => {
            return refuse(
                Param::PairTangentialRestitution(0, 0),
                Problem::DoesNotFit("is only used with rough particles"),
            );
        }
        None => None,
        Some(r) => {
            let alphas: [Real; MAX_PAIRS] =
                core::array::from_fn(|k| laws[k].coefficient(Vec3::ZERO, Vec3::ZERO));
            let betas: [Real; MAX_SPECIES] = core::array::from_fn(|k| noises[k].beta());
            let driven = drive.white_noise().is_some();
            Some(mixture_rotation(
                physics,
                r,
                &species,
                &alphas[..types],
                driven.then_some(&betas[..list.len()]),
                drive.declared_kind().is_some(),
            )?)
        }
    };
    Ok(Some(Slot::keep(MixtureModel {
        species,
        starts,
        factors,
        laws,
        noises,
        rotation,
    })))
}
