//! SIMD batch kernels over all particles: the kick to an observation time, the moment sums and
//! the lighter sums of a synchronization within a run.
//!
//! Each kernel has a plain scalar twin; the `scalar` feature makes the dispatching functions use
//! the twins (so CI tests both paths), and the tests compare the two with a fixed seed. SIMD is
//! `wide::f64x4`, which picks SSE2/AVX/NEON at compile time (x86_64's baseline is SSE2); on
//! x86_64 the moment sums' loop runs in AVX where the processor has it, chosen at run time
//! ([`lanes_avx`]), with the same bits.

pub mod kick;
pub mod lanes;
#[cfg(target_arch = "x86_64")]
pub mod lanes_avx;
pub mod sums;
pub mod sync;
