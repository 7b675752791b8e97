//! The validated building blocks of the event loop (kernel, restitution law, drive, scheme,
//! initial distribution), each made by its own constructor, which holds the rule, from the
//! parameters of a [`super::Physics`]. The axes that combine them ([`super::species`],
//! [`super::rotation`], [`super::dimension`]) and the [`super::Model`] that composes them all
//! build on these.

use super::axes::{WithKernel, kernel_table};
use super::error::{Param, PhysicsError, Problem};
use super::kinds::declared_drives;
use super::{BackgroundKernel, DriveChoice, KernelChoice, RestitutionLaw, SchemeChoice};
use super::{Component, DriveKind, DriveParams, KernelKind, MAX_COMPONENTS};
use crate::drive::host_medium::HostMediumError;
use crate::drive::{
    Declared, Drive, HardSphereBackground, Heating, HostMedium, HostMediumParams,
    MaxwellBackground, Rule, WhiteNoise, WorkInput,
};
use crate::engine::{SplittingOrder, check_step};
use crate::kernel::{Declared as DeclaredKernel, KernelError};
use crate::math::Real;
use crate::particles::{ParticlesError, check_count};
use crate::restitution::{Constant, ImpactSpeed, ImpactSpeedError};
use crate::sample::{Maxwellian, MaxwellianMixture, ParamError};
use crate::vec3::Vec3;

