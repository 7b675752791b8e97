//! A run is a pure function of (scene, seed): the same observables.csv bytes for any thread
//! count, and different bytes for a different seed.

use gdsmc::{output, references};
use gdsmc_validation::*;

fn csv_bytes(name: &str, seed: u64, threads: usize) -> Vec<u8> {
    let s = shipped(name, 64, 50, seed);
    let st = gdsmc::ensemble::run(&s, threads, &|_| {}).unwrap();
    output::observables_csv(&st, &references::for_scene(&s)).unwrap()
}

#[test]
fn observables_are_bit_identical_for_any_thread_count() {
    for name in ["grw-example3", "grw-example5"] {
        let one = csv_bytes(name, 7, 1);
        assert_eq!(one, csv_bytes(name, 7, 2), "{name}: 1 vs 2 threads");
        assert_eq!(one, csv_bytes(name, 7, 3), "{name}: 1 vs 3 threads");
        assert_ne!(one, csv_bytes(name, 8, 2), "{name}: the seed must matter");
    }
}
