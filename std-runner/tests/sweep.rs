//! `gdsmc sweep` (`gdsmc_runner::sweep`): a point is the run of its scene and seed to the last
//! bit, an interrupted sweep continued writes the uninterrupted sweep's bytes, and a bad point
//! or a key both set and varied is refused before anything runs.

use gdsmc_runner::job::{Quiet, Watch};
use gdsmc_runner::scene::{Override, Sourced};
use gdsmc_runner::sweep::Sweep;
use gdsmc_runner::sweep::vary::{Combine, Vary};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

pub(super) fn root(name: &str) -> PathBuf {
    let r = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("sweep")
        .join(name);
    let _ = std::fs::remove_dir_all(&r);
    std::fs::create_dir_all(&r).unwrap();
    r
}

pub(super) fn scene() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/grw-example3.toml")
}

/// The sweep of GRW Example 3 (n = 64, 4 ensembles, seed 5) over `vary`, into `out`.
pub(super) fn sweep(vary: &[&str], sets: &[&str], out: &Path, threads: usize) -> Sweep {
    let mut overrides: Vec<Override> = sets.iter().map(|s| Override::set(*s)).collect();
    overrides.extend(Override::run_flags(Some(64), Some(4), Some(5)));
    Sweep {
        source: Sourced::read(&scene(), overrides).expect("a shipped scene"),
        vary: vary.iter().map(|v| Vary::parse(v).unwrap()).collect(),
        combine: Combine::Grid,
        threads,
        allow_long: false,
        out: Some(out.to_path_buf()),
        fresh: false,
        format: "svg".parse().unwrap(),
        shard: None,
    }
}

pub(super) fn json(path: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap()
}

