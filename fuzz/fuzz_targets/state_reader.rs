//! Fuzz target `state_reader`: see `gdsmc_fuzz_checks::state_reader` for the properties checked.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| gdsmc_fuzz_checks::state_reader(data));
