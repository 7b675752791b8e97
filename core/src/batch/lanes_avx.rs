//! The central moment sums' loop ([`super::sums`]) in AVX's 256-bit registers, chosen at run
//! time where the processor has AVX (x86_64 only; the default target's baseline is SSE2, where
//! `wide::f64x4` is two halves and the loop's 15 four-lane accumulators spill).
//!
//! The same lanes, the same operations in the same order, no fused multiply-add: lane `k` sums
//! particles `4 b + k`, each lane's value is the one [`super::lanes::central_lanes`] computes,
//! bit for bit (tested against it). Detection is CPUID's AVX and OSXSAVE bits and XCR0's SSE
//! and AVX state bits (the operating system saves the registers), read once.

#![allow(unsafe_code)]

use super::lanes::Lanes;
use crate::particles::Particle;
use crate::vec3::Vec3;
use core::arch::x86_64::{
    __cpuid, __m256d, _CMP_UNORD_Q, _mm256_add_pd, _mm256_blendv_pd, _mm256_cmp_pd,
    _mm256_loadu_pd, _mm256_max_pd, _mm256_mul_pd, _mm256_permute2f128_pd, _mm256_set1_pd,
    _mm256_setzero_pd, _mm256_sqrt_pd, _mm256_storeu_pd, _mm256_sub_pd, _mm256_unpackhi_pd,
    _mm256_unpacklo_pd, _xgetbv,
};
use core::sync::atomic::{AtomicU8, Ordering};

/// Whether this processor and operating system run AVX (detected once).
pub fn available() -> bool {
    static KNOWN: AtomicU8 = AtomicU8::new(0);
    match KNOWN.load(Ordering::Relaxed) {
        1 => false,
        2 => true,
        _ => {
            let avx = detect();
            KNOWN.store(1 + u8::from(avx), Ordering::Relaxed);
            avx
        }
    }
}

fn detect() -> bool {
    let leaf1 = __cpuid(1);
    let (osxsave, avx) = (leaf1.ecx >> 27 & 1 == 1, leaf1.ecx >> 28 & 1 == 1);
    // SAFETY: OSXSAVE set means XGETBV is enabled and XCR0 readable.
    osxsave && avx && unsafe { xcr0() } & 0b110 == 0b110
}

/// XCR0, the state components the operating system saves.
///
/// # Safety
/// Only where CPUID's OSXSAVE bit is set.
#[target_feature(enable = "xsave")]
unsafe fn xcr0() -> u64 {
    // SAFETY: the caller checked OSXSAVE, so XGETBV does not fault.
    unsafe { _xgetbv(0) }
}

/// The central lanes of `q`'s whole blocks of four about `bulk` with AVX; `None` where the
/// processor has none.
pub fn central_lanes(q: &[Particle], bulk: Vec3) -> Option<Lanes> {
    // SAFETY: AVX is present (checked).
    available().then(|| unsafe { central_lanes_avx(q, bulk) })
}

/// Four lanes out of a register.
#[inline(always)]
fn out(v: __m256d) -> [f64; 4] {
    let mut a = [0.0; 4];
    // SAFETY: `a` holds four doubles; an unaligned store.
    unsafe { _mm256_storeu_pd(a.as_mut_ptr(), v) };
    a
}

/// [`central_lanes`]' kernel.
///
/// # Safety
/// Only where the processor has AVX.
#[target_feature(enable = "avx")]
unsafe fn central_lanes_avx(q: &[Particle], bulk: Vec3) -> Lanes {
    let (bx, by, bz) = (
        _mm256_set1_pd(bulk.x),
        _mm256_set1_pd(bulk.y),
        _mm256_set1_pd(bulk.z),
    );
    let z = _mm256_setzero_pd();
    let (mut c4, mut c6, mut m2) = (z, z, z);
    let (mut e1, mut e3) = (z, z);
    let (mut cxx, mut cyy, mut czz, mut cxy, mut cxz, mut cyz) = (z, z, z, z, z, z);
    let (mut d1, mut d2, mut d3) = (z, z, z);
    let mut q6 = z;
    for block in q.chunks_exact(4) {
        let p = block.as_ptr().cast::<f64>();
        // SAFETY: a block is four `#[repr(C)]` particles of four doubles each, contiguous:
        // sixteen doubles from `p`, read unaligned.
        let [r0, r1, r2, r3] = unsafe {
            [
                _mm256_loadu_pd(p),
                _mm256_loadu_pd(p.add(4)),
                _mm256_loadu_pd(p.add(8)),
                _mm256_loadu_pd(p.add(12)),
            ]
        };
        // Rows [vx, vy, vz, t] to lanes: [vx0, vx1, vz0, vz1], [vy0, vy1, t0, t1], ...
        let (a, b) = (_mm256_unpacklo_pd(r0, r1), _mm256_unpackhi_pd(r0, r1));
        let (c, d) = (_mm256_unpacklo_pd(r2, r3), _mm256_unpackhi_pd(r2, r3));
        let x = _mm256_permute2f128_pd::<0x20>(a, c);
        let y = _mm256_permute2f128_pd::<0x20>(b, d);
        let w = _mm256_permute2f128_pd::<0x31>(a, c);
        let (add, mul) = (_mm256_add_pd, _mm256_mul_pd);
        let v2 = add(add(mul(x, x), mul(y, y)), mul(w, w));
        q6 = add(q6, mul(mul(v2, v2), v2));
        let (x, y, w) = (
            _mm256_sub_pd(x, bx),
            _mm256_sub_pd(y, by),
            _mm256_sub_pd(w, bz),
        );
        let c2 = add(add(mul(x, x), mul(y, y)), mul(w, w));
        cxx = add(cxx, mul(x, x));
        cyy = add(cyy, mul(y, y));
        czz = add(czz, mul(w, w));
        cxy = add(cxy, mul(x, y));
        cxz = add(cxz, mul(x, w));
        cyz = add(cyz, mul(y, w));
        d1 = add(d1, mul(x, c2));
        d2 = add(d2, mul(y, c2));
        d3 = add(d3, mul(w, c2));
        let c4v = mul(c2, c2);
        let cn = _mm256_sqrt_pd(c2);
        e1 = add(e1, cn);
        e3 = add(e3, mul(cn, c2));
        c4 = add(c4, c4v);
        c6 = add(c6, mul(c4v, c2));
        // `wide`'s max: `c2` where it is not NaN and above `m2`, else `m2` (MAXPD's rule
        // with the right operand's NaN kept out).
        let nan = _mm256_cmp_pd::<_CMP_UNORD_Q>(c2, c2);
        m2 = _mm256_blendv_pd(_mm256_max_pd(m2, c2), m2, nan);
    }
    Lanes::from_registers(
        [cxx, cyy, czz, cxy, cxz, cyz],
        [d1, d2, d3],
        [e1, e3, c4, c6, m2, q6],
        out,
    )
}
