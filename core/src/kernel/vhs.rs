//! Variable hard spheres (GRW (5), RW (18)): a rate proportional to a power `0 <= lambda <= 1`
//! of the relative speed, isotropic scattering.

use super::{Declared, Kernel, KernelError, ParamSpec, check_strength};
use crate::declared::Rule;
use crate::math::{PI, Real, powf, sqrt};

/// Variable hard spheres `B = gamma C_lambda |u|^lambda`, `0 <= lambda <= 1` (GRW (5), RW (18)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vhs {
    strength: Real,
    lambda: Real,
}

impl Vhs {
    /// `B = gamma * c * |u|^lambda`.
    pub fn new(gamma: Real, c: Real, lambda: Real) -> Result<Self, KernelError> {
        let strength = check_strength(gamma, c)?;
        if !(0.0..=1.0).contains(&lambda) {
            return Err(KernelError::Param(0));
        }
        Ok(Vhs { strength, lambda })
    }
    /// `gamma * C_lambda`.
    pub fn strength(&self) -> Real {
        self.strength
    }
}

impl Kernel for Vhs {
    const USES_UMAX: bool = true;
    fn scaled(&self, f: Real) -> Result<Self, KernelError> {
        Vhs::new(self.strength, f, self.lambda)
    }
    #[inline(always)]
    fn b_max(&self, umax: Real) -> Real {
        4.0 * PI * self.strength * powf(umax, self.lambda)
    }
    #[inline(always)]
    fn acceptance(&self, urel: Real, umax: Real) -> Real {
        if urel < umax {
            powf(urel / umax, self.lambda)
        } else {
            1.0
        }
    }
    /// `r < (|u| / Umax)^lambda`; for `lambda = 1/2` (GRW Example 8's VHS) as
    /// `(r^2 Umax)^2 < |u|^2`, with no power and no square root (both sides non-negative; an
    /// overshoot `|u| > Umax` is accepted for every `r < 1`, as `min(1, .)` does).
    #[inline(always)]
    fn accepts(&self, u2: Real, umax: Real, r: Real) -> bool {
        if self.lambda == 0.5 {
            let ru = r * r * umax;
            return ru * ru < u2;
        }
        r < self.acceptance(sqrt(u2), umax)
    }
    #[inline(always)]
    fn pair_rate(&self, urel: Real) -> Real {
        4.0 * PI * self.strength * powf(urel, self.lambda)
    }
    fn lambda(&self) -> Real {
        self.lambda
    }
}

impl Declared for Vhs {
    const PARAMS: &'static [ParamSpec] = &[ParamSpec {
        name: "lambda",
        rule: Rule::Within {
            lo: 0.0,
            hi: 1.0,
            range: "[0, 1]",
        },
        words: "the exponent lambda of B = gamma C |u|^lambda (GRW (5); 0: Maxwell, 1: hard spheres)",
        unit: "dimensionless",
        default: None,
        example: 0.5,
    }];
    const TITLE: &'static str = "VHS kernel";
    fn from_values(gamma: Real, c: Real, values: &[Real]) -> Result<Self, KernelError> {
        Vhs::new(gamma, c, values[0])
    }
    fn exponent(values: &[Real]) -> Option<Real> {
        Some(values[0])
    }
}
