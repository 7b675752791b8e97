//! The validated rotation of a [`super::Physics`] with rough particles: each rule from its own
//! constructor ([`RoughMap::new`] or [`RoughMap::for_disks`] for `alpha`, `beta`, `kappa`; [`Maxwellian::new`] for the
//! start of the rim velocities; [`RoughNoise::new`] for the drive), refusals named by the
//! rotation's parameters.

use super::error::{Param, PhysicsError, Problem};
use super::parts::{DriveModel, LawModel};
use super::{DimensionChoice, MAX_PAIRS, MAX_SPECIES, Physics, RotationChoice};
use crate::math::Real;
use crate::restitution::Restitution;
use crate::rough::{RoughError, RoughMap, RoughNoise, RoughPairLaw};
use crate::sample::{Maxwellian, ParamError};
use crate::vec3::Vec3;

/// A rough gas whose every rule holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughModel {
    /// The collision map (alpha, beta, kappa); with the impact-speed law (the model's law,
    /// which the engine puts into this map) its constant alpha is 1 and unused.
    pub map: RoughMap,
    /// The start distribution of the rim velocities: a Maxwellian of temperature
    /// `T_rot / kappa` per unit mass, so that `kappa <|w|^2>/3 = T_rot` (disks keep its `z`
    /// component: `kappa <w_z^2> = T_rot`).
    pub start: Maxwellian,
    /// The white noise on translation and rotation; `None`: no drive.
    pub noise: Option<RoughNoise>,
}

/// What rotational noise takes beside it (one species or a mixture).
const NOISE_BESIDE: &str = "takes only no drive or white noise on translation beside it (the \
                            thermostats and the host medium are not combined with rotational \
                            noise)";

fn refuse<T>(param: Param, problem: Problem) -> Result<T, PhysicsError> {
    Err(PhysicsError { param, problem })
}

fn at_least_zero(param: Param, x: Real) -> Result<Real, PhysicsError> {
    if x.is_finite() && x >= 0.0 {
        Ok(x)
    } else if x.is_finite() {
        refuse(param, Problem::Negative(x))
    } else {
        refuse(param, Problem::NotFinite(x))
    }
}

/// The rotation of a rough mixture: each pair's law, each species' rim-velocity start and
/// noise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MixtureRotation {
    /// The law of each pair type (alpha, beta, the partners' kappa); with the impact-speed law
    /// (the model's law, which the engine puts into these) each constant alpha is 1 and unused.
    pub laws: [RoughPairLaw; MAX_PAIRS],
    /// Each species' start distribution of the rim velocities: a Maxwellian of mass `m_s`
    /// and temperature `T_rot,s / kappa_s`, so that `m_s kappa_s <|w|^2>/d_rot = T_rot,s`.
    pub starts: [Maxwellian; MAX_SPECIES],
    /// Each species' white noise on translation and rotation; `None`: no drive.
    pub noises: Option<[RoughNoise; MAX_SPECIES]>,
}

/// The kappa of `dimension`'s rough particles by [`RoughMap`]'s rule, its refusal named `param`.
fn inertia(param: Param, kappa: Real, dimension: DimensionChoice) -> Result<Real, PhysicsError> {
    let map = match dimension {
        DimensionChoice::Three => RoughMap::new(1.0, 0.0, kappa),
        DimensionChoice::Two => RoughMap::for_disks(1.0, 0.0, kappa),
    };
    map.map(|_| kappa).map_err(|_| PhysicsError {
        param,
        problem: if kappa.is_finite() {
            Problem::OutOfRange {
                value: kappa,
                range: match dimension {
                    DimensionChoice::Three => "(0, 2/3]",
                    DimensionChoice::Two => "(0, 1] for disks",
                },
            }
        } else {
            Problem::NotFinite(kappa)
        },
    })
}

