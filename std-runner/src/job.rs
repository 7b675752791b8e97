//! A run of a scene as `gdsmc run` makes it, from the loaded scene to the written outputs: the
//! work check, the journal (continued when the same run left one), a shard, the MPI ranks, the
//! output set and the summary; and `gdsmc merge`. The command and the Python package both call
//! it. What the user sees of a run (a progress bar, Ctrl-C, where text goes) is the caller's,
//! through [`Watch`]; the job returns the text to show.

use crate::error::Error;
use crate::report::{self, charts::Formats, set::OutputSet};
use crate::run::{self, Journaled, RunStats, shard};
use crate::scene::{Scene, Sourced};
pub use crate::watch::{Quiet, Watch};
use gdsmc_theory::curves::for_scene;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A run as `gdsmc run` takes it.
#[derive(Clone, Debug)]
pub struct Job {
    /// The scene, with its file's text and overrides (the journal records them).
    pub source: Sourced,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Run even when the work estimate is above the limit.
    pub allow_long: bool,
    /// Run only shard K of S (`--shard K/S`), into a shard file for `gdsmc merge`.
    pub shard: Option<String>,
    /// The output directory (default: out/NAME, or out/NAME-shards for a shard).
    pub out: Option<PathBuf>,
    /// Start anew instead of continuing a journal of the same run.
    pub fresh: bool,
    /// Chart formats.
    pub format: Formats,
    /// Start every ensemble from this state file (`--initial-state`) instead of the scene's
    /// initial distribution.
    pub initial_state: Option<PathBuf>,
    /// Save every ensemble's particles at the last observation to this file (`--save-state`).
    pub save_state: Option<PathBuf>,
}

/// The refusal of a state file where a run is split (shards, MPI ranks): not yet supported.
fn state_refused(how: &str) -> Error {
    Error::Argument {
        flag: "--save-state/--initial-state/observe.snapshots".into(),
        message: format!(
            "are not supported with {how} yet: run the state's ensembles in one process"
        ),
    }
}

/// What a job did, for the caller to show.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The summary and the files written (the command's standard output).
    pub text: String,
    /// Whether every ensemble asked for is done; an interrupted job keeps what it finished
    /// (the same command continues it).
    pub complete: bool,
}

impl Job {
    /// The shard asked for, checked against the scene's ensembles.
    fn shard(&self) -> Result<Option<(u64, u64)>, Error> {
        let ensembles = self.source.scene.ensembles();
        self.shard
            .as_deref()
            .map(|spec| shard::parse_spec(spec, ensembles))
            .transpose()
    }

