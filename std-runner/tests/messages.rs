//! Messages about bad input that a user can read (issue 77's smaller items), driven through the
//! `gdsmc` command. Against 03e7324: `1e300` printed as 301 digits, a 1 MB key line came back
//! as 3 MB of standard error, the 1 MiB refusal held a run of spaces, a FIFO as the scene file
//! blocked for ever, `observe.first = 5e-324` passed and the run failed with t = NaN, and a
//! missing directory for `--save-state` was said to have been removed during the run.

use super::command::{gdsmc, refused, root, s, scene, small_run};
use std::process::{Command, Stdio};
use std::time::Duration;

#[test]
fn numbers_are_short_and_long_lines_cut() {
    let o = small_run("grw-example3", &["--set", "collisions.restitution=1e300"]);
    refused(
        &o,
        &["`collisions.restitution` must lie in (0, 1], got 1e300"],
    );
    assert!(
        o.stderr.len() < 300,
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );

    let r = root("long-lines");
    let big = r.join("big.toml");
    let text = std::fs::read_to_string(scene("grw-example3")).unwrap();
    std::fs::write(&big, format!("{text}\n{} = 1\n", "a".repeat(1_000_000))).unwrap();
    let o = gdsmc(&["run", s(&big)]);
    refused(&o, &["big.toml", "more characters)"]);
    assert!(o.stderr.len() < 2000, "{} bytes of stderr", o.stderr.len());

    let huge = r.join("huge.toml");
    std::fs::write(&huge, format!("# {}\n", "x".repeat(1 << 20))).unwrap();
    let o = gdsmc(&["run", s(&huge)]);
    refused(&o, &["above the 1024 KiB a scene may have"]);
    assert!(
        !String::from_utf8_lossy(&o.stderr).contains("  "),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn a_fifo_as_the_scene_is_refused_at_once() {
    let r = root("fifo");
    let fifo = r.join("scene.toml");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let mut child = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .args(["run", s(&fifo)])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // A watchdog, not a speed test: the refusal takes milliseconds; 60 s only tells a hang.
    let t0 = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if t0.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("gdsmc blocked on a FIFO");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let o = child.wait_with_output().unwrap();
    refused(&o, &["scene.toml", "not a regular file"]);
}

#[test]
fn observation_times_that_are_no_numbers_are_refused_before_the_run() {
    for sets in [
        vec!["observe.first=5e-324"],
        vec!["observe.first=1e-300", "observe.t_end=1e300"],
    ] {
        let mut args = vec![];
        for x in &sets {
            args.extend(["--set", x]);
        }
        let o = small_run("hcs-hard-spheres", &args);
        refused(
            &o,
            &[
                "`observe.first`",
                "not a number later than the time before it",
            ],
        );
    }
}

#[test]
fn a_missing_directory_for_the_state_is_named_as_missing() {
    let r = root("nodir");
    let state = r.join("nodir").join("s.state");
    let o = small_run(
        "grw-example3",
        &["--out", s(&r.join("res")), "--save-state", s(&state)],
    );
    refused(
        &o,
        &["nodir", "does not exist", "create the directory first"],
    );
    assert!(!String::from_utf8_lossy(&o.stderr).contains("removed while"));
}
