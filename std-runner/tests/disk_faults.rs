//! Faults a test can make only in a private mount namespace or under `strace` (issue 52): a
//! full disk, a read-only or vanished output place, and the flushes around the output set's
//! final rename. Without `unshare -m` (root) or `strace` each test says so and passes, unless
//! `GDSMC_REQUIRE_FAULT_TESTS` is set (CI sets it where namespaces work).

use super::command::{ok, root, s, scene, small_run};
use super::faults::{holds, long_run, scene_str, small_sweep, wait_for};
use std::path::Path;
use std::process::{Command, Output, Stdio};

/// Whether the fault tests can run here: a mount namespace (`unshare -m`) and, for the
/// flushes, `strace`. When not, the test says so and passes, unless
/// `GDSMC_REQUIRE_FAULT_TESTS` is set.
fn can(tool: &[&str], what: &str) -> bool {
    let here = Command::new(tool[0])
        .args(&tool[1..])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !here {
        assert!(
            std::env::var_os("GDSMC_REQUIRE_FAULT_TESTS").is_none(),
            "GDSMC_REQUIRE_FAULT_TESTS is set but {what} is not available"
        );
        eprintln!("skipped: {what} is not available here (run as root, or install it)");
    }
    here
}

/// Runs the shell `script` in a private mount namespace; `$G` is gdsmc, `$SCENE` GRW Example
/// 3, `$R` the test's directory. Returns its output.
fn in_namespace(r: &Path, script: &str) -> Output {
    Command::new("unshare")
        .args(["-m", "sh", "-c", script])
        .env("G", env!("CARGO_BIN_EXE_gdsmc"))
        .env("SCENE", scene_str())
        .env("R", r)
        .output()
        .unwrap()
}

/// The file `name` under `r`, as text ("" when absent).
fn text(r: &Path, name: &str) -> String {
    std::fs::read_to_string(r.join(name)).unwrap_or_default()
}

/// The disk fills during a run's and a sweep's output (a 128 KiB file system: the journal
/// fits, the charts do not) and during a journal's records (8 KiB): each a clear error naming
/// the path and "No space left", nothing at `--out`, no staging directory left; after the
/// file system grows, the same command continues from the journal and writes exactly the
/// set a run on a roomy disk writes.
#[test]
fn a_full_disk_loses_nothing_finished() {
    if !can(&["unshare", "-m", "true"], "a mount namespace (unshare -m)") {
        return;
    }
    let r = root("full-disk");
    ok(&small_run("grw-example3", &["--out", s(&r.join("roomy"))]));
    ok(&small_sweep(
        "collisions.restitution=0.5,0.6",
        &["--out", s(&r.join("roomy-sweep"))],
    ));
    for size in ["8k", "128k"] {
        let o = in_namespace(
            &r,
            &format!(
                r#"set -u
D="$R/disk-{size}"; mkdir -p "$D"; mount -t tmpfs -o size={size} tmpfs "$D" || exit 99
run() {{ "$G" run "$SCENE" --n 64 --ensembles 2 --threads 1 --out "$D/res" "$@"; }}
run > "$R/o1-{size}" 2> "$R/e1-{size}"; echo $? > "$R/rc1-{size}"
"$G" sweep "$SCENE" --vary collisions.restitution=0.5,0.6 --n 64 --ensembles 2 --threads 1 \
    --out "$D/sw" > /dev/null 2> "$R/e2-{size}"; echo $? > "$R/rc2-{size}"
ls -a "$D" > "$R/ls-{size}"
mount -o remount,size=16m "$D"
run > "$R/o3-{size}" 2> "$R/e3-{size}"; echo $? > "$R/rc3-{size}"
"$G" sweep "$SCENE" --vary collisions.restitution=0.5,0.6 --n 64 --ensembles 2 --threads 1 \
    --out "$D/sw" > /dev/null 2> "$R/e4-{size}"; echo $? > "$R/rc4-{size}"
cp "$D/res/observables.csv" "$R/observables-{size}.csv"
cp "$D/sw/sweep.csv" "$R/sweep-{size}.csv"
ls -a "$D" > "$R/ls3-{size}"
"#
            ),
        );
        assert_ne!(o.status.code(), Some(99), "tmpfs could not be mounted");
        for (rc, err) in [("rc1", "e1"), ("rc2", "e2")] {
            let e = text(&r, &format!("{err}-{size}"));
            assert_eq!(text(&r, &format!("{rc}-{size}")).trim(), "1", "{size}: {e}");
            assert!(e.contains("No space left on device"), "{size}: {e}");
            assert!(e.contains(&format!("disk-{size}")), "{size}: the path: {e}");
        }
        let listing = text(&r, &format!("ls-{size}"));
        assert!(
            !listing.contains("partial") && !listing.contains("res\n") && !listing.contains("sw\n"),
            "{size}: left {listing}"
        );
        let e3 = text(&r, &format!("e3-{size}"));
        assert_eq!(text(&r, &format!("rc3-{size}")).trim(), "0", "{size}: {e3}");
        let e4 = text(&r, &format!("e4-{size}"));
        assert_eq!(text(&r, &format!("rc4-{size}")).trim(), "0", "{size}: {e4}");
        if size == "128k" {
            assert!(
                e3.contains("continued"),
                "the journal was not continued: {e3}"
            );
        }
        assert_eq!(
            std::fs::read(r.join(format!("observables-{size}.csv"))).unwrap(),
            std::fs::read(r.join("roomy/observables.csv")).unwrap()
        );
        assert_eq!(
            std::fs::read(r.join(format!("sweep-{size}.csv"))).unwrap(),
            std::fs::read(r.join("roomy-sweep/sweep.csv")).unwrap()
        );
        let after = text(&r, &format!("ls3-{size}"));
        assert!(
            !after.contains("partial") && !after.contains("gdsmc-"),
            "{size}: left {after}"
        );
    }
}

