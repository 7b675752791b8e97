//! What [`super::Physics::validate`] reports: which parameter ([`Param`]) breaks which rule
//! ([`Problem`]). Front ends name the parameter in their own words (a scene key such as
//! `collisions.restitution`, a C field such as `config.restitution`) and print the problem as
//! it is, so the same bad value gives the same message everywhere.

use crate::math::Real;

/// A number as a message shows it: the shortest text that reads back to the same `f64`
/// (Rust's `Display`), in scientific notation when plain digits would be long (magnitudes
/// from 10^16 on or below 10^-5), so `1e300` is `1e300`, not 301 digits. Every message that
/// shows a user's number (a parameter's rule, a scene key's, a state file's) shows it so.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shown(pub Real);

impl core::fmt::Display for Shown {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let x = self.0;
        let a = if x < 0.0 { -x } else { x };
        if x.is_finite() && x != 0.0 && !(1e-5..1e16).contains(&a) {
            write!(f, "{x:e}")
        } else {
            write!(f, "{x}")
        }
    }
}

/// A parameter of [`super::Physics`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Param {
    /// The particle count `n`.
    N,
    /// The list of initial components as a whole.
    Components,
    /// Weight of initial component `k`.
    Weight(usize),
    /// Mass of initial component `k`.
    Mass(usize),
    /// Temperature of initial component `k`.
    Temperature(usize),
    /// Drift of initial component `k`.
    Drift(usize),
    /// The collision-rate constant gamma of GRW (1).
    Gamma,
    /// The kernel constant C_lambda.
    C,
    /// Parameter `.1` of a kernel beyond `gamma` and `C` ([`super::KernelKind::params`]:
    /// VHS's `lambda`).
    Kernel(super::KernelKind, usize),
    /// Parameter `i` of a restitution law's declaration ([`super::LawKind::params`]): the
    /// constant coefficient alpha, the impact-speed law's `beta0` and `delta` (BRS (9)).
    Law(super::LawKind, usize),
    /// The white-noise strength beta.
    Beta,
    /// Parameter `.1` of a drive declared by its type ([`super::DriveKind::params`]).
    Drive(super::DriveKind, usize),
    /// Host medium: kernel constant C_1.
    BackgroundC,
    /// Host medium: number density rho^B.
    BackgroundDensity,
    /// Host medium: particle mass m^B.
    BackgroundMass,
    /// Host medium: temperature T^B.
    BackgroundTemperature,
    /// Host medium: drift u^B.
    BackgroundDrift,
    /// Parameter `i` of a scheme's declaration ([`super::SchemeKind::params`]): a splitting's
    /// `dt`, the time-stepped scheme's `step_factor`.
    Step(super::SchemeKind, usize),
    /// The scheme itself (it does not fit the kernel or the drive).
    Scheme,
    /// The species of a mixture as a whole.
    Species,
    /// Particle count of species `k`.
    SpeciesCount(usize),
    /// Mass of species `k`.
    SpeciesMass(usize),
    /// Start temperature of species `k`.
    SpeciesTemperature(usize),
    /// Diameter of species `k`.
    SpeciesDiameter(usize),
    /// White-noise strength of species `k`.
    SpeciesBeta(usize),
    /// Restitution coefficient of the species pair `(s, t)`.
    PairRestitution(usize, usize),
    /// Reduced moment of inertia of species `k` (rough mixtures).
    SpeciesInertia(usize),
    /// Start rotational temperature of species `k` (rough mixtures).
    SpeciesRotationTemperature(usize),
    /// White-noise strength on the rotation of species `k` (rough mixtures).
    SpeciesRotationNoise(usize),
    /// Tangential restitution of the species pair `(s, t)` (rough mixtures).
    PairTangentialRestitution(usize, usize),
    /// The rotation of rough particles as a whole.
    Rotation,
    /// The tangential restitution beta of rough particles, in [-1, 1].
    TangentialRestitution,
    /// The reduced moment of inertia kappa, in (0, 2/3].
    Inertia,
    /// The start temperature of rotation, >= 0.
    RotationTemperature,
    /// The white-noise strength on rotation, >= 0.
    RotationNoise,
    /// The dimension (2: disks, 3: spheres).
    Dimension,
}

