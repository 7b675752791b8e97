//! C ABI for gdsmc-core.
//!
//! This crate is a shell until the C ABI issue: it builds the static and shared libraries that
//! `include/gdsmc.h` will describe, and exports the library version only.

/// The gdsmc version as a NUL-terminated C string (static storage, never freed).
#[unsafe(no_mangle)]
pub extern "C" fn gdsmc_version() -> *const core::ffi::c_char {
    // SAFETY-free: a pointer into a static, NUL-terminated byte string.
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}