/// An output place that is read-only (its parent a read-only mount; or the previous set a
/// read-only mount) gives a clear error naming it and leaves everything as it was; an output
/// directory removed while the run goes (then Ctrl-C) gives a clear error, not a panic.
#[test]
fn a_read_only_or_vanished_place_is_a_clear_error() {
    if !can(&["unshare", "-m", "true"], "a mount namespace (unshare -m)") {
        return;
    }
    let r = root("read-only");
    ok(&small_run(
        "grw-example3",
        &["--out", s(&r.join("place/old"))],
    ));
    let before = super::command::tree(&r.join("place"));
    let o = in_namespace(
        &r,
        r#"set -u
mount --bind "$R/place" "$R/place" && mount -o remount,bind,ro "$R/place" || exit 99
run() { "$G" run "$SCENE" --n 64 --ensembles 2 --threads 1 --seed 2 "$@"; }
run --out "$R/place/new/res" > /dev/null 2> "$R/e1"; echo $? > "$R/rc1"
run --out "$R/place/old" > /dev/null 2> "$R/e2"; echo $? > "$R/rc2"
"#,
    );
    assert_ne!(o.status.code(), Some(99), "the bind mount failed");
    for (rc, e) in [("rc1", "e1"), ("rc2", "e2")] {
        let err = text(&r, e);
        assert_eq!(text(&r, rc).trim(), "1", "{err}");
        assert!(err.contains("Read-only file system"), "{err}");
        assert!(
            err.contains(&format!("{}", r.join("place").display())),
            "{err}"
        );
    }
    assert_eq!(super::command::tree(&r.join("place")), before);

    let gone = r.join("gone");
    let child = long_run(&["--out", s(&gone.join("res"))]);
    wait_for("the journal", || holds(&gone, ".res.run.gdsmc-ensembles"));
    std::fs::remove_dir_all(&gone).unwrap();
    assert!(
        Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .unwrap()
            .success()
    );
    let o = child.output();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("the directory is gone"), "{err}");
    assert!(
        err.contains("cannot be continued"),
        "no false promise: {err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    assert!(
        !gone.exists(),
        "something was made again at the removed place"
    );
}

/// A power cut after the final rename keeps the set whole: every file of the set and the
/// staging directory are flushed (fsync) before the directories are exchanged, and the
/// parent directory after (traced with `strace -f -y`; before: no file of the set but the
/// manifest and no directory was flushed).
#[test]
fn the_set_is_on_the_disk_before_and_after_the_final_rename() {
    if !can(&["strace", "-V"], "strace") {
        return;
    }
    let r = root("flushes");
    let out = r.join("res");
    ok(&small_run("grw-example3", &["--out", s(&out)]));
    let log = r.join("trace");
    let o = Command::new("strace")
        .args([
            "-f",
            "-y",
            "-qq",
            "-e",
            "trace=fsync,fdatasync,rename,renameat2",
        ])
        .arg("-o")
        .arg(&log)
        .arg(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("run")
        .arg(scene("grw-example3"))
        .args([
            "--n",
            "64",
            "--ensembles",
            "2",
            "--threads",
            "1",
            "--seed",
            "2",
        ])
        .args(["--out", s(&out)])
        .output()
        .unwrap();
    ok(&o);
    let trace = std::fs::read_to_string(&log).unwrap();
    let lines: Vec<&str> = trace.lines().collect();
    let exchange = lines
        .iter()
        .position(|l| l.contains("RENAME_EXCHANGE"))
        .unwrap_or_else(|| panic!("no exchange in the trace:\n{trace}"));
    let flushed = |path: &str, range: &[&str]| {
        range
            .iter()
            .any(|l| l.contains("fsync(") && l.contains(&format!("<{path}>")))
    };
    for f in std::fs::read_dir(&out).unwrap().flatten() {
        let name = f.file_name().to_string_lossy().into_owned();
        let before = &lines[..exchange];
        // The file, or the temporary it was renamed from (`.NAME.partial-...`).
        assert!(
            before.iter().any(|l| l.contains("fsync(")
                && l.contains(".res.partial-")
                && (l.contains(&format!("/{name}>")) || l.contains(&format!("/.{name}.partial-")))),
            "{name} not flushed before the exchange:\n{trace}"
        );
    }
    // The staging directory itself: an fsync of a path whose last part is `.res.partial-*`.
    assert!(
        lines[..exchange].iter().any(|l| l.contains("fsync(")
            && l.split('<')
                .nth(1)
                .and_then(|p| p.split('>').next())
                .and_then(|p| p.rsplit('/').next())
                .is_some_and(|last| last.starts_with(".res.partial-"))),
        "the staging directory was not flushed before the exchange:\n{trace}"
    );
    assert!(
        flushed(s(&r), &lines[exchange..]),
        "the parent directory was not flushed after the exchange:\n{trace}"
    );
}
