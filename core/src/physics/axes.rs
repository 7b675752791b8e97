//! The kernel axis as one table. Each kernel (GRW (2), (4), (5)) is one row: its variant, its
//! C code, its scene word, its type (declared by it, [`crate::kernel::Declared`]: parameters,
//! title, exponent), the cargo feature that builds it and its words. Every level that lists
//! the kernels is generated from this table by the macro that takes it (glam's "generated from
//! one template"): [`KernelKind`](super::KernelKind) (code, scene word, feature, parameters,
//! title), the validated kernel ([`KernelModel`](super::parts), with [`WithKernel`] for what
//! is done with whichever kernel it holds), the engine's kernel level
//! ([`ByKernel`](super::engine::ByKernel)) and the dispatch's kernel `match`. A new kernel is
//! its file in `kernel/` (and its `mod` line there), its row here and its cargo feature.

use crate::kernel::Kernel;

/// Calls the macro `$then` with the kernel table, one row per kernel:
/// `Variant(code, "scene-word", Type, "cargo-feature", "doc")`.
macro_rules! kernel_table {
    ($then:ident) => {
        $then! {
            Maxwell(
                0,
                "maxwell",
                crate::kernel::Maxwell,
                "maxwell",
                "Maxwell pseudo-molecules, `B = gamma C` (GRW (2), `lambda = 0`)."
            ),
            HardSpheres(
                1,
                "hard-spheres",
                crate::kernel::HardSpheres,
                "hard-spheres",
                "Hard spheres, `B = gamma C |u|` (hard disks in `d = 2`; GRW (4))."
            ),
            Vhs(
                2,
                "vhs",
                crate::kernel::Vhs,
                "vhs",
                "Variable hard spheres, `B = gamma C |u|^lambda` (GRW (5))."
            ),
            MaxwellImpact(
                3,
                "maxwell-impact",
                crate::kernel::MaxwellImpact,
                "maxwell-impact",
                "Ernst and Brito's inelastic Maxwell model in its impact form, `B = gamma C` with \
the impact direction uniform (`e` of GRW (3) its reflection; in `d = 2` the \
Maxwell kernel's law)."
            ),
        }
    };
}
pub(super) use kernel_table;

/// What is done with the validated kernel, whichever it is:
/// [`KernelModel::with`](super::parts) calls [`WithKernel::with`] with it.
pub(super) trait WithKernel {
    /// The result.
    type Out;
    /// Does it with kernel `k`.
    fn with<K: Kernel>(self, k: K) -> Self::Out;
}
