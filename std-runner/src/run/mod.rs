//! Ensembles: many independent particle systems of one scene, run in parallel.
//!
//! Ensemble `k` uses the seed's Xoshiro256++ generator jumped `k` times. Ensembles are grouped
//! in fixed chunks of [`CHUNK`]; each chunk is accumulated in ensemble order and the chunks are
//! merged in chunk order, so the statistics are bit-identical for any number of threads.
//!
//! The engine is composed at compile time: the core's [`Model::start`] turns the scene's
//! physics into one statically composed event loop per ensemble.

pub mod columns;
pub mod ensemble;
pub mod estimate;
pub mod pages;
pub mod results;
pub mod stats;

pub use ensemble::{initial_sampler, initial_temperature, particle_buffer, run_ensemble};
pub use results::{RunStats, SteadyStats};

use crate::error::Error;
use crate::scene::Scene;
use columns::names;
use gdsmc_core::engine::Counts;
use gdsmc_core::physics::Model;
use gdsmc_core::rng::{Streams, Xoshiro256PlusPlus};
use rayon::prelude::*;
use stats::Accumulator;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Ensembles per chunk: the unit of parallel work and of the fixed merge order (one, so that
/// even a handful of long ensembles spreads over every core).
pub const CHUNK: u64 = 1;
/// Chunks handed to the pool at once (bounds memory; independent of the thread count).
const BATCH: u64 = 256;

struct EnsembleJob<'a> {
    scene: &'a Scene,
    model: &'a Model,
    threads: usize,
    progress: &'a (dyn Fn(u64) + Sync),
    stop: &'a AtomicBool,
}

/// What the parallel part hands back: statistics, steady statistics, histogram statistics,
/// counts, ensembles merged.
type Merged = (Accumulator, Accumulator, Accumulator, Counts, u64);

impl EnsembleJob<'_> {
    fn run(self) -> Result<Merged, Error> {
        let (scene, model) = (self.scene, self.model);
        let ncol = names(scene).len();
        let width = scene.times.len() * ncol;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(self.threads)
            .build()
            .expect("thread pool");
        let first = scene.steady_from.unwrap_or(0);
        let steady_of = |row: &[f64]| -> Vec<f64> {
            let pts = scene.times.len() - first;
            (0..ncol)
                .map(|c| {
                    (first..scene.times.len())
                        .map(|ti| row[ti * ncol + c])
                        .sum::<f64>()
                        / pts as f64
                })
                .collect()
        };
        let hist_len = scene.extra_len();
        let mut total = Accumulator::new(width);
        let mut steady = Accumulator::new(ncol);
        let mut hist = Accumulator::new(hist_len);
        let mut counts = Counts::default();
        let mut streams = Streams::new(scene.seed);
        let m = scene.ensembles;
        let mut start = 0u64;
        while start < m {
            let last = (start + BATCH * CHUNK).min(m);
            let rngs: Vec<Xoshiro256PlusPlus> =
                (&mut streams).take((last - start) as usize).collect();
            // `None`: the chunk was skipped because the run was interrupted.
            type Chunk = Result<Option<(Accumulator, Accumulator, Accumulator, Counts)>, Error>;
            let chunks: Vec<Chunk> = pool.install(|| {
                rngs.par_chunks(CHUNK as usize)
                    .enumerate()
                    .map(|(ci, rs)| {
                        if self.stop.load(Ordering::Relaxed) {
                            return Ok(None);
                        }
                        let mut acc = Accumulator::new(width);
                        let mut st = Accumulator::new(ncol);
                        let mut hi = Accumulator::new(hist_len);
                        let mut cnt = Counts::default();
                        let mut particles = particle_buffer(model.n())?;
                        for (k, r) in rs.iter().enumerate() {
                            let e = start + ci as u64 * CHUNK + k as u64;
                            let (row, c) = run_ensemble(scene, model, r.clone(), &mut particles)
                                .map_err(|err| Error::Engine {
                                    ensemble: e,
                                    message: err.to_string(),
                                })?;
                            let (row, h) = row.split_at(width);
                            acc.push(row);
                            st.push(&steady_of(row));
                            hi.push(h);
                            cnt = cnt.add(&c);
                        }
                        (self.progress)(rs.len() as u64);
                        Ok(Some((acc, st, hi, cnt)))
                    })
                    .collect()
            });
            // Merge in ensemble order, and only an unbroken prefix: an interrupted run keeps
            // exactly what a full run with fewer ensembles would have.
            for (ci, ch) in chunks.into_iter().enumerate() {
                match ch? {
                    Some((a, st, h, c)) => {
                        total.merge(&a);
                        steady.merge(&st);
                        hist.merge(&h);
                        counts = counts.add(&c);
                    }
                    None => return Ok((total, steady, hist, counts, start + ci as u64 * CHUNK)),
                }
            }
            start = last;
        }
        Ok((total, steady, hist, counts, m))
    }
}

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
    let threads = if threads == 0 {
        rayon::current_num_threads()
    } else {
        threads
    };
    let start = Instant::now();
    let cpu0 = cpu_time::ProcessTime::try_now().ok();
    let model = scene
        .physics
        .validate()
        .map_err(|e| Error::Physics(e.to_string()))?;
    let (acc, st, hist, counts, ensembles) = EnsembleJob {
        scene,
        model: &model,
        threads,
        progress,
        stop,
    }
    .run()?;
    let mut at = 0;
    let mut take = |len: usize| {
        let a = hist.slice(at..at + len);
        at += len;
        a
    };
    let histogram = scene.histogram.map(|(k, radius)| (radius, take(k + 1)));
    let reduced = scene.reduced_histogram.map(|(k, c)| (c, take(k + 1)));
    let marginal = scene
        .marginal_histogram
        .map(|(axis, k, r)| (axis, r, take(k + 2), take(k + 2)));
    let steady = scene.steady_from.map(|first| SteadyStats {
        first,
        points: scene.times.len() - first,
        acc: st,
    });
    Ok(RunStats {
        times: scene.times.clone(),
        names: names(scene),
        acc,
        counts,
        ensembles,
        wall: start.elapsed(),
        cpu: cpu0.map_or(Duration::ZERO, |c| c.elapsed()),
        threads,
        steady,
        histogram,
        reduced,
        marginal,
    })
}
