//! Fuzz target `c_abi`: see `gdsmc_fuzz_checks::c_abi` for the properties checked.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| gdsmc_fuzz_checks::c_abi(data));
