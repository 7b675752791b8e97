//! The floating-point shim: one scalar alias and every elementary function the core uses.
//!
//! All floating-point math in `gdsmc-core` goes through this module so that a single-precision
//! build (for FPUs without double precision, such as thumbv7em's) stays a contained change:
//! switch [`Real`] and the `libm` functions below to their `f32` forms. Without `std`, `libm`
//! provides the functions; on x86_64 its `sqrt` compiles to the SSE2 instruction, on WebAssembly
//! with SIMD [`sqrt`] and [`floor`] are the instructions.

/// The scalar type of the whole core.
pub type Real = f64;

/// pi.
pub const PI: Real = core::f64::consts::PI;

/// `sqrt(pi)`, the correctly rounded root of [`PI`] (the same bits as `sqrt(PI)`, which the
/// SSE2 `sqrt` would otherwise compute at run time: inline assembly is never folded).
pub const SQRT_PI: Real = 1.772_453_850_905_515_9;

/// Square root.
#[inline(always)]
pub fn sqrt(x: Real) -> Real {
    // WebAssembly has the instruction, which libm uses only with its unstable intrinsics: its
    // software root (128-bit products) took a quarter of the browser page's time. Through the
    // stable SIMD intrinsic (the page's build has SIMD, web/build.sh), which LLVM emits as the
    // scalar `f64.sqrt`; both are IEEE's correctly rounded root, so the bits are the same.
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    {
        use core::arch::wasm32::{f64x2_extract_lane, f64x2_splat, f64x2_sqrt};
        f64x2_extract_lane::<0>(f64x2_sqrt(f64x2_splat(x)))
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    libm::sqrt(x)
}

/// Natural logarithm.
#[inline(always)]
pub fn ln(x: Real) -> Real {
    libm::log(x)
}

/// Base-10 logarithm.
#[inline(always)]
pub fn log10(x: Real) -> Real {
    libm::log10(x)
}

/// Exponential.
#[inline(always)]
pub fn exp(x: Real) -> Real {
    libm::exp(x)
}

/// `exp(x) - 1`, accurate for small `x`.
#[inline(always)]
pub fn exp_m1(x: Real) -> Real {
    libm::expm1(x)
}

/// `ln(1 + x)`, accurate for small `x`.
#[inline(always)]
pub fn ln_1p(x: Real) -> Real {
    libm::log1p(x)
}

/// `x` to the power `y`.
#[inline(always)]
pub fn powf(x: Real, y: Real) -> Real {
    libm::pow(x, y)
}

/// Sine and cosine of `x`.
#[inline(always)]
pub fn sin_cos(x: Real) -> (Real, Real) {
    libm::sincos(x)
}

/// Absolute value.
#[inline(always)]
pub fn abs(x: Real) -> Real {
    libm::fabs(x)
}

/// Error function.
#[inline(always)]
pub fn erf(x: Real) -> Real {
    libm::erf(x)
}

/// Largest integer value not greater than `x`.
#[inline(always)]
pub fn floor(x: Real) -> Real {
    // The instruction on WebAssembly, as for [`sqrt`]: exact, the same bits.
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    {
        use core::arch::wasm32::{f64x2_extract_lane, f64x2_floor, f64x2_splat};
        f64x2_extract_lane::<0>(f64x2_floor(f64x2_splat(x)))
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    libm::floor(x)
}

/// Larger of two values (NaN-ignoring, as `f64::max`).
#[inline(always)]
pub fn max(a: Real, b: Real) -> Real {
    libm::fmax(a, b)
}

/// Smaller of two values (NaN-ignoring, as `f64::min`).
#[inline(always)]
pub fn min(a: Real, b: Real) -> Real {
    libm::fmin(a, b)
}

/// Four lanes of [`Real`] for the SIMD batch kernels.
pub type RealX4 = wide::f64x4;

/// A value in [1, 2) whose mantissa is the top 52 bits of `bits` (the ziggurat's uniform).
#[inline(always)]
pub fn one_to_two(bits: u64) -> Real {
    f64::from_bits((bits >> 12) | 0x3ff0_0000_0000_0000)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sqrt_pi_is_the_root_of_pi_to_the_bit() {
        assert_eq!(SQRT_PI.to_bits(), sqrt(PI).to_bits());
    }
}
