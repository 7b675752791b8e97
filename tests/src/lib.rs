//! Helpers for the cross-crate validation tests: load a shipped scene, resize it, run it.

use gdsmc_runner::run::{self, RunStats};
use gdsmc_runner::scene::{self, Scene};
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
    s.set_n(n).expect("a valid particle count");
    s.set_ensembles(m).expect("at least one ensemble");
    s.set_seed(seed);
    s
}

/// A shipped scene with `--set` overrides, `n` particles, `m` ensembles and this seed.
pub fn shipped_set(name: &str, set: &[&str], n: usize, m: u64, seed: u64) -> Scene {
    let set: Vec<String> = set.iter().map(|s| s.to_string()).collect();
    let mut s = scene::load_with_overrides(&scene_path(name), &set).expect("valid overrides");
    s.set_n(n).expect("a valid particle count");
    s.set_ensembles(m).expect("at least one ensemble");
    s.set_seed(seed);
    s
}

/// Runs a scene on all cores.
pub fn run(s: &Scene) -> RunStats {
    run::run(s, 0, &|_| {}).expect("run succeeds")
}

/// Mean and 99.9% CI half-width of column `name` at time index `ti`.
pub fn at(stats: &RunStats, ti: usize, name: &str) -> (f64, f64) {
    let c = stats.col(name).expect("known column");
    (stats.mean(ti, c), stats.ci(ti, c))
}

/// How many observation times after the first put column `name` farther from `reference(t)`
/// than `factor` times its 99.9% half-width: a check that must refuse a wrong reference.
pub fn times_outside(
    stats: &RunStats,
    name: &str,
    factor: f64,
    reference: impl Fn(f64) -> f64,
) -> usize {
    (1..stats.times.len())
        .filter(|&ti| {
            let (m, c) = at(stats, ti, name);
            (m - reference(stats.times[ti])).abs() > factor * c
        })
        .count()
}

/// Asserts that column `name` lies within `factor` times its 99.9% half-width of
/// `reference(t)` at every observation time; `what` names the case in the message.
pub fn assert_within_at_all_times(
    stats: &RunStats,
    name: &str,
    factor: f64,
    reference: impl Fn(f64) -> f64,
    what: &str,
) {
    for (ti, &t) in stats.times.iter().enumerate() {
        let (m, c) = at(stats, ti, name);
        let r = reference(t);
        assert!(
            (m - r).abs() <= factor * c,
            "{what}, t = {t}: {name} {m} +- {}, reference {r}",
            factor * c
        );
    }
}

/// Index of the observation time `t` (exactly one of the scene's times).
pub fn time_index(stats: &RunStats, t: f64) -> usize {
    stats
        .times
        .iter()
        .position(|&x| (x - t).abs() < 1e-12)
        .expect("observation time")
}

/// Runs `s`, a Maxwell gas whose temperature is exact (GRW (13) with its drive's heating), and
/// asserts `T_bulk` and the raw `T` within their exact finite-n means jointly at 99.9% over
/// both columns and every time (Bonferroni); `what` names the case. Returns the reference, the
/// run and the family's factor, for the caller's power checks.
pub fn assert_exact_maxwell_temperature(
    s: &Scene,
    what: &str,
) -> (gdsmc_theory::exact::MaxwellTemperature, RunStats, f64) {
    let mt = gdsmc_theory::curves::maxwell_temperature(s).expect("a Maxwell gas: GRW (13) applies");
    let n = s.n();
    let st = run(s);
    let f = gdsmc_stats::family(2 * st.times.len(), gdsmc_stats::dof(st.ensembles));
    let name = gdsmc_runner::run::columns::name::T_BULK;
    assert_within_at_all_times(&st, name, f, |t| mt.finite_n_bulk_mean(n, t), what);
    let name = gdsmc_runner::run::columns::name::T;
    assert_within_at_all_times(&st, name, f, |t| mt.finite_n_raw_mean(n, t), what);
    (mt, st, f)
}
