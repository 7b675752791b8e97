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

/// A mixture that gives each pair its coefficient (`pair_restitution`) cools as the same
/// mixture with one `restitution` for every pair: the estimate sees that cooling (it once
/// took alpha = 1 from the unused `restitution` and asked for 1e12 units at t_end = 1e7, where
/// 1e8 were done), for the smooth mixture, its rough twin at beta = -1 and a rough one, at
/// t_end = 1e7 and every pair alike (the two descriptions of one physics must give one
/// estimate) or unlike (the pairs' mean dissipation: between the two uniform mixtures').
#[test]
fn a_mixture_with_pair_restitution_is_estimated_cooling() {
    let text = std::fs::read_to_string(scene_path("rough-mixture-hcs")).unwrap();
    let text = text.replace("steady_from = 100.0", "");
    let parse = |text: &str| scene::parse(std::path::Path::new("mix.toml"), text).unwrap();
    let units = |text: &str, set: &str| {
        let s = parse(
            &text
                .replace("restitution = 0.9", set)
                .replace("t_end = 200.0", "t_end = 1e7"),
        );
        check(&s, 2, false).unwrap_or_else(|e| panic!("{set}: {e}"));
        estimate(&s).total()
    };
    let smooth_text = text.replace(
        "[rotation]\ntangential_restitution = 0.0\ninertia = 0.4\ntemperature = 1.0\n",
        "",
    );
    let twin = text.replace(
        "tangential_restitution = 0.0",
        "tangential_restitution = -1.0",
    );
    assert!(
        smooth_text != text && twin != text,
        "the scene's texts were replaced"
    );
    for (what, text) in [
        ("smooth", &smooth_text),
        ("beta = -1", &twin),
        ("beta = 0", &text),
    ] {
        let one = units(text, "restitution = 0.9");
        let pairs = units(text, "pair_restitution = [[0.9, 0.9], [0.9, 0.9]]");
        assert!(
            (pairs - one).abs() <= 1e-9 * one,
            "{what}: {pairs} vs {one}"
        );
        let mixed = units(text, "pair_restitution = [[0.8, 0.9], [0.9, 0.95]]");
        let (lo, hi) = (
            units(text, "restitution = 0.8"),
            units(text, "restitution = 0.95"),
        );
        assert!(
            lo < mixed && mixed < hi,
            "{what}: {mixed} not within ({lo}, {hi})"
        );
    }
}
