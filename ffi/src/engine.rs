//! The engine behind a handle: one monomorphized event loop per (scheme, kernel, drive), chosen
//! once at creation; dispatch happens per call, never per collision. An enum, not a box, so the
//! allocation-free variant allocates nothing.

use crate::config::*;
use crate::status::{Failure, fail, gdsmc_status};
use gdsmc_core::drive::{
    ConstantForce, GaussianThermostat, HardSphereBackground, HostMedium, HostMediumParams,
    MaxwellBackground, NoDrive, WhiteNoise,
};
use gdsmc_core::engine::{Counts, EngineError, NoSplitting, Splitting, SplittingOrder};
use gdsmc_core::kernel::{HardSpheres, Maxwell, Vhs};
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::Particles;
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::Xoshiro256PlusPlus;
use gdsmc_core::sample::Maxwellian;
use gdsmc_core::vec3::Vec3;

type HmM = HostMedium<MaxwellBackground>;
type HmH = HostMedium<HardSphereBackground>;
type Ga = GaussianThermostat;
type Cf = ConstantForce;

macro_rules! any_engine {
    ($($v:ident => $e:ident<$k:ty, $d:ty>),* $(,)?) => {
        pub(crate) enum AnyEngine { $($v($e<$k, $d, Constant>)),* }
        $(impl From<$e<$k, $d, Constant>> for AnyEngine {
            fn from(e: $e<$k, $d, Constant>) -> Self { AnyEngine::$v(e) }
        })*
        macro_rules! each {
            ($x:expr, $y:ident => $body:expr) => { match $x { $(AnyEngine::$v($y) => $body),* } };
        }
    };
}

any_engine! {
    NsMw => NoSplitting<Maxwell, WhiteNoise>, NsMn => NoSplitting<Maxwell, NoDrive>,
    NsMhm => NoSplitting<Maxwell, HmM>, NsMhh => NoSplitting<Maxwell, HmH>,
    NsHw => NoSplitting<HardSpheres, WhiteNoise>, NsHn => NoSplitting<HardSpheres, NoDrive>,
    NsHhm => NoSplitting<HardSpheres, HmM>, NsHhh => NoSplitting<HardSpheres, HmH>,
    NsVw => NoSplitting<Vhs, WhiteNoise>, NsVn => NoSplitting<Vhs, NoDrive>,
    NsVhm => NoSplitting<Vhs, HmM>, NsVhh => NoSplitting<Vhs, HmH>,
    SpMw => Splitting<Maxwell, WhiteNoise>, SpMn => Splitting<Maxwell, NoDrive>,
    SpMhm => Splitting<Maxwell, HmM>, SpMhh => Splitting<Maxwell, HmH>,
    SpHw => Splitting<HardSpheres, WhiteNoise>, SpHn => Splitting<HardSpheres, NoDrive>,
    SpHhm => Splitting<HardSpheres, HmM>, SpHhh => Splitting<HardSpheres, HmH>,
    SpVw => Splitting<Vhs, WhiteNoise>, SpVn => Splitting<Vhs, NoDrive>,
    SpVhm => Splitting<Vhs, HmM>, SpVhh => Splitting<Vhs, HmH>,
    NsMga => NoSplitting<Maxwell, Ga>,
    NsMcf => NoSplitting<Maxwell, Cf>,
    NsHga => NoSplitting<HardSpheres, Ga>,
    NsHcf => NoSplitting<HardSpheres, Cf>,
    NsVga => NoSplitting<Vhs, Ga>,
    NsVcf => NoSplitting<Vhs, Cf>,
    SpMga => Splitting<Maxwell, Ga>,
    SpMcf => Splitting<Maxwell, Cf>,
    SpHga => Splitting<HardSpheres, Ga>,
    SpHcf => Splitting<HardSpheres, Cf>,
    SpVga => Splitting<Vhs, Ga>,
    SpVcf => Splitting<Vhs, Cf>,
}

fn invalid<T>(msg: String) -> Result<T, Failure> {
    fail(gdsmc_status::GDSMC_INVALID_ARGUMENT, msg)
}

pub(crate) fn engine_error(e: EngineError) -> Failure {
    let s = match e {
        EngineError::TimeBackwards => gdsmc_status::GDSMC_TIME_BACKWARDS,
        EngineError::NonFinite => gdsmc_status::GDSMC_NON_FINITE,
        EngineError::OffGrid => gdsmc_status::GDSMC_INVALID_ARGUMENT,
    };
    let msg = match e {
        EngineError::OffGrid => {
            "the time is not a multiple of config.dt (splitting schemes)".to_string()
        }
        _ => e.to_string(),
    };
    Failure(s, msg)
}

