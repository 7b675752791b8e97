//! Driving the `gdsmc` command from a test as a user would: a scratch directory per test, the
//! shipped scenes, small runs, and the checks of an exit (refused with its words, or ok) and
//! of what a run left on the disk.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

pub(crate) fn root(name: &str) -> PathBuf {
    let r = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("data_safety")
        .join(name);
    let _ = std::fs::remove_dir_all(&r);
    std::fs::create_dir_all(&r).unwrap();
    r
}

pub(crate) fn scene(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../scenes/{name}.toml"))
}

/// `gdsmc run SCENE --n 64 --ensembles 2 --threads 1 ARGS...`, output captured.
pub(crate) fn small_run(name: &str, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("run")
        .arg(scene(name))
        .args(["--n", "64", "--ensembles", "2", "--threads", "1"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .unwrap()
}

pub(crate) fn gdsmc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .unwrap()
}

pub(crate) fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The run was refused: exit 1 (an error, not a panic's 101 or a signal), the message holding
/// every one of `words`.
pub(crate) fn refused(o: &Output, words: &[&str]) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "not refused cleanly: {err}");
    for w in words {
        assert!(err.contains(w), "`{w}` not in the message: {err}");
    }
}

pub(crate) fn ok(o: &Output) {
    assert!(
        o.status.success(),
        "failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Every file under `dir` with its bytes (a directory as its name with a slash), sorted.
pub(crate) fn tree(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            out.push((format!("{name}/"), Vec::new()));
            out.extend(
                tree(&p)
                    .into_iter()
                    .map(|(n, b)| (format!("{name}/{n}"), b)),
            );
        } else {
            out.push((name, std::fs::read(&p).unwrap()));
        }
    }
    out.sort();
    out
}

/// Staging directories and journals left in `dir`.
pub(crate) fn leftovers(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| {
            n.contains(".partial-")
                || n.ends_with(".gdsmc-ensembles")
                || n.ends_with(".gdsmc-claim")
        })
        .collect()
}
