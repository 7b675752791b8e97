//! The Maxwellian with mass `m`, temperature `T` and drift `u` (BRS (36)):
//! `f_M(v) = (m / (2 pi T))^{3/2} exp(-m |v - u|^2 / (2 T))`, sampled as `u + sqrt(T/m) xi`
//! with `xi` standard normal in R^3. The initial condition of GRW (27) is `m = 1, T = 1, u = 0`.
//!
//! ```
//! use gdsmc_core::{rng::seeded, sample::Maxwellian, vec3::Vec3};
//! let m = Maxwellian::new(1.0, 2.0, Vec3::new(0.0, 1.0, 0.0)).unwrap();
//! let v = m.sample(&mut seeded(5));
//! assert!(v.is_finite());
//! ```

use super::{ParamError, standard_normal3};
use crate::math::{Real, sqrt};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// A Maxwellian velocity distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Maxwellian {
    mass: Real,
    temperature: Real,
    drift: Vec3,
    scale: Real,
}

impl Maxwellian {
    /// A Maxwellian; errors name the parameter out of domain (`mass > 0`, `temperature >= 0`,
    /// finite drift, a finite `2 T / m`).
    pub fn new(mass: Real, temperature: Real, drift: Vec3) -> Result<Self, ParamError> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(ParamError::Mass);
        }
        if !(temperature.is_finite() && temperature >= 0.0) {
            return Err(ParamError::Temperature);
        }
        if !drift.is_finite() {
            return Err(ParamError::Drift);
        }
        // Found by fuzzing: mass 7e-312 with temperature 1.8e308 passed and drew infinite
        // velocities. `2 T / m` is BRS (28)'s `b^2` of a background.
        if !(2.0 * temperature / mass).is_finite() {
            return Err(ParamError::ThermalSpeed);
        }
        Ok(Maxwellian {
            mass,
            temperature,
            drift,
            scale: sqrt(temperature / mass),
        })
    }

    /// The standard Maxwellian GRW (27): unit mass and temperature, no drift.
    pub fn standard() -> Self {
        Maxwellian {
            mass: 1.0,
            temperature: 1.0,
            drift: Vec3::ZERO,
            scale: 1.0,
        }
    }

    /// Mass.
    pub fn mass(&self) -> Real {
        self.mass
    }
    /// Temperature.
    pub fn temperature(&self) -> Real {
        self.temperature
    }
    /// Drift (mean) velocity.
    pub fn drift(&self) -> Vec3 {
        self.drift
    }
    /// `sqrt(T/m)`, the standard deviation of each component.
    pub fn thermal_scale(&self) -> Real {
        self.scale
    }

    /// One velocity.
    #[inline]
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        self.drift + self.scale * standard_normal3(rng)
    }
}