/// Checks every field of a configuration, naming the first bad one.
pub(crate) fn validate(c: &gdsmc_config) -> Result<(), Failure> {
    if c.n < 2 {
        return invalid(format!("config.n must be >= 2, got {}", c.n));
    }
    if c.n > (isize::MAX as u64) / 64 {
        return invalid(format!("config.n = {} is too large", c.n));
    }
    if c.stream > 1 << 24 {
        return invalid(format!(
            "config.stream = {} is above 2^24 (each costs a jump)",
            c.stream
        ));
    }
    if c.scheme > GDSMC_SCHEME_STRANG {
        return invalid(format!(
            "config.scheme = {} is not a GDSMC_SCHEME_* value",
            c.scheme
        ));
    }
    if c.kernel > GDSMC_KERNEL_VHS {
        return invalid(format!(
            "config.kernel = {} is not a GDSMC_KERNEL_* value",
            c.kernel
        ));
    }
    if c.drive > GDSMC_DRIVE_CONSTANT_FORCE {
        return invalid(format!(
            "config.drive = {} is not a GDSMC_DRIVE_* value",
            c.drive
        ));
    }
    let pos = |x: f64, k: &str| {
        if x.is_finite() && x > 0.0 {
            Ok(())
        } else {
            invalid(format!("config.{k} must be finite and > 0, got {x}"))
        }
    };
    let nonneg = |x: f64, k: &str| {
        if x.is_finite() && x >= 0.0 {
            Ok(())
        } else {
            invalid(format!("config.{k} must be finite and >= 0, got {x}"))
        }
    };
    pos(c.gamma, "gamma")?;
    pos(c.c, "c")?;
    pos(c.mass, "mass")?;
    nonneg(c.temperature, "temperature")?;
    if c.kernel == GDSMC_KERNEL_VHS && !(0.0..=1.0).contains(&c.lambda) {
        return invalid(format!(
            "config.lambda must lie in [0, 1], got {}",
            c.lambda
        ));
    }
    if !(c.restitution > 0.0 && c.restitution <= 1.0) {
        return invalid(format!(
            "config.restitution must lie in (0, 1], got {}",
            c.restitution
        ));
    }
    if c.drive == GDSMC_DRIVE_WHITE_NOISE {
        nonneg(c.beta, "beta")?;
    }
    if c.drive == GDSMC_DRIVE_GAUSSIAN && !c.zeta.is_finite() {
        return invalid(format!("config.zeta must be finite, got {}", c.zeta));
    }
    if c.drive == GDSMC_DRIVE_CONSTANT_FORCE {
        nonneg(c.g, "g")?;
        if c.scheme == GDSMC_SCHEME_NO_SPLITTING {
            return invalid(
                "config.drive = GDSMC_DRIVE_CONSTANT_FORCE needs a splitting scheme: its momentum-keeping \
                 correction (MS (62)) couples all particles at every step"
                    .into(),
            );
        }
    }
    if c.drive == GDSMC_DRIVE_HOST_MEDIUM {
        if c.background_kernel > GDSMC_BACKGROUND_HARD_SPHERES {
            return invalid(format!(
                "config.background_kernel = {} is not a GDSMC_BACKGROUND_* value",
                c.background_kernel
            ));
        }
        pos(c.background_c, "background_c")?;
        pos(c.background_density, "background_density")?;
        pos(c.background_mass, "background_mass")?;
        nonneg(c.background_temperature, "background_temperature")?;
        if c.background_drift.iter().any(|x| !x.is_finite()) {
            return invalid("config.background_drift must be finite".into());
        }
    }
    if c.scheme != GDSMC_SCHEME_NO_SPLITTING {
        pos(c.dt, "dt")?;
    }
    if c.drift.iter().any(|x| !x.is_finite()) {
        return invalid("config.drift must be finite".into());
    }
    if !(c.gamma * c.c).is_finite() {
        return invalid("config.gamma * config.c overflows".into());
    }
    Ok(())
}

