//! Kernels declared by their type (the drives' model, [`crate::drive::Declared`]): a kernel
//! names once, in its own file, its parameters beyond `gamma` and `C` ([`ParamSpec`]: name,
//! rule, words, unit), how it is built from their values, its exponent and its title words;
//! its row in the kernel table (`physics/axes.rs`) gives its scene word, C code and cargo
//! feature. The scene's `[collisions]` keys, the C ABI's `kernel_params`, the validation's
//! errors, the engine's kernel level, the dispatch and the runner's words are derived from
//! these declarations.

use super::{Kernel, KernelError};
pub use crate::declared::ParamSpec;
use crate::math::Real;

/// Most parameters a kernel has beyond `gamma` and `C` (the C ABI's `kernel_params`).
pub const MAX_KERNEL_PARAMS: usize = 4;

/// A kernel `B = gamma C |u|^lambda` declared by its type.
pub trait Declared: Kernel + PartialEq + 'static {
    /// Its parameters beyond `gamma` and `C`, in the order of their values (the C ABI's
    /// `kernel_params`).
    const PARAMS: &'static [ParamSpec];
    /// Its name in a chart's title ("hard-sphere kernel"); the title adds the parameters.
    const TITLE: &'static str;

    /// The kernel of `gamma`, `C` and these values, each of which obeys its rule; refused
    /// ([`KernelError`]) when `gamma`, `C` or their product is not finite and positive, or a
    /// value makes it overflow.
    fn from_values(gamma: Real, c: Real, values: &[Real]) -> Result<Self, KernelError>;

    /// The exponent `lambda` of these values' kernel when it is the power law
    /// `B = gamma C |u|^lambda` at every speed (GRW (5)); `None` for a kernel that is not one (a
    /// capped or tabulated kernel). What the references read before a kernel is built: every
    /// power-law result (Haff's law, the Sonine and Maxwellian approximations, GRW (16)) holds
    /// only where this is `Some`, and nothing pretends an exponent for a kernel without one.
    fn exponent(values: &[Real]) -> Option<Real>;
}