/// `gdsmc run` of GRW Example 3 (n = 64, 4 ensembles, one thread) with `seed` and `sets`,
/// into `out`.
pub(super) fn command_run(out: &Path, seed: usize, sets: &[String]) {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gdsmc"));
    c.arg("run")
        .arg(scene())
        .args(["--n", "64", "--ensembles", "4", "--threads", "1", "--seed"])
        .arg(seed.to_string());
    for s in sets {
        c.args(["--set", s]);
    }
    let o = c.arg("--out").arg(out).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Each point of a two-point sweep with a steady window (run on two threads) equals `gdsmc
/// run` of its scene with seed 5 + k (on one thread): every observable's window mean and
/// interval to the last bit, as summary.json's steady state has them.
#[test]
fn a_point_is_the_run_of_its_scene_and_seed() {
    let r = root("same-as-runs");
    let steady = "observe.steady_from=4.0";
    let done = sweep(
        &["collisions.restitution=0.5,0.8"],
        &[steady],
        &r.join("sweep"),
        2,
    )
    .run(&Quiet::default())
    .expect("the sweep runs");
    assert!(done.complete, "{}", done.text);
    let sw = json(&r.join("sweep").join("sweep.json"));
    let points = sw["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    for (k, alpha) in ["0.5", "0.8"].into_iter().enumerate() {
        let out = r.join(format!("run{k}"));
        command_run(
            &out,
            5 + k,
            &[
                format!("collisions.restitution={alpha}"),
                steady.to_string(),
            ],
        );
        let run = json(&out.join("summary.json"));
        let steady = &run["steady_state"]["observables"];
        let p = &points[k];
        assert_eq!(p["window"]["steady_from"], 4.0);
        assert_eq!(p["seed"], 5 + k as u64);
        assert_eq!(p["values"]["collisions.restitution"], alpha);
        let obs = p["observables"].as_object().unwrap();
        assert!(obs.len() > 10, "{p}");
        for (name, v) in obs {
            for field in ["mean", "ci"] {
                assert_eq!(
                    v[field].as_f64(),
                    steady[name][field].as_f64(),
                    "point {k}, {name} {field}"
                );
            }
        }
    }
}

/// The header and the rows of a CSV file, as text.
pub(super) fn csv_cells(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text
        .lines()
        .map(|l| l.split(',').map(String::from).collect::<Vec<_>>());
    (lines.next().unwrap(), lines.collect())
}

/// Without a steady window a point's averages are its last observation's: sweep.csv's cells
/// equal the last row of the run's observables.csv, means and intervals, to the last digit
/// (both write the shortest text that reads back as the same number); and so does the exact
/// temperature GRW (13) at the point's own beta.
#[test]
fn without_a_steady_window_a_point_is_its_last_observation() {
    let r = root("end-window");
    sweep(&["drive.beta=0.5,2"], &[], &r.join("sweep"), 2)
        .run(&Quiet::default())
        .expect("the sweep runs");
    command_run(&r.join("run"), 6, &["drive.beta=2".to_string()]);
    let (sh, srows) = csv_cells(&r.join("sweep").join("sweep.csv"));
    let (rh, rrows) = csv_cells(&r.join("run").join("observables.csv"));
    let point = &srows[1];
    let last = rrows.last().unwrap();
    let cell = |h: &[String], row: &[String], name: &str| {
        let i = h
            .iter()
            .position(|x| x == name)
            .unwrap_or_else(|| panic!("{name}"));
        row[i].clone()
    };
    assert_eq!(cell(&sh, point, "drive.beta"), "2");
    assert_eq!(cell(&sh, point, "window_from"), "8.0");
    let mut compared = 0;
    for name in rh.iter().skip(1) {
        assert_eq!(cell(&sh, point, name), cell(&rh, last, name), "{name}");
        compared += 1;
    }
    assert!(compared > 30, "{compared} columns");
}

/// A watcher that asks the sweep to stop once `after` ensembles have finished.
struct StopAfter {
    after: u64,
    done: AtomicU64,
    stop: AtomicBool,
}

impl Watch for StopAfter {
    fn begin(&self, _: u64) {}
    fn advance(&self, k: u64) {
        if self.done.fetch_add(k, Ordering::SeqCst) + k >= self.after {
            self.stop.store(true, Ordering::SeqCst);
        }
    }
    fn end(&self) {}
    fn stop(&self) -> &AtomicBool {
        &self.stop
    }
    fn note(&self, _: &str) {}
}

/// A sweep stopped in its second point keeps the first and the second's finished ensembles
/// (its output lists the first point alone); run again it writes the uninterrupted sweep's
/// sweep.csv and sweep.json byte for byte, and removes its journals.
#[test]
fn a_stopped_sweep_continued_writes_the_same_bytes() {
    let r = root("continued");
    let vary = ["collisions.restitution=0.5,0.8,0.9"];
    let whole = sweep(&vary, &[], &r.join("whole"), 1)
        .run(&Quiet::default())
        .unwrap();
    assert!(whole.complete);
    let s = sweep(&vary, &[], &r.join("cut"), 1);
    let watch = StopAfter {
        after: 6,
        done: AtomicU64::new(0),
        stop: AtomicBool::new(false),
    };
    let cut = s.run(&watch).expect("the first point is kept");
    assert!(!cut.complete);
    let partial = json(&r.join("cut").join("sweep.json"));
    assert_eq!(partial["points"].as_array().unwrap().len(), 1);
    assert_eq!(partial["complete"], false);
    let journals = |dir: &Path| {
        std::fs::read_dir(dir)
            .unwrap()
            .flatten()
            .filter(|e| e.file_name().to_string_lossy().contains(".point-"))
            .count()
    };
    assert!(journals(&r) >= 2, "the finished point and the running one");
    let again = s.run(&Quiet::default()).unwrap();
    assert!(again.complete);
    for f in ["sweep.csv", "sweep.json", "sweep.md"] {
        assert_eq!(
            std::fs::read(r.join("whole").join(f)).unwrap(),
            std::fs::read(r.join("cut").join(f)).unwrap(),
            "{f}"
        );
    }
    assert_eq!(journals(&r), 0);
}

/// A point that breaks a rule is refused before anything runs, naming the point and the key;
/// so is a key both set and varied; neither leaves an output directory.
#[test]
fn bad_points_are_refused_before_anything_runs() {
    let r = root("refused");
    let e = sweep(&["collisions.restitution=0.5,1.5"], &[], &r.join("o"), 1)
        .run(&Quiet::default())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("point 1") && e.contains("collisions.restitution"),
        "{e}"
    );
    assert!(e.contains("(0, 1]"), "{e}");
    let e = sweep(
        &["collisions.restitution=0.5,0.9"],
        &["collisions.restitution=0.7"],
        &r.join("o"),
        1,
    )
    .run(&Quiet::default())
    .unwrap_err()
    .to_string();
    assert!(e.contains("also sets"), "{e}");
    assert!(!r.join("o").exists());
}

