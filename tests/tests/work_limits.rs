//! Absurd work is refused before a run starts, naming the keys; every shipped scene at its own
//! settings is within the limit. The examples are those that used to run for centuries.

use gdsmc_runner::run::estimate::{MAX_WORK, check, estimate};
use gdsmc_runner::scene;
use gdsmc_validation::scene_path;
use std::path::PathBuf;

fn with(name: &str, set: &[&str]) -> scene::Scene {
    let set: Vec<String> = set.iter().map(|s| s.to_string()).collect();
    scene::load_with_overrides(&scene_path(name), &set).expect("valid scene")
}

#[test]
fn shipped_scenes_are_within_the_limit() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes");
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "toml") {
            let s = scene::load(&p).unwrap();
            let w = check(&s, 2, false).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            assert!(
                w.total() > 0.0 && w.total() < MAX_WORK / 100.0,
                "{}: {w:?}",
                s.name()
            );
        }
    }
}

#[test]
fn absurd_work_is_refused_naming_the_keys() {
    for (name, set) in [
        ("grw-example3", &["observe.t_end=1e300"][..]),
        ("grw-example5", &["collisions.gamma=1e300"][..]),
        // 8e12 steps of 1024 particles (dt = 1e-300 is refused before, by the grid: below).
        (
            "grw-example3",
            &["scheme.kind=euler", "scheme.dt=1e-12"][..],
        ),
        ("brs-example5", &["drive.density=1e300"][..]),
        (
            "ms-gaussian",
            &["scheme.kind=time-stepped", "scheme.step_factor=1e-300"][..],
        ),
        ("grw-example3", &["run.ensembles=9000000000000000000"][..]),
        (
            "ms-white-noise",
            &["observe.collisional_pairs=9223372036854775807"][..],
        ),
    ] {
        let s = with(name, set);
        let e = check(&s, 2, false).unwrap_err().to_string();
        assert!(
            e.contains("observe.t_end") && e.contains("--allow-long"),
            "{name} {set:?}: {e}"
        );
        assert!(
            check(&s, 2, true).is_ok(),
            "--allow-long lets {name} {set:?} run"
        );
        assert!(estimate(&s).total() > MAX_WORK);
    }
    let s = with("grw-example3", &[]);
    let e = check(&s, 100_000, false).unwrap_err().to_string();
    assert!(e.starts_with("--threads: must be at most"), "{e}");
    let s = with("grw-example3", &["particles.n=1000000000000"]);
    let e = check(&s, 2, true).unwrap_err().to_string();
    assert!(e.starts_with("particles.n: = 1000000000000 needs"), "{e}");
    // A step too small for a u64 step count is no grid at all: refused with the scene,
    // naming scheme.dt, before any estimate.
    let set = ["scheme.kind=euler".to_string(), "scheme.dt=1e-300".into()];
    let e = scene::load_with_overrides(&scene_path("grw-example3"), &set)
        .unwrap_err()
        .to_string();
    assert!(e.contains("scheme.dt") && e.contains("2^64 steps"), "{e}");
}
