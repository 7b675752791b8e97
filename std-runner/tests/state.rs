//! `--save-state` and `--initial-state` (docs/state.md): a continuation starts each ensemble
//! from the saved particles, bit for bit (its first observation is the saved run's last), keeps
//! the references where the state is a sample of the scene's own process and drops them where
//! it is not, is the same for any thread count, and bad or foreign files are refused by name.

use gdsmc_runner::job::{Job, Quiet};
use gdsmc_runner::run::columns::name;
use gdsmc_runner::run::state::{MAGIC, StateReader};
use gdsmc_runner::scene::{Override, Sourced};
use std::path::{Path, PathBuf};

fn root(name: &str) -> PathBuf {
    let r = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("state")
        .join(name);
    let _ = std::fs::remove_dir_all(&r);
    std::fs::create_dir_all(&r).unwrap();
    r
}

fn scene(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../scenes/{name}.toml"))
}

/// A job of the shipped scene `name` at n = 64 with `ensembles`, `sets` and the state files.
fn job(name: &str, sets: &[&str], out: &Path, states: (Option<&Path>, Option<&Path>)) -> Job {
    let mut o: Vec<Override> = sets.iter().map(|s| Override::set(*s)).collect();
    let given = |k: &str| sets.iter().any(|s| s.starts_with(k));
    o.extend(Override::run_flags(
        (!given("particles.n")).then_some(64),
        (!given("run.ensembles")).then_some(4),
        Some(7),
    ));
    Job {
        source: Sourced::read(&scene(name), o).expect("a shipped scene"),
        threads: 2,
        allow_long: false,
        shard: None,
        out: Some(out.to_path_buf()),
        fresh: false,
        format: "svg".parse().unwrap(),
        initial_state: states.0.map(Path::to_path_buf),
        save_state: states.1.map(Path::to_path_buf),
    }
}

/// observables.csv's header and rows.
fn table(dir: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(dir.join("observables.csv")).unwrap();
    let mut lines = text
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect());
    (lines.next().unwrap(), lines.collect())
}

/// The observed columns' cells of a row (not the references).
fn observed(header: &[String], row: &[String]) -> Vec<(String, String)> {
    let observed: Vec<&String> = header
        .iter()
        .filter(|c| header.contains(&format!("{c}_ci")))
        .collect();
    header
        .iter()
        .zip(row)
        .filter(|(c, _)| {
            observed
                .iter()
                .any(|o| *o == *c || format!("{o}_ci") == **c)
        })
        .map(|(c, v)| (c.clone(), v.clone()))
        .collect()
}

#[test]
fn a_continuation_starts_where_the_saved_run_stopped() {
    for name in ["grw-example3", "rough-hcs", "mixture-maxwell"] {
        let r = root(name);
        let saved = r.join("s.gdsmc-state");
        // (A steady window inside each segment: rough-hcs's own starts later.)
        let first = [
            "observe.t_end=2",
            "observe.intervals=4",
            "observe.steady_from=1",
        ];
        job(name, &first, &r.join("a"), (None, Some(&saved)))
            .run(&Quiet::default())
            .expect("the first segment runs");
        let h = StateReader::open(&saved).unwrap().header;
        assert_eq!(
            (h.segment, h.time, h.ensembles, h.n),
            (0, 2.0, 4, 64),
            "{name}"
        );
        let later = [
            "observe.t_start=2",
            "observe.t_end=4",
            "observe.intervals=4",
            "observe.steady_from=3",
        ];
        let next = r.join("s2.gdsmc-state");
        job(name, &later, &r.join("b"), (Some(&saved), Some(&next)))
            .run(&Quiet::default())
            .expect("the continuation runs");
        let (ha, a) = table(&r.join("a"));
        let (hb, b) = table(&r.join("b"));
        // The continuation's first observation is the saved run's last, bit for bit (the
        // collisions per particle counted on from the state's).
        assert_eq!(
            observed(&ha, &a[a.len() - 1]),
            observed(&hb, &b[0]),
            "{name}"
        );
        assert_eq!(b[0][0], "2.0");
        // The same process: its references are drawn (the saved run's at t = 2 too).
        assert_eq!(ha, hb, "{name}: the same columns and references");
        let h2 = StateReader::open(&next).unwrap().header;
        assert_eq!(
            (h2.segment, h2.time, &h2.origin),
            (1, 4.0, &h.origin),
            "{name}"
        );
    }
}

