//! # gdsmc-ffi: the C ABI of gdsmc
//!
//! Builds `libgdsmc.a` and `libgdsmc.so`; `include/gdsmc.h` is generated from this crate by
//! cbindgen (`ffi/cbindgen.toml`). Conventions, after rustls-ffi:
//!
//! - every fallible function returns a [`gdsmc_status`]; on failure a message for the calling
//!   thread is kept and [`gdsmc_last_error`] copies it into a caller buffer;
//! - no panic crosses the boundary: each exported function runs inside `catch_unwind` and a
//!   panic becomes `GDSMC_PANIC`;
//! - pointers are checked for null and alignment; enumerations from C are taken as integers and
//!   checked; the only global mutable state is the thread-local error message;
//! - a simulation handle is not thread-safe: use one handle from one thread at a time.
//!   Distinct handles may run on distinct threads concurrently.

#![allow(non_camel_case_types)]

mod access;
mod config;
mod guard;
mod observables;
mod physics;
mod sim;
mod status;

pub use access::*;
pub use config::*;
pub use observables::*;
pub use sim::*;
pub use status::*;

/// The gdsmc version as a NUL-terminated string in static storage (never free it).
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_version() -> *const core::ffi::c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}