/// Generates [`KernelModel`] from the kernel table ([`kernel_table`]).
macro_rules! kernel_model {
    ($($v:ident($code:literal, $scene:literal, $t:ty, $feature:literal, $doc:literal)),* $(,)?) => {
        /// The validated kernel (generated from the kernel table, [`super::axes`]).
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub(super) enum KernelModel {
            $(#[doc = $doc] $v($t),)*
        }

        /// The validated kernel of `k`: `gamma`, `C` and each of its own parameters checked
        /// against its rule ([`crate::kernel::Declared`]), then built.
        pub(super) fn kernel(k: KernelChoice) -> Result<KernelModel, PhysicsError> {
            let (kind, gamma, c) = (k.kind(), k.gamma(), k.c());
            for (i, (spec, &x)) in k.specs().iter().zip(k.values()).enumerate() {
                if !spec.rule.holds(x) {
                    return Err(refusal(Param::Kernel(kind, i), spec.rule, x));
                }
            }
            let refused = |e| match e {
                KernelError::Gamma => not_positive(Param::Gamma, gamma),
                KernelError::C => not_positive(Param::C, c),
                KernelError::Strength => PhysicsError {
                    param: Param::Gamma,
                    problem: Problem::Strength(gamma * c),
                },
                KernelError::Param(i) => PhysicsError {
                    param: Param::Kernel(kind, i),
                    problem: Problem::DoesNotFit("makes the kernel's rate overflow"),
                },
            };
            match kind {
                $(KernelKind::$v => <$t as DeclaredKernel>::from_values(gamma, c, k.values())
                    .map(KernelModel::$v)
                    .map_err(refused),)*
            }
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

/// Generates [`DriveModel`] and the validation of a declared drive from the declared drives'
/// table ([`declared_drives`]).
macro_rules! drive_model {
    ($($v:ident($t:ty, $feature:literal)),* $(,)?) => {
        /// The validated drive (the declared drives' variants generated from their table,
        /// `physics/kinds.rs`).
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub(super) enum DriveModel {
            None,
            WhiteNoise(WhiteNoise),
            HostMaxwell(HostMedium<MaxwellBackground>),
            HostHardSpheres(HostMedium<HardSphereBackground>),
            $($v($t),)*
        }

        impl DriveModel {
            /// The white noise, if this is it.
            pub(super) fn white_noise(&self) -> Option<WhiteNoise> {
                match self {
                    DriveModel::WhiteNoise(w) => Some(*w),
                    DriveModel::None | DriveModel::HostMaxwell(_) | DriveModel::HostHardSpheres(_) => None,
                    $(DriveModel::$v(_) => None,)*
                }
            }

            /// The kind of a declared drive; `None` for none, white noise and the host medium.
            pub(super) fn declared_kind(&self) -> Option<DriveKind> {
                match self {
                    DriveModel::None | DriveModel::WhiteNoise(_) => None,
                    DriveModel::HostMaxwell(_) | DriveModel::HostHardSpheres(_) => None,
                    $(DriveModel::$v(_) => Some(DriveKind::$v),)*
                }
            }

            /// Whether a declared drive acts on a grain of mass `mass` ([`Declared::place`]);
            /// true for the others.
            pub(super) fn places(&self, mass: Real) -> bool {
                match self {
                    DriveModel::None | DriveModel::WhiteNoise(_) => true,
                    DriveModel::HostMaxwell(_) | DriveModel::HostHardSpheres(_) => true,
                    $(DriveModel::$v(d) => d.place::<crate::geometry::Spheres>(mass).is_some(),)*
                }
            }

            /// [`Drive::event_rate`] of a grain of speed at most `speed`.
            pub(super) fn event_rate(&self, speed: Real) -> Real {
                match self {
                    DriveModel::HostMaxwell(d) => d.event_rate(speed),
                    DriveModel::HostHardSpheres(d) => d.event_rate(speed),
                    DriveModel::None | DriveModel::WhiteNoise(_) => 0.0,
                    $(DriveModel::$v(d) => d.event_rate(speed),)*
                }
            }

            /// How the drive alone changes the temperature, when linearly ([`Heating`]): none
            /// and white noise (GRW (18)) besides the declared drives.
            pub(super) fn heating(&self) -> Option<Heating> {
                match self {
                    DriveModel::None => Some(Heating { a: 0.0, b: 0.0, p: 0.0 }),
                    DriveModel::WhiteNoise(w) => Some(Heating { a: 2.0 * w.beta(), b: 0.0, p: 0.0 }),
                    DriveModel::HostMaxwell(_) | DriveModel::HostHardSpheres(_) => None,
                    $(DriveModel::$v(d) => d.heating(),)*
                }
            }

            /// A declared drive's work bound ([`Declared::work`]); `None` for none, white noise
            /// and the host medium.
            pub(super) fn work(&self, w: WorkInput) -> Option<(Real, Real)> {
                match self {
                    DriveModel::None | DriveModel::WhiteNoise(_) => None,
                    DriveModel::HostMaxwell(_) | DriveModel::HostHardSpheres(_) => None,
                    $(DriveModel::$v(d) => Some(d.work(w)),)*
                }
            }
        }

        /// A declared drive from its parameters, each checked against its rule first.
        fn declared(d: &DriveParams) -> Result<DriveModel, PhysicsError> {
            let kind = d.kind();
            for (i, (spec, &x)) in d.specs().iter().zip(d.values()).enumerate() {
                if !spec.rule.holds(x) {
                    return Err(refusal(Param::Drive(kind, i), spec.rule, x));
                }
            }
            let overflow = |i| PhysicsError {
                param: Param::Drive(kind, i),
                problem: Problem::DoesNotFit("makes the drive's rates overflow"),
            };
            match kind {
                $(DriveKind::$v => <$t>::from_values(d.values()).map(DriveModel::$v).map_err(overflow),)*
                DriveKind::None | DriveKind::WhiteNoise | DriveKind::HostMedium => {
                    err(Param::Drive(kind, 0), Problem::DoesNotFit("is not declared by its type"))
                }
            }
        }
    };
}
declared_drives!(drive_model);

/// The refusal of a value `x` of `param` that breaks `rule` (the same problems as the written-out
/// parameters': [`not_positive`], [`negative`]).
fn refusal(param: Param, rule: Rule, x: Real) -> PhysicsError {
    match rule {
        Rule::Positive => not_positive(param, x),
        Rule::AtLeastZero => negative(param, x),
        Rule::Finite => PhysicsError {
            param,
            problem: Problem::NotFinite(x),
        },
        Rule::Within { range, .. } | Rule::AboveAtMost { range, .. } => PhysicsError {
            param,
            problem: Problem::OutOfRange { value: x, range },
        },
    }
}

/// The validated scheme.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum SchemeModel {
    NoSplitting,
    Splitting(SplittingOrder, Real),
    TimeStepped(Real),
    #[cfg(feature = "weighted")]
    Weighted(super::weighted_scheme::WeightedModel),
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

impl super::Physics {
    /// Checks the particle count alone (`n >= 2`, addressable): for front ends that size
    /// memory before they have a whole description.
    pub fn check_n(n: usize) -> Result<(), PhysicsError> {
        particle_count(n)
    }
}

/// The rule for the particle count ([`check_count`]) as a physics error.
pub(crate) fn particle_count(n: usize) -> Result<(), PhysicsError> {
    check_count(n).or_else(|e| match e {
        ParticlesError::TooFew => err(Param::N, Problem::TooFewParticles(n)),
        ParticlesError::TooMany => err(Param::N, Problem::TooManyParticles(n)),
        ParticlesError::SpinCount
        | ParticlesError::WeightCount
        | ParticlesError::Weight
        | ParticlesError::Full => unreachable!("check_count looks at the count alone"),
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

pub(super) fn law(r: RestitutionLaw) -> Result<LawModel, PhysicsError> {
    let kind = r.kind();
    for (i, (spec, &x)) in kind.params().iter().zip(&r.values()).enumerate() {
        if !spec.rule.holds(x) {
            return Err(refusal(Param::Law(kind, i), spec.rule, x));
        }
    }
    // The declared rules are the constructors' own: they hold, so these succeed; a refusal is
    // still the parameter's.
    match r {
        RestitutionLaw::Constant(alpha) => Constant::new(alpha)
            .map(LawModel::Constant)
            .map_err(|_| refusal(Param::Law(kind, 0), kind.params()[0].rule, alpha)),
        RestitutionLaw::ImpactSpeed { beta0, delta } => ImpactSpeed::new(beta0, delta)
            .map(LawModel::ImpactSpeed)
            .map_err(|e| match e {
                ImpactSpeedError::Beta0 => negative(Param::Law(kind, 0), beta0),
                ImpactSpeedError::Delta => negative(Param::Law(kind, 1), delta),
            }),
    }
}

pub(super) fn drive(d: DriveChoice) -> Result<DriveModel, PhysicsError> {
    Ok(match d {
        DriveChoice::None => DriveModel::None,
        DriveChoice::WhiteNoise(beta) => DriveModel::WhiteNoise(
            WhiteNoise::new(beta).ok_or_else(|| negative(Param::Beta, beta))?,
        ),
        DriveChoice::Declared(d) => declared(&d)?,
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
    let kind = s.kind();
    for (i, (spec, &x)) in kind.params().iter().zip(s.values()).enumerate() {
        if !spec.rule.holds(x) {
            return Err(refusal(Param::Step(kind, i), spec.rule, x));
        }
    }
    // The rules held: a step is finite and > 0 (`check_step`).
    let step = |h: Real| check_step(h).map_err(|_| not_positive(Param::Step(kind, 0), h));
    Ok(match s {
        SchemeChoice::NoSplitting => {
            if let Some(why) = d.kind().stepped_only() {
                return err(Param::Scheme, Problem::DoesNotFit(why));
            }
            SchemeModel::NoSplitting
        }
        SchemeChoice::Euler(dt) => SchemeModel::Splitting(SplittingOrder::Euler, step(dt)?),
        SchemeChoice::Strang(dt) => SchemeModel::Splitting(SplittingOrder::Strang, step(dt)?),
        SchemeChoice::TimeStepped(f) => SchemeModel::TimeStepped(step(f)?),
        // A build without the weighted loop refuses the scheme by name here, and keeps its
        // rules out of the smallest firmware (the micro:bit's 64 KiB).
        #[cfg(not(feature = "weighted"))]
        SchemeChoice::Weighted(_) => {
            return err(
                Param::Scheme,
                Problem::DoesNotFit("needs feature `weighted`"),
            );
        }
        #[cfg(feature = "weighted")]
        SchemeChoice::Weighted(values) => {
            SchemeModel::Weighted(super::weighted_scheme::validate(values, d)?)
        }
    })
}
