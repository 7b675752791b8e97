//! The validated building blocks of the event loop (kernel, restitution law, drive, scheme,
//! initial distribution), each made by its own constructor, which holds the rule, from the
//! parameters of a [`super::Physics`]. The axes that combine them ([`super::species`],
//! [`super::rotation`], [`super::dimension`]) and the [`super::Model`] that composes them all
//! build on these.

use super::axes::{WithKernel, kernel_table};
use super::error::{Param, PhysicsError, Problem};
use super::{BackgroundKernel, DriveChoice, KernelChoice, RestitutionLaw, SchemeChoice};
use super::{Component, MAX_COMPONENTS};
use crate::drive::host_medium::HostMediumError;
use crate::drive::{
    ConstantForce, GaussianThermostat, HardSphereBackground, HostMedium, HostMediumParams,
    MaxwellBackground, WhiteNoise,
};
use crate::engine::{SplittingOrder, check_step};
use crate::kernel::{HardSpheres, KernelError, Maxwell, Vhs};
use crate::math::Real;
use crate::particles::{ParticlesError, check_count};
use crate::restitution::{ALPHA_RANGE, Constant, ImpactSpeed, ImpactSpeedError};
use crate::sample::{Maxwellian, MaxwellianMixture, ParamError};
use crate::vec3::Vec3;

/// Generates [`KernelModel`] from the kernel table ([`kernel_table`]).
macro_rules! kernel_model {
    ($($v:ident($t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
        /// The validated kernel (generated from the kernel table, [`super::axes`]).
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub(super) enum KernelModel {
            $(#[doc = $doc] $v($t),)*
        }

        impl KernelModel {
            /// Does `w` with the kernel this holds.
            pub(super) fn with<W: WithKernel>(self, w: W) -> W::Out {
                match self {
                    $(Self::$v(k) => w.with(k),)*
                }
            }
        }
    };
}
kernel_table!(kernel_model);

/// The validated restitution law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum LawModel {
    Constant(Constant),
    ImpactSpeed(ImpactSpeed),
}

/// The validated drive.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum DriveModel {
    None,
    WhiteNoise(WhiteNoise),
    Gaussian(GaussianThermostat),
    ConstantForce(ConstantForce),
    HostMaxwell(HostMedium<MaxwellBackground>),
    HostHardSpheres(HostMedium<HardSphereBackground>),
}

/// The validated scheme.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum SchemeModel {
    NoSplitting,
    Splitting(SplittingOrder, Real),
    TimeStepped(Real),
}

fn err<T>(param: Param, problem: Problem) -> Result<T, PhysicsError> {
    Err(PhysicsError { param, problem })
}

/// The problem of a value that a constructor refused for not being finite and > 0.
fn not_positive(param: Param, x: Real) -> PhysicsError {
    let problem = if x.is_finite() {
        Problem::NotPositive(x)
    } else {
        Problem::NotFinite(x)
    };
    PhysicsError { param, problem }
}

/// The problem of a value that a constructor refused for not being finite and >= 0.
fn negative(param: Param, x: Real) -> PhysicsError {
    let problem = if x.is_finite() {
        Problem::Negative(x)
    } else {
        Problem::NotFinite(x)
    };
    PhysicsError { param, problem }
}

/// The rule for the particle count ([`check_count`]) as a physics error.
pub(crate) fn particle_count(n: usize) -> Result<(), PhysicsError> {
    check_count(n).or_else(|e| match e {
        ParticlesError::TooFew => err(Param::N, Problem::TooFewParticles(n)),
        ParticlesError::TooMany => err(Param::N, Problem::TooManyParticles(n)),
        ParticlesError::SpinCount => unreachable!("check_count does not look at spins"),
    })
}

fn vec3(v: [Real; 3]) -> Vec3 {
    Vec3::new(v[0], v[1], v[2])
}

/// A Maxwellian (BRS (36)) from [`Maxwellian::new`], its refusal named by `names`.
fn maxwellian(
    mass: Real,
    temperature: Real,
    drift: [Real; 3],
    names: [Param; 3],
) -> Result<Maxwellian, PhysicsError> {
    Maxwellian::new(mass, temperature, vec3(drift)).map_err(|e| match e {
        ParamError::Temperature => negative(names[1], temperature),
        ParamError::ThermalSpeed => PhysicsError {
            param: names[1],
            problem: Problem::ThermalSpeed(temperature),
        },
        ParamError::Drift => PhysicsError {
            param: names[2],
            problem: Problem::NotFiniteVector,
        },
        _ => not_positive(names[0], mass),
    })
}

/// The initial mixture (BRS (35)); the component rules live in [`Maxwellian::new`] and
/// [`MaxwellianMixture::push`].
#[inline(never)]
pub(super) fn initial(
    components: &[Component],
) -> Result<MaxwellianMixture<MAX_COMPONENTS>, PhysicsError> {
    if components.is_empty() {
        return err(Param::Components, Problem::NoComponents);
    }
    let mut mix = MaxwellianMixture::new();
    for (k, c) in components.iter().enumerate() {
        let names = [Param::Mass(k), Param::Temperature(k), Param::Drift(k)];
        let m = maxwellian(c.mass, c.temperature, c.drift, names)?;
        mix.push(c.weight, m)
            .map_err(|_| negative(Param::Weight(k), c.weight))?;
    }
    if mix.check().is_err() {
        return err(Param::Components, Problem::AllWeightsZero);
    }
    Ok(mix)
}

