//! Stochastic weighted particles: the SWPM of Rjasanow and Wagner (J. Comput. Phys. 124 (1996)
//! 243-253; "Stochastic Numerics for the Boltzmann Equation", Springer 2005), the building
//! blocks of a weighted scheme for the tails GRW's Conclusions call rare events.
//!
//! A system of `N` particles carries the measure `mu = sum_i g_i delta_{v_i}` of total weight
//! `n0` (the particles a run starts with, each of weight 1). A pair `(i, j)` collides at
//! `int B de * g_i g_j / (gamma(g_i, g_j) n0)` and the collision moves the weight
//! `gamma = min(g_i, g_j)/(1 + kappa)` ([`transfer::Transfer`]) from the pair's velocities to
//! its post-collision velocities ([`transfer::collide`]): `g_i, g_j` lose `gamma`, and two
//! particles of weight `gamma` appear at `v_i'`, `v_j'` (a partner whose weight reaches zero is
//! replaced in place). The expected change of `<phi, mu>` per unit time is then
//! `sum_{i<j} g_i g_j int B [phi(v_i') + phi(v_j') - phi(v_i) - phi(v_j)] de / n0`, the
//! Boltzmann collision operator of GRW (1) on the weighted measure; with `kappa = 0` and equal
//! weights it is GRW's process itself. With `kappa > 0` every collision leaves lighter copies
//! behind, so the particle number grows and the sparse tails fill with light particles; a
//! reduction ([`mod@reduce`]) replaces cells of nearby velocities by a sample of two of their own
//! velocities each (unbiased: the expected measure is the cell's), the replaced particles'
//! weight, momentum and energy kept together by one affine correction.

mod cells;
mod group;
pub mod moments;
pub mod nosplit;
mod packed;
pub mod reduce;
pub mod transfer;
pub mod windows;

pub use reduce::{Reduction, reduce, reduce_allocated};
pub use transfer::{Transfer, collide, collide_with};
