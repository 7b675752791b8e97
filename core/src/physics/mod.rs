//! One physics description from every front end to the event loop.
//!
//! [`Physics`] is plain data: the particle count, the initial distribution, the collision
//! kernel, the restitution law, the drive and the scheme, each with its parameters, as a scene
//! file, a C `gdsmc_config` or a firmware's constant names them. [`Physics::validate`] is the
//! one place where every physical rule is checked (`n >= 2`, `0 < alpha <= 1`, positive rates,
//! the impact-speed law's range, which scheme fits which kernel and drive, ...); it returns a
//! [`Model`] holding the validated building blocks, or a [`PhysicsError`] naming the parameter
//! ([`Param`]) and what is wrong with it ([`Problem`]). Front ends name the parameter in their
//! own words (a scene key, a C field) and print the problem as it is, so every front end gives
//! the same message for the same bad value.
//!
//! [`Model::start`] is the one dispatch from the description to the statically composed event
//! loop: one `match` per level (kernel, drive, restitution law, scheme) builds an [`Engine`],
//! a nest of small enums whose leaves are the monomorphized loops
//! ([`crate::engine::NoSplitting`], [`crate::engine::Splitting`],
//! [`crate::engine::TimeStepped`]). Calls on an [`Engine`] are dispatched once per call (per
//! observation), never per collision, so unused physics costs nothing in the loop.
//!
//! ```
//! use gdsmc_core::physics::{DriveChoice, KernelChoice, Physics, RestitutionLaw, SchemeChoice};
//! use gdsmc_core::{engine::EventLoop, particles::{Particle, Particles}, rng::seeded};
//! // GRW Example 3 with 64 particles: alpha = 1/2, beta = 1, gamma = 4, C0 = 1/(4 pi).
//! let physics = Physics::new(
//!     64,
//!     KernelChoice::maxwell(4.0, 0.25 / core::f64::consts::PI),
//!     RestitutionLaw::Constant(0.5),
//!     DriveChoice::WhiteNoise(1.0),
//!     SchemeChoice::NoSplitting,
//! );
//! let model = physics.validate().unwrap();
//! let mut buf = [Particle::default(); 64];
//! let mut p = Particles::new(&mut buf).unwrap();
//! let mut rng = seeded(1);
//! let (mut engine, _) = model.launch(&mut p, 0.0, &mut rng).unwrap();
//! let obs = engine.advance_to(&mut p, 8.0, &mut rng).unwrap();
//! assert!(obs.t_raw > 1.0); // heated towards T_inf = 8/3
//! // A bad value names its parameter and the rule it breaks:
//! let bad = Physics { restitution: RestitutionLaw::Constant(1.5), ..physics };
//! assert_eq!(bad.validate().unwrap_err().to_string(), "restitution must lie in (0, 1], got 1.5");
//! ```

mod axes;
mod build;
mod built;
mod dimension;
mod dispatch;
mod drives;
pub mod engine;
pub mod error;
mod kernels;
mod kinds;
mod laws;
pub mod model;
mod momentum;
mod parts;
mod rotation;
mod schemes;
mod species;
mod weighted_scheme;

pub use drives::{BackgroundKernel, DriveChoice, DriveParams};
pub use engine::Engine;
pub use error::{Param, PhysicsError, Problem, Shown};
pub use kernels::KernelChoice;
pub use kinds::{DriveKind, KernelKind, LawKind, SchemeKind};
pub use laws::MAX_LAW_PARAMS;
pub use model::Model;
pub use momentum::Momentum;

pub use crate::drive::MAX_DRIVE_PARAMS;
pub use crate::geometry::DimensionChoice;
pub use crate::kernel::MAX_KERNEL_PARAMS;
use crate::math::Real;
pub use crate::mixture::{MAX_PAIRS, MAX_SPECIES};

/// MS's step factor of the time-stepped scheme, `h = 0.01 lambda / v0` (MS Section 3): the
/// default of every front end.
pub const DEFAULT_STEP_FACTOR: Real = 0.01;

