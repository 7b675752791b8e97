//! Ernst and Brito's inelastic Maxwell model, the impact form most of the inelastic-Maxwell
//! literature uses (Ernst and Brito 2002; Santos 2003; Ben-Naim and Krapivsky): a pair
//! collides at a rate independent of its relative velocity `u` and of the impact direction
//! `n`, which is uniform on the sphere, and `v1' = v1 - (1 + alpha)/2 (u . n) n`. As GRW (3)
//! this is `u' = (1 - alpha)/2 u + (1 + alpha)/2 |u| e` with `e = u_hat - 2 (u_hat . n) n`, the
//! reflection of `u_hat` at `n`, which is not uniform in `d = 3`: there the two forms differ
//! (the impact form loses `(1 - alpha^2) |u|^2 / (4 d)` per collision on average, the
//! scattering form `(1 - alpha^2) |u|^2 / 8`), and their cooling rates, `a2` and tail exponents
//! with them; in `d = 2` the reflection doubles a uniform angle and the two coincide.

use super::{Declared, Kernel, KernelError, Maxwell, ParamSpec};
use crate::math::Real;

/// The impact-form inelastic Maxwell model `B = gamma C_0`, `n` uniform (module docs): the
/// Maxwell kernel's rate with [`Kernel::UNIFORM_IMPACT`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaxwellImpact {
    rate: Maxwell,
}

impl MaxwellImpact {
    /// `B = gamma * c0`.
    pub fn new(gamma: Real, c0: Real) -> Result<Self, KernelError> {
        Ok(MaxwellImpact {
            rate: Maxwell::new(gamma, c0)?,
        })
    }
    /// `gamma * C_0`.
    pub fn strength(&self) -> Real {
        self.rate.strength()
    }
}

impl Kernel for MaxwellImpact {
    const USES_UMAX: bool = false;
    const UNIFORM_IMPACT: bool = true;
    fn scaled(&self, f: Real) -> Result<Self, KernelError> {
        Ok(MaxwellImpact {
            rate: self.rate.scaled(f)?,
        })
    }
    #[inline(always)]
    fn b_max(&self, umax: Real) -> Real {
        self.rate.b_max(umax)
    }
    #[inline(always)]
    fn acceptance(&self, urel: Real, umax: Real) -> Real {
        self.rate.acceptance(urel, umax)
    }
    #[inline(always)]
    fn pair_rate(&self, urel: Real) -> Real {
        self.rate.pair_rate(urel)
    }
    fn lambda(&self) -> Real {
        0.0
    }
}

impl Declared for MaxwellImpact {
    const PARAMS: &'static [ParamSpec] = &[];
    const TITLE: &'static str = "inelastic Maxwell model, impact form";
    fn from_values(gamma: Real, c: Real, _values: &[Real]) -> Result<Self, KernelError> {
        MaxwellImpact::new(gamma, c)
    }
    fn exponent(_values: &[Real]) -> Option<Real> {
        Some(0.0)
    }
}
