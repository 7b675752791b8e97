//! The drive in the description: [`DriveChoice`] (none, white noise, a host medium, or a drive
//! declared by its type with its [`DriveParams`]) and the words a title gives it.

use super::{DriveKind, MAX_DRIVE_PARAMS};
use crate::math::Real;

/// The grain-background kernel of a host medium.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BackgroundKernel {
    /// `B_1 = C_1` (BRS (11)).
    Maxwell,
    /// `B_1 = C_1 |g|` (BRS (19)).
    HardSpheres,
}

/// What acts on every particle between collisions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DriveChoice {
    /// No drive: the freely cooling gas.
    None,
    /// White-noise heating of strength beta >= 0 (GRW (1), (18)).
    WhiteNoise(Real),
    /// A drive declared by its type ([`crate::drive::Declared`]): the Gaussian thermostat (MS
    /// (12)), the constant force (MS (14)), the Langevin thermostat, ... with its parameters.
    Declared(DriveParams),
    /// Elastic collisions of unit-mass grains with a Maxwellian host medium (BRS Section 2).
    HostMedium {
        /// The grain-background kernel.
        kernel: BackgroundKernel,
        /// Kernel constant C_1 > 0.
        c1: Real,
        /// Number density rho^B > 0.
        density: Real,
        /// Background particle mass m^B > 0.
        mass: Real,
        /// Background temperature T^B >= 0.
        temperature: Real,
        /// Background drift u^B.
        drift: [Real; 3],
    },
}

/// A drive declared by its type ([`crate::drive::Declared`]): its kind and the values of its
/// parameters in their declared order ([`DriveKind::params`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DriveParams {
    kind: DriveKind,
    values: [Real; MAX_DRIVE_PARAMS],
}

impl DriveParams {
    /// The drive `kind` with `values` for its parameters in their order; `None` unless `kind`
    /// is declared by its type and `values` holds a value for each parameter (the rest are
    /// ignored). The rules are checked by [`super::Physics::validate`].
    #[must_use]
    pub fn new(kind: DriveKind, values: &[Real]) -> Option<Self> {
        let values = crate::declared::fill(kind.params()?, values)?;
        Some(DriveParams { kind, values })
    }

    /// The declared drive `kind` with each parameter's example value ([`ParamSpec::example`](crate::drive::ParamSpec)):
    /// what the combination matrix and the fuzzers run; `None` unless `kind` is declared.
    #[must_use]
    pub fn example(kind: DriveKind) -> Option<Self> {
        let values = crate::declared::examples::<MAX_DRIVE_PARAMS>(kind.params()?);
        Self::new(kind, &values)
    }

    /// Which drive.
    #[must_use]
    pub const fn kind(&self) -> DriveKind {
        self.kind
    }

    /// The values, one per parameter.
    #[must_use]
    pub fn values(&self) -> &[Real] {
        &self.values[..self.specs().len()]
    }

    /// The parameters' declarations.
    #[must_use]
    pub fn specs(&self) -> &'static [crate::drive::ParamSpec] {
        self.kind.params().unwrap_or(&[])
    }

    /// The value of the parameter named `name`, if the drive has one.
    #[must_use]
    pub fn get(&self, name: &str) -> Option<Real> {
        crate::declared::named(self.specs(), self.values(), name)
    }
}

impl DriveChoice {
    /// Which drive this is.
    #[must_use]
    pub const fn kind(&self) -> DriveKind {
        match self {
            DriveChoice::None => DriveKind::None,
            DriveChoice::WhiteNoise(_) => DriveKind::WhiteNoise,
            DriveChoice::HostMedium { .. } => DriveKind::HostMedium,
            DriveChoice::Declared(d) => d.kind(),
        }
    }

    /// The declared drive `kind` with these values ([`DriveParams::new`]).
    #[must_use]
    pub fn declared(kind: DriveKind, values: &[Real]) -> Option<Self> {
        DriveParams::new(kind, values).map(DriveChoice::Declared)
    }

    /// The parameters of a declared drive of kind `kind`; `None` for another drive.
    #[must_use]
    pub fn params_of(&self, kind: DriveKind) -> Option<&DriveParams> {
        match self {
            DriveChoice::Declared(d) if d.kind == kind => Some(d),
            _ => None,
        }
    }
}

/// The drive as a chart's title names it: "cooling freely", "white noise (beta = 1)",
/// "Langevin thermostat (friction = 0.5, temperature = 2)".
impl core::fmt::Display for DriveChoice {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            DriveChoice::None => f.write_str("cooling freely"),
            DriveChoice::WhiteNoise(b) => write!(f, "white noise (beta = {b})"),
            DriveChoice::HostMedium { .. } => f.write_str("in a host medium"),
            DriveChoice::Declared(d) => {
                f.write_str(d.kind.title().unwrap_or(d.kind.scene_name()))?;
                crate::declared::write_params(f, d.specs(), d.values())
            }
        }
    }
}
