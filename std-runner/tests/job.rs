//! The library's run orchestration (`gdsmc_runner::job`), which the command and the Python
//! package share: a job run from the library writes what `gdsmc run` writes, byte for byte
//! (timings aside), and a job stopped before it starts keeps nothing and says so.

use gdsmc_runner::job::{Job, Quiet, Watch};
use gdsmc_runner::scene::{Override, Sourced};
use std::path::PathBuf;
use std::process::Command;

fn root(name: &str) -> PathBuf {
    let r = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("job")
        .join(name);
    let _ = std::fs::remove_dir_all(&r);
    std::fs::create_dir_all(&r).unwrap();
    r
}

fn scene() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml")
}

fn job(out: PathBuf) -> Job {
    Job {
        source: Sourced::read(&scene(), Override::run_flags(Some(64), Some(3), Some(5)))
            .expect("a shipped scene"),
        threads: 1,
        allow_long: false,
        shard: None,
        out: Some(out),
        fresh: false,
        format: "svg".parse().unwrap(),
        initial_state: None,
        save_state: None,
    }
}

/// A job's observables.csv equals the command's for the same scene, flags and seed, and its
/// outcome is complete and names the files it wrote.
#[test]
fn a_library_job_writes_what_the_command_writes() {
    let r = root("same-as-command");
    let done = job(r.join("lib"))
        .run(&Quiet::default())
        .expect("the job runs");
    assert!(done.complete);
    assert!(done.text.contains("observables.csv"), "{}", done.text);
    let o = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("run")
        .arg(scene())
        .args([
            "--n",
            "64",
            "--ensembles",
            "3",
            "--seed",
            "5",
            "--threads",
            "1",
        ])
        .arg("--out")
        .arg(r.join("cmd"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let read = |d: &str| std::fs::read(r.join(d).join("observables.csv")).unwrap();
    assert_eq!(read("lib"), read("cmd"));
}

/// A watcher whose stop flag is set before the job starts: no ensemble runs, the job says it
/// was interrupted, and no output set is written.
#[test]
fn a_job_stopped_before_it_starts_keeps_nothing() {
    let r = root("stopped");
    let quiet = Quiet::default();
    quiet
        .stop()
        .store(true, std::sync::atomic::Ordering::SeqCst);
    let err = job(r.join("o")).run(&quiet).expect_err("nothing ran");
    assert!(matches!(err, gdsmc_runner::Error::Interrupted), "{err}");
    assert!(!r.join("o").join("observables.csv").exists());
}
