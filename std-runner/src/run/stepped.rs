//! A run advanced a few ensembles at a time on the caller's thread: the browser's worker
//! (web/), which must return to its event loop between steps to hear "stop" and to draw the
//! statistics so far. The ensembles are the same (ensemble `k` from the seed's stream jumped
//! `k` times) and are folded in the same order, so its statistics are the command's to the bit.

use super::journal::Timing;
use super::{SystemBuffer, Totals, check_steady, run_ensemble, stats_of, system_buffer};
use crate::Error;
use crate::clock::Stopwatch;
use crate::run::{RunStats, StateIo};
use crate::scene::Scene;
use gdsmc_core::rng::Streams;

/// A run of a scene's ensembles, advanced by [`Stepped::advance`].
pub struct Stepped {
    scene: Scene,
    streams: Streams,
    totals: Totals,
    particles: Option<SystemBuffer>,
    /// Seconds of wall and CPU time spent in [`Stepped::advance`].
    busy: (f64, f64),
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
            let model = self.scene.model();
            let buf = match &mut self.particles {
                Some(buf) => buf,
                None => self.particles.insert(system_buffer(model)?),
            };
            let (row, counts) =
                run_ensemble(&self.scene, model, rng, buf, (e, &StateIo::default()))?;
            self.totals.push(&row, &counts);
        }
        Ok(self.done())
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