/// The parameters of the weighted scheme (`[scheme]` keys `kappa`, `tail_kappa`, `tail_speed`,
/// `capacity`, `target`, `exponent`, `floor`, `split`; [`SchemeKind::params`]): the most any scheme has.
pub const WEIGHTED_PARAMS: usize = 8;

/// Most components an initial mixture of Maxwellians may have (BRS (35)).
pub const MAX_COMPONENTS: usize = 16;

/// The restitution law of GRW (3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RestitutionLaw {
    /// A constant coefficient alpha in (0, 1].
    Constant(Real),
    /// The impact-speed law BRS (9)-(10): `1 - e = 2 beta0 |g . n|^delta`, `beta0, delta >= 0`.
    ImpactSpeed {
        /// `beta_0 >= 0`.
        beta0: Real,
        /// `delta >= 0` (1/5: viscoelastic spheres).
        delta: Real,
    },
}

impl RestitutionLaw {
    /// The coefficient of a constant law; `None` for the impact-speed law (whatever assumes a
    /// constant coefficient, e.g. GRW (13) or MS (65)-(66), must not use it).
    pub fn constant(&self) -> Option<Real> {
        match *self {
            RestitutionLaw::Constant(alpha) => Some(alpha),
            RestitutionLaw::ImpactSpeed { .. } => None,
        }
    }
}

/// The scheme that advances the system in time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SchemeChoice {
    /// The exact no-splitting scheme (GRW Section 3, RW Algorithm 3).
    NoSplitting,
    /// Euler splitting with this time step > 0 (RW Algorithm 1).
    Euler(Real),
    /// Strang splitting with this time step > 0 (RW Algorithm 2).
    Strang(Real),
    /// MS's time-stepped scheme (MS Section 3; Bird's no-time-counter form for the Maxwell and
    /// VHS kernels) with this step factor > 0 (`h = factor lambda / v0`; MS: 0.01).
    TimeStepped(Real),
    /// The exact scheme on weighted particles (Rjasanow and Wagner's SWPM, [`crate::weighted`])
    /// with the values of its parameters in the order of [`SchemeKind::params`].
    Weighted([Real; WEIGHTED_PARAMS]),
}

impl SchemeChoice {
    /// Checks the scheme against the span of a run (from its start to its last time): a
    /// splitting step must be at most the span, or not one step is taken (RW Algorithms 1-2
    /// advance in whole steps; [`crate::engine::grid_index`] refuses every time such a step
    /// would skip). The rule every front end that knows its span applies; the engine's grid
    /// refuses the same advances.
    pub fn check_span(&self, span: Real) -> Result<(), PhysicsError> {
        match *self {
            SchemeChoice::Euler(dt) | SchemeChoice::Strang(dt) if dt.is_nan() || dt > span => {
                Err(PhysicsError {
                    param: Param::Step(self.kind(), 0),
                    problem: Problem::LongerThanSpan { value: dt, span },
                })
            }
            _ => Ok(()),
        }
    }
}

/// One weighted Maxwellian of the initial distribution (BRS (35), (36)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Component {
    /// Weight >= 0 (weights need not sum to one, but not all may be 0).
    pub weight: Real,
    /// Mass > 0.
    pub mass: Real,
    /// Temperature >= 0.
    pub temperature: Real,
    /// Drift velocity.
    pub drift: [Real; 3],
}

impl Component {
    /// The standard Maxwellian of GRW (27): unit weight, mass and temperature, no drift.
    pub const STANDARD: Component = Component {
        weight: 1.0,
        mass: 1.0,
        temperature: 1.0,
        drift: [0.0; 3],
    };
}

