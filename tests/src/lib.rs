//! Helpers for the cross-crate validation tests: load a shipped scene, resize it, run it.

use gdsmc::ensemble::{self, RunStats};
use gdsmc::scene::{self, Scene};
use std::path::PathBuf;

/// Path of a shipped scene file.
pub fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("scenes")
        .join(format!("{name}.toml"))
}

/// A shipped scene with `n` particles, `m` ensembles and this seed.
pub fn shipped(name: &str, n: usize, m: u64, seed: u64) -> Scene {
    let mut s = scene::load(&scene_path(name)).expect("shipped scene loads");
    s.n = n;
    s.ensembles = m;
    s.seed = seed;
    s
}

/// A shipped scene with `--set` overrides, `n` particles, `m` ensembles and this seed.
pub fn shipped_set(name: &str, set: &[&str], n: usize, m: u64, seed: u64) -> Scene {
    let set: Vec<String> = set.iter().map(|s| s.to_string()).collect();
    let mut s = scene::load_with_overrides(&scene_path(name), &set).expect("valid overrides");
    s.n = n;
    s.ensembles = m;
    s.seed = seed;
    s
}

/// Runs a scene on all cores.
pub fn run(s: &Scene) -> RunStats {
    ensemble::run(s, 0, &|_| {}).expect("run succeeds")
}

/// Mean and 99.9% CI half-width of column `name` at time index `ti`.
pub fn at(stats: &RunStats, ti: usize, name: &str) -> (f64, f64) {
    let c = stats.col(name).expect("known column");
    (stats.mean(ti, c), stats.ci(ti, c))
}

/// Index of the observation time `t` (exactly one of the scene's times).
pub fn time_index(stats: &RunStats, t: f64) -> usize {
    stats
        .times
        .iter()
        .position(|&x| (x - t).abs() < 1e-12)
        .expect("observation time")
}
