//! Fuzz target `rough_maps`: see `gdsmc_fuzz_checks::rough_maps` for the properties checked.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| gdsmc_fuzz_checks::rough_maps(data));
