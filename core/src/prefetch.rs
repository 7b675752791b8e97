//! A cache-prefetch hint for the event loops' random particle accesses.
//!
//! At large `n` each candidate pair costs two cache misses; the no-splitting loop draws its
//! pairs a few events ahead and asks for their cache lines early, so the misses of
//! independent pairs overlap (RW Algorithm 3 is unchanged: pairs are i.i.d. uniform whatever
//! their drawing order). A hint only: it never changes a result.

/// Asks the CPU to bring the cache line holding `x` into the cache (x86-64); a no-op
/// elsewhere.
#[inline(always)]
#[allow(unsafe_code)]
pub fn prefetch<T>(x: &T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: `_mm_prefetch` is a hint that never faults and neither reads nor writes memory
    // visibly; the pointer comes from a live reference. SSE is part of the x86-64 baseline.
    unsafe {
        use core::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        _mm_prefetch::<_MM_HINT_T0>((x as *const T).cast::<i8>());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = x;
}