/// Validates a rough mixture's rotation: `r` gives every species' and pair's value unless
/// `physics` names its own; `alphas` are the pairs' validated normal restitutions, `betas`
/// the species' translational noise (white noise; `None`: no white noise), `thermostat`
/// whether the Gaussian thermostat acts on translation (then no species takes rotational
/// noise).
#[inline(never)]
pub(super) fn mixture_rotation(
    physics: &Physics,
    r: RotationChoice,
    species: &crate::mixture::Species,
    alphas: &[Real],
    betas: Option<&[Real]>,
    thermostat: bool,
) -> Result<MixtureRotation, PhysicsError> {
    let dim = physics.dimension;
    let list = &physics.species;
    let mut kappa = [0.4; MAX_SPECIES];
    let mut starts = [Maxwellian::standard(); MAX_SPECIES];
    let mut noises = [RoughNoise::new(None, 0.0, 1.0).expect("no noise"); MAX_SPECIES];
    let mut driven = betas.is_some();
    for (k, c) in list.iter().enumerate() {
        let (kp, kp_param) = match c.inertia {
            Some(x) => (x, Param::SpeciesInertia(k)),
            None => (r.kappa, Param::Inertia),
        };
        kappa[k] = inertia(kp_param, kp, dim)?;
        let (t, t_param) = match c.rotation_temperature {
            Some(x) => (x, Param::SpeciesRotationTemperature(k)),
            None => (r.temperature, Param::RotationTemperature),
        };
        at_least_zero(t_param, t)?;
        starts[k] = Maxwellian::new(species.mass(k), t / kappa[k], Vec3::ZERO).map_err(|_| {
            PhysicsError {
                param: t_param,
                problem: Problem::DoesNotFit(
                    "is too large for this species' mass and inertia: T_rot / (m kappa), the \
                     spins' temperature per unit mass, overflows",
                ),
            }
        })?;
        let (w, w_param) = match c.rotation_noise {
            Some(x) => (x, Param::SpeciesRotationNoise(k)),
            None => (r.noise, Param::RotationNoise),
        };
        at_least_zero(w_param, w)?;
        if thermostat && w > 0.0 {
            return refuse(w_param, Problem::DoesNotFit(NOISE_BESIDE));
        }
        driven |= w > 0.0;
        let beta = betas.map(|b| b[k]);
        noises[k] = RoughNoise::new(beta, w, kappa[k]).ok_or(PhysicsError {
            param: w_param,
            problem: Problem::DoesNotFit(
                "makes the rotational noise rate 2 noise / kappa overflow",
            ),
        })?;
    }
    let given = &physics.pair_tangential_restitution;
    let types = alphas.len();
    if !given.is_empty() && given.len() != types {
        return refuse(
            Param::Species,
            Problem::DoesNotFit("need one tangential restitution per species pair, or none"),
        );
    }
    let mut laws = [RoughPairLaw::new(1.0, 0.0, 0.4, 0.4).expect("valid"); MAX_PAIRS];
    for (k, law) in laws.iter_mut().enumerate().take(types) {
        let (s, t) = species.pair(k);
        let (beta, param) = match given.get(k) {
            Some(&b) => (b, Param::PairTangentialRestitution(s, t)),
            None => (r.beta, Param::TangentialRestitution),
        };
        let made = match dim {
            DimensionChoice::Three => RoughPairLaw::new(alphas[k], beta, kappa[s], kappa[t]),
            DimensionChoice::Two => RoughPairLaw::for_disks(alphas[k], beta, kappa[s], kappa[t]),
        };
        // alpha and both kappas passed their rules above: only beta can be refused here.
        *law = made.map_err(|_| PhysicsError {
            param,
            problem: if beta.is_finite() {
                Problem::OutOfRange {
                    value: beta,
                    range: "[-1, 1]",
                }
            } else {
                Problem::NotFinite(beta)
            },
        })?;
    }
    Ok(MixtureRotation {
        laws,
        starts,
        noises: driven.then_some(noises),
    })
}

