//! The validated physics: the building blocks of the event loop, each made by its own
//! constructor (which holds the rule) from the parameters of a [`Physics`].

use super::error::{Param, PhysicsError, Problem};
use super::{BackgroundKernel, DriveChoice, KernelChoice, Physics, RestitutionLaw, SchemeChoice};
use super::{Component, MAX_COMPONENTS};
use crate::drive::host_medium::HostMediumError;
use crate::drive::{
    ConstantForce, Drive, GaussianThermostat, HardSphereBackground, HostMedium, HostMediumParams,
    MaxwellBackground, WhiteNoise,
};
use crate::engine::{SplittingOrder, check_step};
use crate::kernel::{HardSpheres, Kernel, KernelError, Maxwell, Vhs};
use crate::math::Real;
use crate::particles::{ParticlesError, check_count};
use crate::restitution::{Constant, ImpactSpeed, ImpactSpeedError};
use crate::sample::{Maxwellian, MaxwellianMixture, ParamError};
use crate::vec3::Vec3;

/// The validated kernel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum KernelModel {
    Maxwell(Maxwell),
    HardSpheres(HardSpheres),
    Vhs(Vhs),
}

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

/// The validated scheme; the time-stepped scheme carries its hard-sphere kernel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum SchemeModel {
    NoSplitting,
    Splitting(SplittingOrder, Real),
    TimeStepped(HardSpheres, Real),
}

/// A [`Physics`] whose every rule holds, ready to start engines ([`Model::start`]).
#[derive(Clone, Debug)]
pub struct Model {
    n: usize,
    initial: MaxwellianMixture<MAX_COMPONENTS>,
    pub(super) kernel: KernelModel,
    pub(super) law: LawModel,
    pub(super) drive: DriveModel,
    pub(super) scheme: SchemeModel,
    pub(super) mixture: Option<super::species::MixtureModel>,
    pub(super) rough: Option<super::rotation::RoughModel>,
    pub(super) dimension: super::DimensionChoice,
    /// Hard spheres with no drive run on the sum-form majorant ([`crate::engine::SumNoSplitting`]);
    /// false: on `Umax` ([`crate::engine::NoSplitting`]), for comparisons.
    pub(super) sum_form: bool,
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
fn initial(components: &[Component]) -> Result<MaxwellianMixture<MAX_COMPONENTS>, PhysicsError> {
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

fn kernel(k: KernelChoice) -> Result<KernelModel, PhysicsError> {
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

fn law(r: RestitutionLaw) -> Result<LawModel, PhysicsError> {
    match r {
        RestitutionLaw::Constant(alpha) => {
            Constant::new(alpha)
                .map(LawModel::Constant)
                .ok_or(PhysicsError {
                    param: Param::Restitution,
                    problem: Problem::OutOfRange {
                        value: alpha,
                        range: "(0, 1]",
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

fn drive(d: DriveChoice) -> Result<DriveModel, PhysicsError> {
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

fn scheme(s: SchemeChoice, k: KernelModel, d: DriveChoice) -> Result<SchemeModel, PhysicsError> {
    Ok(match s {
        SchemeChoice::NoSplitting => {
            if let DriveChoice::ConstantForce(_) = d {
                return err(
                    Param::Scheme,
                    Problem::DoesNotFit(
                        "must be time-stepped, Euler or Strang with the constant-force drive: its \
                         momentum-keeping correction (MS (62)) couples all particles at every \
                         step, which the lazy no-splitting scheme cannot do",
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
            let f = check_step(f).map_err(|_| not_positive(Param::StepFactor, f))?;
            let KernelModel::HardSpheres(hs) = k else {
                return err(
                    Param::Scheme,
                    Problem::DoesNotFit("time-stepped (MS Section 3) needs the hard-sphere kernel"),
                );
            };
            SchemeModel::TimeStepped(hs, f)
        }
    })
}

impl Model {
    /// Validates `physics` (see [`Physics::validate`]).
    pub fn new(physics: &Physics) -> Result<Self, PhysicsError> {
        particle_count(physics.n)?;
        let initial = initial(&physics.initial)?;
        let kernel = kernel(physics.kernel)?;
        let law = law(physics.restitution)?;
        let drive = drive(physics.drive)?;
        let scheme = scheme(physics.scheme, kernel, physics.drive)?;
        let mixture = super::species::mixture(physics, kernel, law, drive, scheme)?;
        let dimension = super::dimension::dimension(physics, law, drive, scheme)?;
        let rough = super::rotation::rotation(physics, law, drive, scheme)?;
        Ok(Model {
            n: physics.n,
            initial,
            kernel,
            law,
            drive,
            scheme,
            mixture,
            rough,
            dimension,
            sum_form: true,
        })
    }

    /// The same model on the `Umax` majorant of GRW step 1.4 for hard spheres with no drive
    /// (the loop before the sum form): the same process, for comparisons and benchmarks.
    pub fn with_umax_majorant(mut self) -> Self {
        self.sum_form = false;
        self
    }

    /// The dimension (spheres or disks).
    pub fn dimension(&self) -> super::DimensionChoice {
        self.dimension
    }

    /// Particles per system.
    pub fn n(&self) -> usize {
        self.n
    }

    /// The collision map of a rough gas (`None`: smooth particles, no spins needed).
    pub fn rough_map(&self) -> Option<&crate::rough::RoughMap> {
        self.rough.as_ref().map(|r| &r.map)
    }

    /// The species of a mixture (`None`: one species).
    pub fn species(&self) -> Option<&crate::mixture::Species> {
        self.mixture.as_ref().map(|m| &m.species)
    }

    /// The initial distribution as a sampler (of a one-species gas; a mixture's species start
    /// from their own Maxwellians).
    pub fn initial(&self) -> &MaxwellianMixture<MAX_COMPONENTS> {
        &self.initial
    }

    /// The exact schemes' candidate rate of `n` particles whose relative speeds stay below
    /// `umax`, `2 pi gamma C_lambda (n - 1) Umax^lambda` (GRW Section 3, RW (20)): the
    /// kernel's [`Kernel::majorant_rate`], for estimates made before any engine exists.
    pub fn majorant_rate(&self, n: usize, umax: Real) -> Real {
        match self.kernel {
            KernelModel::Maxwell(k) => k.majorant_rate(n, umax),
            KernelModel::HardSpheres(k) => k.majorant_rate(n, umax),
            KernelModel::Vhs(k) => k.majorant_rate(n, umax),
        }
    }

    /// The candidate rate of one grain's background events, a grain of speed `speed` taken
    /// as far from the background's drift as it can be (`|v - u^B| <= speed + |u^B|`): a host
    /// medium's bound, `4 pi C_1 rho^B` (BRS (11)) or BRS (28) ([`Drive::event_rate`]); 0
    /// without a host medium.
    pub fn background_rate(&self, speed: Real) -> Real {
        match self.drive {
            DriveModel::HostMaxwell(d) => d.event_rate(speed),
            DriveModel::HostHardSpheres(d) => d.event_rate(speed),
            _ => 0.0,
        }
    }
}