/// One species of a granular mixture (Garzó and Dufty 1999): its particles, mass, start
/// temperature (a Maxwellian of zero drift), diameter and white-noise strength. The kernel of
/// species pair `(s, t)` is the description's kernel with `C` times `((d_s + d_t)/2)^2`, the
/// hard-sphere cross section of the pair (GRW (4): `C_1 = d^2/4`); diameter 1 for every
/// species leaves the kernel as it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeciesChoice {
    /// Particles of this species, >= 1.
    pub count: usize,
    /// Mass > 0.
    pub mass: Real,
    /// Start temperature >= 0.
    pub temperature: Real,
    /// Diameter > 0 (relative: 1 keeps the kernel constant).
    pub diameter: Real,
    /// White-noise strength beta >= 0 of this species (with the white-noise drive; GRW (18)
    /// per species).
    pub beta: Real,
    /// Rough particles: this species' reduced moment of inertia `kappa` (`None`: the
    /// rotation's).
    pub inertia: Option<Real>,
    /// Rough particles: this species' start rotational temperature
    /// `T_rot,s = m_s kappa_s <|w|^2>/d_rot >= 0` (`None`: the rotation's).
    pub rotation_temperature: Option<Real>,
    /// Rough particles: the white-noise strength on this species' rotation, `>= 0`,
    /// `dT_rot,s/dt = 2 m_s noise` from it alone, as `beta` on translation (`None`: the
    /// rotation's).
    pub rotation_noise: Option<Real>,
}

impl SpeciesChoice {
    /// A species of `count` particles of mass `mass` starting at `temperature`, diameter 1,
    /// no white noise, its rotation (if rough) the description's.
    pub const fn new(count: usize, mass: Real, temperature: Real) -> Self {
        SpeciesChoice {
            count,
            mass,
            temperature,
            diameter: 1.0,
            beta: 0.0,
            inertia: None,
            rotation_temperature: None,
            rotation_noise: None,
        }
    }
}

/// The rotation of rough particles (Huthmann and Zippelius 1997; [`crate::rough`]): the
/// normal restitution is the description's constant `restitution` (alpha).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RotationChoice {
    /// Tangential restitution beta in [-1, 1] (-1: smooth, rotation untouched; 1: perfectly
    /// rough).
    pub beta: Real,
    /// Reduced moment of inertia `kappa = 4 I / (m sigma^2)` in (0, 2/3] (2/5: uniform
    /// spheres).
    pub kappa: Real,
    /// Start rotational temperature `T_rot >= 0` (a Maxwellian of the rim velocities).
    pub temperature: Real,
    /// White-noise strength on rotation `>= 0`: `dT_rot/dt = 2 noise` from it alone
    /// ([`crate::rough::drive`]).
    pub noise: Real,
}

impl RotationChoice {
    /// Uniform spheres (`kappa = 2/5`) with tangential restitution `beta`, starting at
    /// `T_rot = 1`, no noise on rotation: the defaults every front end gives a rough gas.
    pub const fn spheres(beta: Real) -> Self {
        RotationChoice {
            beta,
            kappa: 0.4,
            temperature: 1.0,
            noise: 0.0,
        }
    }

    /// Uniform disks (`kappa = 1/2`), otherwise as [`RotationChoice::spheres`].
    pub const fn disks(beta: Real) -> Self {
        RotationChoice {
            kappa: 0.5,
            ..Self::spheres(beta)
        }
    }

    /// The defaults of a rough gas in `dimension`: [`RotationChoice::spheres`] or
    /// [`RotationChoice::disks`].
    pub const fn uniform(dimension: DimensionChoice, beta: Real) -> Self {
        match dimension {
            DimensionChoice::Three => Self::spheres(beta),
            DimensionChoice::Two => Self::disks(beta),
        }
    }
}

