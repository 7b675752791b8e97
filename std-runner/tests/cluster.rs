//! Runs split and interrupted: shards merged, and runs killed and continued, give the single
//! run's outputs byte for byte; shard sets that are not one whole run are refused with a
//! message naming the file. (The MPI run is compared with the same files in CI, `.ci/mpi.sh`.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn root(name: &str) -> PathBuf {
    let r = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cluster")
        .join(name);
    let _ = std::fs::remove_dir_all(&r);
    std::fs::create_dir_all(&r).unwrap();
    r
}

fn scene(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../scenes/{name}.toml"))
}

fn gdsmc(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gdsmc"));
    c.args(args).stdout(Stdio::piped()).stderr(Stdio::piped());
    c
}

fn ok(c: &mut Command) -> Output {
    let o = c.output().unwrap();
    assert!(
        o.status.success(),
        "{:?} failed: {}",
        c,
        String::from_utf8_lossy(&o.stderr)
    );
    o
}

/// The statistics of summary.json: everything but the timing, which differs run to run.
fn summary_stats(dir: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    strip_timing(&mut v);
    v
}

fn strip_timing(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(m) => {
            m.retain(|k, _| {
                !matches!(
                    k.as_str(),
                    "wall_seconds" | "cpu_seconds" | "threads" | "collisions_per_second"
                )
            });
            m.values_mut().for_each(strip_timing);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(strip_timing),
        _ => {}
    }
}

/// The data files of an output directory (CSV), by name.
fn data(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "csv"))
        .map(|e| {
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read(e.path()).unwrap(),
            )
        })
        .collect();
    v.sort();
    assert!(!v.is_empty(), "no CSV in {}", dir.display());
    v
}

fn assert_same_outputs(a: &Path, b: &Path) {
    let (da, db) = (data(a), data(b));
    assert_eq!(
        da.iter().map(|x| &x.0).collect::<Vec<_>>(),
        db.iter().map(|x| &x.0).collect::<Vec<_>>()
    );
    for ((name, x), (_, y)) in da.iter().zip(&db) {
        assert!(
            x == y,
            "{name} differs between {} and {}",
            a.display(),
            b.display()
        );
    }
    assert_eq!(summary_stats(a), summary_stats(b));
}

/// `gdsmc merge SHARDS --out MERGED` gives the outputs in `one`.
fn merges_to(shards: &Path, one: &Path, merged: &Path) {
    ok(&mut gdsmc(&[
        "merge",
        shards.to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]));
    assert_same_outputs(one, merged);
}

/// Shard and merge arguments of a small run of `name`.
fn small(name: &str) -> Vec<String> {
    let mut v = vec![
        "run".to_string(),
        scene(name).display().to_string(),
        "--n".into(),
        "300".into(),
        "--ensembles".into(),
        "23".into(),
    ];
    if name == "ms-constant-force" {
        v.extend(["--set".into(), "observe.collisional_pairs=500".into()]);
    }
    v
}

fn args(v: &[String], more: &[&str]) -> Vec<String> {
    v.iter()
        .cloned()
        .chain(more.iter().map(|s| s.to_string()))
        .collect()
}

fn run(v: &[String]) -> Output {
    ok(&mut gdsmc(
        &v.iter().map(String::as_str).collect::<Vec<_>>(),
    ))
}

/// GRW Example 3 (observables), MS's constant-force thermostat (steady averages and the
/// reduced histogram) and GRW Example 3 on weighted particles: one process, and 4 shards (of uneven sizes: 23 = 5 + 6 + 6 + 6)
/// merged, give the same CSV files byte for byte and the same summary statistics.
#[test]
fn four_shards_merged_equal_one_run() {
    for name in ["grw-example3", "ms-constant-force", "grw-example3-weighted"] {
        let r = root(&format!("shards-{name}"));
        let base = small(name);
        let one = r.join("one");
        run(&args(
            &base,
            &["--out", one.to_str().unwrap(), "--threads", "2"],
        ));
        let shards = r.join("shards");
        // Given in another order, with different thread counts.
        for (k, threads) in [(2, "1"), (0, "2"), (3, "1"), (1, "2")] {
            run(&args(
                &base,
                &[
                    "--shard",
                    &format!("{k}/4"),
                    "--out",
                    shards.to_str().unwrap(),
                    "--threads",
                    threads,
                ],
            ));
        }
        merges_to(&shards, &one, &r.join("merged"));
    }
}

/// A small deterministic generator for the kill moments (fixed seed).
fn lcg(state: &mut u64) -> f64 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    (*state >> 11) as f64 / (1u64 << 53) as f64
}

