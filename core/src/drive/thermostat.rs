//! The deterministic thermostats of MS: the Gaussian force `F = m zeta v` (MS (12), (13)) and
//! the constant-magnitude force along the velocity `F = m g v_hat` (MS (14), (15)).
//!
//! Both act on each particle alone, and both are solved exactly for any time. They act on the
//! peculiar velocity `c = v - V` (MS's velocities, of a gas at rest), with `V` the bulk
//! velocity, which both keep: the Gaussian force scales it, `c(t + h) = e^{zeta h} c(t)`
//! (MS (61)); the constant force keeps its direction and adds `g h` to its length,
//! `c(t + h) = c(t) + g h c_hat(t)`. So they are applied lazily, particle by particle, in the
//! no-splitting scheme, like the white noise. `V` is taken from the observables at every
//! synchronization ([`Drive::observe`]); in exact arithmetic it never changes, and taking it
//! afresh keeps rounding from being amplified by `e^{zeta t}`.
//!
//! The constant force does not keep the total momentum in a finite system; MS (62) subtracts
//! the mean increment, `w_i = g h (v_hat_i - k)`, `k = N^{-1} sum_i v_hat_i`. The batch kick of
//! all particles ([`Drive::kick_all`], used by the splitting and time-stepped schemes at every
//! step and by the no-splitting scheme at observations) applies that correction, generalized to
//! per-particle time spans `h_i` (the mean of `g h_i v_hat_i` is subtracted). A particle at rest
//! moving with the bulk has no direction and is left as it is.

use super::Drive;
use super::declared::{Declared, Heating, ParamSpec, Rule, WorkInput};
use crate::geometry::Geometry;
use crate::math::{Real, SQRT_PI, exp, exp_m1, ln, ln_1p, powf, sqrt};
use crate::moments::Observables;
use crate::particles::Particles;
use crate::rng::Rng;
use crate::vec3::Vec3;

/// The Gaussian thermostat `F = m zeta v` (MS (12)): `v -> e^{zeta h} v` (MS (61)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaussianThermostat {
    zeta: Real,
    center: Vec3,
}

impl GaussianThermostat {
    /// `None` unless `zeta` is finite (negative values cool).
    #[must_use]
    pub fn new(zeta: Real) -> Option<Self> {
        zeta.is_finite().then_some(GaussianThermostat {
            zeta,
            center: Vec3::ZERO,
        })
    }
    /// The rate `zeta`.
    pub fn zeta(&self) -> Real {
        self.zeta
    }
}

impl Drive for GaussianThermostat {
    const ACTS: bool = true;
    const OBSERVES: bool = true;
    fn observe(&mut self, obs: &Observables) {
        self.center = obs.bulk;
    }
    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, _rng: &mut R) -> Vec3 {
        self.center + exp(self.zeta * dt) * (v - self.center)
    }
}

/// The constant-magnitude force along the velocity `F = m g v_hat` (MS (14)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstantForce {
    g: Real,
    center: Vec3,
}

impl ConstantForce {
    /// `None` unless `g` is finite and `>= 0`.
    #[must_use]
    pub fn new(g: Real) -> Option<Self> {
        (g.is_finite() && g >= 0.0).then_some(ConstantForce {
            g,
            center: Vec3::ZERO,
        })
    }
    /// The force per unit mass `g`.
    pub fn g(&self) -> Real {
        self.g
    }

    /// The change `g dt c_hat` of a velocity `v` in a time `dt`, along its peculiar velocity
    /// `c = v - V` (MS (14) is written for a gas at rest; about the bulk velocity `V` the
    /// force is the same in every frame). A particle moving with the bulk has no direction.
    #[inline(always)]
    fn increment(&self, v: Vec3, dt: Real) -> Vec3 {
        let c = v - self.center;
        let s = c.norm();
        if s > 0.0 {
            (self.g * dt / s) * c
        } else {
            Vec3::ZERO
        }
    }
}

impl Drive for ConstantForce {
    const ACTS: bool = true;
    const OBSERVES: bool = true;
    const COUPLES: bool = true;
    const EXACT: bool = <Self as Declared>::STEPPED_ONLY.is_none();
    fn observe(&mut self, obs: &Observables) {
        self.center = obs.bulk;
    }
    #[inline(always)]
    fn evolve<R: Rng + ?Sized>(&self, v: Vec3, dt: Real, _rng: &mut R) -> Vec3 {
        v + self.increment(v, dt)
    }

    /// All particles to `t` with the momentum-keeping correction of MS (62).
    fn kick_all<R: Rng + ?Sized>(&self, p: &mut Particles<'_>, t: Real, _rng: &mut R) {
        let n = p.len();
        let mut mean = Vec3::ZERO;
        for q in p.as_slice() {
            mean += self.increment(q.velocity(), t - q.t_kick);
        }
        mean = (1.0 / n as Real) * mean;
        for q in p.as_mut_slice() {
            let v = q.velocity();
            q.set_velocity(v + self.increment(v, t - q.t_kick) - mean);
            q.t_kick = t;
        }
    }

