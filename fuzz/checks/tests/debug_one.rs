//! One input through one target's checks, for a crash or timeout found by fuzzing:
//! `GDSMC_FUZZ_DEBUG=1 GDSMC_FUZZ_TARGET=c_abi GDSMC_FUZZ_INPUT=artifacts/c_abi/timeout-...
//! cargo test --release -p gdsmc-fuzz-checks --test debug_one -- --ignored --nocapture`.

#[test]
#[ignore]
fn one() {
    let input = std::env::var("GDSMC_FUZZ_INPUT").expect("GDSMC_FUZZ_INPUT: the input file");
    let data = std::fs::read(input).expect("readable input");
    match std::env::var("GDSMC_FUZZ_TARGET").as_deref() {
        Ok("collision_maps") => gdsmc_fuzz_checks::collision_maps(&data),
        Ok("rough_maps") => gdsmc_fuzz_checks::rough_maps(&data),
        Ok("samplers") => gdsmc_fuzz_checks::samplers(&data),
        Ok("scene_reader") => gdsmc_fuzz_checks::scene_reader(&data),
        Ok("scene_structured") => gdsmc_fuzz_checks::scene_structured(&data),
        Ok("state_reader") => gdsmc_fuzz_checks::state_reader(&data),
        _ => gdsmc_fuzz_checks::c_abi(&data),
    }
}
