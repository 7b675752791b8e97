//! A sweep split over `--shard` tasks, by points or within them, assembled by the whole
//! sweep's command: the single process's bytes.

use super::sweep::{root, sweep};
use gdsmc_runner::job::Quiet;
use std::path::Path;

/// Runs the sweep over `vary` into `r/name` without `--shard`, which must take all 12
/// ensembles from the journals the shard tasks left, and compares its files with the
/// single-process sweep's in `r/whole`, byte for byte.
fn assemble(vary: &[&str], r: &Path, name: &str) {
    let assembled = sweep(vary, &[], &r.join(name), 1)
        .run(&Quiet::default())
        .unwrap();
    assert!(
        assembled
            .text
            .contains("12 ensembles taken from the points' journals"),
        "{}",
        assembled.text
    );
    for f in ["sweep.csv", "sweep.json", "sweep.md"] {
        assert_eq!(
            std::fs::read(r.join("whole").join(f)).unwrap(),
            std::fs::read(r.join(name).join(f)).unwrap(),
            "{f}"
        );
    }
}

/// A sweep run as two shards (each point journaled where the whole sweep looks for it) and
/// then assembled by the same command without `--shard` writes the single-process sweep's
/// sweep.csv and sweep.json byte for byte, taking every ensemble from the journals.
#[test]
fn a_sharded_sweep_assembled_is_the_single_process_sweep() {
    let r = root("sharded");
    let vary = ["collisions.restitution=0.5,0.7,0.9"];
    sweep(&vary, &[], &r.join("whole"), 1)
        .run(&Quiet::default())
        .unwrap();
    for k in 0..2 {
        let mut s = sweep(&vary, &[], &r.join("sharded"), 1);
        s.shard = Some(format!("{k}/2"));
        let done = s.run(&Quiet::default()).unwrap();
        assert!(done.complete, "{}", done.text);
        assert!(!r.join("sharded").exists(), "a shard writes no outputs");
    }
    let mut too_many = sweep(&vary, &[], &r.join("sharded"), 1);
    too_many.shard = Some("0/13".into());
    let e = too_many.run(&Quiet::default()).unwrap_err().to_string();
    assert!(
        e.contains("--shard") && e.contains("3 points") && e.contains("at most 12"),
        "{e}"
    );
    assemble(&vary, &r, "sharded");
}

/// More shards than points split each point's ensembles (5 tasks over 3 points: each point
/// in 2 shards, 6 units dealt round the tasks): with one task missing the assembly refuses,
/// naming the point and the missing shard, and writes nothing; with every task done it
/// writes the single-process sweep's files byte for byte and removes the shard journals.
#[test]
fn a_sweep_sharded_within_its_points_assembled_is_the_single_process_sweep() {
    let r = root("sharded-points");
    let vary = ["collisions.restitution=0.5,0.7,0.9"];
    sweep(&vary, &[], &r.join("whole"), 1)
        .run(&Quiet::default())
        .unwrap();
    let task = |k: u64| {
        let mut s = sweep(&vary, &[], &r.join("split"), 1);
        s.shard = Some(format!("{k}/5"));
        let done = s.run(&Quiet::default()).unwrap();
        assert!(done.complete, "{}", done.text);
        assert!(done.text.contains("in 2 shards"), "{}", done.text);
    };
    for k in [0, 1, 2, 4] {
        task(k);
    }
    let e = sweep(&vary, &[], &r.join("split"), 1)
        .run(&Quiet::default())
        .unwrap_err()
        .to_string();
    // Task 3 holds unit 3 (point 1, shard 1 of 2).
    assert!(e.contains("point 1") && e.contains("1/2"), "{e}");
    assert!(!r.join("split").exists(), "nothing written: {e}");
    task(3);
    assemble(&vary, &r, "split");
    let left: Vec<_> = std::fs::read_dir(&r)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".gdsmc-ensembles"))
        .collect();
    assert!(left.is_empty(), "journals left: {left:?}");
}