/// Validates the rotation of `physics` against the law and drive already validated (every
/// scheme takes rough particles);
/// `None` when its particles are smooth or form a mixture ([`mixture_rotation`]).
#[inline(never)]
pub(super) fn rotation(
    physics: &Physics,
    law: LawModel,
    drive: DriveModel,
) -> Result<Option<RoughModel>, PhysicsError> {
    let Some(r): Option<RotationChoice> = physics.rotation else {
        return Ok(None);
    };
    if !physics.species.is_empty() {
        return Ok(None);
    }
    // BRS's impact-speed law (9) gives alpha at each collision's normal impact speed (the
    // dispatch puts the model's `law` into the map); the map's own constant is then 1, unused.
    let alpha = match law {
        LawModel::Constant(a) => a.coefficient(Vec3::ZERO, Vec3::ZERO),
        LawModel::ImpactSpeed(_) => 1.0,
    };
    let outside = |param, value: Real, range| PhysicsError {
        param,
        problem: if value.is_finite() {
            Problem::OutOfRange { value, range }
        } else {
            Problem::NotFinite(value)
        },
    };
    let map = match physics.dimension {
        DimensionChoice::Three => RoughMap::new(alpha, r.beta, r.kappa),
        DimensionChoice::Two => RoughMap::for_disks(alpha, r.beta, r.kappa),
    };
    let map = map.map_err(|e| match e {
        RoughError::Beta => outside(Param::TangentialRestitution, r.beta, "[-1, 1]"),
        RoughError::Kappa => outside(Param::Inertia, r.kappa, "(0, 2/3]"),
        RoughError::DiskKappa => outside(Param::Inertia, r.kappa, "(0, 1] for disks"),
        // alpha passed the law's own rule, which is the map's.
        RoughError::Alpha => PhysicsError {
            param: Param::Law(super::LawKind::Constant, 0),
            problem: Problem::OutOfRange {
                value: alpha,
                range: crate::restitution::ALPHA_RANGE,
            },
        },
    })?;
    at_least_zero(Param::RotationTemperature, r.temperature)?;
    let start = Maxwellian::new(1.0, r.temperature / r.kappa, Vec3::ZERO).map_err(|e| {
        // A temperature that is fine alone overflows only through a tiny kappa: that is the
        // parameter to change.
        if Maxwellian::new(1.0, r.temperature, Vec3::ZERO).is_ok() {
            return PhysicsError {
                param: Param::Inertia,
                problem: Problem::DoesNotFit(
                    "is too small for the rotation's start temperature: T_rot / kappa, the \
                     spins' temperature, overflows",
                ),
            };
        }
        let problem = match e {
            ParamError::ThermalSpeed => Problem::ThermalSpeed(r.temperature),
            _ => Problem::NotFinite(r.temperature / r.kappa),
        };
        PhysicsError {
            param: Param::RotationTemperature,
            problem,
        }
    })?;
    at_least_zero(Param::RotationNoise, r.noise)?;
    // The drives act on translation alone (the rotation's own drive is `noise`): the
    // Gaussian thermostat scales `v - V` (MS (12)), the constant force pushes along it (MS
    // (14)), and the host medium's encounters are BRS (2)'s smooth ones, which leave a grain's
    // spin as it is.
    let beta = match drive {
        DriveModel::None => None,
        DriveModel::WhiteNoise(w) => Some(w.beta()),
        _ if r.noise > 0.0 => {
            return refuse(Param::RotationNoise, Problem::DoesNotFit(NOISE_BESIDE));
        }
        _ => None,
    };
    let noise = match (beta, r.noise > 0.0) {
        (None, false) => None,
        (b, _) => Some(RoughNoise::new(b, r.noise, r.kappa).ok_or(PhysicsError {
            param: Param::RotationNoise,
            problem: Problem::DoesNotFit(
                "makes the rotational noise rate 2 noise / kappa overflow",
            ),
        })?),
    };
    Ok(Some(RoughModel { map, start, noise }))
}
