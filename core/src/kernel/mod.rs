//! Collision kernels `B(|u|, mu)` of GRW (4), (5) and RW (18), with the majorant that drives the
//! waiting times and the acceptance probability that makes the thinning exact.
//!
//! The event loop is generic over [`Kernel`], so a scene's loop holds only the kernel it uses:
//! for Maxwell pseudo-molecules (`lambda = 0`) there is no majorant to track and no fictitious
//! collision at all ([`Kernel::USES_UMAX`] is `false` and the branches compile away).
//!
//! One file per kernel, each declaring itself by its type ([`Declared`]: its parameters beyond
//! `gamma` and `C`, its title words, its exponent); its row in the kernel table
//! (`physics/axes.rs`) gives its C code, scene word and cargo feature.

pub mod declared;
pub mod hard_spheres;
pub mod maxwell;
pub mod maxwell_impact;
pub mod vhs;

pub use declared::{Declared, MAX_KERNEL_PARAMS, ParamSpec};
pub use hard_spheres::HardSpheres;
pub use maxwell::Maxwell;
pub use maxwell_impact::MaxwellImpact;
pub use vhs::Vhs;

use crate::math::{Real, sqrt};

/// A kernel parameter out of its domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KernelError {
    /// The collision-rate constant gamma of GRW (1) is not finite and positive.
    Gamma,
    /// The kernel constant C_lambda is not finite and positive.
    C,
    /// The rate constant (gamma times C_lambda) is not finite and positive (over- or underflow).
    Strength,
    /// Parameter `.0` of the kernel's declaration ([`Declared::PARAMS`]) breaks its rule or
    /// makes the kernel overflow.
    Param(usize),
}

impl core::fmt::Display for KernelError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            KernelError::Gamma => {
                f.write_str("collision-rate constant gamma must be finite and > 0")
            }
            KernelError::C => f.write_str("kernel constant C must be finite and > 0"),
            KernelError::Strength => {
                f.write_str("collision rate constant gamma * C must be finite and > 0")
            }
            KernelError::Param(i) => write!(f, "kernel parameter {i} breaks its rule"),
        }
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

    /// True for the impact form of the inelastic Maxwell model ([`MaxwellImpact`]): the
    /// impact direction `n` is uniform and `e` of GRW (3) its reflection of `u_hat`, which is
    /// not uniform in d = 3; false for GRW (3)'s scattering form, `e` uniform (the Maxwell and
    /// VHS kernels), and for hard particles, whose `n` follows `HARD`'s impact law.
    const UNIFORM_IMPACT: bool = false;

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

/// `gamma C` when both and their product are finite and positive.
pub(crate) fn check_strength(gamma: Real, c: Real) -> Result<Real, KernelError> {
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