/// docs/state.md's own commands at n = 64 (from a drawn start): a cooling gas followed to T_bulk = 1e-10 is stored
/// rescaled about its bulk velocity, and a state holds physical velocities, whose peculiar
/// parts beside the bulk velocity `V` keep only their leading digits: a relative rounding of
/// `delta = eps |V| / sqrt(T_bulk)`. So the continuation's first observation is the saved run's
/// last to within that rounding (not to the bit; docs/state.md says so): each observed mean
/// within `6 delta` relatively (the highest moment, `v6`, is of order 6), the dimensionless
/// reduced ones (`a2`, `a3`, `c1`, `c3`, `crit`) within `16 delta` absolutely (their terms are
/// at most 15). Every value is a number (before: `v6` was NaN there).
#[test]
fn a_rescaled_cooling_gas_continues_within_its_rounding() {
    let r = root("rescaled");
    let saved = r.join("hcs.gdsmc-state");
    // A drawn start: the gas carries the bulk velocity whose rounding is the bound below
    // (the shipped scene starts with exact momentum, `V` about 1e-17).
    let drawn = "particles.momentum=drawn";
    job(
        "hcs-hard-spheres",
        &[drawn],
        &r.join("a"),
        (None, Some(&saved)),
    )
    .run(&Quiet::default())
    .unwrap();
    let (ha, a) = table(&r.join("a"));
    let last = &a[a.len() - 1];
    let t_end = last[0].clone();
    let later = [
        format!("observe.t_start={t_end}"),
        "observe.t_end=200000".to_string(),
        drawn.to_string(),
    ];
    let later: Vec<&str> = later.iter().map(String::as_str).collect();
    job(
        "hcs-hard-spheres",
        &later,
        &r.join("b"),
        (Some(&saved), None),
    )
    .run(&Quiet::default())
    .unwrap();
    let (hb, b) = table(&r.join("b"));
    let (x, y) = (observed(&ha, last), observed(&hb, &b[0]));
    let value = |cells: &[(String, String)], name: &str| -> f64 {
        cells
            .iter()
            .find(|(n, _)| n == name)
            .unwrap()
            .1
            .parse()
            .unwrap()
    };
    let t_bulk = value(&x, name::T_BULK);
    assert!(
        t_bulk < 1e-8,
        "the gas was not stored rescaled (T_bulk = {t_bulk})"
    );
    let delta = f64::EPSILON * value(&x, name::V_NORM) / t_bulk.sqrt();
    let reduced = [name::A2, name::A3, name::C1, name::C3, name::CRIT];
    for ((column, u), (_, v)) in x.iter().zip(&y) {
        let (u, v): (f64, f64) = (u.parse().unwrap(), v.parse().unwrap());
        assert!(v.is_finite(), "{column} is {v} at the continuation's start");
        let bound = if reduced.contains(&column.as_str()) {
            16.0 * delta
        } else {
            6.0 * delta * u.abs()
        };
        assert!(
            (u - v).abs() <= bound,
            "{column}: {u} then {v} (bound {bound:e})"
        );
    }
}

#[test]
fn a_continuation_is_the_same_for_any_thread_count_and_drops_foreign_references() {
    let r = root("threads");
    let saved = r.join("s.gdsmc-state");
    job(
        "grw-example3",
        &["observe.t_end=1"],
        &r.join("a"),
        (None, Some(&saved)),
    )
    .run(&Quiet::default())
    .unwrap();
    let later = ["observe.t_start=1", "observe.t_end=2"];
    let mut one = job("grw-example3", &later, &r.join("one"), (Some(&saved), None));
    one.threads = 1;
    one.run(&Quiet::default()).unwrap();
    job("grw-example3", &later, &r.join("two"), (Some(&saved), None))
        .run(&Quiet::default())
        .unwrap();
    let read = |d: &str| std::fs::read_to_string(r.join(d).join("observables.csv")).unwrap();
    assert_eq!(read("one"), read("two"));
    // Other physics from the same velocities: not a sample of its process, no references.
    let mut other = later.to_vec();
    other.push("collisions.restitution=0.9");
    let foreign = r.join("foreign-state");
    let done = job(
        "grw-example3",
        &other,
        &r.join("other"),
        (Some(&saved), Some(&foreign)),
    )
    .run(&Quiet::default())
    .unwrap();
    let (h, _) = table(&r.join("other"));
    assert!(!h.iter().any(|c| c == "T_mean_n"), "{h:?}");
    assert!(!done.text.contains("agrees with"), "{}", done.text);
    assert_eq!(StateReader::open(&foreign).unwrap().header.origin, "none");
}