fn start_with<K, D>(
    c: &gdsmc_config,
    k: K,
    d: D,
    p: &mut Particles<'_>,
) -> Result<(AnyEngine, Observables), Failure>
where
    K: gdsmc_core::kernel::Kernel,
    D: gdsmc_core::drive::Drive,
    NoSplitting<K, D, Constant>: Into<AnyEngine>,
    Splitting<K, D, Constant>: Into<AnyEngine>,
{
    let a = Constant::new(c.restitution).expect("validated");
    if c.scheme == GDSMC_SCHEME_NO_SPLITTING {
        let (e, o) = NoSplitting::start(k, d, a, p, 0.0).map_err(engine_error)?;
        Ok((e.into(), o))
    } else {
        let order = if c.scheme == GDSMC_SCHEME_EULER {
            SplittingOrder::Euler
        } else {
            SplittingOrder::Strang
        };
        let (e, o) = Splitting::start(k, d, a, order, c.dt, p, 0.0).map_err(engine_error)?;
        Ok((e.into(), o))
    }
}

fn with_drive<K>(
    c: &gdsmc_config,
    k: K,
    p: &mut Particles<'_>,
) -> Result<(AnyEngine, Observables), Failure>
where
    K: gdsmc_core::kernel::Kernel,
    NoSplitting<K, WhiteNoise, Constant>: Into<AnyEngine>,
    NoSplitting<K, NoDrive, Constant>: Into<AnyEngine>,
    NoSplitting<K, HmM, Constant>: Into<AnyEngine>,
    NoSplitting<K, HmH, Constant>: Into<AnyEngine>,
    Splitting<K, WhiteNoise, Constant>: Into<AnyEngine>,
    Splitting<K, NoDrive, Constant>: Into<AnyEngine>,
    Splitting<K, HmM, Constant>: Into<AnyEngine>,
    Splitting<K, HmH, Constant>: Into<AnyEngine>,
    NoSplitting<K, Ga, Constant>: Into<AnyEngine>,
    NoSplitting<K, Cf, Constant>: Into<AnyEngine>,
    Splitting<K, Ga, Constant>: Into<AnyEngine>,
    Splitting<K, Cf, Constant>: Into<AnyEngine>,
{
    match c.drive {
        GDSMC_DRIVE_NONE => start_with(c, k, NoDrive, p),
        GDSMC_DRIVE_WHITE_NOISE => start_with(c, k, WhiteNoise::new(c.beta).expect("validated"), p),
        GDSMC_DRIVE_GAUSSIAN => {
            start_with(c, k, GaussianThermostat::new(c.zeta).expect("validated"), p)
        }
        GDSMC_DRIVE_CONSTANT_FORCE => {
            start_with(c, k, ConstantForce::new(c.g).expect("validated"), p)
        }
        _ => {
            let d = c.background_drift;
            let bg = Maxwellian::new(
                c.background_mass,
                c.background_temperature,
                Vec3::new(d[0], d[1], d[2]),
            )
            .expect("validated");
            let params =
                HostMediumParams::new(bg, c.background_density, c.background_c).expect("validated");
            if c.background_kernel == GDSMC_BACKGROUND_HARD_SPHERES {
                start_with(c, k, HostMedium::new(params, HardSphereBackground), p)
            } else {
                start_with(c, k, HostMedium::new(params, MaxwellBackground), p)
            }
        }
    }
}

impl AnyEngine {
    /// Starts the engine of a validated configuration on initialized particles.
    pub(crate) fn start(
        c: &gdsmc_config,
        p: &mut Particles<'_>,
    ) -> Result<(Self, Observables), Failure> {
        match c.kernel {
            GDSMC_KERNEL_MAXWELL => {
                with_drive(c, Maxwell::new(c.gamma, c.c).expect("validated"), p)
            }
            GDSMC_KERNEL_HARD_SPHERES => {
                with_drive(c, HardSpheres::new(c.gamma, c.c).expect("validated"), p)
            }
            _ => with_drive(c, Vhs::new(c.gamma, c.c, c.lambda).expect("validated"), p),
        }
    }

    pub(crate) fn advance(
        &mut self,
        p: &mut Particles<'_>,
        t: f64,
        rng: &mut Xoshiro256PlusPlus,
    ) -> Result<Observables, EngineError> {
        each!(self, e => e.advance_to(p, t, rng))
    }

    pub(crate) fn resync(&mut self, p: &mut Particles<'_>) -> Result<Observables, EngineError> {
        each!(self, e => e.resync(p))
    }

    pub(crate) fn time(&self) -> f64 {
        each!(self, e => e.time())
    }

    pub(crate) fn counts(&self) -> Counts {
        each!(self, e => e.counts())
    }

    pub(crate) fn velocity_map(&self) -> (f64, Vec3) {
        each!(self, e => gdsmc_core::engine::EventLoop::velocity_map(e))
    }
}
