//! The kernel in the description: [`KernelChoice`], a kernel declared by its type
//! ([`crate::kernel::Declared`]) with `gamma`, `C` and the values of its parameters, and the
//! words a title gives it.

use super::{KernelKind, MAX_KERNEL_PARAMS};
use crate::declared::{self, ParamSpec};
use crate::math::Real;

/// The collision kernel `B = gamma C |u|^lambda` (GRW (1), (2), (4), (5)): its kind, the
/// collision-rate constant `gamma` of GRW (1), the kernel constant `C` and the values of the
/// kind's own parameters in their declared order ([`KernelKind::params`]: VHS's `lambda`).
/// The rules are checked by [`Physics::validate`](super::Physics::validate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KernelChoice {
    kind: KernelKind,
    gamma: Real,
    c: Real,
    values: [Real; MAX_KERNEL_PARAMS],
}

impl KernelChoice {
    /// The kernel `kind` with `gamma`, `c` and `values` for its parameters in their order;
    /// `None` unless `values` holds a value for each of them (the rest are ignored).
    #[must_use]
    pub fn new(kind: KernelKind, gamma: Real, c: Real, values: &[Real]) -> Option<Self> {
        let values = declared::fill(kind.params(), values)?;
        Some(KernelChoice {
            kind,
            gamma,
            c,
            values,
        })
    }

    /// The kernel `kind` with `gamma`, `c` and each parameter's example value
    /// ([`ParamSpec::example`]): what the combination matrix and the fuzzers run.
    #[must_use]
    pub fn example(kind: KernelKind, gamma: Real, c: Real) -> Self {
        let values = declared::examples(kind.params());
        KernelChoice {
            kind,
            gamma,
            c,
            values,
        }
    }

    /// Maxwell pseudo-molecules `B = gamma C_0` (GRW (2); GRW: `C_0 = 1/(4 pi)`).
    #[must_use]
    pub const fn maxwell(gamma: Real, c: Real) -> Self {
        Self::written(KernelKind::Maxwell, gamma, c, 0.0)
    }

    /// Ernst and Brito's inelastic Maxwell model, impact form: `B = gamma C_0`, the impact
    /// direction uniform ([`crate::kernel::MaxwellImpact`]).
    #[must_use]
    pub const fn maxwell_impact(gamma: Real, c: Real) -> Self {
        Self::written(KernelKind::MaxwellImpact, gamma, c, 0.0)
    }

    /// Hard spheres `B = gamma C_1 |u|` (GRW (4); hard disks in `d = 2`).
    #[must_use]
    pub const fn hard_spheres(gamma: Real, c: Real) -> Self {
        Self::written(KernelKind::HardSpheres, gamma, c, 0.0)
    }

    /// Variable hard spheres `B = gamma C_lambda |u|^lambda`, `lambda` in `[0, 1]` (GRW (5)).
    #[must_use]
    pub const fn vhs(gamma: Real, c: Real, lambda: Real) -> Self {
        Self::written(KernelKind::Vhs, gamma, c, lambda)
    }

    const fn written(kind: KernelKind, gamma: Real, c: Real, first: Real) -> Self {
        let mut values = [0.0; MAX_KERNEL_PARAMS];
        values[0] = first;
        KernelChoice {
            kind,
            gamma,
            c,
            values,
        }
    }

    /// Which kernel this is.
    #[must_use]
    pub const fn kind(&self) -> KernelKind {
        self.kind
    }

    /// The collision-rate constant `gamma` of GRW (1).
    #[must_use]
    pub const fn gamma(&self) -> Real {
        self.gamma
    }

    /// The kernel constant `C`.
    #[must_use]
    pub const fn c(&self) -> Real {
        self.c
    }

    /// The same kernel with `gamma` and `c` replaced.
    #[must_use]
    pub const fn with_constants(self, gamma: Real, c: Real) -> Self {
        KernelChoice { gamma, c, ..self }
    }

    /// The values of its own parameters, one per declared parameter.
    #[must_use]
    pub fn values(&self) -> &[Real] {
        &self.values[..self.specs().len()]
    }

    /// Its parameters' declarations.
    #[must_use]
    pub fn specs(&self) -> &'static [ParamSpec] {
        self.kind.params()
    }

    /// The value of the parameter named `name`, if the kernel has one.
    #[must_use]
    pub fn get(&self, name: &str) -> Option<Real> {
        declared::named(self.specs(), self.values(), name)
    }

    /// `gamma C`: the kernel's strength (GRW (1), (2), (4), (5)).
    #[must_use]
    pub fn strength(&self) -> Real {
        self.gamma * self.c
    }

    /// The exponent `lambda` when the kernel is the power law `B = gamma C |u|^lambda` (0 for
    /// Maxwell molecules, 1 for hard spheres, the VHS kernel's own); `None` for a kernel that
    /// is not a power law ([`crate::kernel::Declared::exponent`]).
    #[must_use]
    pub fn exponent(&self) -> Option<Real> {
        self.kind.exponent(self.values())
    }

    /// `(gamma C, lambda)` of a power-law kernel `B = gamma C |u|^lambda`: what every
    /// power-law result reads; `None` for a kernel that is not one.
    #[must_use]
    pub fn power_law(&self) -> Option<(Real, Real)> {
        Some((self.strength(), self.exponent()?))
    }
}

/// The kernel as a title names it: "Maxwell kernel", "hard-sphere kernel", "VHS kernel
/// (lambda = 0.5)".
impl core::fmt::Display for KernelChoice {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.kind.title())?;
        declared::write_params(f, self.specs(), self.values())
    }
}
