//! Collision kernels `B(|u|, mu)` of GRW (4), (5) and RW (18), with the majorant that drives the
//! waiting times and the acceptance probability that makes the thinning exact.
//!
//! The event loop is generic over [`Kernel`], so a scene's loop holds only the kernel it uses:
//! for Maxwell pseudo-molecules (`lambda = 0`) there is no majorant to track and no fictitious
//! collision at all ([`Kernel::USES_UMAX`] is `false` and the branches compile away).

use crate::math::{PI, Real, powf, sqrt};

/// A kernel parameter out of its domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KernelError {
    /// The collision-rate constant gamma of GRW (1) is not finite and positive.
    Gamma,
    /// The kernel constant C_lambda is not finite and positive.
    C,
    /// The rate constant (gamma times C_lambda) is not finite and positive (over- or underflow).
    Strength,
    /// The VHS exponent is outside [0, 1].
    Lambda,
}

impl core::fmt::Display for KernelError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            KernelError::Gamma => "collision-rate constant gamma must be finite and > 0",
            KernelError::C => "kernel constant C must be finite and > 0",
            KernelError::Strength => "collision rate constant gamma * C must be finite and > 0",
            KernelError::Lambda => "VHS exponent lambda must lie in [0, 1]",
        })
    }
}

/// An isotropic collision kernel `B = gamma C_lambda |u|^lambda` (GRW (1), (5)): `gamma` is the
/// collision-rate constant of GRW (1) and folded into the kernel's strength.
pub trait Kernel: Copy + core::fmt::Debug {
    /// True when the majorant depends on the maximal relative speed `Umax` (`lambda > 0`).
    const USES_UMAX: bool;

    /// True for hard spheres: the scattering direction follows the hard-particle impact law.
    /// In d = 3 that law makes `e` of GRW (3) uniform, as every kernel here has it; in d = 2
    /// (hard disks) it does not ([`crate::geometry::Disks`]), while the Maxwell and VHS
    /// kernels keep isotropic scattering.
    const HARD: bool = false;

    /// `int_{S^2} B de <= B_max = 4 pi gamma C_lambda Umax^lambda`: GRW (19), RW (7), (19).
    fn b_max(&self, umax: Real) -> Real;

    /// The event rate of an `n`-particle system, `(n - 1)/2 B_max`
    /// `= 2 pi gamma C_lambda (n - 1) Umax^lambda`: GRW Section 3, RW (8), (20).
    #[inline(always)]
    fn majorant_rate(&self, n: usize, umax: Real) -> Real {
        0.5 * (n - 1) as Real * self.b_max(umax)
    }

    /// Probability that a candidate pair with relative speed `urel` collides for real,
    /// `min(1, (urel / Umax)^lambda)`: one minus GRW (20). The `min` is the kernel truncation of
    /// RW (19) and takes effect only when the majorant was overshot (counted by the engine).
    fn acceptance(&self, urel: Real, umax: Real) -> Real;

    /// Whether a candidate with squared relative speed `u2` collides for real, given the
    /// majorant `umax` and a uniform `r` in [0, 1): `r < acceptance(|u|, umax)` (GRW (20)).
    /// Kernels whose acceptance is a power of `|u|` may decide it without the square root.
    #[inline(always)]
    fn accepts(&self, u2: Real, umax: Real, r: Real) -> bool {
        r < self.acceptance(sqrt(u2), umax)
    }

    /// The exact total rate `int_{S^2} B de = 4 pi gamma C_lambda |u|^lambda` of a pair.
    fn pair_rate(&self, urel: Real) -> Real;

    /// The exponent `lambda` of `|u|^lambda`.
    fn lambda(&self) -> Real;

    /// This kernel as hard spheres, if it is (for the schemes that need the impact form).
    fn as_hard_spheres(&self) -> Option<HardSpheres> {
        None
    }

    /// The same kernel with its strength `gamma C_lambda` times `f > 0` (the cross section of
    /// a mixture's species pair); refused when the product is not finite and positive.
    fn scaled(&self, f: Real) -> Result<Self, KernelError>;
}

fn check_strength(gamma: Real, c: Real) -> Result<Real, KernelError> {
    if !(gamma.is_finite() && gamma > 0.0) {
        return Err(KernelError::Gamma);
    }
    if !(c.is_finite() && c > 0.0) {
        return Err(KernelError::C);
    }
    let s = gamma * c;
    if s.is_finite() && s > 0.0 {
        Ok(s)
    } else {
        Err(KernelError::Strength)
    }
}

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
            return Err(KernelError::Lambda);
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
