//! The kernel axis as one table. Each kernel (GRW (2), (4), (5)) is one row: its variant, its
//! type and the cargo feature that builds it. Every level that lists the kernels is generated
//! from this table by the macro that takes it (glam's "generated from one template"): the
//! validated kernel ([`KernelModel`](super::parts), with [`WithKernel`] for what is done with
//! whichever kernel it holds), the engine's kernel level
//! ([`ByKernel`](super::engine::ByKernel)) and the dispatch's kernel `match`. A new kernel is
//! a row here, its type in `kernel.rs`, its parameters in [`KernelChoice`](super::KernelChoice)
//! and their rules in [`parts::kernel`](super::parts).

use crate::kernel::Kernel;

/// Calls the macro `$then` with the kernel table, one row per kernel:
/// `Variant(Type, "cargo-feature", "doc")`.
macro_rules! kernel_table {
    ($then:ident) => {
        $then! {
            Maxwell(crate::kernel::Maxwell, "maxwell", "Maxwell pseudo-molecules (GRW (2))"),
            HardSpheres(
                crate::kernel::HardSpheres,
                "hard-spheres",
                "Hard spheres (hard disks in `d = 2`; GRW (4))"
            ),
            Vhs(crate::kernel::Vhs, "vhs", "Variable hard spheres (GRW (5))"),
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
