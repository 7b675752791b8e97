//! A run advanced a few ensembles at a time (`gdsmc_runner::run::stepped`, the browser's way)
//! gives the statistics of the run the command makes, bit for bit, at every prefix.

use gdsmc_runner::report::observables_csv;
use gdsmc_runner::run::stepped::Stepped;
use gdsmc_runner::scene::{Override, Sourced};
use gdsmc_theory::curves::for_scene;
use std::path::PathBuf;

fn scene(name: &str, ensembles: i64) -> Sourced {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../scenes/{name}.toml"));
    Sourced::read(
        &path,
        Override::run_flags(Some(64), Some(ensembles), Some(11)),
    )
    .expect("a shipped scene")
}

/// Uneven steps over two scenes of different loops (the heated Maxwell gas, a mixture of hard
/// spheres): at the end the observables equal the threaded run's byte for byte, and each prefix
/// equals a run of that many ensembles.
#[test]
fn steps_give_the_threaded_run_bit_for_bit() {
    for name in ["grw-example3", "mixture-hcs-hard-spheres"] {
        let full = scene(name, 9).scene;
        let refs = for_scene(&full);
        let csv = |s: &gdsmc_runner::run::RunStats| observables_csv(s, &refs).unwrap();
        let mut stepped = Stepped::new(full.clone()).unwrap();
        assert_eq!(stepped.advance(4).unwrap(), 4);
        let four = gdsmc_runner::run::run(&scene(name, 4).scene, 2, &|_| {}).unwrap();
        assert_eq!(
            csv(&stepped.stats()),
            csv(&four),
            "{name}: the first 4 ensembles"
        );
        assert_eq!(stepped.advance(1).unwrap(), 5);
        assert_eq!(
            stepped.advance(100).unwrap(),
            9,
            "{name}: stops at the scene's ensembles"
        );
        assert_eq!(stepped.advance(1).unwrap(), 9);
        let threaded = gdsmc_runner::run::run(&full, 3, &|_| {}).unwrap();
        let one = gdsmc_runner::run::run(&full, 1, &|_| {}).unwrap();
        assert_eq!(
            csv(&stepped.stats()),
            csv(&threaded),
            "{name}: stepped against 3 threads"
        );
        assert_eq!(csv(&one), csv(&threaded), "{name}: 1 thread against 3");
    }
}

/// Ensembles run one by one elsewhere, in any order (the browser's helper workers), carried as
/// journal words and folded in order by another run: the threaded run's bits. A row of
/// another length is refused.
#[test]
fn ensembles_run_apart_and_folded_in_order_give_the_run() {
    use gdsmc_runner::run::journal::{ensemble_from_words, ensemble_words};
    let full = scene("grw-example3", 7).scene;
    let refs = for_scene(&full);
    let mut helpers = [
        Stepped::new(full.clone()).unwrap(),
        Stepped::new(full.clone()).unwrap(),
    ];
    let mut words = vec![Vec::new(); 7];
    for (i, e) in [5u64, 2, 0, 6, 1, 3, 4].into_iter().enumerate() {
        let (row, counts) = helpers[i % 2].run_one(e).unwrap();
        words[e as usize] = ensemble_words(&row, &counts);
    }
    let mut folder = Stepped::new(full.clone()).unwrap();
    for (e, w) in words.iter().enumerate() {
        let (row, counts) = ensemble_from_words(w).unwrap();
        assert_eq!(folder.push(&row, &counts).unwrap(), e as u64 + 1);
    }
    let threaded = gdsmc_runner::run::run(&full, 2, &|_| {}).unwrap();
    assert_eq!(
        observables_csv(&folder.stats(), &refs).unwrap(),
        observables_csv(&threaded, &refs).unwrap()
    );
    let (row, counts) = ensemble_from_words(&words[0]).unwrap();
    assert!(folder.push(&row[1..], &counts).is_err());
    assert!(ensemble_from_words(&[1, 2]).is_none());
}
