//! The panic boundary around every exported function.

use crate::status::{Failure, gdsmc_status, msg, set_last_error};

/// Runs `f`, turning its error or a panic into a status and the thread's last-error message.
#[cfg(feature = "std")]
pub(crate) fn guard(f: impl FnOnce() -> Result<(), Failure>) -> gdsmc_status {
    use std::panic::{AssertUnwindSafe, catch_unwind};
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(())) => {
            set_last_error("");
            gdsmc_status::GDSMC_OK
        }
        Ok(Err(Failure(s, m))) => {
            set_last_error(&m);
            s
        }
        Err(p) => {
            let what = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            set_last_error(&msg!(
                "internal error (panic caught at the C boundary): {what}"
            ));
            gdsmc_status::GDSMC_PANIC
        }
    }
}

/// Runs `f`, turning its error into a status and the last-error message. The no_std build has
/// no unwinding: a panic calls the C library's `abort()` (see [`crate::panic`]).
#[cfg(not(feature = "std"))]
pub(crate) fn guard(f: impl FnOnce() -> Result<(), Failure>) -> gdsmc_status {
    match f() {
        Ok(()) => {
            set_last_error("");
            gdsmc_status::GDSMC_OK
        }
        Err(Failure(s, m)) => {
            set_last_error(&m);
            s
        }
    }
}

/// Checks a pointer for null and alignment; names the argument in the message.
pub(crate) fn check_ptr<T>(p: *const T, name: &str) -> Result<(), Failure> {
    if p.is_null() {
        return Err(Failure(
            gdsmc_status::GDSMC_NULL_POINTER,
            msg!("`{name}` is NULL"),
        ));
    }
    if !(p as usize).is_multiple_of(core::mem::align_of::<T>()) {
        return Err(Failure(
            gdsmc_status::GDSMC_MISALIGNED,
            msg!(
                "`{name}` is not aligned to {} bytes",
                core::mem::align_of::<T>()
            ),
        ));
    }
    Ok(())
}
