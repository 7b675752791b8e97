//! Fuzz target `samplers`: see `gdsmc_fuzz_checks::samplers` for the properties checked.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| gdsmc_fuzz_checks::samplers(data));
