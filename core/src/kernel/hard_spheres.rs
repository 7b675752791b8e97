//! Hard spheres (GRW (4); hard disks in `d = 2`): a rate proportional to the relative speed,
//! the scattering direction by the hard-particle impact law.

use super::{Declared, Kernel, KernelError, ParamSpec, check_strength};
use crate::math::{PI, Real};

/// Hard spheres `B = gamma C_1 |u|` (GRW (4) with `C_1 = d^2/4`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HardSpheres {
    strength: Real,
}

impl HardSpheres {
    /// `B = gamma * c1 * |u|`.
    pub fn new(gamma: Real, c1: Real) -> Result<Self, KernelError> {
        Ok(HardSpheres {
            strength: check_strength(gamma, c1)?,
        })
    }
    /// `gamma * C_1`.
    pub fn strength(&self) -> Real {
        self.strength
    }
}

impl Kernel for HardSpheres {
    const USES_UMAX: bool = true;
    const HARD: bool = true;
    fn scaled(&self, f: Real) -> Result<Self, KernelError> {
        HardSpheres::new(self.strength, f)
    }
    #[inline(always)]
    fn b_max(&self, umax: Real) -> Real {
        4.0 * PI * self.strength * umax
    }
    #[inline(always)]
    fn acceptance(&self, urel: Real, umax: Real) -> Real {
        if urel < umax { urel / umax } else { 1.0 }
    }
    /// `r < |u| / Umax` as `(r Umax)^2 < |u|^2` (both sides non-negative; when the majorant
    /// is overshot, `r < 1` makes it true, as `min(1, .)` does): no square root per candidate.
    #[inline(always)]
    fn accepts(&self, u2: Real, umax: Real, r: Real) -> bool {
        let ru = r * umax;
        ru * ru < u2
    }
    #[inline(always)]
    fn pair_rate(&self, urel: Real) -> Real {
        4.0 * PI * self.strength * urel
    }
    fn lambda(&self) -> Real {
        1.0
    }
    fn as_hard_spheres(&self) -> Option<HardSpheres> {
        Some(*self)
    }
}

impl Declared for HardSpheres {
    const PARAMS: &'static [ParamSpec] = &[];
    const TITLE: &'static str = "hard-sphere kernel";
    fn from_values(gamma: Real, c: Real, _values: &[Real]) -> Result<Self, KernelError> {
        HardSpheres::new(gamma, c)
    }
    fn exponent(_values: &[Real]) -> Option<Real> {
        Some(1.0)
    }
}
