//! Shards: a run's ensembles split over processes or machines, and merged back into exactly
//! the single run's statistics.
//!
//! Shard K of S holds ensembles `[K M / S, (K + 1) M / S)` with the same jumped generators as
//! the single run; it is a finished journal ([`crate::run::journal`]). [`merge`] checks that a
//! set of shard files is one run, complete, undamaged, each shard once, and folds their rows in
//! ensemble order, the fold every run uses, so the outputs are byte-identical to `gdsmc run`'s.

use crate::error::Error;
use crate::run::journal::{self, Contents, EXTENSION, Timing};
use crate::run::totals::Totals;
use crate::run::{RunStats, stats_of};
use crate::scene::Scene;
use std::borrow::Cow;
use std::path::PathBuf;

/// Parses `K/S` (0 <= K < S) for a run of `ensembles` ensembles, which must be at least S (a
/// shard with no ensemble is refused: S above the ensemble count cannot be what was meant);
/// errors name the flag.
pub fn parse_spec(spec: &str, ensembles: u64) -> Result<(u64, u64), Error> {
    let bad = |message: String| Error::Argument {
        flag: "--shard".into(),
        message,
    };
    let (k, s) = spec
        .split_once('/')
        .ok_or_else(|| bad(format!("expected K/S (shard K of S, from 0), got `{spec}`")))?;
    let num = |x: &str| {
        x.trim()
            .parse::<u64>()
            .map_err(|_| bad(format!("expected K/S with whole numbers, got `{spec}`")))
    };
    let (k, s) = (num(k)?, num(s)?);
    if s == 0 || k >= s {
        return Err(bad(format!(
            "shard K of S needs 0 <= K < S, got {k}/{s} (shards count from 0)"
        )));
    }
    if s > ensembles {
        return Err(bad(format!(
            "{k}/{s}: {s} shards of a run of {ensembles} ensembles (run.ensembles) would leave \
             shards without an ensemble; use at most {ensembles} shards"
        )));
    }
    Ok((k, s))
}

pub use crate::run::journal::{file_name, range};

/// The ensemble files among `inputs`: each a file, or a directory whose visible
/// `*.gdsmc-ensembles` files are taken (sorted by name).
pub fn files(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, Error> {
    let mut out = Vec::new();
    for p in inputs {
        if p.is_dir() {
            let entries = std::fs::read_dir(p).map_err(|e| Error::Journal {
                path: p.clone(),
                message: format!("cannot read the directory: {e}"),
            })?;
            let mut found: Vec<PathBuf> = entries
                .flatten()
                .map(|e| e.path())
                .filter(|f| {
                    let name = f
                        .file_name()
                        .map_or(String::new(), |n| n.to_string_lossy().into_owned());
                    !name.starts_with('.') && name.ends_with(&format!(".{EXTENSION}"))
                })
                .collect();
            if found.is_empty() {
                return Err(Error::Shards(format!(
                    "{}: no shard files (*.{EXTENSION}) in it",
                    p.display()
                )));
            }
            found.sort();
            out.extend(found);
        } else if std::fs::symlink_metadata(p).is_ok() {
            // Whatever it is (a FIFO or device too): read_file refuses it by its type.
            out.push(p.clone());
        } else {
            return Err(Error::Journal {
                path: p.clone(),
                message: "no such file or directory".into(),
            });
        }
    }
    Ok(out)
}

/// Refuses `out` as the output directory of a merge of `files` when it holds any of them (a
/// set written there would replace the shards, every shard's compute).
pub fn check_output(out: &std::path::Path, files: &[PathBuf]) -> Result<(), Error> {
    let Ok(out_real) = out.canonicalize() else {
        return Ok(()); // nothing there yet: it holds no shard
    };
    for f in files {
        if f.canonicalize().is_ok_and(|r| r.starts_with(&out_real)) {
            return Err(Error::Refused {
                path: out.to_path_buf(),
                message: format!(
                    "holds the shard {} being merged: the merged set would replace it; choose \
                     another output directory (--out)",
                    f.display()
                ),
            });
        }
    }
    Ok(())
}

/// A merged run: its scene (rebuilt from the shards) and statistics.
#[derive(Clone, Debug)]
pub struct Merged {
    /// The scene, as the shards' header gives it.
    pub scene: Scene,
    /// The statistics, bit-identical to a single run's.
    pub stats: RunStats,
    /// The shard count.
    pub shards: u64,
}

/// Reads and merges shard files, one at a time: every file is read and checked first (its
/// rows dropped), then read again and folded in shard order, so memory holds one shard, not
/// the run.
pub fn merge_files(paths: &[PathBuf]) -> Result<Merged, Error> {
    merge_with(paths, |i| journal::read_file(&paths[i]).map(Cow::Owned))
}

/// Merges shards given as (name, bytes) in memory (MPI's rank 0); see [`merge_with`].
pub fn merge(inputs: &[(PathBuf, Vec<u8>)]) -> Result<Merged, Error> {
    let names: Vec<PathBuf> = inputs.iter().map(|(p, _)| p.clone()).collect();
    merge_with(&names, |i| Ok(Cow::Borrowed(&inputs[i].1)))
}

/// Merges the shards named `names`, whose bytes `load(i)` gives (asked twice: to check, then to
/// fold): refuses a set that is not one whole run (a file damaged or cut short, a shard of
/// another scene, seed, ensemble count, shard count or gdsmc version, a shard twice, a shard
/// missing), each with a message naming the files.
pub fn merge_with<'a>(
    names: &[PathBuf],
    load: impl Fn(usize) -> Result<Cow<'a, [u8]>, Error>,
) -> Result<Merged, Error> {
    if names.is_empty() {
        return Err(Error::Shards("no shard files given".into()));
    }
    // (input index, K, header) of every shard, checked one by one.
    let mut shards: Vec<(usize, u64, journal::Header)> = Vec::with_capacity(names.len());
    for (i, path) in names.iter().enumerate() {
        let c = journal::read(path, &load(i)?)?;
        let k = whole_shard(path, &c)?;
        shards.push((i, k, c.header));
    }
    strangers(names, &shards)?;
    shards.sort_by_key(|(_, k, _)| *k);
    let s = shards[0].2.shard.map_or(1, |s| s.1);
    for w in shards.windows(2) {
        if w[0].1 == w[1].1 {
            return Err(Error::Shards(format!(
                "{} given twice: {} and {}",
                journal::shard_words(w[0].2.shard),
                names[w[0].0].display(),
                names[w[1].0].display()
            )));
        }
    }
    if (shards.len() as u64) < s {
        // The first few missing, found by walking the sorted indices (S may be large).
        let mut missing = Vec::new();
        let mut given = shards.iter().map(|x| x.1).peekable();
        let mut k = 0;
        while k < s && missing.len() < 8 {
            if given.peek() == Some(&k) {
                given.next();
            } else {
                missing.push(format!("{k}/{s}"));
            }
            k += 1;
        }
        let count = s - shards.len() as u64;
        if count > missing.len() as u64 {
            missing.push("...".into());
        }
        return Err(Error::Shards(format!(
            "{count} of {s} shards missing: {} (given: {})",
            missing.join(", "),
            names
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )));
    }
    let (i0, _, first) = &shards[0];
    let scene = first.scene(&names[*i0])?;
    let mut totals = Totals::new(&scene);
    let mut timing = Timing::default();
    for (i, _, header) in &shards {
        let c = journal::read(&names[*i], &load(*i)?)?;
        if c.header != *header || c.damage.is_some() {
            return Err(Error::Journal {
                path: names[*i].clone(),
                message: "changed while it was being merged".into(),
            });
        }
        for (row, counts) in &c.rows {
            totals.push(row, counts);
        }
        let t = c.end.unwrap_or_default();
        timing.wall = timing.wall.max(t.wall);
        timing.cpu += t.cpu;
        timing.threads += t.threads;
    }
    Ok(Merged {
        stats: stats_of(&scene, totals, timing),
        scene,
        shards: s,
    })
}

