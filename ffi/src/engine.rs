//! The engine behind a handle: one monomorphized event loop per (kernel, drive), chosen once at
//! creation; dispatch happens per call, never per collision.

use crate::config::*;
use crate::status::{Failure, fail, gdsmc_status};
use gdsmc_core::drive::{NoDrive, WhiteNoise};
use gdsmc_core::engine::{Counts, EngineError, NoSplitting};
use gdsmc_core::kernel::{HardSpheres, Maxwell, Vhs};
use gdsmc_core::moments::Observables;
use gdsmc_core::particles::Particles;
use gdsmc_core::restitution::Constant;
use gdsmc_core::rng::Xoshiro256PlusPlus;

pub(crate) enum AnyEngine {
    MaxwellWhite(NoSplitting<Maxwell, WhiteNoise, Constant>),
    MaxwellNone(NoSplitting<Maxwell, NoDrive, Constant>),
    HardWhite(NoSplitting<HardSpheres, WhiteNoise, Constant>),
    HardNone(NoSplitting<HardSpheres, NoDrive, Constant>),
    VhsWhite(NoSplitting<Vhs, WhiteNoise, Constant>),
    VhsNone(NoSplitting<Vhs, NoDrive, Constant>),
}

macro_rules! each {
    ($e:expr, $x:ident => $body:expr) => {
        match $e {
            AnyEngine::MaxwellWhite($x) => $body,
            AnyEngine::MaxwellNone($x) => $body,
            AnyEngine::HardWhite($x) => $body,
            AnyEngine::HardNone($x) => $body,
            AnyEngine::VhsWhite($x) => $body,
            AnyEngine::VhsNone($x) => $body,
        }
    };
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
    Failure(s, e.to_string())
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
    if c.scheme != GDSMC_SCHEME_NO_SPLITTING {
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
    if c.drive > GDSMC_DRIVE_WHITE_NOISE {
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
    if c.drift.iter().any(|x| !x.is_finite()) {
        return invalid("config.drift must be finite".into());
    }
    if !(c.gamma * c.c).is_finite() {
        return invalid("config.gamma * config.c overflows".into());
    }
    Ok(())
}

impl AnyEngine {
    /// Starts the engine of a validated configuration on initialized particles.
    pub(crate) fn start(
        c: &gdsmc_config,
        p: &mut Particles<'_>,
    ) -> Result<(Self, Observables), Failure> {
        let a = Constant::new(c.restitution).expect("validated");
        let white = c.drive == GDSMC_DRIVE_WHITE_NOISE;
        let w = WhiteNoise::new(c.beta).unwrap_or(WhiteNoise::new(0.0).expect("0 is valid"));
        macro_rules! go {
            ($k:expr) => {{
                let k = $k;
                if white {
                    let (e, o) = NoSplitting::start(k, w, a, p, 0.0).map_err(engine_error)?;
                    (e.into(), o)
                } else {
                    let (e, o) = NoSplitting::start(k, NoDrive, a, p, 0.0).map_err(engine_error)?;
                    (e.into(), o)
                }
            }};
        }
        let r: (AnyEngine, Observables) = match c.kernel {
            GDSMC_KERNEL_MAXWELL => go!(Maxwell::new(c.gamma, c.c).expect("validated")),
            GDSMC_KERNEL_HARD_SPHERES => go!(HardSpheres::new(c.gamma, c.c).expect("validated")),
            _ => go!(Vhs::new(c.gamma, c.c, c.lambda).expect("validated")),
        };
        Ok(r)
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
}

macro_rules! from_engine {
    ($v:ident, $k:ty, $d:ty) => {
        impl From<NoSplitting<$k, $d, Constant>> for AnyEngine {
            fn from(e: NoSplitting<$k, $d, Constant>) -> Self {
                AnyEngine::$v(e)
            }
        }
    };
}
from_engine!(MaxwellWhite, Maxwell, WhiteNoise);
from_engine!(MaxwellNone, Maxwell, NoDrive);
from_engine!(HardWhite, HardSpheres, WhiteNoise);
from_engine!(HardNone, HardSpheres, NoDrive);
from_engine!(VhsWhite, Vhs, WhiteNoise);
from_engine!(VhsNone, Vhs, NoDrive);