/// A run killed (SIGKILL: no chance to clean up) at random moments, each time run again with
/// the same command, ends with the outputs of an uninterrupted run, byte for byte; the same
/// for a shard, which then merges with the others as if never killed.
#[test]
fn killed_runs_continue_to_the_same_bits() {
    let r = root("resume");
    let mut base = small("grw-example3");
    base[3] = "20000".into(); // n: ensembles long enough to be killed in the middle
    base[5] = "48".into();
    let one = r.join("one");
    let t0 = Instant::now();
    run(&args(
        &base,
        &["--out", one.to_str().unwrap(), "--threads", "2"],
    ));
    let full = t0.elapsed();
    let mut seed = 0x5eed_u64;
    let kill_during = |extra: &[&str], state: &mut u64| {
        // A moment in the run's first 90%, uniformly at random (fixed seed).
        let at = full.mul_f64(0.9 * lcg(state));
        let v = args(&base, extra);
        let mut child = gdsmc(&v.iter().map(String::as_str).collect::<Vec<_>>())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(at.max(Duration::from_millis(5)));
        let _ = child.kill();
        let _ = child.wait();
    };
    let again = r.join("again");
    let out = ["--out", again.to_str().unwrap(), "--threads", "2"];
    for _ in 0..3 {
        kill_during(&out, &mut seed);
    }
    let o = run(&args(&base, &out));
    assert_same_outputs(&one, &again);
    let journal = r.join(".again.run.gdsmc-ensembles");
    assert!(
        !journal.exists(),
        "the journal of a finished run is removed"
    );
    let err = String::from_utf8_lossy(&o.stderr);
    eprintln!("resumed run said: {err}");

    // Shards: shard 1 of 2 killed twice, then finished; merged with shard 0.
    let shards = r.join("shards");
    let sh = |k: u64| {
        args(
            &base,
            &[
                "--shard",
                &format!("{k}/2"),
                "--out",
                shards.to_str().unwrap(),
                "--threads",
                "2",
            ],
        )
    };
    run(&sh(0));
    let s1 = sh(1);
    let s1: Vec<&str> = s1[6..].iter().map(String::as_str).collect();
    kill_during(&s1, &mut seed);
    kill_during(&s1, &mut seed);
    run(&sh(1));
    merges_to(&shards, &one, &r.join("merged"));
}

fn merge_err(inputs: &[&Path]) -> String {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gdsmc"));
    c.arg("merge")
        .args(inputs)
        .arg("--out")
        .arg(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cluster/never-written"));
    let o = c.output().unwrap();
    assert!(!o.status.success(), "merge of {inputs:?} succeeded");
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn assert_says(err: &str, words: &[&str]) {
    for w in words {
        assert!(err.contains(w), "`{w}` not in the message: {err}");
    }
}

/// Missing, duplicated, other-seed, other-scene, truncated and damaged shards, and a whole
/// run's journal, are each refused with a message naming the file and what is wrong.
#[test]
fn bad_shard_sets_are_refused() {
    let r = root("bad");
    let base = small("grw-example3");
    let shard = |k: u64, s: u64, dir: &Path, more: &[&str]| -> PathBuf {
        let spec = format!("{k}/{s}");
        let mut extra = vec!["--shard", spec.as_str(), "--out", dir.to_str().unwrap()];
        extra.extend_from_slice(more);
        run(&args(&base, &extra));
        dir.join(format!("grw-example3.shard-{k}-of-{s}.gdsmc-ensembles"))
    };
    let good = r.join("good");
    let f: Vec<PathBuf> = (0..3).map(|k| shard(k, 3, &good, &[])).collect();

    // Missing: shard 1 of 3 not given.
    let e = merge_err(&[&f[0], &f[2]]);
    assert_says(&e, &["1 of 3 shards missing: 1/3"]);

    // Duplicate: shard 2 given twice under two names.
    let dup = r.join("copy.gdsmc-ensembles");
    std::fs::copy(&f[2], &dup).unwrap();
    let e = merge_err(&[&f[0], &f[1], &f[2], &dup]);
    assert_says(&e, &["shard 2/3 given twice", "copy.gdsmc-ensembles"]);

    // Another seed.
    let other = r.join("other-seed");
    let o1 = shard(1, 3, &other, &["--seed", "7"]);
    let e = merge_err(&[&f[0], &o1, &f[2]]);
    assert_says(
        &e,
        &["other-seed", "is not a shard of the run", "seed 7, not 1"],
    );

    // Another scene value.
    let scn = r.join("other-scene");
    let s1 = shard(1, 3, &scn, &["--set", "collisions.restitution=0.6"]);
    let e = merge_err(&[&f[0], &s1, &f[2]]);
    assert_says(&e, &["another scene", "collisions.restitution=0.6"]);

    // Another shard count.
    let four = r.join("four");
    let q = shard(1, 4, &four, &[]);
    let e = merge_err(&[&f[0], &q]);
    assert_says(&e, &["shard 1/4, not shard 0/3"]);

    // Truncated: the last 100 bytes cut off (the end record and part of a record).
    let bytes = std::fs::read(&f[1]).unwrap();
    let cut = r.join("cut.gdsmc-ensembles");
    std::fs::write(&cut, &bytes[..bytes.len() - 100]).unwrap();
    let e = merge_err(&[&f[0], &cut, &f[2]]);
    assert_says(
        &e,
        &[
            "cut.gdsmc-ensembles",
            "shard 1/3 is incomplete",
            "truncated",
        ],
    );

    // Damaged: one bit flipped in the middle of the records.
    let mut bad = bytes.clone();
    let at = bad.len() * 2 / 3;
    bad[at] ^= 0x10;
    let dmg = r.join("damaged.gdsmc-ensembles");
    std::fs::write(&dmg, &bad).unwrap();
    let e = merge_err(&[&f[0], &dmg, &f[2]]);
    assert_says(
        &e,
        &[
            "damaged.gdsmc-ensembles",
            "damaged at the record of ensemble",
        ],
    );

    // Not an ensemble file at all.
    let junk = r.join("junk.gdsmc-ensembles");
    std::fs::write(&junk, b"hello").unwrap();
    let e = merge_err(&[&f[0], &junk, &f[2]]);
    assert_says(&e, &["junk.gdsmc-ensembles", "not a gdsmc ensemble file"]);

    // A bad --shard argument names the flag.
    for spec in ["3/3", "1-3", "a/b", "0/0"] {
        let o = gdsmc(
            &args(&base, &["--shard", spec])
                .iter()
                .map(String::as_str)
                .collect::<Vec<_>>(),
        )
        .output()
        .unwrap();
        assert!(!o.status.success());
        assert_says(&String::from_utf8_lossy(&o.stderr), &["--shard"]);
    }
}
