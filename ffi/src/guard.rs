//! The panic boundary around every exported function.

use crate::status::{Failure, gdsmc_status, msg, set_last_error};

/// Runs `f`, turning its error or a panic into a status and the thread's last-error message.
/// A panic is caught silently: its message and place go to `gdsmc_last_error` only, never to
/// the caller's stderr (see [`quiet`]).
#[cfg(feature = "std")]
pub(crate) fn guard(f: impl FnOnce() -> Result<(), Failure>) -> gdsmc_status {
    use std::panic::{AssertUnwindSafe, catch_unwind};
    let outcome = quiet::inside(|| catch_unwind(AssertUnwindSafe(f)));
    match outcome {
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
            let place = quiet::take_place();
            set_last_error(&msg!(
                "internal error (panic caught at the C boundary{place}): {what}"
            ));
            gdsmc_status::GDSMC_PANIC
        }
    }
}

/// Keeping a caught panic off the caller's stderr. Rust reports a panic through the process's
/// panic hook before unwinding starts, so `catch_unwind` alone still prints. On the first call
/// into the library the hook is wrapped once: while the calling thread is inside a gdsmc call
/// the wrapper records the panic's place (for the last-error message) and prints nothing;
/// everywhere else it calls the hook that was there before (the caller's own panics print as
/// they always did). A hook the caller installs later replaces ours; gdsmc then prints again
/// but still never unwinds across the boundary.
#[cfg(feature = "std")]
mod quiet {
    use std::cell::{Cell, RefCell};
    use std::sync::Once;

    thread_local! {
        static DEPTH: Cell<u32> = const { Cell::new(0) };
        static PLACE: RefCell<String> = const { RefCell::new(String::new()) };
    }
    static INSTALL: Once = Once::new();

    /// Runs `f` with this thread marked as inside a gdsmc call.
    pub(super) fn inside<R>(f: impl FnOnce() -> R) -> R {
        INSTALL.call_once(|| {
            let before = std::panic::take_hook();
            std::panic::set_hook(Box::new(move |info| {
                if DEPTH.with(Cell::get) > 0 {
                    let place = info
                        .location()
                        .map(|l| format!(" at {}:{}", l.file(), l.line()))
                        .unwrap_or_default();
                    PLACE.with(|p| *p.borrow_mut() = place);
                } else {
                    before(info);
                }
            }));
        });
        DEPTH.with(|d| d.set(d.get() + 1));
        let r = f();
        DEPTH.with(|d| d.set(d.get() - 1));
        r
    }

    /// The place of the last panic caught on this thread (` at file:line`), or empty.
    pub(super) fn take_place() -> String {
        PLACE.with(|p| std::mem::take(&mut *p.borrow_mut()))
    }
}

/// Panics on purpose inside the library, to test the boundary (feature `fault-injection`, off
/// in every build but the tests; nothing of it is in the header).
#[cfg(feature = "fault-injection")]
pub mod fault {
    use std::cell::Cell;

    thread_local! {
        static ARMED: Cell<bool> = const { Cell::new(false) };
    }

    /// The next simulation built on this thread panics after its particles are allocated and
    /// before the handle owns them (the path that once leaked them).
    pub fn panic_in_next_build() {
        ARMED.with(|a| a.set(true));
    }

    /// Panics when armed (once), at the caller's place.
    #[track_caller]
    pub(crate) fn check() {
        if ARMED.with(|a| a.replace(false)) {
            panic!("injected fault");
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
