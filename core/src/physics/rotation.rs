//! The validated rotation of a [`super::Physics`] with rough particles: each rule from its own
//! constructor ([`RoughMap::new`] or [`RoughMap::for_disks`] for `alpha`, `beta`, `kappa`; [`Maxwellian::new`] for the
//! start of the rim velocities; [`RoughNoise::new`] for the drive), refusals named by the
//! rotation's parameters.

use super::error::{Param, PhysicsError, Problem};
use super::parts::{DriveModel, LawModel, SchemeModel};
use super::{DimensionChoice, Physics, RotationChoice};
use crate::math::Real;
use crate::restitution::Restitution;
use crate::rough::{RoughError, RoughMap, RoughNoise};
use crate::sample::{Maxwellian, ParamError};
use crate::vec3::Vec3;

/// A rough gas whose every rule holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughModel {
    /// The collision map (alpha, beta, kappa).
    pub map: RoughMap,
    /// The start distribution of the rim velocities: a Maxwellian of temperature
    /// `T_rot / kappa` per unit mass, so that `kappa <|w|^2>/3 = T_rot` (disks keep its `z`
    /// component: `kappa <w_z^2> = T_rot`).
    pub start: Maxwellian,
    /// The white noise on translation and rotation; `None`: no drive.
    pub noise: Option<RoughNoise>,
}

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

/// Validates the rotation of `physics` against the law, drive and scheme already validated;
/// `None` when its particles are smooth.
pub(super) fn rotation(
    physics: &Physics,
    law: LawModel,
    drive: DriveModel,
    scheme: SchemeModel,
) -> Result<Option<RoughModel>, PhysicsError> {
    let Some(r): Option<RotationChoice> = physics.rotation else {
        return Ok(None);
    };
    if !physics.species.is_empty() {
        return refuse(
            Param::Rotation,
            Problem::DoesNotFit("cannot be combined with species (a rough mixture)"),
        );
    }
    if !matches!(scheme, SchemeModel::NoSplitting) {
        return refuse(
            Param::Scheme,
            Problem::DoesNotFit("must be no-splitting for rough particles"),
        );
    }
    let alpha = match law {
        LawModel::Constant(a) => a.coefficient(Vec3::ZERO, Vec3::ZERO),
        LawModel::ImpactSpeed(_) => {
            return refuse(
                Param::Restitution,
                Problem::DoesNotFit("must be constant for rough particles"),
            );
        }
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
            param: Param::Restitution,
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
    let beta = match drive {
        DriveModel::None => None,
        DriveModel::WhiteNoise(w) => Some(w.beta()),
        _ => {
            return refuse(
                Param::Rotation,
                Problem::DoesNotFit(
                    "takes no drive or white noise (on translation, and `noise` on rotation)",
                ),
            );
        }
    };
    let noise = match (beta, r.noise > 0.0) {
        (None, false) => None,
        (b, _) => Some(RoughNoise::new(b.unwrap_or(0.0), r.noise, r.kappa).ok_or(
            PhysicsError {
                param: Param::RotationNoise,
                problem: Problem::DoesNotFit(
                    "makes the rotational noise rate 2 noise / kappa overflow",
                ),
            },
        )?),
    };
    Ok(Some(RoughModel { map, start, noise }))
}
