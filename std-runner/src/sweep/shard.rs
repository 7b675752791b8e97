//! A sweep's shard tasks (`gdsmc sweep --shard K/S`, and each MPI rank's share): which
//! points, or shards of points, task K runs, each journaled beside the output directory where
//! the whole sweep (the same command without `--shard`) finds and merges them.

use super::point::PointScene;
use super::spec::{Sweep, point_journal, point_journal_of};
use crate::error::Error;
use crate::job::{Outcome, Watch};
use crate::run::{self, Journaled};
use std::path::{Path, PathBuf};

/// The shards of each point's ensembles that `s` tasks over `points` give (1 when there are
/// at most as many tasks as points).
pub(super) fn chunks(s: u64, points: &[PointScene]) -> u64 {
    s.div_ceil(points.len().max(1) as u64)
}

/// The units of task `k` of `s`: (point, shard of its ensembles), each point whole when
/// [`chunks`] is 1.
pub(super) fn units(
    k: u64,
    s: u64,
    points: &[PointScene],
) -> Vec<(&PointScene, Option<(u64, u64)>)> {
    let c = chunks(s, points);
    (0..points.len() as u64 * c)
        .filter(|u| u % s == k)
        .map(|u| (&points[(u / c) as usize], (c > 1).then_some((u % c, c))))
        .collect()
}

/// The journal files of task `k` of `s`'s units, beside the output directory `dir` (what an
/// MPI rank sends rank 0).
#[cfg(feature = "mpi")]
pub(super) fn journals(dir: &Path, k: u64, s: u64, points: &[PointScene]) -> Vec<PathBuf> {
    units(k, s, points)
        .into_iter()
        .map(|(p, chunk)| point_journal_of(dir, p.index, chunk))
        .collect()
}

impl Sweep {
    /// Runs shard `K/S` of the sweep, writing no outputs. With at most as many shards
    /// as points: the points with index `k mod S = K`, each journaled beside the output
    /// directory, where the whole sweep finds it. With more shards than points, each point's
    /// ensembles are split into `C = ceil(S / P)` shards as `gdsmc run --shard` splits a run's
    /// (same generators, so the merged point is the run to the last bit): unit `u = k C + c`
    /// (shard `c` of point `k`) goes to task `u mod S`, journaled as
    /// `.NAME.point-K-shard-c-of-C.gdsmc-ensembles`, and the whole sweep merges them.
    pub(super) fn shard_task(
        &self,
        (k, s): (u64, u64),
        points: Vec<PointScene>,
        watch: &dyn Watch,
    ) -> Result<Outcome, Error> {
        let chunks = chunks(s, &points);
        if chunks > 1 {
            let fewest = points
                .iter()
                .map(|p| p.source.scene.ensembles())
                .min()
                .unwrap_or(0);
            if fewest < chunks {
                return Err(Error::Argument {
                    flag: "--shard".into(),
                    message: format!(
                        "{k}/{s}: {s} shards of a sweep of {} points split each point's ensembles into {chunks} shards, more than the {fewest} ensembles a point has (run.ensembles); use at most {} shards",
                        points.len(),
                        points.len() as u64 * fewest
                    ),
                });
            }
        }
        let dir = self.dir();
        let parent = match dir.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        std::fs::create_dir_all(&parent).map_err(|source| Error::Write {
            path: parent.clone(),
            source,
        })?;
        if chunks > 1 {
            return self.run_point_shards(k, s, chunks, &points, &dir, watch);
        }
        let mine: Vec<PointScene> = points
            .into_iter()
            .filter(|p| p.index as u64 % s == k)
            .collect();
        let ran = self.run_points(&mine, Some(&dir), watch)?;
        for n in &ran.notes {
            watch.note(n);
        }
        let complete = ran.results.len() == mine.len();
        let indices: Vec<String> = mine.iter().map(|p| p.index.to_string()).collect();
        let text = format!(
            "shard {k}/{s} of the sweep of {}: points {} ({} of them done, {} ensembles continued from their journals) journaled beside {}\n",
            self.source.scene.name(),
            indices.join(", "),
            ran.results.len(),
            ran.resumed,
            dir.display()
        );
        Ok(shard_outcome(text, complete))
    }
}

