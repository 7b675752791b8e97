//! Ensembles: many independent particle systems of one scene, run in parallel.
//!
//! Ensemble `k` uses the seed's Xoshiro256++ generator jumped `k` times. Workers take the next
//! ensemble as they finish one; the finished ensembles are folded into the statistics in
//! ensemble order ([`totals::Totals`]), so the statistics are bit-identical for any number of
//! threads, and for shards merged ([`shard`]) or a run resumed from its journal ([`journal`]).
//!
//! The engine is composed at compile time: the core's [`Model::start`] turns the scene's
//! physics into one statically composed event loop per ensemble.

pub mod collisional;
pub mod columns;
pub mod cooling;
pub mod ensemble;
pub mod estimate;
pub mod journal;
mod memory;
#[cfg(feature = "mpi")]
pub mod mpi;
pub mod pages;
pub mod results;
pub mod shard;
pub mod state;
pub mod stepped;
pub mod totals;

pub use ensemble::{
    StateIo, SystemBuffer, particle_buffer, run_ensemble, run_on_buffer, system_buffer,
};
pub use memory::{run, run_in_memory, run_interruptible, run_with_samples};
pub use results::{MarginalHistogram, RunStats, ShellHistogram, SteadyStats};

use crate::error::Error;
use crate::scene::Scene;
use columns::names;
use gdsmc_core::engine::Counts;
use gdsmc_core::physics::Model;
use gdsmc_core::rng::{Streams, Xoshiro256PlusPlus};
use journal::{Header, Timing};
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;
use totals::Totals;

/// Ensembles handed to the workers at once (bounds the generators held; independent of the
/// thread count).
const BATCH: u64 = 256;

/// The part of a run the workers share.
struct EnsembleJob<'a> {
    scene: &'a Scene,
    model: &'a Model,
    threads: usize,
    progress: &'a (dyn Fn(u64) + Sync),
    stop: &'a AtomicBool,
    state: StateIo<'a>,
}

/// What sees each finished ensemble (index, row, counts) before it is folded: the journal.
type OnRow<'a> = dyn FnMut(u64, &[f64], &Counts) -> Result<(), Error> + 'a;

/// A finished ensemble as a worker hands it back.
type Done = Result<(Vec<f64>, Counts), Error>;

impl EnsembleJob<'_> {
    /// Runs ensembles `range` (ensemble k from the seed's generator jumped k times), folding
    /// each into `totals` in ensemble order and handing it to `on_row` first (the journal).
    /// Workers take the next ensemble as they finish one, so the finished ensembles form a
    /// prefix up to the few still running; on `stop` the running ones finish and the fold
    /// keeps the unbroken prefix: exactly what a run of fewer ensembles would have.
    fn fold(
        &self,
        range: std::ops::Range<u64>,
        totals: &mut Totals,
        on_row: &mut OnRow,
    ) -> Result<(), Error> {
        let mut streams = Streams::new(self.scene.seed());
        for _ in 0..range.start {
            streams.next();
        }
        let halt = AtomicBool::new(false);
        let before = totals.ensembles;
        let mut start = range.start;
        while start < range.end {
            let last = (start + BATCH).min(range.end);
            let rngs: Vec<Xoshiro256PlusPlus> =
                (&mut streams).take((last - start) as usize).collect();
            let next = AtomicUsize::new(0);
            let mut failed = None;
            let mut pending = BTreeMap::new();
            let mut k = 0usize;
            // Folds the finished prefix of the batch in ensemble order.
            let mut take = |i: usize, done: Done| {
                pending.insert(i, done);
                while let Some(done) = pending.remove(&k) {
                    let e = start + k as u64;
                    let folded = done.and_then(|(row, c)| {
                        on_row(e, &row, &c)?;
                        totals.push(&row, &c);
                        Ok(())
                    });
                    if let Err(err) = folded {
                        halt.store(true, Ordering::SeqCst);
                        failed.get_or_insert(err);
                        pending.clear();
                        break;
                    }
                    k += 1;
                }
            };
            if self.threads <= 1 {
                // One thread: each ensemble run and folded on this one (a browser has no
                // threads to spawn), so the journal holds each as soon as it is done.
                let mut particles = None;
                for (i, rng) in rngs.iter().enumerate() {
                    if self.stop.load(Ordering::Relaxed) || halt.load(Ordering::Relaxed) {
                        break;
                    }
                    let done = self.one(start + i as u64, rng, &mut particles);
                    (self.progress)(1);
                    take(i, done);
                }
            } else {
                let (tx, rx) = mpsc::channel::<(usize, Done)>();
                std::thread::scope(|s| {
                    for _ in 0..self.threads.min(rngs.len()) {
                        let (tx, rngs, next, halt) = (tx.clone(), &rngs, &next, &halt);
                        s.spawn(move || self.work(start, rngs, next, halt, tx));
                    }
                    drop(tx);
                    for (i, done) in rx {
                        take(i, done);
                    }
                });
            }
            if let Some(err) = failed {
                return Err(err);
            }
            if totals.ensembles - before < last - range.start {
                return Ok(()); // interrupted: the unbroken prefix is kept
            }
            start = last;
        }
        Ok(())
    }

    /// Ensemble `k` from its generator, on the worker's particle buffer (made at its first).
    fn one(
        &self,
        k: u64,
        rng: &Xoshiro256PlusPlus,
        particles: &mut Option<ensemble::SystemBuffer>,
    ) -> Done {
        run_on_buffer(
            self.scene,
            self.model,
            rng.clone(),
            particles,
            (k, &self.state),
        )
    }

    /// One worker: takes the next ensemble of the batch until none is left or the run stops.
    fn work(
        &self,
        start: u64,
        rngs: &[Xoshiro256PlusPlus],
        next: &AtomicUsize,
        halt: &AtomicBool,
        tx: mpsc::Sender<(usize, Done)>,
    ) {
        let mut particles = None;
        loop {
            if self.stop.load(Ordering::Relaxed) || halt.load(Ordering::Relaxed) {
                return;
            }
            let i = next.fetch_add(1, Ordering::Relaxed);
            let Some(rng) = rngs.get(i) else { return };
            let done = self.one(start + i as u64, rng, &mut particles);
            (self.progress)(1);
            if tx.send((i, done)).is_err() {
                return;
            }
        }
    }
}

