//! `gdsmc sweep`: a parameter study in one command. The base scene with one or several keys
//! varied ([`vary`]: lists, linear and logarithmic ranges, a grid or zipped), every point
//! validated as a file is before anything runs ([`point`]), then run one after another, each
//! on all threads and journaled beside the output directory as `gdsmc run` journals a run
//! (`.NAME.point-K.gdsmc-ensembles`, a name no run's journal has), so an interrupted sweep continues where it stopped and
//! gives the same bytes. Each point's window averages (the steady window, or the last
//! observation) with their 99.9% intervals and every reference that applies there go into
//! sweep.csv and sweep.json ([`table`]), written as one output set.
//!
//! Point `k` runs with the seed `run.seed + k` (unless `run.seed` is varied): the points are
//! independent samples, and point `k` is the run `gdsmc run SCENE --set KEY=VALUE ...
//! --seed SEED+k` to the last bit.

pub mod chart;
#[cfg(feature = "mpi")]
mod mpi;
mod output;
pub mod point;
mod shard;
mod spec;
pub mod table;
pub mod verdict;
pub mod words;

pub use crate::scene::vary;
pub use spec::Sweep;
pub(crate) use spec::point_journal;

use crate::error::Error;
use crate::job::{Outcome, Watch};
use crate::report::set::OutputSet;
use crate::run::{self, Journaled, estimate};
use crate::scene::Sourced;
use output::{ensembles_words, one_ensemble_notes, summary, write};
use point::{PointResult, PointScene};
use shard::{merged_point, point_shard_journals, stale_shards};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What running a sweep's points gave.
#[derive(Debug)]
pub struct Ran {
    /// The finished points' results, in order.
    pub results: Vec<PointResult>,
    /// Notes about journals not continued or cut.
    pub notes: Vec<String>,
    /// Ensembles taken from journals rather than run.
    pub resumed: u64,
}

/// What a sweep of `source` varies: the `--vary` texts `vary` (a grid, or zipped when `zip`),
/// or, when there are none, the scene file's `[sweep]` table.
pub fn plan(source: &Sourced, vary: &[String], zip: bool) -> Result<vary::Plan, Error> {
    let argument = |message: String| Error::Argument {
        flag: "--vary".into(),
        message,
    };
    if vary.is_empty() {
        return crate::scene::sweep_plan(&source.path, &source.text)?.ok_or_else(|| {
            argument(format!(
                "is required: {} has no [sweep] table saying what varies",
                source.path.display()
            ))
        });
    }
    Ok(vary::Plan {
        vary: vary
            .iter()
            .map(|v| vary::Vary::parse(v))
            .collect::<Result<_, _>>()
            .map_err(argument)?,
        combine: if zip {
            vary::Combine::Zip
        } else {
            vary::Combine::Grid
        },
    })
}

impl Sweep {
    /// Every point's validated scene, in order. A key both set (`--set`, `--n`, ...) and
    /// varied is refused, as is a point whose values break a rule (naming the point).
    pub fn points(&self) -> Result<Vec<PointScene>, Error> {
        let points = vary::points(&self.vary, self.combine).map_err(|message| Error::Argument {
            flag: "--vary".into(),
            message,
        })?;
        for v in &self.vary {
            let probe = crate::scene::Override::set(format!("{}=0", v.key));
            if let Some(o) = self.source.overrides.iter().find(|o| o.overlaps(&probe)) {
                return Err(Error::Argument {
                    flag: "--vary".into(),
                    message: format!(
                        "varies {} which {} also sets ({}): give it once",
                        v.key, o.source, o.assignment
                    ),
                });
            }
        }
        points
            .into_iter()
            .enumerate()
            .map(|(k, values)| PointScene::new(&self.source, k, values))
            .collect()
    }

    /// The output directory: `--out`, or out/NAME-sweep.
    pub fn dir(&self) -> PathBuf {
        self.out.clone().unwrap_or_else(|| {
            PathBuf::from("out").join(format!("{}-sweep", self.source.scene.name()))
        })
    }