impl core::fmt::Display for Param {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Param::N => f.write_str("n"),
            Param::Components => f.write_str("components"),
            Param::Weight(k) => write!(f, "components[{k}].weight"),
            Param::Mass(k) => write!(f, "components[{k}].mass"),
            Param::Temperature(k) => write!(f, "components[{k}].temperature"),
            Param::Drift(k) => write!(f, "components[{k}].drift"),
            Param::Gamma => f.write_str("gamma"),
            Param::C => f.write_str("c"),
            Param::Kernel(kind, i) => match kind.params().get(*i) {
                Some(p) => f.write_str(p.name),
                None => write!(f, "kernel parameter {i}"),
            },
            Param::Law(kind, i) => match kind.params().get(*i) {
                Some(p) => f.write_str(p.name),
                None => write!(f, "law parameter {i}"),
            },
            Param::Beta => f.write_str("beta"),
            Param::Drive(kind, i) => match kind.params().and_then(|p| p.get(*i)) {
                Some(p) => f.write_str(p.name),
                None => write!(f, "drive parameter {i}"),
            },
            Param::BackgroundC => f.write_str("background_c"),
            Param::BackgroundDensity => f.write_str("background_density"),
            Param::BackgroundMass => f.write_str("background_mass"),
            Param::BackgroundTemperature => f.write_str("background_temperature"),
            Param::BackgroundDrift => f.write_str("background_drift"),
            Param::Step(kind, i) => match kind.params().get(*i) {
                Some(p) => f.write_str(p.name),
                None => write!(f, "scheme parameter {i}"),
            },
            Param::Scheme => f.write_str("scheme"),
            Param::Species => f.write_str("species"),
            Param::SpeciesCount(k) => write!(f, "species[{k}].count"),
            Param::SpeciesMass(k) => write!(f, "species[{k}].mass"),
            Param::SpeciesTemperature(k) => write!(f, "species[{k}].temperature"),
            Param::SpeciesDiameter(k) => write!(f, "species[{k}].diameter"),
            Param::SpeciesBeta(k) => write!(f, "species[{k}].beta"),
            Param::PairRestitution(s, t) => write!(f, "restitution of species pair ({s}, {t})"),
            Param::SpeciesInertia(k) => write!(f, "species[{k}].inertia"),
            Param::SpeciesRotationTemperature(k) => {
                write!(f, "species[{k}].rotation_temperature")
            }
            Param::SpeciesRotationNoise(k) => write!(f, "species[{k}].rotation_noise"),
            Param::PairTangentialRestitution(s, t) => {
                write!(f, "tangential restitution of species pair ({s}, {t})")
            }
            Param::Rotation => f.write_str("rotation"),
            Param::TangentialRestitution => f.write_str("tangential_restitution"),
            Param::Inertia => f.write_str("inertia"),
            Param::RotationTemperature => f.write_str("rotation_temperature"),
            Param::RotationNoise => f.write_str("rotation_noise"),
            Param::Dimension => f.write_str("dimension"),
        }
    }
}

/// The rule a parameter breaks, with the offending value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Problem {
    /// Not a finite number.
    NotFinite(Real),
    /// Must be > 0.
    NotPositive(Real),
    /// Must be >= 0.
    Negative(Real),
    /// Must lie in the interval written in `range` (e.g. `"(0, 1]"`).
    OutOfRange {
        /// The value.
        value: Real,
        /// The allowed interval, as text.
        range: &'static str,
    },
    /// A vector with a non-finite component.
    NotFiniteVector,
    /// Fewer than two particles.
    TooFewParticles(usize),
    /// More particles than memory can address.
    TooManyParticles(usize),
    /// No initial component.
    NoComponents,
    /// Every initial weight is 0.
    AllWeightsZero,
    /// The rate constant `gamma * C` is not finite and positive (over- or underflow).
    Strength(Real),
    /// A temperature this large for its mass makes the thermal speed infinite (`2 T / m`).
    ThermalSpeed(Real),
    /// A time step longer than the run it steps through: not one step would be taken.
    LongerThanSpan {
        /// The step.
        value: Real,
        /// The run's span (from its start to its last time).
        span: Real,
    },
    /// The parameter does not fit the rest of the description (the message says why).
    DoesNotFit(&'static str),
}

impl core::fmt::Display for Problem {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            Problem::NotFinite(x) => write!(f, "must be a finite number, got {}", Shown(x)),
            Problem::NotPositive(x) => write!(f, "must be > 0, got {}", Shown(x)),
            Problem::Negative(x) => write!(f, "must be >= 0, got {}", Shown(x)),
            Problem::OutOfRange { value, range } => {
                write!(f, "must lie in {range}, got {}", Shown(value))
            }
            Problem::NotFiniteVector => f.write_str("must be three finite numbers"),
            Problem::TooFewParticles(n) => {
                write!(f, "must be >= 2 (a pair is needed to collide), got {n}")
            }
            Problem::TooManyParticles(n) => write!(
                f,
                "= {n} is too large: {n} particles of 32 bytes exceed the address space"
            ),
            Problem::NoComponents => f.write_str("must hold at least one component"),
            Problem::AllWeightsZero => f.write_str("weights must not all be 0"),
            Problem::Strength(s) => write!(
                f,
                "makes the rate constant gamma * C = {}, which must be finite and > 0",
                Shown(s)
            ),
            Problem::ThermalSpeed(t) => write!(
                f,
                "= {} is too large for its mass: 2 temperature / mass overflows",
                Shown(t)
            ),
            Problem::LongerThanSpan { value, span } => write!(
                f,
                "must be at most the run's span {} (not one step would be taken), got {}",
                Shown(span),
                Shown(value)
            ),
            Problem::DoesNotFit(why) => f.write_str(why),
        }
    }
}

/// A parameter of a [`super::Physics`] out of its domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhysicsError {
    /// Which parameter.
    pub param: Param,
    /// What is wrong with it.
    pub problem: Problem,
}

impl core::fmt::Display for PhysicsError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{} {}", self.param, self.problem)
    }
}

impl core::error::Error for PhysicsError {}

#[cfg(test)]
mod tests {
    use super::Shown;
    extern crate std;
    use std::format;

    #[test]
    fn numbers_are_shown_short_and_read_back() {
        for (x, text) in [
            (1e300, "1e300"),
            (-2.5e-300, "-2.5e-300"),
            (5e-324, "5e-324"),
            (0.1, "0.1"),
            (1234.5, "1234.5"),
            (1e15, "1000000000000000"),
            (1e16, "1e16"),
            (0.0, "0"),
            (f64::NAN, "NaN"),
            (f64::INFINITY, "inf"),
        ] {
            let shown = format!("{}", Shown(x));
            assert_eq!(shown, text);
            if x.is_finite() {
                assert_eq!(shown.parse::<f64>().unwrap(), x, "{shown} reads back");
            }
        }
    }
}