#[test]
fn bad_state_files_and_mismatches_are_refused_by_name() {
    let r = root("bad");
    let saved = r.join("s.gdsmc-state");
    job(
        "grw-example3",
        &["observe.t_end=1"],
        &r.join("a"),
        (None, Some(&saved)),
    )
    .run(&Quiet::default())
    .unwrap();
    let later = ["observe.t_start=1", "observe.t_end=2"];
    let err = |sets: &[&str], file: &Path| {
        job("grw-example3", sets, &r.join("x"), (Some(file), None))
            .run(&Quiet::default())
            .unwrap_err()
            .to_string()
    };
    let e = err(&["observe.t_end=2"], &saved);
    assert!(
        e.contains("observe.t_start is 0 but the state is at t = 1"),
        "{e}"
    );
    let e = err(&[later[0], later[1], "particles.n=65"], &saved);
    assert!(
        e.contains("particles.n is 65 but the state holds 64"),
        "{e}"
    );
    let e = err(&[later[0], later[1], "run.ensembles=5"], &saved);
    assert!(
        e.contains("run.ensembles is 5 but the state holds 4"),
        "{e}"
    );
    let notes = r.join("notes.txt");
    std::fs::write(&notes, "my notes").unwrap();
    let e = err(&later, &notes);
    assert!(e.contains("too short to be a gdsmc state file"), "{e}");
    let long = r.join("long.txt");
    std::fs::write(&long, "my notes ".repeat(1000)).unwrap();
    let e = err(&later, &long);
    assert!(e.contains("not a gdsmc state file"), "{e}");
    let mut bytes = std::fs::read(&saved).unwrap();
    bytes.truncate(bytes.len() - 8);
    let cut = r.join("cut.gdsmc-state");
    std::fs::write(&cut, &bytes).unwrap();
    let e = err(&later, &cut);
    assert!(e.contains("cut short or damaged"), "{e}");
    bytes[MAGIC.len() - 1] = b'9';
    std::fs::write(&cut, &bytes).unwrap();
    let e = err(&later, &cut);
    assert!(e.contains("another format version"), "{e}");
    // A file gdsmc did not write is not replaced by a saved state.
    let e = job(
        "grw-example3",
        &["observe.t_end=1"],
        &r.join("y"),
        (None, Some(&notes)),
    )
    .run(&Quiet::default())
    .unwrap_err()
    .to_string();
    assert!(e.contains("not written by gdsmc"), "{e}");
    assert_eq!(std::fs::read_to_string(&notes).unwrap(), "my notes");
}

/// Every record of a state file, as f64s.
fn records(path: &Path) -> Vec<Vec<f64>> {
    let r = StateReader::open(path).unwrap();
    (0..r.header.ensembles)
        .map(|k| r.record(k).unwrap())
        .collect()
}

/// A velocity snapshot (`observe.snapshots`) at an intermediate observation holds, bit for bit,
/// the particles a run stopped there saves (the observations before it are the same, so the
/// trajectories are), is a state file a continuation starts from, and is listed in the output
/// set's manifest.
#[test]
fn a_snapshot_is_the_state_of_a_run_stopped_there() {
    for name in ["grw-example3", "rough-hcs", "mixture-maxwell"] {
        let r = root(&format!("snap-{name}"));
        let long = [
            "observe.t_end=2",
            "observe.intervals=4",
            "observe.steady_from=1",
            "observe.snapshots=[0.9, 2.0]",
        ];
        job(name, &long, &r.join("a"), (None, None))
            .run(&Quiet::default())
            .expect("the run with snapshots runs");
        let saved = r.join("s.gdsmc-state");
        let short = [
            "observe.t_end=1",
            "observe.intervals=2",
            "observe.steady_from=0.5",
        ];
        job(name, &short, &r.join("b"), (None, Some(&saved)))
            .run(&Quiet::default())
            .expect("the shorter run runs");
        let snap = r.join("a").join("snapshot-0.state");
        let h = StateReader::open(&snap).unwrap().header;
        // 0.9 is taken at the first observation at or after it.
        assert_eq!((h.time, h.segment, h.ensembles), (1.0, 0, 4), "{name}");
        assert_eq!(records(&snap), records(&saved), "{name}");
        assert_eq!(
            StateReader::open(&r.join("a").join("snapshot-1.state"))
                .unwrap()
                .header
                .time,
            2.0
        );
        let manifest = std::fs::read_to_string(r.join("a").join("manifest.json")).unwrap();
        assert!(manifest.contains("snapshot-1.state"), "{name}");
    }
}

/// A snapshot after the last observation is refused by its key; a sweep or a shard of a scene
/// with snapshots says what it does not take.
#[test]
fn snapshots_past_the_end_or_with_shards_are_refused_by_name() {
    let e = Sourced::read(
        &scene("grw-example3"),
        vec![Override::set("observe.snapshots=[0.5, 9.0]")],
    )
    .err()
    .map(|e| e.to_string())
    .unwrap_or_default();
    assert!(
        e.contains("observe.snapshots") && e.contains("at most"),
        "{e}"
    );
    let r = root("snap-shard");
    let mut j = job(
        "grw-example3",
        &["observe.t_end=1", "observe.snapshots=[1.0]"],
        &r.join("a"),
        (None, None),
    );
    j.shard = Some("0/2".into());
    let e = (j.run(&Quiet::default()).err())
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(
        e.contains("observe.snapshots") && e.contains("--shard"),
        "{e}"
    );
}