/// Refuses a `steady_from` (a public index) set by hand past the scene's times, before anything
/// runs.
fn check_steady(scene: &Scene) -> Result<(), Error> {
    if let Some(k) = scene.steady_from()
        && k + 2 > scene.times().len()
    {
        return Err(Error::Argument {
            flag: "steady_from".to_string(),
            message: format!(
                "observation {k} leaves fewer than two of the scene's {} observation times at or \
                 after it",
                scene.times().len()
            ),
        });
    }
    Ok(())
}

/// Runs `f` with the job of the scene's ensembles (on the scene's validated model).
fn job<T>(
    scene: &Scene,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
    stop: &AtomicBool,
    state: StateIo<'_>,
    f: impl FnOnce(&EnsembleJob) -> Result<T, Error>,
) -> Result<T, Error> {
    check_steady(scene)?;
    f(&EnsembleJob {
        scene,
        model: scene.model(),
        threads,
        progress,
        stop,
        state,
    })
}

/// Wall and CPU time of a run from its start.
struct Clock {
    watch: crate::clock::Stopwatch,
    threads: usize,
}

impl Clock {
    fn start(threads: usize) -> Self {
        let threads = if threads == 0 {
            std::thread::available_parallelism().map_or(1, |n| n.get())
        } else {
            threads
        };
        Clock {
            watch: crate::clock::Stopwatch::start(),
            threads,
        }
    }

    fn timing(&self) -> Timing {
        Timing {
            wall: self.watch.wall(),
            cpu: self.watch.cpu(),
            threads: self.threads as u64,
        }
    }
}

/// A run that keeps every finished ensemble in a journal file (resumable, mergeable): the
/// ensembles `header.start..header.end` of the scene.
pub struct Journaled<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// What the journal is of (see [`journal::Header`]).
    pub header: Header,
    /// The journal file.
    pub path: &'a Path,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Start anew even when the journal holds finished ensembles of this run.
    pub fresh: bool,
    /// The state files it starts from and saves to (none: from the scene, nothing saved).
    pub state: StateIo<'a>,
}

/// What a journaled run found and did.
#[derive(Clone, Debug)]
pub struct JournalRun {
    /// The statistics of the ensembles in the journal (all of its range unless interrupted).
    pub stats: RunStats,
    /// Ensembles taken from the journal rather than run.
    pub resumed: u64,
    /// Why an existing journal was not continued, when one was there.
    pub discarded: Option<String>,
    /// Why the journal continued was cut short (damage, or records of another run after its
    /// last good record), when it was: those ensembles were run again.
    pub damage: Option<String>,
}

