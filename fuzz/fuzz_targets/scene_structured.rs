//! Fuzz target `scene_structured`: see `gdsmc_fuzz_checks::scene_structured` for the properties checked.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| gdsmc_fuzz_checks::scene_structured(data));
