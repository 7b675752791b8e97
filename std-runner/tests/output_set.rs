//! Outputs as a set: a `gdsmc run` killed (SIGKILL) at moments spread over its whole duration,
//! writing included, leaves at its output directory either the previous whole set or the new
//! whole set (every file as its manifest lists it), never a mix; the next run removes the
//! staging directories of killed runs; an unwritable output place is refused before any
//! simulation.

use gdsmc_runner::report::set::verify;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

fn scene() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml")
}

fn gdsmc(out: &Path, seed: u64, ensembles: u64) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gdsmc"));
    c.arg("run")
        .arg(scene())
        .args(["--n", "256", "--threads", "1"])
        .args([
            "--seed",
            &seed.to_string(),
            "--ensembles",
            &ensembles.to_string(),
        ])
        .arg("--out")
        .arg(out)
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    c
}

fn seed_of(dir: &Path) -> u64 {
    let run = verify(dir).unwrap_or_else(|e| panic!("{}: not a whole set: {e}", dir.display()));
    run["seed"].as_u64().expect("a seed in the manifest")
}

#[test]
fn a_killed_run_leaves_a_whole_set() {
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("output_set");
    let _ = std::fs::remove_dir_all(&root);
    let out = root.join("grw3");
    assert!(gdsmc(&out, 1, 40).status().unwrap().success());
    assert_eq!(seed_of(&out), 1);
    // How long a full run takes, to spread the kills over it.
    let t0 = Instant::now();
    assert!(gdsmc(&out, 2, 400).status().unwrap().success());
    let full = t0.elapsed();
    let mut prev = seed_of(&out);
    assert_eq!(prev, 2);
    let kills = 12;
    for k in 0..kills {
        let seed = 10 + k as u64;
        let mut child = gdsmc(&out, seed, 400).spawn().unwrap();
        // From the start to three full runs (the later ones finish first; the middle ones hit
        // the simulation, the writing and the swap).
        std::thread::sleep(full.mul_f64(3.0 * (k as f64 + 0.5) / kills as f64));
        let _ = child.kill();
        let _ = child.wait();
        let s = seed_of(&out);
        assert!(
            s == prev || s == seed,
            "kill {k}: seed {s}, expected {prev} or {seed}"
        );
        eprintln!(
            "kill {k}: {}",
            if s == seed { "new set" } else { "previous set" }
        );
        prev = s;
    }
    assert!(gdsmc(&out, 99, 10).status().unwrap().success());
    assert_eq!(seed_of(&out), 99);
    let stale: Vec<_> = std::fs::read_dir(&root)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".partial-"))
        .collect();
    assert!(stale.is_empty(), "staging directories left: {stale:?}");
}

#[test]
fn an_unwritable_output_place_is_refused_before_running() {
    // A million ensembles would take minutes if the run came before the refusal.
    let o = gdsmc(Path::new("/proc/gdsmc-cannot-write-here/x"), 1, 1_000_000)
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("cannot write"), "{err}");
}