    /// Runs the job: the arguments and the work estimate are checked before anything is
    /// allocated or run, the output place before any simulation; finished ensembles are
    /// journaled as they finish (so a rerun of the same job continues), and the outputs are
    /// written when the run is complete or stopped. Under mpirun (the `mpi` feature) the
    /// ranks share the ensembles and rank 0 writes.
    pub fn run(&self, watch: &dyn Watch) -> Result<Outcome, Error> {
        let sc = &self.source.scene;
        let shard = self.shard()?;
        // Absurd work is refused before anything is allocated or run.
        let work = run::estimate::check(sc, self.threads, self.allow_long)?;
        let states =
            self.initial_state.is_some() || self.save_state.is_some() || !sc.snapshots().is_empty();
        if states && sc.model().weighted() {
            // A state file holds n equal particles (docs/state.md), not weights.
            return Err(state_refused("the weighted scheme"));
        }
        #[cfg(feature = "mpi")]
        if let Some(w) = run::mpi::World::init() {
            if states {
                return Err(state_refused("an MPI run"));
            }
            return self.mpi(&w, shard);
        }
        if let Some((k, s)) = shard {
            if states {
                return Err(state_refused("--shard"));
            }
            return self.run_shard(k, s, watch);
        }
        // The state files are checked before anything runs or is written.
        let initial = self
            .initial_state
            .as_deref()
            .map(run::state::StateReader::open)
            .transpose()?;
        if let Some(r) = &initial {
            r.check(sc)?;
            r.notes.iter().for_each(|n| watch.note(n));
        }
        // The output place is prepared (and shown writable) before any simulation.
        let dir = self.dir(sc.name());
        let file = run::journal::beside(&dir, run::journal::Of::Run);
        if let Some(p) = &self.save_state {
            run::state::check_place(p, &dir, &file)?;
        }
        let set = OutputSet::prepare(&dir)?;
        set.notes().iter().for_each(|n| watch.note(n));
        let save = self
            .save_state
            .as_deref()
            .map(|p| {
                let from = initial.as_ref().map(|r| &r.header);
                let header = run::state::StateHeader::of(sc, sc.ensembles(), from);
                run::state::StateWriter::create(p, header)
            })
            .transpose()?;
        let from = initial.as_ref().map(|r| &r.header);
        let snapshots = run::state::snapshot_writers(sc, set.dir(), sc.ensembles(), from)?;
        let io = run::StateIo {
            initial: initial.as_ref(),
            save: save.as_ref(),
            snapshots: &snapshots,
        };
        let r = self.journaled(&file, None, 0..sc.ensembles(), io, watch);
        let kept = r.as_ref().ok().map(|r| r.stats.ensembles);
        run::state::finish_all(snapshots, kept)?;
        // The state: renamed into place when the run is complete; an interrupted run's first
        // ensembles written beside, its partial file kept for the journal's continuation
        // (the same command takes both up); dropped when nothing is left to continue.
        let mut saved = None;
        let r = match (r, save) {
            (Ok(r), Some(w)) if r.stats.ensembles == sc.ensembles() => {
                saved = Some((w.path().to_path_buf(), r.stats.ensembles));
                w.finish(r.stats.ensembles)?;
                r
            }
            (r, Some(w)) => {
                if let Ok(r) = &r
                    && r.stats.ensembles > 0
                {
                    w.save_prefix(r.stats.ensembles)?;
                    saved = Some((w.path().to_path_buf(), r.stats.ensembles));
                }
                if !file.exists() {
                    w.abandon();
                }
                r?
            }
            (r, None) => r?,
        };
        let stats = r.stats;
        let complete = stats.ensembles == sc.ensembles();
        if !complete {
            watch.note(&if file.exists() {
                format!(
                    "kept {} of {} ensembles in {}: run the same command again to continue",
                    stats.ensembles,
                    sc.ensembles(),
                    file.display()
                )
            } else {
                format!(
                    "{} was removed while the run went: its {} finished ensembles cannot be \
                     continued by a rerun",
                    file.display(),
                    stats.ensembles
                )
            });
            if stats.ensembles == 0 {
                return Err(Error::Interrupted);
            }
        }
        // The references are solved from the scene's start: they hold for a continuation of
        // the scene's own process, not for other velocities.
        let refs = match &initial {
            Some(r) if !r.continues(sc) => {
                watch.note(
                    "note: the state file is not a sample of this scene's process (other \
                     physics or initial distribution): no reference is drawn or judged",
                );
                Vec::new()
            }
            _ => for_scene(sc),
        };
        let mut text = write_with(set, sc, &stats, &dir, self.format, &refs)?;
        if let Some((path, m)) = saved {
            let _ = writeln!(
                text,
                "wrote the state of {m} ensembles at t = {} into {}",
                sc.times()[sc.times().len() - 1],
                path.display()
            );
        }
        for (j, &ti) in sc.snapshots().iter().enumerate() {
            let name = run::state::snapshot_name(j);
            let _ = writeln!(text, "velocity snapshot at t = {}: {name}", sc.times()[ti]);
        }
        text.push_str(&work_line(work.total(), sc, &stats));
        if complete {
            // The outputs hold everything now; the journal is no longer needed.
            let _ = std::fs::remove_file(&file);
        }
        Ok(Outcome { text, complete })
    }

    /// The output directory: `--out`, or out/NAME.
    fn dir(&self, name: &str) -> PathBuf {
        self.out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out").join(name))
    }

    /// Runs ensembles `range` (shard `shard`, or the whole run) journaled in `file` (anew with
    /// `--fresh`), from and to the state files of `state`, and tells the watcher what the
    /// journal held.
    fn journaled(
        &self,
        file: &Path,
        shard: Option<(u64, u64)>,
        range: std::ops::Range<u64>,
        state: run::StateIo<'_>,
        watch: &dyn Watch,
    ) -> Result<run::JournalRun, Error> {
        let job = Journaled {
            scene: &self.source.scene,
            header: run::journal::Header::new(&self.source, shard, range.clone())
                .from_state(state.initial.map(|r| r.identity.clone())),
            path: file,
            threads: self.threads,
            fresh: self.fresh,
            state,
        };
        watch.begin(range.end - range.start);
        let r = job.run(&|k| watch.advance(k), watch.stop());
        watch.end();
        let r = r?;
        if let Some(why) = &r.discarded {
            watch.note(&format!(
                "note: {} was not continued ({why}); started anew",
                file.display()
            ));
        } else if r.resumed > 0 {
            watch.note(&format!(
                "continued {}: {} ensembles were already done",
                file.display(),
                r.resumed
            ));
        }
        if let Some(why) = &r.damage {
            watch.note(&format!(
                "note: {} was cut after its last good record ({why}); the ensembles after it were run again",
                file.display()
            ));
        }
        Ok(r)
    }

    /// Runs shard `k` of `s` into its shard file.
    fn run_shard(&self, k: u64, s: u64, watch: &dyn Watch) -> Result<Outcome, Error> {
        let sc = &self.source.scene;
        let range = shard::range(k, s, sc.ensembles());
        let dir = self.dir(&format!("{}-shards", sc.name()));
        std::fs::create_dir_all(&dir).map_err(|source| Error::Write {
            path: dir.clone(),
            source,
        })?;
        let file = dir.join(shard::file_name(sc.name(), k, s));
        let r = self.journaled(
            &file,
            Some((k, s)),
            range.clone(),
            Default::default(),
            watch,
        )?;
        let done = r.stats.ensembles;
        let complete = done == range.end - range.start;
        if !complete {
            watch.note("run the same command again to finish the shard");
        }
        let text = format!(
            "shard {k}/{s} of {}: ensembles {}..{} ({} run now, {} continued from the file), wall = {:.2} s\n{} {}\n",
            sc.name(),
            range.start,
            range.start + done,
            done - r.resumed,
            r.resumed,
            r.stats.wall.as_secs_f64(),
            if complete { "wrote" } else { "kept so far in" },
            file.display()
        );
        Ok(Outcome { text, complete })
    }