pub(super) fn kernel(k: KernelChoice) -> Result<KernelModel, PhysicsError> {
    let (gamma, c) = match k {
        KernelChoice::Maxwell { gamma, c }
        | KernelChoice::HardSpheres { gamma, c }
        | KernelChoice::Vhs { gamma, c, .. } => (gamma, c),
    };
    let refused = |e| match e {
        KernelError::Gamma => not_positive(Param::Gamma, gamma),
        KernelError::C => not_positive(Param::C, c),
        KernelError::Strength => PhysicsError {
            param: Param::Gamma,
            problem: Problem::Strength(gamma * c),
        },
        KernelError::Lambda => {
            let KernelChoice::Vhs { lambda, .. } = k else {
                unreachable!("only VHS has an exponent")
            };
            PhysicsError {
                param: Param::Lambda,
                problem: Problem::OutOfRange {
                    value: lambda,
                    range: "[0, 1]",
                },
            }
        }
    };
    Ok(match k {
        KernelChoice::Maxwell { .. } => {
            KernelModel::Maxwell(Maxwell::new(gamma, c).map_err(refused)?)
        }
        KernelChoice::HardSpheres { .. } => {
            KernelModel::HardSpheres(HardSpheres::new(gamma, c).map_err(refused)?)
        }
        KernelChoice::Vhs { lambda, .. } => {
            KernelModel::Vhs(Vhs::new(gamma, c, lambda).map_err(refused)?)
        }
    })
}

pub(super) fn law(r: RestitutionLaw) -> Result<LawModel, PhysicsError> {
    match r {
        RestitutionLaw::Constant(alpha) => {
            Constant::new(alpha)
                .map(LawModel::Constant)
                .map_err(|_| PhysicsError {
                    param: Param::Restitution,
                    problem: Problem::OutOfRange {
                        value: alpha,
                        range: ALPHA_RANGE,
                    },
                })
        }
        RestitutionLaw::ImpactSpeed { beta0, delta } => ImpactSpeed::new(beta0, delta)
            .map(LawModel::ImpactSpeed)
            .map_err(|e| match e {
                ImpactSpeedError::Beta0 => negative(Param::Beta0, beta0),
                ImpactSpeedError::Delta => negative(Param::Delta, delta),
            }),
    }
}

pub(super) fn drive(d: DriveChoice) -> Result<DriveModel, PhysicsError> {
    Ok(match d {
        DriveChoice::None => DriveModel::None,
        DriveChoice::WhiteNoise(beta) => DriveModel::WhiteNoise(
            WhiteNoise::new(beta).ok_or_else(|| negative(Param::Beta, beta))?,
        ),
        DriveChoice::Gaussian(zeta) => {
            DriveModel::Gaussian(GaussianThermostat::new(zeta).ok_or(PhysicsError {
                param: Param::Zeta,
                problem: Problem::NotFinite(zeta),
            })?)
        }
        DriveChoice::ConstantForce(g) => {
            DriveModel::ConstantForce(ConstantForce::new(g).ok_or_else(|| negative(Param::G, g))?)
        }
        DriveChoice::HostMedium {
            kernel,
            c1,
            density,
            mass,
            temperature,
            drift,
        } => {
            let names = [
                Param::BackgroundMass,
                Param::BackgroundTemperature,
                Param::BackgroundDrift,
            ];
            let bg = maxwellian(mass, temperature, drift, names)?;
            let params = HostMediumParams::new(bg, density, c1).map_err(|e| match e {
                HostMediumError::Density => not_positive(Param::BackgroundDensity, density),
                HostMediumError::Strength => not_positive(Param::BackgroundC, c1),
            })?;
            match kernel {
                BackgroundKernel::Maxwell => {
                    DriveModel::HostMaxwell(HostMedium::new(params, MaxwellBackground))
                }
                BackgroundKernel::HardSpheres => {
                    DriveModel::HostHardSpheres(HostMedium::new(params, HardSphereBackground))
                }
            }
        }
    })
}

pub(super) fn scheme(s: SchemeChoice, d: DriveChoice) -> Result<SchemeModel, PhysicsError> {
    Ok(match s {
        SchemeChoice::NoSplitting => {
            if let DriveChoice::ConstantForce(_) = d {
                return err(
                    Param::Scheme,
                    Problem::DoesNotFit(
                        "must be time-stepped, Euler or Strang with the constant-force drive: the \
                         no-splitting scheme is exact because it moves each particle alone \
                         between its collisions, and the force's momentum-keeping correction \
                         (MS (62)) makes every particle's free motion depend on all the others' \
                         (coupled equations with no closed form), so no exact scheme exists for it",
                    ),
                );
            }
            SchemeModel::NoSplitting
        }
        SchemeChoice::Euler(dt) => SchemeModel::Splitting(
            SplittingOrder::Euler,
            check_step(dt).map_err(|_| not_positive(Param::Dt, dt))?,
        ),
        SchemeChoice::Strang(dt) => SchemeModel::Splitting(
            SplittingOrder::Strang,
            check_step(dt).map_err(|_| not_positive(Param::Dt, dt))?,
        ),
        SchemeChoice::TimeStepped(f) => {
            SchemeModel::TimeStepped(check_step(f).map_err(|_| not_positive(Param::StepFactor, f))?)
        }
    })
}
