//! Status codes, messages and the last-error message (per thread with `std`; one for the
//! whole program in the `no_std` build, which is single-context).

use core::ffi::c_char;
use core::fmt::Write;

/// The result of every fallible gdsmc call.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum gdsmc_status {
    /// Success.
    GDSMC_OK = 0,
    /// A required pointer argument was NULL.
    GDSMC_NULL_POINTER = 1,
    /// A pointer argument was not aligned for its type (see gdsmc_sim_footprint for memory
    /// handed to gdsmc_sim_init_in).
    GDSMC_MISALIGNED = 2,
    /// A caller buffer is smaller than needed.
    GDSMC_BUFFER_TOO_SMALL = 3,
    /// A parameter is out of its domain (the message names it).
    GDSMC_INVALID_ARGUMENT = 4,
    /// The handle is not a live simulation (destroyed, or not made by gdsmc).
    GDSMC_INVALID_HANDLE = 5,
    /// The requested time lies before the simulation's current time.
    GDSMC_TIME_BACKWARDS = 6,
    /// A velocity or moment became non-finite.
    GDSMC_NON_FINITE = 7,
    /// Scene text is not valid TOML or does not match the scene schema.
    GDSMC_PARSE_ERROR = 8,
    /// gdsmc panicked; the panic was caught at the boundary. Please report it.
    GDSMC_PANIC = 9,
    /// Memory for the particles could not be allocated (gdsmc_sim_create).
    GDSMC_OUT_OF_MEMORY = 10,
    /// gdsmc_sim_advance would take more work (candidate events, background events, particle
    /// updates) than the simulation's limit (gdsmc_sim_set_work_limit); nothing was run.
    GDSMC_TOO_MUCH_WORK = 11,
    /// No reference of that name holds for this configuration (gdsmc_reference_find).
    GDSMC_NOT_FOUND = 12,
    /// A reference's arithmetic cannot hold at some of the asked times (its closed form leaves
    /// the range of double there): the values are filled, NaN at those times, and the message
    /// names them. Never a wrong number.
    GDSMC_NOT_COMPUTABLE = 13,
}

/// Most bytes a message keeps (longer ones are cut at a character boundary).
pub(crate) const MSG_CAP: usize = 512;

/// A message: fixed capacity, so that the `no_std` build needs no allocator. (Named through
/// an alias: cbindgen takes any `String<..>` for the standard library's and stops.)
pub(crate) type Msg = FixedText<MSG_CAP>;
use heapless::String as FixedText;

/// Writes into a [`Msg`], dropping what does not fit.
struct Cut<'a>(&'a mut Msg);

impl Write for Cut<'_> {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        for ch in s.chars() {
            if self.0.push(ch).is_err() {
                break;
            }
        }
        Ok(())
    }
}

/// A message from format arguments (see the `msg!` macro).
pub(crate) fn message(args: core::fmt::Arguments<'_>) -> Msg {
    let mut m = Msg::new();
    let _ = Cut(&mut m).write_fmt(args);
    m
}

/// `format!` into a [`Msg`].
macro_rules! msg {
    ($($t:tt)*) => { $crate::status::message(format_args!($($t)*)) };
}
pub(crate) use msg;

/// The status and message of an engine's refusal.
pub(crate) fn engine_error(e: gdsmc_core::engine::EngineError) -> Failure {
    use gdsmc_core::engine::EngineError;
    let s = match e {
        EngineError::TimeBackwards => gdsmc_status::GDSMC_TIME_BACKWARDS,
        EngineError::NonFinite(_) => gdsmc_status::GDSMC_NON_FINITE,
        EngineError::OffGrid
        | EngineError::ParticleCount
        | EngineError::Spins
        | EngineError::NotBuilt(_) => gdsmc_status::GDSMC_INVALID_ARGUMENT,
        // A bug of ours, reported as the panic boundary reports one.
        EngineError::Invariant(_) => gdsmc_status::GDSMC_PANIC,
    };
    let m = match e {
        EngineError::OffGrid => msg!(
            "the time is not a whole multiple of config.dt from the start, at least one step on (splitting schemes)"
        ),
        _ => msg!("{e}"),
    };
    Failure(s, m)
}

/// An error: its status and message.
#[derive(Debug)]
pub(crate) struct Failure(pub gdsmc_status, pub Msg);

pub(crate) fn fail<T>(status: gdsmc_status, m: impl core::fmt::Display) -> Result<T, Failure> {
    Err(Failure(status, msg!("{m}")))
}

#[cfg(feature = "std")]
mod last {
    use super::Msg;
    use std::cell::RefCell;

    thread_local! {
        static LAST_ERROR: RefCell<Msg> = const { RefCell::new(Msg::new()) };
    }

    pub(crate) fn set(m: &str) {
        LAST_ERROR.with(|e| {
            let mut e = e.borrow_mut();
            e.clear();
            let _ = e.push_str(m);
        });
    }

    pub(crate) fn with<R>(f: impl FnOnce(&str) -> R) -> R {
        LAST_ERROR.with(|e| f(&e.borrow()))
    }
}

#[cfg(not(feature = "std"))]
mod last {
    use super::Msg;
    use core::cell::UnsafeCell;

    /// The one message of a single-context program.
    struct Slot(UnsafeCell<Msg>);
    // SAFETY: the no_std build is documented as single-context (gdsmc.h: no calls from
    // interrupts or other threads), so the slot is never accessed concurrently.
    unsafe impl Sync for Slot {}
    static LAST_ERROR: Slot = Slot(UnsafeCell::new(Msg::new()));

    pub(crate) fn set(m: &str) {
        // SAFETY: single context (see Slot); no reference outlives this call.
        let e = unsafe { &mut *LAST_ERROR.0.get() };
        e.clear();
        let _ = e.push_str(m);
    }

    pub(crate) fn with<R>(f: impl FnOnce(&str) -> R) -> R {
        // SAFETY: single context (see Slot); the reference lives for this call only.
        f(unsafe { &*LAST_ERROR.0.get() })
    }
}

pub(crate) fn set_last_error(m: &str) {
    last::set(m);
}

/// Copies the last error message (empty after a success) into `buf` of `len` bytes, truncated
/// and always NUL-terminated when `len > 0`. Returns the message's full length in bytes without
/// the NUL, so a caller can size a buffer (`buf` may be NULL when `len` is 0). With the
/// standard library each thread has its own message; the no_std build keeps one.
///
/// # Safety
/// `buf` must point to `len` writable bytes (or be NULL with `len == 0`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_last_error(buf: *mut c_char, len: usize) -> usize {
    last::with(|e| {
        let bytes = e.as_bytes();
        if !buf.is_null() && len > 0 {
            let k = bytes.len().min(len - 1);
            // SAFETY: the caller gives `len` writable bytes at `buf`; we write k + 1 <= len.
            unsafe {
                core::ptr::copy_nonoverlapping(bytes.as_ptr(), buf.cast::<u8>(), k);
                *buf.add(k) = 0;
            }
        }
        bytes.len()
    })
}