    /// Every point's scene ([`Sweep::points`]), each point's sizes checked against their
    /// limits and the work summed over the points against the work limit (unless
    /// `allow_long`): what is checked before anything runs.
    pub fn checked_points(&self) -> Result<Vec<PointScene>, Error> {
        let points = self.points()?;
        let mut work = 0.0;
        for p in &points {
            work += estimate::check(&p.source.scene, self.threads, true)?.total();
        }
        if !self.allow_long && (work.is_nan() || work > estimate::MAX_WORK) {
            return Err(Error::Argument {
                flag: "--vary".into(),
                message: format!(
                    "gives {} points asking for about {work:.1e} events and particle updates in all, above the limit {:.0e} (about a day of one core); fewer points, smaller runs, or pass --allow-long",
                    points.len(),
                    estimate::MAX_WORK
                ),
            });
        }
        Ok(points)
    }

    /// Runs `points` in order, journaled beside `journals` (the output directory) when given,
    /// else in memory (the Python package's sweep); stops at the first point the watcher's
    /// stop flag cuts short. Returns the finished points' results and the notes about
    /// journals not continued or cut.
    pub fn run_points(
        &self,
        points: &[PointScene],
        journals: Option<&Path>,
        watch: &dyn Watch,
    ) -> Result<Ran, Error> {
        let total: u64 = points.iter().map(|p| p.source.scene.ensembles()).sum();
        watch.begin(total);
        let mut results = Vec::new();
        let mut notes = Vec::new();
        if points
            .iter()
            .any(|p| !p.source.scene.snapshots().is_empty())
        {
            notes.push(
                "note: a sweep takes no velocity snapshots (observe.snapshots): run a point \
                 with `gdsmc run` for them"
                    .to_string(),
            );
        }
        let mut resumed = 0;
        for p in points {
            let sc = &p.source.scene;
            let named = |e: Error| match e {
                Error::Interrupted => e,
                e => Error::Point {
                    index: p.index,
                    values: p.words(),
                    source: Box::new(e),
                },
            };
            // A point split over `--shard` tasks is merged from their journals, unless the
            // sweep starts anew (`--fresh`) or the journals are another sweep's (a note says
            // so; they are removed with the point's journal when the sweep is written).
            let shards = match journals {
                Some(dir) if !self.fresh => point_shard_journals(dir, p.index),
                _ => Vec::new(),
            };
            let stale = (!shards.is_empty())
                .then(|| stale_shards(p, &shards))
                .flatten();
            if let Some(why) = &stale {
                notes.push(format!(
                    "note: the shard journals of point {} ({}, ...) were not merged ({why}); the point runs anew",
                    p.index,
                    shards[0].display()
                ));
            }
            let stats = match journals {
                Some(_) if !shards.is_empty() && stale.is_none() => {
                    // The point was split over shards (`--shard` with more shards than
                    // points): their journals, merged as `gdsmc merge` merges a run's.
                    let merged = match merged_point(p, &shards) {
                        Ok(m) => m,
                        Err(e) => {
                            watch.end();
                            return Err(e);
                        }
                    };
                    watch.advance(merged.ensembles);
                    resumed += merged.ensembles;
                    merged
                }
                Some(dir) => {
                    let file = point_journal(dir, p.index);
                    let job = Journaled {
                        scene: sc,
                        header: run::journal::Header::new(&p.source, None, 0..sc.ensembles()),
                        path: &file,
                        threads: self.threads,
                        fresh: self.fresh,
                        state: Default::default(),
                    };
                    let r = job.run(&|k| watch.advance(k), watch.stop());
                    let r = match r {
                        Ok(r) => r,
                        Err(e) => {
                            watch.end();
                            return Err(named(e));
                        }
                    };
                    if let Some(why) = &r.discarded {
                        notes.push(format!(
                            "note: {} was not continued ({why}); started anew",
                            file.display()
                        ));
                    }
                    if let Some(why) = &r.damage {
                        notes.push(format!(
                            "note: {} was cut after its last good record ({why}); the ensembles after it were run again",
                            file.display()
                        ));
                    }
                    resumed += r.resumed;
                    r.stats
                }
                None => {
                    match run::run_interruptible(
                        sc,
                        self.threads,
                        &|k| watch.advance(k),
                        watch.stop(),
                    ) {
                        Ok(s) => s,
                        Err(e) => {
                            watch.end();
                            return Err(named(e));
                        }
                    }
                }
            };
            if stats.ensembles < sc.ensembles() {
                break; // stopped: a journaled point's finished ensembles stay in its journal
            }
            results.push(PointResult::of(p, &stats));
        }
        watch.end();
        Ok(Ran {
            results,
            notes,
            resumed,
        })
    }