/// Everything physical about a simulation, as plain data; see the module docs.
#[derive(Clone, Debug, PartialEq)]
pub struct Physics {
    /// Particles per system, >= 2.
    pub n: usize,
    /// The initial distribution: a mixture of at most [`MAX_COMPONENTS`] Maxwellians.
    pub initial: heapless::Vec<Component, MAX_COMPONENTS>,
    /// The collision kernel.
    pub kernel: KernelChoice,
    /// The restitution law.
    pub restitution: RestitutionLaw,
    /// The drive.
    pub drive: DriveChoice,
    /// The scheme.
    pub scheme: SchemeChoice,
    /// The species of a mixture (empty: one species, the gas described above). With species,
    /// `n` is their total, the initial distribution is theirs (`initial` is not used), the
    /// drive is none, white noise (each species its own beta) or, for smooth spheres, the
    /// Gaussian thermostat, and the scheme no-splitting. With a `rotation` they are rough
    /// (each species its kappa, start rotational temperature and rotational noise, each pair
    /// its tangential restitution).
    pub species: heapless::Vec<SpeciesChoice, MAX_SPECIES>,
    /// The restitution coefficient of each species pair `(s, t)`, `s <= t`, in the order
    /// `(0,0), (0,1), .., (1,1), ..` (empty: the constant `restitution` for every pair).
    pub pair_restitution: heapless::Vec<Real, MAX_PAIRS>,
    /// Rough mixtures: the tangential restitution of each species pair, in the order of
    /// `pair_restitution` (empty: the rotation's `beta` for every pair).
    pub pair_tangential_restitution: heapless::Vec<Real, MAX_PAIRS>,
    /// Rough particles: their rotation (`None`: smooth particles). A rough gas takes every
    /// kernel, drive, restitution law and scheme (docs/combinations.md) and needs one spin per
    /// particle beside the particle buffer ([`crate::particles::Particles::with_spins`]). With
    /// species, its values are every species' and pair's unless they name their own.
    pub rotation: Option<RotationChoice>,
    /// The dimension: spheres (`d = 3`, the default) or disks (`d = 2`,
    /// [`crate::geometry`]). Disks take every kernel, drive, law and scheme spheres take and
    /// start drifts in the plane; a rough disk has one rotational
    /// degree of freedom and `kappa` in (0, 1]; a mixture of disks has the pair cross section
    /// `(d_s + d_t)/2` (a length) where spheres have its square.
    pub dimension: DimensionChoice,
    /// How the sample's total momentum starts ([`Momentum`]: independent draws, the default,
    /// or the distribution's mean exactly).
    pub momentum: Momentum,
}

impl Physics {
    /// Whether the particles translate as the smooth gas does, bit for bit: no rotation, or
    /// rough particles whose every collision the engine makes the smooth one
    /// ([`crate::rough::collides_smooth`]: `beta = -1`, and a hard kernel or `d = 3`; rough
    /// pseudo-Maxwell disks collide with the hard-disk impact law, not GRW (3)'s isotropic
    /// scattering). A reference of the smooth gas holds for the translation exactly here.
    #[must_use]
    pub fn translation_is_smooth(&self) -> bool {
        self.rotation.is_none_or(|r| {
            crate::rough::collides_smooth(
                self.kernel.kind().hard(),
                self.dimension,
                crate::rough::spin_transfer(r.beta, r.kappa),
            )
        })
    }

    /// A description with the standard Maxwellian GRW (27) as initial distribution.
    pub fn new(
        n: usize,
        kernel: KernelChoice,
        restitution: RestitutionLaw,
        drive: DriveChoice,
        scheme: SchemeChoice,
    ) -> Self {
        let mut initial = heapless::Vec::new();
        // Capacity MAX_COMPONENTS >= 1: the push cannot fail.
        let _ = initial.push(Component::STANDARD);
        Physics {
            n,
            initial,
            kernel,
            restitution,
            drive,
            scheme,
            species: heapless::Vec::new(),
            pair_restitution: heapless::Vec::new(),
            pair_tangential_restitution: heapless::Vec::new(),
            rotation: None,
            dimension: DimensionChoice::Three,
            momentum: Momentum::Drawn,
        }
    }

    /// Whether nothing heats the gas: no drive and no white noise on any rotation (the
    /// rotation's or a species' own). Such a gas cools freely (the homogeneous cooling state):
    /// its temperatures keep falling while its scale-free quantities (cumulants, temperature
    /// ratios) settle.
    #[must_use]
    pub fn cools_freely(&self) -> bool {
        matches!(self.drive, DriveChoice::None)
            && self.rotation.is_none_or(|r| r.noise == 0.0)
            && self
                .species
                .iter()
                .all(|s| s.rotation_noise.is_none_or(|w| w == 0.0))
    }

    /// Checks every physical rule and returns the validated [`Model`], or the first
    /// parameter out of its domain.
    pub fn validate(&self) -> Result<Model, PhysicsError> {
        Model::new(self)
    }
}