/// A directory of the user's at `--out` is refused before anything runs and left as it was.
#[test]
fn a_users_directory_is_never_replaced() {
    let r = root("users-dir");
    let mine = r.join("mine");
    std::fs::create_dir_all(&mine).unwrap();
    std::fs::write(mine.join("notes.txt"), "mine").unwrap();
    let e = sweep(&["collisions.restitution=0.5,0.9"], &[], &mine, 1)
        .run(&Quiet::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains(&mine.display().to_string()), "{e}");
    assert_eq!(
        std::fs::read_to_string(mine.join("notes.txt")).unwrap(),
        "mine"
    );
    assert_eq!(std::fs::read_dir(&mine).unwrap().count(), 1);
}

/// `gdsmc sweep` with no `--vary` takes the scene's `[sweep]` table: the shipped cooling-state
/// sweep (9 values of alpha, spheres and disks) gives 18 rows, each with its Sonine value.
#[test]
fn the_command_takes_the_scenes_sweep_table() {
    let r = root("table");
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/sweep-hcs-a2.toml");
    let o = Command::new(env!("CARGO_BIN_EXE_gdsmc"))
        .arg("sweep")
        .arg(&scene)
        .args([
            "--n",
            "64",
            "--ensembles",
            "2",
            "--set",
            "observe.t_end=20",
            "--set",
        ])
        .arg("observe.steady_from=10")
        .arg("--out")
        .arg(r.join("o"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (header, rows) = csv_cells(&r.join("o").join("sweep.csv"));
    assert_eq!(rows.len(), 18);
    assert_eq!(
        header[1..3],
        ["collisions.restitution", "particles.dimension"]
    );
    let sonine = header.iter().position(|h| h == "a2_sonine").unwrap();
    assert!(rows.iter().all(|row| row[sonine].parse::<f64>().is_ok()));
    assert_eq!(rows[17][1..3], ["0.9", "2"]);
    // sweep.md: the a2 table, a row per point, each beside its Sonine value.
    let md = std::fs::read_to_string(r.join("o").join("sweep.md")).unwrap();
    let a2 = md
        .split("\n## ")
        .find(|t| t.starts_with("a2\n"))
        .expect("an a2 table");
    assert_eq!(
        a2.lines().filter(|l| l.starts_with("| 0.")).count(),
        18,
        "{a2}"
    );
    assert!(a2.contains("mean - a2_sonine | in half-widths"), "{a2}");
}

/// The sweep's verdict checks every exact mean at n over the points together: the heated
/// Maxwell gas over beta (fixed seed; the family's 99.9% level, Bonferroni over the points)
/// has every point inside, and the same results with one point's mean moved by five of its
/// widened half-widths name that point (the verdict can fail).
#[test]
fn the_verdict_checks_the_exact_means_over_the_points() {
    use gdsmc_runner::sweep::verdict;
    let r = root("verdict");
    let s = sweep(&["drive.beta=0.5,1,2"], &[], &r.join("o"), 0);
    let points = s.points().unwrap();
    let mut results: Vec<_> = points
        .iter()
        .map(|p| {
            let st = gdsmc_runner::run::run(&p.source.scene, 0, &|_| {}).unwrap();
            gdsmc_runner::sweep::point::PointResult::of(p, &st)
        })
        .collect();
    let checks = verdict::checks(&results);
    let t = gdsmc_runner::run::columns::name::T;
    let c = checks
        .iter()
        .find(|c| c.of == t)
        .expect("T has its exact mean at n");
    assert_eq!(c.points, 3);
    assert!(c.outside.is_empty() && c.worst <= 1.0, "{checks:?}");
    assert!(verdict::text(&checks).contains("all inside"));
    let o = results[1]
        .observables
        .iter_mut()
        .find(|o| o.0 == t)
        .unwrap();
    o.1 += 5.0 * o.2 * gdsmc_stats::level::family(3, 3);
    let moved = verdict::checks(&results);
    let c = moved.iter().find(|c| c.of == t).unwrap();
    assert_eq!(c.outside, [1]);
    assert!(verdict::text(&moved).contains("OUTSIDE at point 1"));
    // sweep.json carries the same verdict.
    let j = gdsmc_runner::sweep::table::json("grw", &s.vary, s.combine, true, &results);
    let v = j["verdict"]
        .as_array()
        .unwrap()
        .iter()
        .find(|v| v["of"] == t)
        .unwrap()
        .clone();
    assert_eq!(v["outside"], serde_json::json!([1]));
    assert_eq!(v["inside"], false);
    assert_eq!(v["points"], 3);
}
