//! # gdsmc-ffi: the C ABI of gdsmc
//!
//! Builds `libgdsmc.a` and `libgdsmc.so`; `include/gdsmc.h` is generated from this crate by
//! cbindgen (`ffi/cbindgen.toml`). Conventions, after rustls-ffi:
//!
//! - every fallible function returns a [`gdsmc_status`]; on failure a message for the calling
//!   thread is kept and [`gdsmc_last_error`] copies it into a caller buffer;
//! - no panic crosses the boundary: each exported function runs inside `catch_unwind` and a
//!   panic becomes `GDSMC_PANIC`, silently (its message and place go to `gdsmc_last_error`,
//!   nothing to stderr), releasing what the call had allocated;
//! - pointers are checked for null and alignment; enumerations from C are taken as integers and
//!   checked; the only global mutable state is the thread-local error message;
//! - a simulation handle is not thread-safe: use one handle from one thread at a time.
//!   Distinct handles may run on distinct threads concurrently.
//!
//! Without the default `std` feature the crate is `#![no_std]` for microcontrollers: no heap
//! handles (`gdsmc_sim_create`), no scene text (`gdsmc_config_from_toml`), one last-error
//! message for a single-context program, and panic = abort through the C library's `abort()`
//! (`embedded/c/`).

#![cfg_attr(not(feature = "std"), no_std)]
#![allow(non_camel_case_types)]
// An error carries its message in a fixed-capacity string (no allocator in the no_std build);
// errors are the rare path, so their size does not matter.
#![allow(clippy::result_large_err)]

mod access;
mod codes;
mod config;
mod guard;
#[cfg(feature = "fault-injection")]
pub use guard::fault;
#[cfg(feature = "std")]
mod heap;
#[cfg(feature = "std")]
mod mean;
mod observables;
mod physics;
#[cfg(feature = "std")]
mod reference;
mod sim;
mod status;
#[cfg(feature = "std")]
mod toml;

pub use access::*;
pub use codes::*;
pub use config::*;
#[cfg(feature = "std")]
pub use heap::*;
#[cfg(feature = "std")]
pub use mean::*;
pub use observables::*;
#[cfg(feature = "std")]
pub use reference::*;
pub use sim::*;
pub use status::*;
#[cfg(feature = "std")]
pub use toml::*;

/// The no_std build (microcontrollers) has no unwinding: a panic, which gdsmc's own checks
/// should make impossible, ends the program through the C library's `abort()`.
#[cfg(not(feature = "std"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    unsafe extern "C" {
        fn abort() -> !;
    }
    // SAFETY: `abort` is the C library's, which never returns.
    unsafe { abort() }
}

/// The gdsmc version as a NUL-terminated string in static storage (never free it).
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_version() -> *const core::ffi::c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}