/// Refuses shards that are not of one run, naming the strangers: the files whose header is not
/// of the run most of the files hold (the first such run on a tie), whatever their order.
fn strangers(names: &[PathBuf], shards: &[(usize, u64, journal::Header)]) -> Result<(), Error> {
    let holding = |h: &journal::Header| shards.iter().filter(|x| x.2.same_set(h)).count();
    let Some(most) = shards
        .iter()
        .map(|x| (holding(&x.2), x))
        .rev()
        .max_by_key(|(n, _)| *n)
        .map(|(_, x)| x)
    else {
        return Ok(());
    };
    let odd: Vec<&(usize, u64, journal::Header)> =
        shards.iter().filter(|x| !x.2.same_set(&most.2)).collect();
    let Some(first) = odd.first() else {
        return Ok(());
    };
    let others: Vec<String> = shards
        .iter()
        .filter(|x| x.2.same_set(&most.2))
        .map(|x| names[x.0].display().to_string())
        .collect();
    if 2 * others.len() <= shards.len() {
        // No run holds most of the files: none can be named the stranger.
        return Err(Error::Shards(format!(
            "{} and {} are not shards of one run: {} is {} (and no run holds most of the {} files)",
            names[most.0].display(),
            names[first.0].display(),
            names[first.0].display(),
            first.2.difference(&most.2),
            shards.len()
        )));
    }
    let more = if odd.len() > 1 {
        format!(" ({} more files are of other runs)", odd.len() - 1)
    } else {
        String::new()
    };
    Err(Error::Shards(format!(
        "{} is not a shard of the run {} hold{}: it is {}{more}",
        names[first.0].display(),
        others.join(", "),
        if others.len() == 1 { "s" } else { "" },
        first.2.difference(&most.2)
    )))
}

/// The shard index of a file that is a whole shard: one with a shard header and complete; else
/// the error naming it.
fn whole_shard(path: &std::path::Path, c: &Contents) -> Result<u64, Error> {
    let bad = |message: String| Error::Journal {
        path: path.to_path_buf(),
        message,
    };
    let Some((k, s)) = c.header.shard else {
        return Err(bad(
            "the journal of a whole run, not a shard (run with --shard K/S)".into(),
        ));
    };
    if let Some(d) = &c.damage {
        return Err(bad(format!(
            "shard {k}/{s} is incomplete: {d}; it holds ensembles {}..{} of {}..{} \
             (run the same `gdsmc run --shard {k}/{s}` again to finish it)",
            c.header.start,
            c.header.start + c.rows.len() as u64,
            c.header.start,
            c.header.end
        )));
    }
    // Its range is its shard's: journal::read checked the header whole.
    Ok(k)
}
