//! Runs held in memory (the library's and the Python package's): every ensemble of a scene,
//! folded in ensemble order, with the state files and each ensemble's own rows when asked.

use super::{Clock, OnRow, StateIo, Totals, job, stats_of};
use crate::Error;
use crate::run::RunStats;
use crate::run::columns::names;
use crate::scene::Scene;
use std::sync::atomic::AtomicBool;

/// Runs every ensemble of `scene` on `threads` threads (0: all cores); `progress` is called
/// with the number of ensembles each finished chunk adds.
pub fn run(
    scene: &Scene,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<RunStats, Error> {
    run_interruptible(scene, threads, progress, &AtomicBool::new(false))
}

/// As [`run`], stopping early when `stop` becomes true (Ctrl-C): ensembles already running
/// finish, and the statistics cover the first `RunStats::ensembles` ensembles, exactly those a
/// run with that many ensembles would give.
pub fn run_interruptible(
    scene: &Scene,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
    stop: &AtomicBool,
) -> Result<RunStats, Error> {
    run_seeing_rows(
        scene,
        threads,
        (progress, stop),
        StateIo::default(),
        &mut |_, _, _| Ok(()),
    )
}

/// As [`run_interruptible`], keeping every ensemble's own observables: `samples` receives,
/// per ensemble in order (the finished prefix when stopped), its values at every observation
/// time, row-major (`times x columns`, the columns of [`super::columns::names`]): what an analysis
/// beyond the mean and its interval needs (a bootstrap, the spread of a fitted exponent).
pub fn run_with_samples(
    scene: &Scene,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
    stop: &AtomicBool,
    samples: &mut Vec<Vec<f64>>,
) -> Result<RunStats, Error> {
    run_in_memory(
        scene,
        threads,
        (progress, stop),
        StateIo::default(),
        Some(samples),
    )
}

/// The in-memory run the Python package makes: every ensemble of `scene` from and to the
/// state files of `state`, each ensemble's observables into `samples` when given.
pub fn run_in_memory(
    scene: &Scene,
    threads: usize,
    watch: (&(dyn Fn(u64) + Sync), &AtomicBool),
    state: StateIo<'_>,
    mut samples: Option<&mut Vec<Vec<f64>>>,
) -> Result<RunStats, Error> {
    let width = scene.times().len() * names(scene).len();
    run_seeing_rows(scene, threads, watch, state, &mut |_, row, _| {
        if let Some(s) = samples.as_deref_mut() {
            s.push(row[..width].to_vec());
        }
        Ok(())
    })
}

/// Runs every ensemble of `scene` in memory (from and to the state files of `state`), handing
/// each finished ensemble's row to `on_row` in ensemble order before it is folded.
fn run_seeing_rows(
    scene: &Scene,
    threads: usize,
    (progress, stop): (&(dyn Fn(u64) + Sync), &AtomicBool),
    state: StateIo<'_>,
    on_row: &mut OnRow,
) -> Result<RunStats, Error> {
    let clock = Clock::start(threads);
    let mut totals = Totals::new(scene);
    job(scene, clock.threads, progress, stop, state, |job| {
        job.fold(0..scene.ensembles(), &mut totals, on_row)
    })?;
    Ok(stats_of(scene, totals, clock.timing()))
}