impl Journaled<'_> {
    /// Runs the ensembles not yet in the journal, appending each as it finishes, and writes
    /// the end record when the range is complete. A journal of the same run (same scene to the
    /// last bit, seed, ensembles, shard and gdsmc version) is continued unless `fresh`;
    /// the result is bit-identical to an uninterrupted run because the fold is the same.
    pub fn run(
        &self,
        progress: &(dyn Fn(u64) + Sync),
        stop: &AtomicBool,
    ) -> Result<JournalRun, Error> {
        let scene = self.scene;
        let clock = Clock::start(self.threads);
        let mut totals = Totals::new(scene);
        let mut discarded = None;
        let (mut writer, bytes) = journal::Writer::open(self.path)?;
        let mut kept = None;
        let mut damage = None;
        match bytes {
            Ok(b) if self.fresh || b.is_empty() => {}
            Ok(b) => match journal::read(self.path, &b) {
                Ok(c) if c.header.same_run(&self.header) => {
                    for (row, counts) in &c.rows {
                        totals.push(row, counts);
                    }
                    kept = Some(c.valid_len);
                    // Bytes after the last good record are cut off: say why.
                    if c.valid_len < b.len() as u64 {
                        damage = c.damage;
                    }
                }
                Ok(c) => discarded = Some(c.header.difference(&self.header)),
                Err(e) => discarded = Some(e.to_string()),
            },
            Err(why) if !self.fresh => discarded = Some(why),
            Err(_) => {}
        }
        // The journal's ensembles are taken only when every state file the run writes holds
        // their records (written before each was journaled): else the particles they ended
        // with are lost, and the run starts anew.
        if kept.is_some() {
            let writers = self.state.save.into_iter().chain(self.state.snapshots);
            let done = self.header.start..self.header.start + totals.ensembles;
            if let Some(w) = writers
                .into_iter()
                .find(|w| !done.clone().all(|k| w.holds(k)))
            {
                discarded = Some(format!(
                    "the particles of its {} finished ensembles are not all in {}",
                    totals.ensembles,
                    crate::run::state::partial_of(w.path()).display()
                ));
                totals = Totals::new(scene);
                kept = None;
                damage = None;
            }
        }
        match kept {
            Some(len) => writer.keep(len)?,
            None => writer.restart(&self.header)?,
        }
        let resumed = totals.ensembles;
        progress(resumed);
        let range = self.header.start + resumed..self.header.end;
        let key = self.header.key();
        let ran = job(scene, clock.threads, progress, stop, self.state, |job| {
            job.fold(range, &mut totals, &mut |e, row, c| {
                writer.append(&journal::ensemble_record(key, e, row, c))
            })
        });
        if let Err(e) = ran {
            // A journal with no finished ensemble holds nothing to continue: it goes.
            if totals.ensembles == 0 {
                drop(writer);
                let _ = std::fs::remove_file(self.path);
            }
            return Err(e);
        }
        let timing = clock.timing();
        if totals.ensembles == self.header.end - self.header.start {
            writer.append(&journal::end_record(key, totals.ensembles, timing))?;
        }
        Ok(JournalRun {
            stats: stats_of(scene, totals, timing),
            resumed,
            discarded,
            damage,
        })
    }
}

/// A run's statistics from its fold and timing.
pub fn stats_of(scene: &Scene, totals: Totals, timing: Timing) -> RunStats {
    let Totals {
        acc,
        steady: st,
        hist,
        tail,
        counts,
        ensembles,
        ..
    } = totals;
    let mut at = 0;
    let mut take = |len: usize| {
        let a = hist.slice(at..at + len);
        at += len;
        a
    };
    let mut shells = |h: crate::scene::Shells| ShellHistogram {
        radius: h.radius,
        weights: take(h.weights()),
    };
    let histogram = scene.histogram().map(&mut shells);
    let reduced = scene.reduced_histogram().map(&mut shells);
    let marginal = scene.marginal_histogram().map(|h| MarginalHistogram {
        axis: h.axis,
        radius: h.radius,
        first: take(h.weights()),
        last: take(h.weights()),
    });
    let steady = scene.steady_from().map(|first| SteadyStats {
        first,
        points: scene.times().len() - first,
        acc: st,
    });
    RunStats {
        dimension: scene.dimension(),
        times: scene.times().to_vec(),
        names: names(scene),
        acc,
        counts,
        ensembles,
        wall: Duration::from_secs_f64(timing.wall.max(0.0)),
        cpu: Duration::from_secs_f64(timing.cpu.max(0.0)),
        threads: timing.threads as usize,
        steady,
        histogram,
        reduced,
        reduced_tail: tail,
        marginal,
    }
}