    /// Runs the sweep: every point validated and the summed work checked before anything
    /// runs, the output place before any simulation; the points in order, each journaled as
    /// it runs; sweep.csv and sweep.json written at the end (or, when stopped, of the points
    /// finished, which a rerun keeps).
    ///
    /// With `--shard K/S`, only that task's points (or shards of points) run, journaled
    /// (`shard`); under mpirun (the `mpi` feature) rank r runs task r of the ranks and rank 0
    /// assembles (`mpi`).
    pub fn run(&self, watch: &dyn Watch) -> Result<Outcome, Error> {
        let points = self.checked_points()?;
        if let Some(spec) = &self.shard {
            let ks = run::shard::parse_spec(spec, u64::MAX)?;
            return self.shard_task(ks, points, watch);
        }
        #[cfg(feature = "mpi")]
        if let Some(w) = run::mpi::World::init() {
            return self.run_mpi(&w, points, watch);
        }
        self.assemble(points, watch)
    }

    /// The whole sweep in this process: the points in order, each taken from its journal (or
    /// its shards' journals) or run, and the outputs written.
    fn assemble(&self, points: Vec<PointScene>, watch: &dyn Watch) -> Result<Outcome, Error> {
        let dir = self.dir();
        let set = OutputSet::prepare(&dir)?;
        set.notes().iter().for_each(|n| watch.note(n));
        let Ran {
            results,
            notes,
            resumed,
        } = self.run_points(&points, Some(&dir), watch)?;
        for n in notes.iter().chain(&one_ensemble_notes(&results)) {
            watch.note(n);
        }
        let complete = results.len() == points.len();
        if !complete {
            watch.note(&format!(
                "kept {} of {} points (and the running point's finished ensembles) beside {}: run the same command again to continue",
                results.len(),
                points.len(),
                dir.display()
            ));
            if results.is_empty() {
                return Err(Error::Interrupted);
            }
        }
        let charts = chart::charts(&self.source, &self.vary, &points, &results);
        let files = write(set, self, complete, &results, &charts)?;
        if complete {
            // The outputs hold everything now; the journals are no longer needed.
            for p in &points {
                let _ = std::fs::remove_file(point_journal(&dir, p.index));
                for f in point_shard_journals(&dir, p.index) {
                    let _ = std::fs::remove_file(f);
                }
            }
        }
        let mut text = String::new();
        if resumed > 0 {
            let _ = writeln!(
                text,
                "continued  {resumed} ensembles taken from the points' journals (a stopped sweep, or its shards)"
            );
        }
        let _ = writeln!(
            text,
            "sweep      {} points of {} ({}), {}",
            points.len(),
            self.source.scene.name(),
            self.vary
                .iter()
                .map(|v| v.key.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            ensembles_words(&points)
        );
        text.push_str(&summary(&results));
        text.push_str(&verdict::text(&verdict::checks(&results)));
        text.push_str(&crate::job::wrote(&files, &dir));
        Ok(Outcome { text, complete })
    }
}
