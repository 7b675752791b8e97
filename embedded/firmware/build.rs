//! Puts the board's memory layout where cortex-m-rt's link.x finds it (as `memory.x`) and links
//! with link.x: `memory-m0.x` (the micro:bit, Cortex-M0) for thumbv6m, else `memory.x` (MPS2).

use std::path::PathBuf;

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR"));
    let target = std::env::var("TARGET").expect("TARGET");
    let layout = if target.starts_with("thumbv6m") {
        "memory-m0.x"
    } else {
        "memory.x"
    };
    std::fs::copy(layout, out.join("memory.x")).expect("memory layout copied");
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=memory-m0.x");
}
