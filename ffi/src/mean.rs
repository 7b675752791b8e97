//! The statistics kit's ensemble mean for C: a caller-owned accumulator fed one ensemble's
//! value at a time, and its mean with the 99.9% interval `gdsmc run` reports (GRW (25): 3.2
//! sigma, the Student-t quantile of `M - 1` degrees of freedom at that level when ensembles are
//! few, `gdsmc_stats::multiplier`). The same arithmetic as the command's accumulator
//! (`gdsmc_stats::welford`), so values added in ensemble order give its mean to the bit.
//! Needs the standard library.

use crate::guard::{check_ptr, guard};
use crate::status::{fail, gdsmc_status, msg};

/// A running ensemble mean: initialise with zeros (`gdsmc_mean acc = {0};`), add one value per
/// ensemble with gdsmc_mean_add, read with gdsmc_mean_interval. Plain data: copy it freely.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct gdsmc_mean {
    /// Values added.
    pub count: u64,
    /// Their mean.
    pub mean: f64,
    /// The sum of their squared deviations from the mean (Welford's `M2`).
    pub m2: f64,
}

/// Adds one ensemble's value `x` to `*acc`. GDSMC_NON_FINITE for a NaN or infinite `x` (the
/// accumulator is unchanged then).
///
/// # Safety
/// `acc` NULL or a readable and writable gdsmc_mean.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_mean_add(acc: *mut gdsmc_mean, x: f64) -> gdsmc_status {
    guard(|| {
        check_ptr(acc, "acc")?;
        if !x.is_finite() {
            return fail(
                gdsmc_status::GDSMC_NON_FINITE,
                msg!("x = {x} is not finite"),
            );
        }
        // SAFETY: checked non-null and aligned; the caller provides a live gdsmc_mean.
        let a = unsafe { &mut *acc };
        a.count += 1;
        gdsmc_stats::welford(a.count, &mut a.mean, &mut a.m2, x);
        Ok(())
    })
}

/// `*mean` = the mean of the values added to `*acc`, `*half_width` = the half-width of its
/// 99.9% confidence interval, `t sqrt(s^2 / M)` with Student's t quantile of `M - 1` degrees
/// of freedom at the two-sided level of 3.2 normal sigma (3.446 at M = 40; 3.2 as M grows),
/// as `gdsmc run` computes it. GDSMC_INVALID_ARGUMENT below two values (no variance).
///
/// # Safety
/// `acc` NULL or a readable gdsmc_mean; `mean` and `half_width` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_mean_interval(
    acc: *const gdsmc_mean,
    mean: *mut f64,
    half_width: *mut f64,
) -> gdsmc_status {
    guard(|| {
        check_ptr(acc, "acc")?;
        check_ptr(mean, "mean")?;
        check_ptr(half_width, "half_width")?;
        // SAFETY: checked non-null and aligned.
        let a = unsafe { acc.read() };
        if a.count < 2 {
            return fail(
                gdsmc_status::GDSMC_INVALID_ARGUMENT,
                msg!("an interval needs two values or more; {} added", a.count),
            );
        }
        let variance = a.m2 / (a.count - 1) as f64;
        let h = gdsmc_stats::multiplier(a.count) * (variance / a.count as f64).sqrt();
        // SAFETY: checked non-null and aligned.
        unsafe {
            mean.write(a.mean);
            half_width.write(h);
        }
        Ok(())
    })
}
