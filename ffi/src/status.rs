//! Status codes and the thread-local last-error message.

use std::cell::RefCell;
use std::ffi::c_char;

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
}

/// The status and message of an engine's refusal.
pub(crate) fn engine_error(e: gdsmc_core::engine::EngineError) -> Failure {
    use gdsmc_core::engine::EngineError;
    let s = match e {
        EngineError::TimeBackwards => gdsmc_status::GDSMC_TIME_BACKWARDS,
        EngineError::NonFinite => gdsmc_status::GDSMC_NON_FINITE,
        EngineError::OffGrid | EngineError::ParticleCount => gdsmc_status::GDSMC_INVALID_ARGUMENT,
    };
    let msg = match e {
        EngineError::OffGrid => {
            "the time is not a multiple of config.dt (splitting schemes)".to_string()
        }
        _ => e.to_string(),
    };
    Failure(s, msg)
}

/// An error: its status and message.
#[derive(Debug)]
pub(crate) struct Failure(pub gdsmc_status, pub String);

pub(crate) fn fail<T>(status: gdsmc_status, msg: impl Into<String>) -> Result<T, Failure> {
    Err(Failure(status, msg.into()))
}

thread_local! {
    static LAST_ERROR: RefCell<String> = const { RefCell::new(String::new()) };
}

pub(crate) fn set_last_error(msg: &str) {
    LAST_ERROR.with(|e| {
        let mut e = e.borrow_mut();
        e.clear();
        e.push_str(msg);
    });
}

/// Copies the calling thread's last error message (empty after a success) into `buf` of `len`
/// bytes, truncated and always NUL-terminated when `len > 0`. Returns the message's full
/// length in bytes without the NUL, so a caller can size a buffer (`buf` may be NULL when `len`
/// is 0). Thread-safe: each thread has its own message.
///
/// # Safety
/// `buf` must point to `len` writable bytes (or be NULL with `len == 0`).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn gdsmc_last_error(buf: *mut c_char, len: usize) -> usize {
    let r = std::panic::catch_unwind(|| {
        LAST_ERROR.with(|e| {
            let e = e.borrow();
            let bytes = e.as_bytes();
            if !buf.is_null() && len > 0 {
                let k = bytes.len().min(len - 1);
                // SAFETY: the caller gives `len` writable bytes at `buf`; we write k + 1 <= len.
                unsafe {
                    std::ptr::copy_nonoverlapping(bytes.as_ptr(), buf.cast::<u8>(), k);
                    *buf.add(k) = 0;
                }
            }
            bytes.len()
        })
    });
    r.unwrap_or(0)
}