impl Sweep {
    /// Task `k` of `s` when each point's ensembles are split into `chunks` shards (see
    /// [`Sweep::shard_task`]): runs its units in order, each journaled.
    fn run_point_shards(
        &self,
        k: u64,
        s: u64,
        chunks: u64,
        points: &[PointScene],
        dir: &Path,
        watch: &dyn Watch,
    ) -> Result<Outcome, Error> {
        let units: Vec<(&PointScene, u64)> = units(k, s, points)
            .into_iter()
            .map(|(p, chunk)| (p, chunk.map_or(0, |c| c.0)))
            .collect();
        let range = |p: &PointScene, c| run::shard::range(c, chunks, p.source.scene.ensembles());
        watch.begin(
            units
                .iter()
                .map(|&(p, c)| range(p, c).end - range(p, c).start)
                .sum(),
        );
        let (mut done, mut resumed) = (0, 0);
        for &(p, c) in &units {
            let file = point_journal_of(dir, p.index, Some((c, chunks)));
            let job = Journaled {
                scene: &p.source.scene,
                header: run::journal::Header::new(&p.source, Some((c, chunks)), range(p, c)),
                path: &file,
                threads: self.threads,
                fresh: self.fresh,
                state: Default::default(),
            };
            let r = match job.run(&|e| watch.advance(e), watch.stop()) {
                Ok(r) => r,
                Err(e) => {
                    watch.end();
                    return Err(e);
                }
            };
            if let Some(why) = &r.discarded {
                watch.note(&format!(
                    "note: {} was not continued ({why}); started anew",
                    file.display()
                ));
            }
            resumed += r.resumed;
            if r.stats.ensembles < range(p, c).end - range(p, c).start {
                break;
            }
            done += 1;
        }
        watch.end();
        let complete = done == units.len();
        let names: Vec<String> = units
            .iter()
            .map(|(p, c)| format!("{}.{c}", p.index))
            .collect();
        let text = format!(
            "shard {k}/{s} of the sweep of {}: each point's ensembles in {chunks} shards; point.shard {} ({done} of them done, {resumed} ensembles continued from their journals) journaled beside {}\n",
            self.source.scene.name(),
            names.join(", "),
            dir.display()
        );
        Ok(shard_outcome(text, complete))
    }
}

/// A shard task's outcome: its `text` and what to do next.
fn shard_outcome(mut text: String, complete: bool) -> Outcome {
    text.push_str(if complete {
        "when every shard is done, the same command without --shard writes the sweep from the journals\n"
    } else {
        "run the same command again to finish the shard\n"
    });
    Outcome { text, complete }
}
/// The shard journals of point `k` beside `dir` (`--shard` with more shards than points),
/// sorted by name; none when the point was not split. Only names [`point_journal_of`] gives
/// (`...point-K-shard-c-of-C.gdsmc-ensembles`, c and C numbers) are taken.
pub(super) fn point_shard_journals(dir: &Path, k: usize) -> Vec<PathBuf> {
    let Some(parent) = point_journal(dir, k).parent().map(Path::to_path_buf) else {
        return Vec::new();
    };
    let name = dir
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy().into_owned());
    let prefix = format!(".{name}.point-{k}-shard-");
    let suffix = format!(".{}", run::journal::EXTENSION);
    let numbers = |t: &str| !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit());
    let mut found: Vec<PathBuf> = std::fs::read_dir(parent)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| e.path())
        .filter(|f| {
            f.file_name().is_some_and(|n| {
                let n = n.to_string_lossy();
                n.strip_prefix(&prefix)
                    .and_then(|r| r.strip_suffix(&suffix))
                    .and_then(|r| r.split_once("-of-"))
                    .is_some_and(|(c, n)| numbers(c) && numbers(n))
            })
        })
        .collect();
    found.sort();
    found
}

/// Why the shard journals `files` of point `p` are another sweep's (their header is not a
/// shard of this point's run), or `None` when they are this point's (complete or not: an
/// unfinished task is then reported by the merge).
pub(super) fn stale_shards(p: &PointScene, files: &[PathBuf]) -> Option<String> {
    let bytes = run::journal::read_file(&files[0]).ok()?;
    let header = run::journal::read(&files[0], &bytes).ok()?.header;
    let want = shard_header(p, header.shard?.1);
    (!want.same_set(&header)).then(|| header.difference(&want))
}

/// The header of shard 0 of `s` of point `p`'s run: what every shard of it must match but for
/// its index ([`run::journal::Header::same_set`]).
fn shard_header(p: &PointScene, s: u64) -> run::journal::Header {
    run::journal::Header::new(
        &p.source,
        Some((0, s)),
        run::shard::range(0, s, p.source.scene.ensembles()),
    )
}

/// Point `p`'s statistics from the journals of its shards: one whole run of exactly its
/// scene and seed (else the error names the files and what is missing or different).
pub(super) fn merged_point(p: &PointScene, files: &[PathBuf]) -> Result<run::RunStats, Error> {
    let merged = run::shard::merge_files(files).map_err(|e| {
        Error::Shards(format!(
            "point {} of the sweep, split over the --shard tasks: {e}; run the missing or unfinished tasks (gdsmc sweep ... --shard K/S) again",
            p.index
        ))
    })?;
    let first = run::journal::read_file(&files[0])?;
    let header = run::journal::read(&files[0], &first)?.header;
    let want = shard_header(p, merged.shards);
    if !want.same_set(&header) {
        return Err(Error::Shards(format!(
            "{} is not a shard of point {} of this sweep: it is {}",
            files[0].display(),
            p.index,
            header.difference(&want)
        )));
    }
    Ok(merged.stats)
}