    /// `mpirun -n P gdsmc run SCENE`: rank r runs shard r of P, rank 0 merges and writes.
    /// The other ranks return an empty outcome.
    #[cfg(feature = "mpi")]
    fn mpi(&self, w: &run::mpi::World, shard: Option<(u64, u64)>) -> Result<Outcome, Error> {
        if shard.is_some() {
            return Err(Error::Argument {
                flag: "--shard".into(),
                message: "not under mpirun: the ranks are the shards".into(),
            });
        }
        let sc = &self.source.scene;
        let dir = self.dir(sc.name());
        let started = std::time::Instant::now();
        let mut text = String::new();
        run::mpi::run(
            w,
            sc,
            |sh, range| run::journal::Header::new(&self.source, Some(sh), range),
            &dir,
            self.threads,
            || report::set::check_replaceable(&dir),
            |m| {
                let set = OutputSet::prepare(&dir)?;
                let notes = set.notes().join("\n");
                text = write(set, &m.scene, &m.stats, &dir, self.format)?;
                if !notes.is_empty() {
                    text = format!("{notes}\n{text}");
                }
                let _ = writeln!(
                    text,
                    "{} MPI ranks, {} ensembles, {:.2} s from start to merged outputs",
                    m.shards,
                    m.stats.ensembles,
                    started.elapsed().as_secs_f64()
                );
                Ok(())
            },
        )?;
        Ok(Outcome {
            text,
            complete: true,
        })
    }
}

/// `gdsmc merge`: the shard files in `inputs` (files, or directories holding them) merged into
/// the outputs of the whole run, written into `out` (default out/NAME). Returns the text to
/// show.
pub fn merge(inputs: &[PathBuf], out: Option<PathBuf>, format: Formats) -> Result<String, Error> {
    let files = shard::files(inputs)?;
    // A given output place is checked before the shards are read.
    if let Some(o) = &out {
        shard::check_output(o, &files)?;
        report::set::check_replaceable(o)?;
    }
    let started = std::time::Instant::now();
    let m = shard::merge_files(&files)?;
    let merge_s = started.elapsed().as_secs_f64();
    let dir = out.unwrap_or_else(|| PathBuf::from("out").join(m.scene.name()));
    shard::check_output(&dir, &files)?;
    let set = OutputSet::prepare(&dir)?;
    let notes: String = set.notes().iter().map(|n| format!("{n}\n")).collect();
    let mut text = notes + &write(set, &m.scene, &m.stats, &dir, format)?;
    let _ = writeln!(
        text,
        "merged {} shards ({} ensembles) in {merge_s:.3} s; wall and cpu above: the slowest shard's wall, all shards' cpu",
        m.shards, m.stats.ensembles
    );
    Ok(text)
}

/// Writes a run's outputs into the prepared set `set` (at `dir`): the tables, summary.json
/// and the charts in `format`, with every reference that applies. Returns the summary and the
/// list of files written, as the command prints them.
pub fn write(
    set: OutputSet,
    scene: &Scene,
    stats: &RunStats,
    dir: &Path,
    format: Formats,
) -> Result<String, Error> {
    write_with(set, scene, stats, dir, format, &for_scene(scene))
}

/// [`write`] with the references `refs`.
fn write_with(
    set: OutputSet,
    scene: &Scene,
    stats: &RunStats,
    dir: &Path,
    format: Formats,
    refs: &[gdsmc_theory::curves::ReferenceCurve],
) -> Result<String, Error> {
    let files = report::commit_run(set, scene, stats, refs, format)?;
    let mut text = report::summary::text(scene, stats, refs);
    text.push_str(&wrote(&files, dir));
    Ok(text)
}

/// The line that ends a command's output: the files written into `dir`.
pub fn wrote(files: &[String], dir: &Path) -> String {
    format!(
        "\nwrote {} files into {}: {}\n",
        files.len(),
        dir.display(),
        files.join(", ")
    )
}

/// Writes a run's outputs into the prepared set, with every reference that applies; returns
/// the files written.
pub fn commit(
    set: OutputSet,
    scene: &Scene,
    stats: &RunStats,
    format: Formats,
) -> Result<Vec<String>, Error> {
    report::commit_run(set, scene, stats, &for_scene(scene), format)
}

/// The summary's last line: the work estimated before the run (`estimated`, events and
/// particle updates) beside the work done.
pub fn work_line(estimated: f64, scene: &Scene, stats: &RunStats) -> String {
    format!(
        "work estimated before the run: {:.1e} events and particle updates ({:.1e} done)\n",
        estimated,
        stats.counts.candidates as f64 + stats.counts.kicks(scene.n()) as f64
    )
}
