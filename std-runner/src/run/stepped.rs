//! A run advanced a few ensembles at a time on the caller's thread: the browser's worker
//! (web/), which must return to its event loop between steps to hear "stop" and to draw the
//! statistics so far. The ensembles are the same (ensemble `k` from the seed's stream jumped
//! `k` times) and are folded in the same order, so its statistics are the command's to the bit.

use super::journal::Timing;
use super::{SystemBuffer, Totals, check_steady, run_on_buffer, stats_of};
use crate::Error;
use crate::clock::Stopwatch;
use crate::run::{RunStats, StateIo};
use crate::scene::Scene;
use gdsmc_core::engine::Counts;
use gdsmc_core::rng::{Streams, Xoshiro256PlusPlus};

/// A run of a scene's ensembles, advanced by [`Stepped::advance`].
pub struct Stepped {
    scene: Scene,
    streams: Streams,
    totals: Totals,
    particles: Option<SystemBuffer>,
    /// Seconds of wall and CPU time spent in [`Stepped::advance`].
    busy: (f64, f64),
    /// For [`Stepped::run_one`]: the ensemble its streams give next, and those streams.
    alone: Option<(u64, Streams)>,
}

impl Stepped {
    /// A run of `scene` with no ensemble run yet. Refuses what the command refuses before it
    /// runs (a `steady_from` past the times); the work limit is [`crate::run::estimate::check`].
    pub fn new(scene: Scene) -> Result<Self, Error> {
        check_steady(&scene)?;
        Ok(Stepped {
            streams: Streams::new(scene.seed()),
            totals: Totals::new(&scene),
            particles: None,
            busy: (0.0, 0.0),
            alone: None,
            scene,
        })
    }

    /// The scene.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Ensembles finished and folded.
    #[must_use]
    pub fn done(&self) -> u64 {
        self.totals.ensembles
    }

    /// Runs and folds the next `k` ensembles (fewer at the scene's last); returns the number
    /// finished in all. An ensemble that fails ends the run with its error; the ones before it
    /// stay folded.
    pub fn advance(&mut self, k: u64) -> Result<u64, Error> {
        let watch = Stopwatch::start();
        let ran = self.run_to((self.done() + k).min(self.scene.ensembles()));
        self.busy.0 += watch.wall();
        self.busy.1 += watch.cpu();
        ran
    }

    /// Runs and folds the ensembles up to `end`.
    fn run_to(&mut self, end: u64) -> Result<u64, Error> {
        while self.done() < end {
            let e = self.done();
            let rng = self.streams.next().expect("the streams are endless");
            let (row, counts) = self.run_with(e, rng)?;
            self.totals.push(&row, &counts);
        }
        Ok(self.done())
    }

    /// Ensemble `e` from `rng` on this run's particle buffer.
    fn run_with(&mut self, e: u64, rng: Xoshiro256PlusPlus) -> Result<(Vec<f64>, Counts), Error> {
        let at = (e, &StateIo::default());
        run_on_buffer(
            &self.scene,
            self.scene.model(),
            rng,
            &mut self.particles,
            at,
        )
    }

    /// Runs ensemble `e` alone (from the seed's stream jumped `e` times) without folding it:
    /// the browser's helper workers run ensembles this way for the one that folds them
    /// ([`Stepped::push`]). Its time counts as this run's.
    pub fn run_one(&mut self, e: u64) -> Result<(Vec<f64>, Counts), Error> {
        let watch = Stopwatch::start();
        // The streams from the last ensemble run alone when `e` lies ahead of it (a helper is
        // handed increasing ensembles): a jump per ensemble between, not `e` of them.
        let (mut at, mut streams) = match self.alone.take() {
            Some((at, streams)) if at <= e => (at, streams),
            _ => (0, Streams::new(self.scene.seed())),
        };
        while at < e {
            streams.next();
            at += 1;
        }
        let rng = streams.next().expect("the streams are endless");
        self.alone = Some((e + 1, streams));
        let ran = self.run_with(e, rng);
        self.busy.0 += watch.wall();
        self.busy.1 += watch.cpu();
        ran
    }

    /// Folds the next ensemble (number [`Stepped::done`]) from its row and counts, as
    /// [`Stepped::run_one`] gave them elsewhere; the ensembles after it are then run from
    /// their own streams. Refuses a row of another length than this scene's.
    pub fn push(&mut self, row: &[f64], counts: &Counts) -> Result<u64, Error> {
        if row.len() != self.totals.row_len() {
            return Err(Error::Argument {
                flag: "ensemble".into(),
                message: format!(
                    "a row of {} values where this scene's ensembles give {}",
                    row.len(),
                    self.totals.row_len()
                ),
            });
        }
        self.totals.push(row, counts);
        self.streams.next();
        Ok(self.done())
    }

    /// Adds wall and CPU seconds spent for this run elsewhere (the browser's helper workers,
    /// timed by the page) to the time its statistics state.
    pub fn add_time(&mut self, wall: f64, cpu: f64) {
        self.busy.0 += wall;
        self.busy.1 += cpu;
    }

    /// The statistics of the ensembles finished so far (those of a run of that many); its
    /// timing is the time spent in [`Stepped::advance`] ([`crate::clock`]).
    #[must_use]
    pub fn stats(&self) -> RunStats {
        let timing = Timing {
            wall: self.busy.0,
            cpu: self.busy.1,
            threads: 1,
        };
        stats_of(&self.scene, self.totals.clone(), timing)
    }
}
