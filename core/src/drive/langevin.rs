//! The Langevin thermostat: a viscous drag `-gamma v` and white noise at a bath temperature
//! `T_b` on every grain, `dv = -gamma v dt + sqrt(2 gamma T_b / m) dW` (the standard stochastic
//! thermostat of driven granular gases: van Noije, Ernst, Trizac and Pagonabarraga 1999;
//! Puglisi, Loreto, Marini Bettolo Marconi, Petri and Vulpiani 1998). The bath is at rest: the
//! drag pulls every velocity towards 0 and the bulk velocity decays as `e^{-gamma t}`.
//!
//! Between collisions each component is an Ornstein-Uhlenbeck process, solved exactly for any
//! time `h`: `v(t + h) = e^{-gamma h} v(t) + sqrt((T_b/m)(1 - e^{-2 gamma h})) xi`, `xi`
//! standard normal (in the plane for disks). So the drive is applied lazily, particle by
//! particle, in the no-splitting scheme with no time-step error, like white noise (GRW Section
//! 3). A mixture's species each meet the bath with their own mass (the same `gamma`: a drag
//! `-m gamma v`), so each settles at `T_b`.
//!
//! Alone it changes the temperature linearly ([`Heating`]): `dT/dt = 2 gamma (T_b - T)` per
//! degree of freedom, so the Maxwell gas's temperature is exact,
//! `T(t) = T_inf + (T_0 - T_inf) e^{-(2 gamma + k) t}`, `T_inf = 2 gamma T_b/(2 gamma + k)`,
//! `k = pi gamma_c C_0 (1 - alpha^2)` (GRW (13) with the drive's rates).

use super::Drive;
use super::declared::{Declared, Heating, ParamSpec, Rule};
use crate::geometry::{Geometry, Spheres};
use crate::math::{Real, exp, exp_m1, sqrt};
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The Langevin thermostat in dimension `G` on grains of one mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Langevin<G = Spheres> {
    /// The friction rate gamma > 0.
    friction: Real,
    /// The bath temperature `T_b >= 0`.
    temperature: Real,
    /// The velocity variance per component the bath brings a grain to, `T_b / m`.
    variance: Real,
    dimension: core::marker::PhantomData<G>,
}

impl Langevin {
    /// The friction rate gamma.
    #[must_use]
    pub fn friction(&self) -> Real {
        self.friction
    }
    /// The bath temperature `T_b`.
    #[must_use]
    pub fn temperature(&self) -> Real {
        self.temperature
    }
}

impl<G: Geometry> Drive for Langevin<G> {
    const ACTS: bool = true;

    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, rng: &mut R) -> Vec3 {
        let decay = exp(-self.friction * dt);
        let spread = sqrt(-self.variance * exp_m1(-2.0 * self.friction * dt));
        decay * v + spread * G::normal(rng)
    }
}

impl Declared for Langevin {
    const PARAMS: &'static [ParamSpec] = &[
        ParamSpec {
            name: "friction",
            rule: Rule::Positive,
            words: "the friction rate gamma of the drag -gamma v",
            unit: "1/time",
            default: None,
            example: 0.5,
        },
        ParamSpec {
            name: "temperature",
            rule: Rule::AtLeastZero,
            words: "the bath temperature T_b the noise brings every grain to (0: drag alone)",
            unit: "temperature",
            default: None,
            example: 1.0,
        },
    ];
    const TITLE: &'static str = "Langevin thermostat";
    type In<G: Geometry> = Langevin<G>;

    fn from_values(values: &[Real]) -> Result<Self, usize> {
        let (friction, temperature) = (values[0], values[1]);
        // The rate the bath heats at, 2 gamma T_b, must be finite.
        if !(2.0 * friction * temperature).is_finite() {
            return Err(1);
        }
        Ok(Langevin {
            friction,
            temperature,
            variance: temperature,
            dimension: core::marker::PhantomData,
        })
    }

    fn place<G: Geometry>(self, mass: Real) -> Option<Langevin<G>> {
        let variance = self.temperature / mass;
        variance.is_finite().then_some(Langevin {
            friction: self.friction,
            temperature: self.temperature,
            variance,
            dimension: core::marker::PhantomData,
        })
    }

    fn heating(&self) -> Option<Heating> {
        let b = -2.0 * self.friction;
        Some(Heating {
            a: 2.0 * self.friction * self.temperature,
            b,
            p: b,
        })
    }
}
