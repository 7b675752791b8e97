//! Maxwell pseudo-molecules (GRW (2)): a rate that does not depend on the relative speed.

use super::{Declared, Kernel, KernelError, ParamSpec, check_strength};
use crate::math::{PI, Real};

/// Maxwell pseudo-molecules `B = gamma C_0` (GRW: `C_0 = 1/(4 pi)`; RW (22): `C_0 = 1/pi`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Maxwell {
    strength: Real,
}

impl Maxwell {
    /// `B = gamma * c0`.
    pub fn new(gamma: Real, c0: Real) -> Result<Self, KernelError> {
        Ok(Maxwell {
            strength: check_strength(gamma, c0)?,
        })
    }
    /// `gamma * C_0`.
    pub fn strength(&self) -> Real {
        self.strength
    }
}

impl Kernel for Maxwell {
    const USES_UMAX: bool = false;
    fn scaled(&self, f: Real) -> Result<Self, KernelError> {
        Maxwell::new(self.strength, f)
    }
    #[inline(always)]
    fn b_max(&self, _umax: Real) -> Real {
        4.0 * PI * self.strength
    }
    #[inline(always)]
    fn acceptance(&self, _urel: Real, _umax: Real) -> Real {
        1.0
    }
    #[inline(always)]
    fn pair_rate(&self, _urel: Real) -> Real {
        4.0 * PI * self.strength
    }
    fn lambda(&self) -> Real {
        0.0
    }
}

impl Declared for Maxwell {
    const PARAMS: &'static [ParamSpec] = &[];
    const TITLE: &'static str = "Maxwell kernel";
    fn from_values(gamma: Real, c: Real, _values: &[Real]) -> Result<Self, KernelError> {
        Maxwell::new(gamma, c)
    }
    fn exponent(_values: &[Real]) -> Option<Real> {
        Some(0.0)
    }
}
