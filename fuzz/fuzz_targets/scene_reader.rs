//! Fuzz target `scene_reader`: see `gdsmc_fuzz_checks::scene_reader` for the properties checked.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| gdsmc_fuzz_checks::scene_reader(data));
