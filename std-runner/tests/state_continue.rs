//! `--save-state` runs stopped and continued (issue 77): a job killed at its time limit
//! continues from its journal and leaves no litter. Against 03e7324 a `--save-state` run
//! started anew every time (its journal was not continued), each kill left a state-sized
//! `.FILE.partial-PID-0` that no later run removed, and `--save-state` at the run's own journal
//! name exited 0 without a state file.

use super::command::{gdsmc, refused, root, s, scene};
use super::faults::{Held, signalled_after_an_ensemble};
use std::path::Path;
use std::process::{Command, Output, Stdio};

/// `gdsmc run grw-example3 --n 8192 --ensembles 100 --threads 1 --out DIR --save-state FILE`:
/// about a second, long enough to be stopped after its first ensembles.
fn args<'a>(dir: &'a Path, state: &'a Path) -> Vec<String> {
    let scene = scene("grw-example3");
    [
        "run",
        s(&scene),
        "--n",
        "8192",
        "--ensembles",
        "100",
        "--threads",
        "1",
        "--out",
        s(dir),
        "--save-state",
        s(state),
    ]
    .iter()
    .map(|a| a.to_string())
    .collect()
}

/// The run of `args` started, stopped by `signal` once an ensemble is journaled, and waited
/// for.
fn stopped(args: &[String], journal: &Path, signal: &str) -> Output {
    let child = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    signalled_after_an_ensemble(Held::from(child), journal, signal)
}

/// The names in `dir` that gdsmc leaves only while a run is unfinished.
fn litter(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| {
            n.contains("partial") || n.ends_with(".gdsmc-ensembles") || n.ends_with("claim")
        })
        .collect();
    names.sort();
    names
}

#[test]
fn a_killed_save_state_run_continues_to_the_same_bits_and_leaves_nothing() {
    let r = root("save-state-continued");
    let (one, one_state) = (r.join("one"), r.join("one.state"));
    let o = gdsmc(
        &args(&one, &one_state)
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        String::from_utf8_lossy(&o.stdout).contains(&format!(
            "wrote the state of 100 ensembles at t = 8 into {}",
            one_state.display()
        )),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );

    // Killed twice (SIGKILL: no chance to clean up), then run to its end.
    let (two, two_state) = (r.join("two"), r.join("two.state"));
    let a = args(&two, &two_state);
    let journal = r.join(".two.run.gdsmc-ensembles");
    for _ in 0..2 {
        let _ = stopped(&a, &journal, "KILL");
        // One partial state at a fixed name, not one per process (beside the output set's
        // staging directory, which the next run removes).
        let states: Vec<String> = litter(&r)
            .into_iter()
            .filter(|n| n.starts_with(".two.state"))
            .collect();
        assert_eq!(states, [".two.state.gdsmc-state-partial"]);
    }
    let o = gdsmc(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("ensembles were already done"),
        "not continued: {err}"
    );
    assert_eq!(
        std::fs::read(&two_state).unwrap(),
        std::fs::read(&one_state).unwrap()
    );
    assert_eq!(
        std::fs::read(two.join("observables.csv")).unwrap(),
        std::fs::read(one.join("observables.csv")).unwrap()
    );
    assert!(litter(&r).is_empty(), "{:?}", litter(&r));

    // Stopped by SIGTERM (a time limit): the finished ensembles' state is written as the
    // partial set is, and the same command continues to the same bits.
    let (three, three_state) = (r.join("three"), r.join("three.state"));
    let a = args(&three, &three_state);
    let o = stopped(&a, &r.join(".three.run.gdsmc-ensembles"), "TERM");
    assert_eq!(
        o.status.code(),
        Some(143),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let partial = gdsmc_runner::run::state::StateReader::open(&three_state).unwrap();
    let m = partial.header.ensembles;
    assert!(
        (1..24).contains(&m),
        "{m} ensembles in the interrupted state"
    );
    let full = gdsmc_runner::run::state::StateReader::open(&one_state).unwrap();
    for k in 0..m {
        assert_eq!(partial.record(k).unwrap(), full.record(k).unwrap());
    }
    let o = gdsmc(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(
        std::fs::read(&three_state).unwrap(),
        std::fs::read(&one_state).unwrap()
    );
    assert!(litter(&r).is_empty(), "{:?}", litter(&r));
}

#[test]
fn the_state_may_not_be_one_of_the_runs_own_files() {
    let r = root("save-state-place");
    let dir = r.join("res");
    std::fs::create_dir_all(&dir).unwrap();
    for (state, words) in [
        (r.join(".res.run.gdsmc-ensembles"), "the run's own journal"),
        (r.join(".res.gdsmc-claim"), "the run's claim"),
        (dir.join("s.state"), "inside the run's output directory"),
    ] {
        let o = gdsmc(
            &args(&dir, &state)
                .iter()
                .map(String::as_str)
                .collect::<Vec<_>>(),
        );
        refused(&o, &["--save-state", words]);
    }
}
