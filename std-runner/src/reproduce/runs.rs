//! Running the shipped scenes a table needs, and reading its statistics.

use super::Options;
use crate::Error;
use crate::run::{self, RunStats};
use crate::scene::{self, Scene};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;
use std::time::Instant;

/// The shipped scenes, compiled in so that `reproduce` runs from any directory.
pub(crate) const SCENES: &[(&str, &str)] = &[
    (
        "grw-example3",
        include_str!("../../../scenes/grw-example3.toml"),
    ),
    (
        "grw-example4",
        include_str!("../../../scenes/grw-example4.toml"),
    ),
    (
        "rw-transient",
        include_str!("../../../scenes/rw-transient.toml"),
    ),
    ("rw-steady", include_str!("../../../scenes/rw-steady.toml")),
    (
        "rw-steady-30",
        include_str!("../../../scenes/rw-steady-30.toml"),
    ),
    (
        "brs-example1",
        include_str!("../../../scenes/brs-example1.toml"),
    ),
    (
        "brs-example2",
        include_str!("../../../scenes/brs-example2.toml"),
    ),
    (
        "brs-example4",
        include_str!("../../../scenes/brs-example4.toml"),
    ),
    (
        "brs-example5",
        include_str!("../../../scenes/brs-example5.toml"),
    ),
    (
        "ms-white-noise",
        include_str!("../../../scenes/ms-white-noise.toml"),
    ),
    (
        "ms-gaussian",
        include_str!("../../../scenes/ms-gaussian.toml"),
    ),
    (
        "ms-constant-force",
        include_str!("../../../scenes/ms-constant-force.toml"),
    ),
    (
        "hcs-hard-spheres",
        include_str!("../../../scenes/hcs-hard-spheres.toml"),
    ),
];

/// A shipped scene with overrides (`--set` syntax), `n` particles, `m` ensembles and a seed.
pub(crate) fn scene(name: &str, set: &[String], n: usize, m: u64, seed: u64) -> Scene {
    let text = SCENES
        .iter()
        .find(|(k, _)| *k == name)
        .map(|(_, t)| *t)
        .expect("a compiled-in scene");
    let path = format!("scenes/{name}.toml");
    let mut s = scene::parse_with_overrides(Path::new(&path), text, set)
        .expect("shipped scenes and reproduce's overrides are valid");
    s.set_n(n)
        .expect("reproduce's particle counts are valid for its scenes");
    s.set_ensembles(m)
        .expect("reproduce runs at least one ensemble");
    s.set_seed(seed);
    s
}

/// Runs a scene, returning its statistics and wall seconds (those of the first run of the
/// same scene, seed and ensembles while [`with_cached_runs`] holds them on this thread).
pub(crate) fn go(s: &Scene, opts: &Options) -> Result<(RunStats, f64), Error> {
    let key = format!("{} {} {}", s.fingerprint(), s.seed(), s.ensembles());
    if let Some(hit) = CACHE.with_borrow(|c| c.as_ref().and_then(|c| c.get(&key).cloned())) {
        return Ok(hit);
    }
    let t = Instant::now();
    let st = run::run(s, opts.threads, &|_| {})?;
    let done = (st, t.elapsed().as_secs_f64());
    PROGRESS.with(|p| {
        if let Some(k) = p.get() {
            p.set(Some(k + 1));
            eprintln!(
                "  run {} of this table: {}, n = {}, {} ensembles, {:.1} s",
                k + 1,
                s.name(),
                s.n(),
                s.ensembles(),
                done.1
            );
        }
    });
    CACHE.with_borrow_mut(|c| {
        if let Some(c) = c {
            c.insert(key, done.clone());
        }
    });
    Ok(done)
}

thread_local! {
    /// The runs of the current table so far, when the command reports progress within a
    /// table ([`progress_within_tables`]); `None`: silent (the library, Python, the tests).
    static PROGRESS: std::cell::Cell<Option<usize>> = const { std::cell::Cell::new(None) };
}

/// Reports each run of a table on stderr as it finishes (its scene, size and seconds), counting
/// from 1 again after [`next_table`]: `gdsmc reproduce`'s progress within a table.
pub fn progress_within_tables() {
    PROGRESS.with(|p| p.set(Some(0)));
}

/// Counts the next table's runs from 1 (when progress is reported).
pub fn next_table() {
    PROGRESS.with(|p| {
        if p.get().is_some() {
            p.set(Some(0));
        }
    });
}

thread_local! {
    /// The runs kept while [`with_cached_runs`] is in force on this thread.
    static CACHE: RefCell<Option<HashMap<String, (RunStats, f64)>>> = const { RefCell::new(None) };
}

/// Runs `f` keeping every run `reproduce` makes on this thread, so that tables built again
/// (the mutation check rebuilds every table once per perturbed reference) reuse the
/// statistics instead of simulating again: a run is a pure function of its scene, seed and
/// ensembles. The runs are dropped when `f` returns.
pub fn with_cached_runs<T>(f: impl FnOnce() -> T) -> T {
    struct Drop_;
    impl Drop for Drop_ {
        fn drop(&mut self) {
            CACHE.with_borrow_mut(|c| *c = None);
        }
    }
    CACHE.with_borrow_mut(|c| *c = Some(HashMap::new()));
    let _drop = Drop_;
    f()
}

/// Ensembles for a row: the paper's `paper` in full mode; in quick mode as many as keep
/// `n * m` near `budget` (at least 16, at most the paper's).
pub(crate) fn ensembles(opts: &Options, n: usize, paper: u64, budget: u64) -> u64 {
    if opts.quick {
        (budget / n as u64).clamp(16, paper)
    } else {
        paper
    }
}

/// Mean and half-width of column `col` at time index `ti`.
pub(crate) fn at(st: &RunStats, ti: usize, col: &str) -> (f64, f64) {
    let c = st.col(col).expect("a known column");
    (st.mean(ti, c), st.ci(ti, c))
}

/// Steady-state mean and half-width of column `col`.
pub(crate) fn steady(st: &RunStats, col: &str) -> (f64, f64) {
    st.steady
        .as_ref()
        .expect("a steady-state scene")
        .steady_mean_ci(st, st.col(col).expect("a known column"))
}

/// Per observation time: the relative error of the mean of column `col` against `truth`,
/// `(mean(t) - truth(t)) / truth(t)` (signed), and the relative standard deviation of one
/// ensemble, `sd(t) / |truth(t)|`. The largest absolute error is GRW (29), RW's `E_max`, BRS's
/// `Err`.
pub(crate) fn relative(st: &RunStats, col: &str, truth: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let c = st.col(col).expect("a known column");
    st.times
        .iter()
        .enumerate()
        .map(|(ti, &t)| {
            let x = truth(t);
            ((st.mean(ti, c) - x) / x, st.sd(ti, c) / x.abs())
        })
        .collect()
}

/// The largest absolute relative error and the largest relative standard deviation of a
/// [`relative`] profile.
pub(crate) fn largest(rel: &[(f64, f64)]) -> (f64, f64) {
    rel.iter().fold((0.0, 0.0), |(e, s), r| {
        (f64::max(e, r.0.abs()), f64::max(s, r.1))
    })
}
