//! A run is a pure function of (scene, seed): the same observables.csv bytes for any thread
//! count, and different bytes for a different seed.

use gdsmc_runner::scene::RestitutionLaw;

use gdsmc_validation::*;

fn csv_bytes(name: &str, seed: u64, threads: usize) -> Vec<u8> {
    let s = shipped(name, 64, 50, seed);
    let st = gdsmc_runner::run::run(&s, threads, &|_| {}).unwrap();
    gdsmc_runner::report::observables_csv(&st, &gdsmc_theory::curves::for_scene(&s)).unwrap()
}

#[test]
fn observables_are_bit_identical_for_any_thread_count() {
    for name in [
        "grw-example3",
        "grw-example5",
        "rough-white-noise",
        "mixture-maxwell",
    ] {
        let one = csv_bytes(name, 7, 1);
        assert_eq!(one, csv_bytes(name, 7, 2), "{name}: 1 vs 2 threads");
        assert_eq!(one, csv_bytes(name, 7, 3), "{name}: 1 vs 3 threads");
        assert_ne!(one, csv_bytes(name, 8, 2), "{name}: the seed must matter");
    }
}

#[test]
fn impact_speed_law_with_delta_zero_is_the_constant_law() {
    // BRS (9) with delta = 0: e = 1 - 2 beta0 everywhere; beta0 = 1/4 is alpha = 1/2 and the
    // runs must agree to the bit (same random draws, same arithmetic).
    let a = shipped("grw-example5", 64, 20, 5);
    let mut b = a.clone();
    assert_eq!(a.physics().restitution, RestitutionLaw::Constant(0.5));
    b.with_physics(|ph| {
        ph.restitution = RestitutionLaw::ImpactSpeed {
            beta0: 0.25,
            delta: 0.0,
        }
    })
    .expect("a valid physics");
    let sa = gdsmc_runner::run::run(&a, 2, &|_| {}).unwrap();
    let sb = gdsmc_runner::run::run(&b, 2, &|_| {}).unwrap();
    assert_eq!(
        gdsmc_runner::report::observables_csv(&sa, &[]).unwrap(),
        gdsmc_runner::report::observables_csv(&sb, &[]).unwrap()
    );
    // A strong viscoelastic law changes the run and clamps fast impacts to e = 0.
    let mut c = a.clone();
    c.with_physics(|ph| {
        ph.restitution = RestitutionLaw::ImpactSpeed {
            beta0: 0.45,
            delta: 0.2,
        }
    })
    .expect("a valid physics");
    let sc = gdsmc_runner::run::run(&c, 2, &|_| {}).unwrap();
    assert!(sc.counts.clamped > 0, "{:?}", sc.counts);
    assert_ne!(
        gdsmc_runner::report::observables_csv(&sa, &[]).unwrap(),
        gdsmc_runner::report::observables_csv(&sc, &[]).unwrap()
    );
}

#[test]
fn an_interrupted_run_keeps_a_prefix_equal_to_a_shorter_run() {
    use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
    let s = shipped("grw-example3", 64, 400, 9);
    let stop = AtomicBool::new(false);
    let done = AtomicU64::new(0);
    let st = gdsmc_runner::run::run_interruptible(
        &s,
        2,
        &|k| {
            if done.fetch_add(k, Ordering::SeqCst) + k >= 37 {
                stop.store(true, Ordering::SeqCst);
            }
        },
        &stop,
    )
    .unwrap();
    // Ensembles finish out of order; the kept prefix may be shorter than the count done.
    assert!(
        st.ensembles >= 1 && st.ensembles < 400,
        "kept {}",
        st.ensembles
    );
    let mut shorter = s.clone();
    shorter.set_ensembles(st.ensembles).unwrap();
    let full = gdsmc_runner::run::run(&shorter, 1, &|_| {}).unwrap();
    let refs = gdsmc_theory::curves::for_scene(&s);
    assert_eq!(
        gdsmc_runner::report::observables_csv(&st, &refs).unwrap(),
        gdsmc_runner::report::observables_csv(&full, &refs).unwrap()
    );
}