    /// All particles of a mixture to `t`: every grain gains `g dt c_hat` (the force `m g c_hat`
    /// on a grain of mass `m`, MS (14), about the flow velocity the loop tells
    /// [`Drive::observe`]), less the mass-weighted mean gain, so that the total momentum
    /// `sum m v` is kept (MS (62) for several masses; one mass: MS (62) itself).
    fn kick_weighted<R: Rng + ?Sized>(
        &self,
        p: &mut Particles<'_>,
        groups: &[(core::ops::Range<usize>, Real)],
        t: Real,
        _rng: &mut R,
    ) {
        let (mut total, mut mass) = (Vec3::ZERO, 0.0);
        for (range, m) in groups {
            let mut sum = Vec3::ZERO;
            for q in &p.as_slice()[range.clone()] {
                sum += self.increment(q.velocity(), t - q.t_kick);
            }
            total += *m * sum;
            mass += *m * range.len() as Real;
        }
        let mean = (1.0 / mass) * total;
        for (range, _) in groups {
            for q in &mut p.as_mut_slice()[range.clone()] {
                let v = q.velocity();
                q.set_velocity(v + self.increment(v, t - q.t_kick) - mean);
                q.t_kick = t;
            }
        }
    }
}

impl Declared for GaussianThermostat {
    const PARAMS: &'static [ParamSpec] = &[ParamSpec {
        name: "zeta",
        rule: Rule::Finite,
        words: "the rate zeta of the force F = m zeta (v - V) (MS (12); < 0 cools)",
        unit: "1/time",
        default: None,
        example: 0.5,
    }];
    const TITLE: &'static str = "Gaussian thermostat";
    type In<G: Geometry> = Self;

    fn from_values(values: &[Real]) -> Result<Self, usize> {
        Self::new(values[0]).ok_or(0)
    }

    fn place<G: Geometry>(self, _mass: Real) -> Option<Self> {
        Some(self)
    }

    fn heating(&self) -> Option<Heating> {
        Some(Heating {
            a: 0.0,
            b: 2.0 * self.zeta,
            p: 0.0,
        })
    }

    /// The start's temperature, and the time the candidate rate integrates to under the
    /// logistic law of the thermostat's heating `2 zeta T` against Haff's cooling.
    fn work(&self, w: WorkInput) -> (Real, Real) {
        let time = logistic_integral(2.0 * w.s * self.zeta, w.s * w.zeta0, w.t_end);
        (w.t0, time)
    }
}

/// `int_0^t y`, `y(0) = 1`, for the logistic law `y' = r y - c y^2`: with `y = (T/T0)^s` the
/// candidate rate of a gas under the Gaussian thermostat (`r = 2 s zeta`, `c = s zeta_0`),
/// relative to its start. Written so that no intermediate overflows where the result does not.
fn logistic_integral(r: Real, c: Real, t: Real) -> Real {
    if c == 0.0 {
        return if r == 0.0 { t } else { exp_m1(r * t) / r };
    }
    if r == 0.0 {
        ln_1p(c * t) / c
    } else if r > 0.0 {
        // ln(1 + c (e^{rt} - 1)/r) = r t + ln(e^{-rt} + (c/r)(1 - e^{-rt})).
        (r * t + ln(exp(-r * t) - (c / r) * exp_m1(-r * t))) / c
    } else {
        ln_1p(c * exp_m1(r * t) / r) / c
    }
}

impl Declared for ConstantForce {
    const PARAMS: &'static [ParamSpec] = &[ParamSpec {
        name: "g",
        rule: Rule::AtLeastZero,
        words: "the force per unit mass g along the peculiar velocity (MS (14))",
        unit: "speed/time",
        default: None,
        example: 0.5,
    }];
    const TITLE: &'static str = "constant force";
    const STEPPED_ONLY: Option<&'static str> = Some(
        "must be time-stepped, Euler or Strang with the constant-force drive: the no-splitting \
         scheme is exact because it moves each particle alone between its collisions, and the \
         force's momentum-keeping correction (MS (62)) makes every particle's free motion depend \
         on all the others' (coupled equations with no closed form), so no exact scheme exists \
         for it",
    );
    type In<G: Geometry> = Self;

    fn from_values(values: &[Real]) -> Result<Self, usize> {
        Self::new(values[0]).ok_or(0)
    }

    fn place<G: Geometry>(self, _mass: Real) -> Option<Self> {
        Some(self)
    }

    /// `(2/3) g <|c|> = zeta_0 (T/T0)^s T` with `<|c|> = sqrt(8 T/pi)`: the balance, at most
    /// the speed `g t` the force adds with no collision at all; the run's span.
    fn work(&self, w: WorkInput) -> (Real, Real) {
        let drive = 2.0 / 3.0 * self.g * sqrt(8.0) / SQRT_PI;
        let stationary = powf(drive * powf(w.t0, w.s) / w.zeta0, 1.0 / (w.s + 0.5));
        let bound = sqrt(w.t0) + self.g * w.t_end / sqrt(3.0);
        (w.t0.max(stationary.min(bound * bound)), w.t_end)
    }
}
